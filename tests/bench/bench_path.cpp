// navlink-bench-path LEVEL.obj...: NavLink's path search against Detour's on the same polygon mesh.
// For each level, the Recast builder's pipeline (the one nl_navmesh_build runs) makes one polygon
// mesh and detail mesh; NavLink gets it as a navmesh through nl_navmesh_add, Detour through
// dtCreateNavMeshData. The same 10,000 random start/goal pairs are then planned by both, alternately:
// Detour findNearestPoly x 2 + findPath + findStraightPath, NavLink nl_path_find (which snaps both ends,
// searches and string-pulls), each pair three times, its fastest time counting. One line per level:
//   level=NAME polys=N queries=N nl_us=X detour_us=X ratio=X complete=N complete_ratio=X rest_ratio=X
//     nl_len=X detour_len=X nl_walked=X nl_bytes=N
//     detour_bytes=N ... exact_pairs=N within_0.1%=X worst_excess=X% links=N linked_pairs=N
//     linked_within_0.1%=X linked_worst_excess=X% linked_missed=N
// (complete: the pairs NavLink completes; complete_ratio and rest_ratio split the time ratio between
// them and the others, whose partial paths both sides plan differently: Detour searches through all
// it reaches, NavLink asks the body's reachability map and walks to the nearest point it reaches;
// missed: paths the exact search alone does not find, which the corridor search plans instead)
// (lengths: means over the pairs both complete, nl_len and detour_len straight between corners,
// nl_walked NavLink's reported length, walked along the surface; bytes: NavLink's navmesh, link index and
// search index vs Detour's navmesh data; exactness: the first 500 complete paths' x-z lengths against the exact shortest walk
// between the same ends, tests/support/shortest_path_reference.h; then the same with the level's
// generated links for a body that takes them, costs against the cheapest route), then one line with the queue's throughput on 1 and 2 path workers on the largest level.
#include <DetourCommon.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>
#include <DetourNode.h>
#include <navlink/navlink.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "clock.h"
#include "recast_detour.h"
#include "path/any_angle_search.h"
#include "shortest_path_reference.h"
#include "world.h"

namespace {

constexpr int kPairs = 10000;
constexpr int kRounds = 3;
constexpr int kExactPairs = 500;
constexpr int kMaxPolys = 1024;
constexpr float kHalfExtents[3] = {2.0f, 4.0f, 2.0f};

struct Pair {
    float start[3];
    float goal[3];
};

// The same random points as ever: start, goal, start, goal... from one generator.
std::vector<Pair> draw_pairs(const rcPolyMesh& pm) {
    std::mt19937 rng(12345);
    std::vector<Pair> pairs(kPairs);
    for (Pair& p : pairs) nl::bench::random_point(pm, rng, p.start), nl::bench::random_point(pm, rng, p.goal);
    return pairs;
}

float polyline_length(const float* xyz, int count) {
    float length = 0.0f;
    for (int i = 1; i < count; ++i) {
        const float* a = xyz + 3 * (i - 1);
        const float* b = xyz + 3 * i;
        length +=
            std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    }
    return length;
}

struct DetourAnswer {
    bool complete = false;
    float length = 0.0f;
    int nodes = 0;  // search nodes Detour touched
};

// findPath + findStraightPath between located ends, as Detour's samples do (a partial corridor
// ends at the point of its last polygon nearest to the goal).
DetourAnswer detour_search(const nl::bench::DetourMesh& d, dtPolyRef start_ref, const float* start, dtPolyRef goal_ref,
                           const float* goal) {
    static const dtQueryFilter filter;
    dtPolyRef polys[kMaxPolys];
    float straight[3 * kMaxPolys];
    DetourAnswer answer;
    int count = 0;
    const dtStatus status = d.query->findPath(start_ref, goal_ref, start, goal, &filter, polys, &count, kMaxPolys);
    answer.nodes = d.query->getNodePool()->getNodeCount();
    if (dtStatusFailed(status) || count == 0) return answer;
    float end[3];
    dtVcopy(end, goal);
    if (polys[count - 1] != goal_ref) d.query->closestPointOnPoly(polys[count - 1], goal, end, nullptr);
    int points = 0;
    d.query->findStraightPath(start, end, polys, count, straight, nullptr, nullptr, &points, kMaxPolys);
    answer.complete = polys[count - 1] == goal_ref && !(status & DT_PARTIAL_RESULT);
    answer.length = polyline_length(straight, points);
    return answer;
}

// The whole job from raw points: locate both ends, then search.
DetourAnswer detour_path(const nl::bench::DetourMesh& d, const Pair& pair) {
    static const dtQueryFilter filter;
    dtPolyRef start_ref = 0, goal_ref = 0;
    float start[3], goal[3];
    d.query->findNearestPoly(pair.start, kHalfExtents, &filter, &start_ref, start);
    d.query->findNearestPoly(pair.goal, kHalfExtents, &filter, &goal_ref, goal);
    if (!start_ref || !goal_ref) return DetourAnswer{};
    return detour_search(d, start_ref, start, goal_ref, goal);
}

struct Level {
    std::string name;
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    uint32_t polygons = 0;
    std::vector<Pair> pairs;
};

nl_path_request_def request_for(const Level& level, const Pair& pair) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = level.navmesh;
    std::copy(pair.start, pair.start + 3, def.start);
    std::copy(pair.goal, pair.goal + 3, def.goal);
    std::copy(kHalfExtents, kHalfExtents + 3, def.search_half_extents);
    return def;  // a walker of the navmesh's own radius
}

// A body that takes the default generated links.
nl_path_request_def jumper_request_for(const Level& level, const Pair& pair) {
    nl_path_request_def def = request_for(level, pair);
    def.capabilities.max_jump_distance = 4.0f;
    def.capabilities.max_jump_height = 2.0f;
    def.capabilities.max_drop_height = 6.0f;
    return def;
}

struct Exactness {
    int pairs = 0, within = 0, missed = 0;  // missed: complete only through the corridor search
    double worst_excess = 0.0;
};

// Exactness (issue 20): the first kExactPairs complete paths' costs against the exact cheapest route
// between the same snapped ends (tests/support/shortest_path_reference.h). Without links and at the
// default costs, a path's cost is its length seen from above, what the funnel minimises.
template <typename Request>
Exactness exactness(const Level& level, Request request, std::vector<nl_path_point>& points) {
    const auto graph =
        level.world->core->navmeshes().path_graph(nl::Handle{level.navmesh.index1, level.navmesh.revision});
    nl::PathQuery body;
    const nl_path_request_def sample = request(level, level.pairs[0]);
    body.capabilities = nl::AgentCapabilities{sample.capabilities.max_jump_distance,
                                              sample.capabilities.max_jump_height, sample.capabilities.max_drop_height,
                                              sample.capabilities.radius, sample.capabilities.abilities};
    body.link_cost = sample.link_cost;
    const nl::test::ShortestPathReference reference(*graph, body);
    Exactness out;
    for (int i = 0; i < kPairs && out.pairs < kExactPairs; ++i) {
        const nl_path_request_def def = request(level, level.pairs[i]);
        nl_path_result result = nl_path_result_init();
        uint32_t count = 0;
        nl_path_find(level.world, &def, &result, points.data(), uint32_t(points.size()), &count);
        if (result.outcome != NL_PATH_COMPLETE || count == 0) continue;
        // The exact search alone: a way it misses is planned by the corridor search instead.
        nl::PathQuery alone = body;
        alone.start = nl::Vec3(def.start[0], def.start[1], def.start[2]);
        alone.goal = nl::Vec3(def.goal[0], def.goal[1], def.goal[2]);
        const nl::Vec3 box(def.search_half_extents[0], def.search_half_extents[1], def.search_half_extents[2]);
        nl::CorridorSearch exact;
        nl::find_shortest_corridor(*graph, alone, graph->navmesh().find_nearest(alone.start, box),
                                   graph->navmesh().find_nearest(alone.goal, box), 1.0f, nullptr, exact);
        if (!exact.reached_goal) {
            ++out.missed;
            continue;
        }
        const std::optional<double> cheapest =
            reference.length(nl::Vec3(result.start[0], result.start[1], result.start[2]),
                             nl::Vec3(result.goal[0], result.goal[1], result.goal[2]));
        if (!cheapest) continue;  // the reference finds no route (the search went where it sees none)
        ++out.pairs;
        // Without links, the length of the points themselves seen from above: measured here, apart
        // from the planner's own cost.
        double cost = result.cost;
        if (result.links_used == 0) {
            cost = 0.0;
            for (uint32_t k = 1; k < count; ++k)
                cost += std::hypot(double(points[k].position[0]) - points[k - 1].position[0],
                                   double(points[k].position[2]) - points[k - 1].position[2]);
        }
        const double excess = cost / std::max(*cheapest, 1e-9) - 1.0;
        out.worst_excess = std::max(out.worst_excess, excess);
        out.within += excess <= 1e-3 ? 1 : 0;
    }
    return out;
}

bool compare(const char* path, Level& level) {
    nl::bench::RecastLevel recast = nl::bench::build_recast_level_from_obj(path);
    level.name = recast.name;

    nl_world_def world_def = nl_default_world_def();
    world_def.worker_count = 1;
    world_def.path_worker_count = 0;
    if (NL_FAILED(nl_world_create(&world_def, &level.world))) return false;
    if (!nl::bench::add_navlink_navmesh(level.world, recast, &level.navmesh, &level.polygons)) return false;

    nl::bench::DetourMesh detour;
    if (!nl::bench::build_detour(recast, detour)) {
        std::fprintf(stderr, "navlink-bench-path: %s: Detour could not build its navmesh\n", path);
        return false;
    }
    level.pairs = draw_pairs(*recast.solo.polygons);
    const dtPolyRef base = detour.ref(0);

    // Each pair is timed kRounds times on each side, alternately, and its fastest time counts: a
    // shared machine's interruptions land on one side or the other at random; the minimum is the cost.
    std::vector<double> nl_best(kPairs, 1e300), detour_best(kPairs, 1e300);
    double nl_length = 0.0, nl_walked = 0.0, detour_length = 0.0, nl_nodes = 0.0, detour_nodes = 0.0;
    int both_complete = 0;
    std::vector<char> nl_complete(kPairs, 0);
    std::vector<nl_path_point> points(4096, nl_path_point_init());
    for (int round = 0; round < kRounds; ++round) {
        for (int i = 0; i < kPairs; ++i) {
            const Pair& pair = level.pairs[i];
            const double t0 = nl::samples::now_ms();
            const DetourAnswer timed = detour_path(detour, pair);
            const double t1 = nl::samples::now_ms();
            const nl_path_request_def def = request_for(level, pair);
            nl_path_result result{};
            result.size = sizeof result;
            uint32_t count = 0;
            nl_path_find(level.world, &def, &result, points.data(), uint32_t(points.size()), &count);
            const double t2 = nl::samples::now_ms();
            detour_best[i] = std::min(detour_best[i], t1 - t0);
            nl_best[i] = std::min(nl_best[i], t2 - t1);
            if (round + 1 < kRounds) continue;
            nl_nodes += result.nodes_visited;
            detour_nodes += timed.nodes;
            if (result.outcome != NL_PATH_COMPLETE || count == 0) continue;
            nl_complete[i] = 1;
            // Lengths compare the searches and string pulling alone: Detour plans again, untimed,
            // between the very ends and polygons NavLink located (both locate alike, but points on
            // a polygon border may go to either neighbour).
            const DetourAnswer same_ends = detour_search(detour, base | points[0].polygon, result.start,
                                                         base | points[count - 1].polygon, result.goal);
            if (same_ends.complete) {
                ++both_complete;
                std::vector<float> corners(3 * count);
                for (uint32_t k = 0; k < count; ++k)
                    std::copy(points[k].position, points[k].position + 3, &corners[3 * k]);
                nl_length += polyline_length(corners.data(), int(count));  // as Detour's: straight between corners
                nl_walked += result.length;
                detour_length += same_ends.length;
            }
        }
    }
    double nl_ms = 0.0, detour_ms = 0.0, nl_complete_ms = 0.0, detour_complete_ms = 0.0;
    int complete = 0;
    for (int i = 0; i < kPairs; ++i) {
        nl_ms += nl_best[i], detour_ms += detour_best[i];
        if (!nl_complete[i]) continue;
        ++complete, nl_complete_ms += nl_best[i], detour_complete_ms += detour_best[i];
    }

    const Exactness walking = exactness(level, request_for, points);
    const nl::Handle handle{level.navmesh.index1, level.navmesh.revision};
    const auto graph = level.world->core->navmeshes().path_graph(handle);
    const size_t nl_bytes = graph->navmesh().memory_bytes() + graph->link_index_bytes() + graph->search_index_bytes();
    std::printf(
        "level=%s polys=%u queries=%d nl_us=%.2f detour_us=%.2f ratio=%.2f complete=%d complete_ratio=%.2f "
        "rest_ratio=%.2f nl_len=%.4f detour_len=%.4f nl_walked=%.4f nl_bytes=%zu "
        "detour_bytes=%d both_complete=%d nl_nodes=%.1f detour_nodes=%.1f exact_pairs=%d within_0.1%%=%.4f "
        "worst_excess=%.4f%% exact_missed=%d",
        level.name.c_str(), level.polygons, kPairs, 1000.0 * nl_ms / kPairs, 1000.0 * detour_ms / kPairs,
        nl_ms / detour_ms, complete, nl_complete_ms / std::max(1e-12, detour_complete_ms),
        (nl_ms - nl_complete_ms) / std::max(1e-12, detour_ms - detour_complete_ms),
        nl_length / std::max(1, both_complete), detour_length / std::max(1, both_complete),
        nl_walked / std::max(1, both_complete), nl_bytes, detour.bytes, both_complete, nl_nodes / kPairs,
        detour_nodes / kPairs, walking.pairs, double(walking.within) / std::max(1, walking.pairs),
        100.0 * walking.worst_excess, walking.missed);
    std::fflush(stdout);

    // With the level's generated links, for a body that takes them: costs (walking seen from above
    // plus each link's length times its cost modifier) against the reference's cheapest route.
    nl_mesh_id mesh{};
    uint32_t links = 0;
    if (NL_SUCCEEDED(nl_mesh_add_obj_file(level.world, path, nullptr, &mesh)) &&
        NL_SUCCEEDED(nl_navmesh_generate_links(level.world, level.navmesh, nullptr, nullptr, nullptr, nullptr))) {
        nl_navmesh_get_links(level.world, level.navmesh, nullptr, 0, &links);
        const Exactness linked = exactness(level, jumper_request_for, points);
        std::printf(" links=%u linked_pairs=%d linked_within_0.1%%=%.4f linked_worst_excess=%.4f%% linked_missed=%d",
                    links, linked.pairs, double(linked.within) / std::max(1, linked.pairs), 100.0 * linked.worst_excess,
                    linked.missed);
    }
    std::printf("\n");
    std::fflush(stdout);
    return true;
}

// Requests per second through nl_path_request on a world with `workers` path workers: all pairs
// queued from this thread, timed until the last callback.
double queue_throughput(const Level& level, int workers) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    def.path_worker_count = workers;
    nl_world* world = nullptr;
    nl_world_create(&def, &world);
    // The same navmesh, copied through the C ABI into the new world.
    nl_navmesh_info info{};
    info.size = sizeof info;
    nl_navmesh_get_info(level.world, level.navmesh, &info);
    std::vector<float> vertices(3 * size_t(info.vertex_count));
    uint32_t count = 0;
    nl_navmesh_get_vertices(level.world, level.navmesh, vertices.data(), info.vertex_count, &count);
    std::vector<uint32_t> indices;
    std::vector<uint8_t> corners, areas;
    for (uint32_t p = 0; p < info.polygon_count; ++p) {
        nl_nav_polygon polygon = nl_nav_polygon_init();
        nl_navmesh_get_polygon(level.world, level.navmesh, p, &polygon);
        indices.insert(indices.end(), polygon.vertices, polygon.vertices + polygon.vertex_count);
        corners.push_back(uint8_t(polygon.vertex_count));
        areas.push_back(uint8_t(polygon.area));
    }
    nl_navmesh_def navmesh_def = nl_default_navmesh_def();
    navmesh_def.vertices = vertices.data();
    navmesh_def.vertex_count = info.vertex_count;
    navmesh_def.indices = indices.data();
    navmesh_def.polygon_vertex_counts = corners.data();
    navmesh_def.polygon_count = info.polygon_count;
    navmesh_def.areas = areas.data();
    navmesh_def.agent_type = info.agent_type;
    nl_navmesh_id navmesh{};
    nl_navmesh_add(world, &navmesh_def, &navmesh);

    static std::atomic<int> finished;
    const int requests = 4 * kPairs;
    double best = 0.0;
    for (int run = 0; run < 3; ++run) {
        finished = 0;
        std::vector<nl_path_ticket> tickets(requests);
        const double t0 = nl::samples::now_ms();
        for (int i = 0; i < requests; ++i) {
            nl_path_request_def r = request_for(level, level.pairs[i % kPairs]);
            r.navmesh = navmesh;
            r.callback = [](void*, nl_path_ticket, nl_path_outcome) {
                finished.fetch_add(1, std::memory_order_release);
            };
            nl_path_request(world, &r, &tickets[i]);
        }
        while (finished.load(std::memory_order_acquire) < requests) std::this_thread::yield();
        const double seconds = (nl::samples::now_ms() - t0) / 1000.0;
        best = std::max(best, requests / seconds);
        for (nl_path_ticket t : tickets) nl_path_release(world, t);
    }
    nl_world_destroy(world);
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: navlink-bench-path LEVEL.obj...\n");
        return 2;
    }
    // --no-queue skips the throughput line (for profiling the comparison alone).
    const bool queue = std::string(argv[1]) != "--no-queue";
    const int first = queue ? 1 : 2;
    std::vector<Level> levels(argc - first);
    for (int i = first; i < argc; ++i) {
        try {
            if (!compare(argv[i], levels[i - first])) return 1;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-path: %s: %s\n", argv[i], e.what());
            return 1;
        }
    }
    if (!queue || levels.empty()) return 0;
    const Level& largest = *std::max_element(levels.begin(), levels.end(),
                                             [](const Level& a, const Level& b) { return a.polygons < b.polygons; });
    const double one = queue_throughput(largest, 1), two = queue_throughput(largest, 2);
    std::printf("queue level=%s requests=%d workers1_per_s=%.0f workers2_per_s=%.0f speedup=%.2f\n",
                largest.name.c_str(), 4 * kPairs, one, two, two / one);
    for (Level& level : levels) nl_world_destroy(level.world);
    return 0;
}
