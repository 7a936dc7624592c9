// How a body moves along a link over time, on the very path the generator proved clear
// (links/trajectory.h): a jump flies its parabola, a drop walks out past the rim, across, and falls
// straight down with gravity, and any other link (manual, a plugin's) is a straight line. Agents
// follow it; a host can sample it to animate the body.
#pragma once

#include <array>
#include <vector>

#include "level/geometry.h"
#include "links/link.h"
#include "links/trajectory.h"

namespace nl {

// The arc height the generator gives a jump when a link does not say (its default setting).
constexpr float kDefaultArcHeight = 1.0f;

struct BodyMotion {
    float walk_speed = 3.5f;     // m/s, along the ground parts (a drop's walk out and across, other links)
    float gravity = 9.81f;       // m/s^2, > 0
    float takeoff_speed = 0.0f;  // m/s; > 0: a jump's time comes from this take-off speed, not gravity
};

enum class MotionKind : uint32_t { Arc = 0, Fall = 1, Line = 2 };

class LinkMotion {
public:
    // The link taken from its start (or, `reversed`, from its end). A drop taken backward is a jump
    // up along the arc the generator checked for it (link.arc_height).
    LinkMotion(const Link& link, bool reversed, const BodyMotion& body);

    MotionKind kind() const { return kind_; }
    float duration() const { return duration_; }  // seconds, > 0
    const Vec3& from() const { return from_; }
    const Vec3& to() const { return to_; }
    // The highest point: a jump's apex; for a fall where it leaves the ground; for a line the higher end.
    Vec3 apex() const;
    // For a fall: take-off, past the rim, above the landing, landing.
    const std::array<Vec3, 4>& fall_points() const { return fall_; }
    // The times at which the path turns a corner, in order: for a fall, when it passes the rim and
    // when it starts down; none for an arc or a line.
    std::vector<float> corner_times() const;

    // Where the body is `time` seconds after take-off (clamped to [0, duration]), and its velocity.
    Vec3 at(float time, Vec3* velocity = nullptr) const;

private:
    MotionKind kind_;
    Vec3 from_, to_;
    JumpArc arc_;
    std::array<Vec3, 4> fall_{};
    float speed_;
    float gravity_;
    float duration_;
    float walk_time_ = 0.0f;  // a fall's walk out and across
};

}  // namespace nl
