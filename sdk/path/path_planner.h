// One path request from start to finish on one snapshot: snap the ends to the navmesh, search the
// corridor, pull the string through each walked stretch and put the links in between.
#pragma once

#include <atomic>

#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// Plans into `out` (its points' memory is reused), between world-space ends. Never throws for an
// unreachable goal or an end off the navmesh (the outcome says so); throws only for out-of-memory or
// an internal error. A set `cancel` makes the outcome Cancelled. On a navmesh that rides a moving
// mesh, the mesh's pose is read once: the search runs in its space, and each point is given at that
// pose in the world (position) and in the surface's space (carrier_position), where it stays.
void plan_path(const PathGraph& graph, const PathQuery& query, const std::atomic<bool>* cancel, PathResult& out);

// The same with the query's ends (and search box) and the result in the navmesh's own space: what
// agents on a surface plan with. On a navmesh that rides nothing it is plan_path.
void plan_path_in_carrier_space(const PathGraph& graph, const PathQuery& query, const std::atomic<bool>* cancel,
                                PathResult& out);

}  // namespace nl
