// Edges that meet at a T-junction: one polygon's edge runs along two or more edges of its neighbours
// (a tile border of Recast's tiled pipeline or of Unity's exported triangulation), so no two edges share
// both vertices and the polygons would not connect. Each vertex that lies on such an edge (in x-z within
// `tolerance` of the edge's line, strictly between its ends, and within `tolerance` of its height there)
// is inserted into it as a straight corner, so that the edges match pairwise and every query keeps one
// neighbour per edge.
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

// Inserts, into the edges no other edge matches, the vertices of other such edges that lie on them.
// Only the ends of unmatched edges are candidates: a vertex inside other polygons is never one.
JoinedPolygons join_t_junctions(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& first_corner,
                                const std::vector<uint32_t>& corners, float tolerance, uint32_t max_corners);

}  // namespace nl
