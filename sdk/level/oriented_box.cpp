#include "level/oriented_box.h"

#include <algorithm>
#include <cmath>

namespace nl {

OrientedBox box_around(const Eigen::Matrix3f& axes, const Vec3* points, size_t count, float pad) {
    // Measured from the first point, not the world origin: far from the origin a rounding error in
    // the axes would otherwise move the box by that error times the distance.
    const Vec3 origin = count > 0 ? points[0] : Vec3::Zero();
    Vec3 low = Vec3::Constant(std::numeric_limits<float>::infinity());
    Vec3 high = -low;
    for (size_t i = 0; i < count; ++i) {
        const Vec3 local = axes.transpose() * (points[i] - origin);
        low = low.cwiseMin(local);
        high = high.cwiseMax(local);
    }
    OrientedBox box;
    box.axes = axes;
    box.center = origin + axes * (0.5f * (low + high));
    box.half_extents = 0.5f * (high - low) + Vec3::Constant(pad);
    return box;
}

Eigen::Matrix3f axes_along(const Vec3& along, const Vec3& side) {
    // Cross products, not a subtraction: square to float precision even when `side` is nearly
    // parallel to `along`.
    const Vec3 x = along.normalized();
    Vec3 z = x.cross(side);
    z = z.squaredNorm() > 1e-12f ? z.normalized() : x.cross(x.unitOrthogonal()).normalized();
    Eigen::Matrix3f axes;
    axes << x, z.cross(x).normalized(), z;
    return axes;
}

bool triangle_overlaps_box(const Vec3& a, const Vec3& b, const Vec3& c, const OrientedBox& box) {
    // In the box's frame the box is [-h, h] on each axis.
    const Vec3 v[3] = {box.axes.transpose() * (a - box.center), box.axes.transpose() * (b - box.center),
                       box.axes.transpose() * (c - box.center)};
    const Vec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const Vec3 normal = edges[0].cross(edges[1]);
    const float longest = std::max({edges[0].squaredNorm(), edges[1].squaredNorm(), edges[2].squaredNorm()});
    // Rounding in Embree's own tests grows with the triangle's size, and for a sliver with how badly
    // its plane is defined (a 6 m x 20 um one can be hit millimetres off): the box grows as much.
    constexpr float eps = std::numeric_limits<float>::epsilon();
    const float reach = std::max({v[0].cwiseAbs().maxCoeff(), v[1].cwiseAbs().maxCoeff(), v[2].cwiseAbs().maxCoeff()});
    const float area2 = normal.norm();
    const float tilt = area2 > 0.0f ? std::min(1.0f, 8.0f * eps * longest / area2) : 1.0f;
    const Vec3 h = box.half_extents + Vec3::Constant(16.0f * eps * reach + tilt * std::sqrt(longest));
    auto separates = [&](const Vec3& axis) {
        const float p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
        const float radius = h.x() * std::fabs(axis.x()) + h.y() * std::fabs(axis.y()) + h.z() * std::fabs(axis.z());
        return std::min({p0, p1, p2}) > radius || std::max({p0, p1, p2}) < -radius;
    };
    for (int i = 0; i < 3; ++i)
        if (separates(Vec3::Unit(i))) return false;
    // Cross products shorter than this are too ill-conditioned to separate anything.
    auto usable = [](const Vec3& axis, const Vec3& edge) {
        return axis.squaredNorm() > 1e-12f * std::max(edge.squaredNorm(), 1e-12f);
    };
    // A sliver's plane is ill-defined (Embree's can be off by degrees): only a well-shaped triangle's
    // plane may separate.
    if (area2 >= 1e-3f * longest && separates(normal)) return false;
    for (const Vec3& edge : edges)
        for (int i = 0; i < 3; ++i) {
            const Vec3 axis = Vec3::Unit(i).cross(edge);
            if (usable(axis, edge) && separates(axis)) return false;
        }
    return true;
}

}  // namespace nl
