#include "level/swept_body.h"

#include <cmath>
#include <limits>

namespace nl {
namespace {

using Vec3d = Eigen::Vector3d;

Vec3d wide(const Vec3& v) { return v.cast<double>(); }

// The point of the body farthest along `d`: a sum of the segment's, the disc's and the height's.
Vec3d body_support(const SweptCylinder& body, const Vec3d& from, const Vec3d& to, const Vec3d& d) {
    Vec3d p = d.dot(to) > d.dot(from) ? to : from;
    const double flat = std::sqrt(d.x() * d.x() + d.z() * d.z());
    if (flat > 0.0) {
        p.x() += body.radius * d.x() / flat;
        p.z() += body.radius * d.z() / flat;
    }
    p.y() += d.y() >= 0.0 ? body.high : body.low;
    return p;
}

Vec3d triangle_support(const std::array<Vec3d, 3>& t, const Vec3d& d) {
    const double a = d.dot(t[0]), b = d.dot(t[1]), c = d.dot(t[2]);
    return a >= b && a >= c ? t[0] : (b >= c ? t[1] : t[2]);
}

// A simplex of GJK: up to four points of the Minkowski difference.
struct Simplex {
    Vec3d p[4];
    int size = 0;
};

void keep(Simplex& s, std::initializer_list<int> which) {
    Vec3d kept[4];
    int n = 0;
    for (int i : which) kept[n++] = s.p[i];
    for (int i = 0; i < n; ++i) s.p[i] = kept[i];
    s.size = n;
}

Vec3d closest_on_segment(Simplex& s, int a, int b) {
    const Vec3d A = s.p[a], B = s.p[b], AB = B - A;
    const double length2 = AB.squaredNorm();
    const double t = length2 > 0.0 ? -A.dot(AB) / length2 : 0.0;
    if (t <= 0.0) {
        keep(s, {a});
        return A;
    }
    if (t >= 1.0) {
        keep(s, {b});
        return B;
    }
    keep(s, {a, b});
    return A + t * AB;
}

// The point of triangle (a, b, c) nearest the origin, by its Voronoi regions (Ericson, Real-Time
// Collision Detection 5.1.5); the simplex keeps the feature it lies on.
Vec3d closest_on_triangle(Simplex& s, int ia, int ib, int ic) {
    const Vec3d a = s.p[ia], b = s.p[ib], c = s.p[ic];
    const Vec3d ab = b - a, ac = c - a;
    const double d1 = -ab.dot(a), d2 = -ac.dot(a);
    if (d1 <= 0.0 && d2 <= 0.0) {
        keep(s, {ia});
        return a;
    }
    const double d3 = -ab.dot(b), d4 = -ac.dot(b);
    if (d3 >= 0.0 && d4 <= d3) {
        keep(s, {ib});
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        {
            keep(s, {ia, ib});
            return a + v * ab;
        }
    }
    const double d5 = -ab.dot(c), d6 = -ac.dot(c);
    if (d6 >= 0.0 && d5 <= d6) {
        keep(s, {ic});
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        {
            keep(s, {ia, ic});
            return a + w * ac;
        }
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        {
            keep(s, {ib, ic});
            return b + w * (c - b);
        }
    }
    const double sum = va + vb + vc;
    if (!(std::fabs(sum) > 0.0)) {
        // Degenerate (collinear) triangle: its nearest point is on its longest edge.
        Simplex edge = s;
        const Vec3d on_ab = closest_on_segment(edge, ia, ib);
        Simplex other = s;
        const Vec3d on_bc = closest_on_segment(other, ib, ic);
        s = on_bc.squaredNorm() < on_ab.squaredNorm() ? other : edge;
        return on_bc.squaredNorm() < on_ab.squaredNorm() ? on_bc : on_ab;
    }
    keep(s, {ia, ib, ic});
    return a + ab * (vb / sum) + ac * (vc / sum);
}

// Whether the origin and `opposite` lie on different sides of the plane through a, b, c (or the
// tetrahedron is flat, when every face must be looked at).
bool origin_beyond_face(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& opposite) {
    const Vec3d n = (b - a).cross(c - a);
    const double origin_side = -a.dot(n), opposite_side = (opposite - a).dot(n);
    const double scale = n.norm() * std::max({a.norm(), b.norm(), c.norm(), opposite.norm(), 1e-300});
    if (std::fabs(opposite_side) <= 1e-12 * scale) return true;
    return origin_side * opposite_side < 0.0;
}

// The point of the simplex nearest the origin; reduces the simplex to the feature it lies on.
// Returns false when the origin is inside a tetrahedron (the shapes overlap).
bool closest_on_simplex(Simplex& s, Vec3d& out) {
    switch (s.size) {
        case 1: out = s.p[0]; return true;
        case 2: out = closest_on_segment(s, 0, 1); return true;
        case 3: out = closest_on_triangle(s, 0, 1, 2); return true;
        default: break;
    }
    static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    bool any = false;
    double best = std::numeric_limits<double>::infinity();
    Simplex best_simplex;
    for (const auto& f : kFaces) {
        if (!origin_beyond_face(s.p[f[0]], s.p[f[1]], s.p[f[2]], s.p[f[3]])) continue;
        Simplex face = s;
        const Vec3d p = closest_on_triangle(face, f[0], f[1], f[2]);
        if (p.squaredNorm() < best) {
            best = p.squaredNorm();
            out = p;
            best_simplex = face;
        }
        any = true;
    }
    if (!any) return false;
    s = best_simplex;
    return true;
}

}  // namespace

bool proven_apart(const SweptCylinder& body, const std::array<Vec3, 3>& triangle, double margin) {
    const std::array<Vec3d, 3> t{wide(triangle[0]), wide(triangle[1]), wide(triangle[2])};
    const Vec3d from = wide(body.from), to = wide(body.to);
    // The difference triangle - body; its support along d is the triangle's along d minus the
    // body's along -d.
    auto support = [&](const Vec3d& d) -> Vec3d { return triangle_support(t, d) - body_support(body, from, to, -d); };

    Simplex simplex;
    Vec3d v = t[0] - from - Vec3d(0.0, 0.5 * (double(body.low) + body.high), 0.0);
    constexpr int kMostIterations = 64;
    for (int iteration = 0; iteration < kMostIterations; ++iteration) {
        const double vv = v.squaredNorm();
        if (vv <= margin * margin) return false;  // a point of the difference this near the origin
        const Vec3d w = support(-v);
        const double vw = v.dot(w);
        // Every point m of the difference has m . v >= w . v: the plane at w . v / |v| separates.
        if (vw > 0.0 && vw * vw > margin * margin * vv) return true;
        if (vv - vw <= 1e-12 * vv) return false;  // no nearer point: the distance is within the margin
        simplex.p[simplex.size++] = w;
        if (!closest_on_simplex(simplex, v)) return false;  // the origin is inside: they overlap
    }
    return false;  // not settled: count it as a hit
}

OrientedBox bounds_of(const SweptCylinder& body, float pad) {
    Vec3 heading = body.to - body.from;
    heading.y() = 0.0f;
    const Vec3 along = heading.squaredNorm() > 1e-12f ? Vec3(heading.normalized()) : Vec3::UnitX();
    const Vec3 side(-along.z(), 0.0f, along.x());
    Eigen::Matrix3f axes;
    axes << along, Vec3::UnitY(), side;
    const Vec3 lift_low(0.0f, body.low, 0.0f), lift_high(0.0f, body.high, 0.0f);
    // The corners of the body's reach: each end's disc, squared off, at the bottom and the top.
    std::array<Vec3, 16> corners;
    size_t n = 0;
    for (const Vec3& end : {body.from, body.to})
        for (const Vec3& lift : {lift_low, lift_high})
            for (float a : {-1.0f, 1.0f})
                for (float b : {-1.0f, 1.0f}) corners[n++] = end + lift + body.radius * (a * along + b * side);
    return box_around(axes, corners.data(), corners.size(), pad);
}

float body_margin(const Vec3& near) {
    return 1e-3f + 16.0f * std::numeric_limits<float>::epsilon() * near.cwiseAbs().maxCoeff();
}

}  // namespace nl
