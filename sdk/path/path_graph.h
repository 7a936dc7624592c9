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
#include "navmesh/carrier_pose.h"
#include "path/reachability_cache.h"

namespace nl {

// A way out of a polygon over a link: link index in the snapshot, and which way it is taken.
struct LinkExit {
    uint32_t link;
    uint32_t reversed;  // 1: from the link's end to its start
};

// What the exact search (any_angle_search.h) reads of a navmesh alone, whatever its links: built
// once per navmesh and shared by the path graphs of its link snapshots. Immutable.
class NavMeshSearchIndex {
public:
    explicit NavMeshSearchIndex(std::shared_ptr<const NavMesh> navmesh);

    const NavMesh& navmesh() const { return *navmesh_; }
    // Bit a set for each area some polygon of the navmesh has.
    const std::array<uint64_t, 4>& areas_present() const { return areas_present_; }
    // Whether a shortest walk may bend at vertex v: a reflex corner of an obstacle for some body (the
    // polygons round it fill more than half a turn seen from above). For every body the outline's
    // vertices and those where areas meet (an area a body keeps out of is an obstacle to it); for a
    // body wider than the navmesh's agent also the far ends of portals from the outline (its width
    // may close such a portal, which then stands as a wall ending there).
    bool may_bend_at(uint32_t v, bool wider_body) const { return (bends_[v] & (wider_body ? 3u : 1u)) != 0; }
    // The edge of polygon p's neighbour across edge k that leads back to p (the same edge seen from
    // the other side), or kNoTwin for an edge without neighbour.
    static constexpr uint8_t kNoTwin = 0xff;
    uint8_t twin_edge(uint32_t p, uint32_t k) const { return twins_[navmesh_->edge_index(p, k)]; }

    // Dead ends: polygons with one way on at most are peeled, again and again; what goes is trees
    // of polygons hanging from the rest, each from the neighbour it had left (hangs_from), numbered
    // depth first so that a subtree is one range of numbers. peel_order lists the peeled polygons,
    // each after those that hang from it.
    uint32_t hangs_from(uint32_t p) const { return hangs_from_[p]; }
    bool peeled(uint32_t p) const { return subtree_first_[p] != kNoPolygon; }
    // Whether polygon p lies in the subtree of peeled polygon `top`.
    bool in_subtree(uint32_t p, uint32_t top) const {
        return peeled(p) && subtree_first_[p] >= subtree_first_[top] && subtree_first_[p] <= subtree_last_[top];
    }
    const std::vector<uint32_t>& peel_order() const { return peel_order_; }
    // Heap bytes held.
    size_t memory_bytes() const;

private:
    void index_bends();
    void index_appendices();

    std::shared_ptr<const NavMesh> navmesh_;
    std::array<uint64_t, 4> areas_present_{};
    std::vector<uint8_t> bends_;  // per vertex: 1 any body may bend there, 2 a wider body may
    std::vector<uint8_t> twins_;  // per polygon edge
    // Per polygon: the polygon a peeled one hangs from, and the range of depth-first numbers of its
    // subtree (kNoPolygon for the polygons that stay).
    std::vector<uint32_t> hangs_from_, subtree_first_, subtree_last_;
    std::vector<uint32_t> peel_order_;
};

class PathGraph {
public:
    // `frame`: the movable mesh the navmesh rides (null: it stays where it is). The navmesh and the
    // links are in its space; searches run there.
    // `index`: the navmesh's search index from an earlier graph of it, so that a link edit does not
    // build it again (null, or another navmesh's: built here).
    PathGraph(std::shared_ptr<const NavMesh> navmesh, std::shared_ptr<const LinkSnapshot> links,
              std::shared_ptr<const CarrierFrame> frame = nullptr,
              std::shared_ptr<const NavMeshSearchIndex> index = nullptr);

    const NavMesh& navmesh() const { return *navmesh_; }
    const std::shared_ptr<const NavMesh>& navmesh_ptr() const { return navmesh_; }
    const LinkSnapshot& links() const { return *links_; }
    const std::shared_ptr<const LinkSnapshot>& links_ptr() const { return links_; }
    const StoredLink& link(uint32_t index) const { return (*links_)[index]; }
    const std::shared_ptr<const CarrierFrame>& frame() const { return frame_; }
    // Whether any of its links leads to another navmesh (Link::crosses; not in the exits).
    bool has_cross_links() const { return has_cross_links_; }

    // The enabled links leaving polygon p, as [begin, end).
    const LinkExit* exits_begin(uint32_t p) const { return first_exit_.empty() ? nullptr : &exits_[first_exit_[p]]; }
    const LinkExit* exits_end(uint32_t p) const { return first_exit_.empty() ? nullptr : &exits_[first_exit_[p + 1]]; }

    // The smallest cost per metre a link offers (its cost modifier), so the heuristic stays below
    // any real cost; 1 without links.
    float cheapest_link_per_metre() const { return cheapest_link_per_metre_; }

    // What the exact search reads of the navmesh alone (NavMeshSearchIndex).
    const NavMeshSearchIndex& search_index() const { return *index_; }
    const std::shared_ptr<const NavMeshSearchIndex>& search_index_ptr() const { return index_; }
    const std::array<uint64_t, 4>& areas_present() const { return index_->areas_present(); }
    bool may_bend_at(uint32_t v, bool wider_body) const { return index_->may_bend_at(v, wider_body); }
    uint8_t twin_edge(uint32_t p, uint32_t k) const { return index_->twin_edge(p, k); }
    static constexpr uint8_t kNoTwin = NavMeshSearchIndex::kNoTwin;

    // Whether a walk stepping from polygon `from` into its neighbour `into` goes down a dead end: a
    // tree of polygons hanging from the rest of the navmesh (NavMeshSearchIndex), entered from its
    // stem, that holds neither `goal` nor a link's way out. Such a walk can only come back the way it
    // went.
    bool dead_end(uint32_t from, uint32_t into, uint32_t goal) const {
        return index_->hangs_from(into) == from && !index_->in_subtree(goal, into) && subtree_exits_[into] == 0;
    }

    // Heap bytes of the link index (the navmesh counts its own).
    size_t link_index_bytes() const;
    // Heap bytes of what the exact search reads besides the navmesh and links: the navmesh's search
    // index (shared by its graphs) and which dead-end trees a link leaves from.
    size_t search_index_bytes() const;

    // Where a body (capabilities, area costs as a path request gives them) can go on this graph
    // (path/reachability.h): built on first use, shared by every body of its class. Throws only for
    // out-of-memory.
    std::shared_ptr<const ReachabilityMap> reachability(const AgentCapabilities& agent,
                                                        const std::vector<float>& area_costs) const {
        return reachability_.get(*this, agent, area_costs);
    }
    // The body's map when one is already built: what a path request asks, never paying for a build.
    // Valid until this thread asks again (ReachabilityCache::ready).
    const ReachabilityMap* reachability_if_built(const AgentCapabilities& agent,
                                                 const std::vector<float>& area_costs) const {
        return reachability_.ready(agent, area_costs);
    }
    size_t reachability_map_count() const { return reachability_.map_count(); }

private:
    void index_links();
    void mark_subtree_exits();

    std::shared_ptr<const NavMesh> navmesh_;
    std::shared_ptr<const LinkSnapshot> links_;
    std::shared_ptr<const CarrierFrame> frame_;
    std::shared_ptr<const NavMeshSearchIndex> index_;
    std::vector<uint32_t> first_exit_;  // polygon_count + 1 offsets into exits_; empty without links
    std::vector<LinkExit> exits_;
    std::vector<uint8_t> subtree_exits_;  // per polygon: a link leaves from its dead-end subtree
    float cheapest_link_per_metre_ = 1.0f;
    bool has_cross_links_ = false;
    mutable ReachabilityCache reachability_;
};

}  // namespace nl
