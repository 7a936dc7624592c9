// navlink-bench-queries LEVEL.obj...: NavLink's queries for one body against what a game would do
// without them, on the Recast polygon mesh of each level (the path bench's set-up: one mesh handed to
// NavLink through nl_navmesh_add and to Detour through dtCreateNavMeshData). Per level:
//   reach: the reachability map's build time (the core's constructor, best of 5), then for random
//     pairs in different islands (the path bench's random points; the walker of the navmesh's radius)
//     nl_navmesh_can_reach per pair against nl_path_find accepting a partial path (the full search
//     that finds out) and against Detour's findPath for the same located ends; each pair three times,
//     alternately, its fastest time counting.
//   raycast: 10,000 rays from random navmesh points in random directions, 0-10 m long, located by
//     NavLink: nl_navmesh_raycast on the whole batch (one worker), and called once per ray, against
//     Detour's raycast ray by ray from the same polygon and point, fastest of three rounds,
//     alternately; with how often the two agree (both arrive, or both hit within 1 cm). On
//     undulating (coordinates near 5,000 m) about 2% disagree: Detour reports a wall at t = 0 where
//     its segment-polygon test misses the start polygon by rounding, and NavLink walks on.
// Then a large host navmesh (a 400 x 400 grid of quads in strips joined by one-way links): the map's
// build time and an unreachable goal against nl_path_find.
// One line each:
//   reach level=NAME polys=N islands=N map_build_ms=X unreachable_pairs=N reach_us=X path_find_us=X
//     detour_find_path_us=X path_find_ratio=X detour_ratio=X
//   raycast level=NAME rays=N nl_batch_us=X nl_single_us=X detour_us=X detour_with_height_us=X ratio=X
//     height_ratio=X single_height_ratio=X agree=X
//   (Detour's raycast gives t and no point; with getPolyHeight on its last polygon it gives what
//   NavLink's does, the point on the detail surface: height_ratio compares those.)
#include <DetourCommon.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>
#include <navlink/navlink.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "clock.h"
#include "path/reachability.h"
#include "recast_detour.h"
#include "world.h"

namespace {

constexpr int kPairs = 10000;
constexpr int kRays = 10000;
constexpr int kRounds = 3;
constexpr int kMaxPolys = 1024;
constexpr float kHalfExtents[3] = {2.0f, 4.0f, 2.0f};

struct Located {
    float point[3];
    uint32_t polygon;
};

// A random point of the mesh, located by NavLink (so both sides start from the same polygon).
bool locate(nl_world* world, nl_navmesh_id navmesh, const rcPolyMesh& pm, std::mt19937& rng, Located& out) {
    float raw[3];
    nl::bench::random_point(pm, rng, raw);
    nl_nav_point p{};
    if (NL_FAILED(nl_navmesh_find_nearest(world, navmesh, raw, 1, kHalfExtents, &p)) || !p.found) return false;
    std::copy(p.point, p.point + 3, out.point);
    out.polygon = p.polygon;
    return true;
}

void reachability(const nl::bench::RecastLevel& recast, nl_world* world, nl_navmesh_id navmesh, uint32_t polygons,
                  const nl::bench::DetourMesh& detour) {
    const nl::Handle handle{navmesh.index1, navmesh.revision};
    const auto graph = world->core->navmeshes().path_graph(handle);
    nl::AgentCapabilities walker;
    walker.radius = recast.agent.radius;
    const nl::ReachabilityClass body = nl::ReachabilityClass::of(*graph, walker, {});
    double build_ms = 1e300;
    uint32_t islands = 0;
    for (int run = 0; run < 5; ++run) {
        const double t0 = nl::samples::now_ms();
        const nl::ReachabilityMap map(*graph, body);
        build_ms = std::min(build_ms, nl::samples::now_ms() - t0);
        islands = map.island_count();
    }

    // Pairs in different islands among the random pairs.
    std::mt19937 rng(12345);
    std::vector<std::pair<Located, Located>> pairs;
    nl_query_filter filter = nl_default_query_filter();
    filter.capabilities.radius = recast.agent.radius;
    for (int i = 0; i < kPairs; ++i) {
        Located a, b;
        if (!locate(world, navmesh, *recast.solo.polygons, rng, a) ||
            !locate(world, navmesh, *recast.solo.polygons, rng, b))
            continue;
        uint8_t reachable = 1;
        nl_navmesh_can_reach(world, navmesh, &filter, &a.polygon, &b.polygon, 1, &reachable);
        if (!reachable) pairs.emplace_back(a, b);
    }
    const size_t n = std::min<size_t>(pairs.size(), 2000);
    std::vector<double> reach_best(n, 1e300), find_best(n, 1e300), detour_best(n, 1e300);
    std::vector<nl_path_point> points(4096, nl_path_point_init());
    static const dtQueryFilter detour_filter;
    std::vector<dtPolyRef> corridor(kMaxPolys);
    const dtPolyRef base = detour.ref(0);
    for (int round = 0; round < kRounds; ++round) {
        for (size_t i = 0; i < n; ++i) {
            const Located& a = pairs[i].first;
            const Located& b = pairs[i].second;
            uint8_t reachable = 1;
            const double t0 = nl::samples::now_ms();
            nl_navmesh_can_reach(world, navmesh, &filter, &a.polygon, &b.polygon, 1, &reachable);
            const double t1 = nl::samples::now_ms();
            nl_path_request_def def = nl_default_path_request_def();
            def.navmesh = navmesh;
            std::copy(a.point, a.point + 3, def.start);
            std::copy(b.point, b.point + 3, def.goal);
            def.capabilities.radius = recast.agent.radius;
            nl_path_result result = nl_path_result_init();
            uint32_t count = 0;
            nl_path_find(world, &def, &result, points.data(), uint32_t(points.size()), &count);
            const double t2 = nl::samples::now_ms();
            int corridor_count = 0;
            detour.query->findPath(base | a.polygon, base | b.polygon, a.point, b.point, &detour_filter,
                                   corridor.data(), &corridor_count, kMaxPolys);
            const double t3 = nl::samples::now_ms();
            reach_best[i] = std::min(reach_best[i], t1 - t0);
            find_best[i] = std::min(find_best[i], t2 - t1);
            detour_best[i] = std::min(detour_best[i], t3 - t2);
        }
    }
    double reach = 0.0, find = 0.0, detour_ms = 0.0;
    for (size_t i = 0; i < n; ++i) reach += reach_best[i], find += find_best[i], detour_ms += detour_best[i];
    const double per = n ? 1000.0 / double(n) : 0.0;
    std::printf(
        "reach level=%s polys=%u islands=%u map_build_ms=%.3f unreachable_pairs=%zu reach_us=%.3f path_find_us=%.2f "
        "detour_find_path_us=%.2f path_find_ratio=%.4f detour_ratio=%.4f\n",
        recast.name.c_str(), polygons, islands, build_ms, n, reach * per, find * per, detour_ms * per,
        find > 0 ? reach / find : 0.0, detour_ms > 0 ? reach / detour_ms : 0.0);
    std::fflush(stdout);
}

void raycasts(const nl::bench::RecastLevel& recast, nl_world* world, nl_navmesh_id navmesh,
              const nl::bench::DetourMesh& detour) {
    struct Ray {
        Located start;
        float end[3];
    };
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> angle(0.0f, 6.2831853f), length(0.0f, 10.0f);
    std::vector<Ray> rays;
    while (rays.size() < size_t(kRays)) {
        Ray r;
        if (!locate(world, navmesh, *recast.solo.polygons, rng, r.start)) continue;
        const float a = angle(rng), l = length(rng);
        r.end[0] = r.start.point[0] + l * std::cos(a);
        r.end[1] = r.start.point[1];
        r.end[2] = r.start.point[2] + l * std::sin(a);
        rays.push_back(r);
    }
    static const dtQueryFilter filter;
    const dtPolyRef base = detour.ref(0);
    std::vector<nl_navmesh_ray> batch(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        std::copy(rays[i].start.point, rays[i].start.point + 3, batch[i].start);
        batch[i].start_polygon = rays[i].start.polygon;
        std::copy(rays[i].end, rays[i].end + 3, batch[i].end);
    }
    std::vector<nl_navmesh_raycast_hit> hits(rays.size(), nl_navmesh_raycast_hit_init());
    std::vector<uint32_t> crossed(rays.size() * 64);
    std::vector<float> detour_t(rays.size());
    std::vector<dtPolyRef> path(kMaxPolys);
    // The whole batch in one call (the world has one worker) against Detour's raycast ray by ray, and
    // one call per ray (what a host pays asking one at a time); fastest of kRounds each, alternately.
    double nl_batch = 1e300, nl_single = 1e300, detour_ms = 1e300, detour_height_ms = 1e300;
    for (int round = 0; round < kRounds; ++round) {
        const double t0 = nl::samples::now_ms();
        for (size_t i = 0; i < rays.size(); ++i) {
            float normal[3];
            int path_count = 0;
            detour.query->raycast(base | rays[i].start.polygon, rays[i].start.point, rays[i].end, &filter, &detour_t[i],
                                  normal, path.data(), &path_count, kMaxPolys);
        }
        const double t_height = nl::samples::now_ms();
        // Detour's raycast gives no height: the same answer as NavLink's (the point on the surface)
        // takes getPolyHeight on the last polygon as well.
        for (size_t i = 0; i < rays.size(); ++i) {
            float normal[3], point[3], height = 0.0f;
            int path_count = 0;
            detour.query->raycast(base | rays[i].start.polygon, rays[i].start.point, rays[i].end, &filter, &detour_t[i],
                                  normal, path.data(), &path_count, kMaxPolys);
            const float t = detour_t[i] == FLT_MAX ? 1.0f : detour_t[i];
            dtVlerp(point, rays[i].start.point, rays[i].end, t);
            if (path_count > 0) detour.query->getPolyHeight(path[path_count - 1], point, &height);
        }
        const double t1 = nl::samples::now_ms();
        nl_navmesh_raycast(world, navmesh, nullptr, batch.data(), uint32_t(batch.size()), hits.data(), crossed.data(),
                           64);
        const double t2 = nl::samples::now_ms();
        for (size_t i = 0; i < rays.size(); ++i)
            nl_navmesh_raycast(world, navmesh, nullptr, &batch[i], 1, &hits[i], &crossed[64 * i], 64);
        const double t3 = nl::samples::now_ms();
        detour_ms = std::min(detour_ms, t_height - t0);
        detour_height_ms = std::min(detour_height_ms, t1 - t_height);
        nl_batch = std::min(nl_batch, t2 - t1);
        nl_single = std::min(nl_single, t3 - t2);
    }
    int agree = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const bool detour_arrived = detour_t[i] == FLT_MAX;
        const float dx = rays[i].end[0] - rays[i].start.point[0], dz = rays[i].end[2] - rays[i].start.point[2];
        const float ray_length = std::sqrt(dx * dx + dz * dz);
        if (detour_arrived ? !hits[i].hit : hits[i].hit && std::fabs(detour_t[i] - hits[i].t) * ray_length < 0.01f)
            ++agree;
    }
    const double per = 1000.0 / double(rays.size());
    std::printf(
        "raycast level=%s rays=%zu nl_batch_us=%.3f nl_single_us=%.3f detour_us=%.3f detour_with_height_us=%.3f "
        "ratio=%.3f height_ratio=%.3f single_height_ratio=%.3f agree=%.4f\n",
        recast.name.c_str(), rays.size(), nl_batch * per, nl_single * per, detour_ms * per, detour_height_ms * per,
        nl_batch / detour_ms, nl_batch / detour_height_ms, nl_single / detour_height_ms,
        double(agree) / double(rays.size()));
    std::fflush(stdout);
}

// A large host navmesh: a square grid of 1 m quads (`side` x `side`), one in nine cells knocked out
// and every 16th row a wall with a door closed, so the navmesh falls into strips; one-way links join
// each strip to the next. What a reachability map costs to build where it matters, and an
// unreachable goal (the first strip from the last) against the search that finds that out.
void large_grid(int side) {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> corners;
    std::mt19937 rng(99);
    for (int r = 0; r < side; ++r) {
        for (int c = 0; c < side; ++c) {
            if (r % 16 == 15 || rng() % 9 == 0) continue;
            const float x0 = float(c), z0 = float(r);
            for (const auto& [x, z] : {std::pair{x0, z0}, {x0, z0 + 1}, {x0 + 1, z0 + 1}, {x0 + 1, z0}}) {
                indices.push_back(uint32_t(vertices.size() / 3));
                vertices.insert(vertices.end(), {x, 0.0f, z});
            }
            corners.push_back(4);
        }
    }
    nl_world_def world_def = nl_default_world_def();
    world_def.worker_count = 1;
    world_def.path_worker_count = 0;
    nl_world* world = nullptr;
    nl_world_create(&world_def, &world);
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = vertices.data();
    def.vertex_count = uint32_t(vertices.size() / 3);
    def.indices = indices.data();
    def.polygon_vertex_counts = corners.data();
    def.polygon_count = uint32_t(corners.size());
    def.agent_type.radius = 0.0f;
    def.weld_tolerance = 0.01f;
    nl_navmesh_id navmesh{};
    if (NL_FAILED(nl_navmesh_add(world, &def, &navmesh))) {
        std::fprintf(stderr, "navlink-bench-queries: the grid: %s\n", nl_get_last_error_message());
        return;
    }
    // One-way links from each strip down to the next, at x = 0.5 (the first column kept clear).
    for (int strip = 0; strip + 1 < side / 16; ++strip) {
        nl_link_def link = nl_default_link_def();
        link.start[0] = side * 0.5f + 0.5f, link.start[2] = float(16 * strip + 14) + 0.5f;
        link.end[0] = side * 0.5f + 0.5f, link.end[2] = float(16 * strip + 16) + 0.5f;
        nl_link_id id;
        nl_link_add(world, navmesh, &link, &id);
    }
    const nl::Handle handle{navmesh.index1, navmesh.revision};
    const auto graph = world->core->navmeshes().path_graph(handle);
    nl::AgentCapabilities jumper;
    jumper.radius = 0.0f;
    jumper.max_jump_distance = 3.0f;
    const nl::ReachabilityClass body = nl::ReachabilityClass::of(*graph, jumper, {});
    double build_ms = 1e300;
    uint32_t islands = 0;
    for (int run = 0; run < 3; ++run) {
        const double t0 = nl::samples::now_ms();
        const nl::ReachabilityMap map(*graph, body);
        build_ms = std::min(build_ms, nl::samples::now_ms() - t0);
        islands = map.island_count();
    }
    // From the middle of the last strip back to the first: out of reach against the one-way links.
    nl_path_request_def request = nl_default_path_request_def();
    request.navmesh = navmesh;
    request.capabilities = nl_default_agent_capabilities();
    request.capabilities.radius = 0.0f;
    request.capabilities.max_jump_distance = 3.0f;
    request.start[0] = side * 0.5f + 0.5f, request.start[2] = float(side - 2) + 0.5f;
    request.goal[0] = side * 0.5f + 0.5f, request.goal[2] = 0.5f;
    nl_query_filter filter = nl_default_query_filter();
    filter.capabilities = request.capabilities;
    nl_nav_point ends[2];
    const float half[3] = {1, 1, 1};
    float points[6];
    std::copy(request.start, request.start + 3, points);
    std::copy(request.goal, request.goal + 3, points + 3);
    nl_navmesh_find_nearest(world, navmesh, points, 2, half, ends);
    double reach_ms = 1e300, search_ms = 1e300;
    uint8_t reachable = 1;
    nl_path_result result = nl_path_result_init();
    for (int run = 0; run < 3; ++run) {
        const double t0 = nl::samples::now_ms();
        nl_navmesh_can_reach(world, navmesh, &filter, &ends[0].polygon, &ends[1].polygon, 1, &reachable);
        const double t1 = nl::samples::now_ms();
        uint32_t count = 0;
        // Accepting a partial path, it searches everything the body reaches; a start moved a little
        // each run keeps nl_path_find from reusing its last plan.
        request.start[0] += 0.01f;
        nl_path_find(world, &request, &result, nullptr, 0, &count);
        const double t2 = nl::samples::now_ms();
        reach_ms = std::min(reach_ms, t1 - t0);
        search_ms = std::min(search_ms, t2 - t1);
    }
    std::printf(
        "reach level=grid%d polys=%u islands=%u map_build_ms=%.2f reachable=%u reach_us=%.3f "
        "path_find_us=%.1f path_find_outcome=%u nodes=%u\n",
        side, def.polygon_count, islands, build_ms, reachable, 1000.0 * reach_ms, 1000.0 * search_ms, result.outcome,
        result.nodes_visited);
    std::fflush(stdout);
    nl_world_destroy(world);
}

bool bench_level(const char* path) {
    nl::bench::RecastLevel recast = nl::bench::build_recast_level_from_obj(path);
    nl_world_def world_def = nl_default_world_def();
    world_def.worker_count = 1;
    world_def.path_worker_count = 0;
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(&world_def, &world))) return false;
    nl_navmesh_id navmesh{};
    uint32_t polygons = 0;
    nl::bench::DetourMesh detour;
    const bool ok =
        nl::bench::add_navlink_navmesh(world, recast, &navmesh, &polygons) && nl::bench::build_detour(recast, detour);
    if (ok) {
        reachability(recast, world, navmesh, polygons, detour);
        raycasts(recast, world, navmesh, detour);
    } else {
        std::fprintf(stderr, "navlink-bench-queries: %s: could not build the navmeshes\n", path);
    }
    nl_world_destroy(world);
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: navlink-bench-queries LEVEL.obj...\n");
        return 2;
    }
    large_grid(400);
    for (int i = 1; i < argc; ++i) {
        try {
            if (!bench_level(argv[i])) return 1;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-queries: %s: %s\n", argv[i], e.what());
            return 1;
        }
    }
    return 0;
}
