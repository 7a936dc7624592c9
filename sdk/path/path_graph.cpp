#include "path/path_graph.h"

#include <algorithm>
#include <cmath>

namespace nl {

PathGraph::PathGraph(std::shared_ptr<const NavMesh> navmesh, std::shared_ptr<const LinkSnapshot> links,
                     std::shared_ptr<const CarrierFrame> frame, std::shared_ptr<const NavMeshSearchIndex> index)
    : navmesh_(std::move(navmesh)),
      links_(links ? std::move(links) : std::make_shared<const LinkSnapshot>()),
      frame_(std::move(frame)),
      index_(index && &index->navmesh() == navmesh_.get() ? std::move(index)
                                                          : std::make_shared<const NavMeshSearchIndex>(navmesh_)) {
    for (const StoredLink& s : *links_) has_cross_links_ = has_cross_links_ || s.link.crosses();
    index_links();
    mark_subtree_exits();
}

void PathGraph::index_links() {
    const uint32_t polygons = navmesh_->polygon_count();
    auto usable = [&](const Link& l) {
        // A link to another navmesh leaves this graph: agents plan such routes leg by leg (agents/route.h).
        return l.enabled && !l.crosses() && l.start_polygon < polygons && l.end_polygon < polygons;
    };
    // Counting sort by departure polygon: a bidirectional link leaves from both ends.
    std::vector<uint32_t> counts(polygons + 1, 0);
    bool any = false;
    for (const StoredLink& stored : *links_) {
        const Link& l = stored.link;
        if (!usable(l)) continue;
        any = true;
        ++counts[l.start_polygon];
        if (l.bidirectional) ++counts[l.end_polygon];
        cheapest_link_per_metre_ = std::min(cheapest_link_per_metre_, l.cost_modifier);
    }
    if (!any) return;
    first_exit_.assign(polygons + 1, 0);
    for (uint32_t p = 0; p < polygons; ++p) first_exit_[p + 1] = first_exit_[p] + counts[p];
    exits_.resize(first_exit_[polygons]);
    std::vector<uint32_t> fill(first_exit_.begin(), first_exit_.end() - 1);
    for (uint32_t i = 0; i < links_->size(); ++i) {
        const Link& l = (*links_)[i].link;
        if (!usable(l)) continue;
        exits_[fill[l.start_polygon]++] = LinkExit{i, 0};
        if (l.bidirectional) exits_[fill[l.end_polygon]++] = LinkExit{i, 1};
    }
}

NavMeshSearchIndex::NavMeshSearchIndex(std::shared_ptr<const NavMesh> navmesh) : navmesh_(std::move(navmesh)) {
    index_bends();
    index_appendices();
}

void NavMeshSearchIndex::index_bends() {
    const NavMesh& navmesh = *navmesh_;
    constexpr uint8_t kAnyBody = 1, kWiderBody = 2;
    bends_.assign(navmesh.vertex_count(), 0);
    constexpr uint16_t kUnseen = 0xffff;
    std::vector<uint16_t> area_at(navmesh.vertex_count(), kUnseen);
    // The angle the polygons round each vertex fill, seen from above: a shortest walk bends only
    // round an obstacle's reflex corner, where they fill more than half a turn.
    std::vector<double> angle(navmesh.vertex_count(), 0.0);
    for (uint32_t v = 0; v < navmesh.vertex_count(); ++v)
        if (navmesh.on_outline(v)) bends_[v] = kAnyBody;
    twins_.assign(navmesh.edge_count(), kNoTwin);
    for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
        const uint8_t area = navmesh.area(p);
        areas_present_[area >> 6] |= uint64_t(1) << (area & 63);
        const uint32_t n = navmesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t u = navmesh.corner(p, k == 0 ? n - 1 : k - 1), v = navmesh.corner(p, k),
                           w = navmesh.corner(p, k + 1 == n ? 0 : k + 1);
            const double ax = double(navmesh.vertex(u).x()) - navmesh.vertex(v).x(),
                         az = double(navmesh.vertex(u).z()) - navmesh.vertex(v).z();
            const double bx = double(navmesh.vertex(w).x()) - navmesh.vertex(v).x(),
                         bz = double(navmesh.vertex(w).z()) - navmesh.vertex(v).z();
            angle[v] += std::fabs(std::atan2(ax * bz - az * bx, ax * bx + az * bz));
            if (area_at[v] == kUnseen)
                area_at[v] = area;
            else if (area_at[v] != area)
                bends_[v] |= kAnyBody;
            const uint32_t q = navmesh.neighbour(p, k);
            if (q == kNoPolygon) continue;
            const uint32_t m = navmesh.corner_count(q);
            for (uint32_t j = 0; j < m; ++j) {
                // The same edge runs the other way in q; of several edges to p (a non-manifold repair), that one.
                if (navmesh.neighbour(q, j) != p) continue;
                if (twins_[navmesh.edge_index(p, k)] == kNoTwin || navmesh.corner(q, j) == w)
                    twins_[navmesh.edge_index(p, k)] = uint8_t(j);
            }
            if (navmesh.on_outline(v)) bends_[w] |= kWiderBody;
            if (navmesh.on_outline(w)) bends_[v] |= kWiderBody;
        }
    }
    constexpr double kHalfTurn = 3.14159265358979323846;
    for (uint32_t v = 0; v < navmesh.vertex_count(); ++v)
        if (angle[v] <= kHalfTurn + 1e-9) bends_[v] = 0;
}

void NavMeshSearchIndex::index_appendices() {
    const NavMesh& navmesh = *navmesh_;
    const uint32_t polygons = navmesh.polygon_count();
    // Peel the polygons with one way on at most, again and again (leaves, then what they hung
    // from): what goes is trees of polygons hanging from the rest, each from the neighbour it had left.
    hangs_from_.assign(polygons, kNoPolygon);
    subtree_first_.assign(polygons, kNoPolygon);
    subtree_last_.assign(polygons, kNoPolygon);
    std::vector<uint32_t> ways(polygons, 0);
    std::vector<uint32_t>& order = peel_order_;
    std::vector<uint8_t> queued(polygons, 0), peeled(polygons, 0);
    for (uint32_t p = 0; p < polygons; ++p) {
        for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) ways[p] += navmesh.neighbour(p, k) != kNoPolygon;
        if (ways[p] <= 1) order.push_back(p), queued[p] = 1;
    }
    for (size_t i = 0; i < order.size(); ++i) {
        const uint32_t p = order[i];
        peeled[p] = 1;
        for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) {
            const uint32_t q = navmesh.neighbour(p, k);
            if (q == kNoPolygon || peeled[q]) continue;
            hangs_from_[p] = q;
            if (--ways[q] <= 1 && !queued[q]) order.push_back(q), queued[q] = 1;
        }
    }
    if (order.empty()) return;
    // Number each tree depth first, so that a polygon's subtree is one range of numbers.
    std::vector<uint32_t> first_child(polygons + 1, 0), children(order.size());
    for (const uint32_t p : order)
        if (hangs_from_[p] != kNoPolygon && peeled[hangs_from_[p]]) ++first_child[hangs_from_[p] + 1];
    for (uint32_t p = 0; p < polygons; ++p) first_child[p + 1] += first_child[p];
    std::vector<uint32_t> fill(first_child.begin(), first_child.end() - 1);
    for (const uint32_t p : order)
        if (hangs_from_[p] != kNoPolygon && peeled[hangs_from_[p]]) children[fill[hangs_from_[p]]++] = p;
    uint32_t number = 0;
    std::vector<std::pair<uint32_t, uint32_t>> stack;  // polygon, next child
    for (const uint32_t top : order) {
        if (hangs_from_[top] != kNoPolygon && peeled[hangs_from_[top]]) continue;
        stack.push_back({top, first_child[top]});
        subtree_first_[top] = number++;
        while (!stack.empty()) {
            auto& [p, next] = stack.back();
            if (next < first_child[p + 1]) {
                const uint32_t child = children[next++];
                subtree_first_[child] = number++;
                stack.push_back({child, first_child[child]});
                continue;
            }
            subtree_last_[p] = number - 1;
            stack.pop_back();
        }
    }
}

void PathGraph::mark_subtree_exits() {
    subtree_exits_.assign(navmesh_->polygon_count(), 0);
    // Leaves are peeled before what they hang from: one pass in peel order gathers each subtree.
    for (const uint32_t p : index_->peel_order()) {
        subtree_exits_[p] |= exits_begin(p) != exits_end(p);
        const uint32_t stem = index_->hangs_from(p);
        if (stem != kNoPolygon && index_->peeled(stem)) subtree_exits_[stem] |= subtree_exits_[p];
    }
}

size_t NavMeshSearchIndex::memory_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(bends_) + bytes(twins_) + bytes(hangs_from_) + bytes(subtree_first_) + bytes(subtree_last_) +
           bytes(peel_order_);
}

size_t PathGraph::search_index_bytes() const {
    return index_->memory_bytes() + subtree_exits_.capacity() * sizeof(uint8_t);
}

size_t PathGraph::link_index_bytes() const {
    return first_exit_.capacity() * sizeof(uint32_t) + exits_.capacity() * sizeof(LinkExit);
}

}  // namespace nl
