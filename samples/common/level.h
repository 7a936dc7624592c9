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

// Registers an OBJ file with nl_mesh_add_obj_file (its errors are the library's, with the line) with
// `mesh_flags` (NL_MESH_CLOCKWISE: its fronts are wound clockwise) and, when `for_drawing`, reads its
// triangles again to draw them (the C ABI does not give them back). Throws SampleError.
Level load_level_file(nl_world* world, const std::string& path, bool for_drawing, uint32_t mesh_flags = 0);

// Registers a generated level with nl_mesh_add. Throws SampleError.
Level add_generated_level(nl_world* world, const levelgen::GeneratedLevel& generated, const std::string& name);

}  // namespace nl::samples
