// navlink-bench-tiles [--world-km K] [--tile-size N] [--reps N] [--pairs N] [--max-pair-distance M]
//                     [--swaps N] [--detour-nodes N] [--no-breakdown] [--smoke] [[--levels] LEVEL.obj...]:
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
// --smoke: a world of 0.1 km, 1 repetition, 200 pairs, 2 swaps: what ctest runs.
#include <DetourCommon.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
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
    std::vector<std::string> objs;
};

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
WorldPtr make_nl_world(const LevelInput& level, int workers) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    def.path_worker_count = 0;
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
};

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
    uint32_t loaded = 0;
    nl_navmesh_get_tiles(one, navmesh, nullptr, 0, &loaded);
    std::vector<nl_tile_coord> coords(loaded);
    nl_navmesh_get_tiles(one, navmesh, coords.data(), loaded, &loaded);
    std::mt19937 rng(777);
    std::shuffle(coords.begin(), coords.end(), rng);
    coords.resize(std::min<size_t>(coords.size(), size_t(std::max(0, options.swaps))));
    if (loaded < 2) coords.clear();  // a navmesh's last tile cannot be removed
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
}

int usage() {
    std::fprintf(stderr,
                 "usage: navlink-bench-tiles [--world-km K] [--tile-size N] [--reps N] [--pairs N] "
                 "[--max-pair-distance M] [--swaps N] [--detour-nodes N] [--no-breakdown] [--smoke] "
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
        } else if (arg == "--no-breakdown") {
            options.breakdown = false;
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
    if (options.world_km <= 0.0 && options.objs.empty()) return usage();

    std::vector<Row> rows;
    bool ok = true;
    auto run = [&](const LevelInput& level) {
        Row row;
        try {
            ok = measure(level, options, row) && ok;
            rows.push_back(row);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-tiles: %s: %s\n", level.name.c_str(), e.what());
            ok = false;
        }
    };
    if (options.world_km > 0.0) run(make_world(options.world_km));
    for (const std::string& path : options.objs) {
        try {
            run(read_level(path));
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
