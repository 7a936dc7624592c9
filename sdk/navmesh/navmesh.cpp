#include "navmesh/navmesh.h"

#include <limits>

#include "navmesh/closest_point.h"

namespace nl {

Vec3 NavMesh::centre(uint32_t p) const {
    Vec3 sum = Vec3::Zero();
    const uint32_t n = corner_count(p);
    for (uint32_t k = 0; k < n; ++k) sum += vertex(corner(p, k));
    return sum / static_cast<float>(n);
}

Vec3 NavMesh::closest_point_on_polygon(uint32_t p, const Vec3& point) const {
    Vec3 best = Vec3::Zero();
    float best_distance = std::numeric_limits<float>::infinity();
    auto consider = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 q = closest_point_on_triangle(point, a, b, c);
        const float d = (q - point).squaredNorm();
        if (d < best_distance) {
            best_distance = d;
            best = q;
        }
    };
    if (!first_detail_triangle_.empty()) {
        for (uint32_t t = first_detail_triangle_[p]; t < first_detail_triangle_[p + 1]; ++t) {
            const Triangle& tri = detail_triangles_[t];
            consider(detail_vertices_[tri[0]], detail_vertices_[tri[1]], detail_vertices_[tri[2]]);
        }
    } else {
        const Vec3& origin = vertex(corner(p, 0));
        for (uint32_t k = 1; k + 1 < corner_count(p); ++k) consider(origin, vertex(corner(p, k)), vertex(corner(p, k + 1)));
    }
    return best;
}

namespace {

bool overlaps(const Aabb& b, const Vec3& lo, const Vec3& hi) {
    return (b.min.array() <= hi.array()).all() && (b.max.array() >= lo.array()).all();
}

// Keeps the nearest candidate; equal distances go to the lower polygon index, so the answer does not
// depend on the order polygons are visited in.
struct Nearest {
    const NavMesh& mesh;
    const Vec3& point;
    NavPoint best;

    void consider(uint32_t p) {
        const Vec3 q = mesh.closest_point_on_polygon(p, point);
        const float d = (q - point).norm();
        if (!best.found || d < best.distance || (d == best.distance && p < best.polygon)) best = NavPoint{true, q, d, p};
    }
};

}  // namespace

NavPoint NavMesh::find_nearest(const Vec3& point, const Vec3& half_extents) const {
    const Vec3 lo = point - half_extents, hi = point + half_extents;
    Nearest nearest{*this, point, {}};
    grid_.visit(lo, hi, polygon_bounds_, [&](uint32_t p) {
        if (overlaps(polygon_bounds_[p], lo, hi)) nearest.consider(p);
    });
    return nearest.best;
}

NavPoint NavMesh::find_nearest_brute_force(const Vec3& point, const Vec3& half_extents) const {
    const Vec3 lo = point - half_extents, hi = point + half_extents;
    Nearest nearest{*this, point, {}};
    for (uint32_t p = 0; p < polygon_count(); ++p) {
        if (overlaps(polygon_bounds_[p], lo, hi)) nearest.consider(p);
    }
    return nearest.best;
}

size_t NavMesh::memory_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return sizeof(*this) + bytes(vertices_) + bytes(first_corner_) + bytes(corners_) + bytes(neighbours_) +
           bytes(areas_) + bytes(normals_) + bytes(polygon_bounds_) + bytes(detail_vertices_) +
           bytes(detail_triangles_) + bytes(first_detail_triangle_) + bytes(boundary_edges_) + grid_.memory_bytes();
}

}  // namespace nl
