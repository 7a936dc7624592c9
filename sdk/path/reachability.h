// Where a body can go on one navmesh and its links: the polygons split into islands (strongly
// connected: from any polygon of an island the body reaches every other by walking and by the links
// it can take), ordered by the one-way links between them. Answers "can this body get from here to
// there" without a search, exactly as the path search would (the same open portals, excluded areas
// and links), and lists everything reachable from a polygon.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// What decides where a body can go, as the search reads it: the portals its width closes (those
// that leave it no room, as portal_span decides for its margin over the navmesh's agent), the areas
// it keeps out of (cost 0) and the link directions it can take. Bodies with equal classes share one
// map: bodies of slightly different widths that close the same portals too.
struct ReachabilityClass {
    std::vector<uint64_t> closed_portals;      // bit NavMesh::edge_index(p, k); empty when none is closed
    std::array<uint64_t, 4> excluded_areas{};  // bit a: area a is kept out of
    std::vector<uint64_t> takeable;            // bit 2 * link + reversed, for the graph's links

    static ReachabilityClass of(const PathGraph& graph, const AgentCapabilities& agent,
                                const std::vector<float>& area_costs);
    // Bit a set for each area whose cost is 0 (or below: the C layer refuses those).
    static std::array<uint64_t, 4> excluded_areas_of(const std::vector<float>& area_costs);
    bool excludes(uint8_t area) const { return area_excluded(excluded_areas, area); }
    static bool area_excluded(const std::array<uint64_t, 4>& mask, uint8_t area) {
        return (mask[area >> 6] >> (area & 63)) & 1u;
    }
    bool closes(uint32_t edge) const {
        return !closed_portals.empty() && ((closed_portals[edge >> 6] >> (edge & 63)) & 1u);
    }
    bool can_take(uint32_t link, bool reversed) const {
        const uint32_t bit = 2 * link + (reversed ? 1u : 0u);
        return (takeable[bit >> 6] >> (bit & 63)) & 1u;
    }
    bool operator==(const ReachabilityClass& other) const {
        return closed_portals == other.closed_portals && excluded_areas == other.excluded_areas &&
               takeable == other.takeable;
    }
};

class ReachabilityMap {
public:
    static constexpr uint32_t kNoIsland = 0xffffffffu;

    // Linear in polygons, portals and links, plus the closure below.
    ReachabilityMap(const PathGraph& graph, const ReachabilityClass& body);

    // Whether a path for the body leads from polygon `from` to polygon `to` (a polygon reaches
    // itself). A polygon in an excluded area is reachable from nowhere else; a body standing in one
    // can still walk or jump out of it, as a search starting there would.
    bool reaches(uint32_t from, uint32_t to) const;
    // Every polygon reachable from `from` (itself included), in ascending order, into `out`.
    void reachable_polygons(uint32_t from, std::vector<uint32_t>& out) const;
    // The islands reachable from `from` (1 each), sized island_count(): one walk of the island
    // graph for asking about many polygons (an excluded `from` itself has no island: ask for it apart).
    void reachable_islands(uint32_t from, std::vector<uint8_t>& out) const;
    // The island a polygon belongs to, or kNoIsland for one in an excluded area. Islands are numbered
    // from 0 in order of their lowest polygon.
    uint32_t island(uint32_t polygon) const { return island_of_[polygon]; }
    // An island's polygons, ascending, as [begin, end).
    const uint32_t* island_begin(uint32_t island) const { return polygons_.data() + first_polygon_[island]; }
    const uint32_t* island_end(uint32_t island) const { return polygons_.data() + first_polygon_[island + 1]; }
    uint32_t island_count() const { return island_count_; }
    // Whether island-to-island questions read a precomputed closure (true unless the links join more
    // islands than kMaxClosureIslands; then each question walks the island graph: linear in the
    // islands and their links, not constant).
    bool has_closure() const { return closure_width_ != 0 || linked_count_ == 0; }
    size_t memory_bytes() const;

    // Islands joined by links beyond this many are answered by a walk over the island graph
    // instead of a closure of kMaxClosureIslands^2 bits (8 MiB).
    static constexpr uint32_t kMaxClosureIslands = 8192;

private:
    bool island_reaches(uint32_t from, uint32_t to) const;
    // Marks every island reachable from the `count` islands at `from` in `reached` (sized island_count()).
    void mark_reachable(const uint32_t* from, size_t count, std::vector<uint8_t>& reached) const;
    // The islands a polygon in an excluded area leads into, as [begin, end).
    const uint32_t* exits_begin(uint32_t polygon) const;
    const uint32_t* exits_end(uint32_t polygon) const;

    uint32_t island_count_ = 0;
    std::vector<uint32_t> island_of_;        // per polygon
    std::vector<uint32_t> first_polygon_;    // island_count + 1 offsets into polygons_
    std::vector<uint32_t> polygons_;         // by island, ascending within each
    std::vector<uint32_t> first_successor_;  // island_count + 1 offsets into successors_ (the DAG)
    std::vector<uint32_t> successors_;
    std::vector<uint32_t> excluded_index_;  // per polygon: its row in first_exit_, or kNoIsland
    std::vector<uint32_t> first_exit_;      // for excluded polygons: offsets into exits_
    std::vector<uint32_t> exits_;           // islands
    uint32_t linked_count_ = 0;             // islands with a link to or from another
    std::vector<uint32_t> closure_row_;     // per island: its closure row, or kNoIsland
    uint32_t closure_width_ = 0;            // 64-bit words per row
    std::vector<uint64_t> closure_;
};

}  // namespace nl
