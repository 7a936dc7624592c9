// Wavefront OBJ to a triangle mesh, through Debian's tinyobjloader. Only positions and faces are
// read; polygons are fan-triangulated (v0, vi, vi+1), matching how the shared levels were authored.
#pragma once

#include <string>
#include <string_view>

#include "level/geometry.h"

namespace nl {

// Throws NotFound (cannot open), Parse (malformed, with tinyobjloader's message) or InvalidArgument
// (no faces). Indices are checked later, with everything else, by validate_mesh.
TriangleMesh read_obj_file(const std::string& path);
TriangleMesh read_obj_text(std::string_view text, const std::string& name = "<memory>");

}  // namespace nl
