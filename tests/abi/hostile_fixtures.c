/*
 * The fixtures of navlink-abi-hostile-test (hostile_fixtures.h says what each is for): the bad
 * values, worlds A and B and their fingerprints, and the shapes the cases of every part take.
 */
/* mkdtemp(), mkdir(); strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile_fixtures.h"
#include "scene.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---------------------------------------------------------------------------------------------
 * Bad values
 * ------------------------------------------------------------------------------------------- */

const bad_float k_bad_floats[3] = {{"NaN", NAN}, {"inf", INFINITY}, {"-inf", -INFINITY}};

size_t bad_ids(raw_id live, raw_id stale, raw_id foreign, bad_id* out) {
    size_t n = 0, k;
    const raw_id garbage[] = {
        {live.index1, live.revision + 1u},          /* the slot's next counter */
        {live.index1, live.revision ^ 0x80000000u}, /* another world's tag, same counter */
        {live.index1 + 1000u, live.revision},       /* past the last slot */
        {0xffffffffu, 0xffffffffu},
        {0x7fffffffu, 1u},
        {0x9e3779b9u, 0x7f4a7c15u}, /* pseudo-random */
        {0x2545f491u, 0x4f6cdd1du},
    };
    snprintf(out[n].what, sizeof out[n].what, "null");
    out[n++].id = (raw_id){0u, 0u};
    snprintf(out[n].what, sizeof out[n].what, "null {0, %u} (a live revision)", (unsigned)live.revision);
    out[n++].id = (raw_id){0u, live.revision};
    if (stale.index1 != 0u) {
        snprintf(out[n].what, sizeof out[n].what, "stale {%u, %u} (slot reused)", (unsigned)stale.index1,
                 (unsigned)stale.revision);
        out[n++].id = stale;
    }
    for (k = 0; k < sizeof garbage / sizeof *garbage; ++k) {
        snprintf(out[n].what, sizeof out[n].what, "garbage {%u, %u}", (unsigned)garbage[k].index1,
                 (unsigned)garbage[k].revision);
        out[n++].id = garbage[k];
    }
    snprintf(out[n].what, sizeof out[n].what, "foreign {%u, %u}", (unsigned)foreign.index1, (unsigned)foreign.revision);
    out[n++].id = foreign;
    return n;
}

const float k_costs_nan[3] = {1, NAN, 1}, k_costs_inf[3] = {1, INFINITY, 1}, k_costs_minus_inf[3] = {1, -INFINITY, 1};
const float k_costs_negative[3] = {1, 1, -1};
float k_costs_257[257];

/* ---------------------------------------------------------------------------------------------
 * The worlds: A is under test; B, built the same way, issues the foreign ids
 * ------------------------------------------------------------------------------------------- */

world_fixture A, B;

/* The top of the movable box, handed over as a navmesh: one quad, counter-clockwise from above. */
static const float k_quad[12] = {40, 0, -2, 40, 0, 2, 44, 0, 2, 44, 0, -2};
static const uint32_t k_quad_indices[4] = {0, 1, 2, 3};
static const uint8_t k_quad_corners[1] = {4};
static const uint8_t k_quad_area[1] = {3};
static const float k_quad_detail[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, 0.1f, 2, 44, 0.1f, -2};
static const uint32_t k_quad_detail_triangles[6] = {0, 1, 2, 0, 2, 3};
static const uint32_t k_quad_detail_starts[2] = {0, 2};

nl_navmesh_def quad_navmesh_def(void) {
    nl_navmesh_def def = navmesh_def_of(k_quad, 4, k_quad_indices, k_quad_corners, 1);
    def.areas = k_quad_area;
    set_navmesh_detail(&def, k_quad_detail, 4, k_quad_detail_triangles, 2, k_quad_detail_starts);
    return def;
}

nl_navmesh_def tile_navmesh_def(int32_t tile_x, int32_t tile_z) {
    static float vertices[TILE_ROWS][TILE_COLUMNS][12], detail[TILE_ROWS][TILE_COLUMNS][12];
    nl_navmesh_def def;
    float* v;
    float* d;
    float x0, z0, x1, z1;
    int k;
    if (tile_x < 0 || tile_x >= TILE_COLUMNS || tile_z < 0 || tile_z >= TILE_ROWS) fixture_failed("no such tile");
    v = vertices[tile_z][tile_x];
    d = detail[tile_z][tile_x];
    x0 = TILE_ORIGIN_X + (float)tile_x * TILE_WIDTH;
    z0 = TILE_ORIGIN_Z + (float)tile_z * TILE_WIDTH;
    x1 = x0 + TILE_WIDTH;
    z1 = z0 + TILE_WIDTH;
    {
        /* As k_quad: (x0, z0), (x0, z1), (x1, z1), (x1, z0). */
        const float corners[12] = {x0, 0, z0, x0, 0, z1, x1, 0, z1, x1, 0, z0};
        memcpy(v, corners, sizeof corners);
    }
    for (k = 0; k < 12; ++k) d[k] = k % 3 == 1 ? 0.1f : v[k];
    def = navmesh_def_of(v, 4, k_quad_indices, k_quad_corners, 1);
    def.areas = k_quad_area;
    set_navmesh_detail(&def, d, 4, k_quad_detail_triangles, 2, k_quad_detail_starts);
    def.tile_width = TILE_WIDTH;
    def.tile_origin_x = TILE_ORIGIN_X;
    def.tile_origin_z = TILE_ORIGIN_Z;
    def.tile_x = tile_x;
    def.tile_z = tile_z;
    return def;
}

uint32_t navmesh_tiles(const world_fixture* f, nl_navmesh_id id, nl_tile_coord* out, uint32_t capacity) {
    uint32_t count = 0;
    if (NL_FAILED(nl_navmesh_get_tiles(f->world, id, out, capacity, &count))) fixture_failed("nl_navmesh_get_tiles");
    return count;
}

nl_link_def gap_link_def(void) {
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

nl_path_request_def gap_request(nl_navmesh_id navmesh) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    def.start[0] = -6.0f;
    def.goal[0] = 6.0f;
    def.capabilities.max_jump_distance = 6.0f;
    def.capabilities.max_jump_height = 1.5f;
    def.capabilities.max_drop_height = 2.0f;
    return def;
}

nl_agent_def jumper_def(nl_navmesh_id navmesh, float x, float z) {
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

int in_the_air(nl_agent_state state) {
    return state == NL_AGENT_JUMPING || state == NL_AGENT_FALLING || state == NL_AGENT_TRAVERSING;
}

void fixture_failed(const char* what) {
    fprintf(stderr, "fixture: %s: %s\n", what, nl_get_last_error_message());
    exit(4);
}

nl_navmesh_info navmesh_info(const world_fixture* f, nl_navmesh_id id) {
    nl_navmesh_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_get_info(f->world, id, &info))) fixture_failed("nl_navmesh_get_info");
    return info;
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
    if (NL_FAILED(add_box_mesh(f->world, lift_lo, lift_hi, 0u, &f->stale_mesh)) ||
        NL_FAILED(nl_mesh_remove(f->world, f->stale_mesh)))
        fixture_failed("the doomed mesh");
    if (NL_FAILED(add_box_mesh(f->world, platform_lo[0], platform_hi[0], 0u, &f->mesh)) ||
        NL_FAILED(add_box_mesh(f->world, platform_lo[1], platform_hi[1], 0u, &scratch)) ||
        NL_FAILED(add_box_mesh(f->world, pit_lo, pit_hi, 0u, &scratch)) ||
        NL_FAILED(add_box_mesh(f->world, lift_lo, lift_hi, NL_MESH_MOVABLE, &f->movable)))
        fixture_failed("the level");
    if (NL_FAILED(nl_navmesh_add(f->world, &quad, &doomed_navmesh)) ||
        NL_FAILED(nl_navmesh_remove(f->world, doomed_navmesh)))
        fixture_failed("the doomed navmesh");
    f->stale_navmesh = doomed_navmesh;
    if (NL_FAILED(nl_navmesh_build(f->world, &build, &f->navmesh))) fixture_failed("nl_navmesh_build");
    if (NL_FAILED(nl_navmesh_add(f->world, &quad, &f->host_navmesh))) fixture_failed("nl_navmesh_add");
    if (NL_FAILED(nl_link_add(f->world, f->navmesh, &link, &doomed_link)) ||
        NL_FAILED(nl_link_remove(f->world, doomed_link)))
        fixture_failed("the doomed link");
    f->stale_link = doomed_link;
    if (NL_FAILED(nl_navmesh_generate_links(f->world, f->navmesh, NULL, NULL, NULL, NULL)))
        fixture_failed("generate_links");
    if (NL_FAILED(nl_link_add(f->world, f->navmesh, &link, &f->link))) fixture_failed("nl_link_add");
    {
        uint32_t count = 0;
        if (NL_FAILED(nl_world_get_plugins(f->world, &f->plugin, 1, &count))) fixture_failed("nl_world_get_plugins");
    }
    request = gap_request(f->navmesh);
    if (NL_FAILED(nl_path_request(f->world, &request, &f->done_ticket)) ||
        NL_FAILED(nl_path_process(f->world, NL_TEST_BUDGET(0, 0.0), NULL)) ||
        NL_FAILED(nl_path_request(f->world, &request, &f->stale_ticket)) ||
        NL_FAILED(nl_path_process(f->world, NL_TEST_BUDGET(0, 0.0), NULL)) ||
        NL_FAILED(nl_path_release(f->world, f->stale_ticket)) ||
        NL_FAILED(nl_path_request(f->world, &request, &f->pending_ticket)))
        fixture_failed("the path tickets");
    {
        /* The agents: a stale id whose slot the walker took; the flyer stepped until it is on a link
           over the gap; then the walker sent across, its path planned by one short step. */
        const nl_agent_def walker = jumper_def(f->navmesh, -8.0f, 3.0f), flyer = jumper_def(f->navmesh, -3.0f, -3.0f);
        static const float walker_goal[3] = {8.0f, 0.0f, 3.0f}, flyer_goal[3] = {4.0f, 0.0f, -3.0f};
        nl_agent_info info = nl_agent_info_init();
        int step;
        if (NL_FAILED(nl_agent_add(f->world, &walker, &f->stale_agent)) ||
            NL_FAILED(nl_agent_remove(f->world, f->stale_agent)))
            fixture_failed("the doomed agent");
        if (NL_FAILED(nl_agent_add(f->world, &walker, &f->agent)) ||
            NL_FAILED(nl_agent_add(f->world, &flyer, &f->flyer)) ||
            NL_FAILED(nl_agent_set_destination(f->world, f->flyer, flyer_goal)))
            fixture_failed("the agents");
        for (step = 0; step < 300 && !in_the_air(info.state); ++step) {
            if (NL_FAILED(nl_world_step(f->world, 1.0f / 30.0f)) ||
                NL_FAILED(nl_agent_get_info(f->world, f->flyer, &info)))
                fixture_failed("the flyer's steps");
        }
        if (!in_the_air(info.state)) fixture_failed("the flyer never took off");
        if (NL_FAILED(nl_agent_set_destination(f->world, f->agent, walker_goal)) ||
            NL_FAILED(nl_world_step(f->world, 0.001f)) ||
            NL_FAILED(nl_world_get_agent_events(f->world, NULL, 0, &f->agent_events)) ||
            NL_FAILED(nl_agent_get_info(f->world, f->flyer, &info)) || !in_the_air(info.state))
            fixture_failed("the walker's path");
    }
    {
        /* The tiled navmesh: a host's tile (a navmesh of one tile), then the tile beside it. */
        const nl_navmesh_def first = tile_navmesh_def(0, 0), second = tile_navmesh_def(1, 0);
        if (NL_FAILED(nl_navmesh_add(f->world, &first, &f->tiled)) ||
            NL_FAILED(nl_navmesh_add_tile(f->world, f->tiled, &second)))
            fixture_failed("the tiled navmesh");
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

nl_status mesh_get_info_call(nl_world* w, raw_id id, void* out) {
    return nl_mesh_get_info(w, AS(nl_mesh_id, id), (nl_mesh_info*)out);
}
nl_status navmesh_get_info_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_get_info(w, AS(nl_navmesh_id, id), (nl_navmesh_info*)out);
}
nl_status description_call(nl_world* w, raw_id id, void* out) {
    return nl_plugin_get_description(w, AS(nl_plugin_id, id), (nl_plugin_description*)out);
}
nl_status get_meshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_meshes(w, (nl_mesh_id*)out, capacity, count);
}
nl_status get_navmeshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_navmeshes(w, (nl_navmesh_id*)out, capacity, count);
}
nl_status get_plugins(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
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

/* The status of listing the navmeshes, then what `put_one` writes for each (at most 16). */
typedef void put_navmesh_fn(blob* s, nl_world* w, nl_navmesh_id id);
static void put_each_navmesh(blob* s, nl_world* w, put_navmesh_fn* put_one) {
    aligned_buffer ids;
    uint32_t i, n = 0;
    memset(ids.bytes, 0, sizeof ids.bytes);
    put_status(s, get_navmeshes(w, ids.bytes, 16, &n));
    for (i = 0; i < n && i < 16; ++i) {
        raw_id id;
        memcpy(&id, ids.bytes + i * sizeof id, sizeof id);
        put_one(s, w, AS(nl_navmesh_id, id));
    }
}

/* A navmesh's links (put_each_navmesh: every link of every navmesh). */
static void put_links(blob* s, nl_world* w, nl_navmesh_id id) {
    uint32_t count = 0;
    nl_link* links;
    put_status(s, nl_navmesh_get_links(w, id, NULL, 0, &count));
    links = (nl_link*)calloc(count + 1u, sizeof *links);
    if (!links) exit(2);
    links[0] = nl_link_init();
    put_status(s, nl_navmesh_get_links(w, id, links, count, &count));
    put(s, &count, sizeof count);
    put(s, links, count * sizeof *links);
    free(links);
}

/* A path's result and points, from the done ticket or planned now. */
typedef nl_status path_fn(const world_fixture* f, nl_path_result* result, nl_path_point* points, uint32_t capacity,
                          uint32_t* count);
static nl_status done_ticket_path(const world_fixture* f, nl_path_result* result, nl_path_point* points,
                                  uint32_t capacity, uint32_t* count) {
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

/* The tiles a navmesh has loaded (put_each_navmesh: those of every navmesh). */
static void put_tiles(blob* s, nl_world* w, nl_navmesh_id id) {
    nl_tile_coord tiles[64];
    uint32_t count = 0;
    memset(tiles, 0, sizeof tiles);
    put_status(s, nl_navmesh_get_tiles(w, id, tiles, 64, &count));
    put(s, &count, sizeof count);
    put(s, tiles, sizeof tiles);
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
    for (k = 0; k < 10; ++k) {
        static const char* names[10] = {"meshes",     "navmeshes",   "links",          "plugins",
                                        "path queue", "done ticket", "the known path", "the manual link and rays",
                                        "agents",     "tiles"};
        s.size = 0;
        switch (k) {
            case 0: put_each(&s, f->world, get_meshes, mesh_get_info_call, sizeof(nl_mesh_info)); break;
            case 1: put_each(&s, f->world, get_navmeshes, navmesh_get_info_call, sizeof(nl_navmesh_info)); break;
            case 2: put_each_navmesh(&s, f->world, put_links); break;
            case 3: put_each(&s, f->world, get_plugins, description_call, sizeof(nl_plugin_description)); break;
            case 4: put_queue(&s, f); break;
            case 5: put_path(&s, f, done_ticket_path); break;
            case 6: put_path(&s, f, known_path); break;
            case 7: put_link_and_rays(&s, f); break;
            case 8: put_agents(&s, f); break;
            default: put_each_navmesh(&s, f->world, put_tiles); break;
        }
        section(&all, names[k], &s);
    }
    free(s.data);
    free(f->fingerprint);
    f->fingerprint = all.data;
    f->fingerprint_size = all.size;
}

/* The first section of `now` that differs from `then`, or NULL. */
static const char* first_difference(const unsigned char* then, size_t then_size, const unsigned char* now,
                                    size_t now_size) {
    size_t a = 0, b = 0;
    while (a < then_size && b < now_size) {
        const char* name = (const char*)then + a;
        uint64_t na, nb;
        const size_t la = strlen(name) + 1, lb = strlen((const char*)now + b) + 1;
        memcpy(&na, then + a + la, sizeof na);
        memcpy(&nb, now + b + lb, sizeof nb);
        if (strcmp(name, (const char*)now + b) != 0 || na != nb ||
            memcmp(then + a + la + 8, now + b + lb + 8, (size_t)na) != 0)
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
            snprintf(why + used, why_size - used, "%sworld %c: %s differ", same ? "" : "; ", k == 0 ? 'A' : 'B',
                     differs);
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
        if (NL_FAILED(nl_path_find(A.world, &request, &result, NULL, 0, &count)) ||
            result.outcome != NL_PATH_COMPLETE || result.links_used == 0)
            fixture_failed("the known path does not take a link");
        if (NL_FAILED(nl_path_poll(A.world, A.pending_ticket, &pending)) || pending != NL_PATH_PENDING)
            fixture_failed("the pending ticket is not pending");
        if (A.mesh.index1 != A.stale_mesh.index1 || A.navmesh.index1 != A.stale_navmesh.index1 ||
            A.pending_ticket.index1 != A.stale_ticket.index1 || A.link.index1 != B.link.index1 ||
            (A.link.revision & 0xfffffu) != (B.link.revision & 0xfffffu) || A.agent.index1 != A.stale_agent.index1 ||
            A.agent.index1 != B.agent.index1 || (A.agent.revision & 0xfffffu) != (B.agent.revision & 0xfffffu) ||
            A.flyer.index1 != B.flyer.index1 || A.agent_events == 0u || A.tiled.index1 != B.tiled.index1 ||
            (A.tiled.revision & 0xfffffu) != (B.tiled.revision & 0xfffffu))
            fixture_failed("stale and foreign ids do not share slots with live ones");
        {
            nl_tile_coord tiles[4];
            if (navmesh_tiles(&A, A.tiled, tiles, 4) != 2u || tiles[0].x != 0 || tiles[0].z != 0 || tiles[1].x != 1 ||
                tiles[1].z != 0 || navmesh_info(&A, A.tiled).tile_count != 2u)
                fixture_failed("the tiled navmesh does not hold tiles (0, 0) and (1, 0)");
        }
    }
    refresh_worlds();
}

const hostile_fixture hostile_worlds = {setup_worlds, worlds_unchanged, refresh_worlds, teardown_worlds};

/* ---------------------------------------------------------------------------------------------
 * The shapes every case takes: defs made bad field by field, sizes, ids, lists
 * ------------------------------------------------------------------------------------------- */

void* copy_def(aligned_buffer* buffer, const void* def, size_t size) {
    memset(buffer->bytes, SENTINEL, sizeof buffer->bytes);
    memcpy(buffer->bytes, def, size);
    return buffer->bytes;
}

void set_size(void* def, uint32_t size) { memcpy(def, &size, sizeof size); }

void def_cases(const char* function, const void* valid, size_t size, const def_case* cases, size_t count,
               refuse_fn* refuse, accept_fn* accept) {
    size_t i, k;
    for (i = 0; i < count; ++i) {
        CASE(function, "%s", cases[i].description) {
            aligned_buffer buffer;
            unsigned char* def = (unsigned char*)copy_def(&buffer, valid, size);
            for (k = 0; k < sizeof cases[i].set / sizeof *cases[i].set; ++k)
                memcpy(def + cases[i].set[k].offset, &cases[i].set[k].as, cases[i].set[k].size);
            if (cases[i].detail == ALLOWED)
                accept(def);
            else
                refuse(def, cases[i].detail, cases[i].needle);
        }
    }
}

void bad_float_fields(const char* function, const char* param, const void* valid, size_t size,
                      const float_field* fields, size_t field_count, refuse_fn* refuse) {
    size_t i, v;
    unsigned k;
    for (i = 0; i < field_count; ++i) {
        for (k = 0; k < fields[i].count; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                char subject[96];
                if (fields[i].count > 1)
                    snprintf(subject, sizeof subject, "%s->%s[%u]", param, fields[i].name, k);
                else
                    snprintf(subject, sizeof subject, "%s->%s", param, fields[i].name);
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

void def_sizes(const char* function, const char* param, const void* valid, size_t size, refuse_fn* refuse,
               accept_fn* accept) {
    static const char* what[3] = {"0", "small (4)", "large (sizeof + 64, garbage after the struct)"};
    const uint32_t sizes[3] = {0u, 4u, (uint32_t)size + 64u};
    int k;
    for (k = 0; k < 3; ++k) {
        CASE(function, "%s->size %s", param, what[k]) {
            aligned_buffer buffer;
            void* def = copy_def(&buffer, valid, size);
            set_size(def, sizes[k]);
            if (k < 2)
                refuse(def, NL_STATUS_INVALID_ARGUMENT, "size");
            else
                accept(def);
        }
    }
}

const def_function* g_def;

void def_refuses(const void* def, nl_status detail, const char* needle) {
    unsigned char out[16];
    nl_status status;
    fill(out, sizeof out);
    status = g_def->call(A.world, def, out);
    EXPECT_FAILURE(g_def->no_world ? NULL : A.world, status, detail, needle);
    EXPECT_UNTOUCHED(out, g_def->out_size, "out_id");
    /* Accepted where it must be refused (the case failed): undone, so that the cases after it start
       from the worlds as they were, not from its leftovers. */
    if (NL_SUCCEEDED(status)) g_def->undo(out);
}

void def_accepts(const void* def) {
    unsigned char out[16];
    memset(out, 0, sizeof out);
    EXPECT_OK(g_def->call(A.world, def, out));
    g_def->undo(out);
}

void def_function_cases(const def_function* f, const void* valid, size_t size) {
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
            EXPECT_INVALID(f->no_world ? NULL : A.world, f->call(A.world, valid, NULL),
                           f->no_world ? "out_world" : "out_id");
        }
    }
    if (f->def_optional) CASE(f->function, "def NULL (allowed: defaults)") {
            def_accepts(NULL);
        }
    else
        CASE(f->function, "def NULL") { def_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes(f->function, "def", valid, size, def_refuses, def_accepts);
}

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
    {"def->vertex_count huge (vertices NULL: not read)",
     "vertices",
     {GEOMETRY_VERTICES, GEOMETRY_VERTEX_COUNT},
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

void geometry_cases(const char* function, const void* valid, size_t size, const geometry_fields* g) {
    def_case rows[GEOMETRY_ROW_COUNT];
    size_t i;
    int k;
    memset(rows, 0, sizeof rows);
    for (i = 0; i < GEOMETRY_ROW_COUNT; ++i) {
        rows[i].description = k_geometry_rows[i].description;
        rows[i].detail = NL_STATUS_INVALID_ARGUMENT;
        rows[i].needle = k_geometry_rows[i].needle ? k_geometry_rows[i].needle : g->bad_vertex;
        for (k = 0; k < 2; ++k)
            rows[i].set[k] = geometry_value(g, k_geometry_rows[i].field[k], k_geometry_rows[i].value[k]);
    }
    def_cases(function, valid, size, rows, GEOMETRY_ROW_COUNT, def_refuses, def_accepts);
}

void optional_id_cases(const def_function* f, const void* valid, size_t size, size_t offset, const char* field,
                       raw_id live, raw_id stale, raw_id foreign) {
    aligned_buffer def;
    g_def = f;
    CASE(f->function, "%s null (allowed: none)", field) {
        memcpy(def.bytes, valid, size);
        memset(def.bytes + offset, 0, sizeof(raw_id));
        def_accepts(def.bytes);
    }
    FOR_BAD_IDS(bad, live, stale, foreign) {
        if (bad->id.index1 == 0u && bad->id.revision == 0u) continue; /* the null id: allowed above */
        CASE(f->function, "%s %s", field, bad->what) {
            memcpy(def.bytes, valid, size);
            memcpy(def.bytes + offset, &bad->id, sizeof bad->id);
            def_refuses(def.bytes, NL_STATUS_INVALID_HANDLE, field);
        }
    }
}

void remove_navmesh_out(const void* out) {
    nl_navmesh_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_navmesh_is_valid(A.world, id) == 1, "the new navmesh is not valid");
    EXPECT_OK(nl_navmesh_remove(A.world, id));
}

void* g_user_seen;

int32_t cancel_at_once(void* user, float fraction, const char* stage) {
    (void)fraction;
    (void)stage;
    ++*(int*)user;
    return 0;
}

int32_t note_user(void* user, float fraction, const char* stage) {
    (void)fraction;
    (void)stage;
    g_user_seen = user;
    return 1;
}

/* ---------------------------------------------------------------------------------------------
 * Outputs: sizes, ids, lists, savers
 * ------------------------------------------------------------------------------------------- */

void out_sizes(const char* function, const char* param, size_t size, out_call_fn* call) {
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

void out_element_sizes(const char* function, const char* param, size_t size, element_call_fn* call) {
    static const uint32_t too_small[2] = {0u, 4u};
    const size_t stride = size + 64u, room = 256u * stride + 64u;
    unsigned char* buffer = (unsigned char*)malloc(room);
    int k;
    if (!buffer) exit(2);
    for (k = 0; k < 3; ++k) {
        CASE(function,
             k == 0   ? "%s->size 0 (the first element's: unset)"
             : k == 1 ? "%s->size small (4)"
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

void id_cases(const id_function* f, raw_id live, raw_id stale, raw_id foreign) {
    aligned_buffer out;
    void* o = f->out_name ? out.bytes : NULL;
    const char* word = strrchr(f->param, '>') ? strrchr(f->param, '>') + 1 : f->param;
#define FRESH_OUTPUT()                                               \
    do {                                                             \
        fill(out.bytes, sizeof out.bytes);                           \
        if (f->growable) set_size(out.bytes, (uint32_t)f->out_size); \
    } while (0)
#define CHECK_OUTPUT_UNTOUCHED()                                                                  \
    EXPECT_UNTOUCHED(out.bytes + (f->growable ? 4 : 0), sizeof out.bytes - (f->growable ? 4 : 0), \
                     f->out_name ? f->out_name : "memory")
    CASE(f->function, "world NULL") {
        FRESH_OUTPUT();
        EXPECT_INVALID(NULL, f->call(NULL, live, o), "world");
        CHECK_OUTPUT_UNTOUCHED();
    }
    if (f->out_name && !f->out_null_elsewhere) {
        CASE(f->function, "%s NULL", f->out_name) {
            EXPECT_INVALID(A.world, f->call(A.world, live, NULL), f->out_name);
        }
    }
    FOR_BAD_IDS(bad, live, stale, foreign) {
        CASE(f->function, "%s %s%s", f->param, bad->what, f->answers ? " (an answer, not an error)" : "") {
            nl_status status;
            FRESH_OUTPUT();
            status = f->call(A.world, bad->id, o);
            if (f->answers)
                EXPECT_OK(status);
            else
                EXPECT_BAD_HANDLE(A.world, status, word);
            CHECK_OUTPUT_UNTOUCHED();
        }
    }
#undef FRESH_OUTPUT
#undef CHECK_OUTPUT_UNTOUCHED
}

nl_status answered(int32_t valid) {
    EXPECT(valid == 0, "says %d", (int)valid);
    return nl_get_last_status();
}

/* fill_items sets a growable list's first `size` after filling, and `untouched` skips it. */
int g_growable_items;
static void fill_items(unsigned char* items, size_t room, size_t item_size) {
    fill(items, room);
    if (g_growable_items) {
        const uint32_t size = (uint32_t)item_size;
        memcpy(items, &size, sizeof size);
    }
}
static size_t skipped(void) { return g_growable_items ? sizeof(uint32_t) : 0u; }

void list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected, list_call_fn* call) {
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
                EXPECT_FAILURE(A.world, call(items, k == 0 ? 0u : expected - 1u, &count), NL_STATUS_BUFFER_TOO_SMALL,
                               "capacity");
                EXPECT(count == expected, "out_count = %u, expected the %u needed", (unsigned)count,
                       (unsigned)expected);
                EXPECT_UNTOUCHED(items + skipped(), room - skipped(), out_name);
            }
        }
    }
    CASE(function, "capacity huge (a buffer of %u + 4 entries: only %u written)", (unsigned)expected,
         (unsigned)expected) {
        fill_items(items, room, item_size);
        count = 0xdeadbeefu;
        EXPECT_OK(call(items, UINT32_MAX, &count));
        EXPECT(count == expected, "out_count = %u, expected %u", (unsigned)count, (unsigned)expected);
        EXPECT_UNTOUCHED(items + expected * item_size, 4u * item_size, "the entries past out_count");
    }
    free(items);
}

static world_list_fn* g_world_list;
static nl_status call_world_list(void* out, uint32_t capacity, uint32_t* count) {
    return g_world_list(A.world, out, capacity, count);
}

void world_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
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

static navmesh_list_fn* g_navmesh_list;
static nl_navmesh_id g_navmesh_listed; /* the navmesh of A the list cases list from */
static nl_status call_navmesh_list(void* out, uint32_t capacity, uint32_t* count) {
    return g_navmesh_list(A.world, g_navmesh_listed, out, capacity, count);
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

void navmesh_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                        navmesh_list_fn* call) {
    navmesh_list_cases_on(function, out_name, item_size, expected, call, A.navmesh, B.navmesh);
}

void navmesh_list_cases_on(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                           navmesh_list_fn* call, nl_navmesh_id live, nl_navmesh_id foreign) {
    const id_function f = {function, "navmesh", out_name, 16 * item_size, 0, 0, navmesh_list_id_call, 1};
    g_navmesh_list = call;
    g_navmesh_listed = live;
    id_cases(&f, RAW(live), RAW(A.stale_navmesh), RAW(foreign));
    list_cases(function, out_name, item_size, expected, call_navmesh_list);
}

/* The saver the cases run now, into a buffer of what it writes + 64. */
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

void saver_cases(const char* function, const char* out_name, navmesh_saver* saver, const unsigned char* expected,
                 size_t needed, size_t terminator) {
    saver_cases_on(function, out_name, saver, expected, needed, terminator, A.navmesh, B.navmesh);
}

void saver_cases_on(const char* function, const char* out_name, navmesh_saver* saver, const unsigned char* expected,
                    size_t needed, size_t terminator, nl_navmesh_id live, nl_navmesh_id foreign) {
    const id_function f = {function, "navmesh", "buffer", 16, 0, 0, saver_id_call, 1};
    const size_t room = needed + terminator + 64;
    unsigned char* buffer = (unsigned char*)malloc(room);
    size_t length;
    if (!buffer) exit(2);
    g_saver = saver;
    g_save_buffer = buffer;
    g_save_room = room;
    id_cases(&f, RAW(live), RAW(A.stale_navmesh), RAW(foreign));
    CASE(function, "%s NULL", out_name) {
        fill(buffer, room);
        EXPECT_INVALID(A.world, saver(A.world, live, buffer, room, NULL), out_name);
        EXPECT_UNTOUCHED(buffer, room, "buffer");
    }
    CASE(function, "buffer NULL (allowed with capacity 0: measures)") {
        fill(&length, sizeof length);
        EXPECT_OK(saver(A.world, live, NULL, 0, &length));
        EXPECT(length == needed, "%s = %u, expected %u", out_name, (unsigned)length, (unsigned)needed);
    }
    CASE(function, "capacity huge (buffer NULL)") {
        fill(&length, sizeof length);
        EXPECT_INVALID(A.world, saver(A.world, live, NULL, SIZE_MAX, &length), "buffer");
        EXPECT_UNTOUCHED(&length, sizeof length, out_name);
    }
    {
        const size_t too_small[2] = {0, needed + terminator - 1};
        const char* what[2] = {"capacity 0 (a buffer given)", terminator
                                                                  ? "capacity small (the length: no room for the NUL)"
                                                                  : "capacity small (one byte short)"};
        int k;
        for (k = 0; k < 2; ++k) {
            CASE(function, "%s", what[k]) {
                fill(buffer, room);
                fill(&length, sizeof length);
                EXPECT_FAILURE(A.world, saver(A.world, live, buffer, too_small[k], &length), NL_STATUS_BUFFER_TOO_SMALL,
                               "capacity");
                EXPECT_UNTOUCHED(buffer, room, "buffer");
                EXPECT(length == needed, "%s = %u, expected the %u needed", out_name, (unsigned)length,
                       (unsigned)needed);
            }
        }
    }
    CASE(function, "capacity huge (64 bytes to spare: nothing written past the end)") {
        fill(buffer, room);
        EXPECT_OK(saver(A.world, live, buffer, room, &length));
        EXPECT(length == needed, "%s = %u, expected %u", out_name, (unsigned)length, (unsigned)needed);
        EXPECT(memcmp(buffer, expected, needed + terminator) == 0, "other bytes written");
        EXPECT_UNTOUCHED(buffer + needed + terminator, 64, "the bytes past the end");
    }
    free(buffer);
}

/* ---------------------------------------------------------------------------------------------
 * Files
 * ------------------------------------------------------------------------------------------- */

const char k_obj[] = "v 4 3 -1\nv 4 3 1\nv 6 3 1\nv 6 3 -1\nf 1 2 3 4\n";
char g_tmp[64];
char g_obj_path[128];

void write_file(const char* path, const char* text) {
    FILE* f = fopen(path, "wb");
    if (!f || fwrite(text, 1, strlen(text), f) != strlen(text)) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(4);
    }
    fclose(f);
}

void make_tmp(void) {
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

void remove_tmp(const char* const* names, size_t count) {
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

void bad_path_cases(const char* function, nl_status (*load)(const char* path, void* out), size_t out_size,
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

const bad_path k_bad_paths[4] = {
    {"path NULL", NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "path"},
    {"path empty", NULL, "", NL_STATUS_NOT_FOUND, "''"},
    {"path missing", "no-such-file", NULL, NL_STATUS_NOT_FOUND, "no-such-file"},
    {"path a directory", "dir.obj", NULL, NL_STATUS_IO_ERROR, "dir.obj"},
};

/* ---------------------------------------------------------------------------------------------
 * The last error record
 * ------------------------------------------------------------------------------------------- */

void fail_on_purpose(void) { (void)nl_mesh_remove(NULL, (nl_mesh_id){0u, 0u}); }

int record_is_the_failure(void) {
    return nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT) &&
           strcmp(nl_get_last_error_message(), "nl_mesh_remove: world is null") == 0;
}
