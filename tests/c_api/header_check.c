/* Compile check: <navlink/navlink.h> must build as strict C11 (-std=c11 -Wall -Wextra -pedantic -Werror)
 * and every function it declares must be exported by libnavlink.so (this program takes the address of
 * each one, so a declared but missing symbol fails the link). Running it checks the version agreement. */
#include <navlink/navlink.h>

#include <stddef.h>
#include <stdio.h>

/* The layouts bindings (C#, Rust, Python) mirror field by field. A change here is an ABI break. */
_Static_assert(offsetof(nl_world_def, size) == 0, "nl_world_def starts with size");
_Static_assert(offsetof(nl_mesh_def, size) == 0, "nl_mesh_def starts with size");
_Static_assert(offsetof(nl_mesh_info, size) == 0, "nl_mesh_info starts with size");
_Static_assert(sizeof(nl_version) == 12, "nl_version is three int32");
_Static_assert(sizeof(nl_mesh_id) == 8, "nl_mesh_id is two uint32");
_Static_assert(sizeof(nl_status) == 4, "nl_status is a uint32");
_Static_assert(sizeof(nl_log_level) == 4, "nl_log_level is a uint32");
_Static_assert(sizeof(nl_ray) == 28, "nl_ray is seven floats");
_Static_assert(sizeof(nl_segment) == 24, "nl_segment is six floats");
_Static_assert(sizeof(nl_ray_hit) == 44, "nl_ray_hit has no hidden padding");
_Static_assert(offsetof(nl_ray_hit, mesh) == 28, "nl_ray_hit.mesh offset");
_Static_assert(offsetof(nl_ray_hit, hit) == 40, "nl_ray_hit.hit offset");
/* Structs with a size field may grow at their end, so only the offsets of today's fields are fixed. */
#if UINTPTR_MAX == 0xffffffffffffffffu
_Static_assert(offsetof(nl_world_def, worker_count) == 4 && offsetof(nl_world_def, log_fn) == 8 &&
                   offsetof(nl_world_def, log_user) == 16 && offsetof(nl_world_def, log_level) == 24,
               "nl_world_def on LP64");
_Static_assert(offsetof(nl_mesh_def, vertices) == 8 && offsetof(nl_mesh_def, vertex_stride) == 20 &&
                   offsetof(nl_mesh_def, indices) == 24 && offsetof(nl_mesh_def, flags) == 36 &&
                   offsetof(nl_mesh_def, transform) == 40 && offsetof(nl_mesh_def, user_data) == 48,
               "nl_mesh_def on LP64");
_Static_assert(offsetof(nl_mesh_info, transform) == 20 && offsetof(nl_mesh_info, bounds_min) == 84 &&
                   offsetof(nl_mesh_info, bounds_max) == 96 && offsetof(nl_mesh_info, user_data) == 112,
               "nl_mesh_info on LP64");
#endif

/* Every status bit is distinct and inside its part of the word. */
_Static_assert((NL_STATUS_FAILURE & NL_STATUS_SUCCESS) == 0u, "kinds are distinct");
_Static_assert(((NL_STATUS_INVALID_ARGUMENT | NL_STATUS_INVALID_HANDLE | NL_STATUS_BUFFER_TOO_SMALL |
                 NL_STATUS_OUT_OF_MEMORY | NL_STATUS_CANCELLED | NL_STATUS_PARTIAL_RESULT | NL_STATUS_NOT_FOUND |
                 NL_STATUS_INTERNAL_ERROR | NL_STATUS_IO_ERROR | NL_STATUS_PARSE_ERROR |
                 NL_STATUS_VERSION_MISMATCH) & ~NL_STATUS_DETAIL_MASK) == 0u,
               "detail bits stay in the detail mask");
_Static_assert(NL_WORKERS_AUTO == -1, "NL_WORKERS_AUTO");

static void log_sink(void* user, nl_log_level level, nl_status status, const char* message) {
    (void)user;
    (void)level;
    (void)status;
    (void)message;
}

/* One pointer per declared function, typed by its declaration. */
struct api_table {
    nl_version (*get_version)(void);
    const char* (*status_string)(nl_status);
    nl_status (*get_last_status)(void);
    const char* (*get_last_error_message)(void);
    nl_world_def (*default_world_def)(void);
    nl_status (*world_create)(const nl_world_def*, nl_world**);
    void (*world_destroy)(nl_world*);
    int32_t (*world_get_worker_count)(const nl_world*);
    nl_mesh_def (*default_mesh_def)(void);
    nl_status (*mesh_add)(nl_world*, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_add_obj_file)(nl_world*, const char*, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_add_obj_memory)(nl_world*, const char*, size_t, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_remove)(nl_world*, nl_mesh_id);
    nl_status (*mesh_set_transform)(nl_world*, nl_mesh_id, const float*);
    int32_t (*mesh_is_valid)(const nl_world*, nl_mesh_id);
    nl_status (*mesh_get_info)(const nl_world*, nl_mesh_id, nl_mesh_info*);
    nl_status (*world_get_meshes)(const nl_world*, nl_mesh_id*, uint32_t, uint32_t*);
    nl_status (*world_cast_rays)(nl_world*, const nl_ray*, uint32_t, nl_ray_hit*);
    nl_status (*world_segments_blocked)(nl_world*, const nl_segment*, uint32_t, uint8_t*);
    nl_log_fn* log;
};

int main(void) {
    const struct api_table api = {
        nl_get_version,         nl_status_string,      nl_get_last_status,   nl_get_last_error_message,
        nl_default_world_def,   nl_world_create,       nl_world_destroy,     nl_world_get_worker_count,
        nl_default_mesh_def,    nl_mesh_add,           nl_mesh_add_obj_file, nl_mesh_add_obj_memory,
        nl_mesh_remove,         nl_mesh_set_transform, nl_mesh_is_valid,     nl_mesh_get_info,
        nl_world_get_meshes,    nl_world_cast_rays,    nl_world_segments_blocked,
        log_sink,
    };
    const nl_mesh_id null_id = {0u, 0u};
    const nl_version v = api.get_version();
    if (v.major != NL_VERSION_MAJOR || v.minor != NL_VERSION_MINOR || v.patch != NL_VERSION_PATCH) {
        fprintf(stderr, "header says %d.%d.%d, library says %d.%d.%d\n", NL_VERSION_MAJOR, NL_VERSION_MINOR,
                NL_VERSION_PATCH, (int)v.major, (int)v.minor, (int)v.patch);
        return 1;
    }
    return api.mesh_is_valid(NULL, null_id) == 0 && NL_FAILED(api.get_last_status()) ? 0 : 1;
}
