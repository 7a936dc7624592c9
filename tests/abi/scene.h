/*
 * Small builders of defs and levels that the ABI test programs share (navlink-abi-tests and
 * navlink-abi-hostile-test). Strict C11 through the C ABI only.
 */
#ifndef NAVLINK_ABI_SCENE_H
#define NAVLINK_ABI_SCENE_H

#include <navlink/navlink.h>

/* A mesh def over caller-owned arrays (borrowed, as the def says). */
nl_mesh_def mesh_def_of(const float* vertices, uint32_t vertex_count, const uint32_t* indices, uint32_t triangle_count);

/* A navmesh def over caller-owned arrays; `corners` may be NULL (triangles). */
nl_navmesh_def navmesh_def_of(const float* vertices, uint32_t vertex_count, const uint32_t* indices,
                              const uint8_t* corners, uint32_t polygon_count);

/* Gives a navmesh def its height detail: triangles over each polygon, polygon p's from starts[p]. */
void set_navmesh_detail(nl_navmesh_def* def, const float* vertices, uint32_t vertex_count, const uint32_t* triangles,
                        uint32_t triangle_count, const uint32_t* starts);

/* Registers the box from lo to hi: 8 corners (corner k at x from bit 0, y from bit 1, z from bit 2)
   and 12 triangles facing out. */
nl_status add_box_mesh(nl_world* world, const float lo[3], const float hi[3], uint32_t flags, nl_mesh_id* out_id);

#endif /* NAVLINK_ABI_SCENE_H */
