// Where a moving platform is at a time, as its host decides: a shuttle (or a lift) docked at one
// stop, moving to the other, docked there and back, or a disc turning about its axis. The pose is
// computed from the time alone, never accumulated, so a run plays the same at any step rate.
#pragma once

#include <array>

namespace nl::samples {

using Point = std::array<float, 3>;

// A platform's place: its origin in the world and its turn about the vertical (radians,
// counter-clockwise seen from above).
struct PlatformPose {
    Point position{};
    float yaw = 0.0f;

    // As nl_mesh_set_transform takes it: 16 floats, column-major, a rotation and a translation.
    std::array<float, 16> transform() const;
    // A point given in the platform's own space, in the world.
    Point world_point(const Point& own) const;
};

class Timetable {
public:
    // Docked at `from` for `docked` seconds, `travel` seconds to `to` (easing in and out, so riders
    // are not jolted), docked at `to`, and back: a cycle of 2 (docked + travel) seconds. `offset`
    // is how far into its cycle it is at time 0.
    static Timetable shuttle(const Point& from, const Point& to, float docked, float travel, float offset);
    // Turning about the vertical through `axis` once every `period` seconds; `offset` as above.
    static Timetable turntable(const Point& axis, float period, float offset);

    PlatformPose at(double time) const;
    // A turntable: it turns in place and has no stops.
    bool turns() const { return turns_; }
    // Whether it is standing at one of its stops (a turntable never stands).
    bool docked(double time) const;
    // How far along it is: a shuttle 0 at `from` to 1 at `to` (eased as it moves, either way); a
    // turntable the part of its turn, 0 to 1.
    float progress(double time) const;
    // Seconds from one time it is where it is at `time` to the next (a shuttle's cycle, a turn).
    float cycle() const;

private:
    // Seconds into the cycle at `time`.
    double phase(double time) const;

    bool turns_ = false;
    Point from_{}, to_{};
    float docked_ = 0.0f, travel_ = 0.0f, period_ = 0.0f, offset_ = 0.0f;
};

}  // namespace nl::samples
