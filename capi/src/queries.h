// The world's queries as the C ABI defines them, for the nl_* entry points and for the function
// table plugins get (plugin_host.cpp), which must not record the host thread's last status. Each
// validates its arguments as its nl_* function documents and throws nl::Error.
#pragma once

#include <cstdint>

#include "navlink/navlink.h"
#include "world/world.h"

namespace nl::capi {

void cast_rays(const World& world, const nl_ray* rays, uint32_t count, nl_ray_hit* out_hits);
void segments_blocked(const World& world, const nl_segment* segments, uint32_t count, uint8_t* out_blocked);
void navmesh_get_info(const World& world, nl_navmesh_id navmesh, nl_navmesh_info* out_info);
void navmesh_get_boundary_edges(const World& world, nl_navmesh_id navmesh, nl_boundary_edge* out_edges,
                                uint32_t capacity, uint32_t* out_count);
void navmesh_find_nearest(const World& world, nl_navmesh_id navmesh, const float* points, uint32_t count,
                          const float* half_extents, nl_nav_point* out);

}  // namespace nl::capi
