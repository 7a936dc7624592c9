// The exact search: the corridor of the shortest walk, seen from above, for one body, with its links.
// An any-angle search over intervals of polygon edges after Polyanya (Cui, Harabor and Grastien,
// IJCAI 2017): a node is the walks that leave a root point (the start, a corner the walk bends at,
// or where a link lands) in straight lines through an interval of an edge, and its estimate is the
// straight walk from the root through the interval to the goal. Extended with the links (graph edges
// from the point a link takes off to the point it lands, each a new root), the body's margin (a wider
// body crosses a portal only within portal_span's narrowed opening, and bends at its ends instead of
// the outline's corners) and its walking cost per metre. Optimal when walking costs the body the same
// everywhere it may go (uniform_walk_cost); areas of different costs are the corridor search's.
#pragma once

#include <atomic>

#include "path/polygon_astar.h"

namespace nl {

// Searches from `start` to `goal` (both located on graph's navmesh) into `out`, as find_corridor does
// (the same steps, so the funnel turns the corridor into the walk; `cost` is the walk's length seen
// from above times `walk_cost` plus the links' costs). `nodes_visited` counts polygons reached, against
// query.max_nodes; `search_nodes` the interval nodes made. A goal out of reach leaves `reached_goal`
// false and no steps (a partial path leads to the nearest point the body reaches: plan_path). Where
// the navmesh folds over itself seen from above (a neighbour on the same side of the edge it shares),
// views through edges mean nothing: the search may miss a way there, or give up (`gave_up`, past 256
// nodes per polygon it entered); the corridor search plans such paths. Uses per-thread scratch
// memory, as find_corridor.
void find_shortest_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start, const NavPoint& goal,
                            float walk_cost, const std::atomic<bool>* cancel, CorridorSearch& out);

}  // namespace nl
