// Baked navmesh files (nl_navmesh_save_file, nl_navmesh_load_file, nl_navmesh_file_describe) for
// the sample programs.
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

// Writes the navmesh and its links to `path`. Throws SampleError.
void save_navmesh_file(nl_world* world, nl_navmesh_id navmesh, const std::string& path);
// Adds the navmesh a file holds, with its links. Throws SampleError naming the file.
nl_navmesh_id load_navmesh_file(nl_world* world, const std::string& path);

// What a navmesh file holds and what it was made for (its made-for JSON). Throws SampleError.
struct NavmeshFileContents {
    nl_navmesh_file_info info;
    std::string made_for_json;
};
NavmeshFileContents describe_navmesh_file(const std::string& path);

// Whether a path names a baked navmesh file (by its first bytes, so any extension will do).
bool is_navmesh_file(const std::string& path);

}  // namespace nl::samples
