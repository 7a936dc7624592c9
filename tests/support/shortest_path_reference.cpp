#include "shortest_path_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nl::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

struct Point2 {
    double x, z;
};

Point2 seen_from_above(const Vec3& v) { return {double(v.x()), double(v.z())}; }

double cross(const Point2& o, const Point2& a, const Point2& b) { return (a.x - o.x) * (b.z - o.z) - (a.z - o.z) * (b.x - o.x); }

double distance(const Point2& a, const Point2& b) { return std::hypot(b.x - a.x, b.z - a.z); }

// The interior angle of polygon p at its corner k, seen from above.
double corner_angle(const NavMesh& mesh, uint32_t p, uint32_t k) {
    const uint32_t n = mesh.corner_count(p);
    const Point2 v = seen_from_above(mesh.vertex(mesh.corner(p, k)));
    const Point2 before = seen_from_above(mesh.vertex(mesh.corner(p, (k + n - 1) % n)));
    const Point2 after = seen_from_above(mesh.vertex(mesh.corner(p, (k + 1) % n)));
    const double a1 = std::atan2(before.z - v.z, before.x - v.x), a2 = std::atan2(after.z - v.z, after.x - v.x);
    double angle = std::fabs(a1 - a2);
    return angle > kPi ? 2 * kPi - angle : angle;
}

}  // namespace

ShortestPathReference::ShortestPathReference(const NavMesh& navmesh) : navmesh_(navmesh) {
    // Only a corner where the free space turns more than half a circle can be a bend: the outline's
    // reflex corners (the angles of the polygons around it add up past pi).
    std::vector<double> angle(navmesh.vertex_count(), 0.0);
    for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
        for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) angle[navmesh.corner(p, k)] += corner_angle(navmesh, p, k);
    }
    for (uint32_t v = 0; v < navmesh.vertex_count(); ++v) {
        if (navmesh.on_outline(v) && angle[v] > kPi + 1e-6) corners_.push_back(navmesh.vertex(v));
    }
    const size_t n = corners_.size();
    corner_distance_.assign(n, std::vector<double>(n, kInfinity));
    for (size_t i = 0; i < n; ++i) {
        corner_distance_[i][i] = 0.0;
        for (size_t j = i + 1; j < n; ++j) {
            if (walkable(corners_[i], corners_[j]))
                corner_distance_[i][j] = corner_distance_[j][i] = distance(seen_from_above(corners_[i]), seen_from_above(corners_[j]));
        }
    }
}

void ShortestPathReference::containing(double x, double z, std::vector<uint32_t>& out) const {
    constexpr double kOnEdge = 1e-7;  // metres: a point on an edge is on the navmesh
    const Point2 q{x, z};
    out.clear();
    for (uint32_t p = 0; p < navmesh_.polygon_count(); ++p) {
        const uint32_t n = navmesh_.corner_count(p);
        bool in = true;
        for (uint32_t k = 0; k < n && in; ++k) {
            const Point2 a = seen_from_above(navmesh_.vertex(navmesh_.corner(p, k)));
            const Point2 b = seen_from_above(navmesh_.vertex(navmesh_.corner(p, (k + 1) % n)));
            // Counter-clockwise seen from above (x right, z up): the inside is where cross(a, b, q)
            // <= 0 in this orientation (the navmesh's own rule, navmesh.cpp's over_polygon).
            in = -cross(a, b, q) >= -kOnEdge * distance(a, b);
        }
        if (in) out.push_back(p);
    }
}

void ShortestPathReference::reached_from(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after,
                                         const std::vector<uint32_t>& at_cut, std::vector<uint32_t>& out) const {
    // Through the polygons around the cut point, from edge to shared edge: round a corner where
    // polygons meet, never across a corner where two touch alone, never onto another floor.
    std::vector<uint32_t> reached(before), frontier(before);
    out.clear();
    while (!frontier.empty()) {
        const uint32_t p = frontier.back();
        frontier.pop_back();
        if (std::find(after.begin(), after.end(), p) != after.end() && std::find(out.begin(), out.end(), p) == out.end())
            out.push_back(p);
        for (uint32_t k = 0; k < navmesh_.corner_count(p); ++k) {
            const uint32_t q = navmesh_.neighbour(p, k);
            if (q == kNoPolygon || std::find(at_cut.begin(), at_cut.end(), q) == at_cut.end() ||
                std::find(reached.begin(), reached.end(), q) != reached.end())
                continue;
            reached.push_back(q);
            frontier.push_back(q);
        }
    }
}

void ShortestPathReference::on_floor(const Vec3& point, std::vector<uint32_t>& out) const {
    std::vector<uint32_t> below_or_above;
    containing(point.x(), point.z(), below_or_above);
    out.clear();
    for (const uint32_t p : below_or_above) {
        if (std::fabs(navmesh_.surface_height(p, point.x(), point.z()) - point.y()) <= navmesh_.agent().max_climb) out.push_back(p);
    }
}

bool ShortestPathReference::walkable(const Vec3& from, const Vec3& to) const {
    const Point2 a = seen_from_above(from), b = seen_from_above(to);
    const double dx = b.x - a.x, dz = b.z - a.z, length2 = dx * dx + dz * dz;
    std::vector<uint32_t> current, here, at_cut, next;
    on_floor(from, current);
    if (current.empty()) return false;
    if (length2 == 0.0) return true;
    // Every place the segment meets a polygon edge splits it; each piece between lies in one polygon
    // (or two, along a shared edge), which its middle tells.
    std::vector<double> cuts{0.0, 1.0};
    for (uint32_t p = 0; p < navmesh_.polygon_count(); ++p) {
        const uint32_t n = navmesh_.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const Point2 c = seen_from_above(navmesh_.vertex(navmesh_.corner(p, k)));
            const Point2 d = seen_from_above(navmesh_.vertex(navmesh_.corner(p, (k + 1) % n)));
            const double ex = d.x - c.x, ez = d.z - c.z;
            const double denominator = dx * ez - dz * ex;
            const double wx = c.x - a.x, wz = c.z - a.z;
            if (std::fabs(denominator) < 1e-12 * std::sqrt(length2 * (ex * ex + ez * ez))) {
                // Parallel: when on the same line, the edge's ends cut the segment.
                if (std::fabs(wx * dz - wz * dx) > 1e-9 * std::sqrt(length2)) continue;
                for (const Point2& e : {c, d}) cuts.push_back(((e.x - a.x) * dx + (e.z - a.z) * dz) / length2);
                continue;
            }
            const double t = (wx * ez - wz * ex) / denominator, s = (wx * dz - wz * dx) / denominator;
            if (s >= -1e-9 && s <= 1 + 1e-9) cuts.push_back(t);
        }
    }
    // The walk goes piece by piece from the polygons it is in to those of the next piece it reaches
    // around their cut point (reached_from), starting on the start's floor and ending on the end's.
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t0 = std::clamp(cuts[i], 0.0, 1.0), t1 = std::clamp(cuts[i + 1], 0.0, 1.0);
        if (t1 - t0 < 1e-12) continue;
        const double middle = 0.5 * (t0 + t1);
        containing(a.x + middle * dx, a.z + middle * dz, here);
        containing(a.x + t0 * dx, a.z + t0 * dz, at_cut);
        reached_from(current, here, at_cut, next);
        if (next.empty()) return false;
        current.swap(next);
    }
    on_floor(to, here);
    containing(b.x, b.z, at_cut);
    reached_from(current, here, at_cut, next);
    return !next.empty();
}

std::optional<double> ShortestPathReference::length(const Vec3& start, const Vec3& goal, std::vector<Vec3>* bends) const {
    if (bends) bends->clear();
    if (walkable(start, goal)) return distance(seen_from_above(start), seen_from_above(goal));
    // Dijkstra over the corners, from the start (which sees some of them) to the goal (likewise).
    const size_t n = corners_.size();
    std::vector<double> best(n, kInfinity), to_goal(n, kInfinity);
    std::vector<size_t> previous(n, n);
    std::vector<bool> done(n, false);
    for (size_t i = 0; i < n; ++i) {
        if (walkable(start, corners_[i])) best[i] = distance(seen_from_above(start), seen_from_above(corners_[i]));
        if (walkable(corners_[i], goal)) to_goal[i] = distance(seen_from_above(corners_[i]), seen_from_above(goal));
    }
    double answer = kInfinity;
    size_t last = n;
    for (;;) {
        size_t next = n;
        for (size_t i = 0; i < n; ++i) {
            if (!done[i] && best[i] < kInfinity && (next == n || best[i] < best[next])) next = i;
        }
        if (next == n || best[next] >= answer) break;
        done[next] = true;
        if (best[next] + to_goal[next] < answer) answer = best[next] + to_goal[next], last = next;
        for (size_t j = 0; j < n; ++j) {
            if (!done[j] && best[next] + corner_distance_[next][j] < best[j]) best[j] = best[next] + corner_distance_[next][j], previous[j] = next;
        }
    }
    if (answer == kInfinity) return std::nullopt;
    if (bends) {
        for (size_t i = last; i != n; i = previous[i]) bends->push_back(corners_[i]);
        std::reverse(bends->begin(), bends->end());
    }
    return answer;
}

}  // namespace nl::test
