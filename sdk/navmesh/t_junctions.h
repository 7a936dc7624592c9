// Edges that meet at a T-junction: one polygon's edge runs along two or more edges of its neighbours
// (a tile border of Recast's tiled pipeline or of Unity's exported triangulation), so no two edges share
// both vertices and the polygons would not connect. Each vertex that lies on such an edge (in x-z within
// a tolerance of the edge's line, strictly between its ends, and within a tolerance of its height there)
// is inserted into it as a corner, so that the edges match pairwise and every query keeps one neighbour
// per edge.
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"

namespace nl {

// The polygons' corners with the inserted ones, and where each old corner went: meaningful only when
// `inserted` is not 0 (otherwise the polygons stay as they are, and the lists may be left empty).
struct JoinedPolygons {
    std::vector<uint32_t> first_corner;  // polygon_count + 1 offsets into corners
    std::vector<uint32_t> corners;
    // By old corner slot (the input's first_corner[p] + k): its index within its polygon now.
    std::vector<uint8_t> moved_corner;
    uint32_t inserted = 0;   // corners inserted
    uint32_t left_open = 0;  // edges left unjoined: their polygon would have had more than `max_corners`
};

// How near a vertex must be to an edge to become its corner.
struct TJunctionTolerance {
    // In x-z from the edge's line and in height from it, for any edge and vertex; 0: none but those
    // on tile borders are joined.
    float anywhere = 0.0f;
    // Per vertex, 1 on a line between two tiles (tile_join.h); empty: none is.
    const std::vector<uint8_t>* on_tile_border = nullptr;
    // For an edge and a vertex all on tile borders: in x-z, and in height, where two tiles' surfaces
    // may differ by a voxel or two (each tile was voxelised on its own).
    float tile_border = 0.0f;
    float tile_border_height = 0.0f;
};

// Inserts, into the edges no other edge matches, the vertices of other such edges that lie on them.
// Only the ends of unmatched edges are candidates: a vertex inside other polygons is never one.
JoinedPolygons join_t_junctions(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& first_corner,
                                const std::vector<uint32_t>& corners, const TJunctionTolerance& tolerance,
                                uint32_t max_corners);

}  // namespace nl
