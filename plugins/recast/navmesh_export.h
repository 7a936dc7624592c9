// Recast's polygon and detail meshes in NavLink's navmesh form (nl_navmesh_def): world-space vertices,
// polygons as vertex runs with their counts, areas, and the detail mesh as flat triangles with
// polygon_count + 1 offsets. The arrays live here; the def borrows them.
#pragma once

#include <cstdint>
#include <vector>

#include <Recast.h>

#include "navlink/navlink.h"

namespace nl::recast {

class NavMeshExport {
public:
    // Throws INTERNAL_ERROR if the detail mesh does not match the polygon mesh.
    NavMeshExport(const rcPolyMesh& polygons, const rcPolyMeshDetail& detail);

    // Borrows this object's arrays: valid while it lives and is not moved.
    nl_navmesh_def def(const nl_agent_type& agent) const;

    uint32_t polygon_count() const { return static_cast<uint32_t>(vertex_counts_.size()); }

private:
    std::vector<float> vertices_;         // x y z per vertex, world space
    std::vector<uint32_t> indices_;       // polygon corners, polygon after polygon
    std::vector<uint8_t> vertex_counts_;  // corners per polygon
    std::vector<uint8_t> areas_;
    std::vector<float> detail_vertices_;            // x y z per detail vertex, world space
    std::vector<uint32_t> detail_triangles_;        // 3 absolute detail-vertex indices per triangle
    std::vector<uint32_t> detail_triangle_starts_;  // polygon_count + 1 offsets
};

}  // namespace nl::recast
