// One path planned now (nl_path_find) and what it is made of: the points as the library returns
// them, and the segments between them (walk, jump, drop, ...) with their lengths.
#pragma once

#include <navlink/navlink.h>

#include <string>
#include <optional>
#include <vector>

namespace nl::samples {

struct PlannedPath {
    nl_path_result result{};
    std::vector<nl_path_point> points;
};

struct PathSegment {
    nl_segment_kind kind;  // NL_SEGMENT_WALK or the link's kind
    const nl_path_point* from;
    const nl_path_point* to;
    float length;  // straight distance between the two points
};

// Plans from `start` to `goal` for `agent`. Throws SampleError if the call fails (not when the
// search finds no path: read result.outcome).
PlannedPath find_path(nl_world* world, nl_navmesh_id navmesh, const float start[3], const float goal[3],
                      const nl_agent_capabilities& agent, const float* search_half_extents = nullptr);

// The request the samples make: default costs, the given agent, and the default search box unless
// `search_half_extents` is given.
nl_path_request_def path_request(nl_navmesh_id navmesh, const float start[3], const float goal[3],
                                 const nl_agent_capabilities& agent, const float* search_half_extents = nullptr);

// Where the navmesh is nearest `point`, within `half_extents` or, when nothing is, beyond it (the
// library's answer for a miss, nl_nav_point.beyond_box): for saying how far off the navmesh a start
// or goal is.
struct NearestOnNavmesh {
    float point[3];
    float distance;
};
std::optional<NearestOnNavmesh> nearest_on_navmesh(const nl_world* world, nl_navmesh_id navmesh, const float point[3],
                                                   const float half_extents[3]);

// The result of a finished queued request (nl_path_get_result, two calls when the path is long).
// The ticket stays valid: release it with nl_path_release. Throws SampleError.
PlannedPath queued_result(const nl_world* world, nl_path_ticket ticket);

std::vector<PathSegment> path_segments(const PlannedPath& path);

// "complete", "partial", "no path", "start off navmesh", ...
const char* outcome_name(nl_path_outcome outcome);
// "walk", "jump", "drop", "manual", "plugin"
const char* segment_name(nl_segment_kind kind);

// The links a path takes, counted by kind.
struct LinkCounts {
    uint32_t jumps = 0, drops = 0, manual = 0, plugin = 0;
};
LinkCounts count_links(const PlannedPath& path);
LinkCounts count_links(const std::vector<nl_path_point>& points);
// Adds one segment of `kind` (walking adds nothing).
void count_link(LinkCounts& counts, nl_segment_kind kind);

// "2 jumps, 1 drop, 1 manual link" (or "no links").
std::string describe_links(const LinkCounts& counts);

}  // namespace nl::samples
