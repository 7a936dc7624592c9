#include "path/path_graph.h"

#include <algorithm>

namespace nl {

PathGraph::PathGraph(std::shared_ptr<const NavMesh> navmesh, std::shared_ptr<const LinkSnapshot> links,
                     std::shared_ptr<const SurfaceFrame> frame)
    : navmesh_(std::move(navmesh)), links_(links ? std::move(links) : std::make_shared<const LinkSnapshot>()),
      frame_(std::move(frame)) {
    for (const StoredLink& s : *links_) has_cross_links_ = has_cross_links_ || s.link.crosses();
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

size_t PathGraph::link_index_bytes() const {
    return first_exit_.capacity() * sizeof(uint32_t) + exits_.capacity() * sizeof(LinkExit);
}

}  // namespace nl
