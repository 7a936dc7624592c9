// The swept body's reference: exact, slow, and compiled without sanitizers (navlink_test_support).
#include "swept_body_reference.h"

#include <algorithm>
#include <cmath>

namespace nl::test {

// Whether q is inside the body: some t in [0, 1] puts q within the body's height span above the
// path point and within its radius of it, seen from above. The height span gives an interval of t;
// the horizontal distance is a quadratic in t, smallest at one point of that interval.
bool inside(const nl::SweptCylinder& b, const Eigen::Vector3d& q) {
    const Eigen::Vector3d from = b.from.cast<double>(), d = (b.to - b.from).cast<double>();
    double t0 = 0.0, t1 = 1.0;
    // from.y + t d.y + low <= q.y <= from.y + t d.y + high
    const double lo = q.y() - from.y() - b.high, hi = q.y() - from.y() - b.low;  // t d.y in [lo, hi]
    if (std::fabs(d.y()) < 1e-12) {
        if (lo > 0.0 || hi < 0.0) return false;
    } else {
        double a = lo / d.y(), c = hi / d.y();
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a), t1 = std::min(t1, c);
        if (t0 > t1) return false;
    }
    const Eigen::Vector2d p(q.x() - from.x(), q.z() - from.z()), dd(d.x(), d.z());
    const double t = dd.squaredNorm() > 0.0 ? std::clamp(p.dot(dd) / dd.squaredNorm(), t0, t1) : t0;
    return (p - t * dd).norm() <= b.radius;
}

namespace {

Eigen::Vector3d closest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double t = ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return a + t * ab;
}

// The plane's foot point if it falls inside the triangle, else the nearest of the three edges'.
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const std::array<Eigen::Vector3d, 3>& t) {
    const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
    if (n.squaredNorm() > 1e-18) {
        const Eigen::Vector3d foot = p - n * ((p - t[0]).dot(n) / n.squaredNorm());
        bool in = true;
        for (int i = 0; i < 3; ++i) in = in && (t[(i + 1) % 3] - t[i]).cross(foot - t[i]).dot(n) >= 0.0;
        if (in) return foot;
    }
    Eigen::Vector3d best = closest_on_segment(p, t[0], t[1]);
    for (int i = 1; i < 3; ++i) {
        const Eigen::Vector3d c = closest_on_segment(p, t[i], t[(i + 1) % 3]);
        if ((p - c).squaredNorm() < (p - best).squaredNorm()) best = c;
    }
    return best;
}

}  // namespace

// An upper bound of the distance between the triangle and the body: from points of the body's
// surface (side and both caps, at many positions along the stretch) to the triangle.
double sampled_distance(const nl::SweptCylinder& b, const std::array<Eigen::Vector3d, 3>& t) {
    double best = 1e30;
    for (int k = 0; k <= 64; ++k) {
        const Eigen::Vector3d c = (b.from + (b.to - b.from) * (float(k) / 64.0f)).cast<double>();
        for (int a = 0; a < 48; ++a) {
            const double angle = 2.0 * 3.14159265358979 * a / 48.0;
            for (int h = 0; h <= 16; ++h) {
                const double y = b.low + (b.high - b.low) * h / 16.0;
                for (double radial : {0.0, 0.5, 1.0}) {
                    if (radial < 1.0 && h != 0 && h != 16) continue;  // the caps' insides only at the ends
                    const Eigen::Vector3d q = c + Eigen::Vector3d(radial * b.radius * std::cos(angle), y,
                                                                  radial * b.radius * std::sin(angle));
                    best = std::min(best, (q - closest_on_triangle(q, t)).norm());
                }
            }
        }
    }
    return best;
}

}  // namespace nl::test
