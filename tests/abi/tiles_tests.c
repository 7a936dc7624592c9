/*
 * Tiles (navlink.h, recast.h): a flat floor built in tiles (nl_recast_settings.tile_size), its tiles
 * listed and counted alike, taken out and put back at run time through the C ABI only: a path across
 * the floor cut where a column of tiles is out, and whole again once they are back; an agent standing
 * on a removed tile waits (NL_AGENT_EVENT_WAITING, NL_AGENT_REASON_TILE_UNLOADED) and goes on when its
 * tile is back. A tile is put back from the polygons of a second world built the same way (those whose
 * centre lies in the tile's square), as a streaming host would hand over a tile it kept.
 *
 * The floor is a box 40 x 1 x 12 m, its top at y = 0, x in [0, 40], z in [0, 12]: at Recast's default
 * cell size (0.3 m) a tile_size of 32 cells makes tiles of 9.6 m, five columns and two rows of them.
 *
 * Baked tiles (navmesh_file.h): a level of platforms with jumps between them built in tiles, its links
 * generated, every tile saved on its own (nl_navmesh_save_tile, nl_navmesh_save_tile_file) and loaded
 * into a second world in a shuffled order (nl_navmesh_load for the first, nl_navmesh_add_tile_bytes or
 * nl_navmesh_add_tile_file for the rest): the navmesh, its links and a path over them as they were.
 */
/* mkdtemp() for the tiles' files; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "navmesh_scene.h"
#include "scene.h"

#include <navlink/recast.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TILE_CELLS 32u
#define MAX_TILES 64u

typedef struct tiled_floor {
    nl_world* world;
    nl_navmesh_id navmesh;
    nl_navmesh_info info;
} tiled_floor;

/* The floor and its navmesh, built in tiles of TILE_CELLS cells (`tile_size` 0: whole). */
static tiled_floor make_floor(uint32_t tile_size) {
    static const float lo[3] = {0.0f, -1.0f, 0.0f}, hi[3] = {40.0f, 0.0f, 12.0f};
    nl_recast_settings settings = nl_default_recast_settings();
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_mesh_id mesh;
    tiled_floor f;
    memset(&f, 0, sizeof f);
    f.world = make_world(2);
    CHECK_OK(add_box_mesh(f.world, lo, hi, 0u, &mesh));
    settings.tile_size = tile_size;
    build.settings = &settings;
    CHECK_OK(nl_navmesh_build(f.world, &build, &f.navmesh));
    f.info = navmesh_info(f.world, f.navmesh);
    return f;
}

/* The loaded tiles (at most MAX_TILES); 0xdeadbeef if the call failed. */
static uint32_t tiles_of(const tiled_floor* f, nl_tile_coord* out) {
    uint32_t count = 0;
    if (!CHECK_OK(nl_navmesh_get_tiles(f->world, f->navmesh, out, MAX_TILES, &count))) return 0xdeadbeefu;
    return count;
}

static int has_tile(const nl_tile_coord* tiles, uint32_t count, int32_t x, int32_t z) {
    uint32_t i;
    for (i = 0; i < count && i < MAX_TILES; ++i)
        if (tiles[i].x == x && tiles[i].z == z) return 1;
    return 0;
}

/* The tile holding (x, z), by the navmesh's grid. */
static nl_tile_coord tile_at(const nl_navmesh_info* info, float x, float z) {
    nl_tile_coord t;
    t.x = (int32_t)floorf((x - info->tile_origin[0]) / info->tile_width);
    t.z = (int32_t)floorf((z - info->tile_origin[1]) / info->tile_width);
    return t;
}

/* The outcome of a walk from (x0, 0, z0) to (x1, 0, z1) for the navmesh's body; 0xffffffff if the call
   failed. A complete path is SUCCESS; a partial one (accept_partial, the default) SUCCESS with
   PARTIAL_RESULT. */
static nl_path_outcome walk(const tiled_floor* f, float x0, float z0, float x1, float z1) {
    nl_path_request_def def = nl_default_path_request_def();
    nl_path_result result;
    nl_status status;
    uint32_t count = 0;
    def.navmesh = f->navmesh;
    def.start[0] = x0, def.start[2] = z0;
    def.goal[0] = x1, def.goal[2] = z1;
    def.capabilities.radius = f->info.agent_type.radius;
    memset(&result, 0, sizeof result);
    result.size = sizeof result;
    status = nl_path_find(f->world, &def, &result, NULL, 0, &count);
    if (result.outcome == NL_PATH_PARTIAL) {
        if (!CHECK_MSG(status == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT),
                       "a partial path: status 0x%08x, expected SUCCESS | PARTIAL_RESULT", (unsigned)status))
            return 0xffffffffu;
    } else if (!CHECK_OK(status)) {
        return 0xffffffffu;
    }
    return result.outcome;
}

/* A tile as a host hands it over: the polygons of `from`'s navmesh whose centre lies in tile `t`'s
   square, their corners as they are there (copied into `tile`'s arrays), on the navmesh's grid and for
   its agent type. No height detail: the polygons are the surface. */
typedef struct host_tile {
    float* vertices;
    uint32_t* indices;
    uint8_t* corners;
    nl_navmesh_def def;
} host_tile;

static host_tile tile_from(const tiled_floor* from, nl_tile_coord t) {
    const float x0 = from->info.tile_origin[0] + (float)t.x * from->info.tile_width;
    const float z0 = from->info.tile_origin[1] + (float)t.z * from->info.tile_width;
    const float x1 = x0 + from->info.tile_width, z1 = z0 + from->info.tile_width;
    uint32_t vertex_count = 0, p, k, used = 0, index_count = 0, polygon_count = 0;
    float* all = navmesh_vertices(from->world, from->navmesh, &vertex_count);
    uint32_t* remap = (uint32_t*)malloc((vertex_count + 1u) * sizeof *remap);
    host_tile tile;
    memset(&tile, 0, sizeof tile);
    tile.vertices = (float*)malloc((3u * vertex_count + 3u) * sizeof *tile.vertices);
    tile.indices = (uint32_t*)malloc((size_t)from->info.polygon_count * NL_MAX_POLYGON_VERTICES * sizeof *tile.indices +
                                     sizeof *tile.indices);
    tile.corners = (uint8_t*)malloc(from->info.polygon_count + 1u);
    if (!all || !remap || !tile.vertices || !tile.indices || !tile.corners) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    for (k = 0; k < vertex_count; ++k) remap[k] = 0xffffffffu;
    for (p = 0; p < from->info.polygon_count; ++p) {
        nl_nav_polygon polygon = nl_nav_polygon_init();
        if (!CHECK_OK(nl_navmesh_get_polygon(from->world, from->navmesh, p, &polygon))) break;
        if (!(polygon.centre[0] >= x0 && polygon.centre[0] < x1 && polygon.centre[2] >= z0 && polygon.centre[2] < z1))
            continue;
        for (k = 0; k < polygon.vertex_count; ++k) {
            const uint32_t v = polygon.vertices[k];
            if (remap[v] == 0xffffffffu) {
                memcpy(tile.vertices + 3u * used, all + 3u * v, 3u * sizeof(float));
                remap[v] = used++;
            }
            tile.indices[index_count++] = remap[v];
        }
        tile.corners[polygon_count++] = (uint8_t)polygon.vertex_count;
    }
    tile.def = nl_default_navmesh_def();
    tile.def.vertices = tile.vertices;
    tile.def.vertex_count = used;
    tile.def.indices = tile.indices;
    tile.def.polygon_vertex_counts = tile.corners;
    tile.def.polygon_count = polygon_count;
    tile.def.agent_type = from->info.agent_type;
    tile.def.tile_width = from->info.tile_width;
    tile.def.tile_origin_x = from->info.tile_origin[0];
    tile.def.tile_origin_z = from->info.tile_origin[1];
    tile.def.tile_x = t.x;
    tile.def.tile_z = t.z;
    free(all);
    free(remap);
    return tile;
}

static void free_tile(host_tile* tile) {
    free(tile->vertices);
    free(tile->indices);
    free(tile->corners);
    memset(tile, 0, sizeof *tile);
}

/* ---------------------------------------------------------------------------------------------
 * Cases
 * ------------------------------------------------------------------------------------------- */

/* The floor in tiles of 9.6 m: its info and its list of tiles agree, in row order, on the floor. */
static void built_in_tiles(void) {
    tiled_floor f = make_floor(TILE_CELLS), whole;
    const nl_recast_settings recast = nl_default_recast_settings();
    nl_tile_coord tiles[MAX_TILES];
    uint32_t count, counted = 0, i;
    count = tiles_of(&f, tiles);
    CHECK_MSG(count > 1u && count <= 10u, "%u tiles: expected more than one, at most 5 x 2", (unsigned)count);
    CHECK_MSG(f.info.tile_count == count, "nl_navmesh_info.tile_count %u, nl_navmesh_get_tiles %u",
              (unsigned)f.info.tile_count, (unsigned)count);
    CHECK(NL_SUCCEEDED(nl_navmesh_get_tiles(f.world, f.navmesh, NULL, 0, &counted)) && counted == count);
    CHECK_NEAR(f.info.tile_width, TILE_CELLS * recast.cell_size, 1e-4f);
    CHECK_NEAR(f.info.tile_width, 9.6f, 1e-4f);
    CHECK(isfinite(f.info.tile_origin[0]) && isfinite(f.info.tile_origin[1]));
    for (i = 0; i < count && i < MAX_TILES; ++i) {
        /* Each tile overlaps the floor; row order: z, then x. */
        const float x0 = f.info.tile_origin[0] + (float)tiles[i].x * f.info.tile_width;
        const float z0 = f.info.tile_origin[1] + (float)tiles[i].z * f.info.tile_width;
        CHECK_MSG(x0 < 40.0f && x0 + f.info.tile_width > 0.0f && z0 < 12.0f && z0 + f.info.tile_width > 0.0f,
                  "tile (%d, %d) spans x from %g, z from %g: off the floor", (int)tiles[i].x, (int)tiles[i].z,
                  (double)x0, (double)z0);
        if (i > 0)
            CHECK_MSG(tiles[i - 1].z < tiles[i].z || (tiles[i - 1].z == tiles[i].z && tiles[i - 1].x < tiles[i].x),
                      "tiles %u and %u out of row order", (unsigned)(i - 1), (unsigned)i);
    }
    /* The floor's two ends and its middle each lie in a loaded tile. */
    {
        const float at[3][2] = {{2.0f, 6.0f}, {20.0f, 6.0f}, {38.0f, 6.0f}};
        int k;
        for (k = 0; k < 3; ++k) {
            const nl_tile_coord t = tile_at(&f.info, at[k][0], at[k][1]);
            CHECK_MSG(has_tile(tiles, count, t.x, t.z), "no tile loaded at (%g, %g)", (double)at[k][0],
                      (double)at[k][1]);
        }
    }
    CHECK(check_navmesh_structure(f.world, f.navmesh, "tiled floor") == 0);
    /* Built whole, the same floor is a solo navmesh: no tiles. */
    whole = make_floor(0u);
    CHECK(whole.info.tile_count == 0u && whole.info.tile_width == 0.0f);
    CHECK(tiles_of(&whole, tiles) == 0u);
    nl_world_destroy(whole.world);
    nl_world_destroy(f.world);
}

/* A path from one end of the floor to the other; the middle column of tiles (both rows) out: it no
   longer gets there; the tiles back (from a second world's polygons): it does again. */
static void removed_tiles_cut_the_path(void) {
    tiled_floor f = make_floor(TILE_CELLS), source = make_floor(TILE_CELLS);
    const nl_tile_coord middle = tile_at(&f.info, 20.0f, 6.0f);
    nl_tile_coord tiles[MAX_TILES], cut[2];
    uint32_t before, after, row;
    before = tiles_of(&f, tiles);
    cut[0].x = middle.x, cut[0].z = 0;
    cut[1].x = middle.x, cut[1].z = 1;
    CHECK(has_tile(tiles, before, cut[0].x, cut[0].z) && has_tile(tiles, before, cut[1].x, cut[1].z));
    CHECK(walk(&f, 2.0f, 6.0f, 38.0f, 6.0f) == NL_PATH_COMPLETE);
    CHECK(walk(&f, 2.0f, 6.0f, 38.0f, 11.0f) == NL_PATH_COMPLETE);

    for (row = 0; row < 2; ++row) CHECK_OK(nl_navmesh_remove_tile(f.world, f.navmesh, cut[row]));
    after = tiles_of(&f, tiles);
    CHECK_MSG(after == before - 2u, "%u tiles after removing 2 of %u", (unsigned)after, (unsigned)before);
    CHECK(!has_tile(tiles, after, cut[0].x, cut[0].z) && !has_tile(tiles, after, cut[1].x, cut[1].z));
    CHECK(navmesh_info(f.world, f.navmesh).tile_count == after);
    CHECK_THAT(walk(&f, 2.0f, 6.0f, 38.0f, 6.0f) == NL_PATH_PARTIAL,
               "with the middle column of tiles out, no path crosses the floor (a partial one)");
    CHECK_THAT(walk(&f, 2.0f, 6.0f, 38.0f, 11.0f) == NL_PATH_PARTIAL,
               "nor along the second row of tiles (a partial one)");
    CHECK(walk(&f, 2.0f, 6.0f, 8.0f, 6.0f) == NL_PATH_COMPLETE); /* one side still walks */
    /* Removed twice: NOT_FOUND, nothing changed. */
    CHECK_FAIL(nl_navmesh_remove_tile(f.world, f.navmesh, cut[0]), NL_STATUS_NOT_FOUND, "is loaded");
    CHECK(tiles_of(&f, tiles) == after);

    /* Back, as a host hands them over: the path crosses again. */
    for (row = 0; row < 2; ++row) {
        host_tile tile = tile_from(&source, cut[row]);
        CHECK_MSG(tile.def.polygon_count > 0u, "tile (%d, %d) of the second world has no polygon", (int)cut[row].x,
                  (int)cut[row].z);
        CHECK_OK(nl_navmesh_add_tile(f.world, f.navmesh, &tile.def));
        /* Loaded once only. */
        CHECK_INVALID(nl_navmesh_add_tile(f.world, f.navmesh, &tile.def), "loaded already");
        free_tile(&tile);
    }
    CHECK(tiles_of(&f, tiles) == before);
    CHECK(navmesh_info(f.world, f.navmesh).tile_count == before);
    CHECK(walk(&f, 2.0f, 6.0f, 38.0f, 6.0f) == NL_PATH_COMPLETE);
    CHECK(walk(&f, 2.0f, 6.0f, 38.0f, 11.0f) == NL_PATH_COMPLETE);
    CHECK(check_navmesh_structure(f.world, f.navmesh, "tiles back") == 0);
    nl_world_destroy(source.world);
    nl_world_destroy(f.world);
}

/* The events of the last step for `agent`: how many of `kind` with `reason`. */
static uint32_t events_of(nl_world* world, nl_agent_id agent, nl_agent_event_kind kind, nl_agent_reason reason) {
    nl_agent_event events[32];
    uint32_t n = 0, k, found = 0;
    events[0] = nl_agent_event_init();
    if (!CHECK_OK(nl_world_get_agent_events(world, events, 32, &n))) return 0u;
    for (k = 0; k < n && k < 32u; ++k)
        if (events[k].agent.index1 == agent.index1 && events[k].agent.revision == agent.revision &&
            events[k].kind == kind && events[k].reason == reason)
            ++found;
    return found;
}

/* An agent standing on a tile that is removed waits for it (WAITING, TILE_UNLOADED, said once), and
   goes on to its destination once the tile is back. */
static void agent_waits_for_its_tile(void) {
    tiled_floor f = make_floor(TILE_CELLS), source = make_floor(TILE_CELLS);
    const nl_tile_coord middle = tile_at(&f.info, 24.0f, 3.0f);
    const float goal[3] = {36.0f, 0.0f, 3.0f};
    nl_agent_def def = nl_default_agent_def();
    nl_agent_info info = nl_agent_info_init();
    nl_agent_id agent = {0u, 0u};
    host_tile tile;
    int step;
    def.navmesh = f.navmesh;
    def.position[0] = 24.0f, def.position[2] = 3.0f;
    def.user_data = 5u;
    CHECK_OK(nl_agent_add(f.world, &def, &agent));
    CHECK_OK(nl_agent_set_destination(f.world, agent, goal));

    CHECK_OK(nl_navmesh_remove_tile(f.world, f.navmesh, middle));
    CHECK_OK(nl_world_step(f.world, 1.0f / 30.0f));
    CHECK_THAT(events_of(f.world, agent, NL_AGENT_EVENT_WAITING, NL_AGENT_REASON_TILE_UNLOADED) == 1u,
               "the step after its tile went: one WAITING event, reason TILE_UNLOADED");
    CHECK_OK(nl_agent_get_info(f.world, agent, &info));
    CHECK_MSG(info.state == NL_AGENT_WAITING && info.reason == NL_AGENT_REASON_TILE_UNLOADED,
              "nl_agent_get_info: state %u, reason %u; expected WAITING, TILE_UNLOADED", (unsigned)info.state,
              (unsigned)info.reason);
    CHECK_NEAR(info.position[0], 24.0f, 0.05f);
    CHECK_NEAR(info.position[2], 3.0f, 0.05f);
    /* It stays where it stood, waiting; the event was said once. */
    for (step = 0; step < 10; ++step) {
        CHECK_OK(nl_world_step(f.world, 1.0f / 30.0f));
        CHECK(events_of(f.world, agent, NL_AGENT_EVENT_WAITING, NL_AGENT_REASON_TILE_UNLOADED) == 0u);
    }
    CHECK_OK(nl_agent_get_info(f.world, agent, &info));
    CHECK(info.state == NL_AGENT_WAITING && info.reason == NL_AGENT_REASON_TILE_UNLOADED);
    CHECK_NEAR(info.position[0], 24.0f, 0.05f);
    CHECK_NEAR(info.position[2], 3.0f, 0.05f);

    /* The tile back: it plans again and arrives. */
    tile = tile_from(&source, middle);
    CHECK_OK(nl_navmesh_add_tile(f.world, f.navmesh, &tile.def));
    free_tile(&tile);
    {
        uint32_t replanned = 0;
        for (step = 0; step < 900 && info.state != NL_AGENT_ARRIVED; ++step) {
            CHECK_OK(nl_world_step(f.world, 1.0f / 30.0f));
            replanned += events_of(f.world, agent, NL_AGENT_EVENT_REPLANNED, NL_AGENT_REASON_WORLD_CHANGED);
            CHECK_OK(nl_agent_get_info(f.world, agent, &info));
            if (info.state == NL_AGENT_WAITING && info.reason == NL_AGENT_REASON_TILE_UNLOADED) break;
        }
        CHECK_THAT(replanned >= 1u, "its tile back, the agent plans again (REPLANNED, WORLD_CHANGED)");
        CHECK_MSG(info.state == NL_AGENT_ARRIVED, "state %u, reason %u after %d steps with its tile back",
                  (unsigned)info.state, (unsigned)info.reason, step);
        CHECK_NEAR(info.position[0], goal[0], 0.5f);
        CHECK_NEAR(info.position[2], goal[2], 0.5f);
    }
    nl_world_destroy(source.world);
    nl_world_destroy(f.world);
}

/* A link with an end on a removed tile is parked: it no longer holds (nl_link.holds 0), the navmesh is
   not saved (the file would not load back), and once the tile is built again it holds where it was. */
static void link_parked_while_its_tile_is_out(void) {
    tiled_floor f = make_floor(TILE_CELLS);
    const nl_tile_coord far_end = tile_at(&f.info, 36.0f, 6.0f);
    const float centre[3] = {36.0f, 0.0f, 6.0f};
    nl_recast_settings settings = nl_default_recast_settings();
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_link_def def = nl_default_link_def();
    nl_link link = nl_link_init();
    nl_link_id id;
    size_t size = 0;
    def.kind = NL_LINK_MANUAL;
    def.start[0] = 4.0f, def.start[2] = 6.0f;
    def.end[0] = 36.0f, def.end[2] = 6.0f;
    CHECK_OK(nl_link_add(f.world, f.navmesh, &def, &id));
    CHECK_OK(nl_link_get(f.world, id, &link));
    CHECK_THAT(link.holds == 1u, "a link with both ends on loaded tiles holds");
    CHECK_OK(nl_navmesh_save(f.world, f.navmesh, NULL, 0, &size));

    CHECK_OK(nl_navmesh_remove_tile(f.world, f.navmesh, far_end));
    CHECK_OK(nl_link_get(f.world, id, &link));
    CHECK_THAT(link.holds == 0u, "its end's tile out, the link is parked: holds 0");
    CHECK_FAIL(nl_navmesh_save(f.world, f.navmesh, NULL, 0, &size), NL_STATUS_INVALID_ARGUMENT, "not loaded");

    settings.tile_size = TILE_CELLS;
    build.settings = &settings;
    CHECK_OK(nl_navmesh_build_tiles(f.world, f.navmesh, &build, centre, centre));
    CHECK_OK(nl_link_get(f.world, id, &link));
    CHECK_THAT(link.holds == 1u, "its tile built again, the link holds");
    CHECK_NEAR(link.end[0], 36.0f, 0.01f);
    CHECK_OK(nl_navmesh_save(f.world, f.navmesh, NULL, 0, &size));
    nl_world_destroy(f.world);
}

/* ---------------------------------------------------------------------------------------------
 * Baked tiles
 * ------------------------------------------------------------------------------------------- */

/* Four platforms in a row, 8 x 6 m (x from 10 k to 10 k + 8, z in [0, 6]) with gaps of 2 m, the second
   and fourth 0.5 m higher (tops at y = 0 and 0.5), over a floor 3 m below the first: jumps between the
   platforms, drops to the floor. At 20 cells of 0.3 m the tiles are 6 m: seven columns and two rows
   from the floor's corner (-2, -2), so every jump starts on one tile and lands on another. */
static nl_world* make_platforms(void) {
    nl_world* world = make_world(2);
    static const float floor_lo[3] = {-2.0f, -4.0f, -2.0f}, floor_hi[3] = {40.0f, -3.0f, 8.0f};
    nl_mesh_id mesh;
    int k;
    for (k = 0; k < 4; ++k) {
        const float rise = k % 2 ? 0.5f : 0.0f;
        const float lo[3] = {10.0f * (float)k, -1.0f + rise, 0.0f}, hi[3] = {10.0f * (float)k + 8.0f, rise, 6.0f};
        CHECK_OK(add_box_mesh(world, lo, hi, 0u, &mesh));
    }
    CHECK_OK(add_box_mesh(world, floor_lo, floor_hi, 0u, &mesh));
    return world;
}

/* Every link of a navmesh by what it is, sorted (malloc'ed, `count` of them). */
typedef struct link_key {
    uint32_t kind;
    float start[3], end[3], apex[3];
    uint8_t bidirectional, generated, holds, pad;
} link_key;

static int compare_keys(const void* a, const void* b) { return memcmp(a, b, sizeof(link_key)); }

static link_key* link_keys(const nl_world* world, nl_navmesh_id navmesh, uint32_t* count) {
    nl_link* links;
    link_key* keys;
    uint32_t n = 0, i;
    *count = 0;
    if (!CHECK_OK(nl_navmesh_get_links(world, navmesh, NULL, 0, &n))) return NULL;
    links = (nl_link*)calloc(n + 1u, sizeof *links);
    keys = (link_key*)calloc(n + 1u, sizeof *keys);
    if (!links || !keys) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    links[0] = nl_link_init();
    if (!CHECK_OK(nl_navmesh_get_links(world, navmesh, links, n, &n))) n = 0;
    for (i = 0; i < n; ++i) {
        keys[i].kind = (uint32_t)links[i].kind;
        memcpy(keys[i].start, links[i].start, sizeof keys[i].start);
        memcpy(keys[i].end, links[i].end, sizeof keys[i].end);
        memcpy(keys[i].apex, links[i].apex, sizeof keys[i].apex);
        keys[i].bidirectional = links[i].bidirectional;
        keys[i].generated = links[i].generated;
        keys[i].holds = links[i].holds;
    }
    qsort(keys, n, sizeof *keys, compare_keys);
    free(links);
    *count = n;
    return keys;
}

/* A path from the first platform to the fourth for a body that jumps and drops. */
static nl_path_result across_platforms(nl_world* world, nl_navmesh_id navmesh) {
    nl_path_request_def def = nl_default_path_request_def();
    nl_path_result result = nl_path_result_init();
    uint32_t count = 0;
    def.navmesh = navmesh;
    def.start[0] = 2.0f, def.start[2] = 3.0f;
    def.goal[0] = 36.0f, def.goal[1] = 0.5f, def.goal[2] = 3.0f;
    def.capabilities.max_jump_distance = 6.0f;
    def.capabilities.max_jump_height = 1.5f;
    def.capabilities.max_drop_height = 4.0f;
    CHECK_OK(nl_path_find(world, &def, &result, NULL, 0, &count));
    return result;
}

/* The navmesh `loaded` of `world` is `original`'s of `source`: info, tiles, vertices, every link, the path
   across, and every tile's hash. */
static void check_same_navmesh(nl_world* source, nl_navmesh_id original, nl_world* world, nl_navmesh_id loaded,
                               const char* label) {
    const nl_navmesh_info a = navmesh_info(source, original), b = navmesh_info(world, loaded);
    nl_tile_coord tiles_a[MAX_TILES], tiles_b[MAX_TILES];
    uint32_t count_a = 0, count_b = 0, links_a = 0, links_b = 0, i, va = 0, vb = 0;
    float* vertices_a = navmesh_vertices(source, original, &va);
    float* vertices_b = navmesh_vertices(world, loaded, &vb);
    link_key* keys_a;
    link_key* keys_b;
    nl_path_result pa, pb;
    CHECK_MSG(b.polygon_count == a.polygon_count && b.vertex_count == a.vertex_count &&
                  b.portal_count == a.portal_count && b.boundary_edge_count == a.boundary_edge_count,
              "%s: %u polygons, %u vertices, %u portals, %u boundary edges; the original's %u, %u, %u, %u", label,
              (unsigned)b.polygon_count, (unsigned)b.vertex_count, (unsigned)b.portal_count,
              (unsigned)b.boundary_edge_count, (unsigned)a.polygon_count, (unsigned)a.vertex_count,
              (unsigned)a.portal_count, (unsigned)a.boundary_edge_count);
    CHECK_MSG(b.tile_count == a.tile_count && b.tile_width == a.tile_width && b.tile_origin[0] == a.tile_origin[0] &&
                  b.tile_origin[1] == a.tile_origin[1],
              "%s: %u tiles of %g m from (%g, %g); the original's %u of %g m from (%g, %g)", label,
              (unsigned)b.tile_count, (double)b.tile_width, (double)b.tile_origin[0], (double)b.tile_origin[1],
              (unsigned)a.tile_count, (double)a.tile_width, (double)a.tile_origin[0], (double)a.tile_origin[1]);
    CHECK_MSG(memcmp(b.bounds_min, a.bounds_min, sizeof a.bounds_min) == 0 &&
                  memcmp(b.bounds_max, a.bounds_max, sizeof a.bounds_max) == 0 &&
                  same_agent(a.agent_type, b.agent_type),
              "%s: other bounds or agent type", label);
    CHECK(NL_SUCCEEDED(nl_navmesh_get_tiles(source, original, tiles_a, MAX_TILES, &count_a)) &&
          NL_SUCCEEDED(nl_navmesh_get_tiles(world, loaded, tiles_b, MAX_TILES, &count_b)));
    CHECK_MSG(count_a == count_b && memcmp(tiles_a, tiles_b, count_a * sizeof *tiles_a) == 0,
              "%s: the tiles listed differ (%u, the original's %u)", label, (unsigned)count_b, (unsigned)count_a);
    CHECK_MSG(vertices_a && vertices_b && va == vb && memcmp(vertices_a, vertices_b, 3u * va * sizeof(float)) == 0,
              "%s: the vertices are not the original's, bit for bit", label);
    free(vertices_a);
    free(vertices_b);
    keys_a = link_keys(source, original, &links_a);
    keys_b = link_keys(world, loaded, &links_b);
    CHECK_MSG(links_a == links_b && links_a > 0u, "%s: %u links, the original %u", label, (unsigned)links_b,
              (unsigned)links_a);
    for (i = 0; i < links_a && i < links_b; ++i) {
        if (!CHECK_MSG(memcmp(&keys_a[i], &keys_b[i], sizeof keys_a[i]) == 0,
                       "%s: link %u (by kind and place): kind %u (%g, %g, %g) -> (%g, %g, %g), holds %u; the "
                       "original's kind %u (%g, %g, %g) -> (%g, %g, %g), holds %u",
                       label, (unsigned)i, (unsigned)keys_b[i].kind, (double)keys_b[i].start[0],
                       (double)keys_b[i].start[1], (double)keys_b[i].start[2], (double)keys_b[i].end[0],
                       (double)keys_b[i].end[1], (double)keys_b[i].end[2], (unsigned)keys_b[i].holds,
                       (unsigned)keys_a[i].kind, (double)keys_a[i].start[0], (double)keys_a[i].start[1],
                       (double)keys_a[i].start[2], (double)keys_a[i].end[0], (double)keys_a[i].end[1],
                       (double)keys_a[i].end[2], (unsigned)keys_a[i].holds))
            break;
    }
    for (i = 0; i < links_b; ++i)
        if (!CHECK_MSG(keys_b[i].holds == 1u, "%s: link %u is parked with every tile loaded", label, (unsigned)i))
            break;
    free(keys_a);
    free(keys_b);
    pa = across_platforms(source, original);
    pb = across_platforms(world, loaded);
    CHECK_MSG(pa.outcome == NL_PATH_COMPLETE && pa.links_used >= 3u,
              "%s: the original's path across the platforms: outcome %u, %u links", label, (unsigned)pa.outcome,
              (unsigned)pa.links_used);
    CHECK_MSG(pb.outcome == pa.outcome && pb.links_used == pa.links_used && pb.length == pa.length &&
                  pb.point_count == pa.point_count,
              "%s: the path across: outcome %u, %u links, %.6f m, %u points; the original's %u, %u, %.6f m, %u", label,
              (unsigned)pb.outcome, (unsigned)pb.links_used, (double)pb.length, (unsigned)pb.point_count,
              (unsigned)pa.outcome, (unsigned)pa.links_used, (double)pa.length, (unsigned)pa.point_count);
    /* The same level, the same provenance: each tile hashes as in the world it was saved from. */
    for (i = 0; i < count_a && i < MAX_TILES; ++i) {
        uint64_t ha = 0, hb = 0;
        CHECK_OK(nl_navmesh_get_tile_hash(source, original, tiles_a[i], &ha));
        CHECK_OK(nl_navmesh_get_tile_hash(world, loaded, tiles_a[i], &hb));
        if (!CHECK_MSG(ha == hb && ha != 0u, "%s: tile (%d, %d) hashes %016llx; in the original %016llx", label,
                       (int)tiles_a[i].x, (int)tiles_a[i].z, (unsigned long long)hb, (unsigned long long)ha))
            break;
    }
}

/* 0 .. n-1 in an order shuffled by a fixed seed (Fisher-Yates over xorshift32). */
static void shuffled(uint32_t* order, uint32_t n, uint32_t seed) {
    uint32_t i, x = seed;
    for (i = 0; i < n; ++i) order[i] = i;
    for (i = n; i > 1u; --i) {
        uint32_t j, t;
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        j = x % i;
        t = order[i - 1u], order[i - 1u] = order[j], order[j] = t;
    }
}

/* The platforms built in tiles with their links generated; every tile saved with the two-call pattern
   and described; a second world with the same level loads the first tile of a shuffled order
   (nl_navmesh_load) and adds the rest (nl_navmesh_add_tile_bytes): the navmesh, its links and a path
   over them are the original's, and each tile saved again is the file it came from. The same through
   files (nl_navmesh_save_tile_file, nl_navmesh_load_file, nl_navmesh_add_tile_file) in a third world. */
static void baked_tiles_load_in_any_order(void) {
    nl_world* world = make_platforms();
    nl_world* second = make_platforms();
    nl_world* third = make_platforms();
    nl_recast_settings settings = nl_default_recast_settings();
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_link_generation_report report;
    nl_navmesh_info info;
    nl_navmesh_id navmesh = {0u, 0u}, loaded = {0u, 0u}, from_files = {0u, 0u};
    nl_tile_coord tiles[MAX_TILES];
    unsigned char* files[MAX_TILES];
    size_t sizes[MAX_TILES];
    uint32_t order[MAX_TILES], count = 0, i, owning = 0, generated = 0;
    char folder[64], path[128];
    memset(&report, 0, sizeof report);
    report.size = sizeof report;
    settings.tile_size = 20u;
    build.settings = &settings;
    CHECK_OK(nl_navmesh_build(world, &build, &navmesh));
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &report));
    info = navmesh_info(world, navmesh);
    CHECK_NEAR(info.tile_width, 6.0f, 1e-4f);
    CHECK(NL_SUCCEEDED(nl_navmesh_get_tiles(world, navmesh, tiles, MAX_TILES, &count)));
    CHECK_MSG(count >= 8u && count == info.tile_count, "%u tiles (info: %u)", (unsigned)count,
              (unsigned)info.tile_count);
    CHECK_MSG(report.jump_links > 0u && report.drop_links > 0u, "%u jumps and %u drops generated",
              (unsigned)report.jump_links, (unsigned)report.drop_links);
    if (count == 0u || count > MAX_TILES) count = 0u;

    /* Every tile saved (measured, then written) and described. */
    for (i = 0; i < count; ++i) {
        nl_navmesh_file_info described;
        uint64_t hash = 0;
        size_t measured = 0, written = 0;
        files[i] = NULL;
        sizes[i] = 0;
        CHECK_OK(nl_navmesh_save_tile(world, navmesh, tiles[i], NULL, 0, &measured));
        files[i] = (unsigned char*)malloc(measured ? measured : 1u);
        if (!files[i]) exit(2);
        CHECK_OK(nl_navmesh_save_tile(world, navmesh, tiles[i], files[i], measured, &written));
        CHECK_MSG(written == measured && measured > 0u, "tile (%d, %d): %u bytes measured, %u written", (int)tiles[i].x,
                  (int)tiles[i].z, (unsigned)measured, (unsigned)written);
        sizes[i] = written;
        memset(&described, 0, sizeof described);
        described.size = sizeof described;
        CHECK_OK(nl_navmesh_file_describe(files[i], sizes[i], &described, NULL, 0, NULL));
        CHECK_OK(nl_navmesh_get_tile_hash(world, navmesh, tiles[i], &hash));
        CHECK_MSG(described.is_tile == 1u && described.tile.x == tiles[i].x && described.tile.z == tiles[i].z,
                  "tile (%d, %d): is_tile %u, tile (%d, %d)", (int)tiles[i].x, (int)tiles[i].z,
                  (unsigned)described.is_tile, (int)described.tile.x, (int)described.tile.z);
        CHECK_MSG(described.content_hash == hash && hash != 0u,
                  "tile (%d, %d): content_hash %016llx, nl_navmesh_get_tile_hash %016llx", (int)tiles[i].x,
                  (int)tiles[i].z, (unsigned long long)described.content_hash, (unsigned long long)hash);
        CHECK_MSG(described.tile_width == info.tile_width && described.tile_origin_x == info.tile_origin[0] &&
                      described.tile_origin_z == info.tile_origin[1] && described.file_size == sizes[i],
                  "tile (%d, %d): tiles of %g m from (%g, %g), %u bytes", (int)tiles[i].x, (int)tiles[i].z,
                  (double)described.tile_width, (double)described.tile_origin_x, (double)described.tile_origin_z,
                  (unsigned)described.file_size);
        CHECK(described.generated_link_count == described.link_count);
        owning += described.link_count > 0u;
        generated += described.link_count;
    }
    {
        /* Each generated link is in the file of one tile: the one it starts on. */
        uint32_t link_count = 0;
        CHECK_OK(nl_navmesh_get_links(world, navmesh, NULL, 0, &link_count));
        CHECK_MSG(generated == link_count && owning >= 2u, "%u links in the tiles' files (%u tiles own some); %u links",
                  (unsigned)generated, (unsigned)owning, (unsigned)link_count);
    }

    /* The second world: the first tile of a shuffled order loaded, the rest added from their bytes. */
    shuffled(order, count, 20240607u);
    if (count > 0u) {
        nl_tile_coord got[MAX_TILES];
        uint32_t got_count = 0;
        CHECK_OK(nl_navmesh_load(second, files[order[0]], sizes[order[0]], NULL, &loaded));
        CHECK(NL_SUCCEEDED(nl_navmesh_get_tiles(second, loaded, got, MAX_TILES, &got_count)) && got_count == 1u &&
              got[0].x == tiles[order[0]].x && got[0].z == tiles[order[0]].z);
        for (i = 1; i < count; ++i)
            CHECK_OK(nl_navmesh_add_tile_bytes(second, loaded, files[order[i]], sizes[order[i]]));
        check_same_navmesh(world, navmesh, second, loaded, "loaded from bytes");
        /* Each tile saved again is the file it was loaded from. */
        for (i = 0; i < count; ++i) {
            size_t size = 0;
            unsigned char* again = (unsigned char*)malloc(sizes[i] + 1u);
            if (!again) exit(2);
            CHECK_OK(nl_navmesh_save_tile(second, loaded, tiles[i], again, sizes[i] + 1u, &size));
            CHECK_MSG(size == sizes[i] && memcmp(again, files[i], size) == 0,
                      "tile (%d, %d) saved again from the loaded navmesh differs", (int)tiles[i].x, (int)tiles[i].z);
            free(again);
        }
    }

    /* The third world, through files: saved with nl_navmesh_save_tile_file (the bytes of
       nl_navmesh_save_tile), loaded in another shuffled order. */
    snprintf(folder, sizeof folder, "/tmp/navlink-abi-tiles-XXXXXX");
    CHECK(mkdtemp(folder) != NULL);
    for (i = 0; i < count; ++i) {
        FILE* f;
        unsigned char* read = (unsigned char*)malloc(sizes[i] + 1u);
        size_t got = 0;
        if (!read) exit(2);
        snprintf(path, sizeof path, "%s/tile_%d_%d.nltile", folder, (int)tiles[i].x, (int)tiles[i].z);
        CHECK_OK(nl_navmesh_save_tile_file(world, navmesh, tiles[i], path));
        f = fopen(path, "rb");
        if (f) {
            got = fread(read, 1, sizes[i] + 1u, f);
            fclose(f);
        }
        CHECK_MSG(got == sizes[i] && memcmp(read, files[i], got) == 0, "%s: %u bytes, not nl_navmesh_save_tile's %u",
                  path, (unsigned)got, (unsigned)sizes[i]);
        free(read);
    }
    shuffled(order, count, 7u);
    for (i = 0; i < count; ++i) {
        snprintf(path, sizeof path, "%s/tile_%d_%d.nltile", folder, (int)tiles[order[i]].x, (int)tiles[order[i]].z);
        if (i == 0)
            CHECK_OK(nl_navmesh_load_file(third, path, NULL, &from_files));
        else
            CHECK_OK(nl_navmesh_add_tile_file(third, from_files, path));
    }
    if (count > 0u) {
        check_same_navmesh(world, navmesh, third, from_files, "loaded from files");
        /* A tile's file again: loaded already, nothing changed. */
        snprintf(path, sizeof path, "%s/tile_%d_%d.nltile", folder, (int)tiles[0].x, (int)tiles[0].z);
        CHECK_INVALID(nl_navmesh_add_tile_file(third, from_files, path), "loaded already");
        CHECK(navmesh_info(third, from_files).tile_count == count);
    }
    for (i = 0; i < count; ++i) {
        snprintf(path, sizeof path, "%s/tile_%d_%d.nltile", folder, (int)tiles[i].x, (int)tiles[i].z);
        CHECK(remove(path) == 0);
        free(files[i]);
    }
    CHECK(remove(folder) == 0);
    nl_world_destroy(third);
    nl_world_destroy(second);
    nl_world_destroy(world);
}

ABI_SECTION(tiles, ABI_CASE(built_in_tiles), ABI_CASE(removed_tiles_cut_the_path), ABI_CASE(agent_waits_for_its_tile),
            ABI_CASE(link_parked_while_its_tile_is_out), ABI_CASE(baked_tiles_load_in_any_order));
