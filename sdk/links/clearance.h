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

// Appends the segments that sweep `body` along `path` (feet on the path), leaving out `margin` of the
// path's length at each end (take-off and landing touch the floor). Three heights (near the feet, the
// middle, the head) by three lateral offsets (left edge, centre, right edge), each in both
// directions, so that a surface met from either side blocks.
void append_body_sweep(const std::vector<Vec3>& path, const Body& body, float margin, std::vector<Segment>& out);

// Number of segments append_body_sweep adds per piece of path it keeps.
constexpr unsigned kSegmentsPerPiece = 18;

}  // namespace nl
