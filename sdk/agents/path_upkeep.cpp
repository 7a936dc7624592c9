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

PathUpkeep check_path(const Agent& agent, const PathGraph& now, LinkLookup& links, bool carried_over) {
    // Polygon indices of another navmesh mean nothing: the path and the polygon it stands on go.
    if (!agent.graph || (agent.graph->navmesh_ptr() != now.navmesh_ptr() && !carried_over))
        return {PathUpkeep::NavMeshChanged, {}};
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

namespace {

// Whether every tile whose square meets the x-z bounds of a and b is the same in both navmeshes.
bool same_tiles_between(const Vec3& a, const Vec3& b, const NavMesh& before, const NavMesh& now) {
    const TileGrid& grid = now.tiles().grid;
    constexpr float kRim = 1e-3f;  // a stretch along a line between tiles touches both
    const TileCoord lo = grid.tile_at(std::min(a.x(), b.x()) - kRim, std::min(a.z(), b.z()) - kRim);
    const TileCoord hi = grid.tile_at(std::max(a.x(), b.x()) + kRim, std::max(a.z(), b.z()) + kRim);
    if (double(hi.x) - lo.x > 64.0 || double(hi.z) - lo.z > 64.0) return false;  // a long way: plan it again
    for (int32_t z = lo.z; z <= hi.z; ++z)
        for (int32_t x = lo.x; x <= hi.x; ++x)
            if (before.tile_fingerprint(TileCoord{x, z}) != now.tile_fingerprint(TileCoord{x, z})) return false;
    return true;
}

}  // namespace

bool carry_path_over(Agent& agent, const NavMesh& before, const NavMesh& now) {
    if (!now.tiles().grid.tiled() || before.tiles().grid != now.tiles().grid) return false;
    if (agent.next > agent.path.size()) return false;
    Vec3 from = agent.position;
    for (size_t k = agent.next; k < agent.path.size(); ++k) {
        const Vec3& to = agent.path[k].carrier_position;
        if (!same_tiles_between(from, to, before, now)) return false;
        from = to;
    }
    std::vector<uint32_t> placed;
    placed.reserve(agent.path.size() - agent.next);
    for (size_t k = agent.next; k < agent.path.size(); ++k) {
        const NavPoint on = now.find_nearest(agent.path[k].carrier_position, Vec3(0.5f, 1.0f, 0.5f));
        if (!on.found) return false;
        placed.push_back(on.polygon);
    }
    for (size_t k = agent.next; k < agent.path.size(); ++k) agent.path[k].polygon = placed[k - agent.next];
    return true;
}

}  // namespace nl
