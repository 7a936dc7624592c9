// A level registered in a world, with its triangles kept for drawing (the C ABI holds the geometry
// but does not hand it back).
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <string>
#include <vector>

#include "level_generator.h"

namespace nl::samples {

struct Level {
    std::string name;                       // the file, or "generated default level (seed N)"
    std::vector<float> positions;           // x y z per vertex; empty unless read for drawing
    std::vector<uint32_t> triangles;        // 3 indices per triangle
    std::vector<levelgen::Marker> markers;  // a generated level's named points
    nl_mesh_id mesh{};
    nl_mesh_info info{};

    uint32_t triangle_count() const { return static_cast<uint32_t>(triangles.size() / 3); }
};

// How a level file is given, as nl_mesh_def says it: its winding (NL_MESH_CLOCKWISE in `flags`), the
// metres per unit of its numbers (0: not said) and its up axis (NL_UP_AXIS_*).
struct LevelFrame {
    uint32_t flags = 0;
    float metres_per_unit = 0.0f;
    uint32_t up_axis = NL_UP_AXIS_NOT_SAID;
};

// Registers an OBJ file with nl_mesh_add_obj_file (its errors are the library's, with the line) as
// `frame` says it is given and, when `for_drawing`, reads its triangles again to draw them (the C ABI
// does not give them back), brought into NavLink's metres with y up as the library brings them.
// Throws SampleError.
Level load_level_file(nl_world* world, const std::string& path, bool for_drawing, const LevelFrame& frame = {});

// Registers a generated level with nl_mesh_add. Throws SampleError.
Level add_generated_level(nl_world* world, const levelgen::GeneratedLevel& generated, const std::string& name);

}  // namespace nl::samples
