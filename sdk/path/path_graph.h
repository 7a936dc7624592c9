// What a search reads: one navmesh and one moment of its links, with the links indexed by the
// polygon they leave from. Immutable, so any number of searches share it; an edit to the links makes
// the next request build a new one while running searches keep theirs. The reachability maps of
// bodies on it are built when first asked for and kept with it (thread-safe).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "links/link_snapshot.h"
#include "navmesh/navmesh.h"
#include "navmesh/surface_pose.h"
#include "path/reachability_cache.h"

namespace nl {

// A way out of a polygon over a link: link index in the snapshot, and which way it is taken.
struct LinkExit {
    uint32_t link;
    uint32_t reversed;  // 1: from the link's end to its start
};

class PathGraph {
public:
    // `frame`: the movable mesh the navmesh rides (null: it stays where it is). The navmesh and the
    // links are in its space; searches run there.
    PathGraph(std::shared_ptr<const NavMesh> navmesh, std::shared_ptr<const LinkSnapshot> links,
              std::shared_ptr<const SurfaceFrame> frame = nullptr);

    const NavMesh& navmesh() const { return *navmesh_; }
    const std::shared_ptr<const NavMesh>& navmesh_ptr() const { return navmesh_; }
    const std::shared_ptr<const LinkSnapshot>& links_ptr() const { return links_; }
    const StoredLink& link(uint32_t index) const { return (*links_)[index]; }
    const std::shared_ptr<const SurfaceFrame>& frame() const { return frame_; }
    // Whether any of its links leads to another navmesh (Link::crosses; not in the exits).
    bool has_cross_links() const { return has_cross_links_; }

    // The enabled links leaving polygon p, as [begin, end).
    const LinkExit* exits_begin(uint32_t p) const { return first_exit_.empty() ? nullptr : &exits_[first_exit_[p]]; }
    const LinkExit* exits_end(uint32_t p) const { return first_exit_.empty() ? nullptr : &exits_[first_exit_[p + 1]]; }

    // The smallest cost per metre a link offers (its cost modifier), so the heuristic stays below
    // any real cost; 1 without links.
    float cheapest_link_per_metre() const { return cheapest_link_per_metre_; }

    // Bit a set for each area some polygon of the navmesh has.
    const std::array<uint64_t, 4>& areas_present() const { return areas_present_; }
    // Whether a shortest walk may bend at vertex v: a reflex corner of an obstacle for some body (the
    // polygons round it fill more than half a turn seen from above). For every body the outline's
    // vertices and those where areas meet (an area a body keeps out of is an obstacle to it); for a
    // body wider than the navmesh's agent also the far ends of portals from the outline (its width
    // may close such a portal, which then stands as a wall ending there).
    bool may_bend_at(uint32_t v, bool wider_body) const { return (bends_[v] & (wider_body ? 3u : 1u)) != 0; }

    // Whether a walk stepping from polygon `from` into its neighbour `into` goes down a dead end: a
    // tree of polygons hanging from the rest of the navmesh (from a polygon with one way on, and so
    // on), entered from its stem, that holds neither `goal` nor a link's way out. Such a walk can only
    // come back the way it went.
    bool dead_end(uint32_t from, uint32_t into, uint32_t goal) const {
        if (hangs_from_[into] != from) return false;
        const uint32_t goal_number = subtree_first_[goal];
        const bool goal_inside = goal_number != kNoPolygon && goal_number >= subtree_first_[into] && goal_number <= subtree_last_[into];
        return !goal_inside && subtree_exits_[into] == 0;
    }

    // The edge of polygon p's neighbour across edge k that leads back to p (the same edge seen from
    // the other side), or kNoTwin for an edge without neighbour.
    static constexpr uint8_t kNoTwin = 0xff;
    uint8_t twin_edge(uint32_t p, uint32_t k) const { return twins_[navmesh_->edge_index(p, k)]; }

    // Heap bytes of the link index (the navmesh counts its own).
    size_t link_index_bytes() const;

    // Where a body (capabilities, area costs as a path request gives them) can go on this graph
    // (path/reachability.h): built on first use, shared by every body of its class. Throws only for
    // out-of-memory.
    std::shared_ptr<const ReachabilityMap> reachability(const AgentCapabilities& agent,
                                                        const std::vector<float>& area_costs) const {
        return reachability_.get(*this, agent, area_costs);
    }
    // The body's map when one is already built: what a path request asks, never paying for a build.
    std::shared_ptr<const ReachabilityMap> reachability_if_built(const AgentCapabilities& agent,
                                                                 const std::vector<float>& area_costs) const {
        return reachability_.ready(agent, area_costs);
    }
    size_t reachability_map_count() const { return reachability_.map_count(); }

private:
    void index_bends();
    void index_links();
    void index_appendices();

    std::shared_ptr<const NavMesh> navmesh_;
    std::shared_ptr<const LinkSnapshot> links_;
    std::shared_ptr<const SurfaceFrame> frame_;
    std::vector<uint32_t> first_exit_;  // polygon_count + 1 offsets into exits_; empty without links
    std::vector<LinkExit> exits_;
    std::array<uint64_t, 4> areas_present_{};
    std::vector<uint8_t> bends_;
    std::vector<uint8_t> twins_;  // per polygon edge
    // Per polygon: the polygon a peeled one hangs from, and the range of depth-first numbers of its
    // subtree (kNoPolygon for the polygons that stay); whether a link leaves from its subtree.
    std::vector<uint32_t> hangs_from_, subtree_first_, subtree_last_;
    std::vector<uint8_t> subtree_exits_;
    float cheapest_link_per_metre_ = 1.0f;
    bool has_cross_links_ = false;
    mutable ReachabilityCache reachability_;
};

}  // namespace nl
