#include "platform_timetable.h"

#include <cmath>

namespace nl::samples {

std::array<float, 16> PlatformPose::transform() const {
    const float c = std::cos(yaw), s = std::sin(yaw);
    // A turn about +y (x towards -z when counter-clockwise seen from above), then the translation.
    return {c,           0.0f,        -s,          0.0f,  //
            0.0f,        1.0f,        0.0f,        0.0f,  //
            s,           0.0f,        c,           0.0f,  //
            position[0], position[1], position[2], 1.0f};
}

Point PlatformPose::world_point(const Point& own) const {
    const float c = std::cos(yaw), s = std::sin(yaw);
    return {position[0] + c * own[0] + s * own[2], position[1] + own[1], position[2] - s * own[0] + c * own[2]};
}

Timetable Timetable::shuttle(const Point& from, const Point& to, float docked, float travel, float offset) {
    Timetable t;
    t.from_ = from;
    t.to_ = to;
    t.docked_ = docked;
    t.travel_ = travel;
    t.offset_ = offset;
    return t;
}

Timetable Timetable::turntable(const Point& axis, float period, float offset) {
    Timetable t;
    t.turns_ = true;
    t.from_ = t.to_ = axis;
    t.period_ = period;
    t.offset_ = offset;
    return t;
}

float Timetable::cycle() const { return turns_ ? period_ : 2.0f * (docked_ + travel_); }

double Timetable::phase(double time) const {
    const double u = std::fmod(time + offset_, double(cycle()));
    return u < 0.0 ? u + cycle() : u;
}

bool Timetable::docked(double time) const {
    if (turns_) return false;
    const double u = phase(time);
    return u < docked_ || (u >= docked_ + travel_ && u < 2.0 * docked_ + travel_);
}

float Timetable::progress(double time) const {
    const double u = phase(time);
    if (turns_) return static_cast<float>(u / period_);
    // Out in the first half of the cycle, back in the second.
    double along = 0.0;
    if (u < docked_)
        along = 0.0;
    else if (u < docked_ + travel_)
        along = (u - docked_) / travel_;
    else if (u < 2.0 * docked_ + travel_)
        along = 1.0;
    else
        along = 1.0 - (u - 2.0 * docked_ - travel_) / travel_;
    return static_cast<float>(0.5 - 0.5 * std::cos(M_PI * along));
}

PlatformPose Timetable::at(double time) const {
    PlatformPose pose;
    const float along = progress(time);
    if (turns_) {
        pose.position = from_;
        pose.yaw = static_cast<float>(2.0 * M_PI * along);
        return pose;
    }
    for (int k = 0; k < 3; ++k) pose.position[k] = from_[k] + (to_[k] - from_[k]) * along;
    return pose;
}

}  // namespace nl::samples
