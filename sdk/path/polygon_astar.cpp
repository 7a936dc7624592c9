#include "path/polygon_astar.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "path/link_filter.h"
#include "path/portal.h"
#include "path/search_costs.h"
#include "os/compiler.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr uint32_t kNone = 0xffffffffu;
constexpr uint32_t kStraightenDepth = 1;

struct SearchNode {
    Vec3 position;          // where the corridor enters the polygon
    PortalSpan entry_span;  // the portal it enters by (unset for the start and links)
    float g;                // cost from the start to `position` (to the goal point for the goal polygon)
    float f;                // g + heuristic
    uint32_t parent;
    uint32_t entry;
    uint32_t epoch;  // the search that last touched the node; older means untouched
    uint32_t heap;   // index in the open list, or kNone
};

// Per thread, reused by every search on it: polygons index the nodes directly (no hashing, unlike
// Detour's node pool), and an epoch stamp stands for clearing them.
struct SearchScratch {
    std::vector<SearchNode> nodes;
    std::vector<uint32_t> open;  // binary min-heap of polygons by f
    uint32_t epoch = 0;

    uint32_t begin(uint32_t polygons) {
        if (nodes.size() < polygons)
            nodes.resize(polygons,
                         SearchNode{Vec3::Zero(), {Vec3::Zero(), Vec3::Zero()}, 0, 0, kNone, kNone, 0, kNone});
        open.clear();
        if (++epoch == 0) {  // wrapped: old stamps could look current
            for (SearchNode& n : nodes) n.epoch = 0;
            epoch = 1;
        }
        return epoch;
    }
};

SearchScratch& thread_scratch() {
    thread_local SearchScratch scratch;
    return scratch;
}

class OpenList {
public:
    OpenList(std::vector<uint32_t>& heap, SearchNode* nodes) : heap_(heap), nodes_(nodes) {}

    bool empty() const { return heap_.empty(); }

    void push(uint32_t p) {
        heap_.push_back(p);
        sift_up(static_cast<uint32_t>(heap_.size() - 1));
    }

    // After p's f changed (a lower cost through an entry point farther from the goal can raise it).
    void changed(uint32_t p) {
        sift_up(nodes_[p].heap);
        sift_down(nodes_[p].heap);
    }

    uint32_t pop() {
        const uint32_t top = heap_[0];
        nodes_[top].heap = kNone;
        const uint32_t last = heap_.back();
        heap_.pop_back();
        if (!heap_.empty()) {
            heap_[0] = last;
            nodes_[last].heap = 0;
            sift_down(0);
        }
        return top;
    }

private:
    void place(uint32_t i, uint32_t p) {
        heap_[i] = p;
        nodes_[p].heap = i;
    }
    void sift_up(uint32_t i) {
        const uint32_t p = heap_[i];
        const float f = nodes_[p].f;
        while (i > 0) {
            const uint32_t parent = (i - 1) / 2;
            if (nodes_[heap_[parent]].f <= f) break;
            place(i, heap_[parent]);
            i = parent;
        }
        place(i, p);
    }
    void sift_down(uint32_t i) {
        const uint32_t p = heap_[i];
        const float f = nodes_[p].f;
        const uint32_t size = static_cast<uint32_t>(heap_.size());
        for (;;) {
            uint32_t child = 2 * i + 1;
            if (child >= size) break;
            if (child + 1 < size && nodes_[heap_[child + 1]].f < nodes_[heap_[child]].f) ++child;
            if (nodes_[heap_[child]].f >= f) break;
            place(i, heap_[child]);
            i = child;
        }
        place(i, p);
    }

    std::vector<uint32_t>& heap_;
    SearchNode* nodes_;
};

// Where the corridor crosses a portal: the portal's point nearest to the straight line from `from`
// to the goal (in 3D: on stairs and ramps the line seen from above points nowhere useful), kept a
// tenth of the portal away from its ends. Estimates the string-pulled length of a corridor better
// than Detour's edge midpoints, so the search ranks corridors closer to how long they really are.
constexpr float kPortalEndMargin = 0.1f;

// The line from `from` to the goal, with what every portal of one expansion shares.
struct LineToGoal {
    Vec3 from;
    Vec3 direction;  // goal - from
    float length2;   // direction . direction

    LineToGoal(const Vec3& from_point, const Vec3& goal)
        : from(from_point), direction(goal - from_point), length2(direction.dot(direction)) {}
};

Vec3 crossing_point(const PortalSpan& span, const LineToGoal& line) {
    const Vec3 e = span.right - span.left, w = span.left - line.from;
    const float ee = e.dot(e), ed = e.dot(line.direction), ew = e.dot(w), dw = line.direction.dot(w);
    const float denominator = ee * line.length2 - ed * ed;
    const float t = denominator > 1e-12f ? (ed * dw - line.length2 * ew) / denominator : 0.5f;  // parallel: the middle
    return span.left + std::clamp(t, kPortalEndMargin, 1.0f - kPortalEndMargin) * e;
}

// True if the segment a -> b (seen from above) passes through the span. Compares the intersection's
// parameters as fractions without dividing.
bool crosses(const Vec3& a, const Vec3& b, const PortalSpan& span) {
    const float dx = b.x() - a.x(), dz = b.z() - a.z();
    const float ex = span.right.x() - span.left.x(), ez = span.right.z() - span.left.z();
    float denominator = ex * dz - ez * dx;
    const float wx = a.x() - span.left.x(), wz = a.z() - span.left.z();
    float along_span = wx * dz - wz * dx, along_segment = wx * ez - wz * ex;
    if (denominator < 0.0f) denominator = -denominator, along_span = -along_span, along_segment = -along_segment;
    return denominator > 1e-12f && along_span >= 0.0f && along_span <= denominator && along_segment >= 0.0f &&
           along_segment <= denominator;
}

}  // namespace

void find_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start, const NavPoint& goal,
                   const std::atomic<bool>* cancel, CorridorSearch& result) {
    const NavMesh& navmesh = graph.navmesh();
    SearchScratch& scratch = thread_scratch();
    const uint32_t epoch = scratch.begin(navmesh.polygon_count());
    SearchNode* nodes = scratch.nodes.data();
    OpenList open(scratch.open, nodes);
    const float margin = std::max(0.0f, query.capabilities.radius - navmesh.agent().radius);
    const float h_scale = heuristic_scale(graph, query);
    const Vec3 goal_point = goal.point;

    result.steps.clear();
    result.reached_goal = result.out_of_nodes = result.cancelled = result.gave_up = false;
    result.nodes_visited = 0;
    result.search_nodes = 0;

    float nearest_entry = std::numeric_limits<float>::infinity();  // bounds a partial path's end
    uint32_t nearest_entry_polygon = start.polygon;
    auto relax = [&](uint32_t q, uint32_t parent, uint32_t entry, const Vec3& position, float g, const PortalSpan* span)
                     NL_ALWAYS_INLINE {
                         SearchNode& n = nodes[q];
                         if (n.epoch != epoch) {
                             if (query.max_nodes != 0 && result.nodes_visited >= query.max_nodes) {
                                 result.out_of_nodes = true;
                                 return;
                             }
                             ++result.nodes_visited;
                             n.epoch = epoch;
                             n.heap = kNone;
                         } else if (g >= n.g) {
                             return;
                         }
                         n.position = position;
                         if (span) n.entry_span = *span;
                         n.g = g;
                         n.parent = parent;
                         n.entry = entry;
                         const float distance = (goal_point - position).norm();
                         n.f = q == goal.polygon ? g : g + distance * h_scale;
                         if (distance < nearest_entry) nearest_entry = distance, nearest_entry_polygon = q;
                         if (n.heap == kNone) {
                             open.push(q);
                         } else {
                             open.changed(q);
                         }
                     };

    // Theta*-style: the cost to `crossing` straight from an earlier node, when the straight line
    // stays inside the corridor (passes through every portal between), up to kStraightenDepth
    // portals back. A corridor's cost then follows its string-pulled length instead of zigzagging
    // from portal to portal.
    auto straightened_cost = [&](uint32_t p, const Vec3& crossing, float cost_here) {
        float best_cost = std::numeric_limits<float>::infinity();
        uint32_t last = p;  // the line from nodes[last].parent must pass the portals p ... last entered by
        for (uint32_t depth = 0; depth < kStraightenDepth; ++depth) {
            const SearchNode& later = nodes[last];
            if (later.parent == kNone || later.entry >= CorridorStep::kLinkBit) break;
            if (query.area_cost(navmesh.area(later.parent)) != cost_here) break;
            const SearchNode& anchor = nodes[later.parent];
            for (uint32_t x = p;; x = nodes[x].parent) {
                if (!crosses(anchor.position, crossing, nodes[x].entry_span)) return best_cost;
                if (x == last) break;
            }
            best_cost = std::min(best_cost, anchor.g + (crossing - anchor.position).norm() * cost_here);
            last = later.parent;
        }
        return best_cost;
    };

    relax(start.polygon, kNone, CorridorStep::kStart, start.point, 0.0f, nullptr);
    if (start.polygon == goal.polygon) {
        nodes[start.polygon].g = (goal_point - start.point).norm() * query.area_cost(navmesh.area(start.polygon));
    }
    uint32_t expansions = 0;
    while (!open.empty()) {
        if ((++expansions & (kCancelCheckExpansions - 1)) == 0 && cancel && cancel->load(std::memory_order_relaxed)) {
            result.cancelled = true;
            return;
        }
        const uint32_t p = open.pop();
        if (p == goal.polygon) {
            result.reached_goal = true;
            break;
        }
        const SearchNode& node = nodes[p];
        const Vec3 here = node.position;
        const float g_here = node.g;
        const uint32_t came_from = node.parent;
        const float cost_here = query.area_cost(navmesh.area(p));

        const uint32_t corners = navmesh.corner_count(p);
        const uint32_t* const neighbours = navmesh.neighbours_of(p);
        const LineToGoal line(here, goal_point);
        for (uint32_t k = 0; k < corners; ++k) {
            const uint32_t q = neighbours[k];
            if (q == kNoPolygon || q == came_from) continue;
            const float cost_there = query.area_cost(navmesh.area(q));
            if (cost_there <= 0.0f) continue;
            PortalSpan span;
            if (!portal_span(navmesh, p, k, margin, span)) continue;
            const Vec3 crossing = crossing_point(span, line);
            float g = g_here + (crossing - here).norm() * cost_here;
            // Never below the cost here: a child cheaper than its parent could later become its
            // parent's parent, and the chain back to the start would loop.
            g = std::max(g_here, std::min(g, straightened_cost(p, crossing, cost_here)));
            if (q == goal.polygon) g += (goal_point - crossing).norm() * cost_there;
            relax(q, p, k, crossing, g, &span);
        }
        for (const LinkExit* exit = graph.exits_begin(p); exit != graph.exits_end(p); ++exit) {
            const Link& link = graph.link(exit->link).link;
            if (!can_take(link, exit->reversed != 0, query.capabilities)) continue;
            const uint32_t q = exit->reversed ? link.start_polygon : link.end_polygon;
            const float cost_there = query.area_cost(navmesh.area(q));
            if (cost_there <= 0.0f) continue;
            const Vec3& from = exit->reversed ? link.end : link.start;
            const Vec3& to = exit->reversed ? link.start : link.end;
            float g =
                g_here + (from - here).norm() * cost_here + (to - from).norm() * link.cost_modifier + query.link_cost;
            if (q == goal.polygon) g += (goal_point - to).norm() * cost_there;
            const uint32_t entry =
                CorridorStep::kLinkBit | exit->link | (exit->reversed ? CorridorStep::kReversedBit : 0u);
            relax(q, p, entry, to, g, nullptr);
        }
    }

    // Cut short by max_nodes (plan_path sends a goal out of reach to the nearest point the body
    // reaches instead), the path ends on the polygon whose entry point came nearest to the goal, as
    // Detour's does: what the search saw of the rest is all it has.
    const uint32_t last = result.reached_goal ? goal.polygon : nearest_entry_polygon;
    result.cost = nodes[last].g;
    // Costs never rise along a parent chain and a node only changes parent for a strictly lower cost,
    // so the chain leads back to the start; the bound only guards that.
    for (uint32_t p = last, guard = 0; p != kNone; p = nodes[p].parent) {
        if (++guard > result.nodes_visited + 1)
            fail(ErrorCode::Internal, "path search: corridor does not lead back to the start");
        result.steps.push_back(CorridorStep{p, nodes[p].entry});
    }
    std::reverse(result.steps.begin(), result.steps.end());
}

}  // namespace nl
