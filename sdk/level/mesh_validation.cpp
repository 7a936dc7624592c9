#include "level/mesh_validation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/error.h"

namespace nl {

bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, bc = c - b, ca = a - c;
    const float longest_sq = std::max({ab.squaredNorm(), bc.squaredNorm(), ca.squaredNorm()});
    // |ab x ac| = 2 * area; relative to the longest edge squared it is the sine of the widest angle's
    // complement: a needle thinner than ~1e-7 of its length has no usable normal.
    return ab.cross(-ca).norm() <= 1e-7f * longest_sq || longest_sq == 0.0f;
}

ValidatedTriangles validate_mesh(const TriangleMesh& mesh) {
    if (mesh.vertices.empty()) fail_field(ErrorCode::InvalidArgument, "vertex_count is 0");
    if (mesh.triangles.empty()) fail_field(ErrorCode::InvalidArgument, "triangle_count is 0");
    if (mesh.vertices.size() > UINT32_MAX || mesh.triangles.size() > UINT32_MAX / 3)
        fail(ErrorCode::InvalidArgument, "mesh is larger than 2^32 vertices or indices");

    static const char axis[] = {'x', 'y', 'z'};
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const float value = mesh.vertices[i][k];
            if (!std::isfinite(value))
                fail_field(ErrorCode::InvalidArgument, "vertices[", i, "].", axis[k], " is not finite (", value, ")");
            if (std::fabs(value) > kCoordinateLimit)
                fail_field(ErrorCode::InvalidArgument, "vertices[", i, "].", axis[k], " = ", value,
                           " is beyond the coordinate limit of +-", kCoordinateLimit, " m");
        }
    }

    const auto vertex_count = static_cast<uint32_t>(mesh.vertices.size());
    ValidatedTriangles out;
    out.kept.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            if (tri[k] >= vertex_count)
                fail_field(ErrorCode::InvalidArgument, "indices[", t * 3 + k, "] = ", tri[k],
                           " is out of range (vertex_count = ", vertex_count, ")");
        }
        const bool repeated = tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
        if (repeated || is_degenerate(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]])) {
            if (out.degenerate_count++ == 0) {
                // Until now every triangle was kept, so kept[i] came from input i.
                out.input_index.resize(t);
                std::iota(out.input_index.begin(), out.input_index.end(), 0u);
            }
            continue;
        }
        if (out.degenerate_count > 0) out.input_index.push_back(static_cast<uint32_t>(t));
        out.kept.push_back(tri);
    }
    if (out.kept.empty())
        fail_field(ErrorCode::InvalidArgument, "indices: all ", mesh.triangles.size(),
                   " triangles are degenerate (repeated indices or zero area)");
    return out;
}

Transform validate_transform(const Eigen::Matrix4f& m, const char* name) {
    if (!m.allFinite()) fail_field(ErrorCode::InvalidArgument, name, " has a non-finite element");
    if (m(3, 0) != 0.0f || m(3, 1) != 0.0f || m(3, 2) != 0.0f || m(3, 3) != 1.0f)
        fail_field(ErrorCode::InvalidArgument, name, " is not affine (its last row must be 0 0 0 1)");
    // Conditioning, not the raw determinant: the determinant of the unit-length columns is free of
    // the matrix's scale (which would overflow when cubed) and near 0 only for a flattening matrix.
    const Eigen::Matrix3f linear = m.topLeftCorner<3, 3>();
    const Eigen::Vector3f lengths = linear.colwise().norm();
    const float shape = lengths.minCoeff() > 0.0f ? (linear * lengths.cwiseInverse().asDiagonal()).determinant() : 0.0f;
    if (!(std::fabs(shape) > 1e-6f)) fail_field(ErrorCode::InvalidArgument, name, " is singular (it flattens space)");
    Transform t;
    t.matrix() = m;
    return t;
}

Eigen::Matrix3f normal_matrix(const Transform& t) {
    const Eigen::Matrix3f inverse_transpose = t.linear().inverse().transpose();
    return t.linear().determinant() < 0.0f ? Eigen::Matrix3f(-inverse_transpose) : inverse_transpose;
}

}  // namespace nl
