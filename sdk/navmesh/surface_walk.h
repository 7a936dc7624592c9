// Moving over a navmesh's surface without leaving it, as Detour's moveAlongSurface and raycast: what
// agents do every step. Both search outward from a known polygon through portals only, so they never
// jump to a floor above or below.
#pragma once

#include <cstdint>

#include "navmesh/navmesh.h"

namespace nl {

struct SurfaceMove {
    Vec3 position;     // on the surface (the detail height)
    uint32_t polygon;  // holding `position`
    bool blocked;      // a wall stopped the move short of the target
};

// Moves from `from` (on `polygon`) toward `to` in x-z, through portals, at most as far as the target:
// the result is the target when it is reachable in a straight line over the surface, else the
// nearest point to it on a wall of the polygons crossed (sliding along the wall). Deterministic.
SurfaceMove move_along_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to);

// Whether the straight line from `from` (on `polygon`) to `to` stays on the surface in x-z, crossing
// only portals, as Detour's raycast: how an agent sees that it can head past its next corner.
// A line through more than a bounded number of polygons counts as not clear. Deterministic.
bool straight_walk_clear(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to);

}  // namespace nl
