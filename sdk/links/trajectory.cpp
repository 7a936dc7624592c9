#include "links/trajectory.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nl {

JumpArc::JumpArc(const Vec3& start, const Vec3& end, float apex_above) : start_(start), end_(end) {
    // Through end at t = 1 and topping out h above start.y: c solves c^2 + (4h - 2dy) c + dy^2 = 0
    // on its negative root.
    const double dy = double(end.y()) - start.y();
    const double h = std::max(double(start.y()), double(end.y())) + apex_above - start.y();
    c_ = -(2.0 * h - dy) - 2.0 * std::sqrt(std::max(0.0, h * (h - dy)));
    b_ = dy - c_;
    t_apex_ = c_ < 0.0 ? std::clamp(-b_ / (2.0 * c_), 0.0, 1.0) : 0.5;
}

Vec3 JumpArc::at(double t) const {
    const Vec3 flat = start_ + static_cast<float>(t) * (end_ - start_);
    return Vec3(flat.x(), static_cast<float>(start_.y() + b_ * t + c_ * t * t), flat.z());
}

float JumpArc::sagitta(double t0, double t1) const {
    return static_cast<float>(std::fabs(c_) * (t1 - t0) * (t1 - t0) / 4.0);
}

std::vector<Vec3> JumpArc::points(unsigned pieces) const {
    std::vector<Vec3> out;
    out.reserve(pieces + 1);
    for (unsigned i = 0; i <= pieces; ++i) out.push_back(at(double(i) / pieces));
    return out;
}

std::array<Vec3, 4> fall_path(const Vec3& takeoff, const Vec3& heading, float out, const Vec3& landing) {
    const Vec3 past_rim = takeoff + heading * out;
    return {takeoff, Vec3(past_rim.x(), takeoff.y(), past_rim.z()), Vec3(landing.x(), takeoff.y(), landing.z()),
            landing};
}

}  // namespace nl
