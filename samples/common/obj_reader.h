// A small Wavefront OBJ reader: positions and polygonal faces, nothing else. The samples use it for
// what the C ABI does not give back (the level's triangles to draw them) and for navmeshes handed
// over as OBJ files (nl_navmesh_add takes polygons, not a file). Level geometry itself is registered
// with nl_mesh_add_obj_file, whose errors are the library's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nl::samples {

struct ObjPolygons {
    std::vector<float> positions;        // x y z per vertex
    std::vector<uint32_t> indices;       // corners, polygon after polygon (0-based)
    std::vector<uint8_t> corner_counts;  // corners of each polygon

    uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size() / 3); }
    uint32_t polygon_count() const { return static_cast<uint32_t>(corner_counts.size()); }
    // The polygons as a triangle fan each: 3 indices per triangle.
    std::vector<uint32_t> fan_triangles() const;
};

// Parses OBJ text (`name` is used in error messages). Faces may use v, v/vt, v//vn, v/vt/vn and
// negative (relative) indices. Throws SampleError naming the line for a malformed vertex or face,
// a face with more than `max_corners` corners, or no faces at all.
ObjPolygons parse_obj(const std::string& text, const std::string& name, uint32_t max_corners = 255);

// Reads and parses a file; throws SampleError for a missing file too.
ObjPolygons read_obj_file(const std::string& path, uint32_t max_corners = 255);

}  // namespace nl::samples
