// The geometry of "an agent-sized body fits along this path": the path (a jump arc, a fall) is swept
// by a body of a radius and height, approximated by occlusion segments the level tests in batches.
#pragma once

#include <vector>

#include "level/level.h"

namespace nl {

struct Body {
    float radius;
    float height;
};

// A parabola from start to end whose top is `apex_above` over the higher end, cut into `pieces`.
struct JumpArc {
    std::vector<Vec3> points;  // pieces + 1 points, start first
    Vec3 apex;
};
JumpArc jump_arc(const Vec3& start, const Vec3& end, float apex_above, unsigned pieces);

// Lateral offsets of the sweep lines, in agent radii: the centre line, then the two sides of bodies
// 1, 1.5 and 2 radii wide, so that one batch tells the widest body that fits.
constexpr float kSweepOffsets[] = {0.0f, -1.0f, 1.0f, -1.5f, 1.5f, -2.0f, 2.0f};
constexpr unsigned kSweepOffsetCount = sizeof(kSweepOffsets) / sizeof(kSweepOffsets[0]);
constexpr unsigned kSweepHeights = 3;

// Appends the segments that sweep an agent-sized body along `path` (feet on the path), leaving out
// `margin` of the path's length at each end (take-off and landing touch the floor): three heights
// (near the feet, the middle, the head) by the kSweepOffsets lines, each in both directions, so that
// a surface met from either side blocks. Segment k of a piece uses offset (k / 2) % kSweepOffsetCount.
void append_body_sweep(const std::vector<Vec3>& path, const Body& body, float margin, std::vector<Segment>& out);

}  // namespace nl
