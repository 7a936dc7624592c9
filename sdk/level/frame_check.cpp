#include "level/frame_check.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "level/winding_check.h"

namespace nl {
namespace {

float median_wall_height(const TriangleMesh& mesh, float max_slope_degrees) {
    const float walkable = walkable_normal_y(max_slope_degrees);
    std::vector<std::pair<float, float>> height_and_area;
    double total = 0.0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
        const Vec3& b = mesh.vertices[mesh.triangles[t][1]];
        const Vec3& c = mesh.vertices[mesh.triangles[t][2]];
        const Vec3 normal = (b - a).cross(c - a);
        const float length = normal.norm();
        if (!(length > 0.0f) || std::abs(normal.y()) >= walkable * length) continue;
        const float height = std::max({a.y(), b.y(), c.y()}) - std::min({a.y(), b.y(), c.y()});
        height_and_area.emplace_back(height, 0.5f * length);
        total += 0.5 * length;
    }
    std::sort(height_and_area.begin(), height_and_area.end());
    double reached = 0.0;
    for (const auto& [height, area] : height_and_area)
        if ((reached += area) >= 0.5 * total) return height;
    return 0.0f;
}

TriangleMesh only(const TriangleMesh& mesh, const std::vector<uint32_t>& triangles, bool z_up) {
    TriangleMesh out;
    out.vertices.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) out.vertices.push_back(z_up ? Vec3(v.x(), v.z(), -v.y()) : v);
    out.triangles.reserve(triangles.size());
    for (const uint32_t t : triangles) out.triangles.push_back(mesh.triangles[t]);
    return out;
}

}  // namespace

FrameEstimate estimate_frame(const TriangleMesh& mesh, const std::vector<uint32_t>& sized,
                             const std::vector<uint32_t>& floors, float max_slope_degrees, float height) {
    FrameEstimate out;
    if (!floors.empty()) {
        const TriangleMesh y_up = only(mesh, floors, false), z_up = only(mesh, floors, true);
        out.floor_y_up = estimate_winding(y_up, 0, y_up.triangles.size(), max_slope_degrees, height).floor_as_given;
        out.floor_z_up = estimate_winding(z_up, 0, z_up.triangles.size(), max_slope_degrees, height).floor_as_given;
    }
    if (sized.empty()) return out;
    const TriangleMesh level = only(mesh, sized, looks_z_up(out));
    out.wall_height = median_wall_height(level, max_slope_degrees);
    Aabb box;
    for (const Triangle& t : level.triangles)
        for (const uint32_t v : t) box.grow(level.vertices[v]);
    out.across = std::max(box.max.x() - box.min.x(), box.max.z() - box.min.z());
    return out;
}

bool looks_larger_than_metres(const FrameEstimate& estimate, float height) {
    return estimate.wall_height > 25.0f * height;
}

bool looks_smaller_than_metres(const FrameEstimate& estimate, float height) {
    return estimate.across > 0.0f && estimate.across < 2.0f * height;
}

bool looks_z_up(const FrameEstimate& estimate) {
    return estimate.floor_z_up > 1.5f * estimate.floor_y_up && estimate.floor_z_up > estimate.floor_y_up + 1.0f;
}

}  // namespace nl
