// How far apart two navmesh points are on foot, for "is this link worth it?" questions asked while
// links are generated: a jump whose ends are about as near by walking is not generated, and two drop
// landings on one walkable surface are one way down.
//
// The walk goes from corner to corner of the navmesh's polygons, from one polygon into the next only
// through the portal they share: inside a convex polygon a straight line between two of its corners
// (or a corner and a point on it) stays on the polygon, so every walk found is one an agent of the
// navmesh's type can take. The shortest walk may cut across
// several polygons in one straight line where this one turns at a corner on the way, so the length
// found is an upper bound of the shortest walk, close to it on Recast's navmeshes.
#pragma once

#include <cstdint>
#include <vector>

#include "navmesh/navmesh.h"

namespace nl {

class WalkGraph {
public:
    explicit WalkGraph(const NavMesh& navmesh);

    // The length of a walk from `from` (on polygon from_polygon) to `to` (on to_polygon) if one of at
    // most `limit` metres is found; +infinity otherwise. Searches only what could be within the limit
    // (A* with the straight line as its estimate), so it is cheap for short limits. Thread-safe.
    float walk_within(const Vec3& from, uint32_t from_polygon, const Vec3& to, uint32_t to_polygon, float limit) const;

    // The walkable surface a polygon belongs to: polygons joined through portals, however far, share
    // one number.
    uint32_t surface(uint32_t polygon) const { return surface_[polygon]; }

private:
    const NavMesh& navmesh_;
    std::vector<uint32_t> surface_;  // by polygon: its lowest-numbered connected polygon
};

}  // namespace nl
