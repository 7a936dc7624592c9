// The 3D curve a traversal follows, for drawing: a jump rises through its apex, a drop goes out over
// the edge and falls onto the floor, anything else is a straight segment.
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <vector>

namespace nl::picture {

using Point3 = std::array<float, 3>;

// `samples` + 1 points from `start` to `end`. `apex` is the link's (or path point's) apex.
std::vector<Point3> traversal_curve(nl_link_kind kind, const float start[3], const float end[3], const float apex[3],
                                    int samples = 16);

}  // namespace nl::picture
