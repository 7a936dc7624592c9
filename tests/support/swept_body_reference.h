// An independent reference for the exact body test (level/swept_body.h), in double precision and
// slow on purpose; compiled without sanitizers like the other references (navlink_test_support).
#pragma once

#include <array>

#include <Eigen/Core>

#include "level/swept_body.h"

namespace nl::test {

// Whether q is inside the body: some t in [0, 1] puts q within the body's height span above the
// path point and within its radius of it, seen from above.
bool inside(const SweptCylinder& b, const Eigen::Vector3d& q);

// An upper bound of the distance between the triangle and the body: from points of the body's
// surface (side and both caps, at many positions along the stretch) to the triangle.
double sampled_distance(const SweptCylinder& b, const std::array<Eigen::Vector3d, 3>& t);

}  // namespace nl::test
