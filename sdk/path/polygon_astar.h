// A* over polygons and links: finds the corridor (the polygons to walk through and the links to
// take) from the start polygon to the goal polygon, for one agent's body and costs.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "navmesh/navmesh.h"
#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// One polygon of a corridor and how it was entered from the previous one.
struct CorridorStep {
    static constexpr uint32_t kStart = 0xffffffffu;
    static constexpr uint32_t kLinkBit = 0x80000000u;
    static constexpr uint32_t kReversedBit = 0x40000000u;

    uint32_t polygon;
    uint32_t entry;  // kStart; an edge index of the previous polygon; or kLinkBit | link index (| kReversedBit)

    bool by_link() const { return entry != kStart && (entry & kLinkBit) != 0; }
    uint32_t link() const { return entry & ~(kLinkBit | kReversedBit); }
    bool reversed() const { return (entry & kReversedBit) != 0; }
    uint32_t edge() const { return entry; }
};

struct CorridorSearch {
    std::vector<CorridorStep> steps;  // start polygon first
    bool reached_goal = false;
    bool out_of_nodes = false;
    bool cancelled = false;
    bool gave_up = false;  // the exact search stopped: its views could not be trusted (any_angle_search.h)
    uint32_t nodes_visited = 0;
    uint32_t search_nodes = 0;  // the exact search's interval nodes (several per polygon); 0 for A*
    float cost = 0.0f;          // the search's own: to the goal point, or to where it entered its last polygon
};

// How often a search looks at its cancel flag: a power of two, in expansions.
constexpr uint32_t kCancelCheckExpansions = 64;

// Searches from `start` to `goal` (both located on graph's navmesh) into `out`, whose steps' memory
// is reused. A set `cancel` stops the search within kCancelCheckExpansions expansions. Uses per-thread scratch memory:
// no allocation after a thread's first searches on a navmesh of this size.
void find_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start, const NavPoint& goal,
                   const std::atomic<bool>* cancel, CorridorSearch& out);

}  // namespace nl
