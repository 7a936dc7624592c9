#include "platforms_level.h"

#include <cmath>

#include "demo_setup.h"

namespace nl::samples {
namespace {

using levelgen::Box;
using levelgen::GeneratedLevel;

constexpr float kThickness = 0.5f;   // of every slab, ground or platform
constexpr float kClearance = 0.05f;  // between a platform and the ground it docks against
constexpr float kInset = 1.2f;       // a gangway's ends from the rims: well inside the navmeshes
constexpr float kStepUp = 0.6f;      // the far ledge above the shuttle's deck: a jump, not a walk
constexpr float kUpperFloor = 4.0f;  // above the lower floor: too high for any jump
constexpr float kDiscRadius = 3.5f;
constexpr int kDiscSides = 24;

// The platforms along the apron's rim, west to east, their grounds beyond the chasm, the pit and the
// trench 6 m apart or more: too far for any jump or drop the default settings generate, so that
// each is reached by its platform alone.
constexpr float kShuttleX = 3.0f, kDiscX = 17.0f, kLiftX = 31.0f;

// A closed box around the origin, its top at y = 0: a shuttle's or a lift's body in its own space.
GeneratedLevel deck(float half_x, float half_z) {
    GeneratedLevel body;
    body.add_box(Box{{-half_x, -kThickness, -half_z}, {half_x, 0.0f, half_z}});
    return body;
}

// A closed prism of `kDiscSides` sides around the vertical axis through the origin, its top at y = 0.
GeneratedLevel disc() {
    GeneratedLevel body;
    for (int i = 0; i < kDiscSides; ++i) {
        const double a = 2.0 * M_PI * i / kDiscSides;
        const float x = kDiscRadius * static_cast<float>(std::cos(a));
        const float z = kDiscRadius * static_cast<float>(std::sin(a));
        for (float y : {0.0f, -kThickness}) body.positions.insert(body.positions.end(), {x, y, z});
    }
    const uint32_t top = 2 * kDiscSides, bottom = top + 1;  // the centres
    body.positions.insert(body.positions.end(), {0.0f, 0.0f, 0.0f, 0.0f, -kThickness, 0.0f});
    for (uint32_t i = 0; i < uint32_t(kDiscSides); ++i) {
        const uint32_t j = (i + 1) % kDiscSides;
        const uint32_t up_i = 2 * i, down_i = up_i + 1, up_j = 2 * j, down_j = up_j + 1;
        // Counter-clockwise seen from outside. The corners go round clockwise seen from above (the
        // angle grows from +x towards +z), so the top takes them backwards and the bottom forwards.
        for (uint32_t k : {top, up_j, up_i, bottom, down_i, down_j, up_i, up_j, down_j, up_i, down_j, down_i})
            body.indices.push_back(k);
    }
    return body;
}

Gangway gangway(const char* name, nl_link_kind kind, bool onto, double placed_at, const Point& start,
                const Point& end) {
    return Gangway{name, kind, onto, placed_at, start, end};
}

Passenger passenger(AgentProfile profile, const char* name, const Point& start, const char* where,
                    const Point& destination) {
    profile.name = name;
    return Passenger{std::move(profile), start, destination, where};
}

}  // namespace

PlatformsLevel generate_platforms_level(uint32_t seed) {
    PlatformsLevel out;
    GeneratedLevel& level = out.level;
    level = levelgen::generate_default_level(seed);
    const Box lower = level.boxes[4];  // the lower floor under everything
    const float floor = lower.max[1];
    const float rim = lower.max[2] + 6.0f;  // the apron's north rim: every platform docks against it

    // The apron: the lower floor carried 6 m further north, all along it.
    level.add_box(Box{{lower.min[0], floor - kThickness, lower.max[2]}, {lower.max[0], floor, rim}});

    // The shuttle: 4 x 4 m, across a 10 m chasm to a ledge one step higher. Docked 3 s at each side,
    // 4 s across; it leaves the near side at 2 s, before its rider can get there (at about 4 s).
    const float far_rim = rim + 10.0f;
    level.add_box(
        Box{{kShuttleX - 3.0f, floor - kThickness, far_rim}, {kShuttleX + 3.0f, floor + kStepUp, far_rim + 6.0f}});
    const Point near_dock{kShuttleX, floor, rim + kClearance + 2.0f};
    const Point far_dock{kShuttleX, floor, far_rim - kClearance - 2.0f};
    PlatformLayout shuttle{"shuttle", deck(2.0f, 2.0f), Timetable::shuttle(near_dock, far_dock, 3.0f, 4.0f, 1.0f), {}};
    shuttle.gangways = {
        gangway("gangway onto the shuttle", NL_LINK_MANUAL, true, 0.0,  // docked at the near side
                {kShuttleX, floor, rim - kInset}, {kShuttleX, floor, rim + kClearance + kInset}),
        gangway("jump off the shuttle", NL_LINK_JUMP, false, 7.0,  // docked at the far side
                {kShuttleX, floor, far_rim - kClearance - kInset}, {kShuttleX, floor + kStepUp, far_rim + kInset})};

    // The disc: 7 m across, turning once every 16 s in a pit 0.5 m from the apron and from an exit
    // ledge beyond it. The way on ends on its axis, so it holds however the disc stands; the way off
    // starts at its edge, so it holds once a turn: when the disc stands as it did at 9 s.
    const Point axis{kDiscX, floor, rim + 0.5f + kDiscRadius};
    const float exit_rim = axis[2] + kDiscRadius + 0.5f;
    level.add_box(Box{{kDiscX - 4.0f, floor - kThickness, exit_rim}, {kDiscX + 4.0f, floor, exit_rim + 6.0f}});
    PlatformLayout turntable{"disc", disc(), Timetable::turntable(axis, 16.0f, 0.0f), {}};
    turntable.gangways = {gangway("walk onto the disc", NL_LINK_MANUAL, true, 0.0, {kDiscX, floor, rim - kInset}, axis),
                          gangway("walk off the disc", NL_LINK_MANUAL, false, 9.0,
                                  {kDiscX, floor, exit_rim - 0.5f - kInset}, {kDiscX, floor, exit_rim + kInset})};

    // The lift: 4 x 3.9 m in a 4 m trench between the apron and an upper floor 4 m up. Docked 3 s at
    // each floor, 4 s between; it is at the top when the scene starts and on its way down when its
    // passenger gets there.
    const float upper = floor + kUpperFloor, wall = rim + 4.0f;
    level.add_box(Box{{kLiftX - 4.0f, floor - kThickness, wall}, {kLiftX + 4.0f, upper, wall + 8.0f}});
    const Point bottom{kLiftX, floor, rim + 2.0f}, top{kLiftX, upper, rim + 2.0f};
    PlatformLayout lift{"lift", deck(2.0f, 2.0f - kClearance), Timetable::shuttle(bottom, top, 3.0f, 4.0f, 7.0f), {}};
    lift.gangways = {gangway("gangway onto the lift", NL_LINK_MANUAL, true, 7.0,  // at the bottom
                             {kLiftX, floor, rim - kInset}, {kLiftX, floor, rim + kClearance + kInset}),
                     gangway("gangway off the lift", NL_LINK_MANUAL, false, 0.0,  // at the top
                             {kLiftX, upper, wall - kClearance - kInset}, {kLiftX, upper, wall + kInset})};
    out.platforms = {std::move(shuttle), std::move(turntable), std::move(lift)};

    // The passengers line up on the apron. The ferry's jumps off (the long jumper: the jump is 2.45 m
    // end to end); the others walk.
    const std::vector<AgentProfile> cast = demo_agents();
    const AgentProfile& walker = cast[0];
    const AgentProfile& jumper = cast[2];
    const float line = rim - 4.0f;
    out.passengers = {
        passenger(jumper, "ferry rider", {kDiscX - 2.0f, floor, line}, "across the chasm",
                  {kShuttleX, floor + kStepUp, far_rim + 3.0f}),
        passenger(walker, "disc rider", {kDiscX - 0.7f, floor, line}, "on the disc", {kDiscX - 1.8f, floor, axis[2]}),
        passenger(walker, "disc crosser", {kDiscX + 0.7f, floor, line}, "past the disc",
                  {kDiscX, floor, exit_rim + 3.5f}),
        passenger(walker, "lift rider", {kDiscX + 2.0f, floor, line}, "on the upper floor",
                  {kLiftX, upper, wall + 4.5f})};
    out.passengers[1].destination_rides = true;  // a spot on the disc, 1.8 m from its axis
    return out;
}

}  // namespace nl::samples
