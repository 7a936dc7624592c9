#include "path/path_graph.h"

#include <algorithm>
#include <cmath>

namespace nl {

PathGraph::PathGraph(std::shared_ptr<const NavMesh> navmesh, std::shared_ptr<const LinkSnapshot> links,
                     std::shared_ptr<const SurfaceFrame> frame)
    : navmesh_(std::move(navmesh)), links_(links ? std::move(links) : std::make_shared<const LinkSnapshot>()),
      frame_(std::move(frame)) {
    for (const StoredLink& s : *links_) has_cross_links_ = has_cross_links_ || s.link.crosses();
    const uint32_t polygons = navmesh_->polygon_count();
    index_bends();
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

void PathGraph::index_bends() {
    const NavMesh& mesh = *navmesh_;
    constexpr uint8_t kAnyBody = 1, kWiderBody = 2;
    bends_.assign(mesh.vertex_count(), 0);
    constexpr uint16_t kUnseen = 0xffff;
    std::vector<uint16_t> area_at(mesh.vertex_count(), kUnseen);
    // The angle the polygons round each vertex fill, seen from above: a shortest walk bends only
    // round an obstacle's reflex corner, where they fill more than half a turn.
    std::vector<double> angle(mesh.vertex_count(), 0.0);
    for (uint32_t v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.on_outline(v)) bends_[v] = kAnyBody;
    twins_.assign(mesh.edge_count(), kNoTwin);
    dead_ends_.assign(mesh.polygon_count(), 0);
    for (uint32_t p = 0; p < mesh.polygon_count(); ++p) {
        const uint8_t area = mesh.area(p);
        uint32_t neighbours = 0;
        for (uint32_t k = 0; k < mesh.corner_count(p); ++k) neighbours += mesh.neighbour(p, k) != kNoPolygon;
        dead_ends_[p] = neighbours <= 1;
        areas_present_[area >> 6] |= uint64_t(1) << (area & 63);
        const uint32_t n = mesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t u = mesh.corner(p, k == 0 ? n - 1 : k - 1), v = mesh.corner(p, k), w = mesh.corner(p, k + 1 == n ? 0 : k + 1);
            const double ax = double(mesh.vertex(u).x()) - mesh.vertex(v).x(), az = double(mesh.vertex(u).z()) - mesh.vertex(v).z();
            const double bx = double(mesh.vertex(w).x()) - mesh.vertex(v).x(), bz = double(mesh.vertex(w).z()) - mesh.vertex(v).z();
            angle[v] += std::fabs(std::atan2(ax * bz - az * bx, ax * bx + az * bz));
            if (area_at[v] == kUnseen) area_at[v] = area;
            else if (area_at[v] != area) bends_[v] |= kAnyBody;
            const uint32_t q = mesh.neighbour(p, k);
            if (q == kNoPolygon) continue;
            const uint32_t m = mesh.corner_count(q);
            for (uint32_t j = 0; j < m; ++j) {
                // The same edge runs the other way in q; of several edges to p (a non-manifold repair), that one.
                if (mesh.neighbour(q, j) != p) continue;
                if (twins_[mesh.edge_index(p, k)] == kNoTwin || mesh.corner(q, j) == w) twins_[mesh.edge_index(p, k)] = uint8_t(j);
            }
            if (mesh.on_outline(v)) bends_[w] |= kWiderBody;
            if (mesh.on_outline(w)) bends_[v] |= kWiderBody;
        }
    }
    constexpr double kHalfTurn = 3.14159265358979323846;
    for (uint32_t v = 0; v < mesh.vertex_count(); ++v)
        if (angle[v] <= kHalfTurn + 1e-9) bends_[v] = 0;
}

size_t PathGraph::link_index_bytes() const {
    return first_exit_.capacity() * sizeof(uint32_t) + exits_.capacity() * sizeof(LinkExit);
}

}  // namespace nl
