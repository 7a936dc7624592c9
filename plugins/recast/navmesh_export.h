// Recast's polygon and detail meshes in NavLink's navmesh form (nl_navmesh_def): world-space vertices,
// polygons as vertex runs with their counts, areas, and the detail mesh as flat triangles with
// polygon_count + 1 offsets. The arrays live here; the def borrows them.
#pragma once

#include <cstdint>
#include <vector>

#include <Recast.h>

#include "navlink/navlink.h"

namespace nl::recast {

// Where a tile's polygon mesh lies on the level's grid of cells: its vertices are placed from the
// level's origin and their cell counted from it, so that two tiles place a corner they share on the
// line between them at the very same x and z.
struct TilePlace {
    double origin_x = 0.0;  // the level's lower corner: tile (0, 0)'s
    double origin_z = 0.0;
    int64_t first_cell_x = 0;  // the tile's first cell, counted from the origin
    int64_t first_cell_z = 0;
    float tile_width = 0.0f;  // tile_size cells, metres
    int32_t tile_x = 0;
    int32_t tile_z = 0;
};

class NavMeshExport {
public:
    // Throws INTERNAL_ERROR if the detail mesh does not match the polygon mesh. With `tile`, the
    // vertices are placed on the level's grid and the def describes the tile.
    NavMeshExport(const rcPolyMesh& polygons, const rcPolyMeshDetail& detail, const TilePlace* tile = nullptr);

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
    TilePlace tile_;                                // tile_width 0: a solo mesh
};

}  // namespace nl::recast
