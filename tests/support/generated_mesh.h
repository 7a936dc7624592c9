// A procedural level's arrays as the core's triangle mesh, for tests that drive the core directly.
#pragma once

#include "level/geometry.h"
#include "level_generator.h"

namespace nl::test {

inline TriangleMesh to_triangle_mesh(const levelgen::GeneratedLevel& level) {
    TriangleMesh mesh;
    for (size_t i = 0; i + 2 < level.positions.size(); i += 3)
        mesh.vertices.emplace_back(level.positions[i], level.positions[i + 1], level.positions[i + 2]);
    for (size_t i = 0; i + 2 < level.indices.size(); i += 3)
        mesh.triangles.push_back({level.indices[i], level.indices[i + 1], level.indices[i + 2]});
    return mesh;
}

}  // namespace nl::test
