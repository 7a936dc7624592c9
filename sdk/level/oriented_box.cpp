#include "level/oriented_box.h"

#include <algorithm>
#include <cmath>

namespace nl {

OrientedBox box_around(const Eigen::Matrix3f& axes, const Vec3* points, size_t count, float pad) {
    Vec3 low = Vec3::Constant(std::numeric_limits<float>::infinity());
    Vec3 high = -low;
    for (size_t i = 0; i < count; ++i) {
        const Vec3 local = axes.transpose() * points[i];
        low = low.cwiseMin(local);
        high = high.cwiseMax(local);
    }
    OrientedBox box;
    box.axes = axes;
    box.center = axes * (0.5f * (low + high));
    box.half_extents = 0.5f * (high - low) + Vec3::Constant(pad);
    return box;
}

Eigen::Matrix3f axes_along(const Vec3& along, const Vec3& side) {
    const Vec3 x = along.normalized();
    Vec3 y = side - side.dot(x) * x;
    if (y.squaredNorm() < 1e-8f) y = x.unitOrthogonal();
    y.normalize();
    Eigen::Matrix3f axes;
    axes << x, y, x.cross(y);
    return axes;
}

bool triangle_overlaps_box(const Vec3& a, const Vec3& b, const Vec3& c, const OrientedBox& box) {
    // In the box's frame the box is [-h, h] on each axis.
    const Vec3 v[3] = {box.axes.transpose() * (a - box.center), box.axes.transpose() * (b - box.center),
                       box.axes.transpose() * (c - box.center)};
    const Vec3& h = box.half_extents;
    auto separates = [&](const Vec3& axis) {
        const float p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
        const float radius = h.x() * std::fabs(axis.x()) + h.y() * std::fabs(axis.y()) + h.z() * std::fabs(axis.z());
        return std::min({p0, p1, p2}) > radius || std::max({p0, p1, p2}) < -radius;
    };
    for (int i = 0; i < 3; ++i)
        if (separates(Vec3::Unit(i))) return false;
    const Vec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    // Cross products shorter than this are too ill-conditioned to separate anything.
    auto usable = [](const Vec3& axis, const Vec3& edge) {
        return axis.squaredNorm() > 1e-12f * std::max(edge.squaredNorm(), 1e-12f);
    };
    const Vec3 normal = edges[0].cross(edges[1]);
    if (usable(normal, edges[0]) && separates(normal)) return false;
    for (const Vec3& edge : edges)
        for (int i = 0; i < 3; ++i) {
            const Vec3 axis = Vec3::Unit(i).cross(edge);
            if (usable(axis, edge) && separates(axis)) return false;
        }
    return true;
}

}  // namespace nl
