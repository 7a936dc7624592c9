// Whether a level looks given in other units than metres, or with z up (issue 33): a level exported
// in centimetres builds a navmesh of hundreds of islands and no links, one with z up a navmesh of a
// polygon or two, and both succeed: plausible wrong answers. Measured over the triangles whose mesh
// did not say its frame (MeshFrame), against the agent's body:
// - the walls' height: the median by area of the vertical extent of the triangles too steep to walk.
//   A level in metres has walls of about a body's height (0.85-5.3 m on the shared levels, for a
//   body of 2 m); in centimetres they are a hundred times that.
// - the level's width: a level narrower than its body is not in metres, or the body is not.
// - the floor a body could stand on with y up (as given) and with z up (estimate_winding's columns).
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"

namespace nl {

struct FrameEstimate {
    float wall_height = 0.0f;  // m; 0 when no triangle is too steep to walk
    float across = 0.0f;       // the larger horizontal side of the triangles' bounds, m
    float floor_y_up = 0.0f;   // m^2, seen from above
    float floor_z_up = 0.0f;   // m^2, with (x, y, z) read as (x, z, -y)
};

// Walls and width over `sized` (indices into mesh.triangles; obstacles included: they are walls
// too), floors over `floors` (walkable triangles only). When the level looks z up, its walls and
// width are measured with z up too.
FrameEstimate estimate_frame(const TriangleMesh& mesh, const std::vector<uint32_t>& sized,
                             const std::vector<uint32_t>& floors, float max_slope_degrees, float height);

// Walls more than 25 bodies tall: a tall building's walls in metres are a few storeys a triangle,
// centimetres make every wall a hundred bodies tall.
bool looks_larger_than_metres(const FrameEstimate& estimate, float height);
// The whole level narrower than two bodies are tall.
bool looks_smaller_than_metres(const FrameEstimate& estimate, float height);
// With z up the floor would be more than half as large again, and at least a square metre larger.
// Read with z up, a level's walls facing +z are floors where the room in front of them is deeper
// than a body is tall: the shared levels (y up) hold 0.16-1.0 times as much floor so; given with z
// up, they hold 1.8-40 times as much, or all of it (measured by frame_check_tests). A closed room
// or house measures alike both ways and is not told either way; a street between towers three
// times as tall as it is wide would be taken for z up.
bool looks_z_up(const FrameEstimate& estimate);

}  // namespace nl
