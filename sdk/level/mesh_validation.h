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

// Coordinates beyond this (metres) are refused everywhere: Embree asserts on values near 1.8e18, and
// float precision is already coarser than a metre past 1e7, so nothing meaningful lives out there.
constexpr float kCoordinateLimit = 1.0e9f;

inline bool within_coordinate_limit(const Vec3& v) {
    return (v.array().abs() <= kCoordinateLimit).all();  // false for NaN too
}

// Throws InvalidArgument naming the first bad coordinate or out-of-range index ("vertices[3].y",
// "indices[7]"), or when every triangle is degenerate: a failure about a field (fail_field).
ValidatedTriangles validate_mesh(const TriangleMesh& mesh);

// Throws InvalidArgument about the field `name` unless `m` is finite, affine (last row 0 0 0 1) and
// well conditioned.
Transform validate_transform(const Eigen::Matrix4f& m, const char* name);

// Maps object-space normals to world space, keeping the winding's orientation under mirroring
// (the cofactor matrix: det(L) * L^-T, up to a positive scale).
Eigen::Matrix3f normal_matrix(const Transform& t);

bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace nl
