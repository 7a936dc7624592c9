#include "agents/route.h"

#include <algorithm>
#include <limits>

#include "links/link_placement.h"
#include "path/link_filter.h"
#include "path/path_planner.h"

namespace nl {
namespace {

// The routes a step searches are short (a ledge, a platform, a ledge): a bound on the cross links one
// search looks at keeps a world with many from costing a step more than it gives.
constexpr size_t kMaxCrossLinks = 256;

struct CrossLink {
    Handle navmesh;  // where it takes off
    const StoredLink* stored;
    float cost;  // taking it
};

// The cost of walking from `from` to `to` on one navmesh (in its space), or infinity when no whole
// path joins them.
float walk_cost(const PathGraph& graph, const Vec3& from, const Vec3& to, const AgentCapabilities& agent,
                PathResult& scratch) {
    PathQuery q;
    q.start = from;
    q.goal = to;
    q.capabilities = agent;
    q.accept_partial = false;
    plan_path_in_carrier_space(graph, q, nullptr, scratch);
    return scratch.outcome == PathOutcome::Complete ? scratch.cost : std::numeric_limits<float>::infinity();
}

}  // namespace

void StepNavMeshes::add(Handle navmesh, std::shared_ptr<const PathGraph> graph) {
    StepNavMesh n;
    n.navmesh = navmesh;
    n.pose = graph ? pose_of(graph->frame()) : CarrierPose{};
    n.graph = std::move(graph);
    navmeshes_.push_back(std::move(n));
}

const StepNavMesh* StepNavMeshes::find(Handle navmesh) const {
    for (const StepNavMesh& n : navmeshes_)
        if (n.navmesh == navmesh) return &n;
    return nullptr;
}

bool StepNavMeshes::holds(Handle navmesh, const Link& link) const {
    if (!link.crosses()) return true;
    const StepNavMesh* from = find(navmesh);
    const StepNavMesh* to = find(link.landing_navmesh);
    return from && to && from->graph && to->graph && cross_link_holds(link, from->pose, to->pose);
}

bool plan_route(const StepNavMeshes& navmeshes, const RouteQuery& query, PathResult& out) {
    std::vector<CrossLink> cross;
    for (const StepNavMesh& n : navmeshes.all()) {
        if (!n.graph) continue;
        for (const StoredLink& s : n.graph->links()) {
            const Link& l = s.link;
            if (!l.crosses() || !l.enabled || !can_take(l, false, query.capabilities)) continue;
            const StepNavMesh* landing = navmeshes.find(l.landing_navmesh);
            if (!landing || !landing->graph || l.end_polygon >= landing->graph->navmesh().polygon_count()) continue;
            if (!query.through_waiting && !navmeshes.holds(n.navmesh, l)) continue;
            // Its length where it was placed: its end is kept in the landing navmesh's space.
            cross.push_back({n.navmesh, &s, (l.placed_end - l.start).norm() * l.cost_modifier});
            if (cross.size() == kMaxCrossLinks) break;
        }
    }
    if (cross.empty()) return false;
    const StepNavMesh* start = navmeshes.find(query.from_navmesh);
    if (!start || !start->graph) return false;

    // Dijkstra over the cross links: reached[k] is the cost of landing at link k's end.
    const float infinity = std::numeric_limits<float>::infinity();
    std::vector<float> reached(cross.size(), infinity);
    std::vector<uint32_t> first(cross.size(), 0);  // the route's first cross link to land at k
    std::vector<uint8_t> done(cross.size(), 0);
    PathResult scratch;
    for (uint32_t k = 0; k < cross.size(); ++k) {
        if (cross[k].navmesh != query.from_navmesh) continue;
        const float walk =
            walk_cost(*start->graph, query.from, cross[k].stored->link.start, query.capabilities, scratch);
        reached[k] = walk + cross[k].cost;
        first[k] = k;
    }
    float best = infinity;
    uint32_t best_first = 0;
    for (;;) {
        uint32_t k = 0;
        float lowest = infinity;
        for (uint32_t i = 0; i < cross.size(); ++i)
            if (!done[i] && reached[i] < lowest) lowest = reached[i], k = i;
        if (lowest >= best) break;  // nothing cheaper can come: every route left costs more
        done[k] = 1;
        const Link& landed = cross[k].stored->link;
        const StepNavMesh* there = navmeshes.find(landed.landing_navmesh);
        if (landed.landing_navmesh == query.to_navmesh) {
            const float total = lowest + walk_cost(*there->graph, landed.end, query.goal, query.capabilities, scratch);
            if (total < best) best = total, best_first = first[k];
        }
        for (uint32_t m = 0; m < cross.size(); ++m) {
            if (done[m] || cross[m].navmesh != landed.landing_navmesh) continue;
            const float cost =
                lowest +
                walk_cost(*there->graph, landed.end, cross[m].stored->link.start, query.capabilities, scratch) +
                cross[m].cost;
            if (cost < reached[m]) reached[m] = cost, first[m] = first[k];
        }
    }
    if (best == infinity) return false;

    // The first leg: the walk to the first cross link's take-off, which the last point names.
    const CrossLink& takeoff = cross[best_first];
    PathQuery q;
    q.start = query.from;
    q.goal = takeoff.stored->link.start;
    q.capabilities = query.capabilities;
    q.accept_partial = false;
    plan_path_in_carrier_space(*start->graph, q, nullptr, out);
    if (out.outcome != PathOutcome::Complete || out.points.empty()) return false;
    PathPoint& last = out.points.back();
    last.segment = static_cast<uint32_t>(takeoff.stored->link.kind);
    last.link = takeoff.stored->id;
    last.apex = takeoff.stored->link.apex;
    last.reversed = false;
    out.links_used = 1;
    return true;
}

}  // namespace nl
