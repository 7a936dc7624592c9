/*
 * World (navlink.h): defs, creation and destruction, worker counts, the log callback, world tags, the
 * number of worlds at once, and the null world everywhere.
 */
#include "abi_test.h"
#include "floor_scene.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct log_record {
    int calls;
    nl_log_level level;
    nl_status status;
    char message[512];
} log_record;

static void record_log(void* user, nl_log_level level, nl_status status, const char* message) {
    log_record* log = (log_record*)user;
    ++log->calls;
    log->level = level;
    log->status = status;
    snprintf(log->message, sizeof log->message, "%s", message ? message : "(null)");
}

static void create_and_log(void) {
    nl_world* world = NULL;
    nl_world_def def;

    CHECK(NL_WORKERS_AUTO == -1);
    def = nl_default_world_def();
    CHECK(def.size == sizeof(nl_world_def));
    CHECK(def.worker_count == NL_WORKERS_AUTO);
    CHECK(def.log_fn == NULL && def.log_user == NULL);
    CHECK(def.log_level == NL_LOG_WARNING);

    /* NULL def: all defaults, one worker per hardware thread. */
    CHECK_OK(nl_world_create(NULL, &world));
    CHECK(world != NULL);
    CHECK(nl_world_get_worker_count(world) >= 1);
    CHECK(mesh_count(world) == 0);
    nl_world_destroy(world);

    {
        static const int32_t requested[] = {1, 2, 0, NL_WORKERS_AUTO};
        static const int32_t expected[] = {1, 2, 1, -1};
        size_t i;
        for (i = 0; i < sizeof requested / sizeof requested[0]; ++i) {
            world = NULL;
            def = nl_default_world_def();
            def.worker_count = requested[i];
            CHECK_OK(nl_world_create(&def, &world));
            CHECK(world != NULL);
            if (expected[i] > 0) {
                CHECK_MSG(nl_world_get_worker_count(world) == expected[i], "worker_count %d gives %d workers",
                          (int)requested[i], (int)nl_world_get_worker_count(world));
            } else {
                CHECK(nl_world_get_worker_count(world) >= 1);
            }
            nl_world_destroy(world);
        }
    }

    /* Bad defs: rejected naming the field, *out_world untouched. */
    world = NULL;
    def = nl_default_world_def();
    def.worker_count = -2;
    CHECK_INVALID(nl_world_create(&def, &world), "worker_count");
    CHECK(world == NULL);
    def.worker_count = INT32_MIN;
    CHECK_INVALID(nl_world_create(&def, &world), "worker_count");
    CHECK(world == NULL);
    def = nl_default_world_def();
    def.size = 0;
    CHECK_INVALID(nl_world_create(&def, &world), "size");
    CHECK(world == NULL);
    def.size = (uint32_t)offsetof(nl_world_def, log_level); /* shorter than the first release's struct */
    CHECK_INVALID(nl_world_create(&def, &world), "size");
    CHECK(world == NULL);
    def = nl_default_world_def();
    def.log_level = NL_LOG_DEBUG + 1u;
    CHECK_INVALID(nl_world_create(&def, &world), "log_level");
    CHECK(world == NULL);
    CHECK_INVALID(nl_world_create(NULL, NULL), "out_world");

    /* A success clears the last status and message. */
    CHECK(NL_FAILED(nl_get_last_status()));
    CHECK(nl_get_last_error_message()[0] != '\0');
    CHECK_OK(nl_world_create(NULL, &world));
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS);
    CHECK(strcmp(nl_get_last_error_message(), "") == 0);
    /* ... and nl_status_string / nl_get_version leave the record alone. */
    CHECK_INVALID(nl_mesh_add(world, NULL, NULL), "def");
    (void)nl_status_string(NL_STATUS_SUCCESS);
    (void)nl_get_version();
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(mesh_count(world) == 0);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS && nl_get_last_error_message()[0] == '\0');
    nl_world_destroy(world);

    /* The log callback gets each failure on the world, with the user pointer and the message. */
    {
        log_record log;
        nl_mesh_id id = {0u, 0u};
        nl_mesh_def mesh = floor_def();
        memset(&log, 0, sizeof log);
        def = nl_default_world_def();
        def.worker_count = 1;
        def.log_fn = record_log;
        def.log_user = &log;
        world = NULL;
        CHECK_OK(nl_world_create(&def, &world));
        CHECK(log.calls == 0);
        CHECK_OK(nl_mesh_add(world, &mesh, &id));
        CHECK(log.calls == 0);
        mesh.vertex_count = 0;
        CHECK_INVALID(nl_mesh_add(world, &mesh, &id), "vertex_count");
        CHECK(log.calls == 1);
        CHECK(log.level == NL_LOG_ERROR);
        CHECK(log.status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
        CHECK(strstr(log.message, "vertex_count") != NULL);
        CHECK(strcmp(log.message, nl_get_last_error_message()) == 0);
        CHECK(strstr(log.message, "nl_mesh_add") != NULL); /* names the function */
        CHECK_FAIL(nl_mesh_remove(world, (nl_mesh_id){0u, 0u}), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
        CHECK(log.calls == 2);
        CHECK(log.status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE));
        CHECK(strcmp(log.message, nl_get_last_error_message()) == 0);
        CHECK(nl_mesh_is_valid(world, id) == 1);
        CHECK_OK(nl_mesh_remove(world, id));
        CHECK(log.calls == 2);
        nl_world_destroy(world);
        CHECK(log.calls == 2);
    }

    nl_world_destroy(NULL); /* harmless */
    CHECK(1);
}

/* World tags used to be a counter modulo 4095: the 4096th world created shared the first's tag, and
   nl_mesh_remove(first, an id of the other) removed the first world's mesh. */
static void tags_never_repeat_while_alive(void) {
    nl_world* first = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id mine = {0u, 0u}, theirs = {0u, 0u};
    int i, refused = 0, created = 0;
    CHECK_OK(nl_mesh_add(first, &def, &mine));
    for (i = 0; i < 4100; ++i) {
        nl_world_def wd = nl_default_world_def();
        nl_world* other = NULL;
        wd.worker_count = 1;
        wd.path_worker_count = 0;
        if (!NL_SUCCEEDED(nl_world_create(&wd, &other))) break;
        ++created;
        if (i >= 4090) { /* past the old counter's wrap */
            CHECK_OK(nl_mesh_add(other, &def, &theirs));
            refused += nl_mesh_remove(first, theirs) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE);
            refused += nl_mesh_is_valid(first, theirs) == 0;
        }
        nl_world_destroy(other);
    }
    CHECK(created == 4100);
    CHECK(refused == 2 * 10);
    CHECK(nl_mesh_is_valid(first, mine) == 1);
    nl_world_destroy(first);
}

/* As many worlds as the process can hold at once: the next is refused with OUT_OF_MEMORY and a
   message saying why, and destroying them makes room again. */
static void limit(void) {
    enum { MOST = 5000 };
    nl_world** worlds = (nl_world**)calloc(MOST, sizeof(nl_world*));
    nl_status refused = NL_STATUS_SUCCESS;
    nl_world* again = NULL;
    int n = 0, i;
    if (!CHECK(worlds != NULL)) return;
    for (; n < MOST; ++n) {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        def.path_worker_count = 0;
        refused = nl_world_create(&def, &worlds[n]);
        if (refused != NL_STATUS_SUCCESS) break;
    }
    CHECK_MSG(n >= 500 && n < MOST, "%d worlds at once", n);
    CHECK_FAIL(refused, NL_STATUS_OUT_OF_MEMORY, "worlds can exist at once");
    for (i = 0; i < n; ++i) nl_world_destroy(worlds[i]);
    CHECK_OK(nl_world_create(NULL, &again));
    nl_world_destroy(again);
    free(worlds);
}

static const char k_quad_obj[] = FLOOR_QUAD_OBJ;

/* Null world arguments of every function of the world, level and ray sections. */
static void null_world_everywhere(void) {
    const nl_mesh_id id = {1u, 1u};
    nl_mesh_def def = floor_def();
    nl_mesh_info info;
    nl_mesh_id out = {0u, 0u};
    uint32_t count = 0;
    nl_ray r = down_ray(0.0f, 0.0f, 5.0f, INFINITY);
    nl_ray_hit h = nl_ray_hit_init();
    nl_segment s = segment(0, 0, 0, 1, 1, 1);
    uint8_t blocked = 0;
    info.size = sizeof info;

    CHECK_INVALID(nl_world_create(NULL, NULL), "out_world");
    nl_world_destroy(NULL);
    CHECK(nl_world_get_worker_count(NULL) == 0);
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_INVALID(nl_mesh_add(NULL, &def, &out), "world");
    CHECK_INVALID(nl_mesh_add_obj_file(NULL, "a.obj", NULL, &out), "world");
    CHECK_INVALID(nl_mesh_add_obj_memory(NULL, k_quad_obj, strlen(k_quad_obj), NULL, &out), "world");
    CHECK_INVALID(nl_mesh_remove(NULL, id), "world");
    CHECK_INVALID(nl_mesh_set_transform(NULL, id, k_identity), "world");
    CHECK(nl_mesh_is_valid(NULL, id) == 0);
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_INVALID(nl_mesh_get_info(NULL, id, &info), "world");
    CHECK_INVALID(nl_world_get_meshes(NULL, NULL, 0, &count), "world");
    CHECK_INVALID(nl_world_cast_rays(NULL, &r, 1, &h), "world");
    CHECK_INVALID(nl_world_segments_blocked(NULL, &s, 1, &blocked), "world");
    CHECK(out.index1 == 0u && count == 0u && blocked == 0u);
}

ABI_SECTION(world, ABI_CASE(create_and_log), ABI_CASE(tags_never_repeat_while_alive), ABI_CASE(limit),
            ABI_CASE(null_world_everywhere));
