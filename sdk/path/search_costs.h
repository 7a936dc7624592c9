// What a body pays per metre, as both searches read it: the cheapest rate it can meet (which keeps
// a search's estimate below any real cost) and whether walking costs it the same everywhere it may go.
#pragma once

#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// The cheapest cost per metre this body can meet: the area costs it was given and the cost modifiers
// of the links it can take.
float heuristic_scale(const PathGraph& graph, const PathQuery& query);
// The least of `at_most` and the cost modifiers of the links this body can take.
float cheapest_link_rate(const PathGraph& graph, const PathQuery& query, float at_most);

// The cost per metre of walking when every area of the navmesh the body may enter costs it the same
// (the exact search's case); 0 when they differ.
float uniform_walk_cost(const PathGraph& graph, const PathQuery& query);
// The least cost per metre of the areas of the navmesh the body may enter (1 when it may enter none).
float cheapest_walk_cost(const PathGraph& graph, const PathQuery& query);

}  // namespace nl
