#include "brute_force.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace nl::test {
using V = Eigen::Vector3d;

std::optional<ReferenceHit> intersect_triangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& origin,
                                               const Vec3& direction, double max_distance, double slack) {
    const Triangle& t = mesh.triangles[triangle];
    const V a = mesh.vertices[t[0]].cast<double>();
    const V b = mesh.vertices[t[1]].cast<double>();
    const V c = mesh.vertices[t[2]].cast<double>();
    const V o = origin.cast<double>();
    const V d = direction.cast<double>();
    const V e1 = b - a, e2 = c - a;
    const V n = e1.cross(e2);
    const double denom = -d.dot(n);
    if (std::fabs(denom) < 1e-300) return std::nullopt;  // parallel to the plane
    const double distance = (o - a).dot(n) / denom;
    if (!(distance >= 0.0 && distance <= max_distance)) return std::nullopt;
    const V p = o + distance * d;
    // Signed distances from p to each edge line, inside positive.
    const double area2 = n.norm();
    const double u = (c - b).cross(p - b).dot(n) / area2 / (c - b).norm();
    const double v = (a - c).cross(p - c).dot(n) / area2 / (a - c).norm();
    const double w = (b - a).cross(p - a).dot(n) / area2 / (b - a).norm();
    const double margin = std::min({u, v, w});
    if (margin < -slack) return std::nullopt;
    return ReferenceHit{distance, triangle, margin};
}

std::optional<ReferenceHit> closest_hit(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction,
                                        double max_distance) {
    std::optional<ReferenceHit> best;
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto hit = intersect_triangle(mesh, i, origin, direction, best ? best->distance : max_distance);
        if (hit && (!best || hit->distance < best->distance)) best = hit;
    }
    return best;
}

ReferenceOcclusion segment_occlusion(const TriangleMesh& mesh, const Vec3& from, const Vec3& to) {
    ReferenceOcclusion out;
    const Vec3 delta = to - from;
    const double length = delta.cast<double>().norm();
    if (length == 0.0) return out;
    const Vec3 direction = (delta.cast<double>() / length).cast<float>();
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        // Widen by a millimetre so near-misses at edges are reported as ties, not as clear misses.
        const auto hit = intersect_triangle(mesh, i, from, direction, length + 1e-3, 1e-3);
        if (!hit) continue;
        out.least_end_distance = std::min({out.least_end_distance, hit->distance, std::fabs(length - hit->distance)});
        if (hit->distance <= length && hit->edge_margin >= 0.0) out.blocked = true;
        out.least_edge_margin = std::min(out.least_edge_margin, std::fabs(hit->edge_margin));
    }
    return out;
}

}  // namespace nl::test
