// Why a path falls short of its goal (issue 33): no navigation library says why a path is missing,
// and a partial path that ends 54 m from the goal, where a drop of 4.2 m would have reached it for a
// body that drops 4 m, reads as a wrong answer. The request is planned again with one limit lifted at
// a time (the body's width, the excluded areas, what links the body can take); the first that
// reaches the goal is the reason, and a link on that path the body cannot take says which
// capability it lacks and by how much. Costs up to four more searches: asked for, never on the
// request's own path.
#pragma once

#include <cstdint>
#include <string>

#include "path/link_filter.h"
#include "path/path_graph.h"
#include "path/path_query.h"
#include "util/handle.h"

namespace nl {

enum class PathShortfall : uint32_t {
    None = 0,            // the path reaches the goal, or an end is off the navmesh (the outcome says so)
    OutOfNodes = 1,      // max_nodes stopped the search
    BodyTooWide = 2,     // a body of the navmesh's radius would get there: passages on the way are too narrow
    AreasExcluded = 3,   // areas the request keeps the body out of (cost 0) stand in the way
    LinkBeyondBody = 4,  // a link would get there, and the body cannot take it (`limit`)
    NoLinks = 5,         // the goal is on another island of the navmesh, and the navmesh has no links
    NotConnected = 6,    // no passage or link leads there, whatever the body could do
};

struct PathShortfallReport {
    PathShortfall why = PathShortfall::None;
    LinkLimit limit = LinkLimit::None;
    // LinkBeyondBody: what the link needs and what the body has (metres; the body's diameter against
    // the link's clearance for Width; the missing ability bits for Abilities). BodyTooWide: the body's
    // radius and the navmesh's.
    float needed = 0.0f, has = 0.0f;
    uint64_t missing_abilities = 0;
    Handle link;  // LinkBeyondBody
    LinkKind link_kind = LinkKind::Manual;
    bool reversed = false;           // taken from its end to its start
    Vec3 link_start = Vec3::Zero();  // where the body would take it (world)
    float navmesh_radius = 0.0f;     // the body the navmesh was built for: it leaves out passages narrower
};

// `result` is what `query` planned to on `graph` (plan_path).
PathShortfallReport explain_shortfall(const PathGraph& graph, const PathQuery& query, const PathResult& result);

// The report as a sentence for a person, naming the request's field to change ("" for None).
std::string describe(const PathShortfallReport& report, const PathQuery& query);

}  // namespace nl
