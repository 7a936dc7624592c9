#include "navmesh_export.h"

#include "build_failure.h"

namespace nl::recast {

NavMeshExport::NavMeshExport(const rcPolyMesh& pm, const rcPolyMeshDetail& dm, const TilePlace* tile) {
    // Vertices: grid coordinates to world space.
    vertices_.reserve(static_cast<size_t>(pm.nverts) * 3);
    if (tile) tile_ = *tile;
    for (int i = 0; i < pm.nverts; ++i) {
        const unsigned short* v = &pm.verts[i * 3];
        if (tile) {
            vertices_.push_back(static_cast<float>(tile->origin_x + double(tile->first_cell_x + v[0]) * pm.cs));
            vertices_.push_back(pm.bmin[1] + v[1] * pm.ch);
            vertices_.push_back(static_cast<float>(tile->origin_z + double(tile->first_cell_z + v[2]) * pm.cs));
        } else {
            vertices_.push_back(pm.bmin[0] + v[0] * pm.cs);
            vertices_.push_back(pm.bmin[1] + v[1] * pm.ch);
            vertices_.push_back(pm.bmin[2] + v[2] * pm.cs);
        }
    }

    // Polygons: nvp corners (padded with RC_MESH_NULL_IDX), then nvp neighbour entries, per polygon.
    const int nvp = pm.nvp;
    vertex_counts_.reserve(static_cast<size_t>(pm.npolys));
    areas_.reserve(static_cast<size_t>(pm.npolys));
    indices_.reserve(static_cast<size_t>(pm.npolys) * static_cast<size_t>(nvp));
    for (int p = 0; p < pm.npolys; ++p) {
        const unsigned short* poly = &pm.polys[p * 2 * nvp];
        int count = 0;
        while (count < nvp && poly[count] != RC_MESH_NULL_IDX) {
            indices_.push_back(poly[count]);
            ++count;
        }
        if (count < 3) fail(NL_STATUS_INTERNAL_ERROR, "Recast made polygon ", p, " with ", count, " corners");
        vertex_counts_.push_back(static_cast<uint8_t>(count));
        // NavLink's area a is Recast's a + 1 (recast_pipeline.h): Recast's 0 is "not walkable".
        areas_.push_back(static_cast<uint8_t>(pm.areas[p] - 1));
    }

    // Detail: per polygon, meshes[] = vertBase, vertCount, triBase, triCount; triangles have 3 indices
    // local to their polygon's vertices and a flags byte.
    if (dm.nmeshes != pm.npolys)
        fail(NL_STATUS_INTERNAL_ERROR, "Recast's detail mesh has ", dm.nmeshes, " sub-meshes for ", pm.npolys,
             " polygons");
    detail_vertices_.assign(dm.verts, dm.verts + static_cast<size_t>(dm.nverts) * 3);
    detail_triangles_.reserve(static_cast<size_t>(dm.ntris) * 3);
    detail_triangle_starts_.reserve(static_cast<size_t>(pm.npolys) + 1);
    for (int p = 0; p < dm.nmeshes; ++p) {
        const unsigned int* m = &dm.meshes[p * 4];
        const unsigned int vert_base = m[0], vert_count = m[1], tri_base = m[2], tri_count = m[3];
        if (size_t{vert_base} + vert_count > static_cast<size_t>(dm.nverts) ||
            size_t{tri_base} + tri_count > static_cast<size_t>(dm.ntris))
            fail(NL_STATUS_INTERNAL_ERROR, "Recast's detail sub-mesh ", p, " is out of range");
        detail_triangle_starts_.push_back(static_cast<uint32_t>(detail_triangles_.size() / 3));
        for (unsigned int t = tri_base; t < tri_base + tri_count; ++t) {
            const unsigned char* tri = &dm.tris[t * 4];
            for (int k = 0; k < 3; ++k) {
                if (tri[k] >= vert_count)
                    fail(NL_STATUS_INTERNAL_ERROR, "Recast's detail triangle ", t, " of polygon ", p,
                         " is out of range");
                detail_triangles_.push_back(vert_base + tri[k]);
            }
        }
    }
    detail_triangle_starts_.push_back(static_cast<uint32_t>(detail_triangles_.size() / 3));
}

nl_navmesh_def NavMeshExport::def(const nl_agent_type& agent) const {
    nl_navmesh_def d{};
    d.size = sizeof d;
    d.vertices = vertices_.data();
    d.vertex_count = static_cast<uint32_t>(vertices_.size() / 3);
    d.vertex_stride = 3 * sizeof(float);
    d.indices = indices_.data();
    d.polygon_vertex_counts = vertex_counts_.data();
    d.polygon_count = polygon_count();
    d.areas = areas_.data();
    d.weld_tolerance = 0.0f;  // Recast shares vertices between polygons already
    d.agent_type = agent;
    d.detail_vertices = detail_vertices_.data();
    d.detail_vertex_count = static_cast<uint32_t>(detail_vertices_.size() / 3);
    d.detail_triangles = detail_triangles_.data();
    d.detail_triangle_count = static_cast<uint32_t>(detail_triangles_.size() / 3);
    d.detail_triangle_starts = detail_triangle_starts_.data();
    d.tile_width = tile_.tile_width;
    d.tile_origin_x = static_cast<float>(tile_.origin_x);
    d.tile_origin_z = static_cast<float>(tile_.origin_z);
    d.tile_x = tile_.tile_x;
    d.tile_z = tile_.tile_z;
    return d;
}

}  // namespace nl::recast
