// The level's world-space triangles, fetched from the host with the two-call pattern and checked
// for what Recast needs (int counts, indices in range, finite coordinates).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "navlink/plugin.h"

namespace nl::recast {

struct LevelTriangles {
    std::vector<float> vertices;    // x y z per vertex
    std::vector<uint32_t> indices;  // 3 per triangle
    std::vector<uint8_t> areas;     // 1 per triangle: the mesh's area, or NL_BUILD_AREA_OBSTACLE
    // When only some columns of the level were read: the bounds of all of it (min x y z, max x y z).
    std::optional<std::array<float, 6>> whole_bounds;

    int vertex_count() const { return static_cast<int>(vertices.size() / 3); }
    int triangle_count() const { return static_cast<int>(indices.size() / 3); }
};

// Through the host's get_build_triangles, or get_level_triangles (every area 0) from an older host.
// Throws BuildFailure: the host's status when the host's function fails, INVALID_ARGUMENT for a level
// beyond Recast's int counts or with a coordinate that is not finite, INTERNAL_ERROR for an index out
// of range.
// With `columns` (min x, min z, max x, max z), only the triangles that meet them, and the whole
// level's bounds, through get_build_triangles_in_columns when the host offers it (else the whole level).
LevelTriangles fetch_level_triangles(const nl_plugin_host& host, const std::optional<std::array<double, 4>>& columns);

}  // namespace nl::recast
