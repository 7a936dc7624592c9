/*
 * navlink-c-api-host-tasks-test: a world whose batch work runs on the host's task system
 * (nl_world_def.task_enqueue_fn / task_finish_fn), driven from C11 through libnavlink.so only.
 *
 * The host here is a real one: a pthread pool whose enqueue splits a task into chunks its threads
 * take, and whose finish helps with the chunks of its own task, then waits. Its workers are numbered
 * 1..POOL_THREADS; a thread from outside that waits in finish borrows one of the remaining indices
 * (0 and the ones above the pool's) while it helps. Every world below runs the same level, queries
 * and generation, and must give the same bytes as a world on NavLink's own threads (TBB):
 *   - mesh add, then ray, segment and point-location batches;
 *   - a Recast navmesh build, link generation, an update in a box after a wall is added, a path;
 *   - NavLink called from inside a task of the pool (its enqueue and finish on a pool thread), and
 *     from several host threads at once;
 *   - an inline host (enqueue runs the task at once and returns NULL: finish is never called).
 * It also checks that the callbacks were called, that worker indices stayed below worker_count, that
 * a level call from inside NavLink's finish is refused rather than left to hang, that a host breaking
 * the contract fails the call with INTERNAL_ERROR saying how, that an old def size ignores the task
 * fields, and that bad task fields are refused naming them.
 */
#define _POSIX_C_SOURCE 200809L

#include <navlink/navlink.h>

#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int g_failures = 0;

/* The box from lo to hi as one mesh: 8 corners (corner k at x from bit 0, y from bit 1, z from bit 2),
   12 triangles facing out. (Its own copy, so this file needs no other test file.) */
static nl_status add_box_mesh(nl_world* world, const float lo[3], const float hi[3], uint32_t flags,
                              nl_mesh_id* out_id) {
    const float v[24] = {lo[0], lo[1], lo[2], hi[0], lo[1], lo[2], lo[0], hi[1], lo[2], hi[0], hi[1], lo[2],
                         lo[0], lo[1], hi[2], hi[0], lo[1], hi[2], lo[0], hi[1], hi[2], hi[0], hi[1], hi[2]};
    static const uint32_t box[36] = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                     2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = v;
    def.vertex_count = 8;
    def.indices = box;
    def.triangle_count = 12;
    def.flags = flags;
    return nl_mesh_add(world, &def, out_id);
}

static void check_at(int ok, const char* file, int line, const char* format, ...) {
    va_list args;
    if (ok) return;
    ++g_failures;
    fprintf(stderr, "%s:%d: FAILED: ", file, line);
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fprintf(stderr, "\n");
}
#define CHECK(cond, ...) check_at((cond) != 0, __FILE__, __LINE__, __VA_ARGS__)

/* Stops the test at once: what follows would only repeat the failure. */
#define REQUIRE_OK(call)                                                                                       \
    do {                                                                                                       \
        const nl_status required_ = (call);                                                                    \
        if (NL_FAILED(required_)) {                                                                            \
            fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, nl_get_last_error_message()); \
            exit(1);                                                                                           \
        }                                                                                                      \
    } while (0)

/* ---------------------------------------------------------------------------------------------
 * The host's thread pool
 * ------------------------------------------------------------------------------------------- */

#define POOL_THREADS 2
#define OUTSIDE_SLOTS 3 /* worker indices for threads from outside the pool: 0, POOL_THREADS + 1, ... */
#define POOL_WORKERS (POOL_THREADS + OUTSIDE_SLOTS)

typedef struct pool_job {
    nl_task_fn* task;
    void* context;
    uint32_t count, chunk, next, chunks, done;
    struct pool_job* next_job;
} pool_job;

typedef struct pool {
    pthread_mutex_t mutex;
    pthread_cond_t work, done;
    pool_job* jobs; /* in the order they were enqueued */
    int stop;
    int slot_taken[POOL_WORKERS];
    pthread_t threads[POOL_THREADS];
    /* What the test reads. */
    atomic_uint enqueues, finishes, enqueues_on_pool, ranges, ranges_on_pool, bad_worker, bad_request, clashes;
    atomic_uint max_worker;
    /* Ranges running under each worker index, and the thread running them: one thread per index at a
       time (the same thread may nest: a range that calls NavLink runs NavLink's ranges inside it). */
    pthread_mutex_t owner_mutex;
    int running[POOL_WORKERS];
    pthread_t owner[POOL_WORKERS];
} pool;

static _Thread_local uint32_t t_pool_worker = 0; /* 1..POOL_THREADS on the pool's threads */

static void run_range(pool* p, nl_task_fn* task, void* context, uint32_t begin, uint32_t end, uint32_t worker) {
    uint32_t seen;
    if (worker >= POOL_WORKERS) {
        atomic_fetch_add(&p->bad_worker, 1u);
        return;
    }
    seen = atomic_load(&p->max_worker);
    while (worker > seen && !atomic_compare_exchange_weak(&p->max_worker, &seen, worker)) {}
    pthread_mutex_lock(&p->owner_mutex);
    if (p->running[worker] > 0 && !pthread_equal(p->owner[worker], pthread_self())) atomic_fetch_add(&p->clashes, 1u);
    p->owner[worker] = pthread_self();
    ++p->running[worker];
    pthread_mutex_unlock(&p->owner_mutex);
    atomic_fetch_add(&p->ranges, 1u);
    if (t_pool_worker != 0) atomic_fetch_add(&p->ranges_on_pool, 1u);
    task(context, begin, end, worker);
    pthread_mutex_lock(&p->owner_mutex);
    --p->running[worker];
    pthread_mutex_unlock(&p->owner_mutex);
}

/* With the mutex held: claims the next chunk of `only` (of any job when NULL) and runs it unlocked.
   Returns 0 when there was none. */
static int run_one(pool* p, pool_job* only, uint32_t worker) {
    pool_job* job;
    uint32_t begin, end;
    nl_task_fn* task;
    void* context;
    for (job = p->jobs; job; job = job->next_job)
        if ((!only || job == only) && job->next < job->count) break;
    if (!job) return 0;
    begin = job->next;
    end = job->count - begin > job->chunk ? begin + job->chunk : job->count;
    job->next = end;
    task = job->task;
    context = job->context;
    pthread_mutex_unlock(&p->mutex);
    run_range(p, task, context, begin, end, worker);
    pthread_mutex_lock(&p->mutex);
    if (++job->done == job->chunks) pthread_cond_broadcast(&p->done);
    return 1;
}

typedef struct pool_thread_arg {
    pool* p;
    uint32_t index;
} pool_thread_arg;
static pool_thread_arg g_thread_args[POOL_THREADS];

static void* pool_thread(void* arg) {
    pool_thread_arg* a = (pool_thread_arg*)arg;
    pool* p = a->p;
    t_pool_worker = a->index;
    pthread_mutex_lock(&p->mutex);
    for (;;) {
        if (run_one(p, NULL, a->index)) continue;
        if (p->stop) break;
        pthread_cond_wait(&p->work, &p->mutex);
    }
    pthread_mutex_unlock(&p->mutex);
    return NULL;
}

static void pool_start(pool* p) {
    uint32_t i;
    memset(p, 0, sizeof *p);
    pthread_mutex_init(&p->mutex, NULL);
    pthread_mutex_init(&p->owner_mutex, NULL);
    pthread_cond_init(&p->work, NULL);
    pthread_cond_init(&p->done, NULL);
    for (i = 0; i < POOL_THREADS; ++i) {
        g_thread_args[i].p = p;
        g_thread_args[i].index = i + 1;
        if (pthread_create(&p->threads[i], NULL, pool_thread, &g_thread_args[i]) != 0) {
            fprintf(stderr, "pthread_create failed\n");
            exit(1);
        }
    }
}

static void pool_stop(pool* p) {
    uint32_t i;
    pthread_mutex_lock(&p->mutex);
    p->stop = 1;
    pthread_cond_broadcast(&p->work);
    pthread_mutex_unlock(&p->mutex);
    for (i = 0; i < POOL_THREADS; ++i) pthread_join(p->threads[i], NULL);
    CHECK(p->jobs == NULL, "the pool stopped with jobs left");
    pthread_cond_destroy(&p->done);
    pthread_cond_destroy(&p->work);
    pthread_mutex_destroy(&p->owner_mutex);
    pthread_mutex_destroy(&p->mutex);
}

/* nl_task_enqueue_fn */
static void* pool_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count, uint32_t min_range) {
    pool* p = (pool*)user;
    pool_job* job = (pool_job*)calloc(1, sizeof *job);
    pool_job** tail;
    const uint32_t share = (item_count + 4u * POOL_WORKERS - 1u) / (4u * POOL_WORKERS);
    if (!job) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    atomic_fetch_add(&p->enqueues, 1u);
    if (t_pool_worker != 0) atomic_fetch_add(&p->enqueues_on_pool, 1u);
    if (!task || min_range < 1u || item_count <= min_range) atomic_fetch_add(&p->bad_request, 1u);
    job->task = task;
    job->context = task_context;
    job->count = item_count;
    job->chunk = share > min_range ? share : (min_range > 0u ? min_range : 1u);
    job->chunks = (item_count + job->chunk - 1u) / job->chunk;
    pthread_mutex_lock(&p->mutex);
    for (tail = &p->jobs; *tail; tail = &(*tail)->next_job) {}
    *tail = job;
    pthread_cond_broadcast(&p->work);
    pthread_mutex_unlock(&p->mutex);
    return job;
}

/* nl_task_finish_fn: helps with its own job's chunks (never with other work: see nl_task_finish_fn),
   then waits for the chunks other threads took. */
static void pool_finish(void* user, void* host_task) {
    pool* p = (pool*)user;
    pool_job* job = (pool_job*)host_task;
    pool_job** at;
    int slot = -1;
    uint32_t worker = t_pool_worker;
    atomic_fetch_add(&p->finishes, 1u);
    pthread_mutex_lock(&p->mutex);
    if (worker == 0) { /* a thread from outside borrows a free index, or only waits */
        int k;
        for (k = 0; k < OUTSIDE_SLOTS && slot < 0; ++k) {
            const int index = k == 0 ? 0 : POOL_THREADS + k;
            if (!p->slot_taken[index]) slot = index;
        }
        if (slot >= 0) p->slot_taken[slot] = 1;
        worker = slot >= 0 ? (uint32_t)slot : 0u;
    }
    if (t_pool_worker != 0 || slot >= 0)
        while (run_one(p, job, worker)) {}
    while (job->done != job->chunks) pthread_cond_wait(&p->done, &p->mutex);
    if (slot >= 0) p->slot_taken[slot] = 0;
    for (at = &p->jobs; *at != job; at = &(*at)->next_job) {}
    *at = job->next_job;
    pthread_mutex_unlock(&p->mutex);
    free(job);
}

/* The inline host: runs the ranges at once, in pieces of min_range, and returns NULL. */
typedef struct inline_host {
    atomic_uint enqueues, finishes, ranges;
} inline_host;

static void* inline_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count, uint32_t min_range) {
    inline_host* h = (inline_host*)user;
    uint32_t begin;
    atomic_fetch_add(&h->enqueues, 1u);
    for (begin = 0; begin < item_count; begin += min_range) {
        task(task_context, begin, item_count - begin > min_range ? begin + min_range : item_count, 0u);
        atomic_fetch_add(&h->ranges, 1u);
    }
    return NULL;
}

static void inline_finish(void* user, void* host_task) {
    inline_host* h = (inline_host*)user;
    (void)host_task;
    atomic_fetch_add(&h->finishes, 1u);
}

/* ---------------------------------------------------------------------------------------------
 * The level and what is asked of every world
 * ------------------------------------------------------------------------------------------- */

/* Platforms (tops at y 0, 0, 0.5 and 0) across gaps of 2, 3 and 2 m over a floor at y -4; a wall in
   part of the first gap, a pillar on the second platform, a low ceiling over part of the second gap. */
static const float k_boxes[][2][3] = {
    {{-20.0f, -5.0f, -8.0f}, {45.0f, -4.0f, 8.0f}}, {{-16.0f, -1.0f, -6.0f}, {-1.0f, 0.0f, 6.0f}},
    {{1.0f, -1.0f, -6.0f}, {9.0f, 0.0f, 6.0f}},     {{12.0f, -0.5f, -6.0f}, {20.0f, 0.5f, 6.0f}},
    {{22.0f, -1.0f, -6.0f}, {30.0f, 0.0f, 6.0f}},   {{-0.2f, -1.0f, -6.0f}, {0.2f, 3.0f, -2.0f}},
    {{4.0f, 0.0f, -1.0f}, {5.0f, 3.0f, 1.0f}},      {{9.0f, 1.6f, 2.0f}, {12.0f, 2.0f, 6.0f}},
};
#define BOX_COUNT (sizeof k_boxes / sizeof *k_boxes)

#define GRID_X 260
#define GRID_Z 64
#define RANDOM_RAYS 6000
#define RAY_COUNT (GRID_X * GRID_Z + RANDOM_RAYS)
#define SEGMENT_COUNT 6000
#define POINT_COUNT 3000
#define MAX_LINKS 4096
#define MAX_POINTS 256

static uint32_t g_random = 12345u;
static float uniform(float lo, float hi) {
    g_random = g_random * 1664525u + 1013904223u;
    return lo + (hi - lo) * (float)(g_random >> 8) / 16777216.0f;
}

static nl_ray g_rays[RAY_COUNT];
static nl_segment g_segments[SEGMENT_COUNT];
static float g_points[3 * POINT_COUNT];

static void make_queries(void) {
    uint32_t i, x, z, n = 0;
    for (x = 0; x < GRID_X; ++x) {
        for (z = 0; z < GRID_Z; ++z, ++n) {
            const nl_ray r = {
                {-20.0f + 0.25f * (float)x, 10.0f, -8.0f + 0.25f * (float)z}, {0.0f, -1.0f, 0.0f}, 100.0f};
            g_rays[n] = r;
        }
    }
    for (i = 0; i < RANDOM_RAYS; ++i, ++n) {
        nl_ray r;
        r.origin[0] = uniform(-20.0f, 45.0f);
        r.origin[1] = uniform(-4.0f, 5.0f);
        r.origin[2] = uniform(-8.0f, 8.0f);
        r.direction[0] = uniform(-1.0f, 1.0f);
        r.direction[1] = uniform(-1.0f, 0.2f);
        r.direction[2] = uniform(-1.0f, 1.0f);
        r.max_distance = uniform(1.0f, 40.0f);
        g_rays[n] = r;
    }
    for (i = 0; i < SEGMENT_COUNT; ++i) {
        nl_segment s;
        s.from[0] = uniform(-20.0f, 45.0f);
        s.from[1] = uniform(-4.0f, 4.0f);
        s.from[2] = uniform(-8.0f, 8.0f);
        s.to[0] = s.from[0] + uniform(-6.0f, 6.0f);
        s.to[1] = s.from[1] + uniform(-3.0f, 3.0f);
        s.to[2] = s.from[2] + uniform(-6.0f, 6.0f);
        g_segments[i] = s;
    }
    for (i = 0; i < POINT_COUNT; ++i) {
        g_points[3 * i] = uniform(-18.0f, 32.0f);
        g_points[3 * i + 1] = uniform(-3.0f, 2.0f);
        g_points[3 * i + 2] = uniform(-7.0f, 7.0f);
    }
}

/* Everything a world answered. Ids are compared without their world tag (the top 12 bits of a
   generation: worlds alive at once never share one), which is the only part that differs. */
typedef struct results {
    nl_ray_hit hits[RAY_COUNT];
    nl_ray_hit final_hits[RAY_COUNT]; /* after the wall was added */
    uint8_t blocked[SEGMENT_COUNT];
    nl_nav_point nearest[POINT_COUNT];
    nl_navmesh_info navmesh;
    nl_link links[MAX_LINKS];
    uint32_t link_count;
    nl_link updated[MAX_LINKS];
    uint32_t updated_count;
    nl_path_result path;
    nl_path_point points[MAX_POINTS];
    uint32_t point_count;
    uint32_t jumps, drops, jumps_after_update;
} results;

#define UNTAG(id) ((id).revision &= 0xfffffu)

static void cast_rays(nl_world* world, nl_ray_hit* hits) {
    uint32_t i;
    memset(hits, 0, sizeof(nl_ray_hit) * RAY_COUNT);
    hits[0] = nl_ray_hit_init();
    hits[0] = nl_ray_hit_init();
    REQUIRE_OK(nl_world_cast_rays(world, g_rays, RAY_COUNT, hits));
    for (i = 0; i < RAY_COUNT; ++i) UNTAG(hits[i].mesh);
}

static uint32_t get_links(nl_world* world, nl_navmesh_id navmesh, nl_link* links) {
    uint32_t count = 0, i;
    memset(links, 0, sizeof(nl_link) * MAX_LINKS);
    links[0] = nl_link_init();
    REQUIRE_OK(nl_navmesh_get_links(world, navmesh, links, MAX_LINKS, &count));
    for (i = 0; i < count; ++i) {
        UNTAG(links[i].id);
        UNTAG(links[i].navmesh);
    }
    return count;
}

static uint32_t count_kind(const nl_link* links, uint32_t count, nl_link_kind kind) {
    uint32_t i, n = 0;
    for (i = 0; i < count; ++i) n += links[i].kind == kind;
    return n;
}

/* The level, its queries, a navmesh, its links, an update and a path, in one world. */
static void run_scenario(nl_world* world, results* r) {
    const float half_extents[3] = {2.0f, 4.0f, 2.0f};
    const float wall_lo[3] = {20.5f, -4.0f, -7.0f}, wall_hi[3] = {21.5f, 3.0f, 7.0f};
    const float box_min[3] = {19.0f, -6.0f, -7.0f}, box_max[3] = {23.0f, 4.0f, 7.0f};
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_path_request_def request = nl_default_path_request_def();
    nl_navmesh_id navmesh;
    nl_mesh_id mesh;
    uint32_t i;

    for (i = 0; i < BOX_COUNT; ++i) REQUIRE_OK(add_box_mesh(world, k_boxes[i][0], k_boxes[i][1], 0u, &mesh));
    cast_rays(world, r->hits);
    memset(r->blocked, 0xee, sizeof r->blocked);
    REQUIRE_OK(nl_world_segments_blocked(world, g_segments, SEGMENT_COUNT, r->blocked));

    REQUIRE_OK(nl_navmesh_build(world, &build, &navmesh));
    memset(&r->navmesh, 0, sizeof r->navmesh);
    r->navmesh.size = sizeof r->navmesh;
    REQUIRE_OK(nl_navmesh_get_info(world, navmesh, &r->navmesh));
    memset(r->nearest, 0, sizeof r->nearest);
    REQUIRE_OK(nl_navmesh_find_nearest(world, navmesh, g_points, POINT_COUNT, half_extents, r->nearest));

    REQUIRE_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    r->link_count = get_links(world, navmesh, r->links);
    r->jumps = count_kind(r->links, r->link_count, NL_LINK_JUMP);
    r->drops = count_kind(r->links, r->link_count, NL_LINK_DROP);

    /* A path across every gap, for a body that jumps and drops. */
    request.navmesh = navmesh;
    request.start[0] = -10.0f;
    request.goal[0] = 26.0f;
    request.capabilities.max_jump_distance = 4.5f;
    request.capabilities.max_jump_height = 1.5f;
    request.capabilities.max_drop_height = 6.0f;
    memset(&r->path, 0, sizeof r->path);
    memset(r->points, 0, sizeof r->points);
    r->path.size = sizeof r->path;
    r->points[0] = nl_path_point_init();
    REQUIRE_OK(nl_path_find(world, &request, &r->path, r->points, MAX_POINTS, &r->point_count));
    for (i = 0; i < r->point_count; ++i) UNTAG(r->points[i].link);

    /* A wall across the last gap, then the links again in a box around it. */
    REQUIRE_OK(add_box_mesh(world, wall_lo, wall_hi, 0u, &mesh));
    REQUIRE_OK(nl_navmesh_update_links_in_box(world, navmesh, box_min, box_max, NULL, NULL, NULL));
    r->updated_count = get_links(world, navmesh, r->updated);
    r->jumps_after_update = count_kind(r->updated, r->updated_count, NL_LINK_JUMP);
    cast_rays(world, r->final_hits);
}

static int same_results(const char* what, const results* a, const results* b) {
    const int failures = g_failures;
    CHECK(memcmp(a->hits, b->hits, sizeof a->hits) == 0, "%s: ray hits differ from the TBB world's", what);
    CHECK(memcmp(a->final_hits, b->final_hits, sizeof a->final_hits) == 0, "%s: ray hits after the wall differ", what);
    CHECK(memcmp(a->blocked, b->blocked, sizeof a->blocked) == 0, "%s: segment answers differ", what);
    CHECK(memcmp(&a->navmesh, &b->navmesh, sizeof a->navmesh) == 0, "%s: the navmesh differs", what);
    CHECK(memcmp(a->nearest, b->nearest, sizeof a->nearest) == 0, "%s: point location differs", what);
    CHECK(a->link_count == b->link_count && memcmp(a->links, b->links, sizeof(nl_link) * a->link_count) == 0,
          "%s: links differ (%u and %u)", what, (unsigned)a->link_count, (unsigned)b->link_count);
    CHECK(
        a->updated_count == b->updated_count && memcmp(a->updated, b->updated, sizeof(nl_link) * a->updated_count) == 0,
        "%s: links after the update differ (%u and %u)", what, (unsigned)a->updated_count, (unsigned)b->updated_count);
    CHECK(memcmp(&a->path, &b->path, sizeof a->path) == 0 && a->point_count == b->point_count &&
              memcmp(a->points, b->points, sizeof(nl_path_point) * a->point_count) == 0,
          "%s: the path differs", what);
    return g_failures == failures;
}

static nl_world* create_world(const nl_world_def* def) {
    nl_world* world = NULL;
    REQUIRE_OK(nl_world_create(def, &world));
    return world;
}

static nl_world_def pool_def(pool* p) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = POOL_WORKERS;
    def.path_worker_count = 0;
    def.task_enqueue_fn = pool_enqueue;
    def.task_finish_fn = pool_finish;
    def.task_user = p;
    return def;
}

/* ---------------------------------------------------------------------------------------------
 * NavLink called from the pool's own jobs, and from several host threads at once
 * ------------------------------------------------------------------------------------------- */

typedef struct caller_job {
    nl_world* world;
    nl_ray_hit hits[4][RAY_COUNT];
    atomic_uint failures;
} caller_job;

/* A host task (run by the pool like NavLink's): each item casts the whole ray batch from the pool
   thread that runs it, so NavLink enqueues and finishes its own task from inside the pool's. */
static void cast_from_pool(void* context, uint32_t begin, uint32_t end, uint32_t worker_index) {
    caller_job* job = (caller_job*)context;
    uint32_t i, k;
    (void)worker_index;
    for (i = begin; i < end; ++i) {
        job->hits[i][0] = nl_ray_hit_init();
        if (NL_FAILED(nl_world_cast_rays(job->world, g_rays, RAY_COUNT, job->hits[i]))) {
            atomic_fetch_add(&job->failures, 1u);
            continue;
        }
        for (k = 0; k < RAY_COUNT; ++k) UNTAG(job->hits[i][k].mesh);
    }
}

typedef struct caller_thread {
    caller_job* job;
    uint32_t slot;
} caller_thread;

static void* cast_from_thread(void* arg) {
    caller_thread* c = (caller_thread*)arg;
    cast_from_pool(c->job, c->slot, c->slot + 1, 0u);
    return NULL;
}

static void test_calls_from_inside_and_beside(pool* p, nl_world* world, const results* reference) {
    static caller_job job;
    caller_thread callers[3];
    pthread_t threads[3];
    const unsigned on_pool_before = atomic_load(&p->enqueues_on_pool);
    pool_job* host_job;
    uint32_t i;

    /* Four items, one per chunk: the pool's threads take them and call NavLink, whose tasks go to the
       same pool; the main thread, waiting in finish, takes some too. */
    memset(&job, 0, sizeof job);
    job.world = world;
    host_job = (pool_job*)pool_enqueue(p, cast_from_pool, &job, 4u, 1u);
    pool_finish(p, host_job);
    CHECK(atomic_load(&job.failures) == 0u, "a ray batch from inside the pool's task failed");
    for (i = 0; i < 4; ++i)
        CHECK(memcmp(job.hits[i], reference->final_hits, sizeof reference->final_hits) == 0,
              "rays cast from inside the pool's task %u differ", (unsigned)i);
    CHECK(atomic_load(&p->enqueues_on_pool) > on_pool_before,
          "NavLink never enqueued from a pool thread (the nested case was not reached)");

    /* Three host threads at once (each borrows an outside worker index while it waits). */
    memset(&job, 0, sizeof job);
    job.world = world;
    for (i = 0; i < 3; ++i) {
        callers[i].job = &job;
        callers[i].slot = i;
        if (pthread_create(&threads[i], NULL, cast_from_thread, &callers[i]) != 0) {
            fprintf(stderr, "pthread_create failed\n");
            exit(1);
        }
    }
    for (i = 0; i < 3; ++i) pthread_join(threads[i], NULL);
    CHECK(atomic_load(&job.failures) == 0u, "a ray batch from a host thread failed");
    for (i = 0; i < 3; ++i)
        CHECK(memcmp(job.hits[i], reference->final_hits, sizeof reference->final_hits) == 0,
              "rays cast by host thread %u differ", (unsigned)i);
}

/* ---------------------------------------------------------------------------------------------
 * A level call from inside NavLink's finish callback is refused, not left to hang
 * ------------------------------------------------------------------------------------------- */

typedef struct reentrant_host {
    nl_world* world;
    nl_status inner;
    char message[256];
    int finishes;
} reentrant_host;

static void* reentrant_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count,
                               uint32_t min_range) {
    (void)min_range;
    task(task_context, 0u, item_count, 0u);
    return user; /* any non-NULL handle */
}

/* Runs "host work that calls NavLink" while NavLink waits: the world's lock is held by this thread. */
static void reentrant_finish(void* user, void* host_task) {
    reentrant_host* h = (reentrant_host*)user;
    nl_ray_hit hit = nl_ray_hit_init();
    (void)host_task;
    ++h->finishes;
    h->inner = nl_world_cast_rays(h->world, g_rays, 1u, &hit);
    snprintf(h->message, sizeof h->message, "%s", nl_get_last_error_message());
}

static void test_reentrant_finish(void) {
    static reentrant_host host;
    static nl_ray_hit hits[RAY_COUNT];
    nl_world_def def = nl_default_world_def();
    nl_mesh_id mesh;
    nl_world* world;
    memset(&host, 0, sizeof host);
    def.worker_count = 1;
    def.path_worker_count = 0;
    def.task_enqueue_fn = reentrant_enqueue;
    def.task_finish_fn = reentrant_finish;
    def.task_user = &host;
    world = create_world(&def);
    host.world = world;
    REQUIRE_OK(add_box_mesh(world, k_boxes[0][0], k_boxes[0][1], 0u, &mesh));
    hits[0] = nl_ray_hit_init();
    CHECK(nl_world_cast_rays(world, g_rays, RAY_COUNT, hits) == NL_STATUS_SUCCESS, "the outer ray batch failed: %s",
          nl_get_last_error_message());
    CHECK(host.finishes == 1, "finish was called %d times", host.finishes);
    CHECK(
        host.inner == (NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR) && strstr(host.message, "inside a parallel task"),
        "a ray batch from inside the finish callback returned 0x%08x \"%s\" (expected INTERNAL_ERROR, refused)",
        (unsigned)host.inner, host.message);
    nl_world_destroy(world);
}

/* Host work that calls the agents' functions while nl_world_step waits for its parallel loop: the step
   holds the agents' lock on this thread. Both calls are refused, and the lock still works afterwards (a
   read lock taken again used to fail with EDEADLK unseen, run unlocked, and release the step's lock
   when it let go: the next step waited forever). */
typedef struct reentrant_step_host {
    nl_world* world;
    int finishes;
    nl_status get_agents, step;
    char get_agents_message[512], step_message[512];
} reentrant_step_host;

static void reentrant_step_finish(void* user, void* host_task) {
    reentrant_step_host* h = (reentrant_step_host*)user;
    nl_agent_info infos[4];
    uint32_t count = 0;
    (void)host_task;
    if (h->finishes++) return; /* once is enough; the later steps run undisturbed */
    infos[0] = nl_agent_info_init();
    h->get_agents = nl_world_get_agents(h->world, infos, 4u, &count);
    snprintf(h->get_agents_message, sizeof h->get_agents_message, "%s", nl_get_last_error_message());
    h->step = nl_world_step(h->world, 1.0f / 30.0f);
    snprintf(h->step_message, sizeof h->step_message, "%s", nl_get_last_error_message());
}

static void test_reentrant_step(void) {
    static reentrant_step_host host;
    const nl_status refused = NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
    nl_world_def def = nl_default_world_def();
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_agent_def agent = nl_default_agent_def();
    nl_agent_info infos[4];
    nl_navmesh_id navmesh;
    nl_agent_id ids[2];
    nl_mesh_id mesh;
    nl_world* world;
    uint32_t count = 0, i;
    int k;
    memset(&host, 0, sizeof host);
    def.worker_count = 2;
    def.path_worker_count = 0;
    def.task_enqueue_fn = reentrant_enqueue;
    def.task_finish_fn = reentrant_step_finish;
    def.task_user = &host;
    world = create_world(&def);
    host.world = world;
    REQUIRE_OK(add_box_mesh(world, k_boxes[0][0], k_boxes[0][1], 0u, &mesh)); /* the floor, top at y -4 */
    REQUIRE_OK(nl_navmesh_build(world, &build, &navmesh));
    agent.navmesh = navmesh;
    for (i = 0; i < 2; ++i) {
        const float to[3] = {i ? -10.0f : 10.0f, -4.0f, 0.0f};
        agent.position[0] = i ? 10.0f : -10.0f;
        agent.position[1] = -4.0f;
        REQUIRE_OK(nl_agent_add(world, &agent, &ids[i]));
        REQUIRE_OK(nl_agent_set_destination(world, ids[i], to));
    }
    /* Two paths to plan: the step hands them to the host as one parallel loop of two items. */
    CHECK(nl_world_step(world, 1.0f / 30.0f) == NL_STATUS_SUCCESS, "the outer step failed: %s",
          nl_get_last_error_message());
    CHECK(host.finishes == 1, "finish was called %d times (expected once: the step's paths)", host.finishes);
    CHECK(
        host.get_agents == refused && strstr(host.get_agents_message, "the agents"),
        "nl_world_get_agents from a task callback during a step returned 0x%08x \"%s\" (expected INTERNAL_ERROR naming "
        "the agents' lock)",
        (unsigned)host.get_agents, host.get_agents_message);
    CHECK(host.step == refused && strstr(host.step_message, "the agents"),
          "nl_world_step from a task callback during a step returned 0x%08x \"%s\" (expected INTERNAL_ERROR naming the "
          "agents' lock)",
          (unsigned)host.step, host.step_message);
    /* The lock is whole: later steps and reads run (a broken lock hung the next step here). */
    for (k = 0; k < 30; ++k) REQUIRE_OK(nl_world_step(world, 1.0f / 30.0f));
    infos[0] = nl_agent_info_init();
    REQUIRE_OK(nl_world_get_agents(world, infos, 4u, &count));
    CHECK(count == 2u && infos[0].state == NL_AGENT_WALKING && infos[1].state == NL_AGENT_WALKING,
          "after the refused calls: %u agents, states %u and %u (expected two walking)", (unsigned)count,
          (unsigned)infos[0].state, (unsigned)infos[1].state);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * A host that breaks the contract fails the call, naming what it did
 * ------------------------------------------------------------------------------------------- */

typedef struct broken_host {
    int skip_last; /* 1: leaves the last item out; 0: gives worker index 7 (worker_count is 2) */
} broken_host;

static void* broken_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count, uint32_t min_range) {
    const broken_host* h = (const broken_host*)user;
    (void)min_range;
    if (h->skip_last)
        task(task_context, 0u, item_count - 1u, 0u);
    else
        task(task_context, 0u, item_count, 7u);
    return NULL;
}

static void test_broken_host(void) {
    static nl_ray_hit hits[RAY_COUNT];
    static const char* const needles[2] = {"worker 7 of a task", "items of a task of"};
    int k;
    for (k = 0; k < 2; ++k) {
        broken_host host;
        nl_world_def def = nl_default_world_def();
        nl_world* world;
        nl_mesh_id mesh;
        nl_status status;
        host.skip_last = k;
        def.worker_count = 2;
        def.path_worker_count = 0;
        def.task_enqueue_fn = broken_enqueue;
        def.task_finish_fn = inline_finish;
        def.task_user = &host;
        world = create_world(&def);
        REQUIRE_OK(add_box_mesh(world, k_boxes[0][0], k_boxes[0][1], 0u, &mesh));
        hits[0] = nl_ray_hit_init();
        status = nl_world_cast_rays(world, g_rays, RAY_COUNT, hits);
        CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR) &&
                  strstr(nl_get_last_error_message(), "the host's task system ran") &&
                  strstr(nl_get_last_error_message(), needles[k]),
              "a host that %s: 0x%08x \"%s\"", k ? "skips an item" : "gives a worker index >= worker_count",
              (unsigned)status, nl_get_last_error_message());
        /* A batch of one range never reaches the host: the world still answers. */
        hits[0] = nl_ray_hit_init();
        CHECK(nl_world_cast_rays(world, g_rays, 1u, hits) == NL_STATUS_SUCCESS, "one ray after the broken batch: %s",
              nl_get_last_error_message());
        nl_world_destroy(world);
    }
}

/* ---------------------------------------------------------------------------------------------
 * Defs: an old size ignores the task fields; bad task fields are refused by name
 * ------------------------------------------------------------------------------------------- */

static void test_defs(inline_host* never_called) {
    nl_world_def def = nl_default_world_def();
    nl_world* world = NULL;
    nl_status status;
    nl_ray_hit* hits = (nl_ray_hit*)calloc(RAY_COUNT, sizeof *hits);
    nl_mesh_id mesh;
    const unsigned before = atomic_load(&never_called->enqueues);

    CHECK(def.task_enqueue_fn == NULL && def.task_finish_fn == NULL && def.task_user == NULL,
          "nl_default_world_def() sets task fields");
    if (!hits) exit(1);

    /* A host built before the task fields passes the older size: whatever lies after it is not read. */
    def.size = (uint32_t)offsetof(nl_world_def, task_enqueue_fn);
    def.worker_count = 2;
    def.path_worker_count = 0;
    def.task_enqueue_fn = inline_enqueue;
    def.task_finish_fn = inline_finish;
    def.task_user = never_called;
    world = create_world(&def);
    REQUIRE_OK(add_box_mesh(world, k_boxes[0][0], k_boxes[0][1], 0u, &mesh));
    hits[0] = nl_ray_hit_init();
    REQUIRE_OK(nl_world_cast_rays(world, g_rays, RAY_COUNT, hits));
    CHECK(atomic_load(&never_called->enqueues) == before, "task fields past the def's size were used");
    CHECK(nl_world_get_worker_count(world) == 2, "an old-size def: %d workers", (int)nl_world_get_worker_count(world));
    nl_world_destroy(world);
    free(hits);

    /* Refusals, each naming the field. */
    def = nl_default_world_def();
    def.worker_count = 2;
    def.task_enqueue_fn = inline_enqueue;
    world = NULL;
    status = nl_world_create(&def, &world);
    CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) && world == NULL &&
              strstr(nl_get_last_error_message(), "def->task_finish_fn is NULL"),
          "enqueue without finish: 0x%08x \"%s\"", (unsigned)status, nl_get_last_error_message());
    def.task_enqueue_fn = NULL;
    def.task_finish_fn = inline_finish;
    status = nl_world_create(&def, &world);
    CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) && world == NULL &&
              strstr(nl_get_last_error_message(), "def->task_enqueue_fn is NULL"),
          "finish without enqueue: 0x%08x \"%s\"", (unsigned)status, nl_get_last_error_message());
    def.task_enqueue_fn = inline_enqueue;
    def.worker_count = NL_WORKERS_AUTO;
    status = nl_world_create(&def, &world);
    CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) && world == NULL &&
              strstr(nl_get_last_error_message(), "def->worker_count is -1 (with task callbacks"),
          "NL_WORKERS_AUTO with callbacks: 0x%08x \"%s\"", (unsigned)status, nl_get_last_error_message());
    def.worker_count = NL_MAX_WORKERS + 1;
    status = nl_world_create(&def, &world);
    CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) && world == NULL &&
              strstr(nl_get_last_error_message(), "def->worker_count"),
          "NL_MAX_WORKERS + 1 with callbacks: 0x%08x \"%s\"", (unsigned)status, nl_get_last_error_message());
    def.worker_count = 2;
    def.size = (uint32_t)offsetof(nl_world_def, task_user); /* ends between the callbacks and task_user */
    status = nl_world_create(&def, &world);
    CHECK(status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) && world == NULL &&
              strstr(nl_get_last_error_message(), "def->size"),
          "a size inside the task fields: 0x%08x \"%s\"", (unsigned)status, nl_get_last_error_message());
    CHECK(atomic_load(&never_called->enqueues) == before, "a refused def's callbacks were called");
}

/* ---------------------------------------------------------------------------------------------
 * main
 * ------------------------------------------------------------------------------------------- */

static results g_tbb, g_pool, g_inline;

int main(void) {
    static pool p;
    static inline_host inline_host_state;
    nl_world_def tbb_def = nl_default_world_def();
    nl_world_def def;
    nl_world* tbb;
    nl_world* pooled;
    nl_world* inlined;
    unsigned enqueues;

    make_queries();

    /* The reference: NavLink's own threads. */
    tbb_def.worker_count = 2;
    tbb_def.path_worker_count = 0;
    tbb = create_world(&tbb_def);
    run_scenario(tbb, &g_tbb);
    printf("TBB world: %u rays, %u links (%u jumps, %u drops), %u after the update (%u jumps), path of %u points\n",
           (unsigned)RAY_COUNT, (unsigned)g_tbb.link_count, (unsigned)g_tbb.jumps, (unsigned)g_tbb.drops,
           (unsigned)g_tbb.updated_count, (unsigned)g_tbb.jumps_after_update, (unsigned)g_tbb.point_count);
    /* The scenario must have something to compare (or every comparison below would hold trivially). */
    CHECK(g_tbb.jumps > 0 && g_tbb.drops > 0, "the level gave %u jumps and %u drops", (unsigned)g_tbb.jumps,
          (unsigned)g_tbb.drops);
    CHECK(g_tbb.jumps_after_update < g_tbb.jumps, "the wall took no jump away (%u, then %u)", (unsigned)g_tbb.jumps,
          (unsigned)g_tbb.jumps_after_update);
    CHECK(g_tbb.path.outcome == NL_PATH_COMPLETE && g_tbb.path.links_used >= 3,
          "the path: outcome %u, %u links (expected complete, across three gaps)", (unsigned)g_tbb.path.outcome,
          (unsigned)g_tbb.path.links_used);

    /* The pool. */
    pool_start(&p);
    def = pool_def(&p);
    pooled = create_world(&def);
    CHECK(nl_world_get_worker_count(pooled) == POOL_WORKERS, "worker count %d, expected %d",
          (int)nl_world_get_worker_count(pooled), POOL_WORKERS);
    run_scenario(pooled, &g_pool);
    if (same_results("pool", &g_pool, &g_tbb)) printf("pool world: the same bytes as the TBB world\n");
    enqueues = atomic_load(&p.enqueues);
    CHECK(enqueues > 0u && atomic_load(&p.finishes) == enqueues, "the pool: %u enqueues, %u finishes", enqueues,
          (unsigned)atomic_load(&p.finishes));
    CHECK(atomic_load(&p.ranges_on_pool) > 0u, "no range ran on the pool's threads");
    test_calls_from_inside_and_beside(&p, pooled, &g_tbb);
    CHECK(atomic_load(&p.bad_worker) == 0u && atomic_load(&p.max_worker) < POOL_WORKERS,
          "a worker index at or above worker_count (%u)", (unsigned)atomic_load(&p.max_worker));
    CHECK(atomic_load(&p.clashes) == 0u, "a worker index was used by two threads at once");
    CHECK(atomic_load(&p.bad_request) == 0u, "%u enqueues had no task, min_range 0 or item_count <= min_range",
          (unsigned)atomic_load(&p.bad_request));
    printf(
        "pool: %u enqueues (%u from its own threads), %u finishes, %u ranges (%u on its threads), worker indices "
        "up to %u\n",
        (unsigned)atomic_load(&p.enqueues), (unsigned)atomic_load(&p.enqueues_on_pool),
        (unsigned)atomic_load(&p.finishes), (unsigned)atomic_load(&p.ranges), (unsigned)atomic_load(&p.ranges_on_pool),
        (unsigned)atomic_load(&p.max_worker));
    nl_world_destroy(pooled);
    pool_stop(&p);

    /* The inline host. */
    def = nl_default_world_def();
    def.worker_count = 1;
    def.path_worker_count = 0;
    def.task_enqueue_fn = inline_enqueue;
    def.task_finish_fn = inline_finish;
    def.task_user = &inline_host_state;
    inlined = create_world(&def);
    run_scenario(inlined, &g_inline);
    if (same_results("inline", &g_inline, &g_tbb)) printf("inline world: the same bytes as the TBB world\n");
    CHECK(atomic_load(&inline_host_state.enqueues) > 0u && atomic_load(&inline_host_state.finishes) == 0u,
          "the inline host: %u enqueues, %u finishes (NULL handles are never finished)",
          (unsigned)atomic_load(&inline_host_state.enqueues), (unsigned)atomic_load(&inline_host_state.finishes));
    printf("inline: %u enqueues, %u ranges, %u finishes\n", (unsigned)atomic_load(&inline_host_state.enqueues),
           (unsigned)atomic_load(&inline_host_state.ranges), (unsigned)atomic_load(&inline_host_state.finishes));
    nl_world_destroy(inlined);
    nl_world_destroy(tbb);

    test_reentrant_finish();
    test_reentrant_step();
    test_broken_host();
    test_defs(&inline_host_state);

    if (g_failures) {
        printf("%d check(s) FAILED\n", g_failures);
        return 1;
    }
    printf("all host task checks passed\n");
    return 0;
}
