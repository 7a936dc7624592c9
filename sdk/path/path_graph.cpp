#include "path/path_graph.h"

#include <algorithm>

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
    for (uint32_t v = 0; v < mesh.vertex_count(); ++v)
        if (mesh.on_outline(v)) bends_[v] = kAnyBody;
    for (uint32_t p = 0; p < mesh.polygon_count(); ++p) {
        const uint8_t area = mesh.area(p);
        areas_present_[area >> 6] |= uint64_t(1) << (area & 63);
        const uint32_t n = mesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t v = mesh.corner(p, k), w = mesh.corner(p, k + 1 == n ? 0 : k + 1);
            if (area_at[v] == kUnseen) area_at[v] = area;
            else if (area_at[v] != area) bends_[v] |= kAnyBody;
            if (mesh.neighbour(p, k) == kNoPolygon) continue;
            if (mesh.on_outline(v)) bends_[w] |= kWiderBody;
            if (mesh.on_outline(w)) bends_[v] |= kWiderBody;
        }
    }
}

size_t PathGraph::link_index_bytes() const {
    return first_exit_.capacity() * sizeof(uint32_t) + exits_.capacity() * sizeof(LinkExit);
}

}  // namespace nl
