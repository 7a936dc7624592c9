// A planned path printed for people (a table of segments) or for programs (a JSON object). Links are
// named by their index in the navmesh's link list, which is their index in the LINKS.json file they
// were loaded from ("links"[i]): ids are only meaningful inside one run.
#pragma once

#include <navlink/navlink.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "path_plan.h"

namespace nl::cli {

// What was asked beside what was planned: the points given, and for an end off the navmesh, where
// the navmesh is nearest it (nothing within 1 km: unset).
// For a path that falls short of the goal, why (nl_path_explain). For a body wider than the
// navmesh's, its radius and the navmesh's.
struct AskedPath {
    float from[3];
    float to[3];
    std::optional<samples::NearestOnNavmesh> nearest_start;
    std::optional<samples::NearestOnNavmesh> nearest_goal;
    std::optional<nl_path_shortfall> shortfall;
    float body_radius = 0.0f;
    float navmesh_radius = 0.0f;
};

// Looks up the nearest navmesh points for the ends the plan found off the navmesh, and why a path
// that falls short does. Throws SampleError.
AskedPath asked_path(nl_world* world, nl_navmesh_id navmesh, const samples::PlannedPath& path, const float from[3],
                     const float to[3], const float search_half_extents[3], const nl_agent_capabilities& agent);

// The index of `link` in `links`, or -1.
long link_index(const std::vector<nl_link>& links, nl_link_id link);

void print_path_text(std::FILE* out, const samples::PlannedPath& path, const std::vector<nl_link>& links,
                     const AskedPath& asked);

std::string path_json(const samples::PlannedPath& path, const std::vector<nl_link>& links, const AskedPath& asked);

}  // namespace nl::cli
