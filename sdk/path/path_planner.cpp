#include "path/path_planner.h"

#include <algorithm>

#include "navmesh/nearest_point.h"
#include "path/polygon_astar.h"
#include "path/reachability.h"
#include "path/search_costs.h"
#include "path/any_angle_search.h"
#include "path/string_pulling.h"

namespace nl {
namespace {

// Turns a corridor into path points, stretch by stretch: a walk through portals, then a link, then
// the next walk from where the link lands.
class PathAssembler {
public:
    PathAssembler(const PathGraph& graph, const PathQuery& query, const CorridorSearch& corridor, PathResult& result)
        : graph_(graph),
          mesh_(graph.navmesh()),
          query_(query),
          corridor_(corridor),
          result_(result),
          margin_(std::max(0.0f, query.capabilities.radius - mesh_.agent().radius)) {}

    void assemble(const Vec3& start, const Vec3& end) {
        const std::vector<CorridorStep>& steps = corridor_.steps;
        result_.points.reserve(steps.size() + 2);
        Vec3 walk_start = start;
        size_t first = 0;
        for (size_t i = 1; i < steps.size(); ++i) {
            if (!steps[i].by_link()) continue;
            const StoredLink& stored = graph_.link(steps[i].link());
            const Link& link = stored.link;
            const bool reversed = steps[i].reversed();
            walk(first, i - 1, walk_start, reversed ? link.end : link.start);
            PathPoint& takeoff = result_.points.back();
            takeoff.segment = reversed && link.kind == LinkKind::Drop ? uint32_t(LinkKind::Jump) : uint32_t(link.kind);
            takeoff.link = stored.id;
            takeoff.apex = link.apex;
            takeoff.reversed = reversed;
            ++result_.links_used;
            walk_start = reversed ? link.start : link.end;
            const float chord = (walk_start - takeoff.position).norm();
            result_.length += chord;  // a link: its chord
            result_.cost += chord * link.cost_modifier + query_.link_cost;
            first = i;
        }
        walk(first, steps.size() - 1, walk_start, end);
    }

private:
    // Walks from `from` in steps[first] to `to` in steps[last] through the portals between them.
    void walk(size_t first, size_t last, const Vec3& from, const Vec3& to) {
        portals_.clear();
        for (size_t i = first + 1; i <= last; ++i) {
            PortalSpan span;
            portal_span(mesh_, corridor_.steps[i - 1].polygon, corridor_.steps[i].edge(), margin_, span);
            portals_.push_back(span);
        }
        pulled_.clear();
        pull_string(from, to, portals_, pulled_);
        rates_.clear();
        for (size_t i = first; i <= last; ++i)
            rates_.push_back(query_.area_cost(mesh_.area(corridor_.steps[i].polygon)));
        const WalkedLine walked = walk_line(pulled_, portals_, rates_);
        result_.length += walked.length;
        result_.cost += static_cast<float>(walked.cost);
        for (const PulledPoint& pulled : pulled_) {
            const size_t step = first + std::min<size_t>(pulled.portal, last - first);
            const PathPoint point{pulled.position,
                                  pulled.position,
                                  corridor_.steps[step].polygon,
                                  kSegmentWalk,
                                  Handle{},
                                  pulled.position,
                                  false};
            // A link landing where the next one takes off, or a walk of no length, adds no point.
            if (!result_.points.empty() && result_.points.back().position == point.position &&
                result_.points.back().segment == kSegmentWalk) {
                continue;
            }
            result_.points.push_back(point);
        }
    }

    const PathGraph& graph_;
    const NavMesh& mesh_;
    const PathQuery& query_;
    const CorridorSearch& corridor_;
    PathResult& result_;
    const float margin_;
    // Per thread and reused: a request allocates only its result.
    static thread_local std::vector<PortalSpan> portals_;
    static thread_local std::vector<PulledPoint> pulled_;
    static thread_local std::vector<float> rates_;
};

thread_local std::vector<PortalSpan> PathAssembler::portals_;
thread_local std::vector<PulledPoint> PathAssembler::pulled_;
thread_local std::vector<float> PathAssembler::rates_;

}  // namespace

void plan_path(const PathGraph& graph, const PathQuery& query, const std::atomic<bool>* cancel, PathResult& result) {
    const CarrierPose pose = pose_of(graph.frame());
    if (pose.is_identity()) return plan_path_in_carrier_space(graph, query, cancel, result);
    PathQuery local = query;
    local.start = pose.carrier_point(query.start);
    local.goal = pose.carrier_point(query.goal);
    local.search_half_extents = pose.carrier_extents(query.search_half_extents);
    plan_path_in_carrier_space(graph, local, cancel, result);
    for (PathPoint& p : result.points) {
        p.position = pose.world_point(p.carrier_position);
        p.apex = pose.world_point(p.apex);
    }
    result.start = pose.world_point(result.start);
    result.goal = pose.world_point(result.goal);
}

namespace {

// Whether a search went through everything the body reaches from the start without finding its goal.
bool searched_everything(const CorridorSearch& corridor) {
    return !corridor.reached_goal && !corridor.cancelled && !corridor.out_of_nodes && !corridor.gave_up;
}

// The corridor from start to target: the exact search when walking costs the body the same everywhere
// it may go; the corridor search for areas of different costs, for a way the exact search misses,
// and for the best it can do when max_nodes runs out.
void search_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start, const NavPoint& target,
                     float walk_cost, const std::atomic<bool>* cancel, CorridorSearch& corridor) {
    if (walk_cost <= 0.0f) return find_corridor(graph, query, start, target, cancel, corridor);
    find_shortest_corridor(graph, query, start, target, walk_cost, cancel, corridor);
    // It went through everything the body reaches: the map costs about as much again, and answers
    // the next requests for goals out of reach on this graph at once. It also says whether the exact
    // search missed a way there: on a navmesh folded over itself (a neighbour on the same side of the
    // edge they share, seen from above) its views mean nothing, and the corridor search finds the way.
    const bool missed =
        searched_everything(corridor) &&
        graph.reachability(query.capabilities, query.area_costs)->reaches(start.polygon, target.polygon);
    const bool ran_out = corridor.out_of_nodes && !corridor.reached_goal && query.accept_partial;
    if (missed || corridor.gave_up || ran_out) {
        const uint32_t exact_nodes = corridor.nodes_visited;
        find_corridor(graph, query, start, target, cancel, corridor);
        corridor.nodes_visited = std::max(corridor.nodes_visited, exact_nodes);  // both count polygons
    }
}

// Where a partial path ends: the navmesh point nearest the goal among the polygons the body reaches
// from the start (the start's own polygon at least), as located points are ranked (NearestPoint).
// A pass over the reachable polygons' bounds: a fraction of what a search through them costs.
NavPoint nearest_reachable(const NavMesh& navmesh, const ReachabilityMap& map, const NavPoint& start,
                           const NavPoint& goal) {
    thread_local std::vector<uint8_t> reached;
    map.reachable_islands(start.polygon, reached);
    NearestPoint nearest(navmesh, goal.point);
    nearest.consider(start.polygon);
    for (uint32_t island = 0; island < map.island_count(); ++island) {
        if (!reached[island]) continue;
        for (const uint32_t* p = map.island_begin(island); p != map.island_end(island); ++p) nearest.consider(*p);
    }
    return nearest.best();
}

}  // namespace

void plan_path_in_carrier_space(const PathGraph& graph, const PathQuery& query, const std::atomic<bool>* cancel,
                                PathResult& result) {
    const NavMesh& navmesh = graph.navmesh();
    std::vector<PathPoint> points = std::move(result.points);
    points.clear();
    result = PathResult{};
    result.points = std::move(points);
    const NavPoint start = navmesh.find_nearest(query.start, query.search_half_extents);
    if (!start.found) {
        result.outcome = PathOutcome::StartOffNavMesh;
        return;
    }
    const NavPoint goal = navmesh.find_nearest(query.goal, query.search_half_extents);
    result.start = start.point;
    if (!goal.found) {
        result.outcome = PathOutcome::GoalOffNavMesh;
        return;
    }
    result.goal = goal.point;
    // A goal out of reach is known at once when the body's reachability map is built: no path, or a
    // path to the nearest point the body reaches. A request never builds one before searching: it
    // would cost a pass over the whole navmesh (uncancellable, past max_nodes) for a goal two steps
    // away.
    NavPoint target = goal;
    bool heading_to_nearest = false;  // the goal is out of reach: for the nearest point the body reaches
    if (start.polygon != goal.polygon) {
        const ReachabilityMap* map = graph.reachability_if_built(query.capabilities, query.area_costs);
        if (map && !map->reaches(start.polygon, goal.polygon)) {
            if (!query.accept_partial) {
                result.outcome = PathOutcome::NoPath;
                return;
            }
            target = nearest_reachable(navmesh, *map, start, goal);
            heading_to_nearest = true;
        }
    }

    thread_local CorridorSearch corridor;
    const float walk_cost = uniform_walk_cost(graph, query);
    search_corridor(graph, query, start, target, walk_cost, cancel, corridor);
    if (!heading_to_nearest && searched_everything(corridor)) {
        // Out of reach: the map (built once per graph and body) says so at once from now on, and
        // where the body can go instead.
        const auto map = graph.reachability(query.capabilities, query.area_costs);
        if (query.accept_partial) {
            target = nearest_reachable(navmesh, *map, start, goal);
            heading_to_nearest = true;
            const uint32_t first_nodes = corridor.nodes_visited;
            search_corridor(graph, query, start, target, walk_cost, cancel, corridor);
            corridor.nodes_visited += first_nodes;
        }
    }
    result.nodes_visited = corridor.nodes_visited;
    result.out_of_nodes = corridor.out_of_nodes;
    if (corridor.cancelled) {
        result.outcome = PathOutcome::Cancelled;
        return;
    }
    if (!corridor.reached_goal && !query.accept_partial) {
        result.outcome = PathOutcome::NoPath;
        return;
    }
    Vec3 end = target.point;
    // max_nodes ran out: toward the polygon the search got nearest to the goal, as Detour's.
    if (!corridor.reached_goal) end = navmesh.closest_point_on_polygon(corridor.steps.back().polygon, goal.point);
    PathAssembler(graph, query, corridor, result).assemble(start.point, end);
    result.outcome = corridor.reached_goal && !heading_to_nearest ? PathOutcome::Complete : PathOutcome::Partial;

    // Areas of different costs: the corridor search's path has no bound, so the shortest walk (the
    // exact search at the cheapest rate) stands against it, and the cheaper goes. Either costs at
    // most the dearest rate over the cheapest times the cheapest route's cost, as the shortest walk
    // does: walked at the cheapest rate it costs no more than any route.
    if (walk_cost > 0.0f || !corridor.reached_goal) return;
    thread_local CorridorSearch shortest;
    find_shortest_corridor(graph, query, start, target, cheapest_walk_cost(graph, query), cancel, shortest);
    result.nodes_visited += shortest.nodes_visited;
    if (shortest.cancelled) {
        result.outcome = PathOutcome::Cancelled;
        result.points.clear();
        return;
    }
    if (!shortest.reached_goal) return;  // missed where the navmesh folds over itself: no bound there
    thread_local PathResult walked;
    walked.points.clear();
    walked.length = walked.cost = 0.0f;
    walked.links_used = 0;
    PathAssembler(graph, query, shortest, walked).assemble(start.point, end);
    if (walked.cost >= result.cost) return;
    std::swap(result.points, walked.points);
    result.length = walked.length;
    result.cost = walked.cost;
    result.links_used = walked.links_used;
}

}  // namespace nl
