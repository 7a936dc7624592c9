// Links JSON files (schema "navlink-links", docs/link-generation.md) to and from a navmesh.
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

// The navmesh's links as JSON text (nl_navmesh_save_links_json, two calls).
std::string links_json(nl_world* world, nl_navmesh_id navmesh);

// Replaces the navmesh's links with a file's (`flags`: NL_LINKS_LOAD_*); returns how many were
// loaded. Throws SampleError.
uint32_t load_links_file(nl_world* world, nl_navmesh_id navmesh, const std::string& path, uint32_t flags = 0);

}  // namespace nl::samples
