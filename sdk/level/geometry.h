// Plain geometry values shared by the level, the navmesh and link generation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "util/handle.h"

namespace nl {

using Vec3 = Eigen::Vector3f;
using Transform = Eigen::Affine3f;
using Triangle = std::array<uint32_t, 3>;

// Triangles over shared vertices, in the mesh's own (object) space.
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
};

// What a navmesh builder builds on: the triangles, and each one's area, or kObstacleArea for a
// triangle that blocks and is never walked on.
constexpr uint8_t kObstacleArea = 255;
struct BuildTriangles {
    TriangleMesh mesh;
    std::vector<uint8_t> areas;
    // Where each mesh's triangles begin, in order: the mesh, and the index of its first triangle.
    struct MeshStart {
        Handle mesh;
        size_t first = 0;
    };
    std::vector<MeshStart> mesh_starts;

    // One past mesh_starts[k]'s last triangle.
    size_t mesh_end(size_t k) const {
        return k + 1 < mesh_starts.size() ? mesh_starts[k + 1].first : mesh.triangles.size();
    }
};

// Vertex `index` of a packed x y z float array (Embree's vertex buffers).
inline Vec3 vertex_at(const float* xyz, size_t index) {
    return Vec3(xyz[3 * index], xyz[3 * index + 1], xyz[3 * index + 2]);
}

struct Aabb {
    Vec3 min = Vec3::Constant(std::numeric_limits<float>::infinity());
    Vec3 max = Vec3::Constant(-std::numeric_limits<float>::infinity());

    void grow(const Vec3& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
    bool empty() const { return (min.array() > max.array()).any(); }
};

// A triangle's corners in the order its mesh's placement gives them: a mirroring transform turns a
// triangle over, so its corners are swapped to keep its front facing the same way.
inline Triangle wound_as_placed(Triangle t, bool mirrored) {
    if (mirrored) std::swap(t[1], t[2]);
    return t;
}

// Columns of the ground plan, every height: what a tile and its border read of the level. A triangle
// meets them when its bounds seen from above do (compared in double: tile lines are).
struct Columns {
    double min_x = 0.0, min_z = 0.0, max_x = 0.0, max_z = 0.0;

    bool met_by(const Vec3& a, const Vec3& b, const Vec3& c) const {
        return double(std::min({a.x(), b.x(), c.x()})) <= max_x && double(std::max({a.x(), b.x(), c.x()})) >= min_x &&
               double(std::min({a.z(), b.z(), c.z()})) <= max_z && double(std::max({a.z(), b.z(), c.z()})) >= min_z;
    }
    friend bool operator==(const Columns& p, const Columns& q) {
        return p.min_x == q.min_x && p.min_z == q.min_z && p.max_x == q.max_x && p.max_z == q.max_z;
    }
};

// The box, in the space `t` maps to, that holds `box` mapped by `t`.
inline Aabb transformed_box(const Aabb& box, const Transform& t) {
    if (box.empty()) return box;
    const Vec3 centre = t * (0.5f * (box.min + box.max));
    const Vec3 half = t.linear().cwiseAbs() * (0.5f * (box.max - box.min));
    Aabb out;
    out.min = centre - half;
    out.max = centre + half;
    return out;
}

}  // namespace nl
