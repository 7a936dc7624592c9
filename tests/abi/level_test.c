/*
 * navlink-c-api-test: NavLink's behaviour through the C ABI only, written in strict C11.
 *
 * Every check is counted; the last line is "N passed, N failed" and the exit code is nonzero on any
 * failure. Usage: navlink-c-api-test [levels-dir]   (levels-dir holds dungeon.obj; optional)
 *
 * Scenes are built so that every expectation is exact: a floor at y = 1 spanning x, z in [-10, 10],
 * wound counter-clockwise seen from above (normal +Y).
 */
/* fork() and waitpid() isolate the cases that may crash the process; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "scene.h"

#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------------------
 * Checks (declared in c_api_test.h, shared with the other files of this test)
 * ------------------------------------------------------------------------------------------- */

int g_passed;
int g_failed;
const char* g_section = "";

int check_at(int ok, const char* file, int line, const char* what, ...) {
    if (ok) {
        ++g_passed;
        return 1;
    }
    ++g_failed;
    fprintf(stderr, "%s:%d: FAILED [%s] ", file, line, g_section);
    {
        va_list args;
        va_start(args, what);
        vfprintf(stderr, what, args);
        va_end(args);
    }
    fprintf(stderr, "\n    last status 0x%08x (%s), last message \"%s\"\n", (unsigned)nl_get_last_status(),
            nl_status_string(nl_get_last_status()), nl_get_last_error_message());
    return 0;
}

int check_ok_at(nl_status got, const char* expr, const char* file, int line) {
    return check_at(got == NL_STATUS_SUCCESS && nl_get_last_status() == NL_STATUS_SUCCESS &&
                        nl_get_last_error_message()[0] == '\0',
                    file, line, "%s returned 0x%08x (%s): %s", expr, (unsigned)got, nl_status_string(got),
                    nl_get_last_error_message());
}

int check_fail_at(nl_status got, nl_status detail, const char* needle, const char* expr, const char* file, int line) {
    const nl_status expected = NL_STATUS_FAILURE | detail;
    const char* message = nl_get_last_error_message();
    return check_at(got == expected && nl_get_last_status() == expected && message != NULL &&
                        strstr(message, needle) != NULL,
                    file, line, "%s returned 0x%08x (%s), expected 0x%08x (%s) with a message containing \"%s\"",
                    expr, (unsigned)got, nl_status_string(got), (unsigned)expected, nl_status_string(expected),
                    needle);
}

int check_near_at(double a, double b, double tol, const char* ea, const char* eb, const char* file, int line) {
    return check_at(fabs(a - b) <= tol, file, line, "%s = %.9g, expected %s = %.9g (tolerance %g)", ea, a, eb, b, tol);
}

/* ---------------------------------------------------------------------------------------------
 * Scenes
 * ------------------------------------------------------------------------------------------- */

static const float k_floor_vertices[] = {
    -10.0f, 1.0f, -10.0f, /* 0 */
    -10.0f, 1.0f, 10.0f,  /* 1 */
    10.0f,  1.0f, 10.0f,  /* 2 */
    10.0f,  1.0f, -10.0f, /* 3 */
};
/* Counter-clockwise seen from above: (v1 - v0) x (v2 - v0) points to +Y. Triangle 0 holds the points with
 * z > x, triangle 1 those with z < x. */
static const uint32_t k_floor_indices[] = {0, 1, 2, 0, 2, 3};

static const float k_identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static void translation(float m[16], float x, float y, float z) {
    memcpy(m, k_identity, sizeof k_identity);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

static nl_mesh_def floor_def(void) { return mesh_def_of(k_floor_vertices, 4, k_floor_indices, 2); }

nl_world* make_world(int32_t workers) {
    nl_world_def def = nl_default_world_def();
    nl_world* world = NULL;
    def.worker_count = workers;
    if (NL_FAILED(nl_world_create(&def, &world))) {
        fprintf(stderr, "cannot create a world: %s\n", nl_get_last_error_message());
        exit(2);
    }
    return world;
}

static uint32_t mesh_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_meshes(world, NULL, 0, &count);
    return count;
}

static int same_id(nl_mesh_id a, nl_mesh_id b) { return a.index1 == b.index1 && a.generation == b.generation; }

static nl_ray down_ray(float x, float z, float from_y, float max_distance) {
    nl_ray r;
    r.origin[0] = x;
    r.origin[1] = from_y;
    r.origin[2] = z;
    r.direction[0] = 0.0f;
    r.direction[1] = -1.0f;
    r.direction[2] = 0.0f;
    r.max_distance = max_distance;
    return r;
}

/* Casts one ray straight down from (x, 5, z); returns the hit (hit = 0 on a miss or an error). */
static nl_ray_hit cast_down(nl_world* world, float x, float z) {
    const nl_ray r = down_ray(x, z, 5.0f, INFINITY);
    nl_ray_hit h;
    memset(&h, 0, sizeof h);
    if (NL_FAILED(nl_world_cast_rays(world, &r, 1, &h))) memset(&h, 0, sizeof h);
    return h;
}

int all_bytes(const void* p, size_t n, unsigned char value) {
    const unsigned char* b = (const unsigned char*)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (b[i] != value) return 0;
    }
    return 1;
}

/* ---------------------------------------------------------------------------------------------
 * Version and status
 * ------------------------------------------------------------------------------------------- */

static void test_version_and_status(void) {
    static const nl_status details[] = {
        NL_STATUS_INVALID_ARGUMENT, NL_STATUS_INVALID_HANDLE, NL_STATUS_BUFFER_TOO_SMALL, NL_STATUS_OUT_OF_MEMORY,
        NL_STATUS_CANCELLED,        NL_STATUS_NOT_FOUND,      NL_STATUS_INTERNAL_ERROR,   NL_STATUS_IO_ERROR,
        NL_STATUS_PARSE_ERROR,      NL_STATUS_VERSION_MISMATCH,
    };
    const size_t n = sizeof details / sizeof details[0];
    size_t i, j;
    nl_version v;
    g_section = "version/status";

    v = nl_get_version();
    CHECK(v.major == NL_VERSION_MAJOR);
    CHECK(v.minor == NL_VERSION_MINOR);
    CHECK(v.patch == NL_VERSION_PATCH);

    CHECK(strcmp(nl_status_string(NL_STATUS_SUCCESS), "success") == 0);
    CHECK(strstr(nl_status_string(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT), "success") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT), "partial") != NULL);
    CHECK(strcmp(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT), "failure: invalid argument") == 0);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE), "invalid handle") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL), "buffer too small") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND), "not found") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR), "parse") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY), "memory") != NULL);
    CHECK(strncmp(nl_status_string(NL_STATUS_FAILURE), "failure", 7) == 0);
    CHECK(nl_status_string(NL_STATUS_IN_PROGRESS) != NULL && nl_status_string(NL_STATUS_IN_PROGRESS)[0] != '\0');
    CHECK(nl_status_string(0u) != NULL && nl_status_string(0xffffffffu) != NULL);
    {
        /* Each failure detail has its own description, all starting with "failure". */
        int distinct = 1, prefixed = 1;
        for (i = 0; i < n; ++i) {
            const char* a = nl_status_string(NL_STATUS_FAILURE | details[i]);
            if (a == NULL || strncmp(a, "failure", 7) != 0) prefixed = 0;
            for (j = i + 1; j < n; ++j) {
                if (a != NULL && strcmp(a, nl_status_string(NL_STATUS_FAILURE | details[j])) == 0) distinct = 0;
            }
        }
        CHECK(prefixed);
        CHECK(distinct);
    }

    CHECK(NL_SUCCEEDED(NL_STATUS_SUCCESS));
    CHECK(!NL_FAILED(NL_STATUS_SUCCESS));
    CHECK(NL_SUCCEEDED(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(NL_FAILED(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(!NL_SUCCEEDED(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(!NL_SUCCEEDED(NL_STATUS_IN_PROGRESS) && !NL_FAILED(NL_STATUS_IN_PROGRESS));
    CHECK(NL_WORKERS_AUTO == -1);
}

/* ---------------------------------------------------------------------------------------------
 * World
 * ------------------------------------------------------------------------------------------- */

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

static void test_world(void) {
    nl_world* world = NULL;
    nl_world_def def;
    g_section = "world";

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

/* ---------------------------------------------------------------------------------------------
 * Meshes
 * ------------------------------------------------------------------------------------------- */

static void test_mesh_add_and_info(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u}, moved = {0u, 0u};
    nl_mesh_info info;
    float m[16];
    int k;
    g_section = "mesh add/info";

    def = nl_default_mesh_def();
    CHECK(def.size == sizeof(nl_mesh_def));
    CHECK(def.vertices == NULL && def.indices == NULL && def.transform == NULL);
    CHECK(def.vertex_count == 0 && def.triangle_count == 0 && def.vertex_stride == 0);
    CHECK(def.flags == 0 && def.user_data == 0);

    def = floor_def();
    def.user_data = 0x0123456789abcdefull;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    CHECK(id.index1 != 0u);
    CHECK(nl_mesh_is_valid(world, id) == 1);
    CHECK(mesh_count(world) == 1);

    memset(&info, 0xab, sizeof info);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.size == sizeof info);
    CHECK(info.vertex_count == 4);
    CHECK(info.triangle_count == 2);
    CHECK(info.degenerate_triangle_count == 0);
    CHECK(info.flags == 0);
    CHECK(memcmp(info.transform, k_identity, sizeof k_identity) == 0);
    CHECK(info.bounds_min[0] == -10.0f && info.bounds_min[1] == 1.0f && info.bounds_min[2] == -10.0f);
    CHECK(info.bounds_max[0] == 10.0f && info.bounds_max[1] == 1.0f && info.bounds_max[2] == 10.0f);
    CHECK(info.user_data == 0x0123456789abcdefull);

    /* With a transform and a flag: both reported, bounds in world space. */
    translation(m, 100.0f, 2.0f, -3.0f);
    def = floor_def();
    def.transform = m;
    def.flags = NL_MESH_MOVABLE;
    def.user_data = 7u;
    CHECK_OK(nl_mesh_add(world, &def, &moved));
    CHECK(!same_id(id, moved));
    m[12] = 12345.0f; /* the transform was copied */
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, moved, &info));
    CHECK(info.flags == NL_MESH_MOVABLE);
    CHECK(info.transform[12] == 100.0f && info.transform[13] == 2.0f && info.transform[14] == -3.0f);
    CHECK(info.transform[0] == 1.0f && info.transform[5] == 1.0f && info.transform[10] == 1.0f && info.transform[15] == 1.0f);
    CHECK(info.bounds_min[0] == 90.0f && info.bounds_min[1] == 3.0f && info.bounds_min[2] == -13.0f);
    CHECK(info.bounds_max[0] == 110.0f && info.bounds_max[1] == 3.0f && info.bounds_max[2] == 7.0f);
    CHECK(info.user_data == 7u);
    CHECK(mesh_count(world) == 2);

    /* get_info failures write nothing. */
    memset(&info, 0xab, sizeof info);
    info.size = 0;
    CHECK_INVALID(nl_mesh_get_info(world, id, &info), "size");
    CHECK(info.vertex_count == 0xabababab);
    info.size = sizeof info;
    CHECK_INVALID(nl_mesh_get_info(world, id, NULL), "out_info");
    CHECK_INVALID(nl_mesh_get_info(NULL, id, &info), "world");
    CHECK(info.vertex_count == 0xabababab);

    /* Interleaved position + normal (stride 24); the normal slots hold NaN, which must never be read. */
    {
        float interleaved[8 * 6];
        /* Vertex k has x, y, z from bits 0, 1, 2 of k; faces wound counter-clockwise seen from outside. */
        static const uint32_t box[36] = {2, 6, 7, 2, 7, 3,  /* top, +y */
                                         0, 1, 5, 0, 5, 4,  /* bottom, -y */
                                         1, 3, 7, 1, 7, 5,  /* +x */
                                         0, 4, 6, 0, 6, 2,  /* -x */
                                         4, 5, 7, 4, 7, 6,  /* +z */
                                         0, 2, 3, 0, 3, 1}; /* -z */
        nl_mesh_id box_id = {0u, 0u};
        for (k = 0; k < 8; ++k) {
            interleaved[6 * k + 0] = (k & 1) ? 3.0f : 1.0f;
            interleaved[6 * k + 1] = (k & 2) ? 6.0f : 2.0f;
            interleaved[6 * k + 2] = (k & 4) ? -1.0f : -5.0f;
            interleaved[6 * k + 3] = NAN;
            interleaved[6 * k + 4] = INFINITY;
            interleaved[6 * k + 5] = NAN;
        }
        def = nl_default_mesh_def();
        def.vertices = interleaved;
        def.vertex_count = 8;
        def.vertex_stride = 6 * sizeof(float);
        def.indices = box;
        def.triangle_count = 12;
        CHECK_OK(nl_mesh_add(world, &def, &box_id));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, box_id, &info));
        CHECK(info.vertex_count == 8 && info.triangle_count == 12 && info.degenerate_triangle_count == 0);
        CHECK(info.bounds_min[0] == 1.0f && info.bounds_min[1] == 2.0f && info.bounds_min[2] == -5.0f);
        CHECK(info.bounds_max[0] == 3.0f && info.bounds_max[1] == 6.0f && info.bounds_max[2] == -1.0f);
        {
            /* Straight down from y = 10 onto the box top (y = 6), and sideways onto its +x face. */
            nl_ray r[2];
            nl_ray_hit h[2];
            r[0] = down_ray(2.0f, -3.0f, 10.0f, INFINITY);
            r[1] = down_ray(8.0f, -2.0f, 3.0f, INFINITY);
            r[1].direction[0] = -2.0f, r[1].direction[1] = 0.0f;
            CHECK_OK(nl_world_cast_rays(world, r, 2, h));
            CHECK(h[0].hit == 1 && same_id(h[0].mesh, box_id) && h[0].triangle < 2);
            CHECK_NEAR(h[0].distance, 4.0f, TOL);
            CHECK_NEAR(h[0].point[1], 6.0f, TOL);
            CHECK_NEAR(h[0].normal[1], 1.0f, TOL);
            CHECK(h[1].hit == 1 && same_id(h[1].mesh, box_id) && h[1].triangle >= 4 && h[1].triangle < 6);
            CHECK_NEAR(h[1].distance, 5.0f, TOL);
            CHECK_NEAR(h[1].point[0], 3.0f, TOL);
            CHECK_NEAR(h[1].normal[0], 1.0f, TOL);
        }
        CHECK_OK(nl_mesh_remove(world, box_id));
    }

    /* A stride that is not a multiple of 4 (13 bytes, unaligned floats) reads the same positions. */
    {
        unsigned char packed[4 * 13];
        nl_mesh_id odd = {0u, 0u};
        memset(packed, 0xff, sizeof packed); /* the padding byte is garbage */
        for (k = 0; k < 4; ++k) memcpy(packed + 13 * k, k_floor_vertices + 3 * k, 3 * sizeof(float));
        def = floor_def();
        def.vertices = (const float*)(const void*)packed;
        def.vertex_stride = 13;
        CHECK_OK(nl_mesh_add(world, &def, &odd));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, odd, &info));
        CHECK(info.bounds_min[0] == -10.0f && info.bounds_max[2] == 10.0f && info.bounds_max[1] == 1.0f);
        CHECK_OK(nl_mesh_remove(world, odd));
    }

    /* Arrays are copied: the caller's buffers may change after the call. */
    {
        float vertices[12];
        uint32_t indices[6];
        nl_mesh_id copied = {0u, 0u};
        nl_ray_hit h;
        memcpy(vertices, k_floor_vertices, sizeof vertices);
        memcpy(indices, k_floor_indices, sizeof indices);
        def = floor_def();
        def.vertices = vertices;
        def.indices = indices;
        translation(m, 0.0f, 10.0f, 0.0f); /* floor at y = 11 */
        def.transform = m;
        CHECK_OK(nl_mesh_add(world, &def, &copied));
        memset(vertices, 0, sizeof vertices);
        memset(indices, 0, sizeof indices);
        {
            const nl_ray r = down_ray(0.5f, 0.25f, 20.0f, INFINITY);
            CHECK_OK(nl_world_cast_rays(world, &r, 1, &h));
            CHECK(h.hit == 1 && same_id(h.mesh, copied));
            CHECK_NEAR(h.distance, 9.0f, TOL);
        }
        CHECK_OK(nl_mesh_remove(world, copied));
    }
    nl_world_destroy(world);
}

static void test_degenerate(void) {
    nl_world* world = make_world(1);
    /* Input triangles: 0 repeated index, 1 real (floor tri 0), 2 collinear, 3 real (floor tri 1). */
    static const float vertices[] = {
        -10.0f, 1.0f, -10.0f, -10.0f, 1.0f, 10.0f, 10.0f, 1.0f, 10.0f, 10.0f, 1.0f, -10.0f,
        0.0f,   1.0f, 0.0f, /* 4: on the diagonal v0-v2 */
    };
    static const uint32_t indices[] = {0, 0, 1, 0, 1, 2, 0, 4, 2, 0, 2, 3};
    nl_mesh_def def = nl_default_mesh_def();
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h;
    g_section = "degenerate";

    def.vertices = vertices;
    def.vertex_count = 5;
    def.indices = indices;
    def.triangle_count = 4;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.triangle_count == 2);
    CHECK(info.degenerate_triangle_count == 2);
    CHECK(info.vertex_count == 5);
    /* Hits report the input triangle index, counting the skipped ones. */
    h = cast_down(world, -2.0f, 3.0f); /* z > x: input triangle 1 */
    CHECK(h.hit == 1 && h.triangle == 1);
    h = cast_down(world, 3.0f, -2.0f); /* z < x: input triangle 3 */
    CHECK(h.hit == 1 && h.triangle == 3);
    /* The same through a movable mesh's instance. */
    {
        nl_mesh_id movable = {0u, 0u};
        float m[16];
        translation(m, 0.0f, 1.0f, 0.0f);
        def.flags = NL_MESH_MOVABLE;
        def.transform = m;
        CHECK_OK(nl_mesh_add(world, &def, &movable));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, movable, &info));
        CHECK(info.triangle_count == 2 && info.degenerate_triangle_count == 2);
        h = cast_down(world, -2.0f, 3.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, movable) && h.triangle == 1);
        h = cast_down(world, 3.0f, -2.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, movable) && h.triangle == 3);
        CHECK_OK(nl_mesh_remove(world, movable));
        def.flags = 0;
        def.transform = NULL;
    }

    /* Every triangle degenerate: nothing registered. */
    {
        nl_mesh_id untouched = {77u, 77u};
        def.triangle_count = 1; /* only {0, 0, 1} */
        CHECK_INVALID(nl_mesh_add(world, &def, &untouched), "degenerate");
        CHECK(untouched.index1 == 77u && untouched.generation == 77u);
        CHECK(mesh_count(world) == 1);
    }
    nl_world_destroy(world);
}

/* One rejected nl_mesh_add: INVALID_ARGUMENT naming `needle`, nothing registered, out_id untouched. */
#define CHECK_REJECTED_MESH(world, def, needle) check_rejected_mesh((world), (def), (needle), __FILE__, __LINE__)
static void check_rejected_mesh(nl_world* world, const nl_mesh_def* def, const char* needle, const char* file,
                                int line) {
    const uint32_t before = mesh_count(world);
    nl_mesh_id out = {77u, 77u};
    const nl_status status = nl_mesh_add(world, def, &out);
    check_fail_at(status, NL_STATUS_INVALID_ARGUMENT, needle, "nl_mesh_add", file, line);
    check_at(out.index1 == 77u && out.generation == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(mesh_count(world) == before, file, line, "a mesh was registered on failure (%s)", needle);
}

static void test_mesh_rejections(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def;
    nl_mesh_id id = {0u, 0u};
    float vertices[12];
    uint32_t indices[6];
    float m[16];
    g_section = "mesh rejections";

    /* A zero-initialised def (not from nl_default_mesh_def) has size 0. */
    CHECK_INVALID(nl_mesh_add(world, &(nl_mesh_def){0}, &id), "size");
    CHECK(mesh_count(world) == 0);
    def = floor_def();
    CHECK_OK(nl_mesh_add(world, &def, &id)); /* one mesh present, so "unchanged" is not just "still zero" */

    memcpy(vertices, k_floor_vertices, sizeof vertices);
    memcpy(indices, k_floor_indices, sizeof indices);
    def = floor_def();
    def.vertices = vertices;
    def.indices = indices;

    vertices[4] = NAN; /* vertices[1].y */
    CHECK_REJECTED_MESH(world, &def, "vertices[1]");
    vertices[4] = 1.0f;
    vertices[8] = INFINITY; /* vertices[2].z */
    CHECK_REJECTED_MESH(world, &def, "vertices[2]");
    vertices[8] = -INFINITY;
    CHECK_REJECTED_MESH(world, &def, "vertices[2]");
    vertices[8] = 10.0f;

    indices[4] = 4; /* == vertex_count */
    CHECK_REJECTED_MESH(world, &def, "indices[4]");
    indices[4] = UINT32_MAX;
    CHECK_REJECTED_MESH(world, &def, "indices[4]");
    indices[4] = 2;

    def.vertices = NULL;
    CHECK_REJECTED_MESH(world, &def, "vertices");
    def.vertices = vertices;
    def.indices = NULL;
    CHECK_REJECTED_MESH(world, &def, "indices");
    def.indices = indices;
    def.vertex_count = 0;
    CHECK_REJECTED_MESH(world, &def, "vertex_count");
    def.vertex_count = 4;
    def.triangle_count = 0;
    CHECK_REJECTED_MESH(world, &def, "triangle_count");
    def.triangle_count = 2;
    def.vertex_stride = 8;
    CHECK_REJECTED_MESH(world, &def, "vertex_stride");
    def.vertex_stride = 0;
    def.flags = 0x80u;
    CHECK_REJECTED_MESH(world, &def, "flags");
    def.flags = NL_MESH_MOVABLE | 0x100u;
    CHECK_REJECTED_MESH(world, &def, "flags");
    def.flags = 0;
    def.size = 0;
    CHECK_REJECTED_MESH(world, &def, "size");
    def.size = sizeof def - 8u;
    CHECK_REJECTED_MESH(world, &def, "size");
    def.size = sizeof def;

    /* Transforms: non-affine (last row not 0 0 0 1), singular, non-finite. */
    def.transform = m;
    memcpy(m, k_identity, sizeof m);
    m[3] = 0.5f; /* row 3, column 0 */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[15] = 2.0f;
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[5] = 0.0f; /* flattens Y */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[0] = 1.0f, m[1] = 2.0f, m[4] = 2.0f, m[5] = 4.0f; /* two parallel columns */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memset(m, 0, sizeof m);
    m[15] = 1.0f;
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[13] = NAN;
    CHECK_REJECTED_MESH(world, &def, "transform");
    m[13] = INFINITY;
    CHECK_REJECTED_MESH(world, &def, "transform");
    def.flags = NL_MESH_MOVABLE; /* the movable path validates as well */
    CHECK_REJECTED_MESH(world, &def, "transform");
    def.transform = NULL;

    /* Null pointers. */
    {
        nl_mesh_id out = {77u, 77u};
        CHECK_INVALID(nl_mesh_add(world, NULL, &out), "def");
        CHECK_INVALID(nl_mesh_add(world, &def, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add(NULL, &def, &out), "world");
        CHECK(out.index1 == 77u && out.generation == 77u);
    }
    CHECK(mesh_count(world) == 1);
    nl_world_destroy(world);
}

static void test_get_meshes(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id ids[3], out[5];
    uint32_t count = 0xdeadbeefu;
    int found[3] = {0, 0, 0};
    uint32_t i, j;
    g_section = "get_meshes";

    CHECK_OK(nl_world_get_meshes(world, NULL, 0, &count));
    CHECK(count == 0);
    for (i = 0; i < 3; ++i) {
        def.user_data = i;
        CHECK_OK(nl_mesh_add(world, &def, &ids[i]));
    }

    count = 0xdeadbeefu;
    CHECK_OK(nl_world_get_meshes(world, NULL, 0, &count)); /* a count query succeeds */
    CHECK(count == 3);
    memset(out, 0xcd, sizeof out);
    count = 0;
    CHECK_FAIL(nl_world_get_meshes(world, out, 2, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 3);
    CHECK(all_bytes(out, sizeof out, 0xcd)); /* nothing written */

    count = 0;
    CHECK_OK(nl_world_get_meshes(world, out, 3, &count));
    CHECK(count == 3);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (same_id(out[i], ids[j])) ++found[j];
        }
    }
    CHECK(found[0] == 1 && found[1] == 1 && found[2] == 1);

    memset(out, 0xcd, sizeof out);
    CHECK_OK(nl_world_get_meshes(world, out, 5, &count));
    CHECK(count == 3);
    CHECK(all_bytes(&out[3], 2 * sizeof out[0], 0xcd)); /* only `count` entries written */

    CHECK_OK(nl_mesh_remove(world, ids[1]));
    CHECK_OK(nl_world_get_meshes(world, out, 5, &count));
    CHECK(count == 2);
    CHECK((same_id(out[0], ids[0]) && same_id(out[1], ids[2])) || (same_id(out[0], ids[2]) && same_id(out[1], ids[0])));

    count = 0xdeadbeefu;
    CHECK_INVALID(nl_world_get_meshes(world, NULL, 1, &count), "out_ids");
    CHECK_INVALID(nl_world_get_meshes(world, out, 5, NULL), "out_count");
    CHECK_INVALID(nl_world_get_meshes(NULL, out, 5, &count), "world");
    nl_world_destroy(world);
}

/* World tags used to be a counter modulo 4095: the 4096th world created shared the first's tag, and
   nl_mesh_remove(first, an id of the other) removed the first world's mesh. */
static void test_world_tags_never_repeat_while_alive(void) {
    nl_world* first = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id mine = {0u, 0u}, theirs = {0u, 0u};
    int i, refused = 0, created = 0;
    g_section = "world tags";
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
static void test_world_limit(void) {
    enum { MOST = 5000 };
    nl_world** worlds = (nl_world**)calloc(MOST, sizeof(nl_world*));
    nl_status refused = NL_STATUS_SUCCESS;
    nl_world* again = NULL;
    int n = 0, i;
    g_section = "world limit";
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

static void test_stale_ids(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u}, reused = {0u, 0u}, other = {0u, 0u};
    const nl_mesh_id null_id = {0u, 0u};
    nl_mesh_info info;
    float m[16];
    g_section = "stale ids";

    translation(m, 0.0f, 1.0f, 0.0f);
    CHECK_OK(nl_mesh_add(world, &def, &other));
    CHECK_OK(nl_mesh_add(world, &def, &id));
    CHECK(nl_mesh_is_valid(world, id) == 1);
    CHECK_OK(nl_mesh_remove(world, id));
    CHECK(nl_mesh_is_valid(world, id) == 0);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS); /* a stale id is an answer, not an error */
    CHECK_FAIL(nl_mesh_remove(world, id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    memset(&info, 0xab, sizeof info);
    info.size = sizeof info;
    CHECK_FAIL(nl_mesh_get_info(world, id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK(info.vertex_count == 0xabababab);
    CHECK_FAIL(nl_mesh_set_transform(world, id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");
    CHECK(mesh_count(world) == 1);

    /* The null id. */
    CHECK(nl_mesh_is_valid(world, null_id) == 0);
    CHECK_FAIL(nl_mesh_remove(world, null_id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    CHECK_FAIL(nl_mesh_get_info(world, null_id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK_FAIL(nl_mesh_set_transform(world, null_id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");

    /* Ids that were never issued. */
    {
        const nl_mesh_id far = {1000u, 1u}, wrong_generation = {other.index1, other.generation + 1u};
        const nl_mesh_id zero_generation = {other.index1, 0u};
        CHECK(nl_mesh_is_valid(world, far) == 0);
        CHECK(nl_mesh_is_valid(world, wrong_generation) == 0);
        CHECK(nl_mesh_is_valid(world, zero_generation) == 0);
        CHECK_FAIL(nl_mesh_remove(world, far), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
        CHECK_FAIL(nl_mesh_remove(world, wrong_generation), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
        CHECK(nl_mesh_is_valid(world, other) == 1);
    }

    /* A new mesh may take the removed slot; the old id stays stale and cannot touch it. */
    def.user_data = 42u;
    CHECK_OK(nl_mesh_add(world, &def, &reused));
    CHECK(!same_id(reused, id));
    CHECK_MSG(reused.index1 == id.index1, "slot not reused (old {%u,%u}, new {%u,%u}); the reuse checks are vacuous",
              (unsigned)id.index1, (unsigned)id.generation, (unsigned)reused.index1, (unsigned)reused.generation);
    CHECK(nl_mesh_is_valid(world, id) == 0);
    CHECK(nl_mesh_is_valid(world, reused) == 1);
    CHECK_FAIL(nl_mesh_remove(world, id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    CHECK_FAIL(nl_mesh_set_transform(world, id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");
    CHECK_FAIL(nl_mesh_get_info(world, id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK(nl_mesh_is_valid(world, reused) == 1);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, reused, &info));
    CHECK(info.user_data == 42u && info.transform[13] == 0.0f);
    CHECK(mesh_count(world) == 2);

    /* A ray hitting the reused slot reports the new id. */
    CHECK_OK(nl_mesh_remove(world, other));
    {
        const nl_ray_hit h = cast_down(world, 1.0f, 2.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, reused));
    }
    CHECK(nl_mesh_is_valid(NULL, reused) == 0);
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_INVALID(nl_mesh_remove(NULL, reused), "world");
    CHECK_INVALID(nl_mesh_set_transform(NULL, reused, m), "world");
    CHECK_INVALID(nl_mesh_set_transform(world, reused, NULL), "transform");
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Rays and segments
 * ------------------------------------------------------------------------------------------- */

static void test_rays(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_ray rays[4];
    nl_ray_hit hits[4];
    g_section = "rays";

    CHECK_OK(nl_mesh_add(world, &def, &floor));

    /* Straight down onto triangle 0 (z > x) and triangle 1 (z < x). */
    rays[0] = down_ray(-2.0f, 3.0f, 5.0f, INFINITY);
    rays[1] = down_ray(3.0f, -2.0f, 5.0f, 100.0f);
    rays[1].direction[1] = -7.0f; /* any length */
    memset(hits, 0xab, sizeof hits);
    CHECK_OK(nl_world_cast_rays(world, rays, 2, hits));
    CHECK(hits[0].hit == 1);
    CHECK_NEAR(hits[0].distance, 4.0f, TOL);
    CHECK_NEAR(hits[0].point[0], -2.0f, TOL);
    CHECK_NEAR(hits[0].point[1], 1.0f, TOL);
    CHECK_NEAR(hits[0].point[2], 3.0f, TOL);
    CHECK_NEAR(hits[0].normal[0], 0.0f, TOL);
    CHECK_NEAR(hits[0].normal[1], 1.0f, TOL);
    CHECK_NEAR(hits[0].normal[2], 0.0f, TOL);
    CHECK(same_id(hits[0].mesh, floor));
    CHECK(hits[0].triangle == 0);
    CHECK(hits[1].hit == 1);
    CHECK_NEAR(hits[1].distance, 4.0f, TOL);
    CHECK_NEAR(hits[1].point[0], 3.0f, TOL);
    CHECK_NEAR(hits[1].point[1], 1.0f, TOL);
    CHECK_NEAR(hits[1].point[2], -2.0f, TOL);
    CHECK_NEAR(hits[1].normal[1], 1.0f, TOL);
    CHECK(same_id(hits[1].mesh, floor));
    CHECK(hits[1].triangle == 1);

    /* A slanted ray: direction (3, -4, 0) from (0, 5, 0) meets y = 1 at (3, 1, 0), 5 m away. */
    rays[0].origin[0] = 0.0f, rays[0].origin[1] = 5.0f, rays[0].origin[2] = 0.0f;
    rays[0].direction[0] = 3.0f, rays[0].direction[1] = -4.0f, rays[0].direction[2] = 0.0f;
    rays[0].max_distance = INFINITY;
    CHECK_OK(nl_world_cast_rays(world, rays, 1, hits));
    CHECK(hits[0].hit == 1);
    CHECK_NEAR(hits[0].distance, 5.0f, TOL);
    CHECK_NEAR(hits[0].point[0], 3.0f, TOL);
    CHECK_NEAR(hits[0].point[1], 1.0f, TOL);

    /* From below, upward: the back face is hit and the normal is not flipped toward the ray. */
    rays[0] = down_ray(-2.0f, 3.0f, -1.0f, INFINITY);
    rays[0].direction[1] = 1.0f;
    CHECK_OK(nl_world_cast_rays(world, rays, 1, hits));
    CHECK(hits[0].hit == 1);
    CHECK_NEAR(hits[0].distance, 2.0f, TOL);
    CHECK_NEAR(hits[0].normal[1], 1.0f, TOL);

    /* Misses: pointing away, outside the floor, max_distance too short. Everything else is zero. */
    rays[0] = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
    rays[0].direction[1] = 1.0f;
    rays[1] = down_ray(50.0f, 0.0f, 5.0f, INFINITY);
    rays[2] = down_ray(0.5f, 0.25f, 5.0f, 3.99f);
    rays[3] = down_ray(0.5f, 0.25f, 5.0f, 4.01f);
    memset(hits, 0xab, sizeof hits);
    CHECK_OK(nl_world_cast_rays(world, rays, 4, hits));
    CHECK(hits[0].hit == 0 && hits[1].hit == 0 && hits[2].hit == 0);
    CHECK(all_bytes(&hits[0], sizeof hits[0], 0) && all_bytes(&hits[1], sizeof hits[1], 0) &&
          all_bytes(&hits[2], sizeof hits[2], 0));
    CHECK(hits[3].hit == 1 && same_id(hits[3].mesh, floor));
    CHECK_NEAR(hits[3].distance, 4.0f, TOL);
    CHECK(hits[3].reserved[0] == 0 && hits[3].reserved[1] == 0 && hits[3].reserved[2] == 0);

    /* count == 0 succeeds and touches nothing, even with null arrays. */
    memset(hits, 0xab, sizeof hits);
    CHECK_OK(nl_world_cast_rays(world, rays, 0, hits));
    CHECK(all_bytes(hits, sizeof hits, 0xab));
    CHECK_OK(nl_world_cast_rays(world, NULL, 0, NULL));

    /* Invalid rays: the index is named and nothing is written. */
    {
        struct bad_ray {
            int index;
            int field; /* 0 origin, 1 direction, 2 max_distance */
            float value;
            const char* needle;
        };
        static const struct bad_ray bad[] = {
            {1, 0, 0.0f, "rays[1]"}, /* NaN origin, value replaced below */
            {2, 0, 1.0f, "rays[2]"}, /* infinite origin */
            {0, 1, 0.0f, "rays[0]"}, /* zero direction */
            {3, 1, 1.0f, "rays[3]"}, /* infinite direction */
            {2, 1, 2.0f, "rays[2]"}, /* NaN direction */
            {1, 2, 0.0f, "rays[1]"}, /* max_distance 0 */
            {0, 2, -1.0f, "rays[0]"},
            {3, 2, 2.0f, "rays[3]"}, /* max_distance NaN */
            {2, 2, -3.0f, "rays[2]"}, /* -INFINITY */
        };
        size_t b;
        for (b = 0; b < sizeof bad / sizeof bad[0]; ++b) {
            int k;
            for (k = 0; k < 4; ++k) rays[k] = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
            if (bad[b].field == 0) {
                rays[bad[b].index].origin[1] = bad[b].value == 0.0f ? NAN : INFINITY;
            } else if (bad[b].field == 1) {
                float* d = rays[bad[b].index].direction;
                if (bad[b].value == 0.0f) d[0] = d[1] = d[2] = 0.0f;
                else if (bad[b].value == 1.0f) d[2] = INFINITY;
                else d[0] = NAN;
            } else {
                float v = bad[b].value;
                if (v == 2.0f) v = NAN;
                if (v == -3.0f) v = -INFINITY;
                rays[bad[b].index].max_distance = v;
            }
            memset(hits, 0xab, sizeof hits);
            CHECK_INVALID(nl_world_cast_rays(world, rays, 4, hits), bad[b].needle);
            CHECK_MSG(all_bytes(hits, sizeof hits, 0xab), "hits written on failure (case %d)", (int)b);
        }
    }

    rays[0] = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
    CHECK_INVALID(nl_world_cast_rays(world, NULL, 1, hits), "rays");
    CHECK_INVALID(nl_world_cast_rays(world, rays, 1, NULL), "out_hits");
    CHECK_INVALID(nl_world_cast_rays(NULL, rays, 1, hits), "world");
    CHECK_INVALID(nl_world_cast_rays(NULL, rays, 0, hits), "world");

    /* Removing the floor: the same ray misses. */
    CHECK_OK(nl_mesh_remove(world, floor));
    CHECK_OK(nl_world_cast_rays(world, rays, 1, hits));
    CHECK(hits[0].hit == 0);
    nl_world_destroy(world);
}

/* Many rays over the floor, parallel over two workers: every one exact, the same with one worker. */
static void test_ray_batches(void) {
    enum { side = 48, count = side * side };
    nl_world* worlds[2];
    nl_ray* rays = (nl_ray*)malloc(count * sizeof(nl_ray));
    nl_ray_hit* hits[2];
    int w, i, wrong = 0;
    g_section = "ray batches";
    hits[0] = (nl_ray_hit*)malloc(count * sizeof(nl_ray_hit));
    hits[1] = (nl_ray_hit*)malloc(count * sizeof(nl_ray_hit));
    if (!rays || !hits[0] || !hits[1]) {
        CHECK(!"out of memory");
        return;
    }
    worlds[0] = make_world(1);
    worlds[1] = make_world(2);
    for (i = 0; i < count; ++i) {
        /* Grid points strictly inside the floor, never on the diagonal z = x. */
        const float x = -9.5f + 19.0f * (float)(i % side) / (float)(side - 1);
        const float z = -9.3f + 18.7f * (float)(i / side) / (float)(side - 1);
        rays[i] = down_ray(x, z, 3.0f + (float)(i % 7), INFINITY);
    }
    for (w = 0; w < 2; ++w) {
        nl_mesh_def def = floor_def();
        nl_mesh_id id = {0u, 0u};
        CHECK_OK(nl_mesh_add(worlds[w], &def, &id));
        CHECK_OK(nl_world_cast_rays(worlds[w], rays, count, hits[w]));
        for (i = 0; i < count; ++i) {
            const nl_ray_hit* h = &hits[w][i];
            const float expected = rays[i].origin[1] - 1.0f;
            const uint32_t triangle = rays[i].origin[2] > rays[i].origin[0] ? 0u : 1u;
            if (h->hit != 1 || fabsf(h->distance - expected) > TOL || fabsf(h->point[0] - rays[i].origin[0]) > TOL ||
                fabsf(h->point[2] - rays[i].origin[2]) > TOL || h->triangle != triangle || !same_id(h->mesh, id)) {
                ++wrong;
            }
        }
    }
    CHECK_MSG(wrong == 0, "%d of %d batched rays were wrong", wrong, 2 * count);
    /* Deterministic across worker counts; only the mesh ids differ, as each world tags its own. */
    for (i = 0; i < count; ++i) {
        memset(&hits[0][i].mesh, 0, sizeof hits[0][i].mesh);
        memset(&hits[1][i].mesh, 0, sizeof hits[1][i].mesh);
    }
    CHECK(memcmp(hits[0], hits[1], count * sizeof(nl_ray_hit)) == 0);
    nl_world_destroy(worlds[0]);
    nl_world_destroy(worlds[1]);
    free(rays);
    free(hits[0]);
    free(hits[1]);
}

static nl_segment segment(float x0, float y0, float z0, float x1, float y1, float z1) {
    nl_segment s;
    s.from[0] = x0, s.from[1] = y0, s.from[2] = z0;
    s.to[0] = x1, s.to[1] = y1, s.to[2] = z1;
    return s;
}

static void test_segments(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_segment s[7];
    uint8_t blocked[7];
    g_section = "segments";

    CHECK_OK(nl_mesh_add(world, &def, &floor));
    s[0] = segment(0.5f, 5.0f, 0.25f, 0.5f, -5.0f, 0.25f); /* through the floor */
    s[1] = segment(0.5f, 5.0f, 0.25f, 3.0f, 6.0f, 2.0f);   /* above it */
    s[2] = segment(0.5f, 1.0f, 0.25f, 0.5f, 1.0f, 0.25f);  /* zero length, on the floor */
    s[3] = segment(0.5f, 5.0f, 0.25f, 0.5f, 1.5f, 0.25f);  /* stops short */
    s[4] = segment(0.5f, -2.0f, 0.25f, 0.5f, 0.5f, 0.25f); /* below, stops short */
    s[5] = segment(0.5f, -5.0f, 0.25f, 0.5f, 5.0f, 0.25f); /* through, from below */
    s[6] = segment(-20.0f, 5.0f, 0.0f, 20.0f, -5.0f, 0.0f); /* slanted, crosses at x = 8 */
    memset(blocked, 0xab, sizeof blocked);
    CHECK_OK(nl_world_segments_blocked(world, s, 7, blocked));
    CHECK(blocked[0] == 1);
    CHECK(blocked[1] == 0);
    CHECK(blocked[2] == 0);
    CHECK(blocked[3] == 0);
    CHECK(blocked[4] == 0);
    CHECK(blocked[5] == 1);
    CHECK(blocked[6] == 1);

    memset(blocked, 0xab, sizeof blocked);
    CHECK_OK(nl_world_segments_blocked(world, s, 0, blocked));
    CHECK(all_bytes(blocked, sizeof blocked, 0xab));
    CHECK_OK(nl_world_segments_blocked(world, NULL, 0, NULL));

    s[1].to[2] = NAN;
    CHECK_INVALID(nl_world_segments_blocked(world, s, 7, blocked), "segments[1]");
    CHECK(all_bytes(blocked, sizeof blocked, 0xab));
    s[1].to[2] = 2.0f;
    s[4].from[0] = -INFINITY;
    CHECK_INVALID(nl_world_segments_blocked(world, s, 7, blocked), "segments[4]");
    CHECK(all_bytes(blocked, sizeof blocked, 0xab));
    s[4].from[0] = 0.5f;
    CHECK_INVALID(nl_world_segments_blocked(world, NULL, 1, blocked), "segments");
    CHECK_INVALID(nl_world_segments_blocked(world, s, 1, NULL), "out_blocked");
    CHECK_INVALID(nl_world_segments_blocked(NULL, s, 1, blocked), "world");

    CHECK_OK(nl_mesh_remove(world, floor));
    CHECK_OK(nl_world_segments_blocked(world, s, 1, blocked));
    CHECK(blocked[0] == 0);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Moving meshes
 * ------------------------------------------------------------------------------------------- */

static void test_move(uint32_t flags) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h;
    float m[16];
    g_section = flags & NL_MESH_MOVABLE ? "move (movable)" : "move (static, re-upload)";

    def.flags = flags;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.distance, 4.0f, TOL);

    /* Up by 2: the floor is at y = 3. */
    translation(m, 0.0f, 2.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 1);
    CHECK_NEAR(h.distance, 2.0f, TOL);
    CHECK_NEAR(h.point[1], 3.0f, TOL);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.transform[13] == 2.0f);
    CHECK(info.bounds_min[1] == 3.0f && info.bounds_max[1] == 3.0f);
    CHECK(info.flags == flags);

    /* Sideways by 30 in x: the old place is empty, the new one is hit. */
    translation(m, 30.0f, 0.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 0);
    h = cast_down(world, 30.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id));
    CHECK_NEAR(h.distance, 4.0f, TOL);
    CHECK_NEAR(h.point[0], 30.5f, TOL);

    /* Turned upside down (180 degrees about X) and scaled by 2 in x: normal -Y, the floor at y = -1,
       reaching x = 20. The world point (15, -1, 0.25) is object (7.5, 1, -0.25): triangle 1. */
    memcpy(m, k_identity, sizeof m);
    m[0] = 2.0f;
    m[5] = -1.0f;
    m[10] = -1.0f;
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 15.0f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 1);
    CHECK_NEAR(h.distance, 6.0f, TOL);
    CHECK_NEAR(h.point[1], -1.0f, TOL);
    CHECK_NEAR(h.normal[0], 0.0f, TOL);
    CHECK_NEAR(h.normal[1], -1.0f, TOL);
    CHECK_NEAR(h.normal[2], 0.0f, TOL);
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.bounds_min[0] == -20.0f && info.bounds_max[0] == 20.0f && info.bounds_min[1] == -1.0f);

    /* A rejected transform changes nothing. */
    memcpy(m, k_identity, sizeof m);
    m[7] = 1.0f; /* row 3, column 1 */
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    m[7] = 0.0f;
    m[10] = 0.0f; /* singular */
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    m[10] = 1.0f;
    m[14] = NAN;
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    CHECK_INVALID(nl_mesh_set_transform(world, id, NULL), "transform");
    h = cast_down(world, 15.0f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.point[1], -1.0f, TOL);
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.transform[0] == 2.0f && info.transform[5] == -1.0f && info.transform[14] == 0.0f);

    /* Back to identity, then removal. */
    CHECK_OK(nl_mesh_set_transform(world, id, k_identity));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    CHECK_NEAR(h.distance, 4.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, id));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 0);
    nl_world_destroy(world);
}

/* A static and a movable mesh together: each hit resolves to the right id after edits. */
static void test_mixed_scene(void) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id a = {0u, 0u}, b = {0u, 0u}, c = {0u, 0u};
    float m[16];
    nl_ray_hit h;
    g_section = "mixed scene";

    CHECK_OK(nl_mesh_add(world, &def, &a)); /* static, y = 1 */
    translation(m, 0.0f, 2.0f, 0.0f);
    def.transform = m;
    def.flags = NL_MESH_MOVABLE;
    CHECK_OK(nl_mesh_add(world, &def, &b)); /* movable, y = 3 */
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, b));
    CHECK_NEAR(h.point[1], 3.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, b));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, a));
    CHECK_NEAR(h.point[1], 1.0f, TOL);
    translation(m, 0.0f, 1.0f, 0.0f);
    def.flags = 0; /* static, y = 2, may take b's slot */
    CHECK_OK(nl_mesh_add(world, &def, &c));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, c));
    CHECK_NEAR(h.point[1], 2.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, a));
    translation(m, 0.0f, -3.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, c, m)); /* y = -2 */
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, c));
    CHECK_NEAR(h.point[1], -2.0f, TOL);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * OBJ
 * ------------------------------------------------------------------------------------------- */

static const char k_quad_obj[] =
    "# a quad, counter-clockwise from above, at y = 1\n"
    "o floor\n"
    "v -10 1 -10\n"
    "v -10 1 10\n"
    "v 10 1 10\n"
    "v 10 1 -10\n"
    "vn 0 1 0\n"
    "usemtl none\n"
    "f 1 2 3 4\n";

#define CHECK_PARSE_ERROR(world, text, length) check_parse_error((world), (text), (length), __FILE__, __LINE__)
static void check_parse_error(nl_world* world, const char* text, size_t length, const char* file, int line) {
    const uint32_t before = mesh_count(world);
    nl_mesh_id out = {77u, 77u};
    const nl_status status = nl_mesh_add_obj_memory(world, text, length, NULL, &out);
    check_at(status == (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR) && nl_get_last_status() == status &&
                 strstr(nl_get_last_error_message(), "nl_mesh_add_obj_memory") != NULL,
             file, line, "OBJ text gave 0x%08x (%s), expected a parse error: \"%.*s\"", (unsigned)status,
             nl_status_string(status), (int)(length > 60 ? 60 : length), text ? text : "");
    check_at(out.index1 == 77u && out.generation == 77u && mesh_count(world) == before, file, line,
             "a malformed OBJ registered something");
}

static void test_obj(void) {
    nl_world* world = make_world(1);
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h;
    g_section = "obj";

    CHECK_OK(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), NULL, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.vertex_count == 4);
    CHECK(info.triangle_count == 2); /* the quad, fan-triangulated */
    CHECK(info.degenerate_triangle_count == 0);
    CHECK(info.bounds_min[0] == -10.0f && info.bounds_max[2] == 10.0f && info.bounds_min[1] == 1.0f);
    h = cast_down(world, -2.0f, 3.0f); /* fan (1 2 3), (1 3 4): the same triangles as the floor */
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 0);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    h = cast_down(world, 3.0f, -2.0f);
    CHECK(h.hit == 1 && h.triangle == 1);
    CHECK_OK(nl_mesh_remove(world, id));

    /* The text is `length` bytes, not NUL-terminated: what follows is not read. */
    {
        char buffer[sizeof k_quad_obj + 16];
        memcpy(buffer, k_quad_obj, strlen(k_quad_obj));
        memcpy(buffer + strlen(k_quad_obj), "f 1 2 99\nf 7 8", 15); /* would be malformed */
        CHECK_OK(nl_mesh_add_obj_memory(world, buffer, strlen(k_quad_obj), NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.triangle_count == 2);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* Relative (negative) indices, a pentagon (3 triangles) and a triangle, CRLF line ends. */
    {
        static const char text[] = "v 0 0 0\r\nv 1 0 0\r\nv 1 0 1\r\nv 0.5 0 1.5\r\nv 0 0 1\r\n"
                                   "f -5 -1 -2 -3 -4\r\nf 1 3 2\r\n";
        CHECK_OK(nl_mesh_add_obj_memory(world, text, sizeof text - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 5 && info.triangle_count + info.degenerate_triangle_count == 4);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* Texture and normal indices are accepted (and ignored); several objects make one mesh. */
    {
        static const char with_vt_vn[] = "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nvt 0 0\nvn 0 1 0\n"
                                         "usemtl stone\ns off\nf 1/1/1 3/1/1 2/1/1\nl 1 2\n";
        static const char two_objects[] = "o a\nv 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 3\n"
                                          "o b\ng part\nv 0 1 0\nv 1 1 0\nv 1 1 1\nf 4 5 6\nf -3 -2 -1\n";
        CHECK_OK(nl_mesh_add_obj_memory(world, with_vt_vn, sizeof with_vt_vn - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 3 && info.triangle_count == 1);
        CHECK_OK(nl_mesh_remove(world, id));
        CHECK_OK(nl_mesh_add_obj_memory(world, two_objects, sizeof two_objects - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 6 && info.triangle_count + info.degenerate_triangle_count == 3);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* A def's flags, transform and user_data apply. */
    {
        nl_mesh_def def = nl_default_mesh_def();
        float m[16];
        translation(m, 0.0f, 4.0f, 0.0f);
        def.transform = m;
        def.flags = NL_MESH_MOVABLE;
        def.user_data = 99u;
        CHECK_OK(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.flags == NL_MESH_MOVABLE && info.user_data == 99u && info.transform[13] == 4.0f);
        CHECK(info.bounds_min[1] == 5.0f);
        CHECK_OK(nl_mesh_remove(world, id));
        /* ... but not geometry, a bad size, or a bad transform. */
        def.vertex_count = 3;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "def");
        def.vertex_count = 0;
        def.size = 0;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "size");
        def.size = sizeof def;
        m[3] = 1.0f;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "transform");
        def.transform = NULL;
        def.flags = 0x40u;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "flags");
        CHECK(mesh_count(world) == 0);
    }

    /* Malformed text: a parse error, nothing registered. */
    {
        static const char out_of_range[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 99\n";
        static const char before_first[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf -9 1 2\n";
        static const char garbage[] = "this is not an OBJ file\n\x01\x02\x03 {}[] 12 34\n";
        static const char no_faces[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\n";
        static const char zero_index[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 0 1 2\n";
        static const char letter_index[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf a b c\n";
        static const char missing_texcoord[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1/5 3/5 2/5\n";
        CHECK_PARSE_ERROR(world, zero_index, sizeof zero_index - 1);
        CHECK_PARSE_ERROR(world, letter_index, sizeof letter_index - 1);
        CHECK_PARSE_ERROR(world, missing_texcoord, sizeof missing_texcoord - 1);
        CHECK_PARSE_ERROR(world, out_of_range, sizeof out_of_range - 1);
        CHECK_PARSE_ERROR(world, before_first, sizeof before_first - 1);
        CHECK_PARSE_ERROR(world, garbage, sizeof garbage - 1);
        CHECK_PARSE_ERROR(world, no_faces, sizeof no_faces - 1);
        CHECK_PARSE_ERROR(world, "", 0);
        CHECK_PARSE_ERROR(world, NULL, 0);
        {
            /* A coordinate that is not a number must not load as 0. */
            static const char bad_number[] = "v abc 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 3\n";
            nl_mesh_id out = {0u, 0u};
            const nl_status st = nl_mesh_add_obj_memory(world, bad_number, sizeof bad_number - 1, NULL, &out);
            CHECK_THAT(st == (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR),
                        "nl_mesh_add_obj_memory: a coordinate that is not a number (\"v abc 0 0\") is a PARSE_ERROR, not 0");
            if (NL_SUCCEEDED(st)) nl_mesh_remove(world, out);
        }
    }

    /* Files: written next to the test, then read back. */
    {
        const char* path = "navlink_c_api_test_quad.obj";
        FILE* f = fopen(path, "wb");
        CHECK(f != NULL);
        if (f) {
            fputs(k_quad_obj, f);
            fclose(f);
            id.index1 = 0;
            CHECK_OK(nl_mesh_add_obj_file(world, path, NULL, &id));
            CHECK(nl_mesh_is_valid(world, id) == 1);
            CHECK_OK(nl_mesh_get_info(world, id, &info));
            CHECK(info.vertex_count == 4 && info.triangle_count == 2);
            CHECK_OK(nl_mesh_remove(world, id));
            remove(path);
        }
    }
    {
        nl_mesh_id out = {77u, 77u};
        CHECK_FAIL(nl_mesh_add_obj_file(world, "no/such/dir/missing-level.obj", NULL, &out), NL_STATUS_NOT_FOUND,
                   "missing-level.obj");
        CHECK(out.index1 == 77u && out.generation == 77u);
        CHECK_FAIL(nl_mesh_add_obj_file(world, "", NULL, &out), NL_STATUS_NOT_FOUND, "nl_mesh_add_obj_file");
        /* A directory cannot be read as a file, and a file that fails while it is read (/proc/self/mem
           from offset 0: EIO) is an I/O error, not a parse error of the bytes read before. */
        CHECK_FAIL(nl_mesh_add_obj_file(world, ".", NULL, &out), NL_STATUS_IO_ERROR, "directory");
        {
            FILE* mem = fopen("/proc/self/mem", "rb");
            if (mem) {
                fclose(mem);
                CHECK_FAIL(nl_mesh_add_obj_file(world, "/proc/self/mem", NULL, &out), NL_STATUS_IO_ERROR,
                           "cannot read '/proc/self/mem'");
            }
        }
        CHECK(mesh_count(world) == 0);

        /* Null pointers. */
        CHECK_INVALID(nl_mesh_add_obj_file(world, NULL, NULL, &out), "path");
        CHECK_INVALID(nl_mesh_add_obj_file(world, "x.obj", NULL, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add_obj_file(NULL, "x.obj", NULL, &out), "world");
        CHECK_INVALID(nl_mesh_add_obj_memory(world, NULL, 10, NULL, &out), "data");
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), NULL, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add_obj_memory(NULL, k_quad_obj, strlen(k_quad_obj), NULL, &out), "world");
        CHECK(out.index1 == 77u && out.generation == 77u);
    }
    CHECK(mesh_count(world) == 0);
    nl_world_destroy(world);
}

/* Counts the vertices and the fan triangles of an OBJ file (faces of n corners give n - 2). */
static int count_obj(const char* path, unsigned long* vertices, unsigned long* triangles) {
    char line[4096];
    FILE* f = fopen(path, "rb");
    *vertices = *triangles = 0;
    if (!f) return 0;
    while (fgets(line, sizeof line, f)) {
        const char* p = line;
        while (*p == ' ' || *p == '\t') ++p;
        if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            ++*vertices;
        } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            unsigned long corners = 0;
            ++p;
            for (;;) {
                while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
                if (*p == '\0' || *p == '#') break;
                ++corners;
                while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') ++p;
            }
            if (corners >= 3) *triangles += corners - 2;
        }
    }
    fclose(f);
    return 1;
}

static void test_dungeon(const char* levels_dir) {
    char path[4096];
    unsigned long vertices = 0, triangles = 0;
    nl_world* world;
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    g_section = "dungeon.obj";
    snprintf(path, sizeof path, "%s/dungeon.obj", levels_dir);
    if (!CHECK_MSG(count_obj(path, &vertices, &triangles), "cannot read %s", path)) return;
    CHECK(triangles == 10133); /* the README's figure */
    world = make_world(NL_WORKERS_AUTO);
    CHECK_OK(nl_mesh_add_obj_file(world, path, NULL, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK_MSG(info.vertex_count == vertices, "vertex_count %u, the file has %lu", (unsigned)info.vertex_count, vertices);
    CHECK_MSG(info.triangle_count + info.degenerate_triangle_count == triangles,
              "%u kept + %u degenerate triangles, the file's faces fan into %lu", (unsigned)info.triangle_count,
              (unsigned)info.degenerate_triangle_count, triangles);
    CHECK(info.triangle_count > 0 && info.bounds_min[1] < info.bounds_max[1]);
    {
        /* A ray down through the middle of the level finds something. */
        nl_ray r;
        nl_ray_hit h;
        r.origin[0] = 0.5f * (info.bounds_min[0] + info.bounds_max[0]);
        r.origin[1] = info.bounds_max[1] + 1.0f;
        r.origin[2] = 0.5f * (info.bounds_min[2] + info.bounds_max[2]);
        r.direction[0] = 0.0f, r.direction[1] = -1.0f, r.direction[2] = 0.0f;
        r.max_distance = INFINITY;
        CHECK_OK(nl_world_cast_rays(world, &r, 1, &h));
        CHECK(h.hit == 0 || (same_id(h.mesh, id) && h.triangle < triangles));
    }
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Threads: the last error is per thread; queries run beside edits.
 * ------------------------------------------------------------------------------------------- */

typedef struct thread_job {
    nl_world* world;
    int wrong;
    int error_kept;
} thread_job;

static void* query_thread(void* arg) {
    thread_job* job = (thread_job*)arg;
    int i;
    /* This thread's failure stays this thread's. */
    nl_mesh_add(job->world, NULL, NULL);
    for (i = 0; i < 300; ++i) {
        nl_ray rays[16];
        nl_ray_hit hits[16];
        int k;
        for (k = 0; k < 16; ++k) rays[k] = down_ray(-8.0f + (float)k, 0.25f, 5.0f, INFINITY);
        if (NL_FAILED(nl_world_cast_rays(job->world, rays, 16, hits))) {
            ++job->wrong;
            continue;
        }
        for (k = 0; k < 16; ++k) {
            if (hits[k].hit != 1 || fabsf(hits[k].distance - 4.0f) > TOL) ++job->wrong;
        }
    }
    nl_mesh_add(job->world, NULL, NULL);
    job->error_kept = nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) &&
                      strstr(nl_get_last_error_message(), "def") != NULL;
    return NULL;
}

static void test_threads(void) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    thread_job jobs[2];
    pthread_t threads[2];
    int started[2] = {0, 0};
    int i, edits_ok = 1;
    float m[16];
    g_section = "threads";

    CHECK_OK(nl_mesh_add(world, &def, &floor));
    memset(jobs, 0, sizeof jobs);
    for (i = 0; i < 2; ++i) {
        jobs[i].world = world;
        started[i] = pthread_create(&threads[i], NULL, query_thread, &jobs[i]) == 0;
        CHECK(started[i]);
    }
    /* Meanwhile: add, move and remove meshes far away from the queried floor. */
    translation(m, 100.0f, 0.0f, 0.0f);
    def.transform = m;
    for (i = 0; i < 100; ++i) {
        nl_mesh_id id = {0u, 0u};
        def.flags = (i & 1) ? NL_MESH_MOVABLE : 0u;
        if (NL_FAILED(nl_mesh_add(world, &def, &id))) edits_ok = 0;
        m[14] = (float)i;
        if (NL_FAILED(nl_mesh_set_transform(world, id, m))) edits_ok = 0;
        if (NL_FAILED(nl_mesh_remove(world, id))) edits_ok = 0;
    }
    CHECK(edits_ok);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS && nl_get_last_error_message()[0] == '\0');
    for (i = 0; i < 2; ++i) {
        if (started[i]) pthread_join(threads[i], NULL);
        CHECK_MSG(jobs[i].wrong == 0, "thread %d saw %d wrong hits", i, jobs[i].wrong);
        CHECK(!started[i] || jobs[i].error_kept);
    }
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS); /* the threads' failures did not leak here */
    CHECK(mesh_count(world) == 1);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Null arguments of every function, on a live world.
 * ------------------------------------------------------------------------------------------- */

static void test_null_world_everywhere(void) {
    const nl_mesh_id id = {1u, 1u};
    nl_mesh_def def = floor_def();
    nl_mesh_info info;
    nl_mesh_id out = {0u, 0u};
    uint32_t count = 0;
    nl_ray r = down_ray(0.0f, 0.0f, 5.0f, INFINITY);
    nl_ray_hit h;
    nl_segment s = segment(0, 0, 0, 1, 1, 1);
    uint8_t blocked = 0;
    g_section = "null world";
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

/* ---------------------------------------------------------------------------------------------
 * Awkward edges of the contract
 * ------------------------------------------------------------------------------------------- */

static void test_edges(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_ray r;
    nl_ray_hit h;
    g_section = "edges";
    CHECK_OK(nl_mesh_add(world, &def, &floor));

    /* "any nonzero length": a direction with a huge or tiny but finite, nonzero length. */
    r = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
    r.direction[1] = -3.0e38f;
    CHECK_THAT(nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1,
                "nl_world_cast_rays: a finite direction of length 3e38 is accepted");
    r.direction[1] = -1.0e-30f;
    CHECK_THAT(nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1,
                "nl_world_cast_rays: a nonzero direction of length 1e-30 is accepted");

    /* The header's example message names the def's field ("def->indices[7] = 120 is out of range"). */
    {
        uint32_t indices[6];
        nl_mesh_id out = {0u, 0u};
        memcpy(indices, k_floor_indices, sizeof indices);
        indices[4] = 120;
        def.indices = indices;
        (void)nl_mesh_add(world, &def, &out);
        CHECK_THAT(strstr(nl_get_last_error_message(), "def->indices[4] = 120") != NULL,
                    "nl_mesh_add: an index out of range is named as the def's field, \"def->indices[4] = 120\"");
        def.indices = k_floor_indices;
    }

    /* A mirroring transform (determinant < 0): the normal follows the world-space winding, whatever the
       flags. Mirrored in x, the floor's world-space triangles wind clockwise seen from above: normal -Y. */
    {
        static const float mirror_x[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        nl_world* mirrored[2];
        nl_ray_hit hits[2];
        int k;
        for (k = 0; k < 2; ++k) {
            nl_mesh_id out = {0u, 0u};
            mirrored[k] = make_world(1);
            def = floor_def();
            def.flags = k ? NL_MESH_MOVABLE : 0u;
            def.transform = mirror_x;
            CHECK_OK(nl_mesh_add(mirrored[k], &def, &out));
            hits[k] = cast_down(mirrored[k], 0.5f, 0.25f);
            CHECK(hits[k].hit == 1);
            CHECK_NEAR(hits[k].distance, 4.0f, TOL);
            nl_world_destroy(mirrored[k]);
        }
        CHECK_NEAR(hits[0].normal[1], -1.0f, TOL); /* static: from the uploaded world-space triangles */
        CHECK_THAT(fabsf(hits[1].normal[1] - hits[0].normal[1]) <= TOL,
                    "nl_world_cast_rays: under a mirroring transform a NL_MESH_MOVABLE mesh reports the same normal "
                    "as the same mesh added static");
    }

    /* Ids of one world used on another: the header lists "from another world" under INVALID_HANDLE. */
    {
        nl_world* other = make_world(1);
        nl_mesh_id mine = {0u, 0u}, theirs = {0u, 0u};
        def = floor_def();
        CHECK_OK(nl_mesh_add(other, &def, &theirs));
        CHECK(nl_mesh_is_valid(world, floor) == 1);
        mine = floor;
        CHECK_THAT(!same_id(mine, theirs) ? nl_mesh_is_valid(other, mine) == 0 : 0,
                    "an id from another world is not valid here");
        nl_world_destroy(other);
    }
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Cases that may crash the process, each run in a child process (forked before any NavLink thread
 * exists). A crash is a failed check, never the end of the test run.
 * ------------------------------------------------------------------------------------------- */

typedef int isolated_case(nl_world* world);

/* Runs `fn` on a fresh world holding the floor in a child; returns 1 if the child returned normally
   and `fn` said its expectation held, 0 if not, -1 if it crashed. */
static int run_isolated(isolated_case* fn) {
    pid_t pid;
    int status = 0;
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        nl_world* world = make_world(1);
        nl_mesh_def def = floor_def();
        nl_mesh_id id = {0u, 0u};
        int ok;
        if (!freopen("/dev/null", "w", stderr)) { /* a library's abort message is not this test's output */
        }
        ok = NL_SUCCEEDED(nl_mesh_add(world, &def, &id)) && fn(world);
        nl_world_destroy(world);
        _exit(ok ? 0 : 1);
    }
    if (waitpid(pid, &status, 0) != pid) return 0;
    if (WIFSIGNALED(status)) return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 1 : 0;
}

/* Accepted outcomes: rejected naming the ray, or a clean answer. */
static int huge_ray_origin(nl_world* world) {
    nl_ray r = down_ray(1.0e19f, 0.25f, 5.0f, INFINITY);
    nl_ray_hit h;
    const nl_status st = nl_world_cast_rays(world, &r, 1, &h);
    return st == NL_STATUS_SUCCESS ? h.hit == 0
                                   : strstr(nl_get_last_error_message(), "rays[0]") != NULL;
}

static int huge_segment(nl_world* world) {
    const nl_segment s = segment(0.5f, -1.0e19f, 0.25f, 0.5f, 1.0e19f, 0.25f);
    uint8_t blocked = 7;
    const nl_status st = nl_world_segments_blocked(world, &s, 1, &blocked);
    return st == NL_STATUS_SUCCESS ? blocked == 1 : strstr(nl_get_last_error_message(), "segments[0]") != NULL;
}

static int overflowing_segment(nl_world* world) {
    const nl_segment s = segment(0.5f, -3.0e38f, 0.25f, 0.5f, 3.0e38f, 0.25f); /* to - from overflows */
    uint8_t blocked = 7;
    const nl_status st = nl_world_segments_blocked(world, &s, 1, &blocked);
    return st == NL_STATUS_SUCCESS ? blocked == 1 : strstr(nl_get_last_error_message(), "segments[0]") != NULL;
}

static int moderate_coordinates(nl_world* world) {
    /* Large numbers within NL_COORDINATE_LIMIT: 1e6 m away, 2e9 m long. */
    nl_ray r = down_ray(0.5f, 0.25f, 1.0e6f, INFINITY);
    nl_ray_hit h;
    const nl_segment s = segment(0.5f, 1.0e9f, 0.25f, 0.5f, -1.0e9f, 0.25f);
    uint8_t blocked = 7;
    return nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1 &&
           nl_world_segments_blocked(world, &s, 1, &blocked) == NL_STATUS_SUCCESS && blocked == 1;
}

static void test_isolated(void) {
    int result;
    g_section = "isolated";
    result = run_isolated(moderate_coordinates);
    CHECK_MSG(result == 1, "rays and segments with coordinates around 1e6..1e9 (%s)",
              result < 0 ? "crashed" : "wrong answer");
    CHECK_THAT(run_isolated(huge_ray_origin) == 1,
                "nl_world_cast_rays: an origin of 1e19 is refused, not a crash");
    CHECK_THAT(run_isolated(huge_segment) == 1,
                "nl_world_segments_blocked: ends at +-1e19 are refused, not a crash");
    CHECK_THAT(run_isolated(overflowing_segment) == 1,
                "nl_world_segments_blocked: ends at +-3e38 are refused, not a crash");
}

/* Links: generation, the link store, JSON (c_api_links_test.c). */
void test_links_all(void);

int main(int argc, char** argv) {

    /* First, while this process has no threads (fork() copies only the calling thread). */
    test_isolated();
    test_navmesh_isolated();
    test_version_and_status();
    test_world();
    test_mesh_add_and_info();
    test_degenerate();
    test_mesh_rejections();
    test_get_meshes();
    test_stale_ids();
    test_world_tags_never_repeat_while_alive();
    test_world_limit();
    test_rays();
    test_ray_batches();
    test_segments();
    test_move(NL_MESH_MOVABLE);
    test_move(0u);
    test_mixed_scene();
    test_obj();
    test_threads();
    test_null_world_everywhere();
    test_edges();
    test_navmesh_all();
    test_links_all();
    test_paths_all();
    if (argc > 1 && argv[1][0] != '\0') {
        test_dungeon(argv[1]);
    } else {
        printf("note: no levels directory given, dungeon.obj not checked\n");
    }

    printf("%d passed, %d failed\n", g_passed, g_failed);
    return g_failed == 0 ? 0 : 1;
}
