// navlink-bench-tiles [--world-km K] [--tile-size N] [--reps N] [--pairs N] [--max-pair-distance M]
//                     [--swaps N] [--detour-nodes N] [--queue-batch N] [--no-breakdown] [--no-links] [--smoke]
//                     [[--levels] LEVEL.obj...]:
// NavLink's tiled navmesh against Detour's multi-tile dtNavMesh, built from the same level with the
// same Recast settings (nl_recast_settings with tile_size, default agent type), measured in one run.
//
// Levels: a generated world of K x K km (default 0.3; 0 for none): undulating terrain (hills of 6 m
// over some 500 m, smaller waves over 150 m and 20 m, under 12 degrees everywhere) tessellated in cells
// of 1.8 m, with boxes standing on it as obstacles on a jittered 12 m grid (rocks and low steps to climb,
// buildings, thin walls): about 10 million triangles at K = 4; then each OBJ level given.
//
// NavLink: a world per worker count (1 and 2 workers, no path workers) holds the level as one static
// mesh; nl_navmesh_build with the tile size builds the navmesh (the Recast builder's tiles, joined).
// Detour: the same triangles binned by tile as RecastDemo's chunky mesh does, then each tile built as
// Sample_TileMesh::buildTileMesh does (the same rcConfig, single thread), dtCreateNavMeshData, and
// all of them added to one dtNavMesh on NavLink's grid (tests/bench/recast_detour.h). Every figure is
// the median of --reps repetitions (3), the two sides alternating. Printed per level:
//   1. build: milliseconds per tile of NavLink on 1 worker and of Detour (its binning included), their
//      ratio (target <= 1), NavLink on 2 workers and its speed-up over 1 (target >= 1.8); with the
//      breakdown (default on), NavLink's Recast builder alone (the plugin's tiles and their export,
//      serial, no world) and the join of the tiles into one navmesh (join_tiles + build_navmesh: what
//      every tile added or removed does again).
//   2. memory per tile: NavLink's navmesh, link index and search index (as navlink-bench-path counts
//      them), and the tile inputs NavLink keeps to join again, against Detour's tile data.
//   3. paths: --pairs (10,000) random start/goal pairs whose ends lie in different tiles (points on
//      random polygons of Detour's tiles, half a metre up, seed 12345; at most --max-pair-distance apart
//      when given): nl_path_find (locate both ends, search, string-pull) against Detour's
//      findNearestPoly x 2 + findPath + findStraightPath (node pool --detour-nodes, RecastDemo's 2048;
//      corridors of up to 4096 polygons), the total time of a round, median of rounds; how many pairs
//      each completes, and the time ratio over the pairs both complete (both/dt: pairs with no way
//      between their ends cost Detour a search of all it reaches, NavLink a look at its reachability
//      map); and, over the pairs both complete (Detour planned again, untimed, between the ends and
//      polygons NavLink located), NavLink's length seen from above against Detour's straight path's:
//      the worst excess, and how many exceed 0.1% (NavLink's path is the exact shortest), with the
//      request of the worst to reproduce it.
//   4. tiles in and out, over --swaps (8) tiles drawn with seed 777, medians over the tiles:
//      nl_navmesh_remove_tile + nl_navmesh_add_tile of the tile as NavLink built it, against
//      dtNavMesh::removeTile + addTile of its prebuilt data (each 5 times, median); and
//      nl_navmesh_build_tiles of a box in the tile, against building its Detour data again (Recast) and
//      swapping it in; and NavLink's remove + add against that Detour rebuild.
//   5. the tiled navmesh with its links, each size in a child process of its own (the bench run again
//      with --child-world K or --child-level LEVEL, before 1 to 4, so that nothing else is resident):
//      a world with every worker (NL_WORKERS_AUTO) holds the level; nl_navmesh_build, then
//      nl_navmesh_generate_links (default settings: each tile's links over the tiles within reach,
//      docs/tiles.md); their times, the link count, and the process's RSS (/proc/self/statm, after
//      malloc_trim; also without) before the build, after it and after the links, as bytes per tile, with
//      the peak (getrusage's maxrss) and nl_navmesh_save_tile's bytes per tile (every tile, or up to
//      1,024 spread over them, fewer when one takes long: about 15 s in all). For the generated world, worlds of a quarter and a half of its tiles (whole
//      tiles a side) first, so that the bytes per tile can be seen to stay flat; and how many tiles 24 GB
//      holds at the whole world's peak per tile.
//   6. in the child of the whole level, its links generated, with path workers (NL_WORKERS_AUTO): the
//      tiles of 4, each taken out and put back with its links, first with the path queue idle, then busy:
//      --queue-batch (64) requests submitted from the main thread before the tile's changes and kept in
//      flight (each request's callback, on a path worker, counts its outcome, releases it and submits
//      the next; jumps and drops allowed, ends drawn within 4 tiles of the tile). Timed (medians over
//      the tiles): nl_navmesh_save_tile; nl_navmesh_remove_tile + nl_navmesh_add_tile_bytes of those
//      bytes (its links come with it); nl_navmesh_remove_tile + nl_navmesh_build_tiles of the tile (its
//      links and those of the tiles within reach generated again); the requests finished during each,
//      every outcome (an end off the navmesh is expected while its tile is out; no path, cancelled,
//      failed or a refused request are not), and the links and polygons before and after (the same);
//      as ratios to 4's Detour removeTile + addTile and Recast rebuild of the same tiles. Also the queue's
//      pace on a navmesh that does not change (300 ms, before the first tile) against during the changes,
//      and, with the queue idle, how long the first nl_path_request after a change takes (the change
//      built the new navmesh's path graph: paths were asked for on it) and the next, and how long the busy batch,
//      submitted on the navmesh just changed, waits for its first request done.
//      --no-links leaves 5 and 6 out.
// --smoke: a world of 0.1 km, 1 repetition, 200 pairs, 2 swaps: what ctest runs.
#include <DetourCommon.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "build_progress.h"
#include "clock.h"
#include "host_log_context.h"
#include "io/obj_reader.h"
#include "level_generator.h"
#include "level_triangles.h"
#include "navmesh/navmesh.h"
#include "navmesh/tile_join.h"
#include "recast_detour.h"
#include "tiled_mesh.h"
#include "world.h"

namespace {

constexpr float kHalfExtents[3] = {2.0f, 4.0f, 2.0f};
constexpr int kMaxPolys = 4096;
constexpr int kDetourSwapRepeats = 5;
constexpr float kGroundCell = 1.8f;

struct Options {
    double world_km = 0.3;
    uint32_t tile_size = 64;
    int reps = 3;
    int pairs = 10000;
    float max_pair_distance = 0.0f;  // 0: any
    int swaps = 8;
    int detour_nodes = 2048;
    bool breakdown = true;
    bool links_sections = true;  // 5 and 6, in child processes
    int queue_batch = 64;        // 6: path requests kept in flight while tiles change
    std::vector<std::string> objs;
    // A child process (5 and 6 of one level): --child-world K or --child-level PATH, --child-streaming.
    double child_world_km = 0.0;
    std::string child_level;
    bool child_streaming = false;
};

// Figures by name, as a child process prints them on one line ("NLCHILD name=value ...").
using Figures = std::map<std::string, double>;

double figure(const Figures& f, const char* name) {
    const auto it = f.find(name);
    return it == f.end() ? NAN : it->second;
}

struct LevelInput {
    std::string name;
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    uint32_t triangle_count() const { return uint32_t(indices.size() / 3); }
};

// Undulating terrain of km x km with boxes on it as obstacles (levelgen's ground grid and boxes).
LevelInput make_world(double km) {
    const float extent = float(km * 1000.0);
    // Under 12 degrees everywhere: 6 * 0.013 + 1.5 * 0.049 + 0.12 * 0.31 < 0.21.
    auto ground = [](float x, float z) {
        return 6.0f * std::sin(0.011f * x) * std::cos(0.013f * z) + 1.5f * std::sin(0.041f * x + 0.027f * z) +
               0.12f * std::sin(0.31f * x) * std::cos(0.23f * z);
    };
    nl::levelgen::GeneratedLevel level;
    level.add_ground_grid(0.0f, 0.0f, extent, extent, kGroundCell, ground);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto uniform = [&](float a, float b) { return a + (b - a) * unit(rng); };
    const float cell = 12.0f;
    const int cells = int(extent / cell);
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (unit(rng) >= 0.55f) continue;
            float sx, sz, h;
            const float kind = unit(rng);
            if (kind < 0.3f) {  // a rock or step low enough to climb (max_climb 0.9)
                sx = uniform(1.0f, 4.0f), sz = uniform(1.0f, 4.0f), h = uniform(0.3f, 0.8f);
            } else if (kind < 0.8f) {  // a building
                sx = uniform(3.0f, 9.0f), sz = uniform(3.0f, 9.0f), h = uniform(2.5f, 8.0f);
            } else {  // a thin wall along x or z
                const bool along_x = unit(rng) < 0.5f;
                const float length = uniform(5.0f, 11.0f), thickness = uniform(0.3f, 0.6f);
                sx = along_x ? length : thickness, sz = along_x ? thickness : length, h = uniform(1.2f, 3.0f);
            }
            const float x0 = i * cell + uniform(0.0f, cell - sx), z0 = j * cell + uniform(0.0f, cell - sz);
            const float x1 = x0 + sx, z1 = z0 + sz;
            float low = INFINITY, centre = ground(0.5f * (x0 + x1), 0.5f * (z0 + z1));
            for (float x : {x0, x1})
                for (float z : {z0, z1}) low = std::min(low, ground(x, z));
            level.add_box(nl::levelgen::Box{{x0, low - 1.0f, z0}, {x1, centre + h, z1}});
        }
    LevelInput out;
    out.name = "world-" + std::to_string(km).substr(0, std::to_string(km).find('.') + 2) + "km";
    out.vertices = std::move(level.positions);
    out.indices = std::move(level.indices);
    return out;
}

LevelInput read_level(const std::string& path) {
    const nl::TriangleMesh mesh = nl::read_obj_file(path);
    LevelInput out;
    out.name = std::filesystem::path(path).stem().string();
    for (const nl::Vec3& v : mesh.vertices) out.vertices.insert(out.vertices.end(), {v.x(), v.y(), v.z()});
    for (const nl::Triangle& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
    return out;
}

double median(std::vector<double> values) {
    if (values.empty()) return NAN;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

nl::Handle handle_of(nl_navmesh_id id) { return nl::Handle{id.index1, id.revision}; }

void fail_nl(const std::string& level, const char* what) {
    std::fprintf(stderr, "navlink-bench-tiles: %s: %s: %s\n", level.c_str(), what, nl_get_last_error_message());
}

struct WorldDeleter {
    void operator()(nl_world* world) const { nl_world_destroy(world); }
};
using WorldPtr = std::unique_ptr<nl_world, WorldDeleter>;

// A world holding the level as one static mesh, its scene committed (one ray cast) before any timing.
WorldPtr make_nl_world(const LevelInput& level, int workers, int path_workers = 0) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    def.path_worker_count = path_workers;
    nl_world* created = nullptr;
    if (NL_FAILED(nl_world_create(&def, &created))) return nullptr;
    WorldPtr world(created);
    nl_mesh_def mesh = nl_default_mesh_def();
    mesh.vertices = level.vertices.data();
    mesh.vertex_count = uint32_t(level.vertices.size() / 3);
    mesh.indices = level.indices.data();
    mesh.triangle_count = level.triangle_count();
    nl_mesh_id id{};
    if (NL_FAILED(nl_mesh_add(world.get(), &mesh, &id))) return nullptr;
    const nl_ray ray{{level.vertices[0], level.vertices[1] + 100.0f, level.vertices[2]}, {0.0f, -1.0f, 0.0f}, 1e4f};
    nl_ray_hit hit = nl_ray_hit_init();
    nl_world_cast_rays(world.get(), &ray, 1, &hit);
    return world;
}

// A tile as NavLink keeps it (the builder's def, tile_join.h's input), copied into a def again for
// nl_navmesh_add_tile (the kept input goes when the tile is removed).
struct TileDef {
    std::vector<float> vertices, detail_vertices;
    std::vector<uint32_t> indices, detail_indices, detail_starts;
    std::vector<uint8_t> polygon_sizes, areas;
    nl_navmesh_def def = nl_default_navmesh_def();
    TileDef(const nl::NavMeshInput& in, const nl_agent_type& agent)
        : indices(in.indices),
          detail_indices(in.detail_indices),
          detail_starts(in.detail_starts),
          polygon_sizes(in.polygon_sizes),
          areas(in.areas) {
        for (const nl::Vec3& v : in.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
        for (const nl::Vec3& v : in.detail_vertices)
            detail_vertices.insert(detail_vertices.end(), {v.x(), v.y(), v.z()});
        def.vertices = vertices.data();
        def.vertex_count = uint32_t(in.vertices.size());
        def.indices = indices.data();
        def.polygon_vertex_counts = polygon_sizes.empty() ? nullptr : polygon_sizes.data();
        def.polygon_count = polygon_sizes.empty() ? uint32_t(indices.size() / 3) : uint32_t(polygon_sizes.size());
        def.areas = areas.empty() ? nullptr : areas.data();
        def.weld_tolerance = in.weld_tolerance;
        def.agent_type = agent;
        if (!detail_starts.empty()) {
            def.detail_vertices = detail_vertices.data();
            def.detail_vertex_count = uint32_t(in.detail_vertices.size());
            def.detail_triangles = detail_indices.data();
            def.detail_triangle_count = uint32_t(detail_indices.size() / 3);
            def.detail_triangle_starts = detail_starts.data();
        }
        def.tile_width = in.tiles.grid.tile_width;
        def.tile_origin_x = in.tiles.grid.origin_x;
        def.tile_origin_z = in.tiles.grid.origin_z;
        def.tile_x = in.tiles.tiles.front().x;
        def.tile_z = in.tiles.tiles.front().z;
    }
    TileDef(const TileDef&) = delete;
    TileDef& operator=(const TileDef&) = delete;
};

template <typename T>
size_t bytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

size_t input_bytes(const nl::NavMeshInput& in) {
    return sizeof in + bytes(in.vertices) + bytes(in.indices) + bytes(in.polygon_sizes) + bytes(in.areas) +
           bytes(in.detail_vertices) + bytes(in.detail_indices) + bytes(in.detail_starts) + bytes(in.tiles.tiles) +
           bytes(in.polygon_tiles) + bytes(in.on_tile_border);
}

struct Pair {
    float start[3];
    float goal[3];
};

float xz_length(const float* xyz, int count) {
    float length = 0.0f;
    for (int i = 1; i < count; ++i) {
        const float* a = xyz + 3 * (i - 1);
        const float* b = xyz + 3 * i;
        length += std::hypot(b[0] - a[0], b[2] - a[2]);
    }
    return length;
}

float xz_length(const nl_path_point* points, uint32_t count) {
    float length = 0.0f;
    for (uint32_t i = 1; i < count; ++i)
        length += std::hypot(points[i].position[0] - points[i - 1].position[0],
                             points[i].position[2] - points[i - 1].position[2]);
    return length;
}

struct DetourAnswer {
    bool complete = false;
    float length = 0.0f;  // seen from above
};

DetourAnswer detour_search(const dtNavMeshQuery& query, dtPolyRef start_ref, const float* start, dtPolyRef goal_ref,
                           const float* goal, std::vector<dtPolyRef>& polys, std::vector<float>& straight) {
    static const dtQueryFilter filter;
    DetourAnswer answer;
    int count = 0;
    const dtStatus status = query.findPath(start_ref, goal_ref, start, goal, &filter, polys.data(), &count, kMaxPolys);
    if (dtStatusFailed(status) || count == 0) return answer;
    float end[3];
    dtVcopy(end, goal);
    if (polys[count - 1] != goal_ref) query.closestPointOnPoly(polys[count - 1], goal, end, nullptr);
    int points = 0;
    query.findStraightPath(start, end, polys.data(), count, straight.data(), nullptr, nullptr, &points, kMaxPolys);
    answer.complete = polys[count - 1] == goal_ref && !(status & DT_PARTIAL_RESULT);
    answer.length = xz_length(straight.data(), points);
    return answer;
}

DetourAnswer detour_path(const dtNavMeshQuery& query, const Pair& pair, std::vector<dtPolyRef>& polys,
                         std::vector<float>& straight) {
    static const dtQueryFilter filter;
    dtPolyRef start_ref = 0, goal_ref = 0;
    float start[3], goal[3];
    query.findNearestPoly(pair.start, kHalfExtents, &filter, &start_ref, start);
    query.findNearestPoly(pair.goal, kHalfExtents, &filter, &goal_ref, goal);
    if (!start_ref || !goal_ref) return DetourAnswer{};
    return detour_search(query, start_ref, start, goal_ref, goal, polys, straight);
}

// Random pairs on Detour's tiles, their ends in different tiles (and at most `max_distance` apart).
std::vector<Pair> draw_pairs(const nl::bench::TiledLevel& level, const nl::bench::DetourTiles& detour, int count,
                             float max_distance) {
    struct Polygon {
        const dtMeshTile* tile;
        int index;
    };
    std::vector<Polygon> polygons;
    const dtNavMesh& mesh = *detour.navmesh.mesh;
    for (const nl::bench::DetourTile& t : detour.tiles) {
        const dtMeshTile* tile = mesh.getTileAt(t.x, t.z, 0);
        for (int p = 0; tile && p < tile->header->polyCount; ++p)
            if (tile->polys[p].getType() == DT_POLYTYPE_GROUND) polygons.push_back(Polygon{tile, p});
    }
    std::mt19937 rng(12345);
    std::uniform_int_distribution<size_t> pick(0, polygons.size() - 1);
    auto draw = [&](float out[3]) {
        const Polygon& p = polygons[pick(rng)];
        nl::bench::random_point_in_detour_polygon(*p.tile, p.index, rng, out);
    };
    auto tile_of = [&](const float* p) {
        return std::make_pair(std::floor((p[0] - level.origin_x) / level.tile_width),
                              std::floor((p[2] - level.origin_z) / level.tile_width));
    };
    std::vector<Pair> pairs;
    for (int i = 0; i < count; ++i) {
        Pair pair;
        bool found = false;
        for (int attempt = 0; attempt < 1000 && !found; ++attempt) {
            draw(pair.start);
            for (int goal = 0; goal < 100 && !found; ++goal) {
                draw(pair.goal);
                found = tile_of(pair.start) != tile_of(pair.goal) &&
                        (max_distance <= 0.0f ||
                         std::hypot(pair.goal[0] - pair.start[0], pair.goal[2] - pair.start[2]) <= max_distance);
            }
        }
        if (!found) break;
        pairs.push_back(pair);
    }
    return pairs;
}

// NavLink's polygon p as Detour's ref: both hold Recast's polygons tile by tile in the same order
// unless NavLink dropped one, so polygon p is the k-th of its tile on both sides; checked by each
// polygon's box seen from above (T-junction corners lie on edges: they leave it as it was). Empty when
// a tile's polygons do not match.
std::vector<dtPolyRef> detour_refs_of(const nl::NavMesh& navmesh, const dtNavMesh& mesh) {
    std::vector<dtPolyRef> refs(navmesh.polygon_count(), 0);
    uint32_t first = 0;  // the first polygon of the current tile
    for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
        if (p > 0 && navmesh.tile_of(p) != navmesh.tile_of(p - 1)) first = p;
        const nl::TileCoord at = navmesh.tiles().tiles[navmesh.tile_of(p)];
        const dtMeshTile* tile = mesh.getTileAt(at.x, at.z, 0);
        const uint32_t k = p - first;
        if (!tile || k >= uint32_t(tile->header->polyCount)) return {};
        const dtPoly& poly = tile->polys[k];
        float box[2][4] = {{INFINITY, -INFINITY, INFINITY, -INFINITY}, {INFINITY, -INFINITY, INFINITY, -INFINITY}};
        auto grow = [](float* b, float x, float z) {
            b[0] = std::min(b[0], x), b[1] = std::max(b[1], x), b[2] = std::min(b[2], z), b[3] = std::max(b[3], z);
        };
        for (int j = 0; j < poly.vertCount; ++j) {
            const float* v = &tile->verts[3 * poly.verts[j]];
            grow(box[0], v[0], v[2]);
        }
        const uint32_t* corners = navmesh.corners_of(p);
        for (uint32_t j = 0; j < navmesh.corner_count(p); ++j)
            grow(box[1], navmesh.vertex(corners[j]).x(), navmesh.vertex(corners[j]).z());
        for (int j = 0; j < 4; ++j)
            if (std::fabs(box[0][j] - box[1][j]) > 0.01f) return {};
        refs[p] = mesh.getPolyRefBase(tile) | dtPolyRef(k);
    }
    return refs;
}

struct Row {
    std::string name;
    uint32_t triangles = 0;
    int grid_x = 0, grid_z = 0;
    uint32_t nl_tiles = 0, nl_polygons = 0;
    size_t detour_tiles = 0;
    int detour_polygons = 0;
    // 1. build, ms per tile
    double nl1 = NAN, nl2 = NAN, detour = NAN, builder = NAN, join = NAN;
    // 2. memory, bytes per tile
    double nl_bytes = NAN, nl_inputs = NAN, detour_bytes = NAN;
    // 3. paths
    int pairs = 0, nl_complete = 0, detour_complete = 0, compared = 0, over = 0;
    double nl_us = NAN, detour_us = NAN, both_ratio = NAN, worst_excess = NAN;
    Pair worst{};  // the request of the worst excess (nl_path_find from its start to its goal)
    float worst_nl = 0.0f, worst_detour = 0.0f;
    // 4. tiles in and out, medians in ms
    int swaps = 0;
    double nl_remove = NAN, nl_add = NAN, nl_swap = NAN, detour_swap = NAN, nl_rebuild = NAN, detour_rebuild = NAN;
    // 5. the tiled navmesh with its links, a world per size (child processes), smallest first
    std::vector<Figures> sizes;
    // 6. tiles in and out with links while paths are queued (the child of the whole level)
    Figures streaming;
};

// The tiles table 4 takes out and puts back: --swaps of them, drawn with seed 777.
std::vector<nl_tile_coord> tiles_to_swap(nl_world* world, nl_navmesh_id navmesh, int swaps) {
    uint32_t loaded = 0;
    nl_navmesh_get_tiles(world, navmesh, nullptr, 0, &loaded);
    std::vector<nl_tile_coord> coords(loaded);
    nl_navmesh_get_tiles(world, navmesh, coords.data(), loaded, &loaded);
    std::mt19937 rng(777);
    std::shuffle(coords.begin(), coords.end(), rng);
    coords.resize(std::min<size_t>(coords.size(), size_t(std::max(0, swaps))));
    if (loaded < 2) coords.clear();  // a navmesh's last tile cannot be removed
    return coords;
}

bool measure(const LevelInput& input, const Options& options, Row& row) {
    row.name = input.name;
    row.triangles = input.triangle_count();
    std::fprintf(stderr, "%s: %u triangles\n", input.name.c_str(), row.triangles);

    nl_recast_settings settings = nl_default_recast_settings();
    settings.tile_size = options.tile_size;
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.settings = &settings;

    const WorldPtr one_world = make_nl_world(input, 1);
    WorldPtr two_world = make_nl_world(input, 2);
    nl_world* one = one_world.get();
    nl_world* two = two_world.get();
    if (!one || !two) {
        fail_nl(input.name, "world");
        return false;
    }
    nl::bench::TiledLevel level =
        nl::bench::plan_tiled_level(input.name, input.vertices, input.indices, settings, build.agent_type);
    nl::recast::LevelTriangles triangles;  // the breakdown's: the builder's own input
    if (options.breakdown) {
        triangles.vertices = input.vertices;
        triangles.indices = input.indices;
        triangles.areas.assign(input.triangle_count(), 0);
    }

    // 1. Builds, alternating: NavLink on 1 worker, on 2, Detour, NavLink's builder alone, the join.
    std::vector<double> nl1, nl2, detour, builder, join;
    nl_navmesh_id navmesh{}, navmesh2{};
    std::unique_ptr<nl::bench::DetourTiles> tiles;
    nl_navmesh_info info = nl_navmesh_info_init();
    for (int rep = 0; rep < options.reps; ++rep) {
        std::fprintf(stderr, "%s: build %d of %d\n", input.name.c_str(), rep + 1, options.reps);
        if (rep > 0) nl_navmesh_remove(one, navmesh), nl_navmesh_remove(two, navmesh2);
        double t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_build(one, &build, &navmesh))) {
            fail_nl(input.name, "nl_navmesh_build (1 worker)");
            return false;
        }
        nl1.push_back(nl::samples::now_ms() - t0);
        t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_build(two, &build, &navmesh2))) {
            fail_nl(input.name, "nl_navmesh_build (2 workers)");
            return false;
        }
        nl2.push_back(nl::samples::now_ms() - t0);
        if (rep == 0) {
            // Detour on NavLink's grid.
            nl_navmesh_get_info(one, navmesh, &info);
            if (info.tile_origin[0] != float(level.origin_x) || info.tile_origin[1] != float(level.origin_z) ||
                info.tile_width != float(level.tile_width))
                std::fprintf(stderr, "%s: NavLink's grid (%g, %g) of %g m is not the bench's (%g, %g) of %g m\n",
                             input.name.c_str(), info.tile_origin[0], info.tile_origin[1], info.tile_width,
                             level.origin_x, level.origin_z, level.tile_width);
        }
        tiles.reset();
        t0 = nl::samples::now_ms();
        nl::bench::bin_triangles(level);
        tiles = std::make_unique<nl::bench::DetourTiles>();
        if (!nl::bench::build_detour_tiles(level, *tiles, options.detour_nodes)) return false;
        detour.push_back(nl::samples::now_ms() - t0);
        if (options.breakdown) {
            const nl_plugin_host no_host{};  // size 0: no log, no progress, no run_tasks (serial)
            nl::recast::HostLogContext context(no_host);
            size_t handed = 0;
            t0 = nl::samples::now_ms();
            nl::recast::build_tiled_mesh(context, no_host, triangles, settings, build,
                                         nl::recast::BuildProgress(no_host),
                                         [&](const nl::recast::NavMeshExport&) { ++handed; });
            builder.push_back(nl::samples::now_ms() - t0);
            const nl::TileInputs kept = one->core->navmeshes().tile_inputs(handle_of(navmesh));
            t0 = nl::samples::now_ms();
            const auto joined = nl::build_navmesh(nl::join_tiles(kept));
            join.push_back(nl::samples::now_ms() - t0);
        }
    }
    two_world.reset();
    nl_navmesh_get_info(one, navmesh, &info);
    row.grid_x = level.tiles_x, row.grid_z = level.tiles_z;
    row.nl_tiles = info.tile_count;
    row.nl_polygons = info.polygon_count;
    row.detour_tiles = tiles->tiles.size();
    row.detour_polygons = tiles->polygon_count();
    const double nl_per = 1.0 / std::max(1u, row.nl_tiles), detour_per = 1.0 / std::max<size_t>(1, row.detour_tiles);
    row.nl1 = median(nl1) * nl_per;
    row.nl2 = median(nl2) * nl_per;
    row.detour = median(detour) * detour_per;
    row.builder = median(builder) * nl_per;
    row.join = median(join);

    // 2. Memory.
    {
        const auto graph = one->core->navmeshes().path_graph(handle_of(navmesh));
        row.nl_bytes =
            double(graph->navmesh().memory_bytes() + graph->link_index_bytes() + graph->search_index_bytes()) * nl_per;
        size_t kept = 0;
        for (const auto& tile : one->core->navmeshes().tile_inputs(handle_of(navmesh))) kept += input_bytes(*tile);
        row.nl_inputs = double(kept) * nl_per;
        row.detour_bytes = double(tiles->data_bytes()) * detour_per;
    }

    // 3. Paths between tiles.
    const dtNavMeshQuery& query = *tiles->navmesh.query;
    const std::vector<Pair> pairs = row.detour_tiles > 1 && options.pairs > 0
                                        ? draw_pairs(level, *tiles, options.pairs, options.max_pair_distance)
                                        : std::vector<Pair>{};
    row.pairs = int(pairs.size());
    if (!pairs.empty()) {
        std::fprintf(stderr, "%s: %zu path pairs\n", input.name.c_str(), pairs.size());
        std::vector<dtPolyRef> polys(kMaxPolys);
        std::vector<float> straight(3 * kMaxPolys);
        std::vector<nl_path_point> points(65536, nl_path_point_init());
        // Each pair's time in each round, per side.
        std::vector<std::vector<double>> nl_times(options.reps, std::vector<double>(pairs.size())),
            detour_times(options.reps, std::vector<double>(pairs.size()));
        std::vector<char> nl_complete(pairs.size()), detour_complete(pairs.size());
        std::vector<float> nl_length(pairs.size());
        std::vector<uint32_t> first_polygon(pairs.size()), last_polygon(pairs.size());
        std::vector<nl_path_result> results(pairs.size());
        for (int round = 0; round < options.reps; ++round) {
            for (size_t i = 0; i < pairs.size(); ++i) {
                const Pair& pair = pairs[i];
                nl_path_request_def def = nl_default_path_request_def();
                def.navmesh = navmesh;
                std::copy(pair.start, pair.start + 3, def.start);
                std::copy(pair.goal, pair.goal + 3, def.goal);
                std::copy(kHalfExtents, kHalfExtents + 3, def.search_half_extents);
                nl_path_result result = nl_path_result_init();
                uint32_t count = 0;
                DetourAnswer answer;
                // Alternately first, so that neither side always finds the caches warmed by the other.
                for (int side = 0; side < 2; ++side) {
                    const double t0 = nl::samples::now_ms();
                    if ((side == 0) == (i % 2 == 0)) {
                        nl_path_find(one, &def, &result, points.data(), uint32_t(points.size()), &count);
                        nl_times[round][i] = nl::samples::now_ms() - t0;
                    } else {
                        answer = detour_path(query, pair, polys, straight);
                        detour_times[round][i] = nl::samples::now_ms() - t0;
                    }
                }
                if (round + 1 < options.reps) continue;
                nl_complete[i] = result.outcome == NL_PATH_COMPLETE && count > 0;
                detour_complete[i] = answer.complete;
                nl_length[i] = nl_complete[i] ? xz_length(points.data(), count) : 0.0f;
                first_polygon[i] = count ? points[0].polygon : 0;
                last_polygon[i] = count ? points[count - 1].polygon : 0;
                results[i] = result;
            }
        }
        // A round's total over the pairs `which` picks; the median round.
        auto per_pair_us = [&](const std::vector<std::vector<double>>& times, auto which) {
            std::vector<double> rounds;
            int counted = 0;
            for (const std::vector<double>& round : times) {
                double total = 0.0;
                counted = 0;
                for (size_t i = 0; i < pairs.size(); ++i)
                    if (which(i)) total += round[i], ++counted;
                rounds.push_back(total);
            }
            return counted ? 1000.0 * median(rounds) / counted : NAN;
        };
        auto every = [](size_t) { return true; };
        auto both = [&](size_t i) { return nl_complete[i] && detour_complete[i]; };
        row.nl_us = per_pair_us(nl_times, every);
        row.detour_us = per_pair_us(detour_times, every);
        row.both_ratio = per_pair_us(nl_times, both) / per_pair_us(detour_times, both);
        // Lengths, untimed: Detour again between the ends and polygons NavLink located (both locate
        // alike, but a point on a polygon's outline, or over a dip a polygon spans, may go to either).
        const auto located = one->core->navmeshes().navmesh(handle_of(navmesh));
        const std::vector<dtPolyRef> refs = detour_refs_of(*located, *tiles->navmesh.mesh);
        if (refs.empty())
            std::fprintf(stderr, "%s: NavLink's polygons are not Detour's: ends located again\n", input.name.c_str());
        row.worst_excess = 0.0;
        for (size_t i = 0; i < pairs.size(); ++i) {
            row.nl_complete += nl_complete[i];
            row.detour_complete += detour_complete[i];
            if (!nl_complete[i]) continue;
            Pair ends;
            std::copy(results[i].start, results[i].start + 3, ends.start);
            std::copy(results[i].goal, results[i].goal + 3, ends.goal);
            const DetourAnswer same_ends = refs.empty()
                                               ? detour_path(query, ends, polys, straight)
                                               : detour_search(query, refs[first_polygon[i]], ends.start,
                                                               refs[last_polygon[i]], ends.goal, polys, straight);
            if (!same_ends.complete || same_ends.length <= 0.0f) continue;
            ++row.compared;
            const double excess = double(nl_length[i]) / same_ends.length - 1.0;
            row.over += excess > 1e-3;
            if (excess > row.worst_excess) {
                row.worst_excess = excess;
                row.worst_nl = nl_length[i], row.worst_detour = same_ends.length;
                row.worst = pairs[i];
            }
        }
    }

    // 4. Tiles in and out.
    const std::vector<nl_tile_coord> coords = tiles_to_swap(one, navmesh, options.swaps);
    std::vector<double> nl_remove, nl_add, nl_swap, detour_swap, nl_rebuild, detour_rebuild;
    dtNavMesh& mesh = *tiles->navmesh.mesh;
    for (const nl_tile_coord& at : coords) {
        std::fprintf(stderr, "%s: tile (%d, %d) out and in\n", input.name.c_str(), at.x, at.z);
        std::unique_ptr<TileDef> def;
        for (const auto& tile : one->core->navmeshes().tile_inputs(handle_of(navmesh)))
            if (tile->tiles.tiles.front().x == at.x && tile->tiles.tiles.front().z == at.z)
                def = std::make_unique<TileDef>(*tile, info.agent_type);
        if (!def) {
            std::fprintf(stderr, "navlink-bench-tiles: %s: tile (%d, %d) is listed but not kept\n", input.name.c_str(),
                         at.x, at.z);
            return false;
        }
        double t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_remove_tile(one, navmesh, at))) {
            fail_nl(input.name, "nl_navmesh_remove_tile");
            return false;
        }
        const double t1 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_add_tile(one, navmesh, &def->def))) {
            fail_nl(input.name, "nl_navmesh_add_tile");
            return false;
        }
        const double t2 = nl::samples::now_ms();
        nl_remove.push_back(t1 - t0), nl_add.push_back(t2 - t1), nl_swap.push_back(t2 - t0);

        const float centre[2] = {float(level.origin_x + (at.x + 0.5) * level.tile_width),
                                 float(level.origin_z + (at.z + 0.5) * level.tile_width)};
        const float box_min[3] = {centre[0] - 0.25f, level.bmin[1], centre[1] - 0.25f};
        const float box_max[3] = {centre[0] + 0.25f, level.bmax[1], centre[1] + 0.25f};
        t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_build_tiles(one, navmesh, &build, box_min, box_max))) {
            fail_nl(input.name, "nl_navmesh_build_tiles");
            return false;
        }
        nl_rebuild.push_back(nl::samples::now_ms() - t0);

        auto held = std::find_if(tiles->tiles.begin(), tiles->tiles.end(),
                                 [&](const nl::bench::DetourTile& t) { return t.x == at.x && t.z == at.z; });
        if (held == tiles->tiles.end()) continue;  // no Detour data there
        std::vector<double> swaps;
        for (int k = 0; k < kDetourSwapRepeats; ++k) {
            dtTileRef ref = mesh.getTileRefAt(at.x, at.z, 0);
            unsigned char* data = nullptr;
            int size = 0;
            t0 = nl::samples::now_ms();
            mesh.removeTile(ref, &data, &size);
            const dtStatus added = mesh.addTile(data, size, 0, 0, nullptr);
            swaps.push_back(nl::samples::now_ms() - t0);
            if (dtStatusFailed(added)) {
                std::fprintf(stderr, "navlink-bench-tiles: %s: Detour refused tile (%d, %d) again\n",
                             input.name.c_str(), at.x, at.z);
                return false;
            }
        }
        detour_swap.push_back(median(swaps));
        t0 = nl::samples::now_ms();
        nl::bench::DetourTile rebuilt = nl::bench::build_detour_tile(level, at.x, at.z);
        unsigned char* old = nullptr;
        int old_size = 0;
        mesh.removeTile(mesh.getTileRefAt(at.x, at.z, 0), &old, &old_size);
        const dtStatus added = rebuilt.data ? mesh.addTile(rebuilt.data, rebuilt.bytes, 0, 0, nullptr) : DT_SUCCESS;
        detour_rebuild.push_back(nl::samples::now_ms() - t0);
        dtFree(old);
        held->data = rebuilt.data, held->bytes = rebuilt.bytes, held->polygons = rebuilt.polygons;
        if (dtStatusFailed(added)) {
            std::fprintf(stderr, "navlink-bench-tiles: %s: Detour refused rebuilt tile (%d, %d)\n", input.name.c_str(),
                         at.x, at.z);
            return false;
        }
    }
    row.swaps = int(coords.size());
    row.nl_remove = median(nl_remove);
    row.nl_add = median(nl_add);
    row.nl_swap = median(nl_swap);
    row.detour_swap = median(detour_swap);
    row.nl_rebuild = median(nl_rebuild);
    row.detour_rebuild = median(detour_rebuild);
    return true;
}

// 5 and 6 run in a child process per level and size (the bench run again with --child-world or
// --child-level), so that its RSS and peak are the tiled navmesh's alone.

// Resident bytes now (/proc/self/statm), after handing the allocator's free pages back (malloc_trim)
// unless `raw`.
double rss_bytes(bool raw = false) {
    if (!raw) malloc_trim(0);
    long pages = 0, resident = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(sysconf(_SC_PAGESIZE));
}

double peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) * 1024.0;  // kilobytes on Linux
}

uint32_t link_count(nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    nl_navmesh_get_links(world, navmesh, nullptr, 0, &count);
    return count;
}

// Path requests kept in flight: the main thread submits a batch, and each request's callback (on a
// path worker) counts its outcome, releases it and submits the next from the pool while `flowing`.
struct Flow {
    nl_world* world = nullptr;
    std::vector<nl_path_request_def> pool;
    std::atomic<uint64_t> next{0};
    std::atomic<bool> flowing{false};
    std::atomic<uint64_t> outcomes[NL_PATH_FAILED + 2]{};  // the last: any other value
    std::atomic<uint64_t> refused{0};                      // nl_path_request failed
};

void submit_one(Flow& flow) {
    const nl_path_request_def& def = flow.pool[flow.next.fetch_add(1) % flow.pool.size()];
    nl_path_ticket ticket{};
    if (NL_FAILED(nl_path_request(flow.world, &def, &ticket))) flow.refused.fetch_add(1);
}

void flow_finished(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    Flow& flow = *static_cast<Flow*>(user);
    flow.outcomes[std::min<nl_path_outcome>(outcome, NL_PATH_FAILED + 1)].fetch_add(1);
    nl_path_release(flow.world, ticket);
    if (flow.flowing.load()) submit_one(flow);
}

nl_path_queue_stats queue_stats(nl_world* world) {
    nl_path_queue_stats stats = nl_path_queue_stats_init();
    nl_path_get_queue_stats(world, &stats);
    return stats;
}

// Stops the flow and waits until every request's callback has returned.
void drain(Flow& flow) {
    flow.flowing.store(false);
    for (;;) {
        const nl_path_queue_stats stats = queue_stats(flow.world);
        if (stats.finished == stats.submitted && stats.unreleased == 0) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// 6: the tiles of table 4 out and in again with their links, idle and then with the path queue busy.
bool stream_tiles(const std::string& name, const Options& options, nl_world* world, nl_navmesh_id navmesh,
                  const nl_navmesh_build_def& build, Figures& f) {
    nl_navmesh_info info = nl_navmesh_info_init();
    nl_navmesh_get_info(world, navmesh, &info);
    const std::vector<nl_tile_coord> coords = tiles_to_swap(world, navmesh, options.swaps);
    f["s_tiles"] = double(coords.size());
    f["path_workers"] = queue_stats(world).workers;
    f["links_start"] = link_count(world, navmesh);
    f["polygons_start"] = info.polygon_count;
    if (coords.empty() || queue_stats(world).workers == 0) return true;

    nl_agent_capabilities jumper = nl_default_agent_capabilities();
    jumper.max_jump_distance = 4.0f, jumper.max_jump_height = 1.5f, jumper.max_drop_height = 5.0f;
    Flow flow;
    flow.world = world;
    // Per mode (0 idle, 1 busy): each op's times over the tiles, and the requests finished meanwhile.
    enum Op { kSave, kRemove, kAdd, kSwap, kRemoveAgain, kBuild, kRebuild, kOps };
    static const char* const kOpNames[kOps] = {"save", "remove", "add", "swap", "rremove", "build", "rebuild"};
    std::vector<double> ms[2][kOps], done[2][kOps];
    std::vector<double> request_ms[2][2];  // the first and the next request after a change: submit, wait
    std::vector<double> first_done_ms;     // the busy batch's first request done
    std::vector<unsigned char> bytes;
    for (size_t i = 0; i < coords.size(); ++i) {
        const nl_tile_coord at = coords[i];
        const float centre[3] = {info.tile_origin[0] + (float(at.x) + 0.5f) * info.tile_width, 0.0f,
                                 info.tile_origin[1] + (float(at.z) + 0.5f) * info.tile_width};
        // Requests between points within 4 tiles of it, drawn while it is loaded: those with an end on
        // it find that end off the navmesh while it is out.
        nl_random_points_def around = nl_default_random_points_def();
        std::copy(centre, centre + 3, around.centre);
        around.radius = 4.0f * info.tile_width;
        around.seed = 1000 + i;
        std::vector<nl_nav_point> points(512);
        uint32_t found = 0;
        if (NL_FAILED(
                nl_navmesh_random_points(world, navmesh, &around, points.data(), uint32_t(points.size()), &found)) ||
            found < 2) {
            fail_nl(name, "nl_navmesh_random_points");
            return false;
        }
        flow.pool.clear();
        for (uint32_t k = 0; k + 1 < found; k += 2) {
            nl_path_request_def def = nl_default_path_request_def();
            def.navmesh = navmesh;
            std::copy(points[k].point, points[k].point + 3, def.start);
            std::copy(points[k + 1].point, points[k + 1].point + 3, def.goal);
            def.capabilities = jumper;
            def.callback = flow_finished;
            def.user = &flow;
            flow.pool.push_back(def);
        }
        if (i == 0) {
            // The queue's pace on a navmesh that does not change: 100 ms to warm up (the body's
            // reachability map), then requests finished over 300 ms.
            flow.flowing.store(true);
            for (int b = 0; b < options.queue_batch; ++b) submit_one(flow);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            const uint64_t before = queue_stats(world).finished;
            const double t0 = nl::samples::now_ms();
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            f["steady_per_s"] = double(queue_stats(world).finished - before) * 1000.0 / (nl::samples::now_ms() - t0);
            drain(flow);
        }
        const float box_min[3] = {centre[0] - 0.25f, info.bounds_min[1], centre[2] - 0.25f};
        const float box_max[3] = {centre[0] + 0.25f, info.bounds_max[1], centre[2] + 0.25f};
        for (int busy = 0; busy < 2; ++busy) {
            std::fprintf(stderr, "%s: tile (%d, %d) out and in with its links, %s\n", name.c_str(), at.x, at.z,
                         busy ? "paths queued" : "idle");
            if (busy) {
                flow.flowing.store(true);
                // The navmesh changed just before (the tile built again, idle): how long until the
                // first of the batch is done.
                const uint64_t before = queue_stats(world).finished;
                for (int b = 0; b < options.queue_batch; ++b) submit_one(flow);
                const double t0 = nl::samples::now_ms();
                while (queue_stats(world).finished == before && nl::samples::now_ms() - t0 < 600000.0)
                    std::this_thread::sleep_for(std::chrono::microseconds(50));
                first_done_ms.push_back(nl::samples::now_ms() - t0);
            }
            double op_ms[kOps] = {}, op_done[kOps] = {};
            auto timed = [&](Op op, auto&& call) {
                const uint64_t before = queue_stats(world).finished;
                const double t0 = nl::samples::now_ms();
                const nl_status status = call();
                op_ms[op] = nl::samples::now_ms() - t0;
                op_done[op] = double(queue_stats(world).finished - before);
                return NL_SUCCEEDED(status);
            };
            size_t size = 0;
            const bool ok =
                timed(kSave,
                      [&] {
                          nl_status status = nl_navmesh_save_tile(world, navmesh, at, nullptr, 0, &size);
                          if (NL_FAILED(status)) return status;
                          bytes.resize(size);
                          return nl_navmesh_save_tile(world, navmesh, at, bytes.data(), bytes.size(), &size);
                      }) &&
                timed(kRemove, [&] { return nl_navmesh_remove_tile(world, navmesh, at); }) &&
                timed(kAdd, [&] { return nl_navmesh_add_tile_bytes(world, navmesh, bytes.data(), size); }) &&
                timed(kRemoveAgain, [&] { return nl_navmesh_remove_tile(world, navmesh, at); }) &&
                timed(kBuild, [&] { return nl_navmesh_build_tiles(world, navmesh, &build, box_min, box_max); });
            if (!busy && ok) {
                // The tile is back (built again), and the change built the new navmesh's path graph
                // (paths were asked for on it): the first request finds it, as the next does.
                nl_path_request_def def = flow.pool[0];
                def.callback = nullptr, def.user = nullptr;
                for (int k = 0; k < 2; ++k) {
                    nl_path_ticket ticket{};
                    nl_path_outcome outcome = NL_PATH_PENDING;
                    const double t0 = nl::samples::now_ms();
                    if (NL_FAILED(nl_path_request(world, &def, &ticket))) {
                        fail_nl(name, "nl_path_request");
                        return false;
                    }
                    const double t1 = nl::samples::now_ms();
                    nl_path_wait(world, ticket, NL_PATH_WAIT_FOREVER, &outcome);
                    request_ms[k][0].push_back(t1 - t0), request_ms[k][1].push_back(nl::samples::now_ms() - t1);
                    nl_path_release(world, ticket);
                }
            }
            if (busy) drain(flow);
            std::fprintf(stderr, "%s: tile (%d, %d) %s: RSS %.1f MB, peak %.1f MB\n", name.c_str(), at.x, at.z,
                         busy ? "paths queued" : "idle", rss_bytes() / (1024.0 * 1024.0),
                         peak_rss_bytes() / (1024.0 * 1024.0));
            if (!ok) {
                fail_nl(name, "a tile out and in with its links");
                return false;
            }
            op_ms[kSwap] = op_ms[kRemove] + op_ms[kAdd], op_done[kSwap] = op_done[kRemove] + op_done[kAdd];
            op_ms[kRebuild] = op_ms[kRemoveAgain] + op_ms[kBuild];
            op_done[kRebuild] = op_done[kRemoveAgain] + op_done[kBuild];
            for (int op = 0; op < kOps; ++op) ms[busy][op].push_back(op_ms[op]), done[busy][op].push_back(op_done[op]);
        }
    }
    for (int busy = 0; busy < 2; ++busy)
        for (int op = 0; op < kOps; ++op) {
            const std::string key = std::string(busy ? "busy_" : "idle_") + kOpNames[op];
            f[key + "_ms"] = median(ms[busy][op]);
            if (busy) f[key + "_done"] = median(done[busy][op]);
        }
    double during = 0.0, during_ms = 0.0;  // requests finished during the busy ops, all tiles
    for (int op : {kSave, kSwap, kRebuild})
        for (size_t k = 0; k < coords.size(); ++k) during += done[1][op][k], during_ms += ms[1][op][k];
    f["paths_during"] = during;
    f["first_submit_ms"] = median(request_ms[0][0]), f["first_wait_ms"] = median(request_ms[0][1]);
    f["next_submit_ms"] = median(request_ms[1][0]), f["next_wait_ms"] = median(request_ms[1][1]);
    f["first_done_ms"] = median(first_done_ms);
    f["first_done_max_ms"] = *std::max_element(first_done_ms.begin(), first_done_ms.end());
    f["during_per_s"] = during * 1000.0 / during_ms;
    const nl_path_queue_stats stats = queue_stats(world);
    f["paths_submitted"] = double(stats.submitted);
    f["paths_finished"] = double(stats.finished);
    static const char* const kOutcomes[] = {"pending",  "complete",  "partial", "no_path", "start_off",
                                            "goal_off", "cancelled", "failed",  "other"};
    for (uint32_t k = 0; k <= NL_PATH_FAILED + 1; ++k) f[std::string("out_") + kOutcomes[k]] = double(flow.outcomes[k]);
    f["out_refused"] = double(flow.refused);
    info = nl_navmesh_info_init();
    nl_navmesh_get_info(world, navmesh, &info);
    f["links_end"] = link_count(world, navmesh);
    f["polygons_end"] = info.polygon_count;
    return true;
}

// A child process: one level (a generated world of --child-world km, or --child-level's OBJ) built in
// tiles on a world with every worker, its links generated; prints its figures on one line.
int run_child(const Options& options) {
    const LevelInput input =
        options.child_level.empty() ? make_world(options.child_world_km) : read_level(options.child_level);
    Figures f;
    f["triangles"] = input.triangle_count();
    const WorldPtr world_ptr = make_nl_world(input, NL_WORKERS_AUTO, options.child_streaming ? NL_WORKERS_AUTO : 0);
    nl_world* world = world_ptr.get();
    if (!world) {
        fail_nl(input.name, "world");
        return 1;
    }
    f["workers"] = nl_world_get_worker_count(world);
    f["rss_before"] = rss_bytes();

    nl_recast_settings settings = nl_default_recast_settings();
    settings.tile_size = options.tile_size;
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.settings = &settings;
    nl_navmesh_id navmesh{};
    std::fprintf(stderr, "%s (child): build\n", input.name.c_str());
    double t0 = nl::samples::now_ms();
    if (NL_FAILED(nl_navmesh_build(world, &build, &navmesh))) {
        fail_nl(input.name, "nl_navmesh_build");
        return 1;
    }
    f["build_s"] = (nl::samples::now_ms() - t0) / 1000.0;
    nl_navmesh_info info = nl_navmesh_info_init();
    nl_navmesh_get_info(world, navmesh, &info);
    f["tiles"] = info.tile_count;
    f["polygons"] = info.polygon_count;
    f["rss_navmesh_raw"] = rss_bytes(true);
    f["rss_navmesh"] = rss_bytes();

    std::fprintf(stderr, "%s (child): links\n", input.name.c_str());
    nl_link_generation_report report = nl_link_generation_report_init();
    t0 = nl::samples::now_ms();
    if (NL_FAILED(nl_navmesh_generate_links(world, navmesh, nullptr, nullptr, nullptr, &report))) {
        fail_nl(input.name, "nl_navmesh_generate_links");
        return 1;
    }
    f["links_s"] = (nl::samples::now_ms() - t0) / 1000.0;
    f["links_generation_ms"] = report.milliseconds_total;
    f["links"] = link_count(world, navmesh);
    f["rss_links_raw"] = rss_bytes(true);
    f["rss_links"] = rss_bytes();
    f["peak"] = peak_rss_bytes();

    // Baked: every tile's file, or up to 1,024 of them spread over the row order, fewer when saving one
    // takes long (about 15 s in all, 16 at least: the first, timed alone, says).
    uint32_t loaded = 0;
    nl_navmesh_get_tiles(world, navmesh, nullptr, 0, &loaded);
    std::vector<nl_tile_coord> coords(loaded);
    nl_navmesh_get_tiles(world, navmesh, coords.data(), loaded, &loaded);
    std::vector<unsigned char> bytes;
    auto save = [&](nl_tile_coord at, size_t& size) {
        if (NL_FAILED(nl_navmesh_save_tile(world, navmesh, at, nullptr, 0, &size))) return false;
        bytes.resize(size);
        return NL_SUCCEEDED(nl_navmesh_save_tile(world, navmesh, at, bytes.data(), bytes.size(), &size));
    };
    size_t size = 0;
    t0 = nl::samples::now_ms();
    if (coords.empty() || !save(coords[coords.size() / 2], size)) {
        fail_nl(input.name, "nl_navmesh_save_tile");
        return 1;
    }
    const double one_ms = std::max(1e-3, nl::samples::now_ms() - t0);
    const size_t count = std::min(coords.size(), std::clamp<size_t>(size_t(15000.0 / one_ms), 16, 1024));
    const size_t stride = std::max<size_t>(1, coords.size() / count);
    double baked = 0.0, sampled = 0.0;
    t0 = nl::samples::now_ms();
    for (size_t i = 0; i < coords.size(); i += stride) {
        if (!save(coords[i], size)) {
            fail_nl(input.name, "nl_navmesh_save_tile");
            return 1;
        }
        baked += double(size), ++sampled;
    }
    f["save_tile_ms"] = sampled ? (nl::samples::now_ms() - t0) / sampled : NAN;
    f["baked"] = sampled ? baked / sampled : NAN;
    f["baked_sampled"] = sampled;
    f["peak_baked"] = peak_rss_bytes();
    f["rss_baked"] = rss_bytes();

    if (options.child_streaming && !stream_tiles(input.name, options, world, navmesh, build, f)) return 1;
    f["peak_end"] = peak_rss_bytes();
    f["rss_end"] = rss_bytes();
    std::printf("NLCHILD");
    for (const auto& [key, value] : f) std::printf(" %s=%.17g", key.c_str(), value);
    std::printf("\n");
    std::fflush(stdout);
    return 0;
}

std::string shell_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// Runs the bench again as a child process with `args`, and reads the figures it prints.
bool run_child_process(const std::string& args, Figures& out) {
    const std::string command = shell_quoted(std::filesystem::read_symlink("/proc/self/exe").string()) + " " + args;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return false;
    std::string line;
    bool found = false;
    for (int c; (c = std::fgetc(pipe)) != EOF;) {
        if (c != '\n') {
            line += char(c);
            continue;
        }
        if (line.rfind("NLCHILD ", 0) == 0) {
            found = true;
            size_t at = 8;
            while (at < line.size()) {
                size_t end = line.find(' ', at);
                if (end == std::string::npos) end = line.size();
                const std::string token = line.substr(at, end - at);
                const size_t eq = token.find('=');
                if (eq != std::string::npos) out[token.substr(0, eq)] = std::strtod(token.c_str() + eq + 1, nullptr);
                at = end + 1;
            }
        }
        line.clear();
    }
    const int status = pclose(pipe);
    if (!found || status != 0) std::fprintf(stderr, "navlink-bench-tiles: child failed: %s\n", command.c_str());
    return found && status == 0;
}

// The children of one level: `sizes` (each its km, NAN for an OBJ level, and its arguments; smallest
// first; the last is the whole level and also runs 6).
bool run_children(const std::vector<std::pair<double, std::string>>& sizes, const Options& options, Row& row) {
    bool ok = true;
    const std::string common = " --tile-size " + std::to_string(options.tile_size) + " --swaps " +
                               std::to_string(options.swaps) + " --queue-batch " + std::to_string(options.queue_batch);
    for (size_t i = 0; i < sizes.size(); ++i) {
        Figures f;
        const bool last = i + 1 == sizes.size();
        if (!run_child_process(sizes[i].second + common + (last ? " --child-streaming" : ""), f)) {
            ok = false;
            continue;
        }
        f["km"] = sizes[i].first;
        row.sizes.push_back(f);
        if (last) row.streaming = f;
    }
    return ok;
}

void print_tables(const std::vector<Row>& rows, const Options& options) {
    std::printf("\nLevels (tile_size %u cells of 0.3 m: tiles of %.1f m)\n", options.tile_size,
                options.tile_size * 0.3);
    std::printf("%-16s %10s %9s %9s %9s %10s %10s\n", "level", "triangles", "grid", "nl_tiles", "dt_tiles", "nl_polys",
                "dt_polys");
    for (const Row& r : rows)
        std::printf("%-16s %10u %4dx%-4d %9u %9zu %10u %10d\n", r.name.c_str(), r.triangles, r.grid_x, r.grid_z,
                    r.nl_tiles, r.detour_tiles, r.nl_polygons, r.detour_polygons);

    std::printf("\n1. Build, ms per tile (median of %d; Detour: single thread, binning included)\n", options.reps);
    std::printf("%-16s %9s %9s %9s %9s %9s %11s %9s\n", "level", "nl_1w", "detour", "nl/dt", "nl_2w", "1w/2w",
                "nl_builder", "join_ms");
    for (const Row& r : rows)
        std::printf("%-16s %9.3f %9.3f %9.2f %9.3f %9.2f %11.3f %9.1f\n", r.name.c_str(), r.nl1, r.detour,
                    r.nl1 / r.detour, r.nl2, r.nl1 / r.nl2, r.builder, r.join);

    std::printf("\n2. Memory, bytes per tile\n");
    std::printf("%-16s %10s %10s %10s %9s %14s\n", "level", "nl_navmesh", "nl_kept", "detour", "nl/dt", "(nl+kept)/dt");
    for (const Row& r : rows)
        std::printf("%-16s %10.0f %10.0f %10.0f %9.2f %14.2f\n", r.name.c_str(), r.nl_bytes, r.nl_inputs,
                    r.detour_bytes, r.nl_bytes / r.detour_bytes, (r.nl_bytes + r.nl_inputs) / r.detour_bytes);

    std::printf(
        "\n3. Paths between tiles (median round of %d; both/dt: the time ratio over the pairs both complete; lengths\n"
        "   seen from above, over the pairs both complete, Detour planned again from NavLink's ends and polygons)\n",
        options.reps);
    std::printf("%-16s %7s %9s %9s %7s %8s %8s %8s %8s %12s %7s\n", "level", "pairs", "nl_us", "detour_us", "nl/dt",
                "nl_done", "dt_done", "both/dt", "compared", "worst_excess", ">0.1%");
    for (const Row& r : rows) {
        if (r.pairs == 0) {
            std::printf("%-16s %7d  (one tile: no pairs between tiles)\n", r.name.c_str(), 0);
            continue;
        }
        std::printf("%-16s %7d %9.2f %9.2f %7.2f %8d %8d %8.2f %8d %11.4f%% %7d\n", r.name.c_str(), r.pairs, r.nl_us,
                    r.detour_us, r.nl_us / r.detour_us, r.nl_complete, r.detour_complete, r.both_ratio, r.compared,
                    100.0 * r.worst_excess, r.over);
    }

    for (const Row& r : rows)
        if (r.over > 0)
            std::printf(
                "  %s worst: nl_path_find from (%.3f %.3f %.3f) to (%.3f %.3f %.3f): NavLink %.3f m, Detour %.3f m\n",
                r.name.c_str(), r.worst.start[0], r.worst.start[1], r.worst.start[2], r.worst.goal[0], r.worst.goal[1],
                r.worst.goal[2], r.worst_nl, r.worst_detour);

    std::printf(
        "\n4. Tiles in and out, ms (median over the tiles): swap = remove + add of the tile as built; rebuild =\n"
        "   nl_navmesh_build_tiles of the tile / Detour's Recast build of it swapped in\n");
    std::printf("%-16s %5s %9s %9s %9s %9s %9s %10s %10s %9s %14s\n", "level", "tiles", "nl_remove", "nl_add",
                "nl_swap", "dt_swap", "nl/dt", "nl_rebuild", "dt_rebuild", "nl/dt", "nl_swap/dt_reb");
    for (const Row& r : rows)
        std::printf("%-16s %5d %9.3f %9.3f %9.3f %9.4f %9.0f %10.3f %10.3f %9.2f %14.2f\n", r.name.c_str(), r.swaps,
                    r.nl_remove, r.nl_add, r.nl_swap, r.detour_swap, r.nl_swap / r.detour_swap, r.nl_rebuild,
                    r.detour_rebuild, r.nl_rebuild / r.detour_rebuild, r.nl_swap / r.detour_rebuild);

    if (!options.links_sections) return;
    const double mb = 1.0 / (1024.0 * 1024.0);
    std::printf(
        "\n5. The tiled navmesh with its links, a world per size (each in a child process: nl_navmesh_build on all\n"
        "   workers, then nl_navmesh_generate_links, default settings). RSS (/proc/self/statm, after malloc_trim)\n"
        "   before the build (the level held), after it, after the links; bytes per tile from their differences (raw:\n"
        "   without malloc_trim); marg: per tile more than the size above; peak: getrusage's maxrss less RSS before;\n"
        "   baked: nl_navmesh_save_tile's bytes\n");
    std::printf("%-16s %6s %6s %9s %8s %8s %8s %9s %9s %9s %9s %8s %8s %8s %8s %8s %8s %8s\n", "level", "km", "tiles",
                "polygons", "links", "build_s", "links_s", "before_MB", "navmsh_MB", "links_MB", "peak_MB", "nav_B/t",
                "link_B/t", "total/t", "marg/t", "raw/t", "peak/t", "baked/t");
    for (const Row& r : rows)
        for (size_t k = 0; k < r.sizes.size(); ++k) {
            const Figures& f = r.sizes[k];
            const double tiles = std::max(1.0, figure(f, "tiles")), before = figure(f, "rss_before");
            char km[16] = "-";  // an OBJ level's
            if (std::isfinite(figure(f, "km"))) std::snprintf(km, sizeof km, "%.3f", figure(f, "km"));
            // Per tile more than the size before: what the bytes per tile tend to, past fixed costs.
            double marginal = NAN;
            if (k > 0) {
                const Figures& e = r.sizes[k - 1];
                marginal = ((figure(f, "rss_links") - before) - (figure(e, "rss_links") - figure(e, "rss_before"))) /
                           (figure(f, "tiles") - figure(e, "tiles"));
            }
            std::printf(
                "%-16s %6s %6.0f %9.0f %8.0f %8.2f %8.2f %9.1f %9.1f %9.1f %9.1f %8.0f %8.0f %8.0f %8.0f %8.0f %8.0f "
                "%8.0f\n",
                r.name.c_str(), km, figure(f, "tiles"), figure(f, "polygons"), figure(f, "links"), figure(f, "build_s"),
                figure(f, "links_s"), before * mb, figure(f, "rss_navmesh") * mb, figure(f, "rss_links") * mb,
                figure(f, "peak") * mb, (figure(f, "rss_navmesh") - before) / tiles,
                (figure(f, "rss_links") - figure(f, "rss_navmesh")) / tiles, (figure(f, "rss_links") - before) / tiles,
                marginal, (figure(f, "rss_links_raw") - before) / tiles, (figure(f, "peak") - before) / tiles,
                figure(f, "baked"));
        }
    for (const Row& r : rows) {
        if (r.sizes.empty()) continue;
        const Figures& f = r.sizes.back();
        const double per_tile = (figure(f, "peak") - figure(f, "rss_before")) / std::max(1.0, figure(f, "tiles"));
        const double tiles = 24e9 / per_tile, width = options.tile_size * nl_default_recast_settings().cell_size;
        std::printf(
            "  %s: at its peak per tile, 24 GB holds %.0f tiles: a square of %.1f km; links: %.2f s, of which the\n"
            "    generation's report counts %.2f s; %.0f tiles' files sampled, %.2f ms each to save; peak %.1f MB\n"
            "    after saving them; after 6: peak %.1f MB, RSS %.1f MB (%.1f MB before 6)\n",
            r.name.c_str(), tiles, std::sqrt(tiles) * width / 1000.0, figure(f, "links_s"),
            figure(f, "links_generation_ms") / 1000.0, figure(f, "baked_sampled"), figure(f, "save_tile_ms"),
            figure(f, "peak_baked") * mb, figure(f, "peak_end") * mb, figure(f, "rss_end") * mb,
            figure(f, "rss_baked") * mb);
    }

    std::printf(
        "\n6. Tiles in and out with their links while paths are queued (the whole level, its links generated; the\n"
        "   tiles of 4, ms, medians over them): swap = nl_navmesh_remove_tile + nl_navmesh_add_tile_bytes of the\n"
        "   tile's nl_navmesh_save_tile bytes (save: writing them); rebuild = nl_navmesh_remove_tile (rrem) +\n"
        "   nl_navmesh_build_tiles of it (its links and those of the tiles within reach generated again); busy: %d\n"
        "   requests kept in flight on the path workers (ends within 4 tiles of the tile; each finished one "
        "replaced);\n"
        "   idle: none; done: requests finished during it (median); dt: 4's removeTile + addTile, and its Recast "
        "rebuild\n",
        options.queue_batch);
    std::printf("%-16s %5s %7s %8s %8s %8s %8s %8s %9s %6s %8s %8s %8s %8s %8s %8s %8s %6s\n", "level", "tiles", "save",
                "remove", "add", "swap", "idl_swap", "dt_swap", "swap/dt", "done", "rrem", "build", "rebuild",
                "idl_reb", "dt_reb", "reb/dt", "swp/dtrb", "done");
    for (const Row& r : rows) {
        const Figures& f = r.streaming;
        if (f.empty() || !(figure(f, "s_tiles") > 0)) continue;
        std::printf(
            "%-16s %5.0f %7.3f %8.3f %8.3f %8.3f %8.3f %8.4f %9.0f %6.0f %8.3f %8.3f %8.3f %8.3f %8.3f %8.2f %8.2f "
            "%6.0f\n",
            r.name.c_str(), figure(f, "s_tiles"), figure(f, "busy_save_ms"), figure(f, "busy_remove_ms"),
            figure(f, "busy_add_ms"), figure(f, "busy_swap_ms"), figure(f, "idle_swap_ms"), r.detour_swap,
            figure(f, "busy_swap_ms") / r.detour_swap, figure(f, "busy_swap_done"), figure(f, "busy_rremove_ms"),
            figure(f, "busy_build_ms"), figure(f, "busy_rebuild_ms"), figure(f, "idle_rebuild_ms"), r.detour_rebuild,
            figure(f, "busy_rebuild_ms") / r.detour_rebuild, figure(f, "busy_swap_ms") / r.detour_rebuild,
            figure(f, "busy_rebuild_done"));
    }
    for (const Row& r : rows) {
        const Figures& f = r.streaming;
        if (f.empty() || !(figure(f, "s_tiles") > 0)) continue;
        const double unexpected = figure(f, "out_no_path") + figure(f, "out_cancelled") + figure(f, "out_failed") +
                                  figure(f, "out_pending") + figure(f, "out_other") + figure(f, "out_refused");
        std::printf(
            "  %s: %.0f path workers; requests finished per second: %.0f while the navmesh stays, %.0f during the busy "
            "changes;\n    requests submitted %.0f, finished %.0f (%.0f during the busy changes): complete "
            "%.0f, partial %.0f,\n    start off the navmesh %.0f, goal off %.0f (an end on the tile while it was "
            "out);\n"
            "    unexpected: %.0f (no path %.0f, cancelled %.0f, failed %.0f, refused %.0f)%s; links %.0f before, %.0f "
            "after; polygons %.0f before, %.0f after%s\n",
            r.name.c_str(), figure(f, "path_workers"), figure(f, "steady_per_s"), figure(f, "during_per_s"),
            figure(f, "paths_submitted"), figure(f, "paths_finished"), figure(f, "paths_during"),
            figure(f, "out_complete"), figure(f, "out_partial"), figure(f, "out_start_off"), figure(f, "out_goal_off"),
            unexpected, figure(f, "out_no_path"), figure(f, "out_cancelled"), figure(f, "out_failed"),
            figure(f, "out_refused"), unexpected > 0 ? " (!)" : "", figure(f, "links_start"), figure(f, "links_end"),
            figure(f, "polygons_start"), figure(f, "polygons_end"),
            figure(f, "links_start") != figure(f, "links_end") ||
                    figure(f, "polygons_start") != figure(f, "polygons_end")
                ? " (!)"
                : "");
        std::printf(
            "    a request on the navmesh just changed (idle queue): nl_path_request %.3f ms (the change built the "
            "graph),\n    %.3f ms more until done; the next request: %.3f ms, %.3f ms more; the busy batch, submitted "
            "on the\n    navmesh just changed: its first request done after %.3f ms (median; at most %.3f)\n",
            figure(f, "first_submit_ms"), figure(f, "first_wait_ms"), figure(f, "next_submit_ms"),
            figure(f, "next_wait_ms"), figure(f, "first_done_ms"), figure(f, "first_done_max_ms"));
    }
}

int usage() {
    std::fprintf(
        stderr,
        "usage: navlink-bench-tiles [--world-km K] [--tile-size N] [--reps N] [--pairs N] "
        "[--max-pair-distance M] [--swaps N] [--detour-nodes N] [--queue-batch N] [--no-breakdown] [--no-links] "
        "[--smoke] "
        "[[--levels] LEVEL.obj...]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--world-km" && has_value) {
            options.world_km = std::atof(argv[++i]);
        } else if (arg == "--tile-size" && has_value) {
            options.tile_size = uint32_t(std::atoi(argv[++i]));
        } else if (arg == "--reps" && has_value) {
            options.reps = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--pairs" && has_value) {
            options.pairs = std::atoi(argv[++i]);
        } else if (arg == "--max-pair-distance" && has_value) {
            options.max_pair_distance = float(std::atof(argv[++i]));
        } else if (arg == "--swaps" && has_value) {
            options.swaps = std::atoi(argv[++i]);
        } else if (arg == "--detour-nodes" && has_value) {
            options.detour_nodes = std::clamp(std::atoi(argv[++i]), 1, 65535);
        } else if (arg == "--queue-batch" && has_value) {
            options.queue_batch = std::max(1, std::atoi(argv[++i]));
        } else if (arg == "--no-breakdown") {
            options.breakdown = false;
        } else if (arg == "--no-links") {
            options.links_sections = false;
        } else if (arg == "--child-world" && has_value) {
            options.child_world_km = std::atof(argv[++i]);
        } else if (arg == "--child-level" && has_value) {
            options.child_level = argv[++i];
        } else if (arg == "--child-streaming") {
            options.child_streaming = true;
        } else if (arg == "--smoke") {
            options.world_km = 0.1, options.reps = 1, options.pairs = 200, options.swaps = 2;
        } else if (arg == "--levels") {
            continue;  // the files follow
        } else if (arg.rfind("--", 0) == 0) {
            return usage();
        } else {
            options.objs.push_back(arg);
        }
    }
    if (options.child_world_km > 0.0 || !options.child_level.empty()) {
        try {
            return run_child(options);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-tiles (child): %s\n", e.what());
            return 1;
        }
    }
    if (options.world_km <= 0.0 && options.objs.empty()) return usage();

    std::vector<Row> rows;
    bool ok = true;
    // 5 and 6 first, in child processes (while this one holds no level), then 1 to 4 here.
    auto run = [&](const std::vector<std::pair<double, std::string>>& children, auto make_level) {
        Row row;
        if (options.links_sections) ok = run_children(children, options, row) && ok;
        const LevelInput level = make_level();
        try {
            ok = measure(level, options, row) && ok;
            rows.push_back(row);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-tiles: %s: %s\n", level.name.c_str(), e.what());
            ok = false;
        }
    };
    if (options.world_km > 0.0) {
        // Worlds of a quarter and a half of the tiles (whole tiles a side), then the world itself.
        const double width = options.tile_size * nl_default_recast_settings().cell_size;
        const int side = int(std::ceil(options.world_km * 1000.0 / width));
        std::vector<std::pair<double, std::string>> children;
        for (double fraction : {0.5, std::sqrt(0.5)}) {
            const int n = std::max(1, int(std::lround(side * fraction)));
            const double km = (n * width - 0.5) / 1000.0;  // n tiles a side, the last a little narrower
            if (n < side && (children.empty() || km > children.back().first))
                children.emplace_back(km, "--child-world " + std::to_string(km));  // 6 decimals: exact
        }
        char whole[64];
        std::snprintf(whole, sizeof whole, "--child-world %.17g", options.world_km);
        children.emplace_back(options.world_km, whole);
        run(children, [&] { return make_world(options.world_km); });
    }
    for (const std::string& path : options.objs) {
        try {
            const std::string child = "--child-level " + shell_quoted(path);
            run({{NAN, child}}, [&] { return read_level(path); });
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-tiles: %s: %s\n", path.c_str(), e.what());
            ok = false;
        }
    }
    std::printf(
        "NavLink's tiled navmesh (Recast builder, tile_size %u) against Detour's multi-tile dtNavMesh from the same\n"
        "Recast settings, in this run; ratios NavLink / Detour.\n",
        options.tile_size);
    print_tables(rows, options);
    return ok ? 0 : 1;
}
