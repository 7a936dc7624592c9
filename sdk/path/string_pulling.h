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

// The pulled line `pulled` (from pull_string over `portals`) as walked: from corner to corner through
// every portal crossed on the way, at the portal's height where it is crossed.
struct WalkedLine {
    float length = 0.0f;  // along the surface: a walk over a ridge or down a ramp counts its slopes
    double cost = 0.0;    // seen from above, each stretch times its polygon's cost per metre
};
// `rates[k]`: the cost per metre of the walk's polygon k (0: the start's; k: the one past portal
// k - 1; portals.size() + 1 rates).
WalkedLine walk_line(const std::vector<PulledPoint>& pulled, const std::vector<PortalSpan>& portals,
                     const std::vector<float>& rates);

}  // namespace nl
