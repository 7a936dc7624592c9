// Wavefront OBJ to a triangle mesh, through Debian's tinyobjloader. Only positions and faces are
// read; polygons are fan-triangulated (v0, vi, vi+1), matching how the shared levels were authored.
#pragma once

#include <string>
#include <string_view>

#include "level/geometry.h"

namespace nl {

// Wavefront OBJ records other than v, f, o and g are ignored; what is read is checked before
// tinyobjloader sees it (io/obj_records.h). Throws NotFound (no such file), Io (a directory, a file
// that cannot be opened or fails while it is read) or Parse (malformed: the line and the reason, or
// no faces). Degenerate triangles and coordinates are checked later, by validate_mesh.
TriangleMesh read_obj_file(const std::string& path);
TriangleMesh read_obj_text(std::string_view text, const std::string& name = "<memory>");

}  // namespace nl
