// The size each output or input struct had in the release that gave it its `size` field (0.2, or the
// release that introduced the struct): a caller's `size` must be at least this, and the library reads and
// writes no byte past the caller's `size`. Never changes when fields are appended: a field added to a
// struct in the header goes after it (docs/c-api.md, "Structs that grow").
#pragma once

#include <cstddef>
#include <cstdint>

#include "navlink/navlink.h"

namespace nl::capi {

// Listed below for every struct read or written with a size; any other is a compile error.
template <typename T>
inline constexpr size_t kFirstSize = sizeof(typename T::not_listed_in_first_sizes_h);

template <>
inline constexpr size_t kFirstSize<nl_agent_def> = offsetof(nl_agent_def, give_up_seconds);
template <>
inline constexpr size_t kFirstSize<nl_agent_event> = sizeof(nl_agent_event);
template <>
inline constexpr size_t kFirstSize<nl_agent_info> = offsetof(nl_agent_info, user_data) + sizeof(uint64_t);
template <>
inline constexpr size_t kFirstSize<nl_agent_trajectory> = sizeof(nl_agent_trajectory);
template <>
inline constexpr size_t kFirstSize<nl_link> = offsetof(nl_link, requirements) + sizeof(nl_link_requirements);
template <>
inline constexpr size_t kFirstSize<nl_link_def> = offsetof(nl_link_def, requirements) +
                                                  offsetof(nl_link_requirements, length);
template <>
inline constexpr size_t kFirstSize<nl_link_generation_report> = offsetof(nl_link_generation_report,
                                                                         milliseconds_total) +
                                                                sizeof(double);
template <>
inline constexpr size_t kFirstSize<nl_link_settings> = offsetof(nl_link_settings, plugin_settings_json_length) +
                                                       sizeof(size_t);
template <>
inline constexpr size_t kFirstSize<nl_mesh_def> = offsetof(nl_mesh_def, user_data) + sizeof(uint64_t);
template <>
inline constexpr size_t kFirstSize<nl_mesh_info> = offsetof(nl_mesh_info, user_data) + sizeof(uint64_t);
template <>
inline constexpr size_t kFirstSize<nl_nav_polygon> = sizeof(nl_nav_polygon);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_build_def> = offsetof(nl_navmesh_build_def, settings_json_length) +
                                                           sizeof(size_t);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_def> = offsetof(nl_navmesh_def, detail_triangle_starts) +
                                                     sizeof(const uint32_t*);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_file_info> = offsetof(nl_navmesh_file_info, level_hash) +
                                                           sizeof(uint64_t);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_info> = offsetof(nl_navmesh_info, bounds_max) + 3 * sizeof(float);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_load_def> = sizeof(nl_navmesh_load_def);
template <>
inline constexpr size_t kFirstSize<nl_navmesh_raycast_hit> = sizeof(nl_navmesh_raycast_hit);
template <>
inline constexpr size_t kFirstSize<nl_path_budget> = sizeof(nl_path_budget);
template <>
inline constexpr size_t kFirstSize<nl_path_finished> = sizeof(nl_path_finished);
template <>
inline constexpr size_t kFirstSize<nl_path_point> = offsetof(nl_path_point, reserved) + 3;
template <>
inline constexpr size_t kFirstSize<nl_path_queue_stats> = offsetof(nl_path_queue_stats, finished) + sizeof(uint64_t);
template <>
inline constexpr size_t kFirstSize<nl_path_request_def> = offsetof(nl_path_request_def, user) + sizeof(void*);
template <>
inline constexpr size_t kFirstSize<nl_path_result> = offsetof(nl_path_result, goal) + 3 * sizeof(float);
template <>
inline constexpr size_t kFirstSize<nl_plugin_description> = offsetof(nl_plugin_description, description) +
                                                            sizeof(const char*);
template <>
inline constexpr size_t kFirstSize<nl_query_filter> = sizeof(nl_query_filter);
template <>
inline constexpr size_t kFirstSize<nl_random_points_def> = sizeof(nl_random_points_def);
template <>
inline constexpr size_t kFirstSize<nl_ray_hit> = sizeof(nl_ray_hit);
template <>
inline constexpr size_t kFirstSize<nl_world_def> = offsetof(nl_world_def, log_level) + sizeof(nl_log_level);

}  // namespace nl::capi
