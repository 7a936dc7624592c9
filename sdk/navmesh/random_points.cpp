#include "navmesh/random_points.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nl {
namespace {

using Point2 = Eigen::Vector2f;  // x, z

// splitmix64: a seed gives the same numbers on every platform (std's distributions do not).
struct SeededRandom {
    uint64_t state;

    uint64_t next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    float unit() { return float(next() >> 40) * (1.0f / 16777216.0f); }                 // [0, 1)
    double unit_double() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
};

float cross(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

float polygon_area(const std::vector<Point2>& ring) {
    float twice = 0.0f;
    for (size_t i = 1; i + 1 < ring.size(); ++i) twice += cross(ring[0], ring[i], ring[i + 1]);
    return 0.5f * std::fabs(twice);
}

// Keeps the part of a convex ring on the side of `normal . p <= limit` (Sutherland-Hodgman).
void clip(std::vector<Point2>& ring, const Point2& normal, float limit, std::vector<Point2>& scratch) {
    scratch.clear();
    for (size_t i = 0; i < ring.size(); ++i) {
        const Point2& a = ring[i];
        const Point2& b = ring[(i + 1) % ring.size()];
        const float da = normal.dot(a) - limit, db = normal.dot(b) - limit;
        if (da <= 0.0f) scratch.push_back(a);
        if ((da < 0.0f && db > 0.0f) || (da > 0.0f && db < 0.0f)) scratch.push_back(a + (da / (da - db)) * (b - a));
    }
    ring.swap(scratch);
}

// The regular polygon circumscribing the circle that pieces are clipped to: only the slivers between
// it and the circle are drawn and thrown away (1.3% of its area).
constexpr int kClipSides = 16;
// Their outward normals, cos and sin of 2 pi k / 16 written out: a C library's last bit of cos and
// sin would otherwise make another platform's points differ.
constexpr float kClipNormals[kClipSides][2] = {
    {1.0f, 0.0f},  {0.92387953f, 0.38268343f},   {0.70710678f, 0.70710678f},   {0.38268343f, 0.92387953f},
    {0.0f, 1.0f},  {-0.38268343f, 0.92387953f},  {-0.70710678f, 0.70710678f},  {-0.92387953f, 0.38268343f},
    {-1.0f, 0.0f}, {-0.92387953f, -0.38268343f}, {-0.70710678f, -0.70710678f}, {-0.38268343f, -0.92387953f},
    {0.0f, -1.0f}, {0.38268343f, -0.92387953f},  {0.70710678f, -0.70710678f},  {0.92387953f, -0.38268343f}};

// A convex part of one polygon's fan triangle, seen from above, that points are drawn in.
struct Piece {
    uint32_t polygon;
    uint32_t first;  // into corners
    uint32_t count;
};

struct Pieces {
    std::vector<Piece> pieces;
    std::vector<Point2> corners;
    std::vector<double> cumulative;  // weight of pieces[0..i], by surface area

    void add(uint32_t polygon, const std::vector<Point2>& ring, double weight) {
        pieces.push_back(Piece{polygon, static_cast<uint32_t>(corners.size()), static_cast<uint32_t>(ring.size())});
        corners.insert(corners.end(), ring.begin(), ring.end());
        cumulative.push_back((cumulative.empty() ? 0.0 : cumulative.back()) + weight);
    }
};

Pieces collect_pieces(const NavMesh& navmesh, const RandomPointsRequest& request, const PolygonFilter* allowed) {
    Pieces result;
    const bool in_circle = request.radius > 0.0f;
    const Point2 centre(request.centre.x(), request.centre.z());
    std::vector<Point2> ring, scratch;
    for (uint32_t p = 0; p < navmesh.polygon_count(); ++p) {
        if (in_circle) {
            const Aabb& box = navmesh.polygon_bounds(p);
            if (box.min.x() > centre.x() + request.radius || box.max.x() < centre.x() - request.radius ||
                box.min.z() > centre.y() + request.radius || box.max.z() < centre.y() - request.radius)
                continue;
        }
        if (allowed && !(*allowed)(p)) continue;
        const uint32_t n = navmesh.corner_count(p);
        const Vec3& a = navmesh.vertex(navmesh.corner(p, 0));
        for (uint32_t k = 1; k + 1 < n; ++k) {
            const Vec3& b = navmesh.vertex(navmesh.corner(p, k));
            const Vec3& c = navmesh.vertex(navmesh.corner(p, k + 1));
            ring.assign({Point2(a.x(), a.z()), Point2(b.x(), b.z()), Point2(c.x(), c.z())});
            const float seen_from_above = polygon_area(ring);
            if (!(seen_from_above > 0.0f)) continue;
            // Surface area per area seen from above: slopes hold more surface.
            const double slope = 0.5 * double((b - a).cross(c - a).norm()) / seen_from_above;
            if (in_circle) {
                for (int side = 0; side < kClipSides && ring.size() >= 3; ++side) {
                    const Point2 normal(kClipNormals[side][0], kClipNormals[side][1]);
                    clip(ring, normal, normal.dot(centre) + request.radius, scratch);
                }
                if (ring.size() < 3) continue;
            }
            const float area = polygon_area(ring);
            if (area > 0.0f) result.add(p, ring, double(area) * slope);
        }
    }
    return result;
}

// A uniform point of a convex piece: a triangle of its fan by area, then a uniform point in it.
Point2 draw_in(const Pieces& pieces, const Piece& piece, SeededRandom& random) {
    const Point2* ring = &pieces.corners[piece.first];
    float total = 0.0f;
    for (uint32_t i = 1; i + 1 < piece.count; ++i) total += std::fabs(cross(ring[0], ring[i], ring[i + 1]));
    float pick = random.unit() * total;
    uint32_t i = 1;
    for (; i + 2 < piece.count; ++i) {
        const float here = std::fabs(cross(ring[0], ring[i], ring[i + 1]));
        if (pick < here) break;
        pick -= here;
    }
    const float root = std::sqrt(random.unit()), v = random.unit();
    return ring[0] * (1.0f - root) + ring[i] * (root * (1.0f - v)) + ring[i + 1] * (root * v);
}

}  // namespace

uint32_t random_points(const NavMesh& navmesh, const RandomPointsRequest& request, const PolygonFilter* allowed,
                       uint32_t count, NavPoint* out) {
    const Pieces pieces = collect_pieces(navmesh, request, allowed);
    if (pieces.pieces.empty() || count == 0) return 0;
    SeededRandom random{request.seed};
    const double total = pieces.cumulative.back();
    const Point2 centre(request.centre.x(), request.centre.z());
    const float radius2 = request.radius * request.radius;
    uint32_t drawn = 0;
    for (uint64_t tries = 0; drawn < count && tries < uint64_t(kTriesPerPoint) * count; ++tries) {
        const double at = random.unit_double() * total;
        const size_t index = std::min<size_t>(
            std::upper_bound(pieces.cumulative.begin(), pieces.cumulative.end(), at) - pieces.cumulative.begin(),
            pieces.pieces.size() - 1);
        const Piece& piece = pieces.pieces[index];
        const Point2 q = draw_in(pieces, piece, random);
        if (request.radius > 0.0f && (q - centre).squaredNorm() > radius2) continue;
        const float y = navmesh.surface_height(piece.polygon, q.x(), q.y());
        out[drawn++] = NavPoint{true, Vec3(q.x(), y, q.y()), 0.0f, piece.polygon};
    }
    return drawn;
}

}  // namespace nl
