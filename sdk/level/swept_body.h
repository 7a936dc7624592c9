// The agent's body swept along a straight stretch of a path, tested exactly against triangles.
//
// The body is an upright cylinder: a disc of `radius` around the path point, from `low` to `high`
// above it. Swept along a straight segment it is a convex solid (the convex hull of the cylinder at
// both ends), so the distance from a triangle to it is the distance from the origin to their
// Minkowski difference, which GJK finds from the two shapes' support points alone.
//
// A triangle is called apart only with proof: a plane found in double precision with the whole
// triangle on one side, the whole body on the other, and more than `margin` between them. Touching,
// overlapping, or a case the search could not settle within its iterations all count as a hit, so
// the test is conservative whatever the rounding: no thin bar, pole or beam slips between sample
// lines, and a body that starts inside a wall's faces is seen although no line would cross one.
#pragma once

#include <array>

#include "level/geometry.h"
#include "level/oriented_box.h"

namespace nl {

struct SweptCylinder {
    Vec3 from = Vec3::Zero();  // the path point (the feet) at the stretch's start and end
    Vec3 to = Vec3::Zero();
    float radius = 0.0f;  // >= 0
    float low = 0.0f;     // the body's bottom and top above the path point (low <= high)
    float high = 0.0f;
};

// True when a separating plane with more than `margin` metres of room is found between the
// triangle and the swept body; false when they touch, overlap or are within `margin`.
bool proven_apart(const SweptCylinder& body, const std::array<Vec3, 3>& triangle, double margin);

// A box that holds the whole body, grown by `pad` on every side: upright, along the stretch's
// horizontal heading.
OrientedBox bounds_of(const SweptCylinder& body, float pad);

// The margin every clearance test uses: a millimetre, and more far from the origin, where a float
// coordinate of the level is coarser than that.
float body_margin(const Vec3& near);

}  // namespace nl
