#include "path/corridor_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "path/link_filter.h"
#include "path/portal.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

struct SearchNode {
    Vec3 position;  // where the corridor enters the polygon
    float g;        // cost from the start to `position` (to the goal point for the goal polygon)
    float f;        // g + heuristic
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
        if (nodes.size() < polygons) nodes.resize(polygons, SearchNode{Vec3::Zero(), 0, 0, kNone, kNone, 0, kNone});
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

    // After p's f went down.
    void decreased(uint32_t p) { sift_up(nodes_[p].heap); }

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

// Where the corridor crosses a portal: where the straight line from `from` towards `goal` meets it,
// or the portal's nearer end when that line passes outside. Straighter than Detour's edge midpoints,
// so the search ranks corridors closer to their string-pulled length.
Vec3 crossing_point(const PortalSpan& span, const Vec3& from, const Vec3& goal) {
    const Vec3 e = span.right - span.left;
    const float dx = goal.x() - from.x(), dz = goal.z() - from.z();
    const float denominator = e.x() * dz - e.z() * dx;
    float t;
    if (std::fabs(denominator) > 1e-12f) {
        const float wx = from.x() - span.left.x(), wz = from.z() - span.left.z();
        t = (wx * dz - wz * dx) / denominator;
    } else {
        const float length2 = e.x() * e.x() + e.z() * e.z();
        t = length2 > 0.0f ? ((from.x() - span.left.x()) * e.x() + (from.z() - span.left.z()) * e.z()) / length2 : 0.0f;
    }
    return span.left + std::clamp(t, 0.0f, 1.0f) * e;
}

float heuristic_scale(const PathGraph& graph, const PathQuery& query) {
    float scale = std::min(1.0f, graph.cheapest_link_per_metre());
    for (float cost : query.area_costs) {
        if (cost > 0.0f) scale = std::min(scale, cost);
    }
    return scale;
}

}  // namespace

CorridorSearch find_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start,
                             const NavPoint& goal, const std::atomic<bool>* cancel) {
    const NavMesh& mesh = graph.navmesh();
    SearchScratch& scratch = thread_scratch();
    const uint32_t epoch = scratch.begin(mesh.polygon_count());
    SearchNode* nodes = scratch.nodes.data();
    OpenList open(scratch.open, nodes);
    const float margin = std::max(0.0f, query.agent.radius - mesh.agent().radius);
    const float h_scale = heuristic_scale(graph, query);
    const Vec3 goal_point = goal.point;

    CorridorSearch result;
    uint32_t best = start.polygon;  // nearest to the goal so far, for a partial path
    float best_distance = (goal_point - start.point).norm();

    auto relax = [&](uint32_t q, uint32_t parent, uint32_t entry, const Vec3& position, float g) {
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
        n.g = g;
        n.parent = parent;
        n.entry = entry;
        const float distance = (goal_point - position).norm();
        n.f = q == goal.polygon ? g : g + distance * h_scale;
        if (distance < best_distance) {
            best_distance = distance;
            best = q;
        }
        if (n.heap == kNone) {
            open.push(q);
        } else {
            open.decreased(q);
        }
    };

    relax(start.polygon, kNone, CorridorStep::kStart, start.point, 0.0f);
    if (start.polygon == goal.polygon) {
        nodes[start.polygon].g = (goal_point - start.point).norm() * query.area_cost(mesh.area(start.polygon));
    }
    uint32_t expansions = 0;
    while (!open.empty()) {
        if ((++expansions & 63u) == 0 && cancel && cancel->load(std::memory_order_relaxed)) {
            result.cancelled = true;
            return result;
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
        const float cost_here = query.area_cost(mesh.area(p));

        const uint32_t corners = mesh.corner_count(p);
        for (uint32_t k = 0; k < corners; ++k) {
            const uint32_t q = mesh.neighbour(p, k);
            if (q == kNoPolygon || q == came_from) continue;
            const float cost_there = query.area_cost(mesh.area(q));
            if (cost_there <= 0.0f) continue;
            PortalSpan span;
            if (!portal_span(mesh, p, k, margin, span)) continue;
            const Vec3 crossing = crossing_point(span, here, goal_point);
            float g = g_here + (crossing - here).norm() * cost_here;
            if (q == goal.polygon) g += (goal_point - crossing).norm() * cost_there;
            relax(q, p, k, crossing, g);
        }
        for (const LinkExit* exit = graph.exits_begin(p); exit != graph.exits_end(p); ++exit) {
            const Link& link = graph.link(exit->link).link;
            if (!can_take(link, exit->reversed != 0, query.agent)) continue;
            const uint32_t q = exit->reversed ? link.start_polygon : link.end_polygon;
            const float cost_there = query.area_cost(mesh.area(q));
            if (cost_there <= 0.0f) continue;
            const Vec3& from = exit->reversed ? link.end : link.start;
            const Vec3& to = exit->reversed ? link.start : link.end;
            float g = g_here + (from - here).norm() * cost_here + (to - from).norm() * link.cost_modifier + query.link_cost;
            if (q == goal.polygon) g += (goal_point - to).norm() * cost_there;
            const uint32_t entry = CorridorStep::kLinkBit | exit->link | (exit->reversed ? CorridorStep::kReversedBit : 0u);
            relax(q, p, entry, to, g);
        }
    }

    const uint32_t last = result.reached_goal ? goal.polygon : best;
    result.cost = nodes[last].g;
    result.last_position = nodes[last].position;
    // Parents form a chain of strictly falling costs back to the start; the bound only guards that.
    for (uint32_t p = last, guard = 0; p != kNone; p = nodes[p].parent) {
        if (++guard > result.nodes_visited + 1) fail(ErrorCode::Internal, "path search: corridor does not lead back to the start");
        result.steps.push_back(CorridorStep{p, nodes[p].entry});
    }
    std::reverse(result.steps.begin(), result.steps.end());
    return result;
}

}  // namespace nl
