#include "traversal.h"

#include <algorithm>
#include <cmath>

namespace nl::godot_style {
namespace {

double distance(const Vec3& a, const Vec3& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

SegmentMotion::SegmentMotion(const nl_path_point& from, const nl_path_point& to, const Body& body)
    : kind_(from.segment),
      start_{from.position[0], from.position[1], from.position[2]},
      end_{to.position[0], to.position[1], to.position[2]},
      gravity_(body.gravity) {
    peak_ = std::max(start_[1], end_[1]);
    if (kind_ == NL_LINK_JUMP) {
        // Projectile motion through the apex height: up from the start, down to the end; the
        // horizontal speed is constant. The path point's apex is the jump's top.
        peak_ = std::max(from.apex[1], peak_ + 0.05f);
        rise_time_ = std::sqrt(2.0 * (peak_ - start_[1]) / gravity_);
        duration_ = rise_time_ + std::sqrt(2.0 * (peak_ - end_[1]) / gravity_);
    } else if (kind_ == NL_LINK_DROP) {
        // Off the edge and down: a fall from rest, crossing the gap while falling.
        duration_ = std::sqrt(2.0 * std::max(0.05f, start_[1] - end_[1]) / gravity_);
    } else if (kind_ == NL_SEGMENT_WALK) {
        duration_ = distance(start_, end_) / body.walk_speed;
    } else {
        duration_ = distance(start_, end_) / body.climb_speed;
    }
    duration_ = std::max(duration_, 1e-3);
}

Vec3 SegmentMotion::position_at(double t) const {
    t = std::clamp(t, 0.0, duration_);
    const float f = static_cast<float>(t / duration_);
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = start_[k] + (end_[k] - start_[k]) * f;
    if (kind_ == NL_LINK_JUMP) {
        const double from_top = t - rise_time_;
        p[1] = static_cast<float>(peak_ - 0.5 * gravity_ * from_top * from_top);
    } else if (kind_ == NL_LINK_DROP) {
        p[1] = static_cast<float>(std::max<double>(end_[1], start_[1] - 0.5 * gravity_ * t * t));
    }
    return p;
}

}  // namespace nl::godot_style
