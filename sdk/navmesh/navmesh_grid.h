// The grid navmesh coordinates are kept on.
#pragma once

#include <cmath>

#include "level/geometry.h"

namespace nl {

// Every navmesh coordinate (polygon and detail vertices, link ends) is kept on a grid of 2^-10 m
// (0.98 mm; a float beyond 16 km is on it already), so that a baked file holds it exactly in fixed
// point (io/navmesh_file.h) and a loaded navmesh answers every query as the saved one did.
constexpr int kNavMeshGridExponent = -10;
inline float on_navmesh_grid(float v) {
    return static_cast<float>(std::nearbyint(std::ldexp(double(v), -kNavMeshGridExponent)) *
                              std::ldexp(1.0, kNavMeshGridExponent));
}
inline Vec3 on_navmesh_grid(const Vec3& v) {
    return Vec3(on_navmesh_grid(v.x()), on_navmesh_grid(v.y()), on_navmesh_grid(v.z()));
}

}  // namespace nl
