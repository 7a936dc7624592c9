#include "motion/link_motion.h"

#include <algorithm>
#include <cmath>

namespace nl {
namespace {

float arc_height_of(const Link& link) {
    if (link.kind == LinkKind::Jump) {
        const float above = link.apex.y() - std::max(link.start.y(), link.end.y());
        if (above > 0.0f) return above;
    }
    return link.arc_height > 0.0f ? link.arc_height : kDefaultArcHeight;
}

MotionKind kind_of(const Link& link, bool reversed) {
    if (link.kind == LinkKind::Jump || (link.kind == LinkKind::Drop && reversed)) return MotionKind::Arc;
    if (link.kind == LinkKind::Drop) return MotionKind::Fall;
    return MotionKind::Line;
}

}  // namespace

LinkMotion::LinkMotion(const Link& link, bool reversed, const BodyMotion& body)
    : kind_(kind_of(link, reversed)),
      from_(reversed ? link.end : link.start),
      to_(reversed ? link.start : link.end),
      arc_(from_, to_, arc_height_of(link)),
      speed_(std::max(body.walk_speed, 0.01f)),
      gravity_(std::max(body.gravity, 0.01f)) {
    switch (kind_) {
        case MotionKind::Arc: {
            // x and z move uniformly over the flight, so y is quadratic in time: the parabola's
            // curvature fixes the flight time for a gravity (c = -g T^2 / 2), and its take-off
            // direction for a take-off speed.
            const double c = arc_.curvature();
            if (body.takeoff_speed > 0.0f) {
                const double across = Vec3(to_.x() - from_.x(), 0.0f, to_.z() - from_.z()).norm();
                duration_ = static_cast<float>(std::hypot(across, arc_.slope()) / body.takeoff_speed);
            } else {
                duration_ = static_cast<float>(std::sqrt(-2.0 * c / gravity_));
            }
            break;
        }
        case MotionKind::Fall: {
            // Out past the rim and across at the take-off height, then down: as the generator swept.
            fall_ = {from_, Vec3(link.apex.x(), from_.y(), link.apex.z()), Vec3(to_.x(), from_.y(), to_.z()), to_};
            walk_time_ = ((fall_[1] - fall_[0]).norm() + (fall_[2] - fall_[1]).norm()) / speed_;
            const float height = std::max(0.0f, fall_[2].y() - fall_[3].y());
            duration_ = walk_time_ + std::sqrt(2.0f * height / gravity_);
            break;
        }
        case MotionKind::Line: duration_ = (to_ - from_).norm() / speed_; break;
    }
    duration_ = std::max(duration_, 1e-3f);
}

Vec3 LinkMotion::apex() const {
    switch (kind_) {
        case MotionKind::Arc: return arc_.apex();
        case MotionKind::Fall: return fall_[1];
        case MotionKind::Line: break;
    }
    return from_.y() > to_.y() ? from_ : to_;
}

std::vector<float> LinkMotion::corner_times() const {
    if (kind_ != MotionKind::Fall) return {};
    return {(fall_[1] - fall_[0]).norm() / speed_, walk_time_};
}

Vec3 LinkMotion::at(float time, Vec3* velocity) const {
    const float t = std::clamp(time, 0.0f, duration_);
    switch (kind_) {
        case MotionKind::Arc: {
            const double u = t / duration_;
            if (velocity) {
                const Vec3 across = (to_ - from_) / duration_;
                *velocity =
                    Vec3(across.x(), static_cast<float>((arc_.slope() + 2.0 * arc_.curvature() * u) / duration_),
                         across.z());
            }
            return arc_.at(u);
        }
        case MotionKind::Fall: {
            if (t < walk_time_) {
                float along = t * speed_;
                const float first = (fall_[1] - fall_[0]).norm();
                const Vec3& a = along <= first ? fall_[0] : fall_[1];
                const Vec3& b = along <= first ? fall_[1] : fall_[2];
                if (along > first) along -= first;
                const float length = (b - a).norm();
                if (velocity) *velocity = length > 0.0f ? Vec3((b - a) * (speed_ / length)) : Vec3(Vec3::Zero());
                return length > 0.0f ? a + (b - a) * (along / length) : b;
            }
            const float falling = t - walk_time_;
            if (velocity) *velocity = Vec3(0.0f, -gravity_ * falling, 0.0f);
            const float y = std::max(fall_[3].y(), fall_[2].y() - 0.5f * gravity_ * falling * falling);
            return Vec3(fall_[3].x(), y, fall_[3].z());
        }
        case MotionKind::Line: {
            if (velocity) *velocity = (to_ - from_) / duration_;
            return from_ + (to_ - from_) * (t / duration_);
        }
    }
    return to_;
}

}  // namespace nl
