/* The builders of scene.h. */
#include "scene.h"

nl_mesh_def mesh_def_of(const float* vertices, uint32_t vertex_count, const uint32_t* indices,
                        uint32_t triangle_count) {
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = vertices;
    def.vertex_count = vertex_count;
    def.indices = indices;
    def.triangle_count = triangle_count;
    return def;
}

nl_navmesh_def navmesh_def_of(const float* vertices, uint32_t vertex_count, const uint32_t* indices,
                              const uint8_t* corners, uint32_t polygon_count) {
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = vertices;
    def.vertex_count = vertex_count;
    def.indices = indices;
    def.polygon_vertex_counts = corners;
    def.polygon_count = polygon_count;
    return def;
}

void set_navmesh_detail(nl_navmesh_def* def, const float* vertices, uint32_t vertex_count, const uint32_t* triangles,
                        uint32_t triangle_count, const uint32_t* starts) {
    def->detail_vertices = vertices;
    def->detail_vertex_count = vertex_count;
    def->detail_triangles = triangles;
    def->detail_triangle_count = triangle_count;
    def->detail_triangle_starts = starts;
}

nl_status add_box_mesh(nl_world* world, const float lo[3], const float hi[3], uint32_t flags, nl_mesh_id* out_id) {
    const float v[24] = {lo[0], lo[1], lo[2], hi[0], lo[1], lo[2], lo[0], hi[1], lo[2], hi[0], hi[1], lo[2],
                         lo[0], lo[1], hi[2], hi[0], lo[1], hi[2], lo[0], hi[1], hi[2], hi[0], hi[1], hi[2]};
    static const uint32_t box[36] = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                     2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    nl_mesh_def def = mesh_def_of(v, 8, box, 12);
    def.flags = flags;
    return nl_mesh_add(world, &def, out_id);
}
