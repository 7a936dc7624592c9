// How a body moves over one path segment, in time: walking at its speed, jumping along a ballistic
// arc that peaks at the segment's apex, dropping off a ledge under gravity, or climbing a manual
// link (a ladder) at its climbing speed.
#pragma once

#include <navlink/navlink.h>

#include <array>

namespace nl::godot_style {

using Vec3 = std::array<float, 3>;

struct Body {
    double walk_speed = 4.0;   // m/s
    double climb_speed = 1.5;  // m/s, manual and plugin links
    double gravity = 9.81;     // m/s^2, jumps and drops
};

class SegmentMotion {
public:
    // The motion from `from` to `to`, travelled the way `from.segment` says.
    SegmentMotion(const nl_path_point& from, const nl_path_point& to, const Body& body);

    double duration() const { return duration_; }
    Vec3 position_at(double t) const;  // t in [0, duration]
    // The highest point of the motion (for jumps: the apex height).
    float peak_height() const { return peak_; }

private:
    nl_segment_kind kind_;
    Vec3 start_, end_;
    double duration_ = 0.0;
    double rise_time_ = 0.0;  // jumps: from take-off to the top
    double gravity_ = 9.81;
    float peak_ = 0.0f;
};

}  // namespace nl::godot_style
