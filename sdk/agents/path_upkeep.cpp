#include "agents/path_upkeep.h"

#include <algorithm>

#include "path/link_filter.h"

namespace nl {

const Link* LinkLookup::find(const PathGraph& graph, Handle link) {
    const LinkSnapshot* snapshot = graph.links_ptr().get();
    if (!snapshot) return nullptr;
    auto known = std::find_if(snapshots_.begin(), snapshots_.end(), [&](const auto& s) { return s.first == snapshot; });
    if (known == snapshots_.end()) {
        std::unordered_map<uint64_t, const Link*> by_handle;
        by_handle.reserve(snapshot->size());
        for (const StoredLink& s : *snapshot) by_handle.emplace(s.id.packed(), &s.link);
        snapshots_.emplace_back(snapshot, std::move(by_handle));
        known = snapshots_.end() - 1;
    }
    const auto found = known->second.find(link.packed());
    return found == known->second.end() ? nullptr : found->second;
}

PathUpkeep check_path(const Agent& agent, const PathGraph& now, LinkLookup& links) {
    // Polygon indices of another navmesh mean nothing: the path and the polygon it stands on go.
    if (!agent.graph || agent.graph->navmesh_ptr() != now.navmesh_ptr()) return {PathUpkeep::NavMeshChanged, {}};
    for (size_t k = agent.next; k < agent.path.size(); ++k) {
        const PathPoint& point = agent.path[k];
        if (point.segment == kSegmentWalk) continue;
        const Link* planned = links.find(*agent.graph, point.link);
        const Link* current = links.find(now, point.link);
        // A link parked with an end on a tile not loaded (kNoPolygon) serves no path.
        const bool serves = planned && current && current->enabled && current->start_polygon != kNoPolygon &&
                            current->end_polygon != kNoPolygon && current->start == planned->start &&
                            current->end == planned->end && (!point.reversed || current->bidirectional) &&
                            can_take(*current, point.reversed, agent.def.capabilities);
        if (!serves) return {PathUpkeep::LinkGone, point.link};
    }
    return {};
}

}  // namespace nl
