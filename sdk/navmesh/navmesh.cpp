#include "navmesh/navmesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "navmesh/nearest_point.h"

namespace nl {

Vec3 NavMesh::centre(uint32_t p) const {
    Vec3 sum = Vec3::Zero();
    const uint32_t n = corner_count(p);
    for (uint32_t k = 0; k < n; ++k) sum += vertex(corner(p, k));
    return sum / static_cast<float>(n);
}

BoundaryEdge NavMesh::boundary_edge(uint32_t i) const {
    const uint32_t p = boundary_[i].polygon, k = boundary_[i].edge;
    const Vec3& a = vertex(corner(p, k));
    const Vec3& b = vertex(corner(p, (k + 1) % corner_count(p)));
    const Vec3 n = normal(p);
    // The polygon lies left of a -> b seen from above, so right (outward) is edge x normal.
    // Recast's polygons are not planar: the normal is first tilted to be square to the edge,
    // so that outward is exactly across the edge and on the outer side.
    const Vec3 edge = b - a;
    const Vec3 square_normal = n - edge * (n.dot(edge) / edge.squaredNorm());
    const Vec3 outward = edge.cross(square_normal).normalized();
    return BoundaryEdge{a, b, outward, n, p, k};
}

std::vector<BoundaryEdge> NavMesh::boundary_edges() const {
    std::vector<BoundaryEdge> edges;
    edges.reserve(boundary_.size());
    for (uint32_t i = 0; i < boundary_edge_count(); ++i) edges.push_back(boundary_edge(i));
    return edges;
}

size_t NavMesh::memory_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(vertices_) + bytes(first_corner_) + bytes(corners_) + bytes(neighbours_) + bytes(areas_) +
           bytes(on_outline_) + bytes(polygon_bounds_) + bytes(detail_vertices_) + bytes(detail_triangles_) +
           bytes(detail_) + bytes(boundary_) + grid_.memory_bytes() + bytes(polygon_tiles_) + bytes(tiles_.tiles) +
           bytes(tile_fingerprints_);
}

uint64_t NavMesh::tile_fingerprint(const TileCoord& coord) const {
    const auto at = std::lower_bound(tiles_.tiles.begin(), tiles_.tiles.end(), coord);
    if (at == tiles_.tiles.end() || *at != coord || tile_fingerprints_.empty()) return 0;
    return tile_fingerprints_[size_t(at - tiles_.tiles.begin())];
}

bool NavMesh::over_polygon(uint32_t p, float x, float z) const {
    if (!over_bounds(p, x, z)) return false;  // point location's pruning by bounds relies on it
    const uint32_t n = corner_count(p);
    for (uint32_t k = 0; k < n; ++k) {
        const Vec3& a = vertex(corner(p, k));
        const Vec3& b = vertex(corner(p, (k + 1) % n));
        // Counter-clockwise seen from above: the inside is left of every edge.
        if ((b.z() - a.z()) * (x - a.x()) - (b.x() - a.x()) * (z - a.z()) < 0.0f) return false;
    }
    return true;
}

namespace {

// The height at barycentric weights (any scale, each >= 0) of a triangle: exactly the corners' height
// on a level triangle, and never outside its corners' heights, which point location's pruning by
// polygon bounds relies on.
float blend_height(const Vec3& a, const Vec3& b, const Vec3& c, float wa, float wb, float wc) {
    const float height = a.y() + (wb * (b.y() - a.y()) + wc * (c.y() - a.y())) / (wa + wb + wc);
    return std::clamp(height, std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}));
}

}  // namespace

float NavMesh::surface_height(uint32_t p, float x, float z) const {
    // The surface triangle whose x-z projection holds (x, z); on a shared edge any of them gives the
    // same height. Rounding may leave (x, z) just outside all of them: take the least outside.
    // First the usual case without a division per triangle: the triangle that holds (x, z), or
    // misses it by rounding alone (a point computed on an edge: a millionth of the triangle's area).
    auto holds = [&](const Vec3& a, const Vec3& b, const Vec3& c, float& height) {
        const float area = (b.x() - a.x()) * (c.z() - a.z()) - (c.x() - a.x()) * (b.z() - a.z());
        const float sign = area < 0.0f ? -1.0f : 1.0f;
        const float u = sign * ((b.x() - x) * (c.z() - z) - (c.x() - x) * (b.z() - z));
        const float v = sign * ((c.x() - x) * (a.z() - z) - (a.x() - x) * (c.z() - z));
        const float w = sign * area - u - v;
        const float slack = -1e-6f * sign * area;
        if (!(area != 0.0f && u >= slack && v >= slack && w >= slack)) return false;
        height = blend_height(a, b, c, std::max(u, 0.0f), std::max(v, 0.0f), std::max(w, 0.0f));
        return true;
    };
    float height = 0.0f;
    if (!detail_.empty()) {
        for (uint32_t t = detail_[p].first_triangle; t < detail_[p + 1].first_triangle; ++t) {
            const DetailTriangle& tri = detail_triangles_[t];
            if (holds(detail_point(p, tri[0]), detail_point(p, tri[1]), detail_point(p, tri[2]), height)) return height;
        }
    } else {
        const Vec3& origin = vertex(corner(p, 0));
        for (uint32_t k = 1; k + 1 < corner_count(p); ++k) {
            if (holds(origin, vertex(corner(p, k)), vertex(corner(p, k + 1)), height)) return height;
        }
    }
    float best_margin = -std::numeric_limits<float>::infinity(), best_height = vertex(corner(p, 0)).y();
    auto consider = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const float area = (b.x() - a.x()) * (c.z() - a.z()) - (c.x() - a.x()) * (b.z() - a.z());
        if (area == 0.0f) return false;
        const float u = ((b.x() - x) * (c.z() - z) - (c.x() - x) * (b.z() - z)) / area;
        const float v = ((c.x() - x) * (a.z() - z) - (a.x() - x) * (c.z() - z)) / area;
        const float w = 1.0f - u - v;
        const float margin = std::min({u, v, w});
        if (margin > best_margin) {
            best_margin = margin;
            best_height = blend_height(a, b, c, std::max(u, 0.0f), std::max(v, 0.0f), std::max(w, 0.0f));
        }
        return margin >= 0.0f;
    };
    if (!detail_.empty()) {
        for (uint32_t t = detail_[p].first_triangle; t < detail_[p + 1].first_triangle; ++t) {
            const DetailTriangle& tri = detail_triangles_[t];
            if (consider(detail_point(p, tri[0]), detail_point(p, tri[1]), detail_point(p, tri[2]))) break;
        }
    } else {
        const Vec3& origin = vertex(corner(p, 0));
        for (uint32_t k = 1; k + 1 < corner_count(p); ++k) {
            if (consider(origin, vertex(corner(p, k)), vertex(corner(p, k + 1)))) break;
        }
    }
    return best_height;
}

Vec3 NavMesh::closest_point_on_polygon(uint32_t p, const Vec3& point) const {
    if (over_polygon(p, point.x(), point.z()))
        return Vec3(point.x(), surface_height(p, point.x(), point.z()), point.z());
    Vec3 best = Vec3::Zero();
    float best_distance = std::numeric_limits<float>::infinity();
    const uint32_t n = corner_count(p);
    for (uint32_t k = 0; k < n; ++k) {
        const Vec3& a = vertex(corner(p, k));
        const Vec3 ab = vertex(corner(p, (k + 1) % n)) - a;
        const float t = std::clamp((point - a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
        const Vec3 q = a + t * ab;
        const float d = (q - point).squaredNorm();
        if (d < best_distance) {
            best_distance = d;
            best = q;
        }
    }
    return best;
}

namespace {

bool overlaps(const Aabb& b, const Vec3& lo, const Vec3& hi) {
    return (b.min.array() <= hi.array()).all() && (b.max.array() >= lo.array()).all();
}

}  // namespace

NavPoint NavMesh::find_nearest(const Vec3& point, const Vec3& half_extents) const {
    const Vec3 lo = point - half_extents, hi = point + half_extents;
    NearestPoint nearest(*this, point);
    grid_.visit(lo, hi, polygon_bounds_, [&](uint32_t p) {
        if (overlaps(polygon_bounds_[p], lo, hi)) nearest.consider(p);
    });
    return nearest.best();
}

NavPoint NavMesh::find_nearest_anywhere(const Vec3& point, const Vec3& half_extents) const {
    if (polygon_count() == 0) return NavPoint{};
    // No polygon is nearer than the navmesh's bounds: start the widening there (a point far off
    // would otherwise double its box some thirty times).
    const Vec3 to_bounds = (bounds_.min - point).cwiseMax(point - bounds_.max).cwiseMax(Vec3::Zero());
    Vec3 extents = half_extents.cwiseMax(Vec3::Constant(1e-3f)).cwiseMax(to_bounds + Vec3::Constant(1e-3f));
    const Vec3 lo = bounds_.min.cwiseMin(point), hi = bounds_.max.cwiseMax(point);
    for (;;) {
        if (((point - extents).array() <= lo.array()).all() && ((point + extents).array() >= hi.array()).all())
            return find_nearest(point, extents);  // the box holds the whole navmesh
        const NavPoint first = find_nearest(point, extents);
        // Polygons beyond this box can still be nearer than one in its corner: look again as far as
        // the first one found (and a climb more, for a floor straight below or above).
        if (first.found)
            return find_nearest(point, extents.cwiseMax(Vec3::Constant(first.distance + agent_.max_climb)));
        extents *= 2.0f;
    }
}

NavPoint NavMesh::find_nearest_brute_force(const Vec3& point, const Vec3& half_extents) const {
    const Vec3 lo = point - half_extents, hi = point + half_extents;
    NearestPoint nearest(*this, point, false);
    for (uint32_t p = 0; p < polygon_count(); ++p) {
        if (overlaps(polygon_bounds_[p], lo, hi)) nearest.consider(p);
    }
    return nearest.best();
}

}  // namespace nl
