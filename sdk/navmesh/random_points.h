// Random points on a navmesh, uniform by surface area: over the whole navmesh or over its part
// within a radius of a point (seen from above), from a seed, the same on every platform.
#pragma once

#include <cstdint>

#include "navmesh/navmesh.h"
#include "navmesh/surface_walk.h"

namespace nl {

struct RandomPointsRequest {
    Vec3 centre = Vec3::Zero();
    float radius = 0.0f;  // 0: the whole navmesh
    uint64_t seed = 1;
};

// Writes up to `count` points to `out` (each found, on the surface, with its polygon) from the
// polygons `allowed` accepts (null: all) and returns how many: `count`, 0 when no allowed polygon
// lies within the radius, or fewer when the allowed part inside the circle is so thin that
// kTriesPerPoint tries per point met it too seldom.
uint32_t random_points(const NavMesh& navmesh, const RandomPointsRequest& request, const PolygonFilter* allowed,
                       uint32_t count, NavPoint* out);

constexpr uint32_t kTriesPerPoint = 64;

}  // namespace nl
