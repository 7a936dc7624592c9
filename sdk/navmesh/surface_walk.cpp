#include "navmesh/surface_walk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace nl {
namespace {

// The point of segment ab nearest p, in x-z, and its squared x-z distance.
Vec3 nearest_on_segment_xz(const Vec3& a, const Vec3& b, const Vec3& p, float& distance2) {
    const float dx = b.x() - a.x(), dz = b.z() - a.z();
    const float length2 = dx * dx + dz * dz;
    float t = length2 > 0.0f ? ((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / length2 : 0.0f;
    t = std::clamp(t, 0.0f, 1.0f);
    const Vec3 q = a + t * (b - a);
    distance2 = (q.x() - p.x()) * (q.x() - p.x()) + (q.z() - p.z()) * (q.z() - p.z());
    return q;
}

// A bounded breadth-first visit of polygons through portals (small: agents' moves are short).
constexpr size_t kMaxVisited = 48;

}  // namespace

SurfaceMove move_along_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to) {
    // The polygons a circle around the move's middle touches, nearest portals first; the target is
    // the answer if one holds it, else the nearest wall point to it among them.
    const Vec3 middle = 0.5f * (from + to);
    const float reach = 0.5f * Vec3(to.x() - from.x(), 0.0f, to.z() - from.z()).norm() + 0.001f;
    std::array<uint32_t, kMaxVisited> visited{};
    size_t count = 0, head = 0;
    visited[count++] = polygon;
    Vec3 best = from;
    uint32_t best_polygon = polygon;
    float best_distance2 = std::numeric_limits<float>::infinity();
    bool reached = false;
    while (head < count) {
        const uint32_t p = visited[head++];
        if (navmesh.over_polygon(p, to.x(), to.z())) {
            best = to;
            best_polygon = p;
            reached = true;
            break;
        }
        const uint32_t n = navmesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const Vec3& a = navmesh.vertex(navmesh.corner(p, k));
            const Vec3& b = navmesh.vertex(navmesh.corner(p, (k + 1) % n));
            const uint32_t next = navmesh.neighbour(p, k);
            float distance2;
            if (next == kNoPolygon) {
                const Vec3 q = nearest_on_segment_xz(a, b, to, distance2);
                if (distance2 < best_distance2) {
                    best_distance2 = distance2;
                    best = q;
                    best_polygon = p;
                }
                continue;
            }
            nearest_on_segment_xz(a, b, middle, distance2);
            if (distance2 > reach * reach || count == kMaxVisited) continue;
            if (std::find(visited.begin(), visited.begin() + count, next) != visited.begin() + count) continue;
            visited[count++] = next;
        }
    }
    if (!reached && best_distance2 == std::numeric_limits<float>::infinity()) {
        // No wall among the polygons searched (the search ran out): stay put.
        best = from;
        best_polygon = polygon;
    }
    best.y() = navmesh.surface_height(best_polygon, best.x(), best.z());
    return SurfaceMove{best, best_polygon, !reached};
}

bool straight_walk_clear(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to) {
    constexpr int kMaxPolygons = 64;
    constexpr float kOnEdge = 1e-4f;  // an edge hit this near one of its ends still counts
    const float dx = to.x() - from.x(), dz = to.z() - from.z();
    uint32_t p = polygon;
    for (int walked = 0; walked < kMaxPolygons; ++walked) {
        if (navmesh.over_polygon(p, to.x(), to.z())) return true;
        // A convex polygon: the line leaves it through the edge it crosses farthest along.
        const uint32_t n = navmesh.corner_count(p);
        float farthest = -1.0f;
        uint32_t exit = n;
        for (uint32_t k = 0; k < n; ++k) {
            const Vec3& a = navmesh.vertex(navmesh.corner(p, k));
            const Vec3& b = navmesh.vertex(navmesh.corner(p, (k + 1) % n));
            const float ex = b.x() - a.x(), ez = b.z() - a.z();
            const float denominator = dx * ez - dz * ex;
            if (std::fabs(denominator) < 1e-12f) continue;  // parallel to the edge
            const float along = ((a.x() - from.x()) * ez - (a.z() - from.z()) * ex) / denominator;
            const float on_edge = ((a.x() - from.x()) * dz - (a.z() - from.z()) * dx) / denominator;
            if (on_edge < -kOnEdge || on_edge > 1.0f + kOnEdge || along <= farthest) continue;
            farthest = along;
            exit = k;
        }
        if (exit == n || farthest < 0.0f) return false;  // numerically lost: not clear
        const uint32_t next = navmesh.neighbour(p, exit);
        if (next == kNoPolygon) return false;  // a wall before the target
        p = next;
    }
    return false;
}

}  // namespace nl
