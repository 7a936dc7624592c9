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
 */
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

ABI_SECTION(tiles, ABI_CASE(built_in_tiles), ABI_CASE(removed_tiles_cut_the_path), ABI_CASE(agent_waits_for_its_tile),
            ABI_CASE(link_parked_while_its_tile_is_out));
