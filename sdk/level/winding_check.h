// Whether a mesh looks wound the wrong way round for walking on (issue 33): a level exported with
// clockwise fronts (Godot's convention) without NL_MESH_CLOCKWISE builds a navmesh on the undersides
// of its boxes, a plausible wrong answer. Per mesh, looking straight down on a grid of columns, the
// floor a body of the agent's height could stand on is measured as given and as it would be turned
// over: a floor is a surface within the walkable slope facing up (turned over: facing down) with
// the agent's height free above it up to the next surface of the mesh. A mesh whose floor turned over
// is much larger than as given looks turned over. A room seen from inside (its floor facing up, its
// ceiling down) measures alike both ways and is not taken for one.
#pragma once

#include <cstdint>

#include "level/geometry.h"

namespace nl {

struct WindingEstimate {
    float floor_as_given = 0.0f;     // m^2 of floor, seen from above
    float floor_turned_over = 0.0f;  // m^2 of floor with every triangle turned over
};

// Over triangles[first, first + count) of `mesh` (world space, y up), for a body `height` tall that
// walks slopes up to `max_slope_degrees`. Columns are at most kWindingColumns a side over the run's
// extent, and at least 10 cm apart.
constexpr uint32_t kWindingColumns = 128;
WindingEstimate estimate_winding(const TriangleMesh& mesh, size_t first, size_t count, float max_slope_degrees,
                                 float height);

// The least y of a unit normal facing up within `max_slope_degrees`: a floor's.
float walkable_normal_y(float max_slope_degrees);

// Turned over, the floor would be more than twice as large, and at least a square metre larger.
bool looks_turned_over(const WindingEstimate& estimate);

}  // namespace nl
