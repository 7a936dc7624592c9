#include "navmesh/surface_walk.h"

#include <algorithm>
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

// Which polygons a walk has visited, by polygon index: an epoch stamp per polygon stands for
// clearing them, so a walk costs what it visits. Per thread.
struct VisitMarks {
    std::vector<uint32_t> stamps;
    uint32_t epoch = 0;

    void begin(uint32_t polygons) {
        if (stamps.size() < polygons) stamps.resize(polygons, 0);
        if (++epoch == 0) {
            std::fill(stamps.begin(), stamps.end(), 0);
            epoch = 1;
        }
    }
    // True the first time p is marked in this walk.
    bool mark(uint32_t p) {
        if (stamps[p] == epoch) return false;
        stamps[p] = epoch;
        return true;
    }
};

bool may_enter(const SurfaceWalkOptions& options, uint32_t p) {
    return p != kNoPolygon && (!options.passable || (*options.passable)(p));
}

}  // namespace

SurfaceMove move_along_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to,
                               const SurfaceWalkOptions& options) {
    // The polygons a circle around the move's middle touches, nearest portals first; the target is
    // the answer if one holds it, else the nearest wall point to it among them.
    thread_local VisitMarks marks;
    thread_local std::vector<std::pair<uint32_t, uint32_t>> visited;  // polygon, index of the one it was entered from
    marks.begin(navmesh.polygon_count());
    visited.clear();
    const Vec3 middle = 0.5f * (from + to);
    const float reach = 0.5f * Vec3(to.x() - from.x(), 0.0f, to.z() - from.z()).norm() + 0.001f;
    const size_t max_visited = std::max<uint32_t>(1, options.max_polygons);
    visited.emplace_back(polygon, 0);
    marks.mark(polygon);
    size_t head = 0, best_index = 0;
    Vec3 best = from;
    float best_distance2 = std::numeric_limits<float>::infinity();
    bool reached = false;
    while (head < visited.size()) {
        const size_t index = head++;
        const uint32_t p = visited[index].first;
        if (navmesh.over_polygon(p, to.x(), to.z())) {
            best = to;
            best_index = index;
            reached = true;
            break;
        }
        const uint32_t n = navmesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const Vec3& a = navmesh.vertex(navmesh.corner(p, k));
            const Vec3& b = navmesh.vertex(navmesh.corner(p, (k + 1) % n));
            const uint32_t next = navmesh.neighbour(p, k);
            float distance2;
            if (!may_enter(options, next)) {
                const Vec3 q = nearest_on_segment_xz(a, b, to, distance2);
                if (distance2 < best_distance2) {
                    best_distance2 = distance2;
                    best = q;
                    best_index = index;
                }
                continue;
            }
            nearest_on_segment_xz(a, b, middle, distance2);
            if (distance2 > reach * reach || visited.size() == max_visited) continue;
            if (marks.mark(next)) visited.emplace_back(next, static_cast<uint32_t>(index));
        }
    }
    if (!reached && best_distance2 == std::numeric_limits<float>::infinity()) {
        // No wall among the polygons searched (the search ran out): stay put.
        best = from;
        best_index = 0;
    }
    const uint32_t best_polygon = visited[best_index].first;
    best.y() = options.surface_height ? navmesh.surface_height(best_polygon, best.x(), best.z()) : from.y();
    if (options.polygons) {
        options.polygons->clear();
        for (size_t i = best_index;; i = visited[i].second) {
            options.polygons->push_back(visited[i].first);
            if (i == 0) break;
        }
        std::reverse(options.polygons->begin(), options.polygons->end());
    }
    return SurfaceMove{best, best_polygon, !reached};
}

SurfaceRayHit raycast_surface(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to,
                              const SurfaceWalkOptions& options) {
    const float dx = to.x() - from.x(), dz = to.z() - from.z();
    if (options.polygons) options.polygons->clear();
    SurfaceRayHit result;
    auto stop_at = [&](uint32_t p, float t) {
        result.hit = true;
        result.t = std::clamp(t, 0.0f, 1.0f);
        result.point = from + result.t * (to - from);
        result.point.y() = navmesh.surface_height(p, result.point.x(), result.point.z());
        result.end_polygon = p;
    };
    uint32_t p = polygon, came_from = kNoPolygon;
    float entered_at = 0.0f;
    for (uint32_t walked = 0; walked < std::max<uint32_t>(1, options.max_polygons); ++walked) {
        if (options.polygons) options.polygons->push_back(p);
        // A convex polygon, counter-clockwise seen from above: the line is inside while it is left of
        // every edge, and leaves through the edge it crosses first going right (one pass, as Detour's
        // dtIntersectSegmentPoly2D).
        const uint32_t n = navmesh.corner_count(p);
        const uint32_t* const corners = navmesh.corners_of(p);
        float leaves_at = std::numeric_limits<float>::infinity();
        uint32_t exit = n, back_edge = n;
        float back_at = 0.0f;
        for (uint32_t k = 0; k < n; ++k) {
            const Vec3& a = navmesh.vertex(corners[k]);
            const Vec3& b = navmesh.vertex(corners[k + 1 == n ? 0 : k + 1]);
            const float ex = b.x() - a.x(), ez = b.z() - a.z();
            const float towards_outside = dz * ex - dx * ez;  // > 0: the line heads out across this edge's line
            if (!(towards_outside > 0.0f)) continue;
            // A straight line never enters a convex polygon twice: the edge it came in by is no way
            // out. On a navmesh with overlapping polygons it would be, and the walk would bounce
            // between them: there it is a wall.
            const float t = (ez * (from.x() - a.x()) - ex * (from.z() - a.z())) / towards_outside;
            if (came_from != kNoPolygon && navmesh.neighbours_of(p)[k] == came_from) {
                back_edge = k;
                back_at = t;
                continue;
            }
            if (t < leaves_at) {
                leaves_at = t;
                exit = k;
            }
        }
        if (exit == n && back_edge != n) exit = back_edge, leaves_at = back_at;  // only the way back out
        if (exit == n || leaves_at >= 1.0f) {  // the end is in this polygon (or the line has no length)
            result.point = Vec3(to.x(), navmesh.surface_height(p, to.x(), to.z()), to.z());
            result.end_polygon = p;
            return result;
        }
        const float t = std::max(leaves_at, entered_at);  // rounding never walks it back
        const uint32_t next = exit == back_edge ? kNoPolygon : navmesh.neighbours_of(p)[exit];
        if (!may_enter(options, next)) {  // a wall before the end
            stop_at(p, t);
            const Vec3& a = navmesh.vertex(corners[exit]);
            const Vec3& b = navmesh.vertex(corners[exit + 1 == n ? 0 : exit + 1]);
            // The inside is left of a -> b: the normal into the polygon.
            result.wall_normal = Vec3(b.z() - a.z(), 0.0f, a.x() - b.x()).normalized();
            return result;
        }
        came_from = p;
        p = next;
        entered_at = t;
    }
    stop_at(p, entered_at);
    result.gave_up = true;
    return result;
}

bool straight_walk_clear(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to) {
    SurfaceWalkOptions options;
    options.max_polygons = 64;
    return !raycast_surface(navmesh, polygon, from, to, options).hit;
}

}  // namespace nl
