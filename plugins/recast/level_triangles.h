// The level's world-space triangles, fetched from the host with the two-call pattern and checked
// for what Recast needs (int counts, indices in range, finite coordinates).
#pragma once

#include <cstdint>
#include <vector>

#include "navlink/plugin.h"

namespace nl::recast {

struct LevelTriangles {
    std::vector<float> vertices;    // x y z per vertex
    std::vector<uint32_t> indices;  // 3 per triangle
    std::vector<uint8_t> areas;     // 1 per triangle: the mesh's area, or NL_BUILD_AREA_OBSTACLE

    int vertex_count() const { return static_cast<int>(vertices.size() / 3); }
    int triangle_count() const { return static_cast<int>(indices.size() / 3); }
};

// Through the host's get_build_triangles, or get_level_triangles (every area 0) from an older host.
// Throws BuildFailure: the host's status when the host's function fails, INVALID_ARGUMENT for a level
// beyond Recast's int counts or with a coordinate that is not finite, INTERNAL_ERROR for an index out
// of range.
LevelTriangles fetch_level_triangles(const nl_plugin_host& host);

}  // namespace nl::recast
