// C structs the host or a plugin hands over, read into core types (shared by the entry points and
// the plugin adapter). Each throws nl::Error about the struct's fields, named without the struct's
// own name (the caller adds "def->" with nl::naming_fields).
#pragma once

#include <cstddef>

#include "navlink/navlink.h"
#include "navmesh/navmesh_builder.h"
#include "links/link.h"
#include "navmesh/carrier_pose.h"
#include "path/path_query.h"
#include "world/plugin.h"

namespace nl::capi {

AgentType to_core(const nl_agent_type& agent);
nl_agent_type to_c(const AgentType& agent);

// A host's progress callback as the core asks it: true to go on (always, when there is none).
inline auto progress_of(nl_progress_fn* progress, void* user) {
    return [progress, user](float fraction, const char* stage) {
        return !progress || progress(user, fraction, stage) != 0;
    };
}

// A navmesh def (nl_navmesh_add, a builder's sink), read whole; build_navmesh checks the rest.
NavMeshInput navmesh_input_from_def(const nl_navmesh_def& def);

// A build def (nl_navmesh_build, nl_navmesh_build_tiles), read whole over the defaults; its tile
// fields are the world's to set.
NavMeshBuildRequest build_request_from_def(const nl_navmesh_build_def& def);

// A link def (nl_link_add, nl_link_update, a link-kind plugin's sink); the link is not yet placed on
// a navmesh (World does that).
Link link_from_def(const nl_link_def& def);

// A point into a host's float[3].
inline void copy_point(float* out, const Vec3& v) { Eigen::Map<Vec3>{out} = v; }

// A navmesh point as the host reads it, in the world (the navmesh's pose applied).
nl_nav_point to_c(const NavPoint& point, const CarrierPose& pose);

// A body's capabilities and area costs as a path request or a query filter gives them, checked;
// failures name the fields after `prefix` ("def->", "filter->").
AgentCapabilities read_capabilities(const nl_agent_capabilities& agent, const char* prefix);
std::vector<float> read_area_costs(const float* costs, uint32_t count, const char* prefix);

// A path point as the host reads it (nl_path_get_points, nl_agent_get_corners).
nl_path_point to_c(const PathPoint& point);

}  // namespace nl::capi
