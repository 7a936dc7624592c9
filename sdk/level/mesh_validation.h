// Checks a mesh before anything is registered: one bad value rejects the mesh whole, while degenerate
// triangles (which Embree would never report) are dropped and counted.
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"

namespace nl {

struct ValidatedTriangles {
    std::vector<Triangle> kept;
    // Input index of each kept triangle; empty when nothing was dropped (kept[i] is input i).
    std::vector<uint32_t> input_index;
    uint32_t degenerate_count = 0;
};

// Throws InvalidArgument naming the first non-finite coordinate or out-of-range index, or when every
// triangle is degenerate. Messages name fields as the C ABI does ("vertices[3].y", "indices[7]").
ValidatedTriangles validate_mesh(const TriangleMesh& mesh);

// Throws InvalidArgument unless `m` is finite, affine (last row 0 0 0 1) and invertible.
Transform validate_transform(const Eigen::Matrix4f& m, const char* name);

bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace nl
