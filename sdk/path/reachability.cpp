#include "path/reachability.h"

#include <algorithm>

#include "path/link_filter.h"
#include "path/portal.h"

namespace nl {
namespace {

constexpr uint32_t kNoIsland = ReachabilityMap::kNoIsland;

// The polygons a body steps into from p, as the search would: across open portals and over the
// links it can take, never into an excluded area.
template <typename Visit>
void for_each_successor(const PathGraph& graph, const ReachabilityClass& body, uint32_t p, Visit&& visit) {
    const NavMesh& navmesh = graph.navmesh();
    const uint32_t corners = navmesh.corner_count(p);
    const uint32_t* const neighbours = navmesh.neighbours_of(p);
    for (uint32_t k = 0; k < corners; ++k) {
        const uint32_t q = neighbours[k];
        if (q == kNoPolygon || body.excludes(navmesh.area(q)) || body.closes(navmesh.edge_index(p, k))) continue;
        visit(q);
    }
    for (const LinkExit* exit = graph.exits_begin(p); exit != graph.exits_end(p); ++exit) {
        if (!body.can_take(exit->link, exit->reversed != 0)) continue;
        const Link& link = graph.link(exit->link).link;
        const uint32_t q = exit->reversed ? link.start_polygon : link.end_polygon;
        if (!body.excludes(navmesh.area(q))) visit(q);
    }
}

// Tarjan's strongly connected components over the polygons outside excluded areas, without
// recursion (a corridor of a million polygons would overflow the stack). Components are numbered in
// the order they complete: every component a polygon leads to completes before its own.
struct Components {
    std::vector<uint32_t> of;  // per polygon; kNoIsland for excluded ones
    uint32_t count = 0;
};

Components strongly_connected(const PathGraph& graph, const ReachabilityClass& body) {
    const NavMesh& navmesh = graph.navmesh();
    const uint32_t polygons = navmesh.polygon_count();
    Components result;
    result.of.assign(polygons, kNoIsland);
    std::vector<uint32_t> order(polygons, kNoIsland), low(polygons, 0);
    std::vector<uint32_t> stack;  // Tarjan's stack of open polygons
    std::vector<uint8_t> on_stack(polygons, 0);
    std::vector<std::pair<uint32_t, uint32_t>> calls;  // (polygon, next successor to look at)
    std::vector<uint32_t> successors;                  // of every polygon on `calls`, concatenated
    std::vector<uint32_t> first_successor;             // per entry of `calls`: offset into `successors`
    uint32_t next_order = 0;

    auto open = [&](uint32_t p) {
        order[p] = low[p] = next_order++;
        stack.push_back(p);
        on_stack[p] = 1;
        first_successor.push_back(static_cast<uint32_t>(successors.size()));
        for_each_successor(graph, body, p, [&](uint32_t q) { successors.push_back(q); });
        calls.emplace_back(p, first_successor.back());
    };
    for (uint32_t root = 0; root < polygons; ++root) {
        if (order[root] != kNoIsland || body.excludes(navmesh.area(root))) continue;
        open(root);
        while (!calls.empty()) {
            auto& [p, next] = calls.back();  // not used after open(): it may move the calls
            // Deeper calls' successors are gone by the time this one is on top again.
            const uint32_t end = static_cast<uint32_t>(successors.size());
            if (next < end) {
                const uint32_t q = successors[next++];
                if (order[q] == kNoIsland) {
                    open(q);
                } else if (on_stack[q]) {
                    low[p] = std::min(low[p], order[q]);
                }
                continue;
            }
            const uint32_t done = p;
            if (low[done] == order[done]) {
                uint32_t member;
                do {
                    member = stack.back();
                    stack.pop_back();
                    on_stack[member] = 0;
                    result.of[member] = result.count;
                } while (member != done);
                ++result.count;
            }
            successors.resize(first_successor.back());
            first_successor.pop_back();
            calls.pop_back();
            if (!calls.empty()) low[calls.back().first] = std::min(low[calls.back().first], low[done]);
        }
    }
    return result;
}

std::vector<uint32_t>& scratch_marks() {
    thread_local std::vector<uint32_t> marks;
    return marks;
}

}  // namespace

ReachabilityClass ReachabilityClass::of(const PathGraph& graph, const AgentCapabilities& agent,
                                        const std::vector<float>& area_costs) {
    ReachabilityClass c;
    const NavMesh& navmesh = graph.navmesh();
    const float margin = std::max(0.0f, agent.radius - navmesh.agent().radius);
    if (margin > 0.0f) {
        bool any = false;
        std::vector<uint64_t> closed((navmesh.edge_count() + 63) / 64, 0);
        for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
            for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) {
                PortalSpan span;
                if (navmesh.neighbour(p, k) == kNoPolygon || portal_span(navmesh, p, k, margin, span)) continue;
                const uint32_t edge = navmesh.edge_index(p, k);
                closed[edge >> 6] |= uint64_t{1} << (edge & 63);
                any = true;
            }
        }
        if (any) c.closed_portals = std::move(closed);
    }
    c.excluded_areas = excluded_areas_of(area_costs);
    const LinkSnapshot& links = graph.links();
    c.takeable.assign((2 * links.size() + 63) / 64, 0);
    for (size_t i = 0; i < links.size(); ++i) {
        const Link& link = links[i].link;
        if (!link.enabled) continue;
        if (nl::can_take(link, false, agent)) c.takeable[(2 * i) >> 6] |= uint64_t{1} << ((2 * i) & 63);
        if (link.bidirectional && nl::can_take(link, true, agent))
            c.takeable[(2 * i + 1) >> 6] |= uint64_t{1} << ((2 * i + 1) & 63);
    }
    return c;
}

std::array<uint64_t, 4> ReachabilityClass::excluded_areas_of(const std::vector<float>& area_costs) {
    std::array<uint64_t, 4> mask{};
    for (size_t a = 0; a < area_costs.size() && a < 256; ++a) {
        if (area_costs[a] <= 0.0f) mask[a >> 6] |= uint64_t{1} << (a & 63);
    }
    return mask;
}

ReachabilityMap::ReachabilityMap(const PathGraph& graph, const ReachabilityClass& body) {
    const NavMesh& navmesh = graph.navmesh();
    const uint32_t polygons = navmesh.polygon_count();
    const Components components = strongly_connected(graph, body);
    island_count_ = components.count;

    // Islands numbered by their lowest polygon, so the numbers do not depend on the search order.
    std::vector<uint32_t> island_of_component(components.count, kNoIsland);
    std::vector<uint32_t> component_of_island(components.count);
    island_of_.assign(polygons, kNoIsland);
    uint32_t next_island = 0;
    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t c = components.of[p];
        if (c == kNoIsland) continue;
        if (island_of_component[c] == kNoIsland) {
            component_of_island[next_island] = c;
            island_of_component[c] = next_island++;
        }
        island_of_[p] = island_of_component[c];
    }

    first_polygon_.assign(island_count_ + 1, 0);
    for (uint32_t p = 0; p < polygons; ++p) {
        if (island_of_[p] != kNoIsland) ++first_polygon_[island_of_[p] + 1];
    }
    for (uint32_t i = 0; i < island_count_; ++i) first_polygon_[i + 1] += first_polygon_[i];
    polygons_.resize(first_polygon_[island_count_]);
    {
        std::vector<uint32_t> fill(first_polygon_.begin(), first_polygon_.end() - 1);
        for (uint32_t p = 0; p < polygons; ++p) {
            if (island_of_[p] != kNoIsland) polygons_[fill[island_of_[p]]++] = p;
        }
    }

    // The island graph (acyclic), each island's successors once.
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    excluded_index_.assign(polygons, kNoIsland);
    first_exit_.push_back(0);
    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t from = island_of_[p];
        if (from == kNoIsland) {
            excluded_index_[p] = static_cast<uint32_t>(first_exit_.size() - 1);
            const size_t begin = exits_.size();
            for_each_successor(graph, body, p, [&](uint32_t q) { exits_.push_back(island_of_[q]); });
            std::sort(exits_.begin() + begin, exits_.end());
            exits_.erase(std::unique(exits_.begin() + begin, exits_.end()), exits_.end());
            first_exit_.push_back(static_cast<uint32_t>(exits_.size()));
            continue;
        }
        for_each_successor(graph, body, p, [&](uint32_t q) {
            if (island_of_[q] != from) edges.emplace_back(from, island_of_[q]);
        });
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    first_successor_.assign(island_count_ + 1, 0);
    std::vector<uint8_t> linked(island_count_, 0);
    for (const auto& [from, to] : edges) {
        ++first_successor_[from + 1];
        linked[from] = linked[to] = 1;
    }
    for (uint32_t i = 0; i < island_count_; ++i) first_successor_[i + 1] += first_successor_[i];
    successors_.reserve(edges.size());
    for (const auto& edge : edges) successors_.push_back(edge.second);

    // The closure over the islands that links join, rows filled sinks first (the order the
    // components completed in), each the union of its successors' rows.
    closure_row_.assign(island_count_, kNoIsland);
    for (uint32_t i = 0; i < island_count_; ++i) {
        if (linked[i]) closure_row_[i] = linked_count_++;
    }
    if (linked_count_ == 0 || linked_count_ > kMaxClosureIslands) return;
    closure_width_ = (linked_count_ + 63) / 64;
    closure_.assign(size_t(linked_count_) * closure_width_, 0);
    for (uint32_t c = 0; c < components.count; ++c) {
        const uint32_t island = island_of_component[c];
        const uint32_t row = closure_row_[island];
        if (row == kNoIsland) continue;
        uint64_t* bits = &closure_[size_t(row) * closure_width_];
        bits[row >> 6] |= uint64_t{1} << (row & 63);
        for (uint32_t s = first_successor_[island]; s < first_successor_[island + 1]; ++s) {
            const uint64_t* other = &closure_[size_t(closure_row_[successors_[s]]) * closure_width_];
            for (uint32_t w = 0; w < closure_width_; ++w) bits[w] |= other[w];
        }
    }
}

const uint32_t* ReachabilityMap::exits_begin(uint32_t polygon) const {
    return exits_.data() + first_exit_[excluded_index_[polygon]];
}
const uint32_t* ReachabilityMap::exits_end(uint32_t polygon) const {
    return exits_.data() + first_exit_[excluded_index_[polygon] + 1];
}

bool ReachabilityMap::island_reaches(uint32_t from, uint32_t to) const {
    if (from == to) return true;
    const uint32_t from_row = closure_row_[from], to_row = closure_row_[to];
    if (from_row == kNoIsland || to_row == kNoIsland) return false;  // an island no link joins reaches only itself
    if (closure_width_ != 0) return (closure_[size_t(from_row) * closure_width_ + (to_row >> 6)] >> (to_row & 63)) & 1u;
    thread_local std::vector<uint8_t> reached;
    mark_reachable(&from, 1, reached);
    return reached[to] != 0;
}

void ReachabilityMap::mark_reachable(const uint32_t* from, size_t count, std::vector<uint8_t>& reached) const {
    reached.assign(island_count_, 0);
    std::vector<uint32_t>& stack = scratch_marks();
    stack.clear();
    for (size_t i = 0; i < count; ++i) {
        if (!reached[from[i]]) reached[from[i]] = 1, stack.push_back(from[i]);
    }
    while (!stack.empty()) {
        const uint32_t island = stack.back();
        stack.pop_back();
        for (uint32_t s = first_successor_[island]; s < first_successor_[island + 1]; ++s) {
            if (!reached[successors_[s]]) {
                reached[successors_[s]] = 1;
                stack.push_back(successors_[s]);
            }
        }
    }
}

bool ReachabilityMap::reaches(uint32_t from, uint32_t to) const {
    if (from == to) return true;
    const uint32_t target = island_of_[to];
    if (target == kNoIsland) return false;
    if (island_of_[from] != kNoIsland) return island_reaches(island_of_[from], target);
    for (const uint32_t* e = exits_begin(from); e != exits_end(from); ++e) {
        if (island_reaches(*e, target)) return true;
    }
    return false;
}

void ReachabilityMap::reachable_islands(uint32_t from, std::vector<uint8_t>& reached) const {
    if (island_of_[from] != kNoIsland) return mark_reachable(&island_of_[from], 1, reached);
    mark_reachable(exits_begin(from), size_t(exits_end(from) - exits_begin(from)),
                   reached);  // out of an excluded polygon
}

void ReachabilityMap::reachable_polygons(uint32_t from, std::vector<uint32_t>& out) const {
    out.clear();
    std::vector<uint8_t> reached;
    reachable_islands(from, reached);
    if (island_of_[from] == kNoIsland) out.push_back(from);
    for (uint32_t i = 0; i < island_count_; ++i) {
        if (reached[i])
            out.insert(out.end(), polygons_.begin() + first_polygon_[i], polygons_.begin() + first_polygon_[i + 1]);
    }
    std::sort(out.begin(), out.end());
}

size_t ReachabilityMap::memory_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(island_of_) + bytes(first_polygon_) + bytes(polygons_) + bytes(first_successor_) + bytes(successors_) +
           bytes(excluded_index_) + bytes(first_exit_) + bytes(exits_) + bytes(closure_row_) + bytes(closure_);
}

}  // namespace nl
