// How a body travels a link, defined once: the parabola of a jump and the path of a drop's fall. The
// generator proves these paths clear; agents follow the same ones.
#pragma once

#include <array>
#include <vector>

#include "level/geometry.h"

namespace nl {

// A parabola from start to end over the horizontal fraction t in [0, 1]: x and z move linearly,
// y(t) = start.y + b t + c t^2, topping out `apex_above` over the higher end.
class JumpArc {
public:
    JumpArc(const Vec3& start, const Vec3& end, float apex_above);

    Vec3 at(double t) const;
    Vec3 apex() const { return at(t_apex_); }
    // How far the arc strays (vertically) from its chord between t0 and t1: |c| (t1 - t0)^2 / 4.
    float sagitta(double t0, double t1) const;
    // `pieces` + 1 points, evenly spaced in t, start first.
    std::vector<Vec3> points(unsigned pieces) const;
    // y(t) = start.y + slope t + curvature t^2 (curvature < 0): what a body's timing is made from.
    double slope() const { return b_; }
    double curvature() const { return c_; }
    const Vec3& start() const { return start_; }
    const Vec3& end() const { return end_; }

private:
    Vec3 start_, end_;
    double b_ = 0.0, c_ = 0.0, t_apex_ = 0.5;
};

// A drop's fall: the body walks from the take-off point along `heading` (horizontal, unit) for
// `out` metres at the take-off height, moves across at that height to above the landing, and falls
// straight down onto it.
std::array<Vec3, 4> fall_path(const Vec3& takeoff, const Vec3& heading, float out, const Vec3& landing);

}  // namespace nl
