/*
 * Paths (navlink.h): nl_path_*, synchronous and queued, through the C ABI only, in strict C11.
 *
 * Navmeshes are drawn as cell maps and handed over as a host would (nl_navmesh_add): row r of a map
 * is z in [r, r + 1], column c is x in [c, c + 1], every cell a 1 x 1 m square at y = 0; '.' is area
 * 0, a digit that area, anything else no navmesh. The navmeshes are declared as made for a body of
 * radius 0 and the requests ask for radius 0 unless a case is about the radius, so the right path is
 * known exactly. The main map is three islands:
 *
 *     "...#...#..."      A: x in [0, 3]   B: x in [4, 7]   C: x in [8, 11]   (z in [0, 1])
 *
 * with two manual links, both bidirectional:
 * - "jump": NL_LINK_JUMP from (2.9, 0, 0.5) on A to (4.1, 0, 0.5) on B; gap 1.2 m from its ends.
 * - "drop": NL_LINK_DROP from (8.1, 0, 0.5) on C to (6.9, 0, 0.5) on B, declared as gap 1.2 m and
 *   drop 2 m (the map is flat; the requirements are what the filter reads).
 */
/* pthread_self, pthread_equal, nanosleep and the cancelling thread; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---------------------------------------------------------------------------------------------
 * Maps and helpers
 * ------------------------------------------------------------------------------------------- */

#define MAX_CELLS 64
#define MAX_POINTS 32

static const char* const k_islands[] = {"...#...#..."};

static pthread_t g_main_thread; /* the thread a case runs on: set by the cases that compare with it */

static void set3(float* p, float x, float y, float z) {
    p[0] = x;
    p[1] = y;
    p[2] = z;
}

static int same_link(nl_link_id a, nl_link_id b) { return a.index1 == b.index1 && a.revision == b.revision; }
static int same_ticket(nl_path_ticket a, nl_path_ticket b) { return a.index1 == b.index1 && a.revision == b.revision; }

/* A world with one batch thread and `path_workers` path workers; exits the test if it cannot be made. */
static nl_world* path_world(int32_t path_workers) {
    nl_world_def def = nl_default_world_def();
    nl_world* world = NULL;
    def.worker_count = 1;
    def.path_worker_count = path_workers;
    if (NL_FAILED(nl_world_create(&def, &world))) {
        fprintf(stderr, "cannot create a world: %s\n", nl_get_last_error_message());
        exit(2);
    }
    return world;
}

/* Adds the cell map `rows` as a host navmesh made for a body of `agent_radius`; the null id on failure. */
static nl_navmesh_id add_cells(nl_world* world, const char* const* rows, int row_count, float agent_radius) {
    float vertices[MAX_CELLS * 12];
    uint32_t indices[MAX_CELLS * 4];
    uint8_t counts[MAX_CELLS], areas[MAX_CELLS];
    uint32_t cells = 0;
    nl_navmesh_def def = nl_default_navmesh_def();
    nl_navmesh_id id = {0u, 0u};
    int r;
    for (r = 0; r < row_count; ++r) {
        size_t c;
        for (c = 0; rows[r][c] != '\0'; ++c) {
            const char cell = rows[r][c];
            const float x0 = (float)c, x1 = x0 + 1.0f, z0 = (float)r, z1 = z0 + 1.0f;
            uint32_t k;
            if (cell != '.' && (cell < '0' || cell > '9')) continue;
            if (cells == MAX_CELLS) return id;
            /* Counter-clockwise seen from above (y up): +z first, then +x. */
            set3(&vertices[cells * 12 + 0], x0, 0.0f, z0);
            set3(&vertices[cells * 12 + 3], x0, 0.0f, z1);
            set3(&vertices[cells * 12 + 6], x1, 0.0f, z1);
            set3(&vertices[cells * 12 + 9], x1, 0.0f, z0);
            for (k = 0; k < 4; ++k) indices[cells * 4 + k] = cells * 4 + k;
            counts[cells] = 4;
            areas[cells] = cell == '.' ? 0 : (uint8_t)(cell - '0');
            ++cells;
        }
    }
    def.vertices = vertices;
    def.vertex_count = cells * 4;
    def.indices = indices;
    def.polygon_vertex_counts = counts;
    def.polygon_count = cells;
    def.areas = areas;
    def.agent_type.radius = agent_radius;
    if (NL_FAILED(nl_navmesh_add(world, &def, &id))) {
        CHECK_MSG(0, "nl_navmesh_add of a cell map failed: %s", nl_get_last_error_message());
    }
    return id;
}

/* The islands map with its two links. */
typedef struct islands {
    nl_world* world;
    nl_navmesh_id navmesh;
    nl_link_id jump;
    nl_link_id drop;
} islands;

static islands make_islands(int32_t path_workers) {
    islands s;
    nl_link_def jump = nl_default_link_def(), drop = nl_default_link_def();
    memset(&s, 0, sizeof s);
    s.world = path_world(path_workers);
    s.navmesh = add_cells(s.world, k_islands, 1, 0.0f);
    jump.kind = NL_LINK_JUMP;
    set3(jump.start, 2.9f, 0.0f, 0.5f);
    set3(jump.end, 4.1f, 0.0f, 0.5f);
    jump.bidirectional = 1;
    CHECK_OK(nl_link_add(s.world, s.navmesh, &jump, &s.jump));
    drop.kind = NL_LINK_DROP;
    set3(drop.start, 8.1f, 0.0f, 0.5f);
    set3(drop.end, 6.9f, 0.0f, 0.5f);
    drop.requirements_as_given = 1;
    drop.requirements.gap = 1.2f;
    drop.requirements.drop = 2.0f;
    drop.bidirectional = 1;
    CHECK_OK(nl_link_add(s.world, s.navmesh, &drop, &s.drop));
    return s;
}

/* A request on the map's floor (y = 0) for a body as thin as the navmesh assumes. */
static nl_path_request_def request(nl_navmesh_id navmesh, float sx, float sz, float gx, float gz) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    set3(def.start, sx, 0.0f, sz);
    set3(def.goal, gx, 0.0f, gz);
    def.capabilities.radius = 0.0f;
    return def;
}

/* A jumper: gaps up to 1.5 m, no rise, no drop. */
static nl_path_request_def jumper(nl_navmesh_id navmesh, float sx, float gx) {
    nl_path_request_def def = request(navmesh, sx, 0.5f, gx, 0.5f);
    def.capabilities.max_jump_distance = 1.5f;
    return def;
}

typedef struct path {
    nl_status status;
    nl_path_result result;
    uint32_t count;
    nl_path_point points[MAX_POINTS];
} path;

/* nl_path_find with room for MAX_POINTS points. */
static path find(nl_world* world, const nl_path_request_def* def) {
    path p;
    memset(&p, 0, sizeof p);
    p.result.size = sizeof p.result;
    p.points[0] = nl_path_point_init();
    p.status = nl_path_find(world, def, &p.result, p.points, MAX_POINTS, &p.count);
    return p;
}

static nl_path_outcome outcome_of(nl_world* world, const nl_path_request_def* def) {
    const path p = find(world, def);
    return NL_SUCCEEDED(p.status) ? p.result.outcome : 0xffffffffu;
}

/* Within half a millimetre: navmesh corners are kept on a grid of 1/1024 m. */
static int at(const nl_path_point* p, float x, float z) {
    return fabsf(p->position[0] - x) <= 5e-4f && fabsf(p->position[1]) <= 5e-4f && fabsf(p->position[2] - z) <= 5e-4f;
}

static nl_path_queue_stats queue_stats(const nl_world* world) {
    nl_path_queue_stats s;
    memset(&s, 0, sizeof s);
    s.size = sizeof s;
    if (NL_FAILED(nl_path_get_queue_stats(world, &s))) memset(&s, 0xff, sizeof s);
    return s;
}

static nl_path_outcome poll_outcome(const nl_world* world, nl_path_ticket ticket) {
    nl_path_outcome o = 0xdeadbeefu;
    if (NL_FAILED(nl_path_poll(world, ticket, &o))) return 0xdeadbeefu;
    return o;
}

static void sleep_ms(long ms) {
    struct timespec t;
    t.tv_sec = ms / 1000;
    t.tv_nsec = (ms % 1000) * 1000000L;
    nanosleep(&t, NULL);
}

/* What a callback saw. Written by one thread at a time in the tests that read it without atomics
   (the main thread, or a thread joined before the read). */
typedef struct call_log {
    nl_world* world; /* polled from the callback when set */
    int calls;
    nl_path_ticket ticket;
    nl_path_outcome outcome;
    pthread_t thread;
    nl_status poll_status; /* of nl_path_poll(ticket) inside the callback */
    nl_path_outcome polled;
    /* A request to submit from inside the callback (submit_from_callback set). */
    int submit_from_callback;
    nl_path_request_def follow_up;
    nl_path_ticket follow_up_ticket;
    nl_status follow_up_status;
} call_log;

static void record_call(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    call_log* log = (call_log*)user;
    ++log->calls;
    log->ticket = ticket;
    log->outcome = outcome;
    log->thread = pthread_self();
    if (log->world) log->poll_status = nl_path_poll(log->world, ticket, &log->polled);
    if (log->submit_from_callback) {
        log->submit_from_callback = 0;
        log->follow_up_status = nl_path_request(log->world, &log->follow_up, &log->follow_up_ticket);
    }
}

/* ---------------------------------------------------------------------------------------------
 * Defaults
 * ------------------------------------------------------------------------------------------- */

static void defaults(void) {
    const nl_agent_capabilities a = nl_default_agent_capabilities();
    const nl_path_request_def d = nl_default_path_request_def();
    const nl_world_def w = nl_default_world_def();

    CHECK(a.max_jump_distance == 0.0f && a.max_jump_height == 0.0f && a.max_drop_height == 0.0f);
    CHECK(a.radius == 0.6f);
    CHECK(a.abilities == 0u);
    CHECK(d.size == sizeof(nl_path_request_def));
    CHECK(d.navmesh.index1 == 0u && d.navmesh.revision == 0u);
    CHECK(d.start[0] == 0.0f && d.start[1] == 0.0f && d.start[2] == 0.0f);
    CHECK(d.goal[0] == 0.0f && d.goal[1] == 0.0f && d.goal[2] == 0.0f);
    CHECK(d.search_half_extents[0] == 2.0f && d.search_half_extents[1] == 4.0f && d.search_half_extents[2] == 2.0f);
    CHECK(memcmp(&d.capabilities, &a, sizeof a) == 0);
    CHECK(d.area_costs == NULL && d.area_cost_count == 0u);
    CHECK(d.link_cost == 0.0f);
    CHECK(d.max_nodes == 0u);
    CHECK(d.accept_partial == 1);
    CHECK(d.reserved[0] == 0 && d.reserved[1] == 0 && d.reserved[2] == 0);
    CHECK(d.callback == NULL && d.user == NULL);
    CHECK(w.path_worker_count == NL_WORKERS_AUTO);
    {
        nl_world_def bad = nl_default_world_def();
        nl_world* world = NULL;
        bad.path_worker_count = -2;
        CHECK_INVALID(nl_world_create(&bad, &world), "path_worker_count");
        CHECK(world == NULL);
    }
    {
        nl_world* world = path_world(2);
        nl_path_queue_stats s = queue_stats(world);
        CHECK(s.workers == 2u && s.queued == 0u && s.running == 0u && s.unreleased == 0u && s.submitted == 0u &&
              s.finished == 0u);
        nl_world_destroy(world);
        world = path_world(0);
        s = queue_stats(world);
        CHECK(s.workers == 0u);
        nl_world_destroy(world);
    }
}

/* ---------------------------------------------------------------------------------------------
 * nl_path_find: outcomes, segments, links
 * ------------------------------------------------------------------------------------------- */

static void find_synchronous(void) {
    islands s = make_islands(0);
    nl_path_request_def def;
    nl_link jump_link = nl_link_init();
    path p;
    CHECK_OK(nl_link_get(s.world, s.jump, &jump_link));

    /* A walker cannot cross: the path leads to the reachable point nearest to the goal. */
    def = request(s.navmesh, 0.5f, 0.5f, 5.5f, 0.5f);
    p = find(s.world, &def);
    CHECK(p.status == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(nl_get_last_status() == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(nl_get_last_error_message()[0] == '\0');
    CHECK(p.result.outcome == NL_PATH_PARTIAL);
    CHECK(p.result.status == NL_STATUS_SUCCESS);
    CHECK(p.count == 2u && p.result.point_count == 2u);
    CHECK(at(&p.points[0], 0.5f, 0.5f) && at(&p.points[1], 3.0f, 0.5f));
    CHECK_NEAR(p.result.length, 2.5f, 1e-4f);
    CHECK(p.result.links_used == 0u && p.result.out_of_nodes == 0);
    CHECK_NEAR(p.result.start[0], 0.5f, TOL);
    CHECK_NEAR(p.result.goal[0], 5.5f, TOL); /* the snapped goal, not where the path ends */
    CHECK(p.result.size == sizeof p.result);

    /* Without accept_partial: NO_PATH, a plain success, no points. */
    def.accept_partial = 0;
    p = find(s.world, &def);
    CHECK(p.status == NL_STATUS_SUCCESS);
    CHECK(p.result.outcome == NL_PATH_NO_PATH);
    CHECK(p.count == 0u && p.result.point_count == 0u);

    /* A jumper takes the jump: walk, jump, walk. */
    def = jumper(s.navmesh, 0.5f, 5.5f);
    p = find(s.world, &def);
    CHECK_OK(p.status);
    CHECK(p.result.outcome == NL_PATH_COMPLETE);
    CHECK_MSG(p.count == 4u && p.result.point_count == 4u, "%u points", (unsigned)p.count);
    if (p.count == 4u) {
        CHECK(at(&p.points[0], 0.5f, 0.5f) && at(&p.points[1], 2.9f, 0.5f) && at(&p.points[2], 4.1f, 0.5f) &&
              at(&p.points[3], 5.5f, 0.5f));
        CHECK(p.points[0].segment == NL_SEGMENT_WALK && p.points[0].link.index1 == 0u);
        CHECK(memcmp(p.points[0].apex, p.points[0].position, sizeof p.points[0].apex) == 0);
        CHECK(p.points[1].segment == NL_LINK_JUMP);
        CHECK(same_link(p.points[1].link, s.jump));
        CHECK(p.points[1].reversed == 0);
        CHECK(memcmp(p.points[1].apex, jump_link.apex, sizeof jump_link.apex) == 0);
        CHECK(p.points[2].segment == NL_SEGMENT_WALK && p.points[2].link.index1 == 0u);
        CHECK(p.points[3].segment == NL_SEGMENT_WALK); /* the last point */
        /* Polygons keep the cells' order: A is 0..2, B 3..5, C 6..8. */
        CHECK(p.points[0].polygon == 0u && p.points[1].polygon == 2u && p.points[2].polygon == 3u &&
              p.points[3].polygon == 4u);
    }
    CHECK(p.result.links_used == 1u);
    CHECK_NEAR(p.result.length, 5.0f, 1e-4f);
    CHECK_NEAR(p.result.cost, 5.0f, 1e-3f); /* walk 2.4 + link 1.2 x cost_modifier 1 + walk 1.4 */
    CHECK(p.result.nodes_visited >= 2u);

    /* link_cost is added per link taken. */
    def.link_cost = 7.0f;
    p = find(s.world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE);
    CHECK_NEAR(p.result.cost, 12.0f, 1e-3f);
    CHECK_NEAR(p.result.length, 5.0f, 1e-4f);

    /* The gap of 1.2 m against max_jump_distance. */
    def = jumper(s.navmesh, 0.5f, 5.5f);
    def.accept_partial = 0;
    def.capabilities.max_jump_distance = 1.19f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_NO_PATH);
    def.capabilities.max_jump_distance = 1.21f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_COMPLETE);

    /* Back over the bidirectional jump: the same link, reversed. */
    def = jumper(s.navmesh, 5.5f, 0.5f);
    p = find(s.world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE && p.count == 4u);
    CHECK(at(&p.points[1], 4.1f, 0.5f) && at(&p.points[2], 2.9f, 0.5f));
    CHECK(p.points[1].segment == NL_LINK_JUMP && p.points[1].reversed == 1 && same_link(p.points[1].link, s.jump));

    /* Down the drop: a step off the edge, so its gap (1.2 m) is not held against max_jump_distance (0). */
    def = request(s.navmesh, 9.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = 0;
    def.capabilities.max_drop_height = 2.0f;
    p = find(s.world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE && p.count == 4u);
    CHECK(at(&p.points[1], 8.1f, 0.5f) && at(&p.points[2], 6.9f, 0.5f));
    CHECK(p.points[1].segment == NL_LINK_DROP && p.points[1].reversed == 0 && same_link(p.points[1].link, s.drop));
    def.capabilities.max_drop_height = 1.9f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_NO_PATH);

    /* Back up the drop: a jump with the drop's 2 m as its rise, and the gap held against the jump
       distance. The point's segment is NL_LINK_JUMP, reversed. */
    def = request(s.navmesh, 5.5f, 0.5f, 9.5f, 0.5f);
    def.accept_partial = 0;
    def.capabilities.max_drop_height = 2.0f;
    def.capabilities.max_jump_distance = 1.5f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_NO_PATH); /* no rise allowed */
    def.capabilities.max_jump_height = 1.9f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_NO_PATH);
    def.capabilities.max_jump_height = 2.0f;
    def.capabilities.max_jump_distance = 1.0f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_NO_PATH); /* 1.2 m gap */
    def.capabilities.max_jump_distance = 1.5f;
    def.capabilities.max_drop_height = 0.0f; /* going up, the link asks for no drop */
    p = find(s.world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE && p.count == 4u);
    CHECK(at(&p.points[1], 6.9f, 0.5f) && at(&p.points[2], 8.1f, 0.5f));
    CHECK(p.points[1].segment == NL_LINK_JUMP && p.points[1].reversed == 1 && same_link(p.points[1].link, s.drop));

    /* Start and goal that do not snap to the navmesh: their own outcomes, a success, no points. */
    def = request(s.navmesh, -10.0f, 0.5f, 1.5f, 0.5f);
    p = find(s.world, &def);
    CHECK(p.status == NL_STATUS_SUCCESS && p.result.outcome == NL_PATH_START_OFF_NAVMESH && p.count == 0u);
    def = request(s.navmesh, 0.5f, 0.5f, 30.0f, 0.5f);
    p = find(s.world, &def);
    CHECK(p.status == NL_STATUS_SUCCESS && p.result.outcome == NL_PATH_GOAL_OFF_NAVMESH && p.count == 0u);
    def = request(s.navmesh, 0.5f, 0.5f, 1.5f, 0.5f);
    def.start[1] = 10.0f; /* above the default box of +-4 m */
    CHECK(outcome_of(s.world, &def) == NL_PATH_START_OFF_NAVMESH);
    def.search_half_extents[1] = 20.0f;
    CHECK(outcome_of(s.world, &def) == NL_PATH_COMPLETE);

    /* Too small a buffer: BUFFER_TOO_SMALL, the result written, the count the points needed, the
       points untouched. */
    {
        nl_path_point points[3];
        points[0] = nl_path_point_init();
        nl_path_result result;
        uint32_t count = 0;
        nl_status st;
        memset(points, 0xab, sizeof points);
        points[0].size = sizeof points[0]; /* the element size the library lays out with */
        memset(&result, 0, sizeof result);
        result.size = sizeof result;
        def = jumper(s.navmesh, 0.5f, 5.5f);
        st = nl_path_find(s.world, &def, &result, points, 3, &count);
        CHECK_FAIL(st, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        CHECK(count == 4u);
        CHECK(result.outcome == NL_PATH_COMPLETE && result.point_count == 4u && result.links_used == 1u);
        CHECK_NEAR(result.length, 5.0f, 1e-4f);
        CHECK(all_bytes((const unsigned char*)points + sizeof(uint32_t), sizeof points - sizeof(uint32_t), 0xab));

        /* The two-call pattern: NULL points count them, then the buffer gets them. */
        memset(&result, 0, sizeof result);
        result.size = sizeof result;
        count = 0;
        CHECK_OK(nl_path_find(s.world, &def, &result, NULL, 0, &count));
        CHECK(count == 4u && result.outcome == NL_PATH_COMPLETE && result.point_count == 4u);
        p = find(s.world, &def);
        CHECK(p.count == count);

        /* A partial path counts with PARTIAL_RESULT too. */
        def = request(s.navmesh, 0.5f, 0.5f, 5.5f, 0.5f);
        st = nl_path_find(s.world, &def, &result, NULL, 0, &count);
        CHECK(st == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT) && count == 2u);
    }
    nl_world_destroy(s.world);
}

/* Area costs, NL_AREA_EXCLUDED, max_nodes and the body's radius on small maps. */
static void costs_and_radius(void) {
    static const char* const k_mud[] = {"..1.."};
    static const char* const k_long[] = {"................"};
    nl_world* world = path_world(0);
    nl_navmesh_id mud = add_cells(world, k_mud, 1, 0.0f);
    nl_navmesh_id corridor = add_cells(world, k_long, 1, 0.0f);
    nl_path_request_def def = request(mud, 0.5f, 0.5f, 4.5f, 0.5f);
    float costs[2] = {1.0f, 3.0f};
    path p;

    p = find(world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE);
    CHECK_NEAR(p.result.cost, 4.0f, 1e-3f);
    /* 1.5 m of area 0, 1 m of area 1 at 3 per metre, 1.5 m of area 0. */
    def.area_costs = costs;
    def.area_cost_count = 2;
    p = find(world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE);
    CHECK_NEAR(p.result.cost, 6.0f, 1e-3f);
    CHECK_NEAR(p.result.length, 4.0f, 1e-4f);
    /* Areas past area_cost_count cost 1. */
    costs[0] = 2.0f;
    def.area_cost_count = 1;
    p = find(world, &def);
    CHECK_NEAR(p.result.cost, 7.0f, 1e-3f);
    /* NL_AREA_EXCLUDED: the agent stays out; the path stops at the excluded cell. */
    costs[0] = 1.0f;
    costs[1] = NL_AREA_EXCLUDED;
    def.area_cost_count = 2;
    p = find(world, &def);
    CHECK(p.result.outcome == NL_PATH_PARTIAL && p.count == 2u);
    CHECK(p.count == 2u && at(&p.points[1], 2.0f, 0.5f));

    /* max_nodes bounds the search: a partial path, out_of_nodes set. */
    def = request(corridor, 0.5f, 0.5f, 15.5f, 0.5f);
    def.max_nodes = 3;
    p = find(world, &def);
    CHECK(p.status == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(p.result.outcome == NL_PATH_PARTIAL && p.result.out_of_nodes == 1 && p.result.nodes_visited <= 3u);
    def.max_nodes = 0;
    p = find(world, &def);
    CHECK(p.result.outcome == NL_PATH_COMPLETE && p.result.out_of_nodes == 0 && p.result.nodes_visited >= 16u);

    /* A body wider than the navmesh's (radius 0) keeps the difference from the outline: a 1 m wide
       corridor closes for a radius of 0.5 or more (no room left in its portals). */
    def.capabilities.radius = 0.45f;
    CHECK(outcome_of(world, &def) == NL_PATH_COMPLETE);
    def.capabilities.radius = 0.5f;
    def.accept_partial = 0;
    CHECK(outcome_of(world, &def) == NL_PATH_NO_PATH);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Bad input: the documented status, a message naming the field, nothing changed
 * ------------------------------------------------------------------------------------------- */

static int g_never_called;
static void must_not_be_called(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    (void)user;
    (void)ticket;
    (void)outcome;
    ++g_never_called;
}

/* Both nl_path_find and nl_path_request refuse `def` with `detail` and a message containing `needle`,
   and write nothing: not the result, the count, the ticket, nor the queue's counters. */
static void check_refused_at(nl_world* world, const nl_path_request_def* def, nl_status detail, const char* needle,
                             int line) {
    nl_path_result result, before_result;
    nl_path_point points[4], before_points[4];
    uint32_t count = 0xdeadbeefu;
    nl_path_ticket ticket = {0xdeadu, 0xbeefu};
    nl_path_queue_stats before = queue_stats(world), after;
    nl_path_request_def with_callback;
    memset(&result, 0xab, sizeof result);
    result.size = sizeof result;
    before_result = result;
    memset(points, 0xcd, sizeof points);
    points[0].size = sizeof points[0]; /* the element size the library lays out with */
    memcpy(before_points, points, sizeof points);

    check_fail_at(nl_path_find(world, def, &result, points, 4, &count), detail, needle, "nl_path_find", __FILE__, line);
    check_at(memcmp(&result, &before_result, sizeof result) == 0 && memcmp(points, before_points, sizeof points) == 0 &&
                 count == 0xdeadbeefu,
             __FILE__, line, "a refused nl_path_find wrote nothing (%s)", needle);

    if (def) {
        with_callback = *def;
        with_callback.callback = must_not_be_called;
        def = &with_callback;
    }
    check_fail_at(nl_path_request(world, def, &ticket), detail, needle, "nl_path_request", __FILE__, line);
    after = queue_stats(world);
    check_at(ticket.index1 == 0xdeadu && ticket.revision == 0xbeefu && memcmp(&before, &after, sizeof before) == 0,
             __FILE__, line, "a refused nl_path_request made no ticket and left the queue as it was (%s)", needle);
}
#define CHECK_REFUSED(world, def, detail, needle) check_refused_at((world), (def), (detail), (needle), __LINE__)

static void bad_input(void) {
    islands s = make_islands(0);
    nl_world* other = path_world(0);
    nl_navmesh_id foreign = add_cells(other, k_islands, 1, 0.0f);
    const nl_path_request_def good = jumper(s.navmesh, 0.5f, 5.5f);
    nl_path_request_def def;
    nl_path_result result;
    nl_path_point points[4];
    points[0] = nl_path_point_init();
    nl_path_ticket ticket = {0u, 0u}, queued = {0u, 0u};
    nl_path_outcome outcome = 0xdeadbeefu;
    nl_path_queue_stats stats, stats_after;
    uint32_t count = 0xdeadbeefu, processed = 0xdeadbeefu;
    float costs[300];
    size_t i;
    for (i = 0; i < 300; ++i) costs[i] = 1.0f;
    memset(&result, 0, sizeof result);
    result.size = sizeof result;

    /* A queued request, so that "nothing changed" has something to keep. */
    CHECK_OK(nl_path_request(s.world, &good, &queued));

    /* Null pointers. */
    CHECK_REFUSED(s.world, NULL, NL_STATUS_INVALID_ARGUMENT, "def");
    CHECK_INVALID(nl_path_find(NULL, &good, &result, points, 4, &count), "world");
    CHECK_INVALID(nl_path_find(s.world, &good, NULL, points, 4, &count), "out_result");
    CHECK_INVALID(nl_path_find(s.world, &good, &result, points, 4, NULL), "out_count");
    CHECK_INVALID(nl_path_find(s.world, &good, &result, NULL, 4, &count), "out_points");
    CHECK(count == 0xdeadbeefu && result.outcome == 0u);
    CHECK_INVALID(nl_path_request(NULL, &good, &ticket), "world");
    CHECK_INVALID(nl_path_request(s.world, &good, NULL), "out_ticket");
    CHECK_INVALID(nl_path_poll(NULL, queued, &outcome), "world");
    CHECK_INVALID(nl_path_poll(s.world, queued, NULL), "out_outcome");
    CHECK_INVALID(nl_path_get_result(NULL, queued, &result, points, 4, &count), "world");
    CHECK_INVALID(nl_path_get_result(s.world, queued, NULL, points, 4, &count), "out_result");
    CHECK_INVALID(nl_path_get_result(s.world, queued, &result, points, 4, NULL), "out_count");
    CHECK_INVALID(nl_path_cancel(NULL, queued), "world");
    CHECK_INVALID(nl_path_release(NULL, queued), "world");
    CHECK_INVALID(nl_path_process(NULL, NL_TEST_BUDGET(0, 0.0), &processed), "world");
    CHECK_INVALID(nl_path_get_queue_stats(NULL, &stats), "world");
    CHECK_INVALID(nl_path_get_queue_stats(s.world, NULL), "out_stats");
    CHECK(ticket.index1 == 0u && outcome == 0xdeadbeefu && count == 0xdeadbeefu && processed == 0xdeadbeefu);

    /* Sizes. */
    def = good;
    def.size = 8;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->size");
    {
        nl_path_result small;
        memset(&small, 0, sizeof small);
        small.size = 8;
        CHECK_INVALID(nl_path_find(s.world, &good, &small, points, 4, &count), "out_result->size");
        CHECK(count == 0xdeadbeefu && small.outcome == 0u);
        memset(&stats, 0, sizeof stats);
        stats.size = 8;
        CHECK_INVALID(nl_path_get_queue_stats(s.world, &stats), "out_stats->size");
        CHECK(stats.queued == 0u);
    }

    /* Coordinates. */
    def = good;
    def.start[0] = NAN;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->start");
    def = good;
    def.goal[2] = INFINITY;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->goal");
    def = good;
    def.goal[1] = -2.0e9f; /* beyond NL_COORDINATE_LIMIT */
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->goal");
    def = good;
    def.search_half_extents[1] = 0.0f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "search_half_extents");
    def.search_half_extents[1] = -1.0f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "search_half_extents");
    def.search_half_extents[1] = NAN;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "search_half_extents");

    /* Capabilities. */
    def = good;
    def.capabilities.max_jump_distance = -1.0f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "capabilities.max_jump_distance");
    def = good;
    def.capabilities.max_jump_height = -0.5f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "capabilities.max_jump_height");
    def = good;
    def.capabilities.max_drop_height = INFINITY;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "capabilities.max_drop_height");
    def = good;
    def.capabilities.radius = NAN;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "capabilities.radius");
    def.capabilities.radius = -0.1f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "capabilities.radius");

    /* Costs. */
    def = good;
    def.area_costs = costs;
    def.area_cost_count = 3;
    costs[1] = -1.0f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->area_costs[1]");
    costs[1] = NAN;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->area_costs[1]");
    costs[1] = INFINITY;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->area_costs[1]");
    costs[1] = 1.0f;
    def.area_cost_count = 257;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "area_cost_count");
    def.area_cost_count = 256; /* the most there may be */
    CHECK_OK(nl_path_find(s.world, &def, &result, points, 4, &count));
    def.area_costs = NULL;
    def.area_cost_count = 2;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "def->area_costs");
    def = good;
    def.link_cost = -1.0f;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "link_cost");
    def.link_cost = NAN;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_ARGUMENT, "link_cost");

    /* Navmesh ids: null, another world's, removed. */
    def = good;
    memset(&def.navmesh, 0, sizeof def.navmesh);
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_HANDLE, "navmesh");
    def.navmesh = foreign;
    CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_HANDLE, "navmesh");
    {
        static const char* const k_one[] = {".."};
        nl_navmesh_id gone = add_cells(s.world, k_one, 1, 0.0f);
        def = request(gone, 0.5f, 0.5f, 1.5f, 0.5f);
        CHECK(outcome_of(s.world, &def) == NL_PATH_COMPLETE);
        CHECK_OK(nl_navmesh_remove(s.world, gone));
        CHECK_REFUSED(s.world, &def, NL_STATUS_INVALID_HANDLE, "navmesh");
    }

    /* Tickets: null, another world's, released. */
    {
        const nl_path_ticket null_ticket = {0u, 0u};
        nl_path_ticket theirs = {0u, 0u}, released = {0u, 0u};
        nl_path_request_def their_def = jumper(foreign, 0.5f, 5.5f);
        CHECK_OK(nl_path_request(other, &their_def, &theirs));
        CHECK_OK(nl_path_request(s.world, &good, &released));
        CHECK_OK(nl_path_release(s.world, released));
        stats = queue_stats(s.world);
        count = 0xdeadbeefu;
        memset(&result, 0xab, sizeof result);
        result.size = sizeof result;
        CHECK_FAIL(nl_path_poll(s.world, null_ticket, &outcome), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_poll(s.world, theirs, &outcome), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_poll(s.world, released, &outcome), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK(outcome == 0xdeadbeefu);
        CHECK_FAIL(nl_path_get_result(s.world, released, &result, points, 4, &count), NL_STATUS_INVALID_HANDLE,
                   "path ticket");
        CHECK_FAIL(nl_path_get_result(s.world, theirs, &result, points, 4, &count), NL_STATUS_INVALID_HANDLE,
                   "path ticket");
        CHECK(count == 0xdeadbeefu && result.outcome == 0xababababu);
        CHECK_FAIL(nl_path_cancel(s.world, released), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_cancel(s.world, theirs), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_release(s.world, released), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_release(s.world, null_ticket), NL_STATUS_INVALID_HANDLE, "path ticket");
        CHECK_FAIL(nl_path_release(s.world, theirs), NL_STATUS_INVALID_HANDLE, "path ticket");
        stats_after = queue_stats(s.world);
        CHECK_THAT(memcmp(&stats, &stats_after, sizeof stats) == 0, "refused ticket calls left the queue as it was");
        CHECK(poll_outcome(other, theirs) == NL_PATH_PENDING); /* still fine in its own world */
    }

    /* A NaN budget. */
    stats = queue_stats(s.world);
    processed = 0xdeadbeefu;
    CHECK_INVALID(nl_path_process(s.world, NL_TEST_BUDGET(0, NAN), &processed), "max_milliseconds");
    stats_after = queue_stats(s.world);
    CHECK(processed == 0xdeadbeefu);
    CHECK_THAT(memcmp(&stats, &stats_after, sizeof stats) == 0 && stats.queued == 1u,
               "nl_path_process with a NaN budget planned nothing");
    CHECK(poll_outcome(s.world, queued) == NL_PATH_PENDING);

    CHECK_THAT(g_never_called == 0, "no refused request's callback was ever called");
    nl_world_destroy(other);
    nl_world_destroy(s.world);
    CHECK(g_never_called == 0);
}

/* ---------------------------------------------------------------------------------------------
 * The queue with path_worker_count = 0: the host runs it with nl_path_process
 * ------------------------------------------------------------------------------------------- */

typedef struct canceller {
    nl_world* world;
    nl_path_ticket ticket;
    nl_status status;
    pthread_t self;
} canceller;

static void* cancel_on_thread(void* arg) {
    canceller* c = (canceller*)arg;
    c->self = pthread_self();
    c->status = nl_path_cancel(c->world, c->ticket);
    return NULL;
}

static int same_result(const nl_path_result* a, const nl_path_point* pa, uint32_t na, const nl_path_result* b,
                       const nl_path_point* pb, uint32_t nb) {
    return a->outcome == b->outcome && a->point_count == b->point_count && a->length == b->length &&
           a->cost == b->cost && a->links_used == b->links_used && na == nb &&
           (na == 0 || memcmp(pa, pb, na * sizeof *pa) == 0);
}

static void queue_manual(void) {
    enum { N = 6 };
    islands s = make_islands(0);
    nl_path_request_def defs[N];
    nl_path_ticket tickets[N];
    call_log logs[N], follow_up_log;
    nl_path_queue_stats st;
    nl_path_result result;
    nl_path_point points[MAX_POINTS];
    points[0] = nl_path_point_init();
    uint32_t count, processed;
    nl_status status;
    int i;
    memset(logs, 0, sizeof logs);
    g_main_thread = pthread_self();
    memset(&follow_up_log, 0, sizeof follow_up_log);

    for (i = 0; i < N; ++i) {
        defs[i] = jumper(s.navmesh, 0.5f, 5.5f);
        if (i == 1) defs[i].capabilities.max_jump_distance = 0.0f; /* a walker: partial */
        defs[i].callback = record_call;
        defs[i].user = &logs[i];
        logs[i].world = s.world;
        CHECK_OK(nl_path_request(s.world, &defs[i], &tickets[i]));
        CHECK(tickets[i].index1 != 0u);
    }
    /* t5's callback submits a follow-up request (allowed from a callback). */
    logs[5].submit_from_callback = 1;
    logs[5].follow_up = jumper(s.navmesh, 5.5f, 0.5f);
    logs[5].follow_up.callback = record_call;
    logs[5].follow_up.user = &follow_up_log;

    st = queue_stats(s.world);
    CHECK(st.workers == 0u && st.queued == (uint32_t)N && st.running == 0u && st.unreleased == (uint32_t)N &&
          st.submitted == (uint64_t)N && st.finished == 0u);
    for (i = 0; i < N; ++i) CHECK(poll_outcome(s.world, tickets[i]) == NL_PATH_PENDING && logs[i].calls == 0);

    /* Not finished: IN_PROGRESS, nothing written. */
    memset(&result, 0xab, sizeof result);
    result.size = sizeof result;
    memset(points, 0xab, sizeof points);
    points[0].size = sizeof points[0]; /* the element size the library lays out with */
    count = 0xdeadbeefu;
    status = nl_path_get_result(s.world, tickets[0], &result, points, MAX_POINTS, &count);
    CHECK(status == NL_STATUS_IN_PROGRESS);
    CHECK(nl_get_last_status() == NL_STATUS_IN_PROGRESS && nl_get_last_error_message()[0] == '\0');
    CHECK(!NL_FAILED(status) && !NL_SUCCEEDED(status));
    CHECK(count == 0xdeadbeefu && result.outcome == 0xababababu &&
          all_bytes((const unsigned char*)points + sizeof(uint32_t), sizeof points - sizeof(uint32_t), 0xab));

    /* Two per call, in the order they were made, their callbacks here and now. */
    processed = 0xdeadbeefu;
    CHECK_OK(nl_path_process(s.world, NL_TEST_BUDGET(2, 0.0), &processed));
    CHECK(processed == 2u);
    CHECK(logs[0].calls == 1 && logs[1].calls == 1);
    CHECK(logs[2].calls == 0 && logs[3].calls == 0 && logs[4].calls == 0 && logs[5].calls == 0);
    CHECK(same_ticket(logs[0].ticket, tickets[0]) && logs[0].outcome == NL_PATH_COMPLETE);
    CHECK(same_ticket(logs[1].ticket, tickets[1]) && logs[1].outcome == NL_PATH_PARTIAL);
    CHECK_THAT(pthread_equal(logs[0].thread, g_main_thread) && pthread_equal(logs[1].thread, g_main_thread),
               "callbacks of nl_path_process run on the thread calling it");
    CHECK_THAT(logs[0].poll_status == NL_STATUS_SUCCESS && logs[0].polled == NL_PATH_COMPLETE,
               "a callback may poll its ticket, which is finished");
    st = queue_stats(s.world);
    CHECK(st.queued == 4u && st.running == 0u && st.unreleased == 6u && st.submitted == 6u && st.finished == 2u);
    CHECK(poll_outcome(s.world, tickets[0]) == NL_PATH_COMPLETE &&
          poll_outcome(s.world, tickets[1]) == NL_PATH_PARTIAL);
    CHECK(poll_outcome(s.world, tickets[2]) == NL_PATH_PENDING);

    /* The queued result is nl_path_find's, readable any number of times. */
    {
        const path sync = find(s.world, &defs[0]);
        int k;
        for (k = 0; k < 2; ++k) {
            memset(&result, 0, sizeof result);
            result.size = sizeof result;
            CHECK_OK(nl_path_get_result(s.world, tickets[0], &result, points, MAX_POINTS, &count));
            CHECK(same_result(&result, points, count, &sync.result, sync.points, sync.count));
        }
        memset(points, 0xab, sizeof points);
        points[0].size = sizeof points[0]; /* the element size the library lays out with */
        CHECK_FAIL(nl_path_get_result(s.world, tickets[0], &result, points, 2, &count), NL_STATUS_BUFFER_TOO_SMALL,
                   "capacity");
        CHECK(count == 4u && result.point_count == 4u &&
              all_bytes((const unsigned char*)points + sizeof(uint32_t), sizeof points - sizeof(uint32_t), 0xab));
        CHECK_OK(nl_path_get_result(s.world, tickets[0], &result, NULL, 0, &count));
        CHECK(count == 4u);
        status = nl_path_get_result(s.world, tickets[1], &result, points, MAX_POINTS, &count);
        CHECK(status == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT) && result.outcome == NL_PATH_PARTIAL);
    }

    /* Cancel a queued request from another thread: it finishes at once, its callback on that thread. */
    {
        canceller c;
        pthread_t thread;
        memset(&c, 0, sizeof c);
        c.world = s.world;
        c.ticket = tickets[2];
        if (pthread_create(&thread, NULL, cancel_on_thread, &c) == 0) {
            pthread_join(thread, NULL);
            CHECK(c.status == NL_STATUS_SUCCESS);
            CHECK(logs[2].calls == 1 && logs[2].outcome == NL_PATH_CANCELLED &&
                  same_ticket(logs[2].ticket, tickets[2]));
            CHECK_THAT(pthread_equal(logs[2].thread, c.self) && !pthread_equal(logs[2].thread, g_main_thread),
                       "the callback of a request cancelled before it started runs on the cancelling thread");
        } else {
            CHECK_MSG(0, "could not start a thread");
        }
    }
    CHECK(poll_outcome(s.world, tickets[2]) == NL_PATH_CANCELLED);
    memset(&result, 0, sizeof result);
    result.size = sizeof result;
    count = 0xdeadbeefu;
    CHECK_OK(nl_path_get_result(s.world, tickets[2], &result, points, MAX_POINTS, &count));
    CHECK(result.outcome == NL_PATH_CANCELLED && result.point_count == 0u && count == 0u &&
          result.status == NL_STATUS_SUCCESS);
    st = queue_stats(s.world);
    CHECK(st.queued == 3u && st.unreleased == 6u && st.finished == 3u);

    /* Cancelling a finished request changes nothing and calls nobody. */
    CHECK_OK(nl_path_cancel(s.world, tickets[0]));
    CHECK_OK(nl_path_cancel(s.world, tickets[2]));
    CHECK(logs[0].calls == 1 && logs[2].calls == 1);
    CHECK(poll_outcome(s.world, tickets[0]) == NL_PATH_COMPLETE);

    /* Releasing a queued request cancels it: the callback runs (here), the ticket is gone. */
    CHECK_OK(nl_path_release(s.world, tickets[3]));
    CHECK(logs[3].calls == 1 && logs[3].outcome == NL_PATH_CANCELLED && same_ticket(logs[3].ticket, tickets[3]));
    CHECK(pthread_equal(logs[3].thread, g_main_thread));
    CHECK_THAT(logs[3].poll_status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE),
               "a released request's ticket is already invalid in its callback");
    CHECK_FAIL(nl_path_poll(s.world, tickets[3], &count), NL_STATUS_INVALID_HANDLE, "path ticket");
    st = queue_stats(s.world);
    CHECK(st.queued == 2u && st.unreleased == 5u && st.finished == 4u && st.submitted == 6u);

    /* Releasing a finished request frees it: no callback, the ticket is gone. */
    CHECK_OK(nl_path_release(s.world, tickets[0]));
    CHECK(logs[0].calls == 1);
    CHECK_FAIL(nl_path_poll(s.world, tickets[0], &count), NL_STATUS_INVALID_HANDLE, "path ticket");
    CHECK_FAIL(nl_path_release(s.world, tickets[0]), NL_STATUS_INVALID_HANDLE, "path ticket");
    st = queue_stats(s.world);
    CHECK(st.unreleased == 4u && st.finished == 4u);

    /* No limit: the rest, and the request t5's callback submitted meanwhile (the queue is emptied). */
    processed = 0;
    CHECK_OK(nl_path_process(s.world, NL_TEST_BUDGET(0, -1.0), &processed));
    CHECK_MSG(processed == 3u, "processed %u", (unsigned)processed);
    CHECK(logs[4].calls == 1 && logs[4].outcome == NL_PATH_COMPLETE && same_ticket(logs[4].ticket, tickets[4]));
    CHECK(logs[5].calls == 1 && logs[5].outcome == NL_PATH_COMPLETE);
    CHECK(logs[5].follow_up_status == NL_STATUS_SUCCESS);
    CHECK(follow_up_log.calls == 1 && follow_up_log.outcome == NL_PATH_COMPLETE &&
          same_ticket(follow_up_log.ticket, logs[5].follow_up_ticket));
    processed = 0xdeadbeefu;
    CHECK_OK(nl_path_process(s.world, NL_TEST_BUDGET(0, 0.0), &processed));
    CHECK(processed == 0u);
    CHECK_OK(nl_path_process(s.world, NL_TEST_BUDGET(5, 10.0), NULL)); /* out_processed is optional */
    for (i = 0; i < N; ++i) CHECK_MSG(logs[i].calls == 1, "request %d: %d callbacks", i, logs[i].calls);
    st = queue_stats(s.world);
    CHECK(st.queued == 0u && st.running == 0u && st.unreleased == 5u && st.submitted == 7u && st.finished == 7u);

    /* Released, every ticket is gone. */
    CHECK_OK(nl_path_release(s.world, tickets[1]));
    CHECK_OK(nl_path_release(s.world, tickets[2]));
    CHECK_OK(nl_path_release(s.world, tickets[4]));
    CHECK_OK(nl_path_release(s.world, tickets[5]));
    CHECK_OK(nl_path_release(s.world, logs[5].follow_up_ticket));
    st = queue_stats(s.world);
    CHECK(st.unreleased == 0u && st.submitted == 7u && st.finished == 7u);
    nl_world_destroy(s.world);

    /* Destroying a world with requests queued: each callback runs once, CANCELLED, on the destroying
       thread; a finished request's callback is not called again. */
    {
        islands d = make_islands(0);
        call_log dl[3];
        nl_path_ticket dt[3];
        memset(dl, 0, sizeof dl);
        for (i = 0; i < 3; ++i) {
            nl_path_request_def r = jumper(d.navmesh, 0.5f, 5.5f);
            r.callback = record_call;
            r.user = &dl[i];
            dl[i].world = d.world;
            CHECK_OK(nl_path_request(d.world, &r, &dt[i]));
        }
        CHECK_OK(nl_path_process(d.world, NL_TEST_BUDGET(1, 0.0), &processed));
        CHECK(dl[0].calls == 1 && dl[0].outcome == NL_PATH_COMPLETE && dl[1].calls == 0 && dl[2].calls == 0);
        nl_world_destroy(d.world);
        CHECK(dl[0].calls == 1);
        for (i = 1; i < 3; ++i) {
            CHECK_MSG(dl[i].calls == 1 && dl[i].outcome == NL_PATH_CANCELLED && same_ticket(dl[i].ticket, dt[i]),
                      "request %d: %d callbacks, outcome %u", i, dl[i].calls, (unsigned)dl[i].outcome);
            CHECK(pthread_equal(dl[i].thread, g_main_thread));
            CHECK(dl[i].poll_status == NL_STATUS_SUCCESS && dl[i].polled == NL_PATH_CANCELLED);
        }
    }
}

/* A request reads the navmesh and its links as they were when it was made. */
static void snapshots(void) {
    islands s = make_islands(0);
    const nl_path_request_def def = jumper(s.navmesh, 0.5f, 5.5f);
    nl_path_ticket before = {0u, 0u}, after = {0u, 0u}, orphan = {0u, 0u};
    nl_path_result result;
    nl_path_point points[MAX_POINTS];
    points[0] = nl_path_point_init();
    uint32_t count = 0, processed = 0;

    CHECK_OK(nl_path_request(s.world, &def, &before));
    CHECK_OK(nl_link_remove(s.world, s.jump));
    CHECK_OK(nl_path_request(s.world, &def, &after));
    CHECK(outcome_of(s.world, &def) == NL_PATH_PARTIAL); /* now: no link */
    /* The navmesh goes too, with a request still queued on it. */
    CHECK_OK(nl_path_request(s.world, &def, &orphan));
    CHECK_OK(nl_navmesh_remove(s.world, s.navmesh));
    CHECK(outcome_of(s.world, &def) == 0xffffffffu && (nl_get_last_status() & NL_STATUS_INVALID_HANDLE));

    CHECK_OK(nl_path_process(s.world, NL_TEST_BUDGET(0, 0.0), &processed));
    CHECK(processed == 3u);
    memset(&result, 0, sizeof result);
    result.size = sizeof result;
    CHECK_OK(nl_path_get_result(s.world, before, &result, points, MAX_POINTS, &count));
    CHECK_THAT(result.outcome == NL_PATH_COMPLETE && result.links_used == 1u && count == 4u &&
                   same_link(points[1].link, s.jump),
               "a request made before the link was removed uses it");
    CHECK(nl_path_get_result(s.world, after, &result, points, MAX_POINTS, &count) ==
          (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK_THAT(result.outcome == NL_PATH_PARTIAL && result.links_used == 0u,
               "a request made after the link was removed does not see it");
    CHECK(NL_SUCCEEDED(nl_path_get_result(s.world, orphan, &result, points, MAX_POINTS, &count)));
    CHECK_THAT(result.outcome == NL_PATH_PARTIAL && result.links_used == 0u,
               "a request queued on a navmesh removed since is planned on its snapshot");
    nl_world_destroy(s.world);
}

/* ---------------------------------------------------------------------------------------------
 * The queue with 2 path workers: 1000 requests
 * ------------------------------------------------------------------------------------------- */

#define MANY 1000
#define VARIANTS 8

typedef struct slot {
    atomic_int calls;
    nl_path_ticket callback_ticket;
    nl_path_outcome callback_outcome;
    int on_main_thread;
    /* Set for some: the callback reads the result and releases the ticket itself. */
    int release_in_callback;
    nl_status callback_read_status;
    uint32_t callback_point_count;
    nl_status callback_release_status;
} slot;

typedef struct many_state {
    nl_world* world;
    atomic_int completions;
    slot slots[MANY];
} many_state;

static many_state g_many;

static void count_completion(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    slot* sl = (slot*)user;
    sl->callback_ticket = ticket;
    sl->callback_outcome = outcome;
    sl->on_main_thread = pthread_equal(pthread_self(), g_main_thread) != 0;
    if (sl->release_in_callback) {
        nl_path_result r;
        uint32_t n = 0;
        memset(&r, 0, sizeof r);
        r.size = sizeof r;
        sl->callback_read_status = nl_path_get_result(g_many.world, ticket, &r, NULL, 0, &n);
        sl->callback_point_count = n;
        sl->callback_release_status = nl_path_release(g_many.world, ticket);
    }
    atomic_fetch_add(&sl->calls, 1);
    atomic_fetch_add(&g_many.completions, 1); /* last: what the slot holds is visible once this is */
}

static nl_path_request_def variant(const islands* s, int v) {
    /* Jumpers and walkers both ways across A-B, droppers C->B, climbers B->C, from a few places. */
    const float offset = 0.25f * (float)(v / 4);
    nl_path_request_def def;
    switch (v % 4) {
        case 0: def = jumper(s->navmesh, 0.5f + offset, 5.5f); break;
        case 1: def = request(s->navmesh, 0.5f + offset, 0.5f, 6.5f, 0.7f); break; /* walker: partial */
        case 2:
            def = request(s->navmesh, 10.5f - offset, 0.5f, 4.5f, 0.3f);
            def.capabilities.max_drop_height = 2.0f;
            break;
        default:
            def = jumper(s->navmesh, 6.5f - offset, 1.5f);
            def.goal[2] = 0.8f;
            break;
    }
    return def;
}

static void queue_workers(void) {
    islands s = make_islands(2);
    nl_path_request_def defs[VARIANTS];
    path expected[VARIANTS];
    nl_path_ticket* tickets = (nl_path_ticket*)calloc(MANY, sizeof *tickets);
    nl_path_queue_stats st;
    int i, refused = 0, waited_ms = 0, wrong_calls = 0, wrong_ticket = 0, wrong_outcome = 0, wrong_result = 0,
           on_main = 0, wrong_callback_read = 0, released_in_callback = 0;
    if (!tickets) {
        CHECK_MSG(0, "out of memory");
        return;
    }
    g_main_thread = pthread_self();
    memset(&g_many, 0, sizeof g_many);
    g_many.world = s.world;
    atomic_init(&g_many.completions, 0);
    for (i = 0; i < VARIANTS; ++i) {
        defs[i] = variant(&s, i);
        expected[i] = find(s.world, &defs[i]);
        CHECK(NL_SUCCEEDED(expected[i].status) &&
              (expected[i].result.outcome == NL_PATH_COMPLETE || expected[i].result.outcome == NL_PATH_PARTIAL));
    }
    CHECK(expected[0].result.links_used == 1u && expected[1].result.outcome == NL_PATH_PARTIAL &&
          expected[2].result.links_used == 1u && expected[3].result.links_used == 1u);
    CHECK(queue_stats(s.world).workers == 2u);

    for (i = 0; i < MANY; ++i) {
        nl_path_request_def def = defs[i % VARIANTS];
        atomic_init(&g_many.slots[i].calls, 0);
        g_many.slots[i].release_in_callback = i % 10 == 9;
        def.callback = count_completion;
        def.user = &g_many.slots[i];
        if (NL_FAILED(nl_path_request(s.world, &def, &tickets[i]))) ++refused;
    }
    CHECK_MSG(refused == 0, "%d requests refused", refused);
    /* Wait (at most 30 s) for every request to finish and every callback to return. */
    for (;;) {
        st = queue_stats(s.world);
        if ((st.finished == MANY && atomic_load(&g_many.completions) == MANY) || waited_ms >= 30000) break;
        sleep_ms(2);
        waited_ms += 2;
    }
    CHECK_MSG(st.finished == MANY && atomic_load(&g_many.completions) == MANY,
              "after %d ms: %llu finished, %d callbacks", waited_ms, (unsigned long long)st.finished,
              atomic_load(&g_many.completions));
    CHECK(st.submitted == MANY && st.queued == 0u && st.running == 0u);
    CHECK_MSG(st.unreleased == MANY - MANY / 10, "%u unreleased", (unsigned)st.unreleased);

    for (i = 0; i < MANY; ++i) {
        const slot* sl = &g_many.slots[i];
        const path* want = &expected[i % VARIANTS];
        if (atomic_load(&g_many.slots[i].calls) != 1) ++wrong_calls;
        if (!same_ticket(sl->callback_ticket, tickets[i])) ++wrong_ticket;
        if (sl->callback_outcome != want->result.outcome) ++wrong_outcome;
        on_main += sl->on_main_thread;
        if (sl->release_in_callback) {
            nl_path_outcome o;
            ++released_in_callback;
            if (NL_FAILED(sl->callback_read_status) || sl->callback_point_count != want->count ||
                sl->callback_release_status != NL_STATUS_SUCCESS ||
                nl_path_poll(s.world, tickets[i], &o) != (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE))
                ++wrong_callback_read;
        } else {
            path got;
            memset(&got, 0, sizeof got);
            got.result.size = sizeof got.result;
            got.points[0] = nl_path_point_init();
            got.status = nl_path_get_result(s.world, tickets[i], &got.result, got.points, MAX_POINTS, &got.count);
            if (got.status != want->status || poll_outcome(s.world, tickets[i]) != want->result.outcome ||
                !same_result(&got.result, got.points, got.count, &want->result, want->points, want->count))
                ++wrong_result;
            if (NL_FAILED(nl_path_release(s.world, tickets[i]))) ++wrong_result;
        }
    }
    CHECK_MSG(wrong_calls == 0, "%d requests' callbacks did not run exactly once", wrong_calls);
    CHECK_MSG(wrong_ticket == 0, "%d callbacks got another ticket", wrong_ticket);
    CHECK_MSG(wrong_outcome == 0, "%d callbacks got another outcome than nl_path_find's", wrong_outcome);
    CHECK_MSG(wrong_result == 0, "%d queued results differ from nl_path_find's", wrong_result);
    CHECK_MSG(on_main == 0, "%d callbacks ran on the main thread (nobody called nl_path_process there)", on_main);
    CHECK(released_in_callback == MANY / 10);
    CHECK_MSG(wrong_callback_read == 0, "%d callbacks could not read and release their own ticket",
              wrong_callback_read);
    st = queue_stats(s.world);
    CHECK(st.unreleased == 0u && st.finished == MANY && st.submitted == MANY);

    /* Destroyed with requests queued and running: still exactly one callback each. */
    {
        int cancelled = 0, planned = 0, others = 0;
        atomic_store(&g_many.completions, 0);
        for (i = 0; i < MANY; ++i) {
            nl_path_request_def def = defs[i % VARIANTS];
            atomic_store(&g_many.slots[i].calls, 0);
            g_many.slots[i].release_in_callback = 0;
            g_many.slots[i].callback_outcome = NL_PATH_PENDING;
            def.callback = count_completion;
            def.user = &g_many.slots[i];
            if (NL_FAILED(nl_path_request(s.world, &def, &tickets[i]))) ++refused;
        }
        nl_world_destroy(s.world);
        wrong_calls = 0;
        for (i = 0; i < MANY; ++i) {
            const nl_path_outcome o = g_many.slots[i].callback_outcome;
            if (atomic_load(&g_many.slots[i].calls) != 1) ++wrong_calls;
            if (o == NL_PATH_CANCELLED)
                ++cancelled;
            else if (o == NL_PATH_COMPLETE || o == NL_PATH_PARTIAL)
                ++planned;
            else
                ++others;
        }
        CHECK(refused == 0);
        CHECK_MSG(atomic_load(&g_many.completions) == MANY && wrong_calls == 0,
                  "destroyed with requests in flight: %d callbacks, %d requests not called back exactly once",
                  atomic_load(&g_many.completions), wrong_calls);
        CHECK_MSG(others == 0, "%d callbacks with an outcome other than planned or cancelled", others);
        printf("note: world destroyed with %d requests in flight: %d planned, %d cancelled\n", MANY, planned,
               cancelled);
    }
    free(tickets);
}

/* A callback that tries to wait for its own request (refused: it runs on a thread that finishes them). */
typedef struct waiting_callback {
    nl_world* world;
    nl_status status;
} waiting_callback;

static void wait_in_callback(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    waiting_callback* w = (waiting_callback*)user;
    nl_path_outcome seen;
    (void)outcome;
    w->status = nl_path_wait(w->world, ticket, NL_PATH_WAIT_FOREVER, &seen);
}

static void waiting(void) {
    enum { N = 3, WAITED = 32 };
    /* Without path workers the waiting thread plans, oldest first, and no further than its request. */
    islands s = make_islands(0);
    nl_path_ticket tickets[N];
    call_log logs[N];
    nl_path_outcome outcome = 99;
    waiting_callback in_callback;
    nl_path_request_def def;
    nl_path_ticket ticket;
    int i;
    memset(logs, 0, sizeof logs);
    for (i = 0; i < N; ++i) {
        def = jumper(s.navmesh, 0.5f, 5.5f);
        def.callback = record_call;
        def.user = &logs[i];
        CHECK_OK(nl_path_request(s.world, &def, &tickets[i]));
    }
    CHECK(nl_path_wait(s.world, tickets[1], 0, &outcome) == NL_STATUS_IN_PROGRESS && outcome == NL_PATH_PENDING);
    CHECK(nl_get_last_status() == NL_STATUS_IN_PROGRESS && nl_get_last_error_message()[0] == '\0');
    CHECK(logs[0].calls == 0 && logs[1].calls == 0);
    CHECK_OK(nl_path_wait(s.world, tickets[1], NL_PATH_WAIT_FOREVER, &outcome));
    CHECK(outcome == NL_PATH_COMPLETE);
    CHECK(logs[0].calls == 1 && logs[1].calls == 1 && logs[2].calls == 0);
    CHECK(pthread_equal(logs[1].thread, pthread_self()));
    CHECK(poll_outcome(s.world, tickets[2]) == NL_PATH_PENDING);
    CHECK_OK(nl_path_wait(s.world, tickets[2], 60000, &outcome));
    CHECK(outcome == NL_PATH_COMPLETE && logs[2].calls == 1);
    CHECK_OK(nl_path_wait(s.world, tickets[2], 0, &outcome)); /* finished: any timeout answers at once */
    for (i = 0; i < N; ++i) CHECK_OK(nl_path_release(s.world, tickets[i]));
    CHECK_FAIL(nl_path_wait(s.world, tickets[0], NL_PATH_WAIT_FOREVER, &outcome), NL_STATUS_INVALID_HANDLE, "ticket");

    in_callback.world = s.world;
    in_callback.status = 0;
    def = jumper(s.navmesh, 0.5f, 5.5f);
    def.callback = wait_in_callback;
    def.user = &in_callback;
    CHECK_OK(nl_path_request(s.world, &def, &ticket));
    CHECK_OK(nl_path_wait(s.world, ticket, NL_PATH_WAIT_FOREVER, &outcome));
    CHECK_MSG(in_callback.status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT),
              "nl_path_wait inside a path callback returned 0x%x", (unsigned)in_callback.status);
    CHECK_OK(nl_path_release(s.world, ticket));
    nl_world_destroy(s.world);

    /* With path workers the waiting thread sleeps until a worker has finished its request. */
    {
        islands t = make_islands(2);
        nl_path_ticket many[WAITED];
        int wrong = 0;
        for (i = 0; i < WAITED; ++i) {
            def = jumper(t.navmesh, i % 2 ? 0.5f : 5.5f, i % 2 ? 5.5f : 0.5f);
            CHECK_OK(nl_path_request(t.world, &def, &many[i]));
        }
        for (i = 0; i < WAITED; ++i) {
            if (NL_FAILED(nl_path_wait(t.world, many[i], NL_PATH_WAIT_FOREVER, &outcome)) ||
                outcome != NL_PATH_COMPLETE || poll_outcome(t.world, many[i]) != NL_PATH_COMPLETE)
                ++wrong;
            CHECK_OK(nl_path_release(t.world, many[i]));
        }
        CHECK_MSG(wrong == 0, "%d of %d waits did not end with the complete path", wrong, (int)WAITED);
        nl_world_destroy(t.world);
    }
}

/* nl_path_explain on the islands (cells 0-2, 4-6 and 8-10 along x): the jump across the first gap
   is 1.2 m end to end; the drop is 2 m down from x = 8.1 to 6.9, and a jump of 2 m up the other way. */
static nl_path_shortfall explain(nl_world* world, const nl_path_request_def* def) {
    nl_path_shortfall out = nl_path_shortfall_init();
    CHECK_OK(nl_path_explain(world, def, &out));
    return out;
}

static void explain_shortfalls(void) {
    islands s = make_islands(0);
    nl_path_request_def def = jumper(s.navmesh, 0.5f, 5.5f);
    nl_path_shortfall why;
    nl_navmesh_id bare;

    def.capabilities.max_jump_distance = 1.0f;
    why = explain(s.world, &def);
    CHECK(why.reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY && why.limit == NL_LINK_LIMIT_JUMP_DISTANCE);
    CHECK(fabsf(why.needed - 1.2f) < 1e-3f && why.has == 1.0f);
    CHECK(same_link(why.link, s.jump) && why.reversed == 0);
    CHECK_THAT(strstr(why.text, "it needs a jump of 1.2 m across, and the body jumps 1 m (max_jump_distance)") != NULL,
               why.text);

    /* Up the drop: a jump of 2 m up, the drop taken from its end. */
    def = jumper(s.navmesh, 5.5f, 9.5f);
    why = explain(s.world, &def);
    CHECK(why.reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY && why.limit == NL_LINK_LIMIT_JUMP_HEIGHT);
    CHECK(why.needed == 2.0f && why.has == 0.0f && why.reversed == 1 && same_link(why.link, s.drop));
    CHECK(fabsf(why.link_start[0] - 6.9f) < 0.05f && fabsf(why.link_start[2] - 0.5f) < 0.05f);
    CHECK_THAT(strstr(why.text, "a drop taken back up at (6.9, 0, 0.5) would get there") != NULL, why.text);

    /* Down it with a body that drops 1 m. */
    def = jumper(s.navmesh, 9.5f, 5.5f);
    def.capabilities.max_drop_height = 1.0f;
    why = explain(s.world, &def);
    CHECK(why.reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY && why.limit == NL_LINK_LIMIT_DROP_HEIGHT);
    CHECK(why.needed == 2.0f && why.has == 1.0f && why.reversed == 0);

    /* Able enough: nothing to say, whatever the outcome needs. */
    def.capabilities.max_drop_height = 2.0f;
    why = explain(s.world, &def);
    CHECK(why.reason == NL_PATH_SHORTFALL_NONE && why.text[0] == '\0' && why.link.index1 == 0u);

    /* The same map without links. */
    bare = add_cells(s.world, k_islands, 1, 0.0f);
    def = jumper(bare, 0.5f, 5.5f);
    why = explain(s.world, &def);
    CHECK(why.reason == NL_PATH_SHORTFALL_NO_LINKS);
    CHECK_THAT(strstr(why.text, "the navmesh has no links") != NULL, why.text);
    nl_world_destroy(s.world);
}

ABI_SECTION(paths, ABI_CASE(defaults), ABI_CASE(find_synchronous), ABI_CASE(costs_and_radius), ABI_CASE(bad_input),
            ABI_CASE(explain_shortfalls), ABI_CASE(queue_manual), ABI_CASE(snapshots), ABI_CASE(queue_workers),
            ABI_CASE(waiting));
