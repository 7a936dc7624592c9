// One path request from start to finish on one snapshot: snap the ends to the navmesh, search the
// corridor, pull the string through each walked stretch and put the links in between.
#pragma once

#include <atomic>

#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// Plans into `out` (its points' memory is reused). Never throws for an unreachable goal or an end off
// the navmesh (the outcome says so); throws only for out-of-memory or an internal error. A set
// `cancel` makes the outcome Cancelled.
void plan_path(const PathGraph& graph, const PathQuery& query, const std::atomic<bool>* cancel, PathResult& out);

}  // namespace nl
