// Moving over a navmesh's surface without leaving it, as Detour's moveAlongSurface and raycast: what
// agents do every step. Both search outward from a known polygon through portals only, so they never
// jump to a floor above or below.
#pragma once

#include <cstdint>
#include <vector>

#include "navmesh/navmesh.h"
#include "util/function_ref.h"

namespace nl {

struct SurfaceMove {
    Vec3 position;     // on the surface (the detail height)
    uint32_t polygon;  // holding `position`
    bool blocked;      // a wall stopped the move short of the target
};

// Which polygons a walk may enter (the navmesh's outline and the polygons it refuses are walls);
// null: every polygon.
using PolygonFilter = FunctionRef<bool(uint32_t)>;

// Bounds and extras of a walk. Agents' walks are short: the defaults bound them as Detour's; public
// queries lift the bounds and ask for the polygons.
struct SurfaceWalkOptions {
    const PolygonFilter* passable = nullptr;
    uint32_t max_polygons = 48;                 // visited (a move) or crossed (a ray) at most
    std::vector<uint32_t>* polygons = nullptr;  // receives the polygons: see each function
    // A move's result at the surface's height; false: at `from`'s, for a caller that moves a body
    // many times in a row and sets its height once at the end (a detail surface's height costs a
    // scan of the polygon's triangles).
    bool surface_height = true;
};

// Moves from `from` (on `polygon`) toward `to` in x-z, through portals, at most as far as the target:
// the result is the target when it is reachable in a straight line over the surface, else the
// nearest point to it on a wall of the polygons within the circle through both (sliding along the
// wall). options.polygons receives the way from `polygon` to the result's. Deterministic.
SurfaceMove move_along_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to,
                               const SurfaceWalkOptions& options = {});

struct SurfaceRayHit {
    bool hit = false;                 // a wall stopped it before `to` (or it ran past max_polygons)
    bool gave_up = false;             // max_polygons crossed: nothing is known beyond
    float t = 1.0f;                   // fraction of from -> to walked, seen from above
    Vec3 point = Vec3::Zero();        // where it stopped, at the surface height
    Vec3 wall_normal = Vec3::Zero();  // horizontal, into the last polygon; zero unless a wall was hit
    uint32_t end_polygon = kNoPolygon;
};

// Walks the straight line from `from` (on `polygon`) to `to` in x-z across portals, as Detour's
// raycast: where a wall stops it, or `to`. options.polygons receives the polygons crossed, `polygon`
// first. Deterministic.
SurfaceRayHit raycast_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to,
                              const SurfaceWalkOptions& options = {});

// Whether the straight line from `from` (on `polygon`) to `to` stays on the surface in x-z within 64
// polygons: how an agent sees that it can head past its next corner.
bool straight_walk_clear(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to);

}  // namespace nl
