// The records of an OBJ text that NavLink reads, checked, in the form tinyobjloader is then given:
// tinyobjloader reads what it cannot parse as 0 and converts numbers with no range check, so it
// only ever sees text this check wrote.
#pragma once

#include <string>
#include <string_view>

namespace nl {

// An OBJ text of the vertex positions ("v x y z"), the faces as position indices ("f 1 2 3") and
// the object and group names of `text`, one '\n' per line. A line ends where tinyobjloader ends one
// (\n, \r\n or a lone \r); every other record (normals, texture coordinates, materials, weights...)
// is left out. Throws Parse naming `name` and the line for a position that is not three finite
// floats, a face of fewer than 3 corners, or a face index (position, texture or normal) that is not
// a whole number or points at nothing (0, before the first, past the last).
std::string checked_obj_records(std::string_view text, const std::string& name);

}  // namespace nl
