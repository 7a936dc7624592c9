/*
 * Ray queries (navlink.h): nl_world_cast_rays and nl_world_segments_blocked on the floor of
 * floor_scene.h, in batches over one and two workers, beside mesh edits on other threads, and at
 * extreme coordinates in a child process.
 */
/* pthread for the querying threads; fork() and waitpid() for the cases that may crash the process;
   strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "floor_scene.h"
#include "scene.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

static void cast_rays(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_ray rays[4];
    nl_ray_hit hits[4];
    hits[0] = nl_ray_hit_init();

    CHECK_OK(nl_mesh_add(world, &def, &floor));

    /* Straight down onto triangle 0 (z > x) and triangle 1 (z < x). */
    rays[0] = down_ray(-2.0f, 3.0f, 5.0f, INFINITY);
    rays[1] = down_ray(3.0f, -2.0f, 5.0f, 100.0f);
    rays[1].direction[1] = -7.0f; /* any length */
    memset(hits, 0xab, sizeof hits);
    hits[0].size = sizeof hits[0]; /* the element size the library lays out with */
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
    hits[0].size = sizeof hits[0]; /* the element size the library lays out with */
    CHECK_OK(nl_world_cast_rays(world, rays, 4, hits));
    CHECK(hits[0].hit == 0 && hits[1].hit == 0 && hits[2].hit == 0);
    /* A miss is all zero but its size, which is the host's. */
    CHECK(hits[0].size == sizeof hits[0] && hits[1].size == sizeof hits[1] && hits[2].size == sizeof hits[2]);
    CHECK(all_bytes(&hits[0].distance, sizeof hits[0] - sizeof(uint32_t), 0) &&
          all_bytes(&hits[1].distance, sizeof hits[1] - sizeof(uint32_t), 0) &&
          all_bytes(&hits[2].distance, sizeof hits[2] - sizeof(uint32_t), 0));
    CHECK(hits[3].hit == 1 && same_id(hits[3].mesh, floor));
    CHECK_NEAR(hits[3].distance, 4.0f, TOL);
    CHECK(hits[3].reserved[0] == 0 && hits[3].reserved[1] == 0 && hits[3].reserved[2] == 0);

    /* count == 0 succeeds and touches nothing, even with null arrays. */
    memset(hits, 0xab, sizeof hits);
    hits[0].size = sizeof hits[0]; /* the element size the library lays out with */
    CHECK_OK(nl_world_cast_rays(world, rays, 0, hits));
    CHECK(all_bytes((const unsigned char*)hits + sizeof(uint32_t), sizeof hits - sizeof(uint32_t), 0xab));
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
            {1, 0, 0.0f, "rays[1]"},                           /* NaN origin, value replaced below */
            {2, 0, 1.0f, "rays[2]"},                           /* infinite origin */
            {0, 1, 0.0f, "rays[0]"},                           /* zero direction */
            {3, 1, 1.0f, "rays[3]"},                           /* infinite direction */
            {2, 1, 2.0f, "rays[2]"},                           /* NaN direction */
            {1, 2, 0.0f, "rays[1]"},                           /* max_distance 0 */
            {0, 2, -1.0f, "rays[0]"}, {3, 2, 2.0f, "rays[3]"}, /* max_distance NaN */
            {2, 2, -3.0f, "rays[2]"},                          /* -INFINITY */
        };
        size_t b;
        for (b = 0; b < sizeof bad / sizeof bad[0]; ++b) {
            int k;
            for (k = 0; k < 4; ++k) rays[k] = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
            if (bad[b].field == 0) {
                rays[bad[b].index].origin[1] = bad[b].value == 0.0f ? NAN : INFINITY;
            } else if (bad[b].field == 1) {
                float* d = rays[bad[b].index].direction;
                if (bad[b].value == 0.0f)
                    d[0] = d[1] = d[2] = 0.0f;
                else if (bad[b].value == 1.0f)
                    d[2] = INFINITY;
                else
                    d[0] = NAN;
            } else {
                float v = bad[b].value;
                if (v == 2.0f) v = NAN;
                if (v == -3.0f) v = -INFINITY;
                rays[bad[b].index].max_distance = v;
            }
            memset(hits, 0xab, sizeof hits);
            hits[0].size = sizeof hits[0]; /* the element size the library lays out with */
            CHECK_INVALID(nl_world_cast_rays(world, rays, 4, hits), bad[b].needle);
            CHECK_MSG(all_bytes((const unsigned char*)hits + sizeof(uint32_t), sizeof hits - sizeof(uint32_t), 0xab),
                      "hits written on failure (case %d)", (int)b);
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
static void ray_batches(void) {
    enum { side = 48, count = side * side };
    nl_world* worlds[2];
    nl_ray* rays = (nl_ray*)malloc(count * sizeof(nl_ray));
    nl_ray_hit* hits[2];
    int w, i, wrong = 0;
    hits[0] = (nl_ray_hit*)malloc(count * sizeof(nl_ray_hit));
    hits[1] = (nl_ray_hit*)malloc(count * sizeof(nl_ray_hit));
    if (!rays || !hits[0] || !hits[1]) {
        CHECK(!"out of memory");
        return;
    }
    hits[0][0] = nl_ray_hit_init();
    hits[1][0] = nl_ray_hit_init();
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

static void segments_blocked(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_segment s[7];
    uint8_t blocked[7];

    CHECK_OK(nl_mesh_add(world, &def, &floor));
    s[0] = segment(0.5f, 5.0f, 0.25f, 0.5f, -5.0f, 0.25f);  /* through the floor */
    s[1] = segment(0.5f, 5.0f, 0.25f, 3.0f, 6.0f, 2.0f);    /* above it */
    s[2] = segment(0.5f, 1.0f, 0.25f, 0.5f, 1.0f, 0.25f);   /* zero length, on the floor */
    s[3] = segment(0.5f, 5.0f, 0.25f, 0.5f, 1.5f, 0.25f);   /* stops short */
    s[4] = segment(0.5f, -2.0f, 0.25f, 0.5f, 0.5f, 0.25f);  /* below, stops short */
    s[5] = segment(0.5f, -5.0f, 0.25f, 0.5f, 5.0f, 0.25f);  /* through, from below */
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

/* Threads: the last error is per thread; queries run beside edits. */
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
        hits[0] = nl_ray_hit_init();
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

static void queries_beside_edits_on_threads(void) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    thread_job jobs[2];
    pthread_t threads[2];
    int started[2] = {0, 0};
    int i, edits_ok = 1;
    float m[16];

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

/* Awkward edges of the contract: directions of extreme lengths, normals under a mirroring transform. */
static void contract_edges(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    nl_ray r;
    nl_ray_hit h = nl_ray_hit_init();
    CHECK_OK(nl_mesh_add(world, &def, &floor));

    /* "any nonzero length": a direction with a huge or tiny but finite, nonzero length. */
    r = down_ray(0.5f, 0.25f, 5.0f, INFINITY);
    r.direction[1] = -3.0e38f;
    CHECK_THAT(nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1,
               "nl_world_cast_rays: a finite direction of length 3e38 is accepted");
    r.direction[1] = -1.0e-30f;
    CHECK_THAT(nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1,
               "nl_world_cast_rays: a nonzero direction of length 1e-30 is accepted");

    /* A mirroring transform (determinant < 0): the normal follows the world-space winding, whatever the
       flags. Mirrored in x, the floor's world-space triangles wind clockwise seen from above: normal -Y. */
    {
        static const float mirror_x[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        nl_world* mirrored[2];
        nl_ray_hit hits[2];
        hits[0] = nl_ray_hit_init();
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
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Cases that may crash the process, each run in a child process (forked before any NavLink thread
 * exists: the case forks before it makes a world). A crash is a failed check, never the end of the
 * case.
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
    nl_ray_hit h = nl_ray_hit_init();
    const nl_status st = nl_world_cast_rays(world, &r, 1, &h);
    return st == NL_STATUS_SUCCESS ? h.hit == 0 : strstr(nl_get_last_error_message(), "rays[0]") != NULL;
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
    nl_ray_hit h = nl_ray_hit_init();
    const nl_segment s = segment(0.5f, 1.0e9f, 0.25f, 0.5f, -1.0e9f, 0.25f);
    uint8_t blocked = 7;
    return nl_world_cast_rays(world, &r, 1, &h) == NL_STATUS_SUCCESS && h.hit == 1 &&
           nl_world_segments_blocked(world, &s, 1, &blocked) == NL_STATUS_SUCCESS && blocked == 1;
}

static void extreme_coordinates_in_child(void) {
    int result;
    result = run_isolated(moderate_coordinates);
    CHECK_MSG(result == 1, "rays and segments with coordinates around 1e6..1e9 (%s)",
              result < 0 ? "crashed" : "wrong answer");
    CHECK_THAT(run_isolated(huge_ray_origin) == 1, "nl_world_cast_rays: an origin of 1e19 is refused, not a crash");
    CHECK_THAT(run_isolated(huge_segment) == 1, "nl_world_segments_blocked: ends at +-1e19 are refused, not a crash");
    CHECK_THAT(run_isolated(overflowing_segment) == 1,
               "nl_world_segments_blocked: ends at +-3e38 are refused, not a crash");
}

ABI_SECTION(rays, ABI_CASE(cast_rays), ABI_CASE(ray_batches), ABI_CASE(segments_blocked),
            ABI_CASE(queries_beside_edits_on_threads), ABI_CASE(contract_edges),
            ABI_CASE(extreme_coordinates_in_child));
