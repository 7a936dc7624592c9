// The funnel algorithm ("simple stupid funnel", as Detour's findStraightPath): the shortest line
// through a row of portals, seen from above, bending only at portal ends.
#pragma once

#include <cstdint>
#include <vector>

#include "path/portal.h"

namespace nl {

struct PulledPoint {
    Vec3 position;
    uint32_t portal;  // 0: the start; i: portal i - 1; portals.size() + 1: the end
};

// Appends to `out` the start, every corner where the line bends, and the end. Heights come from the
// portal ends (interpolated along a portal where a margin moved them).
void pull_string(const Vec3& start, const Vec3& end, const std::vector<PortalSpan>& portals,
                 std::vector<PulledPoint>& out);

}  // namespace nl
