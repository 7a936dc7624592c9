// The navmesh point nearest a point among the polygons offered, ranked as Detour's findNearestPoly
// ranks them: a polygon straight below or above the point within the agent's climb counts as
// touching it (an agent standing there is on that floor, even when the rim of a ledge beside it is
// nearer); other polygons rank by distance. Equal ranks go to the lower polygon index, so the answer
// does not depend on the order polygons are offered in.
#pragma once

#include <cstdint>

#include "navmesh/navmesh.h"

namespace nl {

class NearestPoint {
public:
    // `skip_by_bounds` false: every polygon offered is measured (the brute-force reference).
    NearestPoint(const NavMesh& navmesh, const Vec3& point, bool skip_by_bounds = true)
        : navmesh_(navmesh),
          point_(point),
          point_scale_(1.0f + point.cwiseAbs().maxCoeff()),
          skip_by_bounds_(skip_by_bounds) {}

    // Offers polygon p: skipped at the cost of a box test when its bounds are beyond the best so far.
    void consider(uint32_t p);
    // The best offered so far; not found before any was offered.
    const NavPoint& best() const { return best_; }

private:
    const NavMesh& navmesh_;
    const Vec3 point_;
    const float point_scale_;  // 1 + its largest coordinate's size: the scale of its rounding
    const bool skip_by_bounds_;
    NavPoint best_;
    float best_rank_ = 0.0f;
};

}  // namespace nl
