// libFuzzer target: a host navmesh through nl_navmesh_add, decoded from the bytes (navmesh_bytes.h).
// A navmesh that is accepted must locate points as the brute-force search does: near its first
// vertices, with small, medium and huge search boxes; and plan paths between polygons exactly when
// the body's reachability map says one reaches the other (partial paths off).
#include <cstddef>
#include <cstdint>

#include <algorithm>
#include <cstdio>

#include "fuzz_support.h"
#include "host_input.h"
#include "navmesh_bytes.h"
#include "path/path_planner.h"
#include "path/reachability.h"
#include "world.h"

namespace {

void check_point_location(const nl::NavMesh& mesh) {
    const nl::Vec3 boxes[] = {nl::Vec3(0.5f, 1.0f, 0.5f), nl::Vec3(2.0f, 4.0f, 2.0f), nl::Vec3(1e4f, 1e4f, 1e4f)};
    for (uint32_t v = 0; v < mesh.vertex_count() && v < 16; ++v) {
        const nl::Vec3 point = mesh.vertex(v) + nl::Vec3(0.25f, 0.5f, -0.25f);
        // The huge box visits every polygon: once is enough.
        for (size_t b = 0; b < (v == 0 ? 3 : 2); ++b) {
            const nl::NavPoint fast = mesh.find_nearest(point, boxes[b]),
                               slow = mesh.find_nearest_brute_force(point, boxes[b]);
            if (fast.found != slow.found || fast.polygon != slow.polygon || !(fast.point == slow.point))
                __builtin_trap();
        }
    }
}

void check_paths(const nl::PathGraph& graph) {
    const nl::NavMesh& mesh = graph.navmesh();
    nl::PathQuery query;
    query.capabilities.radius = mesh.agent().radius;
    query.accept_partial = false;
    query.search_half_extents = nl::Vec3(0.01f, 0.01f, 0.01f);
    const auto map = graph.reachability(query.capabilities, query.area_costs);
    const uint32_t polygons = std::min<uint32_t>(mesh.polygon_count(), 6);
    for (uint32_t from = 0; from < polygons; ++from) {
        for (uint32_t to = 0; to < polygons; ++to) {
            query.start = mesh.centre(from);
            query.goal = mesh.centre(to);
            const nl::NavPoint start = mesh.find_nearest(query.start, query.search_half_extents);
            const nl::NavPoint goal = mesh.find_nearest(query.goal, query.search_half_extents);
            if (!start.found || !goal.found) continue;
            nl::PathResult result;
            nl::plan_path(graph, query, nullptr, result);
            const bool reaches = map->reaches(start.polygon, goal.polygon);
            if ((result.outcome == nl::PathOutcome::Complete) != reaches) {
                // The input that did it is kept as a crash artifact; this says which pair.
                fprintf(stderr, "fuzz_navmesh_add: from polygon %u to %u: outcome %u, but the map says %s\n",
                        start.polygon, goal.polygon, uint32_t(result.outcome),
                        reaches ? "it reaches" : "it does not reach");
                __builtin_trap();
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    const nl::fuzz::NavmeshBytes input(data, size);
    nl_navmesh_id navmesh{};
    const nl_status status = nl_navmesh_add(world, &input.def, &navmesh);
    nl::fuzz::require_reasoned(status);
    if (NL_FAILED(status)) return 0;
    const auto held_navmesh = world->core->navmeshes().navmesh(nl::capi::to_handle(navmesh));
    const auto held_graph = world->core->navmeshes().path_graph(nl::capi::to_handle(navmesh));
    check_point_location(*held_navmesh);
    check_paths(*held_graph);
    nl_navmesh_remove(world, navmesh);
    return 0;
}
