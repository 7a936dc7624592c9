// A box with its own axes, and the exact test of a triangle against it: the broad phase that proves
// a bundle of occlusion segments clear without casting them.
#pragma once

#include <cstddef>

#include "level/geometry.h"

namespace nl {

struct OrientedBox {
    Vec3 center = Vec3::Zero();
    Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();  // columns: orthonormal directions
    Vec3 half_extents = Vec3::Zero();                    // along each axis

    // Radius of a sphere around the box, with room for the rounding triangle_overlaps_box allows
    // (a triangle just outside the box may still count as touching it).
    float bounding_radius() const { return half_extents.norm() + 0.05f + 1e-6f * center.cwiseAbs().maxCoeff(); }
};

// The smallest box along `axes` (orthonormal columns) holding every point, grown by `pad` on every
// side.
OrientedBox box_around(const Eigen::Matrix3f& axes, const Vec3* points, size_t count, float pad);

// Axes whose first is `along` and second `side` made square to it (any square direction when they
// are parallel); `along` must not be zero.
Eigen::Matrix3f axes_along(const Vec3& along, const Vec3& side);

// Whether the triangle and the box share a point (separating axis test over the box's three axes,
// the triangle's normal and the nine edge-by-axis cross products). Touching counts as sharing.
// Conservative where rounding could decide: a sliver's plane (and any axis that cannot be formed) is
// not used to separate, and the box grows with the triangle's size, as Embree's rounding does.
bool triangle_overlaps_box(const Vec3& a, const Vec3& b, const Vec3& c, const OrientedBox& box);

}  // namespace nl
