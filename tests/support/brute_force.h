// Reference ray queries: every triangle, double precision, one thread. Slow on purpose.
#pragma once

#include <cstdint>
#include <optional>

#include "level/geometry.h"

namespace nl::test {

struct ReferenceHit {
    double distance;
    uint32_t triangle;
    double edge_margin;  // distance from the hit point to the triangle's nearest edge, in metres
};

// Hit of one triangle (Moller-Trumbore in double). `slack` widens the triangle by that many metres
// at its edges, to ask "would a hit within rounding of an edge count?".
std::optional<ReferenceHit> intersect_triangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& origin,
                                               const Vec3& direction, double max_distance, double slack = 0.0);

// Closest hit over all triangles within [0, max_distance].
std::optional<ReferenceHit> closest_hit(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction,
                                        double max_distance);

// Every triangle the segment from `from` to `to` crosses; reports the least edge margin among the
// crossings and how close any crossing is to the segment's ends (in metres), for tie analysis.
struct ReferenceOcclusion {
    bool blocked = false;
    double least_edge_margin = 1e30;
    double least_end_distance = 1e30;
};
ReferenceOcclusion segment_occlusion(const TriangleMesh& mesh, const Vec3& from, const Vec3& to);

}  // namespace nl::test
