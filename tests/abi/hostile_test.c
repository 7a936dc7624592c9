/*
 * navlink-abi-hostile-test: every public nl_* function called with bad input, through the C ABI
 * only, in strict C11. For each call it checks what the header promises of a failure:
 *
 * - the status is exactly FAILURE with the documented detail bit (INVALID_ARGUMENT, INVALID_HANDLE,
 *   BUFFER_TOO_SMALL, NOT_FOUND, ...), and it is the thread's last status;
 * - the last error message starts with the function's name and names the bad argument, and the
 *   world's log callback received the same failure once (nothing when there is no world);
 * - the outputs are untouched (they are filled with a sentinel byte first), but for the count of a
 *   list that did not fit;
 * - the worlds are as they were: after every case the runner compares everything both worlds hold
 *   (meshes and their info, navmeshes, every link, plugins, the path queue, a known link, a known
 *   path, two rays, every agent's info, corners and trajectory, the last step's agent events) with
 *   how it was when the group started.
 *
 * Calls the header allows (a NULL optional output, count 0, a NULL world to nl_world_destroy) are
 * checked as documented. Cases are rows of tables where they can be (def_case, text_case, the id
 * functions): a new field or function gets its cases by a row, and the coverage check says which. The bad inputs: each pointer NULL in turn; counts and lengths 0 and huge (a
 * huge count with a NULL pointer must not be read); ids null, stale (their slot reused by a live
 * object), garbage and foreign (issued by the second live world, with the same slot and counter as
 * a live id of the first: only the world tag differs), and for agents ids of other kinds; `size` fields 0, too small and larger than
 * the library's struct; NaN and infinities in every float input.
 *
 * Two worlds, A (under test) and B (foreign), are built the same way in each child process (see
 * build_world). Each group runs in its own child (hostile_runner.c), so a crash names its
 * case. At the end, the coverage check (hostile_coverage.c) reads the public headers and fails
 * for any NL_API function, parameter or input field without its cases.
 *
 * A defect that needs a core fix is listed in k_known_failures: its case prints "KNOWN FAILURE" and
 * does not fail the run, and fails it once it passes (so the list stays true).
 *
 * Usage: navlink-abi-hostile-test --headers DIR... [--library LIBNAVLINK] [--plugin CLIMB_PLUGIN]
 *                                   [--only GROUP]
 */
/* Built with a sanitizer (GCC says so with __SANITIZE_*__, clang with __has_feature). */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define NAVLINK_HOSTILE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define NAVLINK_HOSTILE_SANITIZED 1
#endif
#endif

/* fork() (in the runner), pthreads, mkdtemp(), strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile.h"
#include "scene.h"

#include <navlink/plugin.h>
#include <navlink/recast.h>

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------------------
 * Bad values
 * ------------------------------------------------------------------------------------------- */

typedef struct bad_float {
    const char* name;
    float value;
} bad_float;
static const bad_float k_bad_floats[] = {{"NaN", NAN}, {"inf", INFINITY}, {"-inf", -INFINITY}};
#define BAD_FLOAT_COUNT (sizeof k_bad_floats / sizeof *k_bad_floats)

/* Ids by value, whatever their type: every nl_*_id is {index1, generation}. */
typedef struct raw_id {
    uint32_t index1, generation;
} raw_id;
#define RAW(id) ((raw_id){(id).index1, (id).generation})
#define AS(type, r) ((type){(r).index1, (r).generation})

typedef struct bad_id {
    char what[64]; /* "null", "stale", "garbage {1, 2}", "foreign" */
    raw_id id;
} bad_id;
#define MAX_BAD_IDS 12

/* The ids that must be refused where `live` is accepted. `stale` is {0, 0} where no id can go stale. */
static size_t bad_ids(raw_id live, raw_id stale, raw_id foreign, bad_id* out) {
    size_t n = 0, k;
    const raw_id garbage[] = {
        {live.index1, live.generation + 1u},         /* the slot's next counter */
        {live.index1, live.generation ^ 0x80000000u}, /* another world's tag, same counter */
        {live.index1 + 1000u, live.generation},      /* past the last slot */
        {0xffffffffu, 0xffffffffu},
        {0x7fffffffu, 1u},
        {0x9e3779b9u, 0x7f4a7c15u}, /* pseudo-random */
        {0x2545f491u, 0x4f6cdd1du},
    };
    snprintf(out[n].what, sizeof out[n].what, "null");
    out[n++].id = (raw_id){0u, 0u};
    snprintf(out[n].what, sizeof out[n].what, "null {0, %u} (a live generation)", (unsigned)live.generation);
    out[n++].id = (raw_id){0u, live.generation};
    if (stale.index1 != 0u) {
        snprintf(out[n].what, sizeof out[n].what, "stale {%u, %u} (slot reused)", (unsigned)stale.index1,
                 (unsigned)stale.generation);
        out[n++].id = stale;
    }
    for (k = 0; k < sizeof garbage / sizeof *garbage; ++k) {
        snprintf(out[n].what, sizeof out[n].what, "garbage {%u, %u}", (unsigned)garbage[k].index1,
                 (unsigned)garbage[k].generation);
        out[n++].id = garbage[k];
    }
    snprintf(out[n].what, sizeof out[n].what, "foreign {%u, %u}", (unsigned)foreign.index1, (unsigned)foreign.generation);
    out[n++].id = foreign;
    return n;
}

/* Runs the block once per bad id, with `bad` naming the current one. */
#define FOR_BAD_IDS(bad, live, stale, foreign)                                                          \
    for (bad_id bad##_all_[MAX_BAD_IDS], *bad = bad##_all_,                                             \
                *bad##_end_ = bad##_all_ + bad_ids(RAW(live), RAW(stale), RAW(foreign), bad##_all_); \
         bad < bad##_end_; ++bad)

/* A buffer aligned for any struct, for defs copied and made bad. */
typedef union aligned_buffer {
    max_align_t align;
    unsigned char bytes[2048];
} aligned_buffer;

/* ---------------------------------------------------------------------------------------------
 * The worlds: A is under test; B, built the same way, issues the foreign ids
 * ------------------------------------------------------------------------------------------- */

typedef struct world_fixture {
    nl_world* world;
    nl_mesh_id mesh, movable, stale_mesh;                    /* mesh took stale_mesh's slot */
    nl_navmesh_id navmesh, host_navmesh, stale_navmesh;      /* navmesh took stale_navmesh's */
    nl_link_id link, stale_link;                             /* the manual link; a generated one took stale_link's */
    nl_plugin_id plugin;                                     /* the built-in Recast builder */
    nl_path_ticket done_ticket, pending_ticket, stale_ticket; /* pending took stale_ticket's */
    nl_agent_id agent, flyer, stale_agent;                   /* agent walks (took stale_agent's slot); flyer is in the air */
    uint32_t agent_events;                                   /* the events of the fixture's last step */
    unsigned char* fingerprint;
    size_t fingerprint_size;
} world_fixture;

static world_fixture A, B;

/* The top of the movable box, handed over as a navmesh: one quad, counter-clockwise from above. */
static const float k_quad[12] = {40, 0, -2, 40, 0, 2, 44, 0, 2, 44, 0, -2};
static const uint32_t k_quad_indices[4] = {0, 1, 2, 3};
static const uint8_t k_quad_corners[1] = {4};
static const uint8_t k_quad_area[1] = {3};
static const float k_quad_detail[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, 0.1f, 2, 44, 0.1f, -2};
static const uint32_t k_quad_detail_triangles[6] = {0, 1, 2, 0, 2, 3};
static const uint32_t k_quad_detail_starts[2] = {0, 2};

static nl_navmesh_def quad_navmesh_def(void) {
    nl_navmesh_def def = navmesh_def_of(k_quad, 4, k_quad_indices, k_quad_corners, 1);
    def.areas = k_quad_area;
    set_navmesh_detail(&def, k_quad_detail, 4, k_quad_detail_triangles, 2, k_quad_detail_starts);
    return def;
}

/* The manual link across the gap, 1.5 m inside each rim. */
static nl_link_def gap_link_def(void) {
    nl_link_def def = nl_default_link_def();
    def.start[0] = -2.5f;
    def.start[2] = 3.0f;
    def.end[0] = 2.5f;
    def.end[2] = 3.0f;
    def.bidirectional = 1;
    def.cost_modifier = 1.5f;
    def.user_data = 42;
    return def;
}

/* From one platform to the other for an agent that jumps 6 m: it takes a link. */
static nl_path_request_def gap_request(nl_navmesh_id navmesh) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    def.start[0] = -6.0f;
    def.goal[0] = 6.0f;
    def.agent.max_jump_distance = 6.0f;
    def.agent.max_jump_height = 1.5f;
    def.agent.max_drop_height = 2.0f;
    return def;
}

/* An agent that jumps what the known path needs, on `navmesh` at (x, 0, z). */
static nl_agent_def jumper_def(nl_navmesh_id navmesh, float x, float z) {
    nl_agent_def def = nl_default_agent_def();
    def.navmesh = navmesh;
    def.position[0] = x;
    def.position[2] = z;
    def.capabilities.max_jump_distance = 6.0f;
    def.capabilities.max_jump_height = 1.5f;
    def.capabilities.max_drop_height = 2.0f;
    def.capabilities.radius = 0.4f;
    def.user_data = 7;
    return def;
}

static int in_the_air(nl_agent_state state) {
    return state == NL_AGENT_JUMPING || state == NL_AGENT_FALLING || state == NL_AGENT_TRAVERSING;
}

static void fixture_failed(const char* what) {
    fprintf(stderr, "fixture: %s: %s\n", what, nl_get_last_error_message());
    exit(4);
}

/* Builds a world the same way each time, so that A's and B's ids share slots and counters. */
static void build_world(world_fixture* f) {
    static const float platform_lo[2][3] = {{-11, -1, -5}, {1, -1, -5}}, platform_hi[2][3] = {{-1, 0, 5}, {11, 0, 5}};
    static const float pit_lo[3] = {-12, -21, -6}, pit_hi[3] = {12, -20, 6};
    static const float lift_lo[3] = {40, -1, -2}, lift_hi[3] = {44, 0, 2};
    nl_world_def wd = nl_default_world_def();
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_def quad = quad_navmesh_def();
    nl_link_def link = gap_link_def();
    nl_path_request_def request;
    nl_mesh_id scratch;
    nl_link_id doomed_link;
    nl_navmesh_id doomed_navmesh;
    memset(f, 0, sizeof *f);
    wd.worker_count = 1;
    wd.path_worker_count = 0; /* the host runs the queue: a pending ticket stays pending */
    wd.log_fn = hostile_log;
    wd.log_level = NL_LOG_ERROR;
    if (NL_FAILED(nl_world_create(&wd, &f->world))) fixture_failed("nl_world_create");
    /* Stale ids whose slots live objects took again (slots are reused last freed first). */
    if (NL_FAILED(add_box_mesh(f->world, lift_lo, lift_hi, 0u, &f->stale_mesh)) || NL_FAILED(nl_mesh_remove(f->world, f->stale_mesh)))
        fixture_failed("the doomed mesh");
    if (NL_FAILED(add_box_mesh(f->world, platform_lo[0], platform_hi[0], 0u, &f->mesh)) ||
        NL_FAILED(add_box_mesh(f->world, platform_lo[1], platform_hi[1], 0u, &scratch)) ||
        NL_FAILED(add_box_mesh(f->world, pit_lo, pit_hi, 0u, &scratch)) ||
        NL_FAILED(add_box_mesh(f->world, lift_lo, lift_hi, NL_MESH_MOVABLE, &f->movable)))
        fixture_failed("the level");
    if (NL_FAILED(nl_navmesh_add(f->world, &quad, &doomed_navmesh)) || NL_FAILED(nl_navmesh_remove(f->world, doomed_navmesh)))
        fixture_failed("the doomed navmesh");
    f->stale_navmesh = doomed_navmesh;
    if (NL_FAILED(nl_navmesh_build(f->world, &build, &f->navmesh))) fixture_failed("nl_navmesh_build");
    if (NL_FAILED(nl_navmesh_add(f->world, &quad, &f->host_navmesh))) fixture_failed("nl_navmesh_add");
    if (NL_FAILED(nl_link_add(f->world, f->navmesh, &link, &doomed_link)) || NL_FAILED(nl_link_remove(f->world, doomed_link)))
        fixture_failed("the doomed link");
    f->stale_link = doomed_link;
    if (NL_FAILED(nl_navmesh_generate_links(f->world, f->navmesh, NULL, NULL, NULL, NULL))) fixture_failed("generate_links");
    if (NL_FAILED(nl_link_add(f->world, f->navmesh, &link, &f->link))) fixture_failed("nl_link_add");
    {
        uint32_t count = 0;
        if (NL_FAILED(nl_world_get_plugins(f->world, &f->plugin, 1, &count))) fixture_failed("nl_world_get_plugins");
    }
    request = gap_request(f->navmesh);
    if (NL_FAILED(nl_path_request(f->world, &request, &f->done_ticket)) || NL_FAILED(nl_path_process(f->world, NL_TEST_BUDGET(0, 0.0), NULL)) ||
        NL_FAILED(nl_path_request(f->world, &request, &f->stale_ticket)) || NL_FAILED(nl_path_process(f->world, NL_TEST_BUDGET(0, 0.0), NULL)) ||
        NL_FAILED(nl_path_release(f->world, f->stale_ticket)) || NL_FAILED(nl_path_request(f->world, &request, &f->pending_ticket)))
        fixture_failed("the path tickets");
    {
        /* The agents: a stale id whose slot the walker took; the flyer stepped until it is on a link
           over the gap; then the walker sent across, its path planned by one short step. */
        const nl_agent_def walker = jumper_def(f->navmesh, -8.0f, 3.0f), flyer = jumper_def(f->navmesh, -3.0f, -3.0f);
        static const float walker_goal[3] = {8.0f, 0.0f, 3.0f}, flyer_goal[3] = {4.0f, 0.0f, -3.0f};
        nl_agent_info info = nl_agent_info_init();
        int step;
        if (NL_FAILED(nl_agent_add(f->world, &walker, &f->stale_agent)) || NL_FAILED(nl_agent_remove(f->world, f->stale_agent)))
            fixture_failed("the doomed agent");
        if (NL_FAILED(nl_agent_add(f->world, &walker, &f->agent)) || NL_FAILED(nl_agent_add(f->world, &flyer, &f->flyer)) ||
            NL_FAILED(nl_agent_set_destination(f->world, f->flyer, flyer_goal)))
            fixture_failed("the agents");
        for (step = 0; step < 300 && !in_the_air(info.state); ++step) {
            if (NL_FAILED(nl_world_step(f->world, 1.0f / 30.0f)) || NL_FAILED(nl_agent_get_info(f->world, f->flyer, &info)))
                fixture_failed("the flyer's steps");
        }
        if (!in_the_air(info.state)) fixture_failed("the flyer never took off");
        if (NL_FAILED(nl_agent_set_destination(f->world, f->agent, walker_goal)) || NL_FAILED(nl_world_step(f->world, 0.001f)) ||
            NL_FAILED(nl_world_get_agent_events(f->world, NULL, 0, &f->agent_events)) ||
            NL_FAILED(nl_agent_get_info(f->world, f->flyer, &info)) || !in_the_air(info.state))
            fixture_failed("the walker's path");
    }
}

/* ---------------------------------------------------------------------------------------------
 * Fingerprints: everything a world holds, as named sections of bytes
 * ------------------------------------------------------------------------------------------- */

typedef struct blob {
    unsigned char* data;
    size_t size, capacity;
} blob;

static void put(blob* b, const void* p, size_t n) {
    if (b->size + n > b->capacity) {
        b->capacity = 2 * (b->size + n) + 256;
        b->data = (unsigned char*)realloc(b->data, b->capacity);
        if (!b->data) exit(2);
    }
    memcpy(b->data + b->size, p, n);
    b->size += n;
}

/* A section: its name (NUL-terminated), then its length and bytes. */
static void section(blob* b, const char* name, const blob* content) {
    const uint64_t n = content->size;
    put(b, name, strlen(name) + 1);
    put(b, &n, sizeof n);
    if (content->size) put(b, content->data, content->size);
}

static void put_status(blob* b, nl_status status) { put(b, &status, sizeof status); }

/* Calls that describe one object, or list a world's: the fingerprint's, and the cases'. */
typedef nl_status id_call_fn(nl_world* world, raw_id id, void* out);
typedef nl_status world_list_fn(const nl_world* world, void* out, uint32_t capacity, uint32_t* out_count);

/* Adapters of the id-taking functions to id_call_fn: with no output, with an output of a type, and
   the nl_*_is_valid functions (answered() turns the 0 they must return into the recorded status). */
#define ID_CALL_THROUGH(name, id_type, function, through)       \
    static nl_status name(nl_world* w, raw_id id, void* out) {     \
        (void)out;                                                  \
        return through(function(w, AS(id_type, id)));               \
    }
#define ID_CALL(name, id_type, function) ID_CALL_THROUGH(name, id_type, function, )
#define ID_VALID_CALL(name, id_type, function) ID_CALL_THROUGH(name, id_type, function, answered)
#define ID_OUT_CALL(name, id_type, out_type, function)             \
    static nl_status name(nl_world* w, raw_id id, void* out) {     \
        return function(w, AS(id_type, id), (out_type*)out);        \
    }
static nl_status answered(int32_t valid);

ID_OUT_CALL(mesh_get_info_call, nl_mesh_id, nl_mesh_info, nl_mesh_get_info)
ID_OUT_CALL(navmesh_get_info_call, nl_navmesh_id, nl_navmesh_info, nl_navmesh_get_info)
ID_OUT_CALL(description_call, nl_plugin_id, nl_plugin_description, nl_plugin_get_description)
static nl_status get_meshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_meshes(w, (nl_mesh_id*)out, capacity, count);
}
static nl_status get_navmeshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_navmeshes(w, (nl_navmesh_id*)out, capacity, count);
}
static nl_status get_plugins(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_plugins(w, (nl_plugin_id*)out, capacity, count);
}

/* Each id of a list (at most 16), and what `describe` writes for it into a zeroed struct of
   `size` bytes (its size field set). */
static void put_each(blob* s, nl_world* w, world_list_fn* list, id_call_fn* describe, size_t size) {
    aligned_buffer ids, out;
    uint32_t i, n = 0;
    memset(ids.bytes, 0, sizeof ids.bytes);
    put_status(s, list(w, ids.bytes, 16, &n));
    put(s, &n, sizeof n);
    for (i = 0; i < n && i < 16; ++i) {
        raw_id id;
        const uint32_t struct_size = (uint32_t)size;
        memcpy(&id, ids.bytes + i * sizeof id, sizeof id);
        memset(out.bytes, 0, size);
        memcpy(out.bytes, &struct_size, sizeof struct_size);
        put(s, &id, sizeof id);
        put_status(s, describe(w, id, out.bytes));
        put(s, out.bytes, size);
    }
}

/* Every link of every navmesh. */
static void put_links(blob* s, nl_world* w) {
    aligned_buffer ids;
    uint32_t i, n = 0;
    memset(ids.bytes, 0, sizeof ids.bytes);
    put_status(s, get_navmeshes(w, ids.bytes, 16, &n));
    for (i = 0; i < n && i < 16; ++i) {
        raw_id id;
        uint32_t count = 0;
        nl_link* links;
        memcpy(&id, ids.bytes + i * sizeof id, sizeof id);
        put_status(s, nl_navmesh_get_links(w, AS(nl_navmesh_id, id), NULL, 0, &count));
        links = (nl_link*)calloc(count + 1u, sizeof *links);
        if (!links) exit(2);
        links[0] = nl_link_init();
        put_status(s, nl_navmesh_get_links(w, AS(nl_navmesh_id, id), links, count, &count));
        put(s, &count, sizeof count);
        put(s, links, count * sizeof *links);
        free(links);
    }
}

/* A path's result and points, from the done ticket or planned now. */
typedef nl_status path_fn(const world_fixture* f, nl_path_result* result, nl_path_point* points, uint32_t capacity,
                          uint32_t* count);
static nl_status done_ticket_path(const world_fixture* f, nl_path_result* result, nl_path_point* points, uint32_t capacity,
                                  uint32_t* count) {
    return nl_path_get_result(f->world, f->done_ticket, result, points, capacity, count);
}
static nl_status known_path(const world_fixture* f, nl_path_result* result, nl_path_point* points, uint32_t capacity,
                            uint32_t* count) {
    const nl_path_request_def request = gap_request(f->navmesh);
    return nl_path_find(f->world, &request, result, points, capacity, count);
}
static void put_path(blob* s, const world_fixture* f, path_fn* path) {
    nl_path_result result;
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count = 0;
    memset(&result, 0, sizeof result);
    result.size = sizeof result;
    memset(points, 0, sizeof points);
    points[0].size = sizeof points[0]; /* the element size the library lays out with */
    put_status(s, path(f, &result, points, 64, &count));
    put(s, &result, sizeof result);
    put(s, points, sizeof points);
}

/* The queue's counters and the outcomes of the done and pending tickets. */
static void put_queue(blob* s, const world_fixture* f) {
    nl_path_queue_stats stats;
    nl_path_outcome outcomes[2] = {99, 99};
    memset(&stats, 0, sizeof stats);
    stats.size = sizeof stats;
    put_status(s, nl_path_get_queue_stats(f->world, &stats));
    put(s, &stats, sizeof stats);
    put_status(s, nl_path_poll(f->world, f->done_ticket, &outcomes[0]));
    put_status(s, nl_path_poll(f->world, f->pending_ticket, &outcomes[1]));
    put(s, outcomes, sizeof outcomes);
}

/* The manual link, and two rays onto the platform and the lift. */
static void put_link_and_rays(blob* s, const world_fixture* f) {
    static const nl_ray rays[2] = {{{-6, 5, 0}, {0, -1, 0}, 100}, {{42, 5, 0}, {0, -1, 0}, 100}};
    nl_ray_hit hits[2];
    hits[0] = nl_ray_hit_init();
    nl_link link = nl_link_init();
    const int32_t valid = nl_link_is_valid(f->world, f->link);
    memset(&link, 0, sizeof link);
    link.size = sizeof link; /* the element size the library lays out with */
    memset(hits, 0, sizeof hits);
    hits[0].size = sizeof hits[0]; /* the element size the library lays out with */
    put(s, &valid, sizeof valid);
    put_status(s, nl_link_get(f->world, f->link, &link));
    put(s, &link, sizeof link);
    put_status(s, nl_world_cast_rays(f->world, rays, 2, hits));
    put(s, hits, sizeof hits);
}

/* Every agent's info, corners and trajectory, and the last step's events. */
static void put_agents(blob* s, const world_fixture* f) {
    nl_agent_info infos[8];
    nl_agent_event events[16];
    uint32_t n = 0, m = 0, i;
    memset(infos, 0, sizeof infos);
    infos[0].size = sizeof infos[0];
    memset(events, 0, sizeof events);
    events[0].size = sizeof events[0];
    put_status(s, nl_world_get_agents(f->world, infos, 8, &n));
    put(s, &n, sizeof n);
    put(s, infos, sizeof infos);
    put_status(s, nl_world_get_agent_events(f->world, events, 16, &m));
    put(s, &m, sizeof m);
    put(s, events, sizeof events);
    for (i = 0; i < n && i < 8; ++i) {
        nl_path_point corners[16];
        nl_agent_trajectory trajectory;
        uint32_t c = 0;
        const int32_t valid = nl_agent_is_valid(f->world, infos[i].id);
        memset(corners, 0, sizeof corners);
        corners[0].size = sizeof corners[0];
        memset(&trajectory, 0, sizeof trajectory);
        trajectory.size = sizeof trajectory;
        put(s, &valid, sizeof valid);
        put_status(s, nl_agent_get_corners(f->world, infos[i].id, corners, 16, &c));
        put(s, &c, sizeof c);
        put(s, corners, sizeof corners);
        put_status(s, nl_agent_get_trajectory(f->world, infos[i].id, &trajectory));
        put(s, &trajectory, sizeof trajectory);
    }
}

static void fingerprint(world_fixture* f) {
    blob all = {NULL, 0, 0}, s = {NULL, 0, 0};
    int k;
    for (k = 0; k < 9; ++k) {
        static const char* names[9] = {"meshes",     "navmeshes",  "links",          "plugins",
                                       "path queue", "done ticket", "the known path", "the manual link and rays", "agents"};
        s.size = 0;
        switch (k) {
            case 0: put_each(&s, f->world, get_meshes, mesh_get_info_call, sizeof(nl_mesh_info)); break;
            case 1: put_each(&s, f->world, get_navmeshes, navmesh_get_info_call, sizeof(nl_navmesh_info)); break;
            case 2: put_links(&s, f->world); break;
            case 3: put_each(&s, f->world, get_plugins, description_call, sizeof(nl_plugin_description)); break;
            case 4: put_queue(&s, f); break;
            case 5: put_path(&s, f, done_ticket_path); break;
            case 6: put_path(&s, f, known_path); break;
            case 7: put_link_and_rays(&s, f); break;
            default: put_agents(&s, f); break;
        }
        section(&all, names[k], &s);
    }
    free(s.data);
    free(f->fingerprint);
    f->fingerprint = all.data;
    f->fingerprint_size = all.size;
}

/* The first section of `now` that differs from `then`, or NULL. */
static const char* first_difference(const unsigned char* then, size_t then_size, const unsigned char* now, size_t now_size) {
    size_t a = 0, b = 0;
    while (a < then_size && b < now_size) {
        const char* name = (const char*)then + a;
        uint64_t na, nb;
        const size_t la = strlen(name) + 1, lb = strlen((const char*)now + b) + 1;
        memcpy(&na, then + a + la, sizeof na);
        memcpy(&nb, now + b + lb, sizeof nb);
        if (strcmp(name, (const char*)now + b) != 0 || na != nb || memcmp(then + a + la + 8, now + b + lb + 8, (size_t)na) != 0)
            return name;
        a += la + 8 + (size_t)na;
        b += lb + 8 + (size_t)nb;
    }
    return a == then_size && b == now_size ? NULL : "(the sections)";
}

static void refresh_worlds(void) {
    fingerprint(&A);
    fingerprint(&B);
}

static int worlds_unchanged(char* why, size_t why_size) {
    world_fixture* worlds[2] = {&A, &B};
    int k, same = 1;
    why[0] = '\0';
    for (k = 0; k < 2; ++k) {
        unsigned char* then = worlds[k]->fingerprint;
        const size_t then_size = worlds[k]->fingerprint_size;
        const char* differs;
        worlds[k]->fingerprint = NULL;
        fingerprint(worlds[k]);
        differs = first_difference(then, then_size, worlds[k]->fingerprint, worlds[k]->fingerprint_size);
        if (differs) {
            const size_t used = strlen(why);
            snprintf(why + used, why_size - used, "%sworld %c: %s differ", same ? "" : "; ", k == 0 ? 'A' : 'B', differs);
            same = 0;
        }
        /* Keep the reference: a later case is compared with the group's start, not with this one. */
        free(worlds[k]->fingerprint);
        worlds[k]->fingerprint = then;
        worlds[k]->fingerprint_size = then_size;
    }
    return same;
}

static void teardown_worlds(void) {
    world_fixture* worlds[2] = {&A, &B};
    int k;
    for (k = 0; k < 2; ++k) {
        nl_world_destroy(worlds[k]->world);
        free(worlds[k]->fingerprint);
        memset(worlds[k], 0, sizeof *worlds[k]);
    }
}

static void setup_worlds(void) {
    build_world(&A);
    build_world(&B);
    {
        /* The fixture's promises, checked once: the known path takes a link; ids share slots. */
        const nl_path_request_def request = gap_request(A.navmesh);
        nl_path_result result;
        uint32_t count = 0;
        nl_path_outcome pending = 99;
        memset(&result, 0, sizeof result);
        result.size = sizeof result;
        if (NL_FAILED(nl_path_find(A.world, &request, &result, NULL, 0, &count)) || result.outcome != NL_PATH_COMPLETE ||
            result.links_used == 0)
            fixture_failed("the known path does not take a link");
        if (NL_FAILED(nl_path_poll(A.world, A.pending_ticket, &pending)) || pending != NL_PATH_PENDING)
            fixture_failed("the pending ticket is not pending");
        if (A.mesh.index1 != A.stale_mesh.index1 || A.navmesh.index1 != A.stale_navmesh.index1 ||
            A.pending_ticket.index1 != A.stale_ticket.index1 || A.link.index1 != B.link.index1 ||
            (A.link.generation & 0xfffffu) != (B.link.generation & 0xfffffu) || A.agent.index1 != A.stale_agent.index1 ||
            A.agent.index1 != B.agent.index1 || (A.agent.generation & 0xfffffu) != (B.agent.generation & 0xfffffu) ||
            A.flyer.index1 != B.flyer.index1 || A.agent_events == 0u)
            fixture_failed("stale and foreign ids do not share slots with live ones");
    }
    refresh_worlds();
}

/* ---------------------------------------------------------------------------------------------
 * The shapes every case takes: defs made bad field by field, sizes, ids, lists
 * ------------------------------------------------------------------------------------------- */

/* A copy of a def in an aligned buffer, the bytes after it SENTINEL. */
static void* copy_def(aligned_buffer* buffer, const void* def, size_t size) {
    memset(buffer->bytes, SENTINEL, sizeof buffer->bytes);
    memcpy(buffer->bytes, def, size);
    return buffer->bytes;
}

static void set_size(void* def, uint32_t size) { memcpy(def, &size, sizeof size); }

/* Calls the function under test with `def` and checks it failed with `detail` naming `needle`,
   its outputs untouched. */
typedef void refuse_fn(const void* def, nl_status detail, const char* needle);
/* Calls it with `def`, checks it succeeded, and undoes what it did (or takes the worlds as they
   are now as the reference, where the change cannot be undone, as a generation's new link ids). */
typedef void accept_fn(const void* def);

/* One field of a def set to a value: offset and size of the member, and the value's bytes. */
typedef struct field_value {
    size_t offset, size; /* size 0: no change */
    union {
        uint32_t u32;
        int32_t i32;
        size_t length;
        float f32;
        const void* pointer;
    } as;
} field_value;
#define SET_U32(type, member, v) {offsetof(type, member), sizeof(uint32_t), {.u32 = (v)}}
#define SET_I32(type, member, v) {offsetof(type, member), sizeof(int32_t), {.i32 = (v)}}
#define SET_LENGTH(type, member, v) {offsetof(type, member), sizeof(size_t), {.length = (v)}}
#define SET_F32(type, member, v) {offsetof(type, member), sizeof(float), {.f32 = (v)}}
#define SET_PTR(type, member, v) {offsetof(type, member), sizeof(const void*), {.pointer = (v)}}

/* A def made bad (or unusual but allowed) by up to six fields: detail 0 means it is accepted. */
typedef struct def_case {
    const char* description;
    nl_status detail;
    const char* needle;
    field_value set[6];
} def_case;
#define ALLOWED 0u
#define INVALID NL_STATUS_INVALID_ARGUMENT

static void def_cases(const char* function, const void* valid, size_t size, const def_case* cases, size_t count,
                      refuse_fn* refuse, accept_fn* accept) {
    size_t i, k;
    for (i = 0; i < count; ++i) {
        CASE(function, "%s", cases[i].description) {
            aligned_buffer buffer;
            unsigned char* def = (unsigned char*)copy_def(&buffer, valid, size);
            for (k = 0; k < sizeof cases[i].set / sizeof *cases[i].set; ++k)
                memcpy(def + cases[i].set[k].offset, &cases[i].set[k].as, cases[i].set[k].size);
            if (cases[i].detail == ALLOWED) accept(def);
            else refuse(def, cases[i].detail, cases[i].needle);
        }
    }
}

/* A text a function reads, (data, length) as given (OBJ, JSON), and how it must refuse it. */
typedef struct text_case {
    const char* what;
    const char* data;
    size_t length;
    nl_status detail;
    const char* needle;
} text_case;
#define TEXT(literal) literal, sizeof literal - 1

/* A float field of a def (or of an array element): its name as the message spells it, its offset,
   how many floats it has. */
typedef struct float_field {
    const char* name;
    size_t offset;
    unsigned count;
} float_field;
#define FLOAT_FIELD(type, member, n) {#member, offsetof(type, member), (n)}

/* Each float of each field set to each bad value in turn ("def->start[1] NaN"), refused naming it. */
static void bad_float_fields(const char* function, const char* param, const void* valid, size_t size,
                             const float_field* fields, size_t field_count, refuse_fn* refuse) {
    size_t i, v;
    unsigned k;
    for (i = 0; i < field_count; ++i) {
        for (k = 0; k < fields[i].count; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                char subject[96];
                if (fields[i].count > 1) snprintf(subject, sizeof subject, "%s->%s[%u]", param, fields[i].name, k);
                else snprintf(subject, sizeof subject, "%s->%s", param, fields[i].name);
                CASE(function, "%s %s", subject, k_bad_floats[v].name) {
                    aligned_buffer buffer;
                    unsigned char* def = (unsigned char*)copy_def(&buffer, valid, size);
                    memcpy(def + fields[i].offset + k * sizeof(float), &k_bad_floats[v].value, sizeof(float));
                    refuse(def, NL_STATUS_INVALID_ARGUMENT, fields[i].name);
                }
            }
        }
    }
}

/* A def's `size` 0, too small (4: the size field alone) and larger than the library's struct (the
   bytes past it are garbage the library must not read as fields). */
static void def_sizes(const char* function, const char* param, const void* valid, size_t size, refuse_fn* refuse,
                      accept_fn* accept) {
    static const char* what[3] = {"0", "small (4)", "large (sizeof + 64, garbage after the struct)"};
    const uint32_t sizes[3] = {0u, 4u, (uint32_t)size + 64u};
    int k;
    for (k = 0; k < 3; ++k) {
        CASE(function, "%s->size %s", param, what[k]) {
            aligned_buffer buffer;
            void* def = copy_def(&buffer, valid, size);
            set_size(def, sizes[k]);
            if (k < 2) refuse(def, NL_STATUS_INVALID_ARGUMENT, "size");
            else accept(def);
        }
    }
}

/* A function that makes something from a def: `call` runs it on `world` with `def`, writing the
   new object's id (or world) to `out`; `undo` checks an accepted def's object and removes it. */
typedef nl_status def_call_fn(nl_world* world, const void* def, void* out);
typedef struct def_function {
    const char* function;
    def_call_fn* call;
    size_t out_size;
    void (*undo)(const void* out);
    int def_optional; /* a NULL def means the defaults */
    int no_world;     /* nl_world_create: no world to pass (nor log) */
    int world_null_elsewhere; /* its world NULL case is its id cases' */
} def_function;
static const def_function* g_def; /* the function the def cases run now */

static void def_refuses(const void* def, nl_status detail, const char* needle) {
    unsigned char out[16];
    fill(out, sizeof out);
    EXPECT_FAILURE(g_def->no_world ? NULL : A.world, g_def->call(A.world, def, out), detail, needle);
    EXPECT_UNTOUCHED(out, g_def->out_size, "out_id");
}

static void def_accepts(const void* def) {
    unsigned char out[16];
    memset(out, 0, sizeof out);
    EXPECT_OK(g_def->call(A.world, def, out));
    g_def->undo(out);
}

/* The world, the def and the output NULL, and the def's size. */
static void def_function_cases(const def_function* f, const void* valid, size_t size) {
    g_def = f;
    if (!f->no_world && !f->world_null_elsewhere) {
        CASE(f->function, "world NULL") {
            unsigned char out[16];
            fill(out, sizeof out);
            EXPECT_INVALID(NULL, f->call(NULL, valid, out), "world");
            EXPECT_UNTOUCHED(out, f->out_size, "out_id");
        }
    }
    if (f->out_size > 0) {
        CASE(f->function, "%s NULL", f->no_world ? "out_world" : "out_id") {
            EXPECT_INVALID(f->no_world ? NULL : A.world, f->call(A.world, valid, NULL), f->no_world ? "out_world" : "out_id");
        }
    }
    if (f->def_optional) CASE(f->function, "def NULL (allowed: defaults)") { def_accepts(NULL); }
    else CASE(f->function, "def NULL") { def_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes(f->function, "def", valid, size, def_refuses, def_accepts);
}

/* What every geometry def has (nl_mesh_def, nl_navmesh_def): vertex and index arrays. Their rows
   are the same for each, made from the def's offsets and its vertices made bad. */
typedef struct geometry_fields {
    size_t vertices, vertex_count, vertex_stride, indices;
    const float* bad_vertices[3]; /* NaN, inf and -inf at the vertex `bad_vertex` names */
    const char* bad_vertex;
} geometry_fields;
#define GEOMETRY_FIELDS(type) \
    offsetof(type, vertices), offsetof(type, vertex_count), offsetof(type, vertex_stride), offsetof(type, indices)

/* The geometry rows: which fields each one sets (-1: none) to which value. */
enum { GEOMETRY_VERTICES, GEOMETRY_VERTEX_COUNT, GEOMETRY_VERTEX_STRIDE, GEOMETRY_INDICES };
enum { VALUE_NULL, VALUE_NAN_VERTICES, VALUE_INF_VERTICES, VALUE_MINUS_INF_VERTICES, VALUE_0, VALUE_HUGE, VALUE_11 };
typedef struct geometry_row {
    const char* description;
    const char* needle; /* NULL: the bad vertex */
    int field[2], value[2];
} geometry_row;
static const geometry_row k_geometry_rows[] = {
    {"def->vertices NULL", "vertices", {GEOMETRY_VERTICES, -1}, {VALUE_NULL, 0}},
    {"def->vertices NaN", NULL, {GEOMETRY_VERTICES, -1}, {VALUE_NAN_VERTICES, 0}},
    {"def->vertices inf", NULL, {GEOMETRY_VERTICES, -1}, {VALUE_INF_VERTICES, 0}},
    {"def->vertices -inf", NULL, {GEOMETRY_VERTICES, -1}, {VALUE_MINUS_INF_VERTICES, 0}},
    {"def->vertex_count 0", "vertex_count", {GEOMETRY_VERTEX_COUNT, -1}, {VALUE_0, 0}},
    {"def->vertex_count huge (vertices NULL: not read)", "vertices", {GEOMETRY_VERTICES, GEOMETRY_VERTEX_COUNT},
     {VALUE_NULL, VALUE_HUGE}},
    {"def->vertex_stride 11 (below 12)", "vertex_stride", {GEOMETRY_VERTEX_STRIDE, -1}, {VALUE_11, 0}},
    {"def->indices NULL", "indices", {GEOMETRY_INDICES, -1}, {VALUE_NULL, 0}},
};
#define GEOMETRY_ROW_COUNT (sizeof k_geometry_rows / sizeof *k_geometry_rows)

static field_value geometry_value(const geometry_fields* g, int field, int value) {
    const size_t offsets[4] = {g->vertices, g->vertex_count, g->vertex_stride, g->indices};
    const uint32_t integers[3] = {0u, UINT32_MAX, 11u};
    field_value v;
    memset(&v, 0, sizeof v);
    if (field < 0) return v;
    v.offset = offsets[field];
    if (value >= VALUE_0) {
        v.size = sizeof(uint32_t);
        v.as.u32 = integers[value - VALUE_0];
    } else {
        v.size = sizeof(const void*);
        v.as.pointer = value == VALUE_NULL ? NULL : g->bad_vertices[value - VALUE_NAN_VERTICES];
    }
    return v;
}

static void geometry_cases(const char* function, const void* valid, size_t size, const geometry_fields* g) {
    def_case rows[GEOMETRY_ROW_COUNT];
    size_t i;
    int k;
    memset(rows, 0, sizeof rows);
    for (i = 0; i < GEOMETRY_ROW_COUNT; ++i) {
        rows[i].description = k_geometry_rows[i].description;
        rows[i].detail = NL_STATUS_INVALID_ARGUMENT;
        rows[i].needle = k_geometry_rows[i].needle ? k_geometry_rows[i].needle : g->bad_vertex;
        for (k = 0; k < 2; ++k) rows[i].set[k] = geometry_value(g, k_geometry_rows[i].field[k], k_geometry_rows[i].value[k]);
    }
    def_cases(function, valid, size, rows, GEOMETRY_ROW_COUNT, def_refuses, def_accepts);
}

/* An output struct with a `size` field: `call` runs the function with `out` and returns its
   status. Size 0 and 4 are refused with nothing written; sizeof - 1 is either refused or written
   only up to that size; a larger size is accepted and nothing past the library's struct is written. */
typedef nl_status out_call_fn(void* out);
static void out_sizes(const char* function, const char* param, size_t size, out_call_fn* call) {
    static const uint32_t too_small[2] = {0u, 4u};
    int k;
    for (k = 0; k < 2; ++k) {
        CASE(function, k == 0 ? "%s->size 0" : "%s->size small (4)", param) {
            aligned_buffer buffer;
            fill(buffer.bytes, sizeof buffer.bytes);
            set_size(buffer.bytes, too_small[k]);
            EXPECT_INVALID(A.world, call(buffer.bytes), "size");
            EXPECT_UNTOUCHED_AFTER_SIZE(buffer.bytes, size + 64, param);
        }
    }
    CASE(function, "%s->size small (sizeof - 1)", param) {
        aligned_buffer buffer;
        uint32_t kept;
        nl_status status;
        fill(buffer.bytes, sizeof buffer.bytes);
        set_size(buffer.bytes, (uint32_t)size - 1u);
        status = call(buffer.bytes);
        memcpy(&kept, buffer.bytes, sizeof kept);
        if (NL_FAILED(status)) {
            EXPECT_INVALID(A.world, status, "size");
            EXPECT_UNTOUCHED_AFTER_SIZE(buffer.bytes, size + 64, param);
        } else {
            EXPECT(kept == size - 1u, "%s->size became %u", param, (unsigned)kept);
            EXPECT_UNTOUCHED(buffer.bytes + size - 1, 65, "the bytes past the caller's size");
        }
    }
    CASE(function, "%s->size large (sizeof + 64)", param) {
        aligned_buffer buffer;
        uint32_t kept;
        fill(buffer.bytes, sizeof buffer.bytes);
        set_size(buffer.bytes, (uint32_t)size + 64u);
        EXPECT_OK(call(buffer.bytes));
        memcpy(&kept, buffer.bytes, sizeof kept);
        EXPECT(kept == size + 64u, "%s->size became %u", param, (unsigned)kept);
        EXPECT_UNTOUCHED(buffer.bytes + size, 64, "the bytes past the library's struct");
    }
}

/* An output of growable elements (an array laid out by its first element's `size`, or one such
   struct): `call` runs the function with `out` (room for 256 elements of sizeof + 64 bytes) and
   says how many elements a success wrote. Size 0, 4 and sizeof - 1 (no element's size: not a multiple
   of its alignment) are refused with nothing written; a larger size (a newer header's elements) lays
   the array out with that stride, sets each element's size to it and writes nothing past the
   library's part of each. */
typedef nl_status element_call_fn(void* out, uint32_t* written);
static void out_element_sizes(const char* function, const char* param, size_t size, element_call_fn* call) {
    static const uint32_t too_small[2] = {0u, 4u};
    const size_t stride = size + 64u, room = 256u * stride + 64u;
    unsigned char* buffer = (unsigned char*)malloc(room);
    int k;
    if (!buffer) exit(2);
    for (k = 0; k < 3; ++k) {
        CASE(function, k == 0 ? "%s->size 0 (the first element's: unset)" : k == 1 ? "%s->size small (4)"
                                                                            : "%s->size small (sizeof - 1: no struct's size)",
             param) {
            uint32_t written = 0;
            fill(buffer, room);
            set_size(buffer, k < 2 ? too_small[k] : (uint32_t)size - 1u);
            EXPECT_INVALID(A.world, call(buffer, &written), "size");
            EXPECT_UNTOUCHED(buffer + sizeof(uint32_t), room - sizeof(uint32_t), param);
        }
    }
    CASE(function, "%s->size large (sizeof + 64: a newer header's elements)", param) {
        uint32_t written = 0, i, got;
        fill(buffer, room);
        set_size(buffer, (uint32_t)stride);
        EXPECT_OK(call(buffer, &written));
        EXPECT(written >= 1u && written <= 256u, "%u elements written", (unsigned)written);
        for (i = 0; i < written && i < 256u; ++i) {
            memcpy(&got, buffer + i * stride, sizeof got);
            EXPECT(got == stride, "%s[%u].size became %u", param, (unsigned)i, (unsigned)got);
            EXPECT_UNTOUCHED(buffer + i * stride + size, 64, "the bytes of an element past the library's struct");
        }
        EXPECT_UNTOUCHED(buffer + written * stride, 64, "the bytes past the last element");
    }
    free(buffer);
}

/* A function that takes an id: `call` runs it on `world` with `id` and the output `out` (NULL when
   the case passes none); for an nl_*_is_valid function it returns the recorded status and
   reports a 1. */
typedef struct id_function {
    const char* function;
    const char* param;    /* the id's parameter, and the word the message names it by */
    const char* out_name; /* NULL: no output */
    size_t out_size;
    int growable;         /* the output starts with `size`, set by the caller */
    int answers;          /* an nl_*_is_valid: a bad id is an answer (0), not an error */
    id_call_fn* call;
    int out_null_elsewhere; /* the output NULL has cases of its own (optional, or a list's) */
} id_function;

/* The world NULL, the output NULL, and every bad id (named in the message by the last word of
   the parameter: "navmesh" for def->navmesh). */
static void id_cases(const id_function* f, raw_id live, raw_id stale, raw_id foreign) {
    aligned_buffer out;
    void* o = f->out_name ? out.bytes : NULL;
    const char* word = strrchr(f->param, '>') ? strrchr(f->param, '>') + 1 : f->param;
#define FRESH_OUTPUT()                                          \
    do {                                                        \
        fill(out.bytes, sizeof out.bytes);                      \
        if (f->growable) set_size(out.bytes, (uint32_t)f->out_size); \
    } while (0)
#define CHECK_OUTPUT_UNTOUCHED() \
    EXPECT_UNTOUCHED(out.bytes + (f->growable ? 4 : 0), sizeof out.bytes - (f->growable ? 4 : 0), f->out_name ? f->out_name : "memory")
    CASE(f->function, "world NULL") {
        FRESH_OUTPUT();
        EXPECT_INVALID(NULL, f->call(NULL, live, o), "world");
        CHECK_OUTPUT_UNTOUCHED();
    }
    if (f->out_name && !f->out_null_elsewhere) {
        CASE(f->function, "%s NULL", f->out_name) { EXPECT_INVALID(A.world, f->call(A.world, live, NULL), f->out_name); }
    }
    FOR_BAD_IDS(bad, live, stale, foreign) {
        CASE(f->function, "%s %s%s", f->param, bad->what, f->answers ? " (an answer, not an error)" : "") {
            nl_status status;
            FRESH_OUTPUT();
            status = f->call(A.world, bad->id, o);
            if (f->answers) EXPECT_OK(status);
            else EXPECT_BAD_HANDLE(A.world, status, word);
            CHECK_OUTPUT_UNTOUCHED();
        }
    }
#undef FRESH_OUTPUT
#undef CHECK_OUTPUT_UNTOUCHED
}

/* What an nl_*_is_valid returned, as the recorded status; a 1 for a bad id is reported. */
static nl_status answered(int32_t valid) {
    EXPECT(valid == 0, "says %d", (int)valid);
    return nl_get_last_status();
}

/* The two-call list pattern: `call` runs the function with (out, capacity, out_count). */
typedef nl_status list_call_fn(void* out, uint32_t capacity, uint32_t* out_count);
/* A list of growable elements (nl_link...) is laid out with its first element's `size`: fill_items
   sets it after filling, and `untouched` skips it. */
static int g_growable_items;
static void fill_items(unsigned char* items, size_t room, size_t item_size) {
    fill(items, room);
    if (g_growable_items) {
        const uint32_t size = (uint32_t)item_size;
        memcpy(items, &size, sizeof size);
    }
}
static size_t skipped(void) { return g_growable_items ? sizeof(uint32_t) : 0u; }

static void list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                       list_call_fn* call) {
    const size_t room = (expected + 4u) * item_size;
    unsigned char* items = (unsigned char*)malloc(room);
    uint32_t count;
    if (!items) exit(2);
    if (g_growable_items) {
        CASE(function, "%s[0].size 0 (unset): refused, nothing written", out_name) {
            fill_items(items, room, item_size);
            memset(items, 0, sizeof(uint32_t));
            count = 0xdeadbeefu;
            EXPECT_INVALID(A.world, call(items, expected + 4u, &count), "size");
            EXPECT_UNTOUCHED(items + sizeof(uint32_t), room - sizeof(uint32_t), out_name);
        }
        CASE(function, "%s[0].size odd (sizeof + 1): refused, nothing written", out_name) {
            const uint32_t odd = (uint32_t)item_size + 1u;
            fill_items(items, room, item_size);
            memcpy(items, &odd, sizeof odd);
            count = 0xdeadbeefu;
            EXPECT_INVALID(A.world, call(items, expected + 4u, &count), "size");
            EXPECT_UNTOUCHED(items + sizeof(uint32_t), room - sizeof(uint32_t), out_name);
        }
    }
    CASE(function, "out_count NULL") {
        fill_items(items, room, item_size);
        EXPECT_INVALID(A.world, call(items, expected + 4u, NULL), "out_count");
        EXPECT_UNTOUCHED(items + skipped(), room - skipped(), out_name);
    }
    CASE(function, "out_count NULL (counting: %s NULL too)", out_name) {
        EXPECT_INVALID(A.world, call(NULL, 0u, NULL), "out_count");
    }
    CASE(function, "%s NULL (allowed: counts)", out_name) {
        count = 0xdeadbeefu;
        EXPECT_OK(call(NULL, 0u, &count));
        EXPECT(count == expected, "out_count = %u, expected %u", (unsigned)count, (unsigned)expected);
    }
    CASE(function, "%s NULL with capacity 1", out_name) {
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world, call(NULL, 1u, &count), out_name);
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE(function, "capacity huge (%s NULL)", out_name) {
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world, call(NULL, UINT32_MAX, &count), out_name);
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    if (expected > 0u) {
        static const char* what[2] = {"capacity 0 (a buffer given)", "capacity small (one less than needed)"};
        int k;
        for (k = 0; k < 2; ++k) {
            CASE(function, "%s", what[k]) {
                fill_items(items, room, item_size);
                count = 0xdeadbeefu;
                EXPECT_FAILURE(A.world, call(items, k == 0 ? 0u : expected - 1u, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
                EXPECT(count == expected, "out_count = %u, expected the %u needed", (unsigned)count, (unsigned)expected);
                EXPECT_UNTOUCHED(items + skipped(), room - skipped(), out_name);
            }
        }
    }
    CASE(function, "capacity huge (a buffer of %u + 4 entries: only %u written)", (unsigned)expected, (unsigned)expected) {
        fill_items(items, room, item_size);
        count = 0xdeadbeefu;
        EXPECT_OK(call(items, UINT32_MAX, &count));
        EXPECT(count == expected, "out_count = %u, expected %u", (unsigned)count, (unsigned)expected);
        EXPECT_UNTOUCHED(items + expected * item_size, 4u * item_size, "the entries past out_count");
    }
    free(items);
}

/* A list with a world of its own: the world NULL too. */
static world_list_fn* g_world_list;
static nl_status call_world_list(void* out, uint32_t capacity, uint32_t* count) { return g_world_list(A.world, out, capacity, count); }

static void world_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                             world_list_fn* call) {
    CASE(function, "world NULL") {
        uint32_t count;
        fill(&count, sizeof count);
        EXPECT_INVALID(NULL, call(NULL, NULL, 0, &count), "world");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    g_world_list = call;
    list_cases(function, out_name, item_size, expected, call_world_list);
}

/* Something failed first, so the record holds a failure a call that must not touch it could clear. */
static void fail_on_purpose(void) { (void)nl_mesh_remove(NULL, (nl_mesh_id){0u, 0u}); }

static int record_is_the_failure(void) {
    return nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) &&
           strcmp(nl_get_last_error_message(), "nl_mesh_remove: world is null") == 0;
}
/* ---------------------------------------------------------------------------------------------
 * Version, statuses and the last error
 * ------------------------------------------------------------------------------------------- */

static void group_version(void) {
    CASE("nl_get_version", "record untouched (never fails)") {
        nl_version v;
        fail_on_purpose();
        v = nl_get_version();
        EXPECT(v.major == NL_VERSION_MAJOR && v.minor == NL_VERSION_MINOR && v.patch == NL_VERSION_PATCH,
               "nl_get_version() = %d.%d.%d, the header says %d.%d.%d", (int)v.major, (int)v.minor, (int)v.patch,
               NL_VERSION_MAJOR, NL_VERSION_MINOR, NL_VERSION_PATCH);
        EXPECT(record_is_the_failure(), "nl_get_version changed the last error record");
    }
}

static void group_status_string(void) {
    static const nl_status statuses[] = {0u, UINT32_MAX, NL_STATUS_FAILURE, NL_STATUS_SUCCESS | NL_STATUS_FAILURE,
                                         NL_STATUS_IN_PROGRESS | NL_STATUS_FAILURE, NL_STATUS_DETAIL_MASK};
    static const char* names[] = {"status 0", "status huge (0xffffffff)", "status FAILURE without a detail",
                                  "status SUCCESS|FAILURE", "status IN_PROGRESS|FAILURE", "status DETAIL_MASK without a kind"};
    size_t i;
    for (i = 0; i < sizeof statuses / sizeof *statuses; ++i) {
        CASE("nl_status_string", "%s", names[i]) {
            const char* s;
            fail_on_purpose();
            s = nl_status_string(statuses[i]);
            EXPECT(s != NULL && s[0] != '\0', "nl_status_string(0x%08x) is NULL or empty", (unsigned)statuses[i]);
            EXPECT(record_is_the_failure(), "nl_status_string changed the last error record");
        }
    }
    CASE("nl_status_string", "status every single bit, alone and with FAILURE") {
        int bit;
        for (bit = 0; bit < 32; ++bit) {
            const char* alone = nl_status_string((nl_status)1u << bit);
            const char* failed = nl_status_string(NL_STATUS_FAILURE | ((nl_status)1u << bit));
            EXPECT(alone && alone[0] && failed && failed[0], "nl_status_string of bit %d is NULL or empty", bit);
        }
    }
}

static void* fresh_thread_record(void* out) {
    int* ok = (int*)out;
    const char* message = nl_get_last_error_message();
    *ok = nl_get_last_status() == NL_STATUS_SUCCESS && message != NULL && message[0] == '\0';
    (void)nl_mesh_remove(NULL, (nl_mesh_id){0u, 0u}); /* this thread's failure is its own */
    return NULL;
}

static void group_last_error(void) {
    static const char* functions[2] = {"nl_get_last_status", "nl_get_last_error_message"};
    int k;
    for (k = 0; k < 2; ++k) {
        CASE(functions[k], "thread fresh (SUCCESS and an empty message, never NULL), and per thread") {
            pthread_t thread;
            int ok = 0;
            fail_on_purpose();
            EXPECT(pthread_create(&thread, NULL, fresh_thread_record, &ok) == 0, "pthread_create failed");
            pthread_join(thread, NULL);
            EXPECT(ok, "a thread that made no call has a last status other than SUCCESS, or a NULL or non-empty message");
            EXPECT(record_is_the_failure(), "another thread's failure changed this thread's record");
        }
    }
    CASE("nl_get_last_error_message", "record read twice (the getters do not touch it)") {
        fail_on_purpose();
        (void)nl_get_last_error_message();
        (void)nl_get_last_status();
        EXPECT(record_is_the_failure(), "reading the record changed it");
    }
}

/* ---------------------------------------------------------------------------------------------
 * Defaults: never fail, set `size`, leave the record alone
 * ------------------------------------------------------------------------------------------- */

#define DEFAULT_CASE(function, type, has_size)                                                         \
    CASE(#function, "record untouched (never fails)") {                                               \
        type value;                                                                                   \
        fail_on_purpose();                                                                            \
        value = function();                                                                           \
        EXPECT(record_is_the_failure(), #function " changed the last error record");                 \
        if (has_size) {                                                                               \
            uint32_t size;                                                                            \
            memcpy(&size, &value, sizeof size);                                                       \
            EXPECT(size == sizeof(type), #function "().size = %u, not sizeof = %u", (unsigned)size,  \
                   (unsigned)sizeof(type));                                                          \
        }                                                                                             \
    }

static void group_defaults(void) {
    DEFAULT_CASE(nl_default_world_def, nl_world_def, 1)
    DEFAULT_CASE(nl_default_mesh_def, nl_mesh_def, 1)
    DEFAULT_CASE(nl_default_navmesh_def, nl_navmesh_def, 1)
    DEFAULT_CASE(nl_default_navmesh_build_def, nl_navmesh_build_def, 1)
    DEFAULT_CASE(nl_default_navmesh_load_def, nl_navmesh_load_def, 1)
    DEFAULT_CASE(nl_default_recast_settings, nl_recast_settings, 1)
    DEFAULT_CASE(nl_default_link_def, nl_link_def, 1)
    DEFAULT_CASE(nl_default_link_settings, nl_link_settings, 1)
    DEFAULT_CASE(nl_default_path_request_def, nl_path_request_def, 1)
    DEFAULT_CASE(nl_default_path_budget, nl_path_budget, 1)
    DEFAULT_CASE(nl_default_agent_type, nl_agent_type, 0)
    DEFAULT_CASE(nl_default_agent_capabilities, nl_agent_capabilities, 0)
    DEFAULT_CASE(nl_default_agent_def, nl_agent_def, 1)
    CASE("nl_default_agent_type", "values as documented (0.6, 2, 0.9, 45)") {
        const nl_agent_type a = nl_default_agent_type();
        EXPECT(a.radius == 0.6f && a.height == 2.0f && a.max_climb == 0.9f && a.max_slope == 45.0f,
               "nl_default_agent_type() = {%g, %g, %g, %g}", a.radius, a.height, a.max_climb, a.max_slope);
    }
    CASE("nl_default_agent_def", "values as documented (a walker, height 2, 3.5 m/s, 8 m/s2, gravity 9.81, avoidance on)") {
        const nl_agent_def d = nl_default_agent_def();
        const nl_agent_capabilities c = nl_default_agent_capabilities();
        EXPECT(d.navmesh.index1 == 0u && d.navmesh.generation == 0u && d.height == 2.0f && d.max_speed == 3.5f &&
                   d.max_acceleration == 8.0f && d.gravity == 9.81f && d.takeoff_speed == 0.0f && d.position[0] == 0.0f &&
                   d.position[1] == 0.0f && d.position[2] == 0.0f && d.avoidance == 1u && d.user_data == 0u &&
                   memcmp(&d.capabilities, &c, sizeof c) == 0,
               "nl_default_agent_def() = {height %g, speed %g, acceleration %g, gravity %g, avoidance %u}", d.height, d.max_speed,
               d.max_acceleration, d.gravity, (unsigned)d.avoidance);
    }
    CASE("nl_default_agent_capabilities", "values as documented (a walker: radius 0.6, no jumps)") {
        const nl_agent_capabilities a = nl_default_agent_capabilities();
        EXPECT(a.radius == 0.6f && a.max_jump_distance == 0.0f && a.max_jump_height == 0.0f && a.max_drop_height == 0.0f &&
                   a.abilities == 0u,
               "nl_default_agent_capabilities() = {%g, %g, %g, %g}", a.max_jump_distance, a.max_jump_height,
               a.max_drop_height, a.radius);
    }
}

/* ---------------------------------------------------------------------------------------------
 * The world
 * ------------------------------------------------------------------------------------------- */

static nl_status world_create_call(nl_world* world, const void* def, void* out) {
    (void)world;
    return nl_world_create((const nl_world_def*)def, (nl_world**)out);
}

/* A world created as documented: it works, and is destroyed. */
static void world_destroy_out(const void* out) {
    nl_world* world;
    memcpy(&world, out, sizeof world);
    EXPECT(world != NULL && nl_world_get_worker_count(world) >= 1, "no working world was returned");
    nl_world_destroy(world);
}

static const def_case k_world_defs[] = {
    {"def->worker_count -2", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, -2)}},
    {"def->worker_count INT32_MIN", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, INT32_MIN)}},
    {"def->worker_count huge (INT32_MAX)", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, INT32_MAX)}},
    {"def->worker_count huge (NL_MAX_WORKERS + 1)", INVALID, "NL_MAX_WORKERS",
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS + 1)}},
    {"def->worker_count 0 (allowed: the calling thread only)", ALLOWED, NULL, {SET_I32(nl_world_def, worker_count, 0)}},
    {"def->path_worker_count -2", INVALID, "path_worker_count", {SET_I32(nl_world_def, path_worker_count, -2)}},
    {"def->path_worker_count huge (INT32_MAX)", INVALID, "path_worker_count",
     {SET_I32(nl_world_def, path_worker_count, INT32_MAX)}},
    {"def->path_worker_count 0 (allowed: the host runs the queue)", ALLOWED, NULL, {SET_I32(nl_world_def, path_worker_count, 0)}},
    {"def->log_level 4", INVALID, "log_level", {SET_U32(nl_world_def, log_level, 4u)}},
    {"def->log_level huge", INVALID, "log_level", {SET_U32(nl_world_def, log_level, UINT32_MAX)}},
    {"def->log_fn NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_world_def, log_fn, NULL)}},
    {"def->log_user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_world_def, log_user, NULL)}},
};

/* A host task system that runs every task at once (and returns NULL), for defs with task callbacks. */
static void* hostile_task_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count,
                                  uint32_t min_range) {
    (void)user;
    (void)min_range;
    task(task_context, 0u, item_count, 0u);
    return NULL;
}
static void hostile_task_finish(void* user, void* host_task) {
    (void)user;
    (void)host_task;
}

/* Made bad from a def with both task callbacks set and worker_count 2. */
static const def_case k_world_task_defs[] = {
    {"def->task_enqueue_fn NULL (task_finish_fn set)", INVALID, "def->task_enqueue_fn is NULL",
     {SET_PTR(nl_world_def, task_enqueue_fn, NULL)}},
    {"def->task_finish_fn NULL (task_enqueue_fn set)", INVALID, "def->task_finish_fn is NULL",
     {SET_PTR(nl_world_def, task_finish_fn, NULL)}},
    {"def->task_enqueue_fn NULL and task_finish_fn NULL (allowed: TBB)", ALLOWED, NULL,
     {SET_PTR(nl_world_def, task_enqueue_fn, NULL), SET_PTR(nl_world_def, task_finish_fn, NULL)}},
    {"def->task_user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_world_def, task_user, NULL)}},
    {"def->worker_count 0 (with task callbacks: the host's workers, at least 1)", INVALID, "worker_count",
     {SET_I32(nl_world_def, worker_count, 0)}},
    {"def->worker_count -1 (NL_WORKERS_AUTO, with task callbacks)", INVALID, "worker_count",
     {SET_I32(nl_world_def, worker_count, NL_WORKERS_AUTO)}},
    {"def->worker_count huge (NL_MAX_WORKERS + 1, with task callbacks)", INVALID, "NL_MAX_WORKERS",
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS + 1)}},
    {"def->worker_count NL_MAX_WORKERS (allowed with task callbacks: no thread starts)", ALLOWED, NULL,
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS)}},
    {"def->size small (ends inside the task callbacks)", INVALID, "def->size",
     {SET_U32(nl_world_def, size, (uint32_t)offsetof(nl_world_def, task_finish_fn))}},
    {"def->size small (before the task callbacks: they are not read)", ALLOWED, NULL,
     {SET_U32(nl_world_def, size, (uint32_t)offsetof(nl_world_def, task_enqueue_fn)),
      SET_PTR(nl_world_def, task_finish_fn, NULL)}},
};

static void group_world_create(void) {
    static const def_function create = {"nl_world_create", world_create_call, sizeof(nl_world*), world_destroy_out, 1, 1, 0};
    nl_world_def with_tasks;
    nl_world_def valid = nl_default_world_def();
#if !defined(NAVLINK_HOSTILE_SANITIZED)
    /* A library that starts the absurd thread counts runs out of stacks in milliseconds here instead
       of taking the machine's threads (not under sanitizers: their shadow memory needs the room). */
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > ((rlim_t)8 << 30))) {
        limit.rlim_cur = (rlim_t)8 << 30;
        setrlimit(RLIMIT_AS, &limit);
    }
#endif
    valid.worker_count = 1;
    valid.path_worker_count = 0;
    valid.log_fn = hostile_log; /* nl_world_create never logs: there is no world yet */
    def_function_cases(&create, &valid, sizeof valid);
    def_cases("nl_world_create", &valid, sizeof valid, k_world_defs, sizeof k_world_defs / sizeof *k_world_defs, def_refuses,
              def_accepts);
    with_tasks = valid;
    with_tasks.worker_count = 2;
    with_tasks.task_enqueue_fn = hostile_task_enqueue;
    with_tasks.task_finish_fn = hostile_task_finish;
    with_tasks.task_user = &with_tasks;
    def_cases("nl_world_create", &with_tasks, sizeof with_tasks, k_world_task_defs,
              sizeof k_world_task_defs / sizeof *k_world_task_defs, def_refuses, def_accepts);
}

static void group_world_destroy(void) {
    CASE("nl_world_destroy", "world NULL (allowed: ignored)") {
        fail_on_purpose();
        nl_world_destroy(NULL);
        EXPECT(nl_get_last_status() == NL_STATUS_SUCCESS && nl_get_last_error_message()[0] == '\0',
               "nl_world_destroy(NULL) left the status 0x%08x, \"%s\"", (unsigned)nl_get_last_status(),
               nl_get_last_error_message());
    }
}

static void group_world_get_worker_count(void) {
    CASE("nl_world_get_worker_count", "world NULL") {
        const int32_t n = nl_world_get_worker_count(NULL);
        EXPECT(n == 0, "returned %d for a NULL world", (int)n);
        EXPECT_INVALID(NULL, nl_get_last_status(), "world");
    }
    CASE("nl_world_get_worker_count", "world valid (1 worker, recorded as a success)") {
        const int32_t n = nl_world_get_worker_count(A.world);
        EXPECT(n == 1, "returned %d", (int)n);
        EXPECT_OK(nl_get_last_status());
    }
}

/* ---------------------------------------------------------------------------------------------
 * Level geometry
 * ------------------------------------------------------------------------------------------- */

/* A 2 x 2 m floor at y = 3 over the right platform, counter-clockwise from above, and copies of it
   made bad. */
static const float k_tile[12] = {4, 3, -1, 4, 3, 1, 6, 3, 1, 6, 3, -1};
static const float k_tile_nan[12] = {4, 3, -1, 4, 3, 1, 6, NAN, 1, 6, 3, -1};
static const float k_tile_inf[12] = {4, 3, -1, 4, 3, 1, INFINITY, 3, 1, 6, 3, -1};
static const float k_tile_minus_inf[12] = {4, 3, -1, 4, 3, 1, 6, 3, -INFINITY, 6, 3, -1};
static const float k_tile_far[12] = {4, 3, -1, 2.0e9f, 3, 1, 6, 3, 1, 6, 3, -1};
static const uint32_t k_tile_indices[6] = {0, 1, 2, 0, 2, 3};
static const uint32_t k_tile_index_4[6] = {0, 1, 2, 0, 4, 3};
static const uint32_t k_tile_index_huge[6] = {0, 1, 2, 0, UINT32_MAX, 3};
static const uint32_t k_tile_flat[6] = {0, 0, 1, 2, 2, 2};

static nl_mesh_def tile_def(void) { return mesh_def_of(k_tile, 4, k_tile_indices, 2); }

/* Transforms the header refuses: non-finite elements, not affine, singular, or moving the geometry
   beyond the coordinate limit (element 14). */
typedef struct transform_change {
    const char* what;
    int index;
    float value;
} transform_change;
static const transform_change k_bad_transforms[] = {
    {"[0] NaN", 0, NAN},          {"[5] inf", 5, INFINITY}, {"[10] -inf", 10, -INFINITY},
    {"[12] NaN", 12, NAN},        {"[13] inf", 13, INFINITY}, {"[15] NaN", 15, NAN},
    {"[3] non-affine (1)", 3, 1}, {"[15] non-affine (2)", 15, 2}, {"[0] singular (0: flattens x)", 0, 0},
    {"[14] beyond the limit (2e9)", 14, 2.0e9f},
};
#define BAD_TRANSFORM_COUNT (sizeof k_bad_transforms / sizeof *k_bad_transforms)
static const float k_identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static void transform_from(const transform_change* c, float m[16]) {
    memcpy(m, k_identity, sizeof k_identity);
    m[c->index] = c->value;
}
static const char* transform_needle(const transform_change* c) { return c->index == 14 ? "limit" : "transform"; }

/* Each bad transform as a def's (`set` puts it in the def and calls). */
static void bad_def_transforms(const char* function, const char* suffix, const nl_mesh_def* valid, refuse_fn* refuse) {
    size_t i;
    for (i = 0; i < BAD_TRANSFORM_COUNT; ++i) {
        CASE(function, "def->transform%s%s", k_bad_transforms[i].what, suffix) {
            float m[16];
            nl_mesh_def def = *valid;
            transform_from(&k_bad_transforms[i], m);
            def.transform = m;
            refuse(&def, NL_STATUS_INVALID_ARGUMENT, transform_needle(&k_bad_transforms[i]));
        }
    }
}

/* A mesh added as documented is valid, and is removed: the worlds end as they were. */
static void remove_mesh_out(const void* out) {
    nl_mesh_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_mesh_is_valid(A.world, id) == 1, "the new mesh {%u, %u} is not valid", (unsigned)id.index1, (unsigned)id.generation);
    EXPECT_OK(nl_mesh_remove(A.world, id));
}

static nl_status mesh_add_call(nl_world* world, const void* def, void* out) {
    return nl_mesh_add(world, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}

/* What nl_mesh_add and the two OBJ loads share: the def function's cases, the flags, the transform. */
static void mesh_def_cases(const def_function* f, const nl_mesh_def* valid) {
    def_function_cases(f, valid, sizeof *valid);
    CASE(f->function, "def->flags unknown (0x10)") {
        nl_mesh_def def = *valid;
        def.flags = 0x10u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "flags");
    }
    CASE(f->function, "def->flags NL_MESH_OBSTACLE | NL_MESH_NOT_IN_NAVMESH (contradictory)") {
        nl_mesh_def def = *valid;
        def.flags = NL_MESH_OBSTACLE | NL_MESH_NOT_IN_NAVMESH;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "NL_MESH_NOT_IN_NAVMESH");
    }
    CASE(f->function, "def->area huge (NL_MESH_MAX_AREA + 1)") {
        nl_mesh_def def = *valid;
        def.area = NL_MESH_MAX_AREA + 1u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "area");
    }
    CASE(f->function, "def->area huge (UINT32_MAX)") {
        nl_mesh_def def = *valid;
        def.area = UINT32_MAX;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "area");
    }
    CASE(f->function, "def->reserved not 0") {
        nl_mesh_def def = *valid;
        def.reserved = 1u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "reserved");
    }
    CASE(f->function, "def->transform NULL (allowed: identity)") { def_accepts(valid); }
    bad_def_transforms(f->function, "", valid, def_refuses);
    {
        static const struct {
            const char* name;
            float value;
        } bad_units[] = {{"def->metres_per_unit NaN", NAN}, {"def->metres_per_unit inf", INFINITY},
                         {"def->metres_per_unit -inf", -INFINITY}, {"def->metres_per_unit negative", -0.01f},
                         {"def->metres_per_unit tiny (1e-7)", 1e-7f}, {"def->metres_per_unit huge (1e7)", 1e7f}};
        size_t i;
        for (i = 0; i < sizeof bad_units / sizeof bad_units[0]; ++i) {
            CASE(f->function, "%s", bad_units[i].name) {
                nl_mesh_def def = *valid;
                def.metres_per_unit = bad_units[i].value;
                def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "metres_per_unit");
            }
        }
    }
    CASE(f->function, "def->up_axis 3") {
        nl_mesh_def def = *valid;
        def.up_axis = 3u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "up_axis");
    }
    CASE(f->function, "def->up_axis huge (UINT32_MAX)") {
        nl_mesh_def def = *valid;
        def.up_axis = UINT32_MAX;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "up_axis");
    }
}

static const geometry_fields k_mesh_geometry = {GEOMETRY_FIELDS(nl_mesh_def), {k_tile_nan, k_tile_inf, k_tile_minus_inf}, "vertices[2]"};
static const def_case k_mesh_defs[] = {
    {"def->vertices beyond the limit (2e9)", INVALID, "vertices[1]", {SET_PTR(nl_mesh_def, vertices, k_tile_far)}},
    {"def->indices out of range (4)", INVALID, "indices[4]", {SET_PTR(nl_mesh_def, indices, k_tile_index_4)}},
    {"def->indices out of range (UINT32_MAX)", INVALID, "indices[4]", {SET_PTR(nl_mesh_def, indices, k_tile_index_huge)}},
    {"def->indices degenerate (every triangle)", INVALID, "degenerate", {SET_PTR(nl_mesh_def, indices, k_tile_flat)}},
    {"def->triangle_count 0", INVALID, "triangle_count", {SET_U32(nl_mesh_def, triangle_count, 0u)}},
    {"def->triangle_count huge (indices NULL: not read)", INVALID, "indices",
     {SET_PTR(nl_mesh_def, indices, NULL), SET_U32(nl_mesh_def, triangle_count, UINT32_MAX)}},
    {"def->flags unknown (0x80000000)", INVALID, "flags", {SET_U32(nl_mesh_def, flags, 0x80000000u)}},
};

static void group_mesh_add(void) {
    static const def_function add = {"nl_mesh_add", mesh_add_call, sizeof(nl_mesh_id), remove_mesh_out, 0, 0, 0};
    const nl_mesh_def valid = tile_def();
    nl_mesh_def movable = valid;
    movable.flags = NL_MESH_MOVABLE;
    mesh_def_cases(&add, &valid);
    geometry_cases("nl_mesh_add", &valid, sizeof valid, &k_mesh_geometry);
    def_cases("nl_mesh_add", &valid, sizeof valid, k_mesh_defs, sizeof k_mesh_defs / sizeof *k_mesh_defs, def_refuses, def_accepts);
    bad_def_transforms("nl_mesh_add", " (movable)", &movable, def_refuses);
}

/* OBJ loads: a file and the same text in memory; g_obj_text is what the memory load reads. */
static const char k_obj[] = "v 4 3 -1\nv 4 3 1\nv 6 3 1\nv 6 3 -1\nf 1 2 3 4\n";
static char g_tmp[64];       /* a folder of the child's own */
static char g_obj_path[128]; /* k_obj as a file */

static void write_file(const char* path, const char* text) {
    FILE* f = fopen(path, "wb");
    if (!f || fwrite(text, 1, strlen(text), f) != strlen(text)) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(4);
    }
    fclose(f);
}

/* The folder, with quad.obj and an empty folder dir.obj in it. */
static void make_tmp(void) {
    char path[128];
    snprintf(g_tmp, sizeof g_tmp, "/tmp/navlink-hostile-XXXXXX");
    if (!mkdtemp(g_tmp)) {
        fprintf(stderr, "mkdtemp failed\n");
        exit(4);
    }
    snprintf(g_obj_path, sizeof g_obj_path, "%s/quad.obj", g_tmp);
    write_file(g_obj_path, k_obj);
    snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
    mkdir(path, 0700);
}

/* Removes the folder and the files the group made in it. */
static void remove_tmp(const char* const* names, size_t count) {
    char path[256];
    size_t i;
    for (i = 0; i < count; ++i) {
        snprintf(path, sizeof path, "%s/%s", g_tmp, names[i]);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/quad.obj", g_tmp);
    remove(path);
    snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
    remove(path);
    if (remove(g_tmp) != 0) fprintf(stderr, "note: cannot remove %s\n", g_tmp);
}

static const char* g_obj_text;
static size_t g_obj_length;
static nl_status add_obj_file(nl_world* world, const void* def, void* out) {
    return nl_mesh_add_obj_file(world, g_obj_path, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}
static nl_status add_obj_memory(nl_world* world, const void* def, void* out) {
    return nl_mesh_add_obj_memory(world, g_obj_text, g_obj_length, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}
static const def_function k_obj_file = {"nl_mesh_add_obj_file", add_obj_file, sizeof(nl_mesh_id), remove_mesh_out, 1, 0, 0};
static const def_function k_obj_memory = {"nl_mesh_add_obj_memory", add_obj_memory, sizeof(nl_mesh_id), remove_mesh_out, 1, 0, 0};

/* An OBJ def may set flags, transform and user_data only. */
static const def_case k_obj_defs[] = {
    {"def->vertices NULL (allowed: an OBJ def has no geometry)", ALLOWED, NULL, {SET_PTR(nl_mesh_def, vertices, NULL)}},
    {"def->vertices set (geometry in an OBJ def)", INVALID, "geometry", {SET_PTR(nl_mesh_def, vertices, k_tile)}},
    {"def->vertices NaN (geometry in an OBJ def)", INVALID, "geometry",
     {SET_PTR(nl_mesh_def, vertices, k_tile_nan), SET_U32(nl_mesh_def, vertex_count, 4u)}},
    {"def->vertices inf (geometry in an OBJ def)", INVALID, "geometry",
     {SET_PTR(nl_mesh_def, vertices, k_tile_inf), SET_U32(nl_mesh_def, vertex_count, 4u)}},
    {"def->vertex_count 0 (allowed: the default)", ALLOWED, NULL, {SET_U32(nl_mesh_def, vertex_count, 0u)}},
    {"def->vertex_count huge (geometry in an OBJ def)", INVALID, "geometry", {SET_U32(nl_mesh_def, vertex_count, UINT32_MAX)}},
    {"def->indices NULL (allowed: the default)", ALLOWED, NULL, {SET_PTR(nl_mesh_def, indices, NULL)}},
    {"def->indices set (geometry in an OBJ def)", INVALID, "geometry", {SET_PTR(nl_mesh_def, indices, k_tile_indices)}},
    {"def->triangle_count 0 (allowed: the default)", ALLOWED, NULL, {SET_U32(nl_mesh_def, triangle_count, 0u)}},
    {"def->triangle_count huge (geometry in an OBJ def)", INVALID, "geometry",
     {SET_U32(nl_mesh_def, triangle_count, UINT32_MAX)}},
};

/* Malformed text: non-finite numbers, faces past the vertices, no faces. */
typedef struct bad_obj {
    const char* what;
    const char* text;
    const char* needle;
} bad_obj;
static const bad_obj k_bad_objs[] = {
    {"text NaN coordinate", "v 0 0 0\nv 1 0 0\nv nan 0 1\nf 1 2 3\n", ":3:"},
    {"text inf coordinate", "v 0 0 0\nv 1 0 0\nv 1 inf 1\nf 1 2 3\n", ":3:"},
    {"text -inf coordinate", "v 0 0 0\nv -inf 0 0\nv 1 0 1\nf 1 2 3\n", ":2:"},
    {"text coordinate overflowing float (1e39)", "v 0 0 0\nv 1 0 0\nv 1 0 1e39\nf 1 2 3\n", ":3:"},
    {"text face index past the vertices", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 4\n", ":4: vertex index 4 is past the last one"},
    {"text face index huge", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 99999999999999999999\n", ":4:"},
    {"text no faces", "v 0 0 0\nv 1 0 0\n", "face"},
};

/* `from_file`: the text goes to bad.obj and the file is loaded, else it is loaded from memory. */
static void bad_obj_cases(const char* function, int from_file) {
    char path[160];
    size_t i;
    snprintf(path, sizeof path, "%s/bad.obj", g_tmp);
    for (i = 0; i < sizeof k_bad_objs / sizeof *k_bad_objs; ++i) {
        CASE(function, "%s", k_bad_objs[i].what) {
            nl_mesh_id out;
            nl_status status;
            fill(&out, sizeof out);
            if (from_file) {
                write_file(path, k_bad_objs[i].text);
                status = nl_mesh_add_obj_file(A.world, path, NULL, &out);
            } else {
                status = nl_mesh_add_obj_memory(A.world, k_bad_objs[i].text, strlen(k_bad_objs[i].text), NULL, &out);
            }
            EXPECT_FAILURE(A.world, status, NL_STATUS_PARSE_ERROR, k_bad_objs[i].needle);
            EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        }
    }
}

static void obj_def_cases(const def_function* f) {
    const nl_mesh_def valid = nl_default_mesh_def();
    mesh_def_cases(f, &valid);
    def_cases(f->function, &valid, sizeof valid, k_obj_defs, sizeof k_obj_defs / sizeof *k_obj_defs, def_refuses, def_accepts);
}

/* A path a loader must refuse: `name` in the group's folder, or `path` as it is. */
typedef struct bad_path {
    const char* what;
    const char* name; /* under the folder; NULL: the path as given */
    const char* path;
    nl_status detail;
    const char* needle;
} bad_path;

static void bad_path_cases(const char* function, nl_status (*load)(const char* path, void* out), size_t out_size,
                           const bad_path* paths, size_t count) {
    size_t i;
    for (i = 0; i < count; ++i) {
        CASE(function, "%s", paths[i].what) {
            char path[256];
            unsigned char out[16];
            const char* p = paths[i].path;
            if (paths[i].name) {
                snprintf(path, sizeof path, "%s/%s", g_tmp, paths[i].name);
                p = path;
            }
            fill(out, sizeof out);
            EXPECT_FAILURE(A.world, load(p, out), paths[i].detail, paths[i].needle);
            EXPECT_UNTOUCHED(out, out_size, "out_id");
        }
    }
}

/* Paths every loader refuses (an OBJ file, a plugin), with the folder of make_tmp. */
static const bad_path k_bad_paths[] = {
    {"path NULL", NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "path"},
    {"path empty", NULL, "", NL_STATUS_NOT_FOUND, "''"},
    {"path missing", "no-such-file", NULL, NL_STATUS_NOT_FOUND, "no-such-file"},
    {"path a directory", "dir.obj", NULL, NL_STATUS_IO_ERROR, "dir.obj"},
};
#define BAD_PATH_COUNT (sizeof k_bad_paths / sizeof *k_bad_paths)

static nl_status load_obj_at(const char* path, void* out) {
    return nl_mesh_add_obj_file(A.world, path, NULL, (nl_mesh_id*)out);
}

static void group_mesh_add_obj_file(void) {
    static const char* made[] = {"bad.obj"};
    make_tmp();
    bad_path_cases("nl_mesh_add_obj_file", load_obj_at, sizeof(nl_mesh_id), k_bad_paths, BAD_PATH_COUNT);
    CASE("nl_mesh_add_obj_file", "path huge (8000 characters)") {
        char* long_path = (char*)malloc(8001);
        nl_mesh_id out;
        nl_status status;
        if (!long_path) exit(2);
        memset(long_path, 'a', 8000);
        long_path[0] = '/';
        long_path[8000] = '\0';
        fill(&out, sizeof out);
        status = nl_mesh_add_obj_file(A.world, long_path, NULL, &out);
        EXPECT(status == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND) || status == (NL_STATUS_FAILURE | NL_STATUS_IO_ERROR),
               "returned 0x%08x (%s), expected NOT_FOUND or IO_ERROR", (unsigned)status, nl_status_string(status));
        EXPECT_FAILURE(A.world, status, status & NL_STATUS_DETAIL_MASK, "aaaa");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        free(long_path);
    }
    bad_obj_cases("nl_mesh_add_obj_file", 1);
    obj_def_cases(&k_obj_file);
    remove_tmp(made, 1);
}


static void group_mesh_add_obj_memory(void) {
    const size_t n = strlen(k_obj);
    const text_case texts[] = {
        {"data NULL (length 10)", NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data"},
        {"length huge (data NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data"},
        {"length 0 (no faces)", k_obj, 0, NL_STATUS_PARSE_ERROR, "face"},
        {"length 0 (data NULL: no faces)", NULL, 0, NL_STATUS_PARSE_ERROR, "face"},
        {"length short (the face cut to two corners)", k_obj, n - 5, NL_STATUS_PARSE_ERROR, ":5:"},
    };
    size_t i;
    g_obj_text = k_obj;
    g_obj_length = n;
    for (i = 0; i < sizeof texts / sizeof *texts; ++i) {
        CASE("nl_mesh_add_obj_memory", "%s", texts[i].what) {
            nl_mesh_id out;
            fill(&out, sizeof out);
            EXPECT_FAILURE(A.world, nl_mesh_add_obj_memory(A.world, texts[i].data, texts[i].length, NULL, &out), texts[i].detail,
                           texts[i].needle);
            EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        }
    }
    CASE("nl_mesh_add_obj_memory", "data not NUL-terminated (allowed: exactly length bytes read)") {
        char* exact = (char*)malloc(n);
        if (!exact) exit(2);
        memcpy(exact, k_obj, n);
        g_obj_text = exact;
        g_def = &k_obj_memory;
        def_accepts(NULL);
        g_obj_text = k_obj;
        free(exact);
    }
    bad_obj_cases("nl_mesh_add_obj_memory", 0);
    obj_def_cases(&k_obj_memory);
}

/* The functions that take a mesh id. */
static float g_moved[16];
ID_CALL(mesh_remove_call, nl_mesh_id, nl_mesh_remove)
static nl_status mesh_set_transform_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_mesh_set_transform(w, AS(nl_mesh_id, id), g_moved);
}
ID_VALID_CALL(mesh_is_valid_call, nl_mesh_id, nl_mesh_is_valid)
static const id_function k_mesh_functions[] = {
    {"nl_mesh_remove", "mesh", NULL, 0, 0, 0, mesh_remove_call, 0},
    {"nl_mesh_set_transform", "mesh", NULL, 0, 0, 0, mesh_set_transform_call, 0},
    {"nl_mesh_is_valid", "mesh", NULL, 0, 0, 1, mesh_is_valid_call, 0},
    {"nl_mesh_get_info", "mesh", "out_info", sizeof(nl_mesh_info), 1, 0, mesh_get_info_call, 0},
};

static void mesh_id_cases(size_t which) { id_cases(&k_mesh_functions[which], RAW(A.mesh), RAW(A.stale_mesh), RAW(B.mesh)); }

static void group_mesh_remove(void) { mesh_id_cases(0); }

static void group_mesh_set_transform(void) {
    size_t i;
    int k;
    memcpy(g_moved, k_identity, sizeof g_moved);
    g_moved[13] = 0.5f;
    mesh_id_cases(1);
    for (k = 0; k < 2; ++k) {
        const nl_mesh_id mesh = k ? A.movable : A.mesh;
        const char* suffix = k ? " (movable)" : "";
        CASE("nl_mesh_set_transform", "transform NULL%s", suffix) {
            EXPECT_INVALID(A.world, nl_mesh_set_transform(A.world, mesh, NULL), "transform");
        }
        for (i = 0; i < BAD_TRANSFORM_COUNT; ++i) {
            CASE("nl_mesh_set_transform", "transform%s%s", k_bad_transforms[i].what, suffix) {
                float m[16];
                transform_from(&k_bad_transforms[i], m);
                EXPECT_INVALID(A.world, nl_mesh_set_transform(A.world, mesh, m), transform_needle(&k_bad_transforms[i]));
            }
        }
    }
}

static void group_mesh_is_valid(void) { mesh_id_cases(2); }

static nl_status mesh_info_into(void* out) { return nl_mesh_get_info(A.world, A.mesh, (nl_mesh_info*)out); }

static void group_mesh_get_info(void) {
    mesh_id_cases(3);
    out_sizes("nl_mesh_get_info", "out_info", sizeof(nl_mesh_info), mesh_info_into);
}

static void group_world_get_meshes(void) { world_list_cases("nl_world_get_meshes", "out_ids", sizeof(nl_mesh_id), 4u, get_meshes); }

/* Batches of three items, the last one made bad: nothing is written for any. `batch` calls the
   function with (items, count, out) for the case's items. */
typedef nl_status batch_fn(nl_world* world, const void* items, uint32_t count, void* out);
typedef struct batch_function {
    const char* function;
    const char* items_name; /* "rays" */
    const char* out_name;
    size_t item_size, out_size; /* per item */
    batch_fn* call;
} batch_function;

/* The pointers NULL, the counts 0 and huge (never read through a NULL pointer, nor past the first
   item when the output is NULL). */
static void batch_pointer_cases(const batch_function* f, const void* valid) {
    unsigned char out[256];
    CASE(f->function, "world NULL") {
        fill(out, sizeof out);
        EXPECT_INVALID(NULL, f->call(NULL, valid, 3, out), "world");
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "%s NULL", f->items_name) {
        fill(out, sizeof out);
        EXPECT_INVALID(A.world, f->call(A.world, NULL, 3, out), f->items_name);
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "count huge (%s NULL: not read)", f->items_name) {
        fill(out, sizeof out);
        EXPECT_INVALID(A.world, f->call(A.world, NULL, UINT32_MAX, out), f->items_name);
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "%s NULL", f->out_name) { EXPECT_INVALID(A.world, f->call(A.world, valid, 3, NULL), f->out_name); }
    CASE(f->function, "count huge (%s NULL: the items past the first not read)", f->out_name) {
        EXPECT_INVALID(A.world, f->call(A.world, valid, UINT32_MAX, NULL), f->out_name);
    }
    CASE(f->function, "count 0 (allowed, with %s and %s NULL)", f->items_name, f->out_name) {
        EXPECT_OK(f->call(A.world, NULL, 0, NULL));
    }
}

/* The batch of three items made bad: refused naming "ITEMS[2].FIELD", nothing written. */
static const batch_function* g_batch;
static void batch_refuses(const void* items, nl_status detail, const char* field) {
    unsigned char out[256];
    char needle[64];
    snprintf(needle, sizeof needle, "%s[2].%s", g_batch->items_name, field);
    fill(out, sizeof out);
    EXPECT_FAILURE(A.world, g_batch->call(A.world, items, 3, out), detail, needle);
    EXPECT_UNTOUCHED(out, sizeof out, g_batch->out_name);
}

/* One more bad value of a field of item 2. */
typedef struct extra_value {
    const char* what; /* "rays->max_distance 0" */
    const char* field;
    size_t offset;    /* in the item */
    float value;
} extra_value;

/* Each bad float of each field of item 2, and the extra values. */
static void batch_float_cases(const batch_function* f, const void* valid, const float_field* fields, size_t field_count,
                              const extra_value* extra, size_t extra_count) {
    float_field in_item_2[4];
    size_t i;
    g_batch = f;
    for (i = 0; i < field_count && i < 4; ++i) {
        in_item_2[i] = fields[i];
        in_item_2[i].offset += 2 * f->item_size;
    }
    bad_float_fields(f->function, f->items_name, valid, 3 * f->item_size, in_item_2, i, batch_refuses);
    for (i = 0; i < extra_count; ++i) {
        CASE(f->function, "%s", extra[i].what) {
            aligned_buffer items;
            copy_def(&items, valid, 3 * f->item_size);
            memcpy(items.bytes + 2 * f->item_size + extra[i].offset, &extra[i].value, sizeof(float));
            batch_refuses(items.bytes, NL_STATUS_INVALID_ARGUMENT, extra[i].field);
        }
    }
}

static nl_status cast_rays(nl_world* w, const void* items, uint32_t count, void* out) {
    return nl_world_cast_rays(w, (const nl_ray*)items, count, (nl_ray_hit*)out);
}
static nl_status segments_blocked(nl_world* w, const void* items, uint32_t count, void* out) {
    return nl_world_segments_blocked(w, (const nl_segment*)items, count, (uint8_t*)out);
}

static nl_status cast_known_rays(void* out, uint32_t* written) {
    const nl_ray rays[3] = {{{-6, 5, 0}, {0, -1, 0}, 100}, {{6, 5, 0}, {0, -1, 0}, 100}, {{42, 5, 0}, {0, -1, 0}, 100}};
    *written = 3u;
    return nl_world_cast_rays(A.world, rays, 3, (nl_ray_hit*)out);
}

static void group_world_cast_rays(void) {
    static const batch_function f = {"nl_world_cast_rays", "rays", "out_hits", sizeof(nl_ray), sizeof(nl_ray_hit), cast_rays};
    const nl_ray valid[3] = {{{-6, 5, 0}, {0, -1, 0}, 100}, {{6, 5, 0}, {0, -1, 0}, 100}, {{42, 5, 0}, {0, -1, 0}, 100}};
    static const float_field fields[] = {FLOAT_FIELD(nl_ray, origin, 3), FLOAT_FIELD(nl_ray, direction, 3)};
    static const extra_value extra[] = {
        {"rays->origin beyond the limit (2e9)", "origin", offsetof(nl_ray, origin[1]), 2.0e9f},
        {"rays->direction zero", "direction", offsetof(nl_ray, direction[1]), 0.0f},
        {"rays->max_distance NaN", "max_distance", offsetof(nl_ray, max_distance), NAN},
        {"rays->max_distance -inf", "max_distance", offsetof(nl_ray, max_distance), -INFINITY},
        {"rays->max_distance 0", "max_distance", offsetof(nl_ray, max_distance), 0.0f},
        {"rays->max_distance negative (-1)", "max_distance", offsetof(nl_ray, max_distance), -1.0f},
    };
    batch_pointer_cases(&f, valid);
    batch_float_cases(&f, valid, fields, 2, extra, sizeof extra / sizeof *extra);
    CASE("nl_world_cast_rays", "rays->max_distance inf (allowed)") {
        nl_ray rays[3];
        nl_ray_hit hits[3];
        hits[0] = nl_ray_hit_init();
        memcpy(rays, valid, sizeof rays);
        rays[2].max_distance = INFINITY;
        EXPECT_OK(nl_world_cast_rays(A.world, rays, 3, hits));
        EXPECT(hits[0].hit == 1 && hits[2].hit == 1, "the rays down onto the platform and the lift missed");
    }
    out_element_sizes("nl_world_cast_rays", "out_hits", sizeof(nl_ray_hit), cast_known_rays);
}

static void group_world_segments_blocked(void) {
    static const batch_function f = {"nl_world_segments_blocked", "segments", "out_blocked", sizeof(nl_segment), 1,
                                     segments_blocked};
    const nl_segment valid[3] = {{{-6, 5, 0}, {-6, -5, 0}}, {{-6, 5, 0}, {6, 5, 0}}, {{42, 5, 0}, {42, -5, 0}}};
    static const float_field fields[] = {FLOAT_FIELD(nl_segment, from, 3), FLOAT_FIELD(nl_segment, to, 3)};
    static const extra_value extra[] = {{"segments->to beyond the limit (-2e9)", "to", offsetof(nl_segment, to[1]), -2.0e9f}};
    batch_pointer_cases(&f, valid);
    batch_float_cases(&f, valid, fields, 2, extra, 1);
}

/* ---------------------------------------------------------------------------------------------
 * Navmeshes
 * ------------------------------------------------------------------------------------------- */

/* A navmesh added (or built) as documented is valid, and is removed. */
static void remove_navmesh_out(const void* out) {
    nl_navmesh_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_navmesh_is_valid(A.world, id) == 1, "the new navmesh is not valid");
    EXPECT_OK(nl_navmesh_remove(A.world, id));
}

static nl_status navmesh_add_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_add(world, (const nl_navmesh_def*)def, (nl_navmesh_id*)out);
}

/* The quad, and its parts made bad. */
static const float k_quad_nan[12] = {40, 0, -2, 40, NAN, 2, 44, 0, 2, 44, 0, -2};
static const float k_quad_inf[12] = {40, 0, -2, INFINITY, 0, 2, 44, 0, 2, 44, 0, -2};
static const float k_quad_minus_inf[12] = {40, 0, -2, 40, 0, -INFINITY, 44, 0, 2, 44, 0, -2};
static const float k_dart[12] = {40, 0, -2, 42, 0, -1, 44, 0, -2, 42, 0, 2}; /* concave at corner 1 */
static const float k_quad_detail_nan[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, NAN, 2, 44, 0.1f, -2};
static const float k_quad_detail_inf[12] = {40, 0.1f, -2, 40, 0.1f, 2, INFINITY, 0.1f, 2, 44, 0.1f, -2};
static const float k_quad_detail_minus_inf[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, 0.1f, -INFINITY, 44, 0.1f, -2};
static const uint32_t k_quad_index_4[4] = {0, 1, 2, 4};
static const uint8_t k_corners_2[1] = {2}, k_corners_17[1] = {17}, k_corners_0[1] = {0};
static const uint32_t k_detail_starts_short[2] = {0, 1};
static const uint32_t k_detail_triangles_9[6] = {0, 1, 2, 0, 2, 9};

#define NO_DETAIL                                                                                                \
    SET_PTR(nl_navmesh_def, detail_vertices, NULL), SET_U32(nl_navmesh_def, detail_vertex_count, 0u),          \
        SET_PTR(nl_navmesh_def, detail_triangles, NULL), SET_U32(nl_navmesh_def, detail_triangle_count, 0u),   \
        SET_PTR(nl_navmesh_def, detail_triangle_starts, NULL)
static const geometry_fields k_navmesh_geometry = {
    GEOMETRY_FIELDS(nl_navmesh_def), {k_quad_nan, k_quad_inf, k_quad_minus_inf}, "vertices[1]"};
static const def_case k_navmesh_defs[] = {
    {"def->indices out of range (4)", INVALID, "indices[3]", {SET_PTR(nl_navmesh_def, indices, k_quad_index_4)}},
    {"def->indices concave polygon", INVALID, "convex", {SET_PTR(nl_navmesh_def, vertices, k_dart), NO_DETAIL}},
    {"def->polygon_count 0", INVALID, "polygon_count", {SET_U32(nl_navmesh_def, polygon_count, 0u)}},
    {"def->polygon_count huge (indices NULL: no per-polygon array read)", INVALID, "indices",
     {SET_PTR(nl_navmesh_def, indices, NULL), SET_U32(nl_navmesh_def, polygon_count, UINT32_MAX)}},
    {"def->polygon_vertex_counts NULL (allowed: triangles)", ALLOWED, NULL,
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, NULL), NO_DETAIL}},
    {"def->polygon_vertex_counts 2", INVALID, "polygon_vertex_counts[0]", {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_2)}},
    {"def->polygon_vertex_counts 17", INVALID, "polygon_vertex_counts[0]",
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_17)}},
    {"def->polygon_vertex_counts 0", INVALID, "polygon_vertex_counts[0]", {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_0)}},
    {"def->areas NULL (allowed: area 0)", ALLOWED, NULL, {SET_PTR(nl_navmesh_def, areas, NULL)}},
    {"def->weld_tolerance negative", INVALID, "weld_tolerance", {SET_F32(nl_navmesh_def, weld_tolerance, -1.0f)}},
    {"def->weld_tolerance 2 (more than 1 m)", INVALID, "weld_tolerance", {SET_F32(nl_navmesh_def, weld_tolerance, 2.0f)}},
    {"def->agent.radius negative", INVALID, "radius", {SET_F32(nl_navmesh_def, agent.radius, -0.5f)}},
    {"def->detail_vertices NULL (allowed with no detail at all)", ALLOWED, NULL, {NO_DETAIL}},
    {"def->detail_vertices NULL (the rest of the detail given)", INVALID, "detail_vertices",
     {SET_PTR(nl_navmesh_def, detail_vertices, NULL)}},
    {"def->detail_vertices NaN (detail vertex 2)", INVALID, "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_nan)}},
    {"def->detail_vertices inf (detail vertex 2)", INVALID, "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_inf)}},
    {"def->detail_vertices -inf (detail vertex 2)", INVALID, "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_minus_inf)}},
    {"def->detail_vertex_count 0", INVALID, "detail_vertex_count", {SET_U32(nl_navmesh_def, detail_vertex_count, 0u)}},
    {"def->detail_vertex_count huge (detail_vertices NULL: not read)", INVALID, "detail_vertices",
     {SET_PTR(nl_navmesh_def, detail_vertices, NULL), SET_U32(nl_navmesh_def, detail_vertex_count, UINT32_MAX)}},
    {"def->detail_triangles NULL", INVALID, "detail_triangles", {SET_PTR(nl_navmesh_def, detail_triangles, NULL)}},
    {"def->detail_triangles out of range (9)", INVALID, "detail_triangles[5]",
     {SET_PTR(nl_navmesh_def, detail_triangles, k_detail_triangles_9)}},
    {"def->detail_triangle_count 0", INVALID, "detail_triangle_count", {SET_U32(nl_navmesh_def, detail_triangle_count, 0u)}},
    {"def->detail_triangle_count huge (detail_triangles NULL: not read)", INVALID, "detail_triangles",
     {SET_PTR(nl_navmesh_def, detail_triangles, NULL), SET_U32(nl_navmesh_def, detail_triangle_count, UINT32_MAX)}},
    {"def->detail_triangle_starts NULL", INVALID, "detail_triangle_starts",
     {SET_PTR(nl_navmesh_def, detail_triangle_starts, NULL)}},
    {"def->detail_triangle_starts not ending at the count", INVALID, "detail_triangle_starts",
     {SET_PTR(nl_navmesh_def, detail_triangle_starts, k_detail_starts_short)}},
};
#undef NO_DETAIL

static const float_field k_agent_type_floats[] = {
    FLOAT_FIELD(nl_agent_type, radius, 1), FLOAT_FIELD(nl_agent_type, height, 1),
    FLOAT_FIELD(nl_agent_type, max_climb, 1), FLOAT_FIELD(nl_agent_type, max_slope, 1)};

/* The agent type's floats at `offset` in a def, named "agent.FIELD". */
static void bad_agent_floats(const char* function, const void* valid, size_t size, size_t offset, refuse_fn* refuse) {
    float_field fields[4];
    char names[4][32];
    size_t i;
    for (i = 0; i < 4; ++i) {
        snprintf(names[i], sizeof names[i], "agent.%s", k_agent_type_floats[i].name);
        fields[i].name = names[i];
        fields[i].offset = offset + k_agent_type_floats[i].offset;
        fields[i].count = 1;
    }
    bad_float_fields(function, "def", valid, size, fields, 4, refuse);
}

/* A def's optional id at `offset`, named `field` ("def->surface"): the null id is allowed (the
   def's default), every other bad id is INVALID_HANDLE naming the field. */
static void optional_id_cases(const def_function* f, const void* valid, size_t size, size_t offset, const char* field,
                              raw_id live, raw_id stale, raw_id foreign) {
    aligned_buffer def;
    g_def = f;
    CASE(f->function, "%s null (allowed: none)", field) {
        memcpy(def.bytes, valid, size);
        memset(def.bytes + offset, 0, sizeof(raw_id));
        def_accepts(def.bytes);
    }
    FOR_BAD_IDS(bad, live, stale, foreign) {
        if (bad->id.index1 == 0u && bad->id.generation == 0u) continue; /* the null id: allowed above */
        CASE(f->function, "%s %s", field, bad->what) {
            memcpy(def.bytes, valid, size);
            memcpy(def.bytes + offset, &bad->id, sizeof bad->id);
            def_refuses(def.bytes, NL_STATUS_INVALID_HANDLE, field);
        }
    }
}

/* A def's `surface` mesh id (at `offset`): the movable lift is allowed too (the navmesh rides it;
   `riding` is a def that fits on the lift), a static mesh is INVALID_ARGUMENT. */
static void surface_cases(const def_function* f, const void* valid, const void* riding, size_t size, size_t offset) {
    aligned_buffer def;
    optional_id_cases(f, valid, size, offset, "def->surface", RAW(A.movable), RAW(A.stale_mesh), RAW(B.movable));
    CASE(f->function, "def->surface the movable lift (allowed: the navmesh rides it)") {
        memcpy(def.bytes, riding, size);
        memcpy(def.bytes + offset, &A.movable, sizeof A.movable);
        def_accepts(def.bytes);
    }
    CASE(f->function, "def->surface a static mesh") {
        memcpy(def.bytes, valid, size);
        memcpy(def.bytes + offset, &A.mesh, sizeof A.mesh);
        def_refuses(def.bytes, NL_STATUS_INVALID_ARGUMENT, "def->surface is not a movable mesh");
    }
}

static void group_navmesh_add(void) {
    static const def_function add = {"nl_navmesh_add", navmesh_add_call, sizeof(nl_navmesh_id), remove_navmesh_out, 0, 0, 0};
    static const float_field weld[] = {FLOAT_FIELD(nl_navmesh_def, weld_tolerance, 1)};
    const nl_navmesh_def valid = quad_navmesh_def();
    def_function_cases(&add, &valid, sizeof valid);
    geometry_cases("nl_navmesh_add", &valid, sizeof valid, &k_navmesh_geometry);
    def_cases("nl_navmesh_add", &valid, sizeof valid, k_navmesh_defs, sizeof k_navmesh_defs / sizeof *k_navmesh_defs,
              def_refuses, def_accepts);
    bad_float_fields("nl_navmesh_add", "def", &valid, sizeof valid, weld, 1, def_refuses);
    bad_agent_floats("nl_navmesh_add", &valid, sizeof valid, offsetof(nl_navmesh_def, agent), def_refuses);
    surface_cases(&add, &valid, &valid, sizeof valid, offsetof(nl_navmesh_def, surface));
}

/* The functions that take a navmesh id and no more than an output. */
ID_CALL(navmesh_remove_call, nl_navmesh_id, nl_navmesh_remove)
ID_VALID_CALL(navmesh_is_valid_call, nl_navmesh_id, nl_navmesh_is_valid)
static nl_status navmesh_get_polygon_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_get_polygon(w, AS(nl_navmesh_id, id), 0, (nl_nav_polygon*)out);
}
ID_OUT_CALL(remove_generated_call, nl_navmesh_id, uint32_t, nl_navmesh_remove_generated_links)
static const id_function k_navmesh_functions[] = {
    {"nl_navmesh_remove", "navmesh", NULL, 0, 0, 0, navmesh_remove_call, 0},
    {"nl_navmesh_is_valid", "navmesh", NULL, 0, 0, 1, navmesh_is_valid_call, 0},
    {"nl_navmesh_get_info", "navmesh", "out_info", sizeof(nl_navmesh_info), 1, 0, navmesh_get_info_call, 0},
    {"nl_navmesh_get_polygon", "navmesh", "out_polygon", sizeof(nl_nav_polygon), 0, 0, navmesh_get_polygon_call, 0},
    {"nl_navmesh_remove_generated_links", "navmesh", "out_removed", sizeof(uint32_t), 0, 0, remove_generated_call, 1},
};

static void navmesh_id_cases(size_t which) {
    id_cases(&k_navmesh_functions[which], RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
}

static void group_navmesh_remove(void) { navmesh_id_cases(0); }
static void group_navmesh_is_valid(void) { navmesh_id_cases(1); }

static nl_status navmesh_info_into(void* out) { return nl_navmesh_get_info(A.world, A.navmesh, (nl_navmesh_info*)out); }

static void group_navmesh_get_info(void) {
    navmesh_id_cases(2);
    out_sizes("nl_navmesh_get_info", "out_info", sizeof(nl_navmesh_info), navmesh_info_into);
}

static nl_navmesh_info navmesh_info(const world_fixture* f, nl_navmesh_id id) {
    nl_navmesh_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_get_info(f->world, id, &info))) fixture_failed("nl_navmesh_get_info");
    return info;
}

static nl_status polygon_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_navmesh_get_polygon(A.world, A.navmesh, 0, (nl_nav_polygon*)out);
}

static void group_navmesh_get_polygon(void) {
    const uint32_t polygons = navmesh_info(&A, A.navmesh).polygon_count;
    const uint32_t out_of_range[2] = {polygons, UINT32_MAX};
    int k;
    navmesh_id_cases(3);
    CASE("nl_navmesh_get_polygon", "polygon 0 (allowed: the first)") {
        nl_nav_polygon out = nl_nav_polygon_init();
        EXPECT_OK(nl_navmesh_get_polygon(A.world, A.navmesh, 0, &out));
        EXPECT(out.vertex_count >= 3 && out.vertex_count <= NL_MAX_POLYGON_VERTICES, "vertex_count %u", (unsigned)out.vertex_count);
    }
    for (k = 0; k < 2; ++k) {
        CASE("nl_navmesh_get_polygon", k == 0 ? "polygon out of range (polygon_count)" : "polygon huge") {
            nl_nav_polygon out = nl_nav_polygon_init();
            fill(&out, sizeof out);
            EXPECT_INVALID(A.world, nl_navmesh_get_polygon(A.world, A.navmesh, out_of_range[k], &out), "polygon");
            EXPECT_UNTOUCHED(&out, sizeof out, "out_polygon");
        }
    }
    out_element_sizes("nl_navmesh_get_polygon", "out_polygon", sizeof(nl_nav_polygon), polygon_into);
}

/* The list functions of a navmesh, with their id cases: `call` lists from A's navmesh. */
typedef nl_status navmesh_list_fn(const nl_world* world, nl_navmesh_id navmesh, void* out, uint32_t capacity,
                                  uint32_t* out_count);
static navmesh_list_fn* g_navmesh_list;
static nl_status call_navmesh_list(void* out, uint32_t capacity, uint32_t* count) {
    return g_navmesh_list(A.world, A.navmesh, out, capacity, count);
}
/* A 16-entry buffer: the id case checks it stays untouched, and the count too. */
static nl_status navmesh_list_id_call(nl_world* w, raw_id id, void* out) {
    uint32_t count;
    nl_status status;
    fill(&count, sizeof count);
    status = g_navmesh_list(w, AS(nl_navmesh_id, id), out, 16u, &count);
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}

static void navmesh_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                               navmesh_list_fn* call) {
    const id_function f = {function, "navmesh", out_name, 16 * item_size, 0, 0, navmesh_list_id_call, 1};
    g_navmesh_list = call;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    list_cases(function, out_name, item_size, expected, call_navmesh_list);
}

static nl_status list_vertices(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_vertices(w, n, (float*)out, capacity, count);
}
static nl_status list_edges(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_boundary_edges(w, n, (nl_boundary_edge*)out, capacity, count);
}
static nl_status list_links(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_links(w, n, (nl_link*)out, capacity, count);
}

static void group_navmesh_get_vertices(void) {
    navmesh_list_cases("nl_navmesh_get_vertices", "out_xyz", 3 * sizeof(float), navmesh_info(&A, A.navmesh).vertex_count,
                       list_vertices);
}

static void group_navmesh_get_boundary_edges(void) {
    navmesh_list_cases("nl_navmesh_get_boundary_edges", "out_edges", sizeof(nl_boundary_edge),
                       navmesh_info(&A, A.navmesh).boundary_edge_count, list_edges);
}

/* nl_navmesh_find_nearest on A's navmesh, with two points (the second one made bad) and a box. */
static const float k_points[6] = {-6, 1, 0, 6, 1, 0};
static const float k_extents[3] = {2, 4, 2};
static const float* g_nearest_points = k_points;
static const float* g_nearest_extents = k_extents;
static nl_status find_nearest_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_find_nearest(w, AS(nl_navmesh_id, id), g_nearest_points, 2, g_nearest_extents, (nl_nav_point*)out);
}

static void nearest_refused(const float* points, uint32_t count, const float* extents, const char* needle) {
    nl_nav_point out[2];
    fill(out, sizeof out);
    EXPECT_INVALID(A.world, nl_navmesh_find_nearest(A.world, A.navmesh, points, count, extents, out), needle);
    EXPECT_UNTOUCHED(out, sizeof out, "out");
}

static void group_navmesh_find_nearest(void) {
    static const id_function f = {"nl_navmesh_find_nearest", "navmesh", "out", 2 * sizeof(nl_nav_point), 0, 0, find_nearest_call, 0};
    size_t v;
    int k, which;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_find_nearest", "points NULL") { nearest_refused(NULL, 2, k_extents, "points"); }
    CASE("nl_navmesh_find_nearest", "count huge (points NULL: not read)") { nearest_refused(NULL, UINT32_MAX, k_extents, "points"); }
    CASE("nl_navmesh_find_nearest", "count huge (out NULL: points past the first not read)") {
        EXPECT_INVALID(A.world, nl_navmesh_find_nearest(A.world, A.navmesh, k_points, UINT32_MAX, k_extents, NULL), "out");
    }
    CASE("nl_navmesh_find_nearest", "count 0 (allowed, with points and out NULL)") {
        EXPECT_OK(nl_navmesh_find_nearest(A.world, A.navmesh, NULL, 0, k_extents, NULL));
    }
    CASE("nl_navmesh_find_nearest", "half_extents NULL") { nearest_refused(k_points, 2, NULL, "half_extents"); }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT + 2; ++v) {
                static const char* more[2] = {"0", "negative (-1)"};
                const float value = v < BAD_FLOAT_COUNT ? k_bad_floats[v].value : v == BAD_FLOAT_COUNT ? 0.0f : -1.0f;
                const char* what = v < BAD_FLOAT_COUNT ? k_bad_floats[v].name : more[v - BAD_FLOAT_COUNT];
                if (which == 0 && v >= BAD_FLOAT_COUNT) continue; /* 0 and -1 are fine coordinates */
                CASE("nl_navmesh_find_nearest", which == 0 ? "points[%d] %s (point 1)" : "half_extents[%d] %s",
                     which == 0 ? 3 + k : k, what) {
                    float p[6], e[3];
                    memcpy(p, k_points, sizeof p);
                    memcpy(e, k_extents, sizeof e);
                    if (which == 0) p[3 + k] = value;
                    else e[k] = value;
                    nearest_refused(p, 2, e, which == 0 ? "points[1]" : "half_extents");
                }
            }
        }
    }
    CASE("nl_navmesh_find_nearest", "points beyond the limit (point 1, 2e9)") {
        float p[6];
        memcpy(p, k_points, sizeof p);
        p[5] = 2.0e9f;
        nearest_refused(p, 2, k_extents, "points[1]");
    }
}

static void group_world_get_navmeshes(void) {
    world_list_cases("nl_world_get_navmeshes", "out_ids", sizeof(nl_navmesh_id), 2u, get_navmeshes);
}

/* ---------------------------------------------------------------------------------------------
 * Building navmeshes
 * ------------------------------------------------------------------------------------------- */

static nl_status build_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_build(world, (const nl_navmesh_build_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_build = {"nl_navmesh_build", build_call, sizeof(nl_navmesh_id), remove_navmesh_out, 0, 0, 0};

/* Recast's settings made bad, through def->settings. */
static void build_with_recast_refuses(const void* settings, nl_status detail, const char* needle) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    g_def = &k_build;
    def_refuses(&def, detail, needle);
}
static void build_with_recast_accepts(const void* settings) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    g_def = &k_build;
    def_accepts(&def);
}

#define JSON(text) SET_PTR(nl_navmesh_build_def, settings_json, text), SET_LENGTH(nl_navmesh_build_def, settings_json_length, sizeof text - 1)
static const def_case k_build_defs[] = {
    {"def->builder NULL (allowed: recast)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, builder, NULL)}},
    {"def->builder empty", NL_STATUS_NOT_FOUND, "''", {SET_PTR(nl_navmesh_build_def, builder, "")}},
    {"def->builder unknown", NL_STATUS_NOT_FOUND, "no-such-builder", {SET_PTR(nl_navmesh_build_def, builder, "no-such-builder")}},
    {"def->settings NULL (allowed: Recast's defaults)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, settings, NULL)}},
    {"def->settings_json NULL (allowed with length 0)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, settings_json, NULL)}},
    {"def->settings_json_length huge (settings_json NULL: not read)", INVALID, "settings_json",
     {SET_LENGTH(nl_navmesh_build_def, settings_json_length, SIZE_MAX)}},
    {"def->settings_json_length 0 (an empty string is not a JSON object)", NL_STATUS_PARSE_ERROR, "settings_json",
     {SET_PTR(nl_navmesh_build_def, settings_json, "{}")}},
    {"def->settings_json not an object", INVALID, "settings_json", {JSON("[1]")}},
    {"def->settings_json malformed", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": ")}},
    {"def->settings_json inf (1e400)", INVALID, "cell_size", {JSON("{\"cell_size\": 1e400}")}},
    {"def->settings_json -inf (-1e400)", INVALID, "edge_max_error", {JSON("{\"edge_max_error\": -1e400}")}},
    {"def->settings_json NaN (not JSON)", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": NaN}")}},
    {"def->progress NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, progress, NULL)}},
};
#undef JSON

static int32_t cancel_at_once(void* user, float fraction, const char* stage);
static int32_t note_user(void* user, float fraction, const char* stage);
static void* g_user_seen;

static const def_case k_recast_settings[] = {
    {"settings->vertices_per_polygon 0", INVALID, "vertices_per_polygon", {SET_U32(nl_recast_settings, vertices_per_polygon, 0u)}},
    {"settings->vertices_per_polygon 2", INVALID, "vertices_per_polygon", {SET_U32(nl_recast_settings, vertices_per_polygon, 2u)}},
    {"settings->vertices_per_polygon 7", INVALID, "vertices_per_polygon", {SET_U32(nl_recast_settings, vertices_per_polygon, 7u)}},
    {"settings->vertices_per_polygon huge", INVALID, "vertices_per_polygon",
     {SET_U32(nl_recast_settings, vertices_per_polygon, UINT32_MAX)}},
    {"settings->partition 3", INVALID, "partition", {SET_U32(nl_recast_settings, partition, 3u)}},
    {"settings->partition huge", INVALID, "partition", {SET_U32(nl_recast_settings, partition, UINT32_MAX)}},
};

static const float_field k_recast_floats[] = {
    FLOAT_FIELD(nl_recast_settings, cell_size, 1),          FLOAT_FIELD(nl_recast_settings, cell_height, 1),
    FLOAT_FIELD(nl_recast_settings, region_min_size, 1),    FLOAT_FIELD(nl_recast_settings, region_merge_size, 1),
    FLOAT_FIELD(nl_recast_settings, edge_max_length, 1),    FLOAT_FIELD(nl_recast_settings, edge_max_error, 1),
    FLOAT_FIELD(nl_recast_settings, detail_sample_distance, 1),
    FLOAT_FIELD(nl_recast_settings, detail_sample_max_error, 1)};

static void group_navmesh_build(void) {
    const nl_navmesh_build_def valid = nl_default_navmesh_build_def();
    const nl_recast_settings recast = nl_default_recast_settings();
    def_function_cases(&k_build, &valid, sizeof valid);
    def_cases("nl_navmesh_build", &valid, sizeof valid, k_build_defs, sizeof k_build_defs / sizeof *k_build_defs, def_refuses,
              def_accepts);
    bad_agent_floats("nl_navmesh_build", &valid, sizeof valid, offsetof(nl_navmesh_build_def, agent), def_refuses);
    {
        nl_navmesh_build_def small = valid; /* the 4 m lift, eroded by a 0.6 m body, is below Recast's smallest region */
        small.agent.radius = 0.2f;
        surface_cases(&k_build, &valid, &small, sizeof valid, offsetof(nl_navmesh_build_def, surface));
    }
    CASE("nl_navmesh_build", "def->progress cancels (returns 0 at once: CANCELLED, nothing added)") {
        nl_navmesh_build_def def = valid;
        int calls = 0;
        def.progress = cancel_at_once;
        def.progress_user = &calls;
        def_refuses(&def, NL_STATUS_CANCELLED, "cancelled");
        EXPECT(calls == 1, "the progress callback was called %d times, expected once (it cancelled)", calls);
    }
    CASE("nl_navmesh_build", "def->progress_user NULL (allowed: passed back as it is)") {
        nl_navmesh_build_def def = valid;
        int calls = 0;
        g_user_seen = &calls;
        def.progress = note_user;
        def.progress_user = NULL;
        def_accepts(&def);
        EXPECT(g_user_seen == NULL, "the progress callback received user %p, not NULL", g_user_seen);
    }
    def_sizes("nl_navmesh_build", "settings", &recast, sizeof recast, build_with_recast_refuses, build_with_recast_accepts);
    def_cases("nl_navmesh_build", &recast, sizeof recast, k_recast_settings, sizeof k_recast_settings / sizeof *k_recast_settings,
              build_with_recast_refuses, build_with_recast_accepts);
    bad_float_fields("nl_navmesh_build", "settings", &recast, sizeof recast, k_recast_floats,
                     sizeof k_recast_floats / sizeof *k_recast_floats, build_with_recast_refuses);
}

/* ---------------------------------------------------------------------------------------------
 * Links
 * ------------------------------------------------------------------------------------------- */

static const float_field k_link_def_floats[] = {
    FLOAT_FIELD(nl_link_def, start, 3),           FLOAT_FIELD(nl_link_def, end, 3),
    FLOAT_FIELD(nl_link_def, cost_modifier, 1),   FLOAT_FIELD(nl_link_def, requirements.gap, 1),
    FLOAT_FIELD(nl_link_def, requirements.rise, 1), FLOAT_FIELD(nl_link_def, requirements.drop, 1),
    FLOAT_FIELD(nl_link_def, requirements.clearance_width, 1), FLOAT_FIELD(nl_link_def, requirements.length, 1),
    FLOAT_FIELD(nl_link_def, tolerance, 1),
};

static const def_case k_link_defs[] = {
    {"def->start off the navmesh (10 m above)", INVALID, "def->start", {SET_F32(nl_link_def, start[1], 10.0f)}},
    {"def->end beyond the limit (2e9)", INVALID, "def->end", {SET_F32(nl_link_def, end[2], 2.0e9f)}},
    {"def->kind 0", INVALID, "kind", {SET_U32(nl_link_def, kind, 0u)}},
    {"def->kind 4", INVALID, "kind", {SET_U32(nl_link_def, kind, 4u)}},
    {"def->kind 255", INVALID, "kind", {SET_U32(nl_link_def, kind, 255u)}},
    {"def->cost_modifier negative", INVALID, "cost_modifier", {SET_F32(nl_link_def, cost_modifier, -1.0f)}},
    {"def->requirements.gap negative", INVALID, "gap", {SET_F32(nl_link_def, requirements.gap, -1.0f)}},
    {"def->requirements.length negative", INVALID, "length", {SET_F32(nl_link_def, requirements.length, -1.0f)}},
    {"def->requirements.clearance_width negative", INVALID, "clearance_width",
     {SET_F32(nl_link_def, requirements.clearance_width, -1.0f)}},
};

/* nl_link_add on A's navmesh, and nl_link_update of A's manual link (which has no output). */
static nl_status link_add_def_call(nl_world* world, const void* def, void* out) {
    return nl_link_add(world, A.navmesh, (const nl_link_def*)def, (nl_link_id*)out);
}
static nl_status link_update_def_call(nl_world* world, const void* def, void* out) {
    (void)out;
    return nl_link_update(world, A.link, (const nl_link_def*)def);
}
/* An added link is removed again; the manual link updated with the def it was made from is as it was. */
static void remove_link_out(const void* out) {
    nl_link_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_link_is_valid(A.world, id) == 1, "the new link is not valid");
    EXPECT_OK(nl_link_remove(A.world, id));
}
static void nothing_to_undo(const void* out) { (void)out; }
static const def_function k_link_add = {"nl_link_add", link_add_def_call, sizeof(nl_link_id), remove_link_out, 0, 0, 1};
static const def_function k_link_update = {"nl_link_update", link_update_def_call, 0, nothing_to_undo, 0, 0, 1};

/* The def's cases of nl_link_add and nl_link_update. */
static void link_def_cases(const def_function* f) {
    const nl_link_def valid = gap_link_def();
    def_function_cases(f, &valid, sizeof valid);
    def_cases(f->function, &valid, sizeof valid, k_link_defs, sizeof k_link_defs / sizeof *k_link_defs, def_refuses, def_accepts);
    bad_float_fields(f->function, "def", &valid, sizeof valid, k_link_def_floats,
                     sizeof k_link_def_floats / sizeof *k_link_def_floats, def_refuses);
    optional_id_cases(f, &valid, sizeof valid, offsetof(nl_link_def, landing_navmesh), "def->landing_navmesh",
                      RAW(A.host_navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(f->function, "def->landing_navmesh the link's own navmesh") {
        nl_link_def def = valid;
        def.landing_navmesh = A.navmesh;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->landing_navmesh is the link's own navmesh");
    }
    CASE(f->function, "def->landing_navmesh with bidirectional set") {
        nl_link_def def = valid;
        def.landing_navmesh = A.host_navmesh;
        def.bidirectional = 1;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->bidirectional");
    }
    CASE(f->function, "def->landing_navmesh with the end off it") {
        nl_link_def def = valid; /* the end lies on the link's own navmesh, 40 m from the lift's */
        def.landing_navmesh = A.host_navmesh;
        def.bidirectional = 0;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->end is not within");
    }
}

static const nl_link_def* g_link_def;
static nl_status link_add_call(nl_world* w, raw_id id, void* out) {
    return nl_link_add(w, AS(nl_navmesh_id, id), g_link_def, (nl_link_id*)out);
}
static nl_status link_update_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_link_update(w, AS(nl_link_id, id), g_link_def);
}
ID_CALL(link_remove_call, nl_link_id, nl_link_remove)
ID_VALID_CALL(link_is_valid_call, nl_link_id, nl_link_is_valid)
ID_OUT_CALL(link_get_call, nl_link_id, nl_link, nl_link_get)
static const id_function k_link_functions[] = {
    {"nl_link_add", "navmesh", "out_id", sizeof(nl_link_id), 0, 0, link_add_call, 0},
    {"nl_link_update", "link", NULL, 0, 0, 0, link_update_call, 0},
    {"nl_link_remove", "link", NULL, 0, 0, 0, link_remove_call, 0},
    {"nl_link_is_valid", "link", NULL, 0, 0, 1, link_is_valid_call, 0},
    {"nl_link_get", "link", "out_link", sizeof(nl_link), 0, 0, link_get_call, 0},
};

/* The link functions' id cases; nl_link_add's id is the navmesh's. The world NULL is id_cases'. */
static void link_id_cases(size_t which) {
    const nl_link_def def = gap_link_def();
    g_link_def = &def;
    if (which == 0) id_cases(&k_link_functions[0], RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    else id_cases(&k_link_functions[which], RAW(A.link), RAW(A.stale_link), RAW(B.link));
}

static void group_link_add(void) {
    link_id_cases(0);
    link_def_cases(&k_link_add);
}

static void group_link_update(void) {
    link_id_cases(1);
    link_def_cases(&k_link_update);
}

static void group_link_remove(void) { link_id_cases(2); }
static void group_link_is_valid(void) { link_id_cases(3); }
static nl_status link_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_link_get(A.world, A.link, (nl_link*)out);
}
static void group_link_get(void) {
    link_id_cases(4);
    out_element_sizes("nl_link_get", "out_link", sizeof(nl_link), link_into);
}

static uint32_t link_count(nl_navmesh_id navmesh) {
    uint32_t n = 0;
    if (NL_FAILED(nl_navmesh_get_links(A.world, navmesh, NULL, 0, &n))) fixture_failed("nl_navmesh_get_links");
    return n;
}

static nl_status links_into(void* out, uint32_t* written) {
    return nl_navmesh_get_links(A.world, A.navmesh, (nl_link*)out, 256u, written);
}
static void group_navmesh_get_links(void) {
    g_growable_items = 1;
    navmesh_list_cases("nl_navmesh_get_links", "out_links", sizeof(nl_link), link_count(A.navmesh), list_links);
    g_growable_items = 0;
    out_element_sizes("nl_navmesh_get_links", "out_links", sizeof(nl_link), links_into);
}

static void group_navmesh_remove_generated_links(void) {
    navmesh_id_cases(4);
    CASE("nl_navmesh_remove_generated_links", "out_removed NULL (allowed: the manual link stays)") {
        const uint32_t before = link_count(A.navmesh);
        EXPECT_OK(nl_navmesh_remove_generated_links(A.world, A.navmesh, NULL));
        EXPECT(link_count(A.navmesh) == 1u && before > 1u, "%u links before, %u after (the manual one should stay)",
               (unsigned)before, (unsigned)link_count(A.navmesh));
        EXPECT(nl_link_is_valid(A.world, A.link) == 1, "the manual link went too");
        fixture_refresh();
    }
}

/* Link settings: every float of the struct. */
static const float_field k_link_settings_floats[] = {
    FLOAT_FIELD(nl_link_settings, min_edge_length, 1),          FLOAT_FIELD(nl_link_settings, sample_spacing, 1),
    FLOAT_FIELD(nl_link_settings, falloff_distance, 1),         FLOAT_FIELD(nl_link_settings, max_jump_gap, 1),
    FLOAT_FIELD(nl_link_settings, min_link_distance, 1),        FLOAT_FIELD(nl_link_settings, short_link_distance, 1),
    FLOAT_FIELD(nl_link_settings, max_jump_up, 1),              FLOAT_FIELD(nl_link_settings, jump_arc_height, 1),
    FLOAT_FIELD(nl_link_settings, strict_forward_angle, 1),     FLOAT_FIELD(nl_link_settings, permissive_forward_angle, 1),
    FLOAT_FIELD(nl_link_settings, strict_incline_angle, 1),     FLOAT_FIELD(nl_link_settings, permissive_incline_angle, 1),
    FLOAT_FIELD(nl_link_settings, max_drop_distance, 1),        FLOAT_FIELD(nl_link_settings, drop_angles, 3),
    FLOAT_FIELD(nl_link_settings, drop_steepness, 1),           FLOAT_FIELD(nl_link_settings, merge_distance, 1),
    FLOAT_FIELD(nl_link_settings, clearance_margin, 1),         FLOAT_FIELD(nl_link_settings, walk_factor, 1),
    FLOAT_FIELD(nl_link_settings, walk_distance, 1),
};

/* nl_link_settings_from_json's settings made bad: refused with "{}", the struct unchanged (the
   bytes past it too). */
static void from_json_refuses(const void* settings, nl_status detail, const char* needle) {
    aligned_buffer now, before;
    copy_def(&now, settings, sizeof(nl_link_settings));
    memcpy(before.bytes, now.bytes, sizeof before.bytes);
    EXPECT_FAILURE(NULL, nl_link_settings_from_json("{}", 2, (nl_link_settings*)(void*)now.bytes), detail, needle);
    EXPECT(memcmp(now.bytes, before.bytes, sizeof now.bytes) == 0, "settings changed on failure");
}

/* A larger struct: read and written up to the library's size, nothing past it. */
static void from_json_accepts(const void* settings) {
    aligned_buffer now;
    uint32_t size;
    copy_def(&now, settings, sizeof(nl_link_settings) + 64);
    EXPECT_OK(nl_link_settings_from_json("{\"sample_spacing\": 2}", 21, (nl_link_settings*)(void*)now.bytes));
    memcpy(&size, now.bytes, sizeof size);
    EXPECT(size == sizeof(nl_link_settings) + 64u && ((nl_link_settings*)(void*)now.bytes)->sample_spacing == 2.0f,
           "size %u, sample_spacing %g", (unsigned)size, ((nl_link_settings*)(void*)now.bytes)->sample_spacing);
    EXPECT_UNTOUCHED(now.bytes + sizeof(nl_link_settings), 64, "the bytes past the library's struct");
}

/* (json, length) pairs refused: the settings stay as they were. */
static const text_case k_settings_json[] = {
    {"json NULL (length 2)", NULL, 2, NL_STATUS_INVALID_ARGUMENT, "json"},
    {"length huge (json NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "json"},
    {"length 0 (an empty string is not a JSON object)", "{}", 0, NL_STATUS_PARSE_ERROR, ""},
    {"json malformed", TEXT("{\"sample_spacing\": "), NL_STATUS_PARSE_ERROR, ""},
    {"json NaN (not JSON)", TEXT("{\"merge_distance\": NaN}"), NL_STATUS_PARSE_ERROR, ""},
    {"json not an object", TEXT("[1, 2]"), NL_STATUS_INVALID_ARGUMENT, ""},
    {"json unknown key", TEXT("{\"no_such_key\": 1}"), NL_STATUS_INVALID_ARGUMENT, "no_such_key"},
    {"json wrong type", TEXT("{\"sample_spacing\": \"far\"}"), NL_STATUS_INVALID_ARGUMENT, "sample_spacing"},
    {"json inf (1e400)", TEXT("{\"sample_spacing\": 1e400}"), NL_STATUS_INVALID_ARGUMENT, "sample_spacing"},
    {"json -inf (-1e400)", TEXT("{\"merge_distance\": -1e400}"), NL_STATUS_INVALID_ARGUMENT, "merge_distance"},
    {"json drop_angles 17 entries", TEXT("{\"drop_angles\": [0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}"), NL_STATUS_INVALID_ARGUMENT,
     "drop_angles"},
};

static const def_case k_settings_counts[] = {
    {"settings->drop_angle_count huge", INVALID, "drop_angle_count", {SET_U32(nl_link_settings, drop_angle_count, UINT32_MAX)}},
};

static void group_link_settings_from_json(void) {
    const nl_link_settings valid = nl_default_link_settings();
    size_t i;
    CASE("nl_link_settings_from_json", "settings NULL") {
        EXPECT_INVALID(NULL, nl_link_settings_from_json("{}", 2, NULL), "settings");
    }
    for (i = 0; i < sizeof k_settings_json / sizeof *k_settings_json; ++i) {
        const text_case* t = &k_settings_json[i];
        CASE("nl_link_settings_from_json", "%s", t->what) {
            nl_link_settings settings = valid;
            EXPECT_FAILURE(NULL, nl_link_settings_from_json(t->data, t->length, &settings), t->detail, t->needle);
            EXPECT(memcmp(&settings, &valid, sizeof settings) == 0, "settings changed on failure");
        }
    }
    def_sizes("nl_link_settings_from_json", "settings", &valid, sizeof valid, from_json_refuses, from_json_accepts);
    bad_float_fields("nl_link_settings_from_json", "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, from_json_refuses);
    def_cases("nl_link_settings_from_json", &valid, sizeof valid, k_settings_counts, 1, from_json_refuses, from_json_accepts);
}

/* nl_navmesh_generate_links and nl_navmesh_update_links_in_box on A's navmesh: refused before any
   work, the report untouched, the links as they were. */
static const float k_box_min[3] = {-3, -2, -6}, k_box_max[3] = {3, 2, 6};
static const float* g_box_min = k_box_min;
static const float* g_box_max = k_box_max;
static int g_update;
/* nl_navmesh_generate_cross_links between `navmesh` and A's lift navmesh (the same body's). */
static int g_cross;
static float g_tolerance = 0.25f;
static nl_status generate_call(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                               nl_progress_fn* progress, void* user, nl_link_generation_report* report) {
    if (g_cross)
        return nl_navmesh_generate_cross_links(world, navmesh, A.host_navmesh, g_tolerance, settings, progress, user, report);
    return g_update ? nl_navmesh_update_links_in_box(world, navmesh, g_box_min, g_box_max, progress, user, report)
                    : nl_navmesh_generate_links(world, navmesh, settings, progress, user, report);
}

static void generate_fails_with(nl_navmesh_id navmesh, const void* settings, nl_progress_fn* progress, void* user,
                                nl_status detail, const char* needle) {
    nl_link_generation_report report;
    fill(&report, sizeof report);
    report.size = sizeof report;
    EXPECT_FAILURE(A.world, generate_call(A.world, navmesh, (const nl_link_settings*)settings, progress, user, &report), detail,
                   needle);
    EXPECT_UNTOUCHED_AFTER_SIZE(&report, sizeof report, "out_report");
}

static void generate_refuses(const void* settings, nl_status detail, const char* needle) {
    generate_fails_with(A.navmesh, settings, NULL, NULL, detail, needle);
}

/* A generation as documented: the generated links get new ids, so the worlds' reference is taken again. */
static void generate_accepts(const void* settings) {
    EXPECT_OK(generate_call(A.world, A.navmesh, (const nl_link_settings*)settings, NULL, NULL, NULL));
    EXPECT(nl_link_is_valid(A.world, A.link) == 1, "the manual link went");
    fixture_refresh();
}

static nl_status generate_id_call(nl_world* w, raw_id id, void* out) {
    return generate_call(w, AS(nl_navmesh_id, id), NULL, NULL, NULL, (nl_link_generation_report*)out);
}

static nl_status generate_into(void* report) {
    const nl_status status = generate_call(A.world, A.navmesh, NULL, NULL, NULL, (nl_link_generation_report*)report);
    if (NL_SUCCEEDED(status)) fixture_refresh();
    return status;
}

static int32_t cancel_at_once(void* user, float fraction, const char* stage) {
    (void)fraction;
    (void)stage;
    ++*(int*)user;
    return 0;
}

static int32_t note_user(void* user, float fraction, const char* stage) {
    (void)fraction;
    (void)stage;
    g_user_seen = user;
    return 1;
}

/* What they share: the ids (the navmesh's parameter named `param`), the progress callback and its
   user, the report. */
static void generation_cases_of(const char* function, const char* param) {
    const id_function f = {function, param, "out_report", sizeof(nl_link_generation_report), 1, 0, generate_id_call, 1};
    int calls = 0;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "progress cancels (returns 0 at once)") {
        generate_fails_with(A.navmesh, NULL, cancel_at_once, &calls, NL_STATUS_CANCELLED, "");
        EXPECT(calls >= 1, "the progress callback was not called");
    }
    CASE(function, "progress NULL (allowed)") { generate_accepts(NULL); }
    CASE(function, "user NULL (allowed: passed back as it is)") {
        g_user_seen = &calls;
        EXPECT_OK(generate_call(A.world, A.navmesh, NULL, note_user, NULL, NULL));
        EXPECT(g_user_seen == NULL, "the progress callback received user %p, not NULL", g_user_seen);
        fixture_refresh();
    }
    CASE(function, "out_report NULL (allowed)") { generate_accepts(NULL); }
    out_sizes(function, "out_report", sizeof(nl_link_generation_report), generate_into);
}
static void generation_cases(const char* function) { generation_cases_of(function, "navmesh"); }

static const def_case k_generation_settings[] = {
    {"settings->drop_angle_count huge", INVALID, "drop_angle_count", {SET_U32(nl_link_settings, drop_angle_count, UINT32_MAX)}},
    {"settings->drop_angle_count 0 (allowed: no drop probes)", ALLOWED, NULL, {SET_U32(nl_link_settings, drop_angle_count, 0u)}},
    {"settings->min_group_size 0", INVALID, "min_group_size", {SET_U32(nl_link_settings, min_group_size, 0u)}},
    {"settings->max_group_size huge", INVALID, "max_group_size", {SET_U32(nl_link_settings, max_group_size, UINT32_MAX)}},
    {"settings->arc_segments 0", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, 0u)}},
    {"settings->arc_segments 1", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, 1u)}},
    {"settings->arc_segments huge", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, UINT32_MAX)}},
    {"settings->sample_spacing tiny (1e-6: far too many samples)", INVALID, "sample_spacing",
     {SET_F32(nl_link_settings, sample_spacing, 1.0e-6f)}},
    {"settings->plugin_settings_json NULL (allowed: none)", ALLOWED, NULL, {SET_PTR(nl_link_settings, plugin_settings_json, NULL)}},
    {"settings->plugin_settings_json not an object", INVALID, "plugin_settings_json",
     {SET_PTR(nl_link_settings, plugin_settings_json, "[1]"), SET_LENGTH(nl_link_settings, plugin_settings_json_length, 3)}},
    {"settings->plugin_settings_json malformed", NL_STATUS_PARSE_ERROR, "plugin_settings_json",
     {SET_PTR(nl_link_settings, plugin_settings_json, "{\"climb\": "), SET_LENGTH(nl_link_settings, plugin_settings_json_length, 10)}},
    {"settings->plugin_settings_json_length 0 (allowed: none)", ALLOWED, NULL,
     {SET_PTR(nl_link_settings, plugin_settings_json, "{}"), SET_LENGTH(nl_link_settings, plugin_settings_json_length, 0)}},
    {"settings->plugin_settings_json_length huge (plugin_settings_json NULL: not read)", INVALID, "plugin_settings_json",
     {SET_LENGTH(nl_link_settings, plugin_settings_json_length, SIZE_MAX)}},
};

static void group_navmesh_generate_links(void) {
    const nl_link_settings valid = nl_default_link_settings();
    g_update = 0;
    generation_cases("nl_navmesh_generate_links");
    CASE("nl_navmesh_generate_links", "settings NULL (allowed: defaults)") { generate_accepts(NULL); }
    def_sizes("nl_navmesh_generate_links", "settings", &valid, sizeof valid, generate_refuses, generate_accepts);
    def_cases("nl_navmesh_generate_links", &valid, sizeof valid, k_generation_settings,
              sizeof k_generation_settings / sizeof *k_generation_settings, generate_refuses, generate_accepts);
    bad_float_fields("nl_navmesh_generate_links", "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, generate_refuses);
}

/* nl_navmesh_generate_cross_links with A's navmesh first and `id` second. */
static nl_status cross_second_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_generate_cross_links(w, A.navmesh, AS(nl_navmesh_id, id), g_tolerance, NULL, NULL, NULL,
                                           (nl_link_generation_report*)out);
}

static void group_navmesh_generate_cross_links(void) {
    static const char* const function = "nl_navmesh_generate_cross_links";
    const id_function second = {function, "second", "out_report", sizeof(nl_link_generation_report), 1, 0, cross_second_call, 1};
    const nl_link_settings valid = nl_default_link_settings();
    size_t v;
    g_update = 0;
    g_cross = 1;
    generation_cases_of(function, "first");
    id_cases(&second, RAW(A.host_navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "settings NULL (allowed: defaults)") { generate_accepts(NULL); }
    def_sizes(function, "settings", &valid, sizeof valid, generate_refuses, generate_accepts);
    def_cases(function, &valid, sizeof valid, k_generation_settings, sizeof k_generation_settings / sizeof *k_generation_settings,
              generate_refuses, generate_accepts);
    bad_float_fields(function, "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, generate_refuses);
    for (v = 0; v < sizeof k_bad_floats / sizeof *k_bad_floats; ++v) {
        CASE(function, "tolerance %s", k_bad_floats[v].name) {
            g_tolerance = k_bad_floats[v].value;
            generate_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "tolerance");
            g_tolerance = 0.25f;
        }
    }
    CASE(function, "tolerance negative") {
        g_tolerance = -1.0f;
        generate_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "tolerance");
        g_tolerance = 0.25f;
    }
    CASE(function, "second the same as first") {
        nl_link_generation_report report;
        fill(&report, sizeof report);
        report.size = sizeof report;
        EXPECT_FAILURE(A.world, nl_navmesh_generate_cross_links(A.world, A.navmesh, A.navmesh, 0.25f, NULL, NULL, NULL, &report),
                       NL_STATUS_INVALID_ARGUMENT, "one");
        EXPECT_UNTOUCHED_AFTER_SIZE(&report, sizeof report, "out_report");
    }
    g_cross = 0;
}

static void group_navmesh_update_links_in_box(void) {
    size_t v;
    int k, end;
    g_update = 1;
    generation_cases("nl_navmesh_update_links_in_box");
    CASE("nl_navmesh_update_links_in_box", "navmesh never generated") {
        generate_fails_with(A.host_navmesh, NULL, NULL, NULL, NL_STATUS_NOT_FOUND, "generat");
    }
    for (end = 0; end < 2; ++end) {
        CASE("nl_navmesh_update_links_in_box", "%s NULL", end ? "box_max" : "box_min") {
            g_box_min = end ? k_box_min : NULL;
            g_box_max = end ? NULL : k_box_max;
            generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, end ? "box_max" : "box_min");
        }
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE("nl_navmesh_update_links_in_box", "%s[%d] %s", end ? "box_max" : "box_min", k, k_bad_floats[v].name) {
                    float lo[3], hi[3];
                    memcpy(lo, k_box_min, sizeof lo);
                    memcpy(hi, k_box_max, sizeof hi);
                    (end ? hi : lo)[k] = k_bad_floats[v].value;
                    g_box_min = lo;
                    g_box_max = hi;
                    generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "box");
                }
            }
        }
    }
    CASE("nl_navmesh_update_links_in_box", "box_min inverted (above box_max)") {
        g_box_min = k_box_max;
        g_box_max = k_box_min;
        generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "box");
    }
    g_box_min = k_box_min;
    g_box_max = k_box_max;
}

/* The JSON of A's navmesh's links, malloc'ed. */
static char* saved_links(size_t* length) {
    char* json;
    if (NL_FAILED(nl_navmesh_save_links_json(A.world, A.navmesh, NULL, 0, length))) fixture_failed("save_links_json");
    json = (char*)malloc(*length + 1);
    if (!json || NL_FAILED(nl_navmesh_save_links_json(A.world, A.navmesh, json, *length + 1, length)))
        fixture_failed("save_links_json");
    return json;
}

/* A navmesh's savers (nl_navmesh_save_links_json, nl_navmesh_save): they write into a caller's
   buffer with the two-call pattern and a size_t length (the list cases of uint32_t counts do not
   apply). `g_saver` is the one the cases run now, into a buffer of what it writes + 64. */
typedef nl_status navmesh_saver(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity, size_t* out_length);
static navmesh_saver* g_saver;
static unsigned char* g_save_buffer;
static size_t g_save_room;
static nl_status saver_id_call(nl_world* w, raw_id id, void* out) {
    size_t length;
    nl_status status;
    fill(&length, sizeof length);
    fill(g_save_buffer, g_save_room);
    status = g_saver(w, AS(nl_navmesh_id, id), out ? g_save_buffer : NULL, out ? g_save_room : 0, &length);
    EXPECT_UNTOUCHED(&length, sizeof length, "the length");
    EXPECT_UNTOUCHED(g_save_buffer, g_save_room, "buffer");
    return status;
}
static nl_status save_links_json_saver(const nl_world* w, nl_navmesh_id n, void* buffer, size_t capacity, size_t* out_length) {
    return nl_navmesh_save_links_json(w, n, (char*)buffer, capacity, out_length);
}

/* Every case of a saver: its ids, its output, its buffer. `expected` is what it writes (`needed`
   bytes, then `terminator` more: the NUL of a text). */
static void saver_cases(const char* function, const char* out_name, navmesh_saver* saver, const unsigned char* expected,
                        size_t needed, size_t terminator) {
    const id_function f = {function, "navmesh", "buffer", 16, 0, 0, saver_id_call, 1};
    const size_t room = needed + terminator + 64;
    unsigned char* buffer = (unsigned char*)malloc(room);
    size_t length;
    if (!buffer) exit(2);
    g_saver = saver;
    g_save_buffer = buffer;
    g_save_room = room;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "%s NULL", out_name) {
        fill(buffer, room);
        EXPECT_INVALID(A.world, saver(A.world, A.navmesh, buffer, room, NULL), out_name);
        EXPECT_UNTOUCHED(buffer, room, "buffer");
    }
    CASE(function, "buffer NULL (allowed with capacity 0: measures)") {
        fill(&length, sizeof length);
        EXPECT_OK(saver(A.world, A.navmesh, NULL, 0, &length));
        EXPECT(length == needed, "%s = %u, expected %u", out_name, (unsigned)length, (unsigned)needed);
    }
    CASE(function, "capacity huge (buffer NULL)") {
        fill(&length, sizeof length);
        EXPECT_INVALID(A.world, saver(A.world, A.navmesh, NULL, SIZE_MAX, &length), "buffer");
        EXPECT_UNTOUCHED(&length, sizeof length, out_name);
    }
    {
        const size_t too_small[2] = {0, needed + terminator - 1};
        const char* what[2] = {"capacity 0 (a buffer given)", terminator ? "capacity small (the length: no room for the NUL)"
                                                                          : "capacity small (one byte short)"};
        int k;
        for (k = 0; k < 2; ++k) {
            CASE(function, "%s", what[k]) {
                fill(buffer, room);
                fill(&length, sizeof length);
                EXPECT_FAILURE(A.world, saver(A.world, A.navmesh, buffer, too_small[k], &length), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
                EXPECT_UNTOUCHED(buffer, room, "buffer");
                EXPECT(length == needed, "%s = %u, expected the %u needed", out_name, (unsigned)length, (unsigned)needed);
            }
        }
    }
    CASE(function, "capacity huge (64 bytes to spare: nothing written past the end)") {
        fill(buffer, room);
        EXPECT_OK(saver(A.world, A.navmesh, buffer, room, &length));
        EXPECT(length == needed, "%s = %u, expected %u", out_name, (unsigned)length, (unsigned)needed);
        EXPECT(memcmp(buffer, expected, needed + terminator) == 0, "other bytes written");
        EXPECT_UNTOUCHED(buffer + needed + terminator, 64, "the bytes past the end");
    }
    free(buffer);
}

static void group_navmesh_save_links_json(void) {
    size_t needed = 0;
    char* json = saved_links(&needed);
    saver_cases("nl_navmesh_save_links_json", "out_length", save_links_json_saver, (const unsigned char*)json, needed, 1);
    free(json);
}

/* A saved file with the elements of the first array `key` holds (links[0]'s) replaced by `elements`. */
static char* edited_links(const char* json, const char* key, const char* elements) {
    char pattern[64];
    const char *open, *close;
    char* out;
    snprintf(pattern, sizeof pattern, "\"%s\": [", key);
    open = strstr(json, pattern);
    close = open ? strchr(open, ']') : NULL;
    if (!close) fixture_failed("the saved links lack the array to edit");
    open += strlen(pattern);
    out = (char*)malloc(strlen(json) + strlen(elements) + 1);
    if (!out) exit(2);
    memcpy(out, json, (size_t)(open - json));
    strcpy(out + (open - json), elements);
    strcat(out, close);
    return out;
}

static const char* g_load_json;
static size_t g_load_length;
static nl_status load_id_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_load_links_json(w, AS(nl_navmesh_id, id), g_load_json, g_load_length, 0, (uint32_t*)out);
}

static void load_fails_with(const char* json, size_t length, nl_status detail, const char* needle) {
    uint32_t count;
    fill(&count, sizeof count);
    EXPECT_FAILURE(A.world, nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, &count), detail, needle);
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
}

static void group_navmesh_load_links_json(void) {
    static const id_function f = {"nl_navmesh_load_links_json", "navmesh", "out_count", sizeof(uint32_t), 0, 0, load_id_call, 1};
    static const char* values[][2] = {{"1e400", "inf"}, {"-1e400", "-inf"}, {"null", "null"}, {"\"x\"", "a string"}};
    size_t length, i;
    char* json = saved_links(&length);
    const text_case texts[] = {
        {"json NULL (length 10)", NULL, 10, NL_STATUS_INVALID_ARGUMENT, "json"},
        {"length huge (json NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "json"},
        {"length 0 (not JSON)", json, 0, NL_STATUS_PARSE_ERROR, ""},
        {"length short (cut in the middle)", json, length / 2, NL_STATUS_PARSE_ERROR, ""},
    };
    g_load_json = json;
    g_load_length = length;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    for (i = 0; i < sizeof texts / sizeof *texts; ++i) {
        CASE("nl_navmesh_load_links_json", "%s", texts[i].what) { load_fails_with(texts[i].data, texts[i].length, texts[i].detail, texts[i].needle); }
    }
    CASE("nl_navmesh_load_links_json", "json another format") {
        char* other = (char*)malloc(length + 1);
        const char* at = strstr(json, "navlink-links");
        if (!at || !other) fixture_failed("the saved links have no format");
        memcpy(other, json, length + 1);
        memcpy(other + (at - json), "navlink-other", 13);
        load_fails_with(other, length, NL_STATUS_VERSION_MISMATCH, "");
        free(other);
    }
    for (i = 0; i < sizeof values / sizeof *values; ++i) {
        CASE("nl_navmesh_load_links_json", "json links[0].start %s", values[i][1]) {
            char elements[64], *bad;
            snprintf(elements, sizeof elements, "%s, 0, 3", values[i][0]);
            bad = edited_links(json, "start", elements);
            load_fails_with(bad, strlen(bad), NL_STATUS_INVALID_ARGUMENT, "links[0].start");
            free(bad);
        }
    }
    CASE("nl_navmesh_load_links_json", "json links[0].end off the navmesh (20 m up)") {
        char* bad = edited_links(json, "end", "-6, 20, 0");
        load_fails_with(bad, strlen(bad), NL_STATUS_INVALID_ARGUMENT, "links[0].end");
        free(bad);
    }
    CASE("nl_navmesh_load_links_json", "json not NUL-terminated (allowed: exactly length bytes read)") {
        char* exact = (char*)malloc(length);
        uint32_t count = 0;
        if (!exact) exit(2);
        memcpy(exact, json, length);
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, exact, length, 0, &count));
        EXPECT(count == link_count(A.navmesh), "out_count = %u", (unsigned)count);
        free(exact);
        fixture_refresh(); /* new ids */
    }
    CASE("nl_navmesh_load_links_json", "flags 0 (allowed: the file's body is the navmesh's)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, &count));
        fixture_refresh();
    }
    CASE("nl_navmesh_load_links_json", "flags NL_LINKS_LOAD_ANY_BODY (allowed)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, NL_LINKS_LOAD_ANY_BODY, &count));
        fixture_refresh();
    }
    CASE("nl_navmesh_load_links_json", "flags huge (unknown bits)") {
        uint32_t count;
        fill(&count, sizeof count);
        EXPECT_FAILURE(A.world, nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0xffffffffu, &count),
                       NL_STATUS_INVALID_ARGUMENT, "flags");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_navmesh_load_links_json", "json made for another body (radius 0.25)") {
        const char* at = strstr(json, "\"radius\"");
        char* other = (char*)malloc(length + 16);
        if (!at || !other) fixture_failed("the saved links do not say their body");
        snprintf(other, length + 16, "%.*s\"radius\": 0.25, \"was\": %s", (int)(at - json), json, at + 9);
        load_fails_with(other, strlen(other), NL_STATUS_INVALID_ARGUMENT, "radius 0.25");
        free(other);
    }
    CASE("nl_navmesh_load_links_json", "out_count NULL (allowed)") {
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, NULL));
        fixture_refresh();
    }
    free(json);
}

/* ---------------------------------------------------------------------------------------------
 * Baked navmesh files
 * ------------------------------------------------------------------------------------------- */

/* A's navmesh as a file, malloc'ed. */
static unsigned char* saved_navmesh(size_t* size) {
    unsigned char* file;
    if (NL_FAILED(nl_navmesh_save(A.world, A.navmesh, NULL, 0, size))) fixture_failed("nl_navmesh_save");
    file = (unsigned char*)malloc(*size);
    if (!file || NL_FAILED(nl_navmesh_save(A.world, A.navmesh, file, *size, size))) fixture_failed("nl_navmesh_save");
    return file;
}

static void group_navmesh_save(void) {
    size_t needed = 0;
    unsigned char* file = saved_navmesh(&needed);
    saver_cases("nl_navmesh_save", "out_size", nl_navmesh_save, file, needed, 0);
    free(file);
}

static char g_save_path[256];
static nl_status save_file_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_save_file(w, AS(nl_navmesh_id, id), g_save_path);
}

static void group_navmesh_save_file(void) {
    static const id_function f = {"nl_navmesh_save_file", "navmesh", NULL, 0, 0, 0, save_file_id_call, 0};
    static const char* made[] = {"saved.nlnav"};
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_save_file", "path NULL") { EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, NULL), "path"); }
    CASE("nl_navmesh_save_file", "path empty") { EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, ""), "path"); }
    CASE("nl_navmesh_save_file", "path in a missing folder") {
        char path[300];
        snprintf(path, sizeof path, "%s/no-such-folder/x.nlnav", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "no-such-folder");
    }
    CASE("nl_navmesh_save_file", "path a directory") {
        char path[300];
        snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "dir.obj");
    }
    CASE("nl_navmesh_save_file", "path writable (allowed: the file is the buffer's)") {
        size_t size = 0;
        unsigned char* file = saved_navmesh(&size);
        FILE* f2;
        unsigned char* read = (unsigned char*)malloc(size + 1);
        size_t got = 0;
        EXPECT_OK(nl_navmesh_save_file(A.world, A.navmesh, g_save_path));
        f2 = fopen(g_save_path, "rb");
        if (f2 && read) {
            got = fread(read, 1, size + 1, f2);
            fclose(f2);
        }
        EXPECT(got == size && memcmp(read, file, size) == 0, "the file holds %u bytes, not the %u saved", (unsigned)got, (unsigned)size);
        free(read);
        free(file);
    }
    remove_tmp(made, 1);
}

/* Loads of A's navmesh's file into A's world (the new navmesh removed again by the undo). */
static unsigned char* g_navmesh_file;
static size_t g_navmesh_file_size;
static nl_status load_navmesh_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load(world, g_navmesh_file, g_navmesh_file_size, (const nl_navmesh_load_def*)def, (nl_navmesh_id*)out);
}
static nl_status load_navmesh_file_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load_file(world, g_save_path, (const nl_navmesh_load_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_navmesh_load = {"nl_navmesh_load", load_navmesh_call, sizeof(nl_navmesh_id), remove_navmesh_out, 1, 0, 0};
static const def_function k_navmesh_load_file = {"nl_navmesh_load_file", load_navmesh_file_call, sizeof(nl_navmesh_id),
                                                 remove_navmesh_out, 1, 0, 0};

static const def_case k_load_defs[] = {
    {"def->flags unknown bits", INVALID, "flags", {SET_U32(nl_navmesh_load_def, flags, 0x80u)}},
    {"def->flags NL_NAVMESH_LOAD_SAME_LEVEL (allowed: the level is the one it was built from)", ALLOWED, NULL,
     {SET_U32(nl_navmesh_load_def, flags, NL_NAVMESH_LOAD_SAME_LEVEL)}},
};

static void load_def_cases(const def_function* f) {
    const nl_navmesh_load_def valid = nl_default_navmesh_load_def();
    def_function_cases(f, &valid, sizeof valid);
    def_cases(f->function, &valid, sizeof valid, k_load_defs, sizeof k_load_defs / sizeof *k_load_defs, def_refuses, def_accepts);
    optional_id_cases(f, &valid, sizeof valid, offsetof(nl_navmesh_load_def, surface), "def->surface", RAW(A.movable),
                      RAW(A.stale_mesh), RAW(B.movable));
}

static void load_data_fails_with(const void* data, size_t size, nl_status detail, const char* needle) {
    nl_navmesh_id out;
    fill(&out, sizeof out);
    EXPECT_FAILURE(A.world, nl_navmesh_load(A.world, data, size, NULL, &out), detail, needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
}

static void group_navmesh_load(void) {
    size_t i;
    unsigned char* bad;
    g_navmesh_file = saved_navmesh(&g_navmesh_file_size);
    load_def_cases(&k_navmesh_load);
    CASE("nl_navmesh_load", "data NULL (size 10)") { load_data_fails_with(NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data"); }
    CASE("nl_navmesh_load", "size huge (data NULL: not read)") { load_data_fails_with(NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data"); }
    CASE("nl_navmesh_load", "size 0 (not a navmesh file)") { load_data_fails_with(g_navmesh_file, 0, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file"); }
    CASE("nl_navmesh_load", "size short (cut in the middle)") {
        load_data_fails_with(g_navmesh_file, g_navmesh_file_size / 2, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_load", "size long (a byte past the file)") {
        bad = (unsigned char*)malloc(g_navmesh_file_size + 1);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[g_navmesh_file_size] = 0;
        load_data_fails_with(bad, g_navmesh_file_size + 1, NL_STATUS_PARSE_ERROR, "extra bytes");
        free(bad);
    }
    CASE("nl_navmesh_load", "data a links JSON file") { load_data_fails_with("{\"format\": \"navlink-links\"}", 27, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file"); }
    CASE("nl_navmesh_load", "data of a newer format version") {
        bad = (unsigned char*)malloc(g_navmesh_file_size);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[8] = 9;
        load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_VERSION_MISMATCH, "newer");
        free(bad);
    }
    for (i = 40; i < g_navmesh_file_size; i += g_navmesh_file_size / 7) {
        CASE("nl_navmesh_load", "data with byte %u changed (corrupted)", (unsigned)i) {
            bad = (unsigned char*)malloc(g_navmesh_file_size);
            if (!bad) exit(2);
            memcpy(bad, g_navmesh_file, g_navmesh_file_size);
            bad[i] ^= 0x5a;
            load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
    }
    free(g_navmesh_file);
}

static nl_status load_navmesh_at(const char* path, void* out) { return nl_navmesh_load_file(A.world, path, NULL, (nl_navmesh_id*)out); }

static void group_navmesh_load_file(void) {
    static const char* made[] = {"saved.nlnav", "bad.nlnav"};
    char path[300];
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    if (NL_FAILED(nl_navmesh_save_file(A.world, A.navmesh, g_save_path))) fixture_failed("nl_navmesh_save_file");
    load_def_cases(&k_navmesh_load_file);
    bad_path_cases("nl_navmesh_load_file", load_navmesh_at, sizeof(nl_navmesh_id), k_bad_paths, BAD_PATH_COUNT);
    CASE("nl_navmesh_load_file", "path an OBJ file (named in the message)") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, g_obj_path, NULL, &out), NL_STATUS_VERSION_MISMATCH, "quad.obj");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    snprintf(path, sizeof path, "%s/bad.nlnav", g_tmp);
    write_file(path, "NLNAV");
    CASE("nl_navmesh_load_file", "path a 5-byte file") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, path, NULL, &out), NL_STATUS_VERSION_MISMATCH, "bad.nlnav");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    remove_tmp(made, 2);
}

static void describe_fails_with(const void* data, size_t size, nl_navmesh_file_info* info, char* json, size_t capacity,
                                size_t* length, nl_status detail, const char* needle) {
    EXPECT_FAILURE(NULL, nl_navmesh_file_describe(data, size, info, json, capacity, length), detail, needle);
}

static void group_navmesh_file_describe(void) {
    size_t size = 0, length, needed = 0;
    unsigned char* file = saved_navmesh(&size);
    nl_navmesh_file_info info;
    char json[4096];
    if (NL_FAILED(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &needed)) || needed + 1 > sizeof json)
        fixture_failed("nl_navmesh_file_describe");
    CASE("nl_navmesh_file_describe", "data NULL (size 10)") {
        describe_fails_with(NULL, 10, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size huge (data NULL: not read)") {
        describe_fails_with(NULL, SIZE_MAX, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size 0 (not a navmesh file)") {
        describe_fails_with(file, 0, NULL, NULL, 0, &length, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_file_describe", "size short (truncated)") {
        describe_fails_with(file, size - 1, NULL, NULL, 0, &length, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_file_describe", "out_info NULL (allowed: the JSON only)") {
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, json, sizeof json, &length));
        EXPECT(length == needed && strstr(json, "\"builder\"") != NULL, "the JSON: %s", json);
    }
    {
        static const char* what[3] = {"0", "small (4)", "large (sizeof + 64: nothing written past the struct)"};
        int k;
        for (k = 0; k < 3; ++k) {
            CASE("nl_navmesh_file_describe", "out_info->size %s", what[k]) {
                unsigned char buffer[sizeof(nl_navmesh_file_info) + 64];
                const uint32_t sizes[3] = {0u, 4u, (uint32_t)sizeof buffer};
                fill(buffer, sizeof buffer);
                memcpy(buffer, &sizes[k], sizeof sizes[k]);
                if (k < 2) {
                    describe_fails_with(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL, NL_STATUS_INVALID_ARGUMENT, "size");
                    EXPECT_UNTOUCHED(buffer + 4, sizeof buffer - 4, "out_info");
                } else {
                    nl_navmesh_file_info got;
                    EXPECT_OK(nl_navmesh_file_describe(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL));
                    memcpy(&got, buffer, sizeof got);
                    EXPECT(got.version == 1 && got.file_size == size && got.polygon_count > 0, "the info read back");
                    EXPECT_UNTOUCHED(buffer + sizeof got, 64, "the bytes past out_info");
                }
            }
        }
    }
    CASE("nl_navmesh_file_describe", "made_for_json NULL (allowed with capacity 0: measures)") {
        fill(&length, sizeof length);
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &length));
        EXPECT(length == needed, "out_length = %u", (unsigned)length);
    }
    CASE("nl_navmesh_file_describe", "capacity 0 (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, 0, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity small (the length: no room for the NUL)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, needed, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity huge (buffer NULL)") {
        describe_fails_with(file, size, NULL, NULL, SIZE_MAX, &length, NL_STATUS_INVALID_ARGUMENT, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_length NULL (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, sizeof json, NULL, NL_STATUS_INVALID_ARGUMENT, "out_length");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_info with out_length NULL (allowed: the info only)") {
        memset(&info, 0, sizeof info);
        info.size = sizeof info;
        EXPECT_OK(nl_navmesh_file_describe(file, size, &info, NULL, 0, NULL));
        EXPECT(info.quantum == 1.0f / 1024.0f && info.link_count > 0, "quantum %g, %u links", (double)info.quantum,
               (unsigned)info.link_count);
    }
    free(file);
}

/* ---------------------------------------------------------------------------------------------
 * Paths
 * ------------------------------------------------------------------------------------------- */

static const float_field k_request_floats[] = {
    FLOAT_FIELD(nl_path_request_def, start, 3),
    FLOAT_FIELD(nl_path_request_def, goal, 3),
    FLOAT_FIELD(nl_path_request_def, search_half_extents, 3),
    FLOAT_FIELD(nl_path_request_def, agent.max_jump_distance, 1),
    FLOAT_FIELD(nl_path_request_def, agent.max_jump_height, 1),
    FLOAT_FIELD(nl_path_request_def, agent.max_drop_height, 1),
    FLOAT_FIELD(nl_path_request_def, agent.radius, 1),
    FLOAT_FIELD(nl_path_request_def, link_cost, 1),
};

static const float k_costs_nan[3] = {1, NAN, 1}, k_costs_inf[3] = {1, INFINITY, 1}, k_costs_minus_inf[3] = {1, -INFINITY, 1};
static const float k_costs_negative[3] = {1, 1, -1};
static float k_costs_257[257];
static const def_case k_request_defs[] = {
    {"def->start beyond the limit (2e9)", INVALID, "start", {SET_F32(nl_path_request_def, start[0], 2.0e9f)}},
    {"def->search_half_extents 0", INVALID, "search_half_extents", {SET_F32(nl_path_request_def, search_half_extents[1], 0.0f)}},
    {"def->search_half_extents negative", INVALID, "search_half_extents",
     {SET_F32(nl_path_request_def, search_half_extents[1], -1.0f)}},
    {"def->agent.radius negative", INVALID, "radius", {SET_F32(nl_path_request_def, agent.radius, -1.0f)}},
    {"def->link_cost negative", INVALID, "link_cost", {SET_F32(nl_path_request_def, link_cost, -1.0f)}},
    {"def->area_costs NULL (area_cost_count 3)", INVALID, "area_costs", {SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_cost_count huge (area_costs NULL: not read)", INVALID, "area_cost_count",
     {SET_U32(nl_path_request_def, area_cost_count, UINT32_MAX)}},
    {"def->area_cost_count 257", INVALID, "area_cost_count",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_257), SET_U32(nl_path_request_def, area_cost_count, 257u)}},
    {"def->area_costs NaN ([1])", INVALID, "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_nan), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs inf ([1])", INVALID, "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_inf), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs -inf ([1])", INVALID, "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_minus_inf), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs negative ([2])", INVALID, "area_costs[2]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_negative), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs NULL (allowed with area_cost_count 0)", ALLOWED, NULL, {SET_PTR(nl_path_request_def, area_costs, NULL)}},
    {"def->area_cost_count 0 (allowed: area_costs not read)", ALLOWED, NULL,
     {SET_PTR(nl_path_request_def, area_costs, "not floats"), SET_U32(nl_path_request_def, area_cost_count, 0u)}},
    {"def->callback NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_path_request_def, callback, NULL)}},
    {"def->user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_path_request_def, user, NULL)}},
};

static int g_callbacks; /* callbacks of requests made by the cases */
static void count_callback(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    (void)user;
    (void)ticket;
    (void)outcome;
    ++g_callbacks;
}

/* nl_path_find, nl_path_request (g_queued) or nl_path_explain (g_explained) with a def: refused with
   nothing written, no ticket made (the queue's counters, compared after each case, say so) and no
   callback run. */
static int g_queued, g_explained;
static void request_refuses(const void* def, nl_status detail, const char* needle) {
    nl_path_result result;
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_path_ticket ticket;
    nl_path_shortfall shortfall;
    const int callbacks = g_callbacks;
    fill(&result, sizeof result);
    result.size = sizeof result;
    fill(points, sizeof points);
    fill(&count, sizeof count);
    fill(&ticket, sizeof ticket);
    fill(&shortfall, sizeof shortfall);
    shortfall.size = sizeof shortfall;
    if (g_explained) {
        EXPECT_FAILURE(A.world, nl_path_explain(A.world, (const nl_path_request_def*)def, &shortfall), detail, needle);
        EXPECT_UNTOUCHED_AFTER_SIZE(&shortfall, sizeof shortfall, "out_shortfall");
    } else if (g_queued) {
        EXPECT_FAILURE(A.world, nl_path_request(A.world, (const nl_path_request_def*)def, &ticket), detail, needle);
        EXPECT_UNTOUCHED(&ticket, sizeof ticket, "out_ticket");
        EXPECT(g_callbacks == callbacks, "the callback of a refused request ran");
    } else {
        EXPECT_FAILURE(A.world, nl_path_find(A.world, (const nl_path_request_def*)def, &result, points, 64, &count), detail, needle);
        EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
        EXPECT_UNTOUCHED(points, sizeof points, "out_points");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
}

/* A def accepted: it plans as the valid one does (a queued one is released again). */
static void request_accepts(const void* def) {
    if (g_explained) {
        nl_path_shortfall shortfall = nl_path_shortfall_init();
        EXPECT_OK(nl_path_explain(A.world, (const nl_path_request_def*)def, &shortfall));
        EXPECT(shortfall.reason == NL_PATH_SHORTFALL_NONE && shortfall.text[0] == '\0', "reason %u: %s", (unsigned)shortfall.reason,
               shortfall.text);
    } else if (g_queued) {
        nl_path_ticket ticket = {0u, 0u};
        EXPECT_OK(nl_path_request(A.world, (const nl_path_request_def*)def, &ticket));
        EXPECT_OK(nl_path_release(A.world, ticket));
        fixture_refresh();
    } else {
        nl_path_result result;
        nl_path_point points[64];
        points[0] = nl_path_point_init();
        uint32_t count = 0;
        memset(&result, 0, sizeof result);
        result.size = sizeof result;
        EXPECT_OK(nl_path_find(A.world, (const nl_path_request_def*)def, &result, points, 64, &count));
        EXPECT(result.outcome == NL_PATH_COMPLETE, "outcome %u", (unsigned)result.outcome);
    }
}

static const nl_path_request_def* g_request;
static nl_status request_id_call(nl_world* w, raw_id id, void* out) {
    nl_path_request_def def = *g_request;
    nl_path_point points[4];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_status status;
    def.navmesh = AS(nl_navmesh_id, id);
    if (g_explained) return nl_path_explain(w, &def, (nl_path_shortfall*)out);
    if (g_queued) return nl_path_request(w, &def, (nl_path_ticket*)out);
    fill(points, sizeof points);
    points[0].size = sizeof points[0];
    fill(&count, sizeof count);
    status = nl_path_find(w, &def, (nl_path_result*)out, points, 4, &count);
    EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}

/* Everything about the def, shared by nl_path_find and nl_path_request. */
static void request_def_cases(const char* function) {
    nl_path_request_def valid = gap_request(A.navmesh);
    const id_function find = {function, "def->navmesh", "out_result", sizeof(nl_path_result), 1, 0, request_id_call, 1};
    const id_function request = {function, "def->navmesh", "out_ticket", sizeof(nl_path_ticket), 0, 0, request_id_call, 1};
    const id_function explain = {function, "def->navmesh", "out_shortfall", sizeof(nl_path_shortfall), 1, 0, request_id_call, 1};
    valid.callback = count_callback;
    g_request = &valid;
    id_cases(g_explained ? &explain : g_queued ? &request : &find, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "def NULL") { request_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes(function, "def", &valid, sizeof valid, request_refuses, request_accepts);
    def_cases(function, &valid, sizeof valid, k_request_defs, sizeof k_request_defs / sizeof *k_request_defs, request_refuses,
              request_accepts);
    bad_float_fields(function, "def", &valid, sizeof valid, k_request_floats, sizeof k_request_floats / sizeof *k_request_floats,
                     request_refuses);
}

/* The result and points of nl_path_find and nl_path_get_result: `call` runs one of them with the
   outputs given. */
typedef nl_status result_call_fn(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count);
typedef struct result_case {
    const char* what;
    int result, points, count; /* which outputs are given */
    uint32_t capacity;         /* UINT32_MAX - 1: one less than the points */
    nl_status detail;          /* 0: a success */
    const char* needle;
} result_case;

static void result_cases(const char* function, result_call_fn* call) {
    static const result_case cases[] = {
        {"out_result NULL", 0, 1, 1, 64, NL_STATUS_INVALID_ARGUMENT, "out_result"},
        {"out_count NULL", 1, 1, 0, 64, NL_STATUS_INVALID_ARGUMENT, "out_count"},
        {"out_points NULL (allowed with capacity 0: counts)", 1, 0, 1, 0, 0u, NULL},
        {"capacity huge (out_points NULL)", 1, 0, 1, UINT32_MAX, NL_STATUS_INVALID_ARGUMENT, "out_points"},
        {"capacity 0 (points given: the result is written, the points are not)", 1, 1, 1, 0, NL_STATUS_BUFFER_TOO_SMALL, "capacity"},
        {"capacity small (one less than the points)", 1, 1, 1, UINT32_MAX - 1, NL_STATUS_BUFFER_TOO_SMALL, "capacity"},
        {"capacity huge (room for 68: only the points written)", 1, 1, 1, UINT32_MAX, 0u, NULL},
    };
    nl_path_result expected;
    uint32_t needed = 0;
    size_t i;
    memset(&expected, 0, sizeof expected);
    expected.size = sizeof expected;
    if (NL_FAILED(call(&expected, NULL, 0, &needed)) || needed < 2 || needed >= 68) fixture_failed("the known path's points");
    for (i = 0; i < sizeof cases / sizeof *cases; ++i) {
        const result_case* c = &cases[i];
        CASE(function, "%s", c->what) {
            nl_path_result result;
            nl_path_point points[68];
            points[0] = nl_path_point_init();
            uint32_t count;
            const uint32_t capacity = c->capacity == UINT32_MAX - 1 ? needed - 1 : c->capacity;
            nl_status status;
            fill(&result, sizeof result);
            result.size = sizeof result;
            fill(points, sizeof points);
            points[0].size = sizeof points[0];
            fill(&count, sizeof count);
            status = call(c->result ? &result : NULL, c->points ? points : NULL, capacity, c->count ? &count : NULL);
            if (c->detail == 0u || c->detail == NL_STATUS_BUFFER_TOO_SMALL) {
                /* The result and the count are written; the points only when they fit. */
                if (c->detail == 0u) EXPECT_OK(status);
                else EXPECT_FAILURE(A.world, status, c->detail, c->needle);
                EXPECT(count == needed && memcmp(&result, &expected, sizeof result) == 0, "count %u, or another result",
                       (unsigned)count);
                if (c->detail == 0u) EXPECT_UNTOUCHED(points + needed, (68 - needed) * sizeof *points, "the points past out_count");
                else EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
            } else {
                EXPECT_FAILURE(A.world, status, c->detail, c->needle);
                EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
                EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
                EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
            }
        }
    }
}

static nl_status find_known(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count) {
    const nl_path_request_def def = gap_request(A.navmesh);
    return nl_path_find(A.world, &def, result, points, capacity, count);
}
static nl_status find_into(void* result) {
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count = 0;
    return find_known((nl_path_result*)result, points, 64, &count);
}

static nl_status find_points(void* out, uint32_t* written) {
    nl_path_result result = nl_path_result_init();
    return find_known(&result, (nl_path_point*)out, 256u, written);
}

static void group_path_find(void) {
    g_queued = 0;
    request_def_cases("nl_path_find");
    result_cases("nl_path_find", find_known);
    out_sizes("nl_path_find", "out_result", sizeof(nl_path_result), find_into);
    out_element_sizes("nl_path_find", "out_points", sizeof(nl_path_point), find_points);
}

static nl_status explain_into(void* shortfall) {
    const nl_path_request_def def = gap_request(A.navmesh);
    return nl_path_explain(A.world, &def, (nl_path_shortfall*)shortfall);
}

static void group_path_explain(void) {
    g_queued = 0;
    g_explained = 1;
    CASE("nl_path_explain", "out_shortfall NULL") {
        const nl_path_request_def def = gap_request(A.navmesh);
        EXPECT_INVALID(A.world, nl_path_explain(A.world, &def, NULL), "out_shortfall");
    }
    request_def_cases("nl_path_explain");
    out_sizes("nl_path_explain", "out_shortfall", sizeof(nl_path_shortfall), explain_into);
    g_explained = 0;
}

static void group_path_request(void) {
    const nl_path_request_def valid = gap_request(A.navmesh);
    g_queued = 1;
    CASE("nl_path_request", "out_ticket NULL") {
        nl_path_request_def def = valid;
        const int callbacks = g_callbacks;
        def.callback = count_callback;
        EXPECT_INVALID(A.world, nl_path_request(A.world, &def, NULL), "out_ticket");
        EXPECT(g_callbacks == callbacks, "the callback of a refused request ran");
    }
    request_def_cases("nl_path_request");
    CASE("nl_path_request", "def->callback set, released before it ran (its callback runs once)") {
        nl_path_request_def def = valid;
        nl_path_ticket ticket;
        const int callbacks = g_callbacks;
        def.callback = count_callback;
        EXPECT_OK(nl_path_request(A.world, &def, &ticket));
        EXPECT_OK(nl_path_release(A.world, ticket));
        EXPECT(g_callbacks == callbacks + 1, "the callback ran %d times, expected once", g_callbacks - callbacks);
        fixture_refresh();
    }
}

/* The functions that take a ticket. */
ID_OUT_CALL(poll_call, nl_path_ticket, nl_path_outcome, nl_path_poll)
ID_CALL(cancel_call, nl_path_ticket, nl_path_cancel)
/* Waits forever: a bad ticket must fail at once, not hang. */
static nl_status wait_call(nl_world* w, raw_id id, void* out) {
    return nl_path_wait(w, AS(nl_path_ticket, id), NL_PATH_WAIT_FOREVER, (nl_path_outcome*)out);
}
ID_CALL(release_call, nl_path_ticket, nl_path_release)
/* The result of a ticket, with its points and count untouched too. */
static nl_status get_result_call(nl_world* w, raw_id id, void* out) {
    nl_path_point points[4];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_status status;
    fill(points, sizeof points);
    points[0].size = sizeof points[0];
    fill(&count, sizeof count);
    status = nl_path_get_result(w, AS(nl_path_ticket, id), (nl_path_result*)out, points, 4, &count);
    EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}
static const id_function k_ticket_functions[] = {
    {"nl_path_poll", "ticket", "out_outcome", sizeof(nl_path_outcome), 0, 0, poll_call, 0},
    {"nl_path_cancel", "ticket", NULL, 0, 0, 0, cancel_call, 0},
    {"nl_path_release", "ticket", NULL, 0, 0, 0, release_call, 0},
    {"nl_path_get_result", "ticket", "out_result", sizeof(nl_path_result), 1, 0, get_result_call, 1},
    {"nl_path_wait", "ticket", "out_outcome", sizeof(nl_path_outcome), 0, 0, wait_call, 0},
};

static void ticket_id_cases(size_t which) {
    id_cases(&k_ticket_functions[which], RAW(A.pending_ticket), RAW(A.stale_ticket), RAW(B.pending_ticket));
}

static void group_path_poll(void) { ticket_id_cases(0); }
static void group_path_cancel(void) { ticket_id_cases(1); }
static void group_path_release(void) { ticket_id_cases(2); }
static void group_path_wait(void) {
    ticket_id_cases(4);
    CASE("nl_path_wait", "timeout_ms 0 on a pending ticket (looks only: IN_PROGRESS, nothing planned)") {
        nl_path_outcome outcome = 99;
        EXPECT(nl_path_wait(A.world, A.pending_ticket, 0, &outcome) == NL_STATUS_IN_PROGRESS, "expected IN_PROGRESS");
        EXPECT(outcome == NL_PATH_PENDING, "outcome %u, expected NL_PATH_PENDING", outcome);
    }
    CASE("nl_path_wait", "timeout_ms huge (NL_PATH_WAIT_FOREVER - 1) on a finished ticket (answers at once)") {
        nl_path_outcome outcome = 99;
        EXPECT_OK(nl_path_wait(A.world, A.done_ticket, NL_PATH_WAIT_FOREVER - 1u, &outcome));
        EXPECT(outcome == NL_PATH_COMPLETE, "outcome %u, expected NL_PATH_COMPLETE", outcome);
    }
    CASE("nl_path_wait", "timeout_ms huge (NL_PATH_WAIT_FOREVER - 1) on a pending ticket (no workers: this thread plans it)") {
        nl_path_outcome outcome = 99;
        EXPECT_OK(nl_path_wait(A.world, A.pending_ticket, NL_PATH_WAIT_FOREVER - 1u, &outcome));
        EXPECT(outcome != NL_PATH_PENDING, "still pending after the wait");
        fixture_refresh();
    }
}

static nl_status result_of_done(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count) {
    return nl_path_get_result(A.world, A.done_ticket, result, points, capacity, count);
}
static nl_status result_into(void* result) {
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count = 0;
    return result_of_done((nl_path_result*)result, points, 64, &count);
}

static nl_status result_points(void* out, uint32_t* written) {
    nl_path_result result = nl_path_result_init();
    return result_of_done(&result, (nl_path_point*)out, 256u, written);
}

static void group_path_get_result(void) {
    ticket_id_cases(3);
    CASE("nl_path_get_result", "ticket pending (IN_PROGRESS: nothing written)") {
        nl_path_result result;
        fill(&result, sizeof result);
        result.size = sizeof result;
        EXPECT_STATUS(get_result_call(A.world, RAW(A.pending_ticket), &result), NL_STATUS_IN_PROGRESS);
        EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
    }
    result_cases("nl_path_get_result", result_of_done);
    out_sizes("nl_path_get_result", "out_result", sizeof(nl_path_result), result_into);
    out_element_sizes("nl_path_get_result", "out_points", sizeof(nl_path_point), result_points);
}

/* nl_path_process with `out_processed` given: what it must return and how many it must plan. */
typedef struct process_case {
    const char* what;
    uint32_t max_requests;
    double max_milliseconds;
    int with_out;
    nl_status detail; /* 0: a success */
    uint32_t processed;
} process_case;

static void group_path_process(void) {
    const process_case cases[] = {
        {"budget->max_milliseconds NaN (nothing planned)", 0, (double)NAN, 1, NL_STATUS_INVALID_ARGUMENT, 0},
        {"budget->max_milliseconds -inf (allowed: no limit)", 1, -(double)INFINITY, 1, 0u, 1},
        {"budget->max_milliseconds inf (allowed: no limit)", 0, (double)INFINITY, 1, 0u, 0},
        {"budget->max_requests 0 (allowed: no limit)", 0, 0.0, 1, 0u, 0},
        {"budget->max_requests huge (allowed)", UINT32_MAX, 0.0, 1, 0u, 0},
        {"out_processed NULL (allowed)", 0, 0.0, 0, 0u, 0},
    };
    size_t i;
    CASE("nl_path_process", "world NULL") {
        uint32_t processed;
        fill(&processed, sizeof processed);
        EXPECT_INVALID(NULL, nl_path_process(NULL, NL_TEST_BUDGET(0, 0.0), &processed), "world");
        EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
    }
    for (i = 0; i < sizeof cases / sizeof *cases; ++i) {
        CASE("nl_path_process", "%s", cases[i].what) {
            uint32_t processed;
            nl_status status;
            fill(&processed, sizeof processed);
            status = nl_path_process(A.world, NL_TEST_BUDGET(cases[i].max_requests, cases[i].max_milliseconds), cases[i].with_out ? &processed : NULL);
            if (cases[i].detail) {
                EXPECT_INVALID(A.world, status, "max_milliseconds");
                EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
            } else {
                EXPECT_OK(status);
                if (cases[i].with_out)
                    EXPECT(processed == cases[i].processed, "planned %u requests, expected %u (the pending one, then none)",
                           (unsigned)processed, (unsigned)cases[i].processed);
                fixture_refresh(); /* the pending request finished */
            }
        }
    }
    {
        /* A request to plan, queued before each case that plans one (the fixture's pending one is
           planned by the cases above). */
        const nl_path_request_def def = gap_request(A.navmesh);
        nl_path_ticket queued;
        static const uint32_t bad[3] = {0u, 4u, (uint32_t)sizeof(nl_path_budget) - 1u};
        static const char* what[3] = {"budget->size 0", "budget->size small (4)", "budget->size small (sizeof - 1)"};
        int k;
        if (NL_FAILED(nl_path_request(A.world, &def, &queued))) fixture_failed("a request to plan");
        fixture_refresh();
        for (k = 0; k < 3; ++k) {
            CASE("nl_path_process", "%s (nothing planned)", what[k]) {
                nl_path_budget budget = nl_default_path_budget();
                uint32_t processed;
                nl_path_outcome outcome = NL_PATH_COMPLETE;
                budget.size = bad[k];
                fill(&processed, sizeof processed);
                EXPECT_INVALID(A.world, nl_path_process(A.world, &budget, &processed), "budget->size");
                EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
                EXPECT(NL_SUCCEEDED(nl_path_poll(A.world, queued, &outcome)) && outcome == NL_PATH_PENDING,
                       "the queued request was planned");
            }
        }
        CASE("nl_path_process", "budget NULL (allowed: no limits)") {
            uint32_t processed;
            fill(&processed, sizeof processed);
            EXPECT_OK(nl_path_process(A.world, NULL, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected the queued one", (unsigned)processed);
            fixture_refresh();
        }
        nl_path_release(A.world, queued);
        if (NL_FAILED(nl_path_request(A.world, &def, &queued)) || NL_FAILED(nl_path_request(A.world, &def, &queued)))
            fixture_failed("requests to plan");
        fixture_refresh();
        CASE("nl_path_process", "budget->size large (sizeof + 64: the fields it knows are read)") {
            aligned_buffer buffer;
            nl_path_budget budget = nl_default_path_budget();
            uint32_t processed = 0;
            fill(buffer.bytes, sizeof buffer.bytes);
            budget.size = (uint32_t)sizeof budget + 64u;
            budget.max_requests = 1u;
            memcpy(buffer.bytes, &budget, sizeof budget);
            EXPECT_OK(nl_path_process(A.world, (const nl_path_budget*)buffer.bytes, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected 1 of 2 (max_requests read)", (unsigned)processed);
            fixture_refresh();
        }
        CASE("nl_path_process", "budget->max_search_nodes 1 (allowed: one request, the one crossing it)") {
            nl_path_budget budget = nl_default_path_budget();
            uint32_t processed = 0;
            budget.max_search_nodes = 1u;
            EXPECT_OK(nl_path_process(A.world, &budget, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected 1", (unsigned)processed);
            fixture_refresh();
        }
    }
}

/* A request planned and finished, waiting to be taken; its ticket in *out. */
static void finish_one(nl_path_ticket* out) {
    const nl_path_request_def def = gap_request(A.navmesh);
    if (NL_FAILED(nl_path_request(A.world, &def, out)) || NL_FAILED(nl_path_process(A.world, NULL, NULL)))
        fixture_failed("a request to take");
}

static nl_status take_into(void* out, uint32_t* written) {
    return nl_path_take_finished(A.world, (nl_path_finished*)out, 256u, written, NULL);
}

static void group_path_take_finished(void) {
    nl_path_ticket ticket;
    uint32_t waiting = 0, taken;
    nl_path_finished drained[64];
    drained[0] = nl_path_finished_init();
    /* The fixture's finished requests taken first: then exactly one waits. */
    if (NL_FAILED(nl_path_take_finished(A.world, drained, 64, &taken, &waiting)) || waiting != 0u)
        fixture_failed("the fixture's finished requests");
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "world NULL") {
        nl_path_finished out[2];
        uint32_t count, remaining;
        fill(out, sizeof out);
        out[0].size = sizeof out[0];
        fill(&count, sizeof count);
        fill(&remaining, sizeof remaining);
        EXPECT_INVALID(NULL, nl_path_take_finished(NULL, out, 2, &count, &remaining), "world");
        EXPECT_UNTOUCHED_AFTER_SIZE(out, sizeof out, "out_finished");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_path_take_finished", "out_count NULL") {
        nl_path_finished out[2];
        fill(out, sizeof out);
        out[0].size = sizeof out[0];
        EXPECT_INVALID(A.world, nl_path_take_finished(A.world, out, 2, NULL, NULL), "out_count");
        EXPECT_UNTOUCHED_AFTER_SIZE(out, sizeof out, "out_finished");
    }
    CASE("nl_path_take_finished", "out_finished NULL with capacity 2") {
        uint32_t count;
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world, nl_path_take_finished(A.world, NULL, 2, &count, NULL), "out_finished");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_path_take_finished", "capacity 0 (allowed: takes nothing, says how many wait)") {
        uint32_t count = 77u, remaining = 0u, again = 0u;
        EXPECT_OK(nl_path_take_finished(A.world, NULL, 0, &count, &remaining));
        EXPECT_OK(nl_path_take_finished(A.world, NULL, 0, &count, &again));
        /* finish_one planned the fixture's pending request too: two wait, and stay. */
        EXPECT(count == 0u && remaining == 2u && again == 2u, "took %u, %u then %u waiting", (unsigned)count,
               (unsigned)remaining, (unsigned)again);
    }
    /* Each size refusal keeps the finished request: the size-large case takes it (then the world
       changed: refreshed). */
    /* The refusals below lose nothing: the finished request is still there for the size-large case. */
    out_element_sizes("nl_path_take_finished", "out_finished", sizeof(nl_path_finished), take_into);
    fixture_refresh();
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "capacity huge (allowed: takes what there is)") {
        nl_path_finished out[4];
        uint32_t count = 0u;
        out[0] = nl_path_finished_init();
        EXPECT_OK(nl_path_take_finished(A.world, out, UINT32_MAX, &count, NULL));
        EXPECT(count == 1u && out[0].ticket.index1 == ticket.index1 && out[0].outcome == NL_PATH_COMPLETE,
               "took %u requests", (unsigned)count);
        fixture_refresh();
    }
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "out_remaining NULL (allowed)") {
        nl_path_finished out[1];
        uint32_t count = 0u;
        out[0] = nl_path_finished_init();
        EXPECT_OK(nl_path_take_finished(A.world, out, 1, &count, NULL));
        EXPECT(count == 1u, "took %u requests", (unsigned)count);
        fixture_refresh();
    }
}

static nl_status stats_into(void* stats) { return nl_path_get_queue_stats(A.world, (nl_path_queue_stats*)stats); }
static void group_path_get_queue_stats(void) {
    CASE("nl_path_get_queue_stats", "world NULL") {
        nl_path_queue_stats stats;
        fill(&stats, sizeof stats);
        stats.size = sizeof stats;
        EXPECT_INVALID(NULL, nl_path_get_queue_stats(NULL, &stats), "world");
        EXPECT_UNTOUCHED_AFTER_SIZE(&stats, sizeof stats, "out_stats");
    }
    CASE("nl_path_get_queue_stats", "out_stats NULL") { EXPECT_INVALID(A.world, nl_path_get_queue_stats(A.world, NULL), "out_stats"); }
    out_sizes("nl_path_get_queue_stats", "out_stats", sizeof(nl_path_queue_stats), stats_into);
}

/* ---------------------------------------------------------------------------------------------
 * Queries: on A's navmesh (the gap level), a walk on the near platform from polygon g_near
 * ------------------------------------------------------------------------------------------- */

static const float k_walk_start[3] = {-6.0f, 0.0f, 0.0f};
static const float k_walk_end[3] = {-7.0f, 0.0f, 1.0f};
static uint32_t g_near = NL_NO_POLYGON; /* the polygon under k_walk_start */

static uint32_t polygon_under(const float* point) {
    const float extents[3] = {1.0f, 2.0f, 1.0f};
    nl_nav_point p;
    return NL_SUCCEEDED(nl_navmesh_find_nearest(A.world, A.navmesh, point, 1, extents, &p)) && p.found ? p.polygon
                                                                                                      : NL_NO_POLYGON;
}
static uint32_t near_polygon(void) {
    if (g_near == NL_NO_POLYGON) g_near = polygon_under(k_walk_start);
    return g_near;
}

static const float_field k_filter_floats[] = {
    FLOAT_FIELD(nl_query_filter, agent.max_jump_distance, 1),
    FLOAT_FIELD(nl_query_filter, agent.max_jump_height, 1),
    FLOAT_FIELD(nl_query_filter, agent.max_drop_height, 1),
    FLOAT_FIELD(nl_query_filter, agent.radius, 1),
};

static const def_case k_filter_defs[] = {
    {"filter->agent.radius negative", INVALID, "radius", {SET_F32(nl_query_filter, agent.radius, -1.0f)}},
    {"filter->area_costs NULL (area_cost_count 3)", INVALID, "area_costs", {SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_cost_count huge (area_costs NULL: not read)", INVALID, "area_cost_count",
     {SET_U32(nl_query_filter, area_cost_count, UINT32_MAX)}},
    {"filter->area_cost_count 257", INVALID, "area_cost_count",
     {SET_PTR(nl_query_filter, area_costs, k_costs_257), SET_U32(nl_query_filter, area_cost_count, 257u)}},
    {"filter->area_costs NaN ([1])", INVALID, "area_costs[1]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_nan), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_costs inf ([1])", INVALID, "area_costs[1]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_inf), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_costs negative ([2])", INVALID, "area_costs[2]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_negative), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_cost_count 0 (allowed: area_costs not read)", ALLOWED, NULL,
     {SET_PTR(nl_query_filter, area_costs, "not floats"), SET_U32(nl_query_filter, area_cost_count, 0u)}},
};

/* The query the filter cases run now: it calls its function with `filter` and every other argument
   valid, its outputs in `out` (filled by the caller). */
typedef nl_status query_call_fn(const nl_query_filter* filter, void* out);
static query_call_fn* g_query;
static size_t g_query_out_size;
static size_t g_query_out_skip; /* bytes the call sets itself (an output's size) */

static void query_refuses(const void* filter, nl_status detail, const char* needle) {
    aligned_buffer out;
    fill(out.bytes, sizeof out.bytes);
    EXPECT_FAILURE(A.world, g_query((const nl_query_filter*)filter, out.bytes), detail, needle);
    EXPECT_UNTOUCHED(out.bytes + g_query_out_skip, g_query_out_size - g_query_out_skip, "the outputs");
}
static void query_accepts(const void* filter) {
    aligned_buffer out;
    fill(out.bytes, sizeof out.bytes);
    EXPECT_OK(g_query((const nl_query_filter*)filter, out.bytes));
}

/* Everything about a query's filter: NULL (the defaults), its sizes, areas and capabilities. */
static void filter_cases(const char* function, query_call_fn* call, size_t out_size, size_t out_skip) {
    nl_query_filter valid = nl_default_query_filter();
    g_query = call;
    g_query_out_size = out_size;
    g_query_out_skip = out_skip;
    CASE(function, "filter NULL (allowed: the default walker)") { query_accepts(NULL); }
    def_sizes(function, "filter", &valid, sizeof valid, query_refuses, query_accepts);
    def_cases(function, &valid, sizeof valid, k_filter_defs, sizeof k_filter_defs / sizeof *k_filter_defs, query_refuses,
              query_accepts);
    bad_float_fields(function, "filter", &valid, sizeof valid, k_filter_floats, sizeof k_filter_floats / sizeof *k_filter_floats,
                     query_refuses);
}

static void group_default_query_filter(void) {
    CASE("nl_default_query_filter", "the defaults") {
        const nl_query_filter f = nl_default_query_filter();
        const nl_agent_capabilities walker = nl_default_agent_capabilities();
        EXPECT(f.size == sizeof f && f.area_costs == NULL && f.area_cost_count == 0 && f.reserved == 0 &&
                   memcmp(&f.agent, &walker, sizeof walker) == 0,
               "not a default walker keeping out of no area");
    }
}

/* nl_navmesh_can_reach: two pairs, (near, near) and (near, 0). */
static uint32_t g_reach_from[2], g_reach_to[2];
static nl_status can_reach_call(const nl_query_filter* filter, void* out) {
    g_reach_from[0] = g_reach_from[1] = g_reach_to[0] = near_polygon();
    g_reach_to[1] = 0;
    return nl_navmesh_can_reach(A.world, A.navmesh, filter, g_reach_from, g_reach_to, 2, (uint8_t*)out);
}
static nl_status can_reach_id_call(nl_world* w, raw_id id, void* out) {
    g_reach_from[0] = g_reach_from[1] = g_reach_to[0] = g_reach_to[1] = 0;
    return nl_navmesh_can_reach(w, AS(nl_navmesh_id, id), NULL, g_reach_from, g_reach_to, 2, (uint8_t*)out);
}

static void group_navmesh_can_reach(void) {
    static const id_function f = {"nl_navmesh_can_reach", "navmesh", "out_reachable", 2, 0, 0, can_reach_id_call, 0};
    const uint32_t zero = 0, beyond = 1000000u;
    uint8_t answer[2];
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases("nl_navmesh_can_reach", can_reach_call, sizeof answer, 0);
    CASE("nl_navmesh_can_reach", "from_polygons NULL") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, &zero, 1, answer), "from_polygons");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "to_polygons NULL") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &zero, NULL, 1, answer), "to_polygons");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "count 0 (allowed, with the arrays and out_reachable NULL)") {
        EXPECT_OK(nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, NULL, 0, NULL));
    }
    CASE("nl_navmesh_can_reach", "count huge (from_polygons NULL: not read)") {
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, &zero, UINT32_MAX, answer), "from_polygons");
    }
    CASE("nl_navmesh_can_reach", "from_polygons out of range (1000000)") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &beyond, &zero, 1, answer), "from_polygons[0]");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "to_polygons NL_NO_POLYGON") {
        const uint32_t none = NL_NO_POLYGON;
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &zero, &none, 1, answer), "to_polygons[0]");
    }
}

static nl_status list_reachable(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_reachable_polygons(w, n, NULL, 0, (uint32_t*)out, capacity, count);
}
static nl_status reachable_call(const nl_query_filter* filter, void* out) {
    uint32_t* listed = (uint32_t*)out; /* the count first, then room for the polygons */
    return nl_navmesh_get_reachable_polygons(A.world, A.navmesh, filter, near_polygon(), listed + 1,
                                             (uint32_t)(sizeof(aligned_buffer) / 4 - 1), listed);
}

static void group_navmesh_get_reachable_polygons(void) {
    uint32_t count = 0;
    nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, 0, NULL, 0, &count);
    navmesh_list_cases("nl_navmesh_get_reachable_polygons", "out_polygons", sizeof(uint32_t), count, list_reachable);
    filter_cases("nl_navmesh_get_reachable_polygons", reachable_call, 4, 0);
    CASE("nl_navmesh_get_reachable_polygons", "from_polygon 0 (allowed)") {
        EXPECT_OK(nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, 0, NULL, 0, &count));
        EXPECT(count >= 1, "polygon 0 reaches %u polygons", (unsigned)count);
    }
    CASE("nl_navmesh_get_reachable_polygons", "from_polygon huge") {
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world, nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, UINT32_MAX, NULL, 0, &count),
                       "from_polygon");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
}

static nl_status list_islands(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_islands(w, n, NULL, (uint32_t*)out, capacity, count, NULL);
}
static nl_status islands_call(const nl_query_filter* filter, void* out) {
    uint32_t* counts = (uint32_t*)out;
    return nl_navmesh_get_islands(A.world, A.navmesh, filter, NULL, 0, &counts[0], &counts[1]);
}

static void group_navmesh_get_islands(void) {
    navmesh_list_cases("nl_navmesh_get_islands", "out_islands", sizeof(uint32_t), navmesh_info(&A, A.navmesh).polygon_count,
                       list_islands);
    filter_cases("nl_navmesh_get_islands", islands_call, 8, 0);
    CASE("nl_navmesh_get_islands", "out_island_count NULL (allowed)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_get_islands(A.world, A.navmesh, NULL, NULL, 0, &count, NULL));
    }
    CASE("nl_navmesh_get_islands", "out_island_count given: at least one island") {
        uint32_t count = 0, islands = 0;
        EXPECT_OK(nl_navmesh_get_islands(A.world, A.navmesh, NULL, NULL, 0, &count, &islands));
        EXPECT(islands >= 1 && islands <= count, "%u islands of %u polygons", (unsigned)islands, (unsigned)count);
    }
}

/* nl_navmesh_move_along_surface from k_walk_start toward k_walk_end. */
static nl_status move_filter_call(const nl_query_filter* filter, void* out) {
    return nl_navmesh_move_along_surface(A.world, A.navmesh, filter, near_polygon(), k_walk_start, k_walk_end,
                                         (nl_nav_point*)out, NULL, 0, NULL);
}
static nl_status move_id_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_move_along_surface(w, AS(nl_navmesh_id, id), NULL, 0, k_walk_start, k_walk_end, (nl_nav_point*)out,
                                         NULL, 0, NULL);
}
static void move_refused(uint32_t polygon, const float* start, const float* target, uint32_t* polygons, uint32_t capacity,
                         const char* needle) {
    nl_nav_point out;
    uint32_t count;
    fill(&out, sizeof out);
    fill(&count, sizeof count);
    EXPECT_INVALID(A.world, nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, polygon, start, target, &out, polygons,
                                                          capacity, &count),
                   needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_point");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
}

static void group_navmesh_move_along_surface(void) {
    static const char* const function = "nl_navmesh_move_along_surface";
    static const id_function f = {"nl_navmesh_move_along_surface", "navmesh", "out_point", sizeof(nl_nav_point), 0, 0,
                                  move_id_call, 0};
    const float far_platform[3] = {6.0f, 0.0f, 0.0f};
    size_t v;
    int k, which;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases(function, move_filter_call, sizeof(nl_nav_point), 0);
    CASE(function, "start_polygon 0 or any other the start is not over (the far platform's): refused") {
        move_refused(polygon_under(far_platform), k_walk_start, k_walk_end, NULL, 0, "start is not over start_polygon");
    }
    CASE(function, "start_polygon huge") { move_refused(UINT32_MAX, k_walk_start, k_walk_end, NULL, 0, "start_polygon"); }
    CASE(function, "start NULL") { move_refused(near_polygon(), NULL, k_walk_end, NULL, 0, "start"); }
    CASE(function, "target NULL") { move_refused(near_polygon(), k_walk_start, NULL, NULL, 0, "target"); }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE(function, "%s[%d] %s", which == 0 ? "start" : "target", k, k_bad_floats[v].name) {
                    float start[3], target[3];
                    memcpy(start, k_walk_start, sizeof start);
                    memcpy(target, k_walk_end, sizeof target);
                    (which == 0 ? start : target)[k] = k_bad_floats[v].value;
                    move_refused(near_polygon(), start, target, NULL, 0, which == 0 ? "start" : "target");
                }
            }
        }
    }
    CASE(function, "target beyond the limit (2e9)") {
        const float far[3] = {2.0e9f, 0.0f, 0.0f};
        move_refused(near_polygon(), k_walk_start, far, NULL, 0, "target");
    }
    CASE(function, "out_polygons NULL (capacity 1)") { move_refused(near_polygon(), k_walk_start, k_walk_end, NULL, 1, "out_polygons"); }
    CASE(function, "capacity huge (out_polygons NULL)") {
        move_refused(near_polygon(), k_walk_start, k_walk_end, NULL, UINT32_MAX, "out_polygons");
    }
    CASE(function, "capacity 0 (a buffer given: BUFFER_TOO_SMALL, the point written, the count of all)") {
        nl_nav_point out;
        uint32_t polygons[4], count = 0;
        fill(polygons, sizeof polygons);
        EXPECT_FAILURE(A.world, nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, near_polygon(), k_walk_start, k_walk_end,
                                                              &out, polygons, 0, &count),
                       NL_STATUS_BUFFER_TOO_SMALL, "capacity is 0");
        EXPECT(count >= 1 && out.found == 1, "out_count %u, found %u", (unsigned)count, (unsigned)out.found);
        EXPECT_UNTOUCHED(polygons, sizeof polygons, "out_polygons");
    }
    CASE(function, "out_count NULL (allowed)") {
        nl_nav_point out;
        uint32_t polygons[64];
        EXPECT_OK(nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, near_polygon(), k_walk_start, k_walk_end, &out,
                                                polygons, 64, NULL));
        EXPECT(polygons[0] == near_polygon(), "the first polygon is %u, not the start's", (unsigned)polygons[0]);
    }
}

/* nl_navmesh_raycast: two rays from k_walk_start, the second one made bad by the cases. */
static nl_navmesh_ray walk_ray(void) {
    nl_navmesh_ray r;
    memcpy(r.start, k_walk_start, sizeof r.start);
    memcpy(r.end, k_walk_end, sizeof r.end);
    r.start_polygon = near_polygon();
    return r;
}
static void raycast_refused(const nl_navmesh_ray* rays, uint32_t count, uint32_t* polygons, uint32_t per_ray,
                            const char* needle) {
    nl_navmesh_raycast_hit hits[2];
    fill(hits, sizeof hits);
    set_size(hits, (uint32_t)sizeof hits[0]);
    EXPECT_INVALID(A.world, nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, count, hits, polygons, per_ray), needle);
    EXPECT_UNTOUCHED((unsigned char*)hits + 4, sizeof hits - 4, "out_hits");
}
static nl_status raycast_filter_call(const nl_query_filter* filter, void* out) {
    const nl_navmesh_ray r = walk_ray();
    set_size(out, (uint32_t)sizeof(nl_navmesh_raycast_hit));
    return nl_navmesh_raycast(A.world, A.navmesh, filter, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}
static nl_status raycast_id_call(nl_world* w, raw_id id, void* out) {
    nl_navmesh_ray r = walk_ray();
    r.start_polygon = 0;
    if (out) set_size(out, (uint32_t)sizeof(nl_navmesh_raycast_hit));
    return nl_navmesh_raycast(w, AS(nl_navmesh_id, id), NULL, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}
static nl_status raycast_into(void* out) {
    const nl_navmesh_ray r = walk_ray();
    return nl_navmesh_raycast(A.world, A.navmesh, NULL, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}

static void group_navmesh_raycast(void) {
    static const char* const function = "nl_navmesh_raycast";
    static const id_function f = {"nl_navmesh_raycast", "navmesh", "out_hits", sizeof(nl_navmesh_raycast_hit), 1, 0,
                                  raycast_id_call, 0};
    const float far_platform[3] = {6.0f, 0.0f, 0.0f};
    nl_navmesh_ray rays[2];
    size_t v;
    int k, which;
    rays[0] = rays[1] = walk_ray();
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases(function, raycast_filter_call, sizeof(nl_navmesh_raycast_hit), 4);
    out_sizes(function, "out_hits", sizeof(nl_navmesh_raycast_hit), raycast_into);
    CASE(function, "rays NULL") { raycast_refused(NULL, 2, NULL, 0, "rays"); }
    CASE(function, "count 0 (allowed, rays and out_hits NULL)") {
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, NULL, 0, NULL, NULL, 0));
    }
    CASE(function, "count huge (rays NULL: not read)") { raycast_refused(NULL, UINT32_MAX, NULL, 0, "rays"); }
    CASE(function, "rays->start_polygon of another polygon (the far platform's): refused, naming the ray") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].start_polygon = polygon_under(far_platform);
        raycast_refused(bad, 2, NULL, 0, "rays[1].start is not over rays[1].start_polygon");
    }
    CASE(function, "rays->start_polygon huge") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].start_polygon = UINT32_MAX;
        raycast_refused(bad, 2, NULL, 0, "rays[1].start_polygon");
    }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE(function, "rays->%s[%d] %s (ray 1)", which == 0 ? "start" : "end", k, k_bad_floats[v].name) {
                    nl_navmesh_ray bad[2] = {rays[0], rays[1]};
                    (which == 0 ? bad[1].start : bad[1].end)[k] = k_bad_floats[v].value;
                    raycast_refused(bad, 2, NULL, 0, which == 0 ? "rays[1].start" : "rays[1].end");
                }
            }
        }
    }
    CASE(function, "rays->end beyond the limit (2e9, ray 1)") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].end[0] = 2.0e9f;
        raycast_refused(bad, 2, NULL, 0, "rays[1].end");
    }
    CASE(function, "out_polygons NULL (polygons_per_ray 1)") { raycast_refused(rays, 2, NULL, 1, "out_polygons"); }
    CASE(function, "polygons_per_ray huge (out_polygons NULL)") { raycast_refused(rays, 2, NULL, UINT32_MAX, "out_polygons"); }
    CASE(function, "polygons_per_ray 0 (allowed with out_polygons NULL)") {
        nl_navmesh_raycast_hit hits[2];
        hits[0] = nl_navmesh_raycast_hit_init();
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, 2, hits, NULL, 0));
        EXPECT(hits[1].size == sizeof hits[1] && hits[1].polygon_count >= 1, "second hit: size %u, %u polygons",
               (unsigned)hits[1].size, (unsigned)hits[1].polygon_count);
    }
    CASE(function, "polygons_per_ray 1 (the first polygon of each ray; the count of all)") {
        nl_navmesh_raycast_hit hits[2];
        uint32_t polygons[2];
        hits[0] = nl_navmesh_raycast_hit_init();
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, 2, hits, polygons, 1));
        EXPECT(polygons[0] == near_polygon() && polygons[1] == near_polygon(), "first polygons %u, %u", (unsigned)polygons[0],
               (unsigned)polygons[1]);
    }
}

/* nl_navmesh_random_points: three points with a def. */
static const float_field k_random_floats[] = {
    FLOAT_FIELD(nl_random_points_def, centre, 3),
    FLOAT_FIELD(nl_random_points_def, radius, 1),
};
static const nl_query_filter k_bad_filter = {sizeof(nl_query_filter), {0.0f, 0.0f, -1.0f, 0.6f, 0u}, NULL, 0u, 0u};
static const def_case k_random_defs[] = {
    {"def->radius negative", INVALID, "radius", {SET_F32(nl_random_points_def, radius, -1.0f)}},
    {"def->radius beyond the limit (2e9)", INVALID, "radius", {SET_F32(nl_random_points_def, radius, 2.0e9f)}},
    {"def->centre beyond the limit (2e9)", INVALID, "centre", {SET_F32(nl_random_points_def, centre[2], 2.0e9f)}},
    {"def->filter NULL (allowed: every polygon)", ALLOWED, NULL, {SET_PTR(nl_random_points_def, filter, NULL)}},
    {"def->filter refused (a negative drop)", INVALID, "def->filter->agent.max_drop_height",
     {SET_PTR(nl_random_points_def, filter, &k_bad_filter)}},
    {"def->reachable_from out of range", INVALID, "reachable_from",
     {SET_U32(nl_random_points_def, reachable_from, 1000000u)}},
    {"def->reachable_from 0 (allowed)", ALLOWED, NULL, {SET_U32(nl_random_points_def, reachable_from, 0u)}},
};

static void random_refuses(const void* def, nl_status detail, const char* needle) {
    nl_nav_point points[3];
    uint32_t found;
    fill(points, sizeof points);
    fill(&found, sizeof found);
    EXPECT_FAILURE(A.world, nl_navmesh_random_points(A.world, A.navmesh, (const nl_random_points_def*)def, points, 3, &found),
                   detail, needle);
    EXPECT_UNTOUCHED(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&found, sizeof found, "out_found");
}
static void random_accepts(const void* def) {
    nl_nav_point points[3];
    uint32_t found = 0;
    EXPECT_OK(nl_navmesh_random_points(A.world, A.navmesh, (const nl_random_points_def*)def, points, 3, &found));
    EXPECT(found == 3 && points[2].found == 1, "%u points", (unsigned)found);
}
static nl_status random_id_call(nl_world* w, raw_id id, void* out) {
    const nl_random_points_def def = nl_default_random_points_def();
    uint32_t found;
    return nl_navmesh_random_points(w, AS(nl_navmesh_id, id), &def, (nl_nav_point*)out, 2, &found);
}

static void group_default_random_points_def(void) {
    CASE("nl_default_random_points_def", "the defaults") {
        const nl_random_points_def d = nl_default_random_points_def();
        EXPECT(d.size == sizeof d && d.filter == NULL && d.radius == 0.0f && d.reachable_from == NL_NO_POLYGON && d.seed == 1u,
               "not the whole navmesh with seed 1");
    }
}

static void group_navmesh_random_points(void) {
    static const id_function f = {"nl_navmesh_random_points", "navmesh", "out_points", 2 * sizeof(nl_nav_point), 0, 0,
                                  random_id_call, 0};
    const nl_random_points_def valid = nl_default_random_points_def();
    nl_nav_point points[2];
    uint32_t found;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_random_points", "def NULL") { random_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes("nl_navmesh_random_points", "def", &valid, sizeof valid, random_refuses, random_accepts);
    def_cases("nl_navmesh_random_points", &valid, sizeof valid, k_random_defs, sizeof k_random_defs / sizeof *k_random_defs,
              random_refuses, random_accepts);
    bad_float_fields("nl_navmesh_random_points", "def", &valid, sizeof valid, k_random_floats,
                     sizeof k_random_floats / sizeof *k_random_floats, random_refuses);
    CASE("nl_navmesh_random_points", "count 0 (allowed, out_points NULL)") {
        found = 77;
        EXPECT_OK(nl_navmesh_random_points(A.world, A.navmesh, &valid, NULL, 0, &found));
        EXPECT(found == 0, "out_found %u", (unsigned)found);
    }
    CASE("nl_navmesh_random_points", "count huge (out_points NULL)") {
        fill(&found, sizeof found);
        EXPECT_INVALID(A.world, nl_navmesh_random_points(A.world, A.navmesh, &valid, NULL, UINT32_MAX, &found), "out_points");
        EXPECT_UNTOUCHED(&found, sizeof found, "out_found");
    }
    CASE("nl_navmesh_random_points", "out_found NULL") {
        fill(points, sizeof points);
        EXPECT_INVALID(A.world, nl_navmesh_random_points(A.world, A.navmesh, &valid, points, 2, NULL), "out_found");
        EXPECT_UNTOUCHED(points, sizeof points, "out_points");
    }
}

/* ---------------------------------------------------------------------------------------------
 * Agents: A.agent walks across the gap (its path planned), A.flyer is on a link over it
 * ------------------------------------------------------------------------------------------- */

static const float k_agent_goal[3] = {8.0f, 0.0f, -1.0f}; /* on the far platform */
static const float k_agent_spot[3] = {-7.0f, 0.0f, 1.0f}; /* on the near platform */

/* An agent's info, read after the checks of a case (it records a status of its own). */
static nl_agent_info agent_info(nl_agent_id id) {
    nl_agent_info info = nl_agent_info_init();
    const nl_status status = nl_agent_get_info(A.world, id, &info);
    EXPECT(status == NL_STATUS_SUCCESS, "nl_agent_get_info: %s", nl_get_last_error_message());
    return info;
}

static int finite3(const float* p) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

/* The navmesh point nearest `p` on A's navmesh is within `within` metres of it. */
static int on_navmesh(nl_navmesh_id navmesh, const float* p, float within) {
    const float extents[3] = {within, within, within};
    nl_nav_point near;
    memset(&near, 0, sizeof near);
    return NL_SUCCEEDED(nl_navmesh_find_nearest(A.world, navmesh, p, 1, extents, &near)) && near.found;
}

/* nl_agent_add: the def's navmesh is its id. */
static const nl_agent_def* g_agent_def;
static nl_status agent_add_id_call(nl_world* w, raw_id id, void* out) {
    nl_agent_def def = *g_agent_def;
    def.navmesh = AS(nl_navmesh_id, id);
    return nl_agent_add(w, &def, (nl_agent_id*)out);
}
static nl_status agent_add_def_call(nl_world* world, const void* def, void* out) {
    return nl_agent_add(world, (const nl_agent_def*)def, (nl_agent_id*)out);
}
/* An added agent stands idle, valid; removed again, the world is as it was. */
static void remove_agent_out(const void* out) {
    nl_agent_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_agent_is_valid(A.world, id) == 1, "the new agent is not valid");
    EXPECT(agent_info(id).state == NL_AGENT_IDLE, "the new agent is not idle");
    EXPECT_OK(nl_agent_remove(A.world, id));
}
static const def_function k_agent_add = {"nl_agent_add", agent_add_def_call, sizeof(nl_agent_id), remove_agent_out, 0, 0, 1};

static const float_field k_agent_def_floats[] = {
    FLOAT_FIELD(nl_agent_def, height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_jump_distance, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_jump_height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_drop_height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.radius, 1),
    FLOAT_FIELD(nl_agent_def, max_speed, 1),
    FLOAT_FIELD(nl_agent_def, max_acceleration, 1),
    FLOAT_FIELD(nl_agent_def, gravity, 1),
    FLOAT_FIELD(nl_agent_def, takeoff_speed, 1),
    FLOAT_FIELD(nl_agent_def, position, 3),
    FLOAT_FIELD(nl_agent_def, give_up_seconds, 1),
};

#define SET_U8(type, member, v) {offsetof(type, member), sizeof(uint8_t), {.u32 = (v)}}
static const def_case k_agent_defs[] = {
    {"def->size small (8 short of the first release)", INVALID, "def->size",
     {SET_U32(nl_agent_def, size, (uint32_t)offsetof(nl_agent_def, give_up_seconds) - 8u)}},
    {"def->size of the first release (allowed: give_up_seconds its default)", ALLOWED, NULL,
     {SET_U32(nl_agent_def, size, (uint32_t)offsetof(nl_agent_def, give_up_seconds))}},
    {"def->size odd (sizeof + 1: no struct's size)", INVALID, "def->size", {SET_U32(nl_agent_def, size, (uint32_t)sizeof(nl_agent_def) + 1u)}},
    {"def->height 0", INVALID, "def->height", {SET_F32(nl_agent_def, height, 0.0f)}},
    {"def->height negative", INVALID, "def->height", {SET_F32(nl_agent_def, height, -2.0f)}},
    {"def->max_speed 0", INVALID, "def->max_speed", {SET_F32(nl_agent_def, max_speed, 0.0f)}},
    {"def->max_speed negative", INVALID, "def->max_speed", {SET_F32(nl_agent_def, max_speed, -3.5f)}},
    {"def->max_acceleration 0", INVALID, "def->max_acceleration", {SET_F32(nl_agent_def, max_acceleration, 0.0f)}},
    {"def->max_acceleration negative", INVALID, "def->max_acceleration", {SET_F32(nl_agent_def, max_acceleration, -8.0f)}},
    {"def->gravity 0", INVALID, "def->gravity", {SET_F32(nl_agent_def, gravity, 0.0f)}},
    {"def->gravity negative (upward)", INVALID, "def->gravity", {SET_F32(nl_agent_def, gravity, -9.81f)}},
    {"def->takeoff_speed negative", INVALID, "def->takeoff_speed", {SET_F32(nl_agent_def, takeoff_speed, -1.0f)}},
    {"def->give_up_seconds negative", INVALID, "def->give_up_seconds", {SET_F32(nl_agent_def, give_up_seconds, -1.0f)}},
    {"def->give_up_seconds 5 (allowed)", ALLOWED, NULL, {SET_F32(nl_agent_def, give_up_seconds, 5.0f)}},
    {"def->capabilities.max_jump_distance negative", INVALID, "def->capabilities.max_jump_distance",
     {SET_F32(nl_agent_def, capabilities.max_jump_distance, -1.0f)}},
    {"def->capabilities.max_jump_height negative", INVALID, "def->capabilities.max_jump_height",
     {SET_F32(nl_agent_def, capabilities.max_jump_height, -1.0f)}},
    {"def->capabilities.max_drop_height negative", INVALID, "def->capabilities.max_drop_height",
     {SET_F32(nl_agent_def, capabilities.max_drop_height, -1.0f)}},
    {"def->capabilities.radius negative", INVALID, "def->capabilities.radius", {SET_F32(nl_agent_def, capabilities.radius, -0.4f)}},
    {"def->position off the navmesh (10 m above)", NL_STATUS_NOT_FOUND, "def->position is not on the navmesh",
     {SET_F32(nl_agent_def, position[1], 10.0f)}},
    {"def->position off the navmesh (nothing within 25 m)", NL_STATUS_NOT_FOUND, "def->position is not on the navmesh",
     {SET_F32(nl_agent_def, position[0], 100.0f)}},
    {"def->position beyond the limit (2e9)", INVALID, "def->position", {SET_F32(nl_agent_def, position[2], 2.0e9f)}},
    {"def->position 1 m above the navmesh (allowed: put on it)", ALLOWED, NULL, {SET_F32(nl_agent_def, position[1], 1.0f)}},
    {"def->capabilities.radius 0 (allowed: a point body)", ALLOWED, NULL, {SET_F32(nl_agent_def, capabilities.radius, 0.0f)}},
    {"def->takeoff_speed 12 (allowed: a jump's time from it)", ALLOWED, NULL, {SET_F32(nl_agent_def, takeoff_speed, 12.0f)}},
    {"def->avoidance 0 (allowed)", ALLOWED, NULL, {SET_U8(nl_agent_def, avoidance, 0u)}},
};
#undef SET_U8

static void group_agent_add(void) {
    static const id_function f = {"nl_agent_add", "def->navmesh", "out_id", sizeof(nl_agent_id), 0, 0, agent_add_id_call, 0};
    const nl_agent_def valid = jumper_def(A.navmesh, -6.0f, -1.0f);
    g_agent_def = &valid;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    def_function_cases(&k_agent_add, &valid, sizeof valid);
    def_cases("nl_agent_add", &valid, sizeof valid, k_agent_defs, sizeof k_agent_defs / sizeof *k_agent_defs, def_refuses,
              def_accepts);
    bad_float_fields("nl_agent_add", "def", &valid, sizeof valid, k_agent_def_floats,
                     sizeof k_agent_def_floats / sizeof *k_agent_def_floats, def_refuses);
    CASE("nl_agent_add", "def->navmesh the lift's (allowed: an agent of another navmesh)") {
        nl_agent_def def = jumper_def(A.host_navmesh, 42.0f, 0.0f);
        nl_agent_id id;
        memset(&id, 0, sizeof id);
        EXPECT_OK(nl_agent_add(A.world, &def, &id));
        remove_agent_out(&id);
    }
}

/* The functions that take an agent id, with a valid rest (a point on the navmesh, capabilities). */
static const float* g_agent_point = k_agent_goal;
static nl_agent_capabilities g_agent_capabilities;
ID_CALL(agent_remove_call, nl_agent_id, nl_agent_remove)
ID_VALID_CALL(agent_is_valid_call, nl_agent_id, nl_agent_is_valid)
ID_CALL(agent_stop_call, nl_agent_id, nl_agent_stop)
static nl_status agent_set_destination_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_destination(w, AS(nl_agent_id, id), g_agent_point);
}
static nl_status agent_teleport_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_teleport(w, AS(nl_agent_id, id), g_agent_point);
}
static nl_status agent_set_capabilities_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_capabilities(w, AS(nl_agent_id, id), &g_agent_capabilities);
}
static nl_status agent_set_speed_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_speed(w, AS(nl_agent_id, id), 5.0f, 10.0f);
}
ID_OUT_CALL(agent_get_info_call, nl_agent_id, nl_agent_info, nl_agent_get_info)
ID_OUT_CALL(agent_get_trajectory_call, nl_agent_id, nl_agent_trajectory, nl_agent_get_trajectory)
/* Corners into 16 elements of the right size (only the id is wrong), the count untouched too. */
static nl_status agent_corners_id_call(nl_world* w, raw_id id, void* out) {
    uint32_t count;
    nl_status status;
    fill(&count, sizeof count);
    status = nl_agent_get_corners(w, AS(nl_agent_id, id), (nl_path_point*)out, 16u, &count);
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}
static const id_function k_agent_functions[] = {
    {"nl_agent_remove", "agent", NULL, 0, 0, 0, agent_remove_call, 0},
    {"nl_agent_is_valid", "agent", NULL, 0, 0, 1, agent_is_valid_call, 0},
    {"nl_agent_set_destination", "agent", NULL, 0, 0, 0, agent_set_destination_call, 0},
    {"nl_agent_stop", "agent", NULL, 0, 0, 0, agent_stop_call, 0},
    {"nl_agent_teleport", "agent", NULL, 0, 0, 0, agent_teleport_call, 0},
    {"nl_agent_set_capabilities", "agent", NULL, 0, 0, 0, agent_set_capabilities_call, 0},
    {"nl_agent_set_speed", "agent", NULL, 0, 0, 0, agent_set_speed_call, 0},
    {"nl_agent_get_info", "agent", "out_info", sizeof(nl_agent_info), 1, 0, agent_get_info_call, 0},
    {"nl_agent_get_corners", "agent", "out_points", sizeof(nl_path_point), 1, 0, agent_corners_id_call, 1},
    {"nl_agent_get_trajectory", "agent", "out_trajectory", sizeof(nl_agent_trajectory), 1, 0, agent_get_trajectory_call, 0},
};

/* An id of another kind passed as an agent's: refused as any bad id (an nl_agent_is_valid answers 0). */
static void wrong_kind_case(const id_function* f, const char* what, raw_id id) {
    CASE(f->function, "%s wrong kind (%s)%s", f->param, what, f->answers ? " (an answer, not an error)" : "") {
        aligned_buffer out;
        nl_status status;
        const size_t skip = f->growable ? sizeof(uint32_t) : 0u;
        fill(out.bytes, sizeof out.bytes);
        if (f->growable) set_size(out.bytes, (uint32_t)f->out_size);
        status = f->call(A.world, id, f->out_name ? out.bytes : NULL);
        if (f->answers) EXPECT_OK(status);
        else EXPECT_BAD_HANDLE(A.world, status, "agent");
        EXPECT_UNTOUCHED(out.bytes + skip, sizeof out.bytes - skip, f->out_name ? f->out_name : "memory");
    }
}

/* The id cases of an agent function: the world NULL, the output NULL, every bad id, and ids of the
   other kinds, A's navmesh id last: it sits in a slot of the same number and counter as A's agent,
   and only the kind each id carries tells them apart. */
static void agent_id_cases(size_t which) {
    const id_function* f = &k_agent_functions[which];
    g_agent_capabilities = jumper_def(A.navmesh, 0.0f, 0.0f).capabilities;
    g_agent_point = which == 4 ? k_agent_spot : k_agent_goal;
    id_cases(f, RAW(A.agent), RAW(A.stale_agent), RAW(B.agent));
    wrong_kind_case(f, "A's link id", RAW(A.link));
    wrong_kind_case(f, "A's plugin id", RAW(A.plugin));
    wrong_kind_case(f, "A's path ticket", RAW(A.pending_ticket));
    wrong_kind_case(f, "B's navmesh id", RAW(B.navmesh));
    wrong_kind_case(f, "A's navmesh id", RAW(A.navmesh));
}

static void group_agent_remove(void) { agent_id_cases(0); }
static void group_agent_is_valid(void) {
    CASE("nl_agent_is_valid", "agent live (1, the record SUCCESS)") {
        fail_on_purpose();
        EXPECT(nl_agent_is_valid(A.world, A.agent) == 1 && nl_agent_is_valid(A.world, A.flyer) == 1, "a live agent is not valid");
        EXPECT(nl_get_last_status() == NL_STATUS_SUCCESS, "the record is not SUCCESS");
    }
    agent_id_cases(1);
}
static void group_agent_stop(void) { agent_id_cases(3); }

/* nl_agent_set_destination and nl_agent_teleport: the point made bad; nothing changes (the
   fingerprint: a refused destination is not kept, a refused teleport moves nobody). */
typedef nl_status agent_point_fn(nl_world* world, nl_agent_id agent, const float* point);
static void agent_point_cases(const char* function, agent_point_fn* call, const float* valid) {
    size_t v;
    int k;
    CASE(function, "point NULL") { EXPECT_INVALID(A.world, call(A.world, A.agent, NULL), "point"); }
    CASE(function, "point NULL (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, call(A.world, A.stale_agent, NULL), "agent");
    }
    for (k = 0; k < 3; ++k) {
        for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
            CASE(function, "point[%d] %s", k, k_bad_floats[v].name) {
                float p[3];
                memcpy(p, valid, sizeof p);
                p[k] = k_bad_floats[v].value;
                EXPECT_INVALID(A.world, call(A.world, A.agent, p), "point");
            }
        }
    }
    CASE(function, "point[2] beyond the limit (2e9)") {
        float p[3];
        memcpy(p, valid, sizeof p);
        p[2] = 2.0e9f;
        EXPECT_INVALID(A.world, call(A.world, A.agent, p), "point");
    }
    CASE(function, "point off the navmesh (10 m above: NOT_FOUND, nothing kept)") {
        float p[3];
        memcpy(p, valid, sizeof p);
        p[1] = 10.0f;
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND, "point is not on the navmesh");
    }
    CASE(function, "point off the navmesh (over the gap, 20 m above the pit's floor)") {
        const float p[3] = {0.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND, "point is not on the navmesh");
    }
    CASE(function, "point off the navmesh (nothing within 25 m)") {
        const float p[3] = {200.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND, "point is not on the navmesh (nothing within 25 m)");
    }
}

static void group_agent_set_destination(void) {
    agent_point_cases("nl_agent_set_destination", nl_agent_set_destination, k_agent_goal);
    CASE("nl_agent_set_destination", "agent in the air (allowed: it lands first, then plans)") {
        nl_agent_info info;
        EXPECT_OK(nl_agent_set_destination(A.world, A.flyer, k_agent_goal));
        info = agent_info(A.flyer);
        EXPECT(in_the_air(info.state) && info.has_destination && fabsf(info.destination[0] - k_agent_goal[0]) < 0.5f,
               "state %u, has_destination %u", (unsigned)info.state, (unsigned)info.has_destination);
        fixture_refresh();
    }
    agent_id_cases(2);
}

static void group_agent_teleport(void) {
    agent_point_cases("nl_agent_teleport", nl_agent_teleport, k_agent_spot);
    CASE("nl_agent_teleport", "agent in the air (taking a link: refused, nothing changed)") {
        EXPECT_INVALID(A.world, nl_agent_teleport(A.world, A.flyer, k_agent_spot), "taking a link");
    }
    CASE("nl_agent_teleport", "agent in the air, point off the navmesh (NOT_FOUND)") {
        const float p[3] = {200.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, nl_agent_teleport(A.world, A.flyer, p), NL_STATUS_NOT_FOUND, "not on the navmesh");
    }
    agent_id_cases(4);
}

/* nl_agent_set_capabilities: each figure NaN, infinite, negative; refused with nothing changed. */
static const float_field k_capability_floats[] = {
    FLOAT_FIELD(nl_agent_capabilities, max_jump_distance, 1),
    FLOAT_FIELD(nl_agent_capabilities, max_jump_height, 1),
    FLOAT_FIELD(nl_agent_capabilities, max_drop_height, 1),
    FLOAT_FIELD(nl_agent_capabilities, radius, 1),
};
static const def_case k_capability_defs[] = {
    {"capabilities->max_jump_distance negative", INVALID, "max_jump_distance", {SET_F32(nl_agent_capabilities, max_jump_distance, -1.0f)}},
    {"capabilities->max_jump_height negative", INVALID, "max_jump_height", {SET_F32(nl_agent_capabilities, max_jump_height, -1.0f)}},
    {"capabilities->max_drop_height negative", INVALID, "max_drop_height", {SET_F32(nl_agent_capabilities, max_drop_height, -1.0f)}},
    {"capabilities->radius negative", INVALID, "radius", {SET_F32(nl_agent_capabilities, radius, -0.4f)}},
    {"capabilities->radius -0 (allowed: 0)", ALLOWED, NULL, {SET_F32(nl_agent_capabilities, radius, -0.0f)}},
    {"capabilities->max_jump_distance 0 (allowed: no jumps, it plans again)", ALLOWED, NULL,
     {SET_F32(nl_agent_capabilities, max_jump_distance, 0.0f)}},
};
static void capabilities_refused(const void* capabilities, nl_status detail, const char* needle) {
    EXPECT_FAILURE(A.world, nl_agent_set_capabilities(A.world, A.agent, (const nl_agent_capabilities*)capabilities), detail, needle);
}
/* Accepted: the agent keeps walking (it plans again); the worlds as they are now are the reference. */
static void capabilities_accepted(const void* capabilities) {
    nl_agent_info info;
    EXPECT_OK(nl_agent_set_capabilities(A.world, A.agent, (const nl_agent_capabilities*)capabilities));
    info = agent_info(A.agent);
    EXPECT(info.state == NL_AGENT_WALKING && info.has_destination, "state %u", (unsigned)info.state);
    fixture_refresh();
}

static void group_agent_set_capabilities(void) {
    const nl_agent_capabilities valid = jumper_def(A.navmesh, 0.0f, 0.0f).capabilities;
    CASE("nl_agent_set_capabilities", "capabilities NULL") {
        EXPECT_INVALID(A.world, nl_agent_set_capabilities(A.world, A.agent, NULL), "capabilities");
    }
    CASE("nl_agent_set_capabilities", "capabilities NULL (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_capabilities(A.world, A.stale_agent, NULL), "agent");
    }
    bad_float_fields("nl_agent_set_capabilities", "capabilities", &valid, sizeof valid, k_capability_floats,
                     sizeof k_capability_floats / sizeof *k_capability_floats, capabilities_refused);
    def_cases("nl_agent_set_capabilities", &valid, sizeof valid, k_capability_defs,
              sizeof k_capability_defs / sizeof *k_capability_defs, capabilities_refused, capabilities_accepted);
    agent_id_cases(5);
}

/* nl_agent_set_speed: each figure NaN, infinite, 0 and negative; refused with nothing changed. */
static void group_agent_set_speed(void) {
    static const struct {
        const char* what;
        float value;
    } bad[] = {{"NaN", NAN}, {"inf", INFINITY}, {"-inf", -INFINITY}, {"0", 0.0f}, {"-0", -0.0f}, {"negative", -1.0f}};
    size_t v;
    int k;
    for (k = 0; k < 2; ++k) {
        for (v = 0; v < sizeof bad / sizeof *bad; ++v) {
            const char* name = k == 0 ? "max_speed" : "max_acceleration";
            CASE("nl_agent_set_speed", "%s %s", name, bad[v].what) {
                const float speed = k == 0 ? bad[v].value : 5.0f, acceleration = k == 1 ? bad[v].value : 10.0f;
                EXPECT_INVALID(A.world, nl_agent_set_speed(A.world, A.agent, speed, acceleration), name);
            }
        }
    }
    CASE("nl_agent_set_speed", "max_speed NaN (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_speed(A.world, A.stale_agent, NAN, 10.0f), "agent");
    }
    agent_id_cases(6);
}

/* Every agent of A: its state finite, standing on its navmesh or on its link's trajectory. */
static void expect_agents_sane(const char* when) {
    nl_agent_info infos[8];
    uint32_t n = 0, i;
    memset(infos, 0, sizeof infos);
    infos[0].size = sizeof infos[0];
    EXPECT(NL_SUCCEEDED(nl_world_get_agents(A.world, infos, 8, &n)), "nl_world_get_agents: %s", nl_get_last_error_message());
    for (i = 0; i < n && i < 8; ++i) {
        const nl_agent_info* a = &infos[i];
        EXPECT(finite3(a->position) && finite3(a->velocity) && isfinite(a->link_progress),
               "%s: agent %u at (%g, %g, %g), velocity (%g, %g, %g)", when, (unsigned)i, a->position[0], a->position[1],
               a->position[2], a->velocity[0], a->velocity[1], a->velocity[2]);
        EXPECT(a->state <= NL_AGENT_FAILED, "%s: agent %u in state %u", when, (unsigned)i, (unsigned)a->state);
        if (!in_the_air(a->state))
            EXPECT(on_navmesh(A.navmesh, a->position, 0.5f), "%s: agent %u at (%g, %g, %g) is off its navmesh", when, (unsigned)i,
                   a->position[0], a->position[1], a->position[2]);
    }
}

static void group_world_step(void) {
    static const struct {
        const char* what;
        float dt;
    } bad[] = {{"dt NaN", NAN},
               {"dt inf", INFINITY},
               {"dt -inf", -INFINITY},
               {"dt negative (-0.1)", -0.1f},
               {"dt negative (-FLT_TRUE_MIN: barely)", -FLT_TRUE_MIN},
               {"dt negative (-FLT_MAX)", -FLT_MAX}};
    size_t i;
    CASE("nl_world_step", "world NULL") { EXPECT_INVALID(NULL, nl_world_step(NULL, 0.1f), "world"); }
    for (i = 0; i < sizeof bad / sizeof *bad; ++i) {
        CASE("nl_world_step", "%s (refused: nobody moves, the last step's events stay)", bad[i].what) {
            EXPECT_INVALID(A.world, nl_world_step(A.world, bad[i].dt), "dt");
        }
    }
    CASE("nl_world_step", "dt 0 (allowed: nothing changes, the last step's events stay)") { EXPECT_OK(nl_world_step(A.world, 0.0f)); }
    CASE("nl_world_step", "dt -0 (allowed: 0)") { EXPECT_OK(nl_world_step(A.world, -0.0f)); }
    CASE("nl_world_step", "dt FLT_TRUE_MIN (allowed: a step too short to move)") {
        EXPECT_OK(nl_world_step(A.world, FLT_TRUE_MIN));
        expect_agents_sane("after a denormal step");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (1e6 s: allowed; every agent finite, on its navmesh)") {
        EXPECT_OK(nl_world_step(A.world, 1.0e6f));
        expect_agents_sane("after 1e6 s");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (FLT_MAX: allowed; every agent finite, on its navmesh)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_agent_id walker;
        memset(&walker, 0, sizeof walker);
        EXPECT_OK(nl_agent_add(A.world, &def, &walker));
        EXPECT_OK(nl_agent_set_destination(A.world, walker, k_agent_goal));
        EXPECT_OK(nl_world_step(A.world, 0.001f)); /* its path */
        EXPECT_OK(nl_world_step(A.world, FLT_MAX));
        expect_agents_sane("after FLT_MAX s");
        EXPECT_OK(nl_world_step(A.world, FLT_MAX));
        expect_agents_sane("after twice FLT_MAX s");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (1 s) with max_speed and max_acceleration FLT_MAX (allowed; every agent finite)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_agent_id runner;
        memset(&runner, 0, sizeof runner);
        EXPECT_OK(nl_agent_add(A.world, &def, &runner));
        EXPECT_OK(nl_agent_set_speed(A.world, runner, FLT_MAX, FLT_MAX));
        EXPECT_OK(nl_agent_set_destination(A.world, runner, k_agent_goal));
        EXPECT_OK(nl_world_step(A.world, 1.0f));
        expect_agents_sane("after 1 s at FLT_MAX m/s");
        EXPECT_OK(nl_world_step(A.world, 1.0f));
        expect_agents_sane("after 2 s at FLT_MAX m/s");
        fixture_refresh();
    }
}

static nl_status agent_info_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_agent_get_info(A.world, A.agent, (nl_agent_info*)out);
}

static void group_agent_get_info(void) {
    CASE("nl_agent_get_info", "agent live (allowed: its id, state, user_data)") {
        nl_agent_info info;
        fill(&info, sizeof info);
        info.size = sizeof info;
        EXPECT_OK(nl_agent_get_info(A.world, A.agent, &info));
        EXPECT(info.size == sizeof info && info.id.index1 == A.agent.index1 && info.id.generation == A.agent.generation &&
                   info.state == NL_AGENT_WALKING && info.user_data == 7u && info.has_destination == 1u &&
                   info.corners_ahead > 0u && finite3(info.position),
               "size %u, state %u, user_data %llu", (unsigned)info.size, (unsigned)info.state, (unsigned long long)info.user_data);
    }
    agent_id_cases(7);
    out_element_sizes("nl_agent_get_info", "out_info", sizeof(nl_agent_info), agent_info_into);
}

static nl_status get_agents(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_agents(w, (nl_agent_info*)out, capacity, count);
}
static nl_status agents_into(void* out, uint32_t* written) { return nl_world_get_agents(A.world, (nl_agent_info*)out, 256u, written); }

static void group_world_get_agents(void) {
    g_growable_items = 1;
    world_list_cases("nl_world_get_agents", "out_infos", sizeof(nl_agent_info), 2u, get_agents);
    g_growable_items = 0;
    out_element_sizes("nl_world_get_agents", "out_infos", sizeof(nl_agent_info), agents_into);
}

static uint32_t corner_count(nl_agent_id agent) {
    uint32_t n = 0;
    if (NL_FAILED(nl_agent_get_corners(A.world, agent, NULL, 0, &n))) fixture_failed("nl_agent_get_corners");
    return n;
}
static nl_status call_corners(void* out, uint32_t capacity, uint32_t* count) {
    return nl_agent_get_corners(A.world, A.agent, (nl_path_point*)out, capacity, count);
}
static nl_status corners_into(void* out, uint32_t* written) {
    return nl_agent_get_corners(A.world, A.agent, (nl_path_point*)out, 256u, written);
}

static void group_agent_get_corners(void) {
    const uint32_t corners = corner_count(A.agent);
    if (corners == 0u) fixture_failed("the walker has no corners ahead");
    agent_id_cases(8);
    g_growable_items = 1;
    list_cases("nl_agent_get_corners", "out_points", sizeof(nl_path_point), corners, call_corners);
    g_growable_items = 0;
    out_element_sizes("nl_agent_get_corners", "out_points", sizeof(nl_path_point), corners_into);
    CASE("nl_agent_get_corners", "agent idle (allowed: no path, 0 corners, nothing written)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_path_point points[4];
        nl_agent_id idle;
        uint32_t count = 0xdeadbeefu;
        memset(&idle, 0, sizeof idle);
        fill(points, sizeof points);
        points[0].size = sizeof points[0];
        EXPECT_OK(nl_agent_add(A.world, &def, &idle));
        EXPECT_OK(nl_agent_get_corners(A.world, idle, points, 4, &count));
        EXPECT(count == 0u, "out_count = %u", (unsigned)count);
        EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
        EXPECT_OK(nl_agent_remove(A.world, idle));
    }
}

static nl_status trajectory_into(void* out) { return nl_agent_get_trajectory(A.world, A.flyer, (nl_agent_trajectory*)out); }

static void group_agent_get_trajectory(void) {
    CASE("nl_agent_get_trajectory", "agent on the ground (allowed: kind NONE, the rest zero)") {
        nl_agent_trajectory t, zero;
        fill(&t, sizeof t);
        t.size = sizeof t;
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.agent, &t));
        memset(&zero, 0, sizeof zero);
        zero.size = sizeof zero;
        EXPECT(memcmp(&t, &zero, sizeof t) == 0, "kind %u, duration %g: not all zero", (unsigned)t.kind, t.duration);
    }
    CASE("nl_agent_get_trajectory", "agent in the air (allowed: its link's trajectory)") {
        nl_agent_trajectory t;
        const nl_agent_info info = agent_info(A.flyer);
        fill(&t, sizeof t);
        t.size = sizeof t;
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.flyer, &t));
        EXPECT(t.kind == NL_TRAJECTORY_ARC || t.kind == NL_TRAJECTORY_FALL || t.kind == NL_TRAJECTORY_LINE, "kind %u", (unsigned)t.kind);
        EXPECT(t.link.index1 == info.link.index1 && t.link.generation == info.link.generation && t.link.index1 != 0u,
               "the trajectory's link is not the agent's");
        EXPECT(isfinite(t.duration) && t.duration > 0.0f && t.elapsed >= 0.0f && t.elapsed <= t.duration && finite3(t.from) &&
                   finite3(t.to) && finite3(t.apex),
               "duration %g, elapsed %g", t.duration, t.elapsed);
    }
    CASE("nl_agent_get_trajectory", "out_trajectory->size 0 (agent on the ground: refused all the same)") {
        nl_agent_trajectory t;
        fill(&t, sizeof t);
        t.size = 0;
        EXPECT_INVALID(A.world, nl_agent_get_trajectory(A.world, A.agent, &t), "out_trajectory->size");
        EXPECT_UNTOUCHED_AFTER_SIZE(&t, sizeof t, "out_trajectory");
    }
    agent_id_cases(9);
    out_sizes("nl_agent_get_trajectory", "out_trajectory", sizeof(nl_agent_trajectory), trajectory_into);
}

static nl_status get_agent_events(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_agent_events(w, (nl_agent_event*)out, capacity, count);
}
static nl_status agent_events_into(void* out, uint32_t* written) {
    return nl_world_get_agent_events(A.world, (nl_agent_event*)out, 256u, written);
}

static void group_world_get_agent_events(void) {
    g_growable_items = 1;
    world_list_cases("nl_world_get_agent_events", "out_events", sizeof(nl_agent_event), A.agent_events, get_agent_events);
    g_growable_items = 0;
    out_element_sizes("nl_world_get_agent_events", "out_events", sizeof(nl_agent_event), agent_events_into);
}

/* An agent whose navmesh is removed: at the next step it fails, with one FAILED event
   (NAVMESH_REMOVED); the calls that need its navmesh say so, the others answer; nothing crashes. */
static int failed_events_of(nl_agent_id agent) {
    nl_agent_event events[16];
    uint32_t n = 0, i;
    int failed = 0;
    memset(events, 0, sizeof events);
    events[0].size = sizeof events[0];
    EXPECT(NL_SUCCEEDED(nl_world_get_agent_events(A.world, events, 16, &n)), "nl_world_get_agent_events: %s",
           nl_get_last_error_message());
    for (i = 0; i < n && i < 16; ++i) {
        if (events[i].agent.index1 != agent.index1 || events[i].agent.generation != agent.generation) continue;
        EXPECT(events[i].kind == NL_AGENT_EVENT_FAILED && events[i].reason == NL_AGENT_REASON_NAVMESH_REMOVED &&
                   events[i].user_data == 7u,
               "event kind %u, reason %u", (unsigned)events[i].kind, (unsigned)events[i].reason);
        ++failed;
    }
    return failed;
}

static void expect_failed_for_navmesh(nl_agent_id agent) {
    const nl_agent_info info = agent_info(agent);
    EXPECT(info.state == NL_AGENT_FAILED && info.reason == NL_AGENT_REASON_NAVMESH_REMOVED && finite3(info.position) &&
               info.velocity[0] == 0.0f && info.velocity[1] == 0.0f && info.velocity[2] == 0.0f,
           "state %u, reason %u", (unsigned)info.state, (unsigned)info.reason);
}

static void group_agent_navmesh_removed(void) {
    const nl_navmesh_def quad = quad_navmesh_def();
    static const float lift_goal[3] = {43.5f, 0.0f, 1.5f};
    const nl_agent_def def = jumper_def(A.host_navmesh, 40.5f, -1.5f);
    nl_navmesh_id doomed;
    nl_agent_id lost;
    memset(&doomed, 0, sizeof doomed);
    memset(&lost, 0, sizeof lost);
    CASE("nl_world_step", "agent's navmesh removed (allowed: it fails, with one FAILED event; the others go on)") {
        nl_agent_def on_doomed = def;
        EXPECT_OK(nl_navmesh_add(A.world, &quad, &doomed));
        on_doomed.navmesh = doomed;
        EXPECT_OK(nl_agent_add(A.world, &on_doomed, &lost));
        EXPECT_OK(nl_agent_set_destination(A.world, lost, lift_goal));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        EXPECT(agent_info(lost).state == NL_AGENT_WALKING, "the agent on the doomed navmesh does not walk");
        EXPECT_OK(nl_navmesh_remove(A.world, doomed));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(lost);
        EXPECT(failed_events_of(lost) == 1, "not one FAILED event");
        EXPECT(agent_info(A.agent).state != NL_AGENT_FAILED && in_the_air(agent_info(A.flyer).state), "the others stopped");
        fixture_refresh();
    }
    CASE("nl_agent_set_destination", "agent's navmesh removed (INVALID_HANDLE naming it, nothing changed)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_destination(A.world, lost, lift_goal), "agent's navmesh");
    }
    CASE("nl_agent_teleport", "agent's navmesh removed (INVALID_HANDLE naming it, nothing changed)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_teleport(A.world, lost, lift_goal), "agent's navmesh");
    }
    CASE("nl_agent_get_info", "agent's navmesh removed (allowed: FAILED, NAVMESH_REMOVED)") { expect_failed_for_navmesh(lost); }
    CASE("nl_agent_get_corners", "agent's navmesh removed (allowed: no corners)") {
        uint32_t count = 0xdeadbeefu;
        EXPECT_OK(nl_agent_get_corners(A.world, lost, NULL, 0, &count));
        EXPECT(count == 0u, "out_count = %u", (unsigned)count);
    }
    CASE("nl_agent_get_trajectory", "agent's navmesh removed (allowed: kind NONE)") {
        nl_agent_trajectory t = nl_agent_trajectory_init();
        EXPECT_OK(nl_agent_get_trajectory(A.world, lost, &t));
        EXPECT(t.kind == NL_TRAJECTORY_NONE, "kind %u", (unsigned)t.kind);
    }
    CASE("nl_agent_set_speed", "agent's navmesh removed (allowed: it stays FAILED)") {
        EXPECT_OK(nl_agent_set_speed(A.world, lost, 2.0f, 4.0f));
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_set_capabilities", "agent's navmesh removed (allowed: it stays FAILED)") {
        const nl_agent_capabilities c = nl_default_agent_capabilities();
        EXPECT_OK(nl_agent_set_capabilities(A.world, lost, &c));
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_stop", "agent's navmesh removed (allowed: it stays FAILED, no second event)") {
        EXPECT_OK(nl_agent_stop(A.world, lost));
        expect_failed_for_navmesh(lost);
        EXPECT(agent_info(lost).has_destination == 0u, "the destination is kept");
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(lost);
        EXPECT(failed_events_of(lost) == 0, "a second FAILED event");
        fixture_refresh();
    }
    CASE("nl_world_step", "agent's navmesh removed, stepped again (allowed: no second event)") {
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        EXPECT(failed_events_of(lost) == 0, "a second FAILED event");
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_remove", "agent's navmesh removed (allowed: removed, then stale)") {
        EXPECT_OK(nl_agent_remove(A.world, lost));
        EXPECT(nl_agent_is_valid(A.world, lost) == 0, "still valid");
        EXPECT_BAD_HANDLE(A.world, nl_agent_remove(A.world, lost), "agent");
        fixture_refresh();
    }
    CASE("nl_world_step", "agent in the air, its navmesh removed (allowed: it fails at once, off the link)") {
        nl_agent_trajectory t = nl_agent_trajectory_init();
        EXPECT_OK(nl_navmesh_remove(A.world, A.navmesh));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(A.flyer);
        expect_failed_for_navmesh(A.agent);
        EXPECT(failed_events_of(A.flyer) == 1 && failed_events_of(A.agent) == 1, "not one FAILED event each");
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.flyer, &t));
        EXPECT(t.kind == NL_TRAJECTORY_NONE, "kind %u", (unsigned)t.kind);
        fixture_refresh();
    }
}

/* ---------------------------------------------------------------------------------------------
 * Plugins
 * ------------------------------------------------------------------------------------------- */

static const char* g_library_path; /* libnavlink.so: a library without nl_plugin_entry */
static const char* g_plugin_path;  /* the climb plugin, when built */

static nl_status load_plugin_at(const char* path, void* out) { return nl_plugin_load(A.world, path, (nl_plugin_id*)out); }

static void group_plugin_load(void) {
    static const char* made[] = {"not-a-library.so"};
    static const bad_path not_a_library = {"path not a library (a text file)", "not-a-library.so", NULL, NL_STATUS_IO_ERROR,
                                           "not-a-library.so"};
    char path[160];
    make_tmp();
    snprintf(path, sizeof path, "%s/not-a-library.so", g_tmp);
    write_file(path, "not an ELF file\n");
    CASE("nl_plugin_load", "world NULL") {
        nl_plugin_id out;
        fill(&out, sizeof out);
        EXPECT_INVALID(NULL, nl_plugin_load(NULL, path, &out), "world");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    CASE("nl_plugin_load", "out_id NULL") { EXPECT_INVALID(A.world, nl_plugin_load(A.world, path, NULL), "out_id"); }
    bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), k_bad_paths, BAD_PATH_COUNT);
    bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), &not_a_library, 1);
    if (g_library_path) {
        const bad_path no_entry = {"path a library without nl_plugin_entry (libnavlink.so)", NULL, g_library_path,
                                   NL_STATUS_NOT_FOUND, NL_PLUGIN_ENTRY_SYMBOL};
        bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), &no_entry, 1);
    }
    if (g_plugin_path) {
        CASE("nl_plugin_load", "path loaded twice (the name is taken)") {
            nl_plugin_id first = {0u, 0u};
            const bad_path twice = {"", NULL, g_plugin_path, NL_STATUS_INVALID_ARGUMENT, "already loaded"};
            EXPECT_OK(nl_plugin_load(A.world, g_plugin_path, &first));
            fixture_refresh();
            EXPECT_FAILURE(A.world, load_plugin_at(twice.path, &first), twice.detail, twice.needle);
        }
    }
    remove_tmp(made, 1);
}

/* Entry functions that refuse, or describe themselves wrongly: nothing is registered. */
static nl_status entry_refuses(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)info;
    host->set_error(host->context, "this plugin always refuses");
    return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
}
static nl_status entry_newer(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)host;
    (void)info;
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}
static nl_status build_nothing(void* state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                               nl_navmesh_sink_fn* sink, void* context) {
    (void)state;
    (void)host;
    (void)def;
    (void)sink;
    (void)context;
    return NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
}

/* A description made wrong field by field (from a builder named "hostile"). */
typedef struct wrong_plugin {
    const char* what;
    nl_status detail;
    const char* needle;
    const char* name;
    uint32_t abi_version;
    uint32_t kinds;
    int no_build;
} wrong_plugin;
static const wrong_plugin k_wrong_plugins[] = {
    {"entry describes no name", NL_STATUS_INVALID_ARGUMENT, "name", NULL, NL_PLUGIN_ABI_VERSION, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes an empty name", NL_STATUS_INVALID_ARGUMENT, "name", "", NL_PLUGIN_ABI_VERSION, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes the name of the built-in builder", NL_STATUS_INVALID_ARGUMENT, "recast", "recast", NL_PLUGIN_ABI_VERSION,
     NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes ABI version 0", NL_STATUS_VERSION_MISMATCH, "version", "hostile", 0u, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes an ABI version newer than the host's", NL_STATUS_VERSION_MISMATCH, "version", "hostile",
     NL_PLUGIN_ABI_VERSION + 1u, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes a builder without a build function", NL_STATUS_INVALID_ARGUMENT, "build", "hostile",
     NL_PLUGIN_ABI_VERSION, NL_PLUGIN_NAVMESH_BUILDER, 1},
    {"entry describes unknown kinds", NL_STATUS_INVALID_ARGUMENT, "kinds", "hostile", NL_PLUGIN_ABI_VERSION, 0x80u, 0},
    {"entry describes a link kind without a generate function", NL_STATUS_INVALID_ARGUMENT, "link kind", "hostile",
     NL_PLUGIN_ABI_VERSION, NL_PLUGIN_LINK_KIND, 0},
};
static const wrong_plugin* g_wrong;
static nl_status entry_wrong(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)host;
    info->abi_version = g_wrong->abi_version;
    info->name = g_wrong->name;
    info->kinds = g_wrong->kinds;
    info->navmesh_builder.build = g_wrong->no_build ? NULL : build_nothing;
    return NL_STATUS_SUCCESS;
}

static void plugin_register_fails_with(nl_plugin_entry_fn* entry, nl_status detail, const char* needle) {
    nl_plugin_id out;
    fill(&out, sizeof out);
    EXPECT_FAILURE(A.world, nl_plugin_register(A.world, entry, &out), detail, needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
}

static void group_plugin_register(void) {
    size_t i;
    g_wrong = &k_wrong_plugins[0];
    CASE("nl_plugin_register", "world NULL") {
        nl_plugin_id out;
        fill(&out, sizeof out);
        EXPECT_INVALID(NULL, nl_plugin_register(NULL, entry_refuses, &out), "world");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    CASE("nl_plugin_register", "entry NULL") { plugin_register_fails_with(NULL, NL_STATUS_INVALID_ARGUMENT, "entry"); }
    CASE("nl_plugin_register", "out_id NULL") { EXPECT_INVALID(A.world, nl_plugin_register(A.world, entry_refuses, NULL), "out_id"); }
    CASE("nl_plugin_register", "entry refuses (with a reason)") {
        plugin_register_fails_with(entry_refuses, NL_STATUS_INTERNAL_ERROR, "this plugin always refuses");
    }
    CASE("nl_plugin_register", "entry speaks no common version") {
        plugin_register_fails_with(entry_newer, NL_STATUS_VERSION_MISMATCH, "version");
    }
    for (i = 0; i < sizeof k_wrong_plugins / sizeof *k_wrong_plugins; ++i) {
        CASE("nl_plugin_register", "%s", k_wrong_plugins[i].what) {
            g_wrong = &k_wrong_plugins[i];
            plugin_register_fails_with(entry_wrong, k_wrong_plugins[i].detail, k_wrong_plugins[i].needle);
        }
    }
}

static nl_status description_into(void* out) { return description_call(A.world, RAW(A.plugin), out); }

static void group_plugin_get_description(void) {
    static const id_function f = {"nl_plugin_get_description", "plugin", "out_description", sizeof(nl_plugin_description), 1, 0,
                                  description_call, 0};
    id_cases(&f, RAW(A.plugin), (raw_id){0u, 0u}, RAW(B.plugin));
    out_sizes("nl_plugin_get_description", "out_description", sizeof(nl_plugin_description), description_into);
}

static void group_world_get_plugins(void) {
    world_list_cases("nl_world_get_plugins", "out_ids", sizeof(nl_plugin_id), 1u, get_plugins);
}

/* ---------------------------------------------------------------------------------------------
 * The table of groups, what does not apply, the known failures, and main
 * ------------------------------------------------------------------------------------------- */

static const hostile_group k_groups[] = {
    {"version", group_version},
    {"status_string", group_status_string},
    {"last_error", group_last_error},
    {"defaults", group_defaults},
    {"world_create", group_world_create},
    {"world_destroy", group_world_destroy},
    {"world_get_worker_count", group_world_get_worker_count},
    {"mesh_add", group_mesh_add},
    {"mesh_add_obj_file", group_mesh_add_obj_file},
    {"mesh_add_obj_memory", group_mesh_add_obj_memory},
    {"mesh_remove", group_mesh_remove},
    {"mesh_set_transform", group_mesh_set_transform},
    {"mesh_is_valid", group_mesh_is_valid},
    {"mesh_get_info", group_mesh_get_info},
    {"world_get_meshes", group_world_get_meshes},
    {"world_cast_rays", group_world_cast_rays},
    {"world_segments_blocked", group_world_segments_blocked},
    {"navmesh_add", group_navmesh_add},
    {"navmesh_remove", group_navmesh_remove},
    {"navmesh_is_valid", group_navmesh_is_valid},
    {"navmesh_get_info", group_navmesh_get_info},
    {"navmesh_get_vertices", group_navmesh_get_vertices},
    {"navmesh_get_polygon", group_navmesh_get_polygon},
    {"navmesh_get_boundary_edges", group_navmesh_get_boundary_edges},
    {"navmesh_find_nearest", group_navmesh_find_nearest},
    {"world_get_navmeshes", group_world_get_navmeshes},
    {"navmesh_build", group_navmesh_build},
    {"link_add", group_link_add},
    {"link_update", group_link_update},
    {"link_remove", group_link_remove},
    {"link_is_valid", group_link_is_valid},
    {"link_get", group_link_get},
    {"navmesh_get_links", group_navmesh_get_links},
    {"navmesh_remove_generated_links", group_navmesh_remove_generated_links},
    {"link_settings_from_json", group_link_settings_from_json},
    {"navmesh_generate_links", group_navmesh_generate_links},
    {"navmesh_generate_cross_links", group_navmesh_generate_cross_links},
    {"navmesh_update_links_in_box", group_navmesh_update_links_in_box},
    {"navmesh_save_links_json", group_navmesh_save_links_json},
    {"navmesh_load_links_json", group_navmesh_load_links_json},
    {"navmesh_save", group_navmesh_save},
    {"navmesh_save_file", group_navmesh_save_file},
    {"navmesh_load", group_navmesh_load},
    {"navmesh_load_file", group_navmesh_load_file},
    {"navmesh_file_describe", group_navmesh_file_describe},
    {"path_find", group_path_find},
    {"path_explain", group_path_explain},
    {"path_request", group_path_request},
    {"path_poll", group_path_poll},
    {"path_get_result", group_path_get_result},
    {"path_cancel", group_path_cancel},
    {"path_release", group_path_release},
    {"path_wait", group_path_wait},
    {"path_process", group_path_process},
    {"path_take_finished", group_path_take_finished},
    {"path_get_queue_stats", group_path_get_queue_stats},
    {"default_query_filter", group_default_query_filter},
    {"navmesh_can_reach", group_navmesh_can_reach},
    {"navmesh_get_reachable_polygons", group_navmesh_get_reachable_polygons},
    {"navmesh_get_islands", group_navmesh_get_islands},
    {"navmesh_raycast", group_navmesh_raycast},
    {"navmesh_move_along_surface", group_navmesh_move_along_surface},
    {"default_random_points_def", group_default_random_points_def},
    {"navmesh_random_points", group_navmesh_random_points},
    {"agent_add", group_agent_add},
    {"agent_remove", group_agent_remove},
    {"agent_is_valid", group_agent_is_valid},
    {"agent_set_destination", group_agent_set_destination},
    {"agent_stop", group_agent_stop},
    {"agent_teleport", group_agent_teleport},
    {"agent_set_capabilities", group_agent_set_capabilities},
    {"agent_set_speed", group_agent_set_speed},
    {"world_step", group_world_step},
    {"agent_get_info", group_agent_get_info},
    {"world_get_agents", group_world_get_agents},
    {"agent_get_corners", group_agent_get_corners},
    {"agent_get_trajectory", group_agent_get_trajectory},
    {"world_get_agent_events", group_world_get_agent_events},
    {"agent_navmesh_removed", group_agent_navmesh_removed},
    {"plugin_load", group_plugin_load},
    {"plugin_register", group_plugin_register},
    {"plugin_get_description", group_plugin_get_description},
    {"world_get_plugins", group_world_get_plugins},
};

static const coverage_exemption k_exemptions[] = {
    {"nl_plugin_get_description", "plugin", "stale", "plugins stay loaded until the world is destroyed: no plugin id goes stale"},
};

/* Defects whose fix belongs in the core (sdk/) or a plugin, not in the C mapping layer. An entry is
   {function, case, why}. (The JSON readers' number overflow, listed here before, is fixed.)
   Ids of every kind count their slots alike in a world (sdk/util/handle.h: the generation holds the
   world's tag and the slot's counter, nothing of the kind), so an id of another kind whose slot and
   counter are a live agent's is that agent: A's navmesh id is A's walker. The C types keep the kinds
   apart; a binding that stores ids as plain integers does not. A kind in the generation is a change
   of the handle layout for every kind. */
const known_failure k_known_failures[1] = {{NULL, NULL, NULL}};
const size_t k_known_failure_count = 0;

int main(int argc, char** argv) {
    const char* header_dirs[8];
    size_t dir_count = 0, case_count = 0, g, selected_count = 0;
    const char* only = NULL;
    case_record* cases = NULL;
    hostile_group selected[sizeof k_groups / sizeof *k_groups];
    const hostile_fixture fixture = {setup_worlds, worlds_unchanged, refresh_worlds, teardown_worlds};
    int failed, gaps = 0, i, mode = 0;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--headers") == 0) mode = 1;
        else if (strcmp(argv[i], "--library") == 0 && i + 1 < argc) g_library_path = argv[++i];
        else if (strcmp(argv[i], "--plugin") == 0 && i + 1 < argc) g_plugin_path = argv[++i];
        else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) only = argv[++i];
        else if (mode == 1 && dir_count < sizeof header_dirs / sizeof *header_dirs) header_dirs[dir_count++] = argv[i];
        else {
            fprintf(stderr, "usage: %s --headers DIR... [--library LIBNAVLINK] [--plugin PLUGIN] [--only GROUP]\n", argv[0]);
            return 2;
        }
    }
    for (g = 0; g < sizeof k_groups / sizeof *k_groups; ++g)
        if (!only || strcmp(only, k_groups[g].name) == 0) selected[selected_count++] = k_groups[g];
    failed = run_groups(selected, selected_count, &fixture, &cases, &case_count);
    if (only) {
        printf("coverage: not checked (--only %s)\n", only);
    } else if (dir_count == 0) {
        printf("coverage: FAILED: no --headers given, so no check that every function has its cases\n");
        gaps = 1;
    } else {
        gaps = check_coverage(header_dirs, dir_count, cases, case_count, k_exemptions, sizeof k_exemptions / sizeof *k_exemptions);
    }
    free(cases);
    printf("%s\n", failed == 0 && gaps == 0 ? "PASSED" : "FAILED");
    return failed == 0 && gaps == 0 ? 0 : 1;
}
