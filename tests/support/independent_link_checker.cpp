#include "independent_link_checker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace nl::test {
namespace {

using Vec2d = Eigen::Vector2d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double cross2(const Vec2d& u, const Vec2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Sutherland-Hodgman against one horizontal plane, inclusive: keeps y >= level (`above`) or y <= level.
int clip_by_height(const Vec3d* in, int n, double level, bool above, Vec3d* out) {
    auto inside = [&](const Vec3d& p) { return above ? p.y() >= level : p.y() <= level; };
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3d& p = in[(i + n - 1) % n];
        const Vec3d& q = in[i];
        const bool pin = inside(p), qin = inside(q);
        if (pin != qin) {
            // One strictly outside, so p.y != q.y.
            const double t = (level - p.y()) / (q.y() - p.y());
            Vec3d x = p + t * (q - p);
            x.y() = level;
            out[m++] = x;
        }
        if (qin) out[m++] = q;
    }
    return m;
}

}  // namespace

bool cylinder_meets_triangle(const UprightCylinder& cy, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    // Cheap rejection by bounds.
    const double r = cy.radius;
    if (std::max({a.y(), b.y(), c.y()}) < cy.y0 || std::min({a.y(), b.y(), c.y()}) > cy.y1) return false;
    if (std::max({a.x(), b.x(), c.x()}) < cy.x - r || std::min({a.x(), b.x(), c.x()}) > cy.x + r) return false;
    if (std::max({a.z(), b.z(), c.z()}) < cy.z - r || std::min({a.z(), b.z(), c.z()}) > cy.z + r) return false;
    // The part of the triangle within the height slab (a convex polygon, at most 5 corners).
    Vec3d p0[3] = {a, b, c}, p1[5], p2[6];
    const int n1 = clip_by_height(p0, 3, cy.y0, true, p1);
    if (n1 == 0) return false;
    const int n2 = clip_by_height(p1, n1, cy.y1, false, p2);
    if (n2 == 0) return false;
    // Seen from above, relative to the axis: the disc of radius r at the origin against the polygon.
    Vec2d q[6];
    for (int i = 0; i < n2; ++i) q[i] = Vec2d(p2[i].x() - cy.x, p2[i].z() - cy.z);
    const double r2 = r * r;
    for (int i = 0; i < n2; ++i)
        if (q[i].squaredNorm() <= r2) return true;
    for (int i = 0; i < n2; ++i) {
        const Vec2d& p = q[i];
        const Vec2d d = q[(i + 1) % n2] - p;
        const double dd = d.squaredNorm();
        if (dd <= 0.0) continue;
        const double t = std::clamp(-p.dot(d) / dd, 0.0, 1.0);
        if ((p + t * d).squaredNorm() <= r2) return true;
    }
    // The axis inside the polygon (only a polygon with area has an inside; a vertical triangle seen
    // from above is a segment, handled by the edge test).
    double area = 0.0;
    for (int i = 0; i < n2; ++i) area += cross2(q[i], q[(i + 1) % n2]);
    if (std::fabs(area) <= 1e-14) return false;
    bool positive = true, negative = true;
    for (int i = 0; i < n2; ++i) {
        const double s = cross2(q[(i + 1) % n2] - q[i], -q[i]);
        positive = positive && s >= 0.0;
        negative = negative && s <= 0.0;
    }
    return positive || negative;
}

const char* verdict_name(LinkVerdict v) {
    switch (v) {
        case LinkVerdict::Ok: return "ok";
        case LinkVerdict::Touches: return "touches";
        case LinkVerdict::EndNotOnFloor: return "end not on floor";
        case LinkVerdict::WrongFigures: return "wrong figures";
        case LinkVerdict::Inconclusive: return "inconclusive";
        case LinkVerdict::NotChecked: return "not checked";
    }
    return "?";
}

std::string describe_link(const Link& l) {
    std::ostringstream s;
    s.precision(4);
    s << std::fixed;
    s << (l.kind == LinkKind::Jump   ? "jump"
          : l.kind == LinkKind::Drop ? "drop"
                                     : "link")
      << " (" << l.start.x() << ", " << l.start.y() << ", " << l.start.z() << ") -> (" << l.end.x() << ", " << l.end.y()
      << ", " << l.end.z() << ")" << (l.bidirectional ? " <->" : " ->") << " apex (" << l.apex.x() << ", " << l.apex.y()
      << ", " << l.apex.z() << ") gap " << l.requirements.gap << " rise " << l.requirements.rise << " drop "
      << l.requirements.drop;
    s << " length " << l.requirements.length;
    s << " width " << l.requirements.clearance_width;
    return s.str();
}

std::string LinkCheck::describe() const {
    std::ostringstream s;
    s.precision(4);
    s << std::fixed << verdict_name(verdict);
    if (touch)
        s << ": the r = " << touch->radius << " body touches triangle " << touch->triangle << " at "
          << 100.0 * touch->along << "% of the path, path point (" << touch->path_point.x() << ", "
          << touch->path_point.y() << ", " << touch->path_point.z() << ")";
    if (inconclusive) s << "; " << inconclusive_pieces << " piece(s) inconclusive";
    for (const std::string& p : problems) s << "; " << p;
    s << " [checker: floors " << start_floor_y << " / " << end_floor_y << ", rims " << rim_start << " / " << rim_end
      << ", gap " << gap << ", rise " << rise << ", drop " << drop << ", length " << length << ", width "
      << clearance_width << ", path " << path_length << " m]";
    return s.str();
}

void CheckTally::add(const Link& link, const LinkCheck& c) {
    ++links;
    inconclusive_pieces += c.inconclusive_pieces;
    cylinder_tests += c.cylinder_tests;
    ok += c.verdict == LinkVerdict::Ok;
    touches += c.touches;
    end_not_on_floor += c.end_not_on_floor;
    wrong_figures += c.wrong_figures;
    inconclusive += c.inconclusive;
    if (c.touches && touching.size() < 12)
        touching.push_back(describe_link(link) + "\n      " + c.describe());
    else if (c.verdict != LinkVerdict::Ok && c.verdict != LinkVerdict::Inconclusive && failures.size() < 12)
        failures.push_back(describe_link(link) + "\n      " + c.describe());
}

void CheckTally::add(const CheckTally& o) {
    links += o.links;
    ok += o.ok;
    touches += o.touches;
    end_not_on_floor += o.end_not_on_floor;
    wrong_figures += o.wrong_figures;
    inconclusive += o.inconclusive;
    inconclusive_pieces += o.inconclusive_pieces;
    cylinder_tests += o.cylinder_tests;
    for (const std::string& f : o.touching)
        if (touching.size() < 12) touching.push_back(f);
    for (const std::string& f : o.failures)
        if (failures.size() < 12) failures.push_back(f);
}

std::string CheckTally::line() const {
    std::ostringstream s;
    s << links << " links: " << ok << " ok; " << touches << " touch, " << end_not_on_floor
      << " with an end off the floor, " << wrong_figures << " with wrong figures, " << inconclusive << " inconclusive ("
      << inconclusive_pieces << " pieces); " << cylinder_tests << " cylinder-triangle tests";
    return s.str();
}

// ---------------------------------------------------------------------------------------------

Vec3d IndependentLinkChecker::Piece::at(double u) const {
    const Vec2d xz = from + u * (to - from);
    return Vec3d(xz.x(), y0 + y1 * u + y2 * u * u, xz.y());
}

double IndependentLinkChecker::Piece::u_at_length(double s) const {
    if (s <= 0.0) return 0.0;
    if (s >= arc.back()) return 1.0;
    const auto it = std::lower_bound(arc.begin(), arc.end(), s);
    const size_t k = size_t(it - arc.begin());
    const double s0 = arc[k - 1], s1 = arc[k];
    const double f = s1 > s0 ? (s - s0) / (s1 - s0) : 0.0;
    return (double(k - 1) + f) / double(arc.size() - 1);
}

void IndependentLinkChecker::Piece::y_range(double u0, double u1, double& lo, double& hi) const {
    auto y = [&](double u) { return y0 + y1 * u + y2 * u * u; };
    lo = std::min(y(u0), y(u1));
    hi = std::max(y(u0), y(u1));
    if (y2 != 0.0) {
        const double u = -y1 / (2.0 * y2);
        if (u > u0 && u < u1) {
            lo = std::min(lo, y(u));
            hi = std::max(hi, y(u));
        }
    }
}

IndependentLinkChecker::IndependentLinkChecker(const TriangleMesh& level, const CheckedAgent& agent,
                                               const LinkSettings& settings, const CheckerTolerances& tolerances)
    : agent_(agent), settings_(settings), tol_(tolerances), lift_(std::min(0.3, agent.height / 4.0)) {
    triangles_.reserve(level.triangles.size());
    for (const Triangle& t : level.triangles) {
        Tri x;
        x.a = level.vertices[t[0]].cast<double>();
        x.b = level.vertices[t[1]].cast<double>();
        x.c = level.vertices[t[2]].cast<double>();
        x.lo = x.a.cwiseMin(x.b).cwiseMin(x.c);
        x.hi = x.a.cwiseMax(x.b).cwiseMax(x.c);
        triangles_.push_back(x);
    }
}

std::optional<double> IndependentLinkChecker::floor_below(double x, double z, double top, double reach) const {
    std::vector<uint32_t> all(triangles_.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    return floor_below(all, x, z, top, reach);
}

std::optional<double> IndependentLinkChecker::floor_below(const std::vector<uint32_t>& among, double x, double z,
                                                          double top, double reach) const {
    std::optional<double> best;
    const Vec2d p(x, z);
    for (uint32_t i : among) {
        const Tri& t = triangles_[i];
        if (t.lo.x() > x || t.hi.x() < x || t.lo.z() > z || t.hi.z() < z) continue;
        if (t.lo.y() > top || t.hi.y() < top - reach) continue;
        const Vec2d a(t.a.x(), t.a.z()), b(t.b.x(), t.b.z()), c(t.c.x(), t.c.z());
        const double area = cross2(b - a, c - a);
        if (std::fabs(area) < 1e-12) continue;  // vertical seen from above: not something to stand on
        // Barycentric, inclusive, a hair (1e-9 of the area) of slack so that shared edges never leak.
        const double u = cross2(c - b, p - b) / area, v = cross2(a - c, p - c) / area, w = cross2(b - a, p - a) / area;
        const double slack = -1e-9;
        if (u < slack || v < slack || w < slack) continue;
        const double y = u * t.a.y() + v * t.b.y() + w * t.c.y();
        if (y > top || y < top - reach) continue;
        if (!best || y > *best) best = y;
    }
    return best;
}

double IndependentLinkChecker::rim_along(const std::vector<uint32_t>& among, const Vec2d& from, const Vec2d& heading,
                                         double floor_y, double limit) const {
    const double probe = std::min(0.5, 0.5 * agent_.height);
    const double reach = probe + agent_.max_climb + 0.05;
    auto ground = [&](double s) {
        const Vec2d q = from + s * heading;
        return floor_below(among, q.x(), q.y(), floor_y + probe, reach).has_value();
    };
    double last = 0.0;
    for (double s = tol_.rim_step; s <= limit + 1e-9; s += tol_.rim_step) {
        if (ground(s)) {
            last = s;
            continue;
        }
        double lo = last, hi = s;
        while (hi - lo > 1e-3) {
            const double mid = 0.5 * (lo + hi);
            (ground(mid) ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }
    return kNaN;
}

IndependentLinkChecker::Path IndependentLinkChecker::documented_path(const Link& link, const LinkCheck& found) const {
    Path path;
    auto add_piece = [&](const Vec2d& from, const Vec2d& to, double y0, double y1, double y2) {
        Piece p{from, to, y0, y1, y2, {}};
        const double h = (to - from).norm();
        const bool curved = y2 != 0.0;
        const int n = curved ? 4096 : 1;
        p.arc.assign(size_t(n) + 1, 0.0);
        // Trapezoids of |dp/du| (exact for straight pieces).
        auto speed = [&](double u) { return std::hypot(h, y1 + 2.0 * y2 * u); };
        for (int k = 1; k <= n; ++k) {
            const double u0 = double(k - 1) / n, u1 = double(k) / n;
            p.arc[size_t(k)] = p.arc[size_t(k) - 1] + 0.5 * (speed(u0) + speed(u1)) * (u1 - u0);
        }
        if (p.length() > 1e-9) path.pieces.push_back(std::move(p));
    };
    const Vec3d s = link.start.cast<double>(), e = link.end.cast<double>();
    const Vec2d s2(s.x(), s.z()), e2(e.x(), e.z());
    if (link.kind == LinkKind::Jump) {
        // y(t) = s.y + b t + c t^2 through the end at t = 1, topping out at the apex's height h above
        // the start: b = dy - c and b^2 = -4 c h, so c^2 + (4h - 2dy) c + dy^2 = 0, on its negative root.
        const double dy = e.y() - s.y();
        const double h = double(link.apex.y()) - s.y();
        if (!(h >= std::max(0.0, dy))) {
            path.valid = false;
            path.why_not = "the apex is below an end";
            return path;
        }
        const double c = -(2.0 * h - dy) - 2.0 * std::sqrt(std::max(0.0, h * (h - dy)));
        add_piece(s2, e2, s.y(), dy - c, c);
        return path;
    }
    if (link.kind == LinkKind::Drop) {
        // Out along the heading to the rim + 0.2 m at take-off height; across to above the landing;
        // down. The heading: toward the link's apex when the link records the out point there (apex
        // horizontally away from the start), else toward the landing (a straight-out drop).
        Vec2d out;
        const Vec2d apex2(link.apex.x(), link.apex.z());
        if ((apex2 - s2).norm() > 0.01) {
            out = apex2;
        } else if (std::isfinite(found.rim_start) && (e2 - s2).norm() > 1e-6) {
            out = s2 + (e2 - s2).normalized() * (found.rim_start + 0.2);
        } else {
            out = s2;
        }
        add_piece(s2, out, s.y(), 0.0, 0.0);
        add_piece(out, e2, s.y(), 0.0, 0.0);
        add_piece(e2, e2, s.y(), e.y() - s.y(), 0.0);
        return path;
    }
    path.valid = false;
    path.why_not = "not a jump or a drop";
    return path;
}

std::vector<uint32_t> IndependentLinkChecker::candidates(const Path& path, double widest_radius) const {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
    for (const Piece& p : path.pieces) {
        for (double u : {0.0, 1.0}) {
            lo = lo.cwiseMin(p.at(u));
            hi = hi.cwiseMax(p.at(u));
        }
        double ylo, yhi;
        p.y_range(0.0, 1.0, ylo, yhi);
        lo.y() = std::min(lo.y(), ylo);
        hi.y() = std::max(hi.y(), yhi);
    }
    // Wide enough for the widest body, the rim search between the ends and the floor rays.
    const double pad = widest_radius + 0.05 + tol_.sample_step;
    lo -= Eigen::Vector3d(pad, 3.0, pad);
    hi += Eigen::Vector3d(pad, agent_.height + 1.0, pad);
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < triangles_.size(); ++i) {
        const Tri& t = triangles_[i];
        if ((t.hi.array() >= lo.array()).all() && (t.lo.array() <= hi.array()).all()) out.push_back(i);
    }
    return out;
}

bool IndependentLinkChecker::any_touches(const std::vector<uint32_t>& among, const UprightCylinder& cy, uint32_t* which,
                                         uint64_t& tests) const {
    for (uint32_t i : among) {
        const Tri& t = triangles_[i];
        if (t.hi.y() < cy.y0 || t.lo.y() > cy.y1 || t.hi.x() < cy.x - cy.radius || t.lo.x() > cy.x + cy.radius ||
            t.hi.z() < cy.z - cy.radius || t.lo.z() > cy.z + cy.radius)
            continue;
        ++tests;
        if (cylinder_meets_triangle(cy, t.a, t.b, t.c)) {
            if (which) *which = i;
            return true;
        }
    }
    return false;
}

IndependentLinkChecker::SweepResult IndependentLinkChecker::sweep(const Path& path, const std::vector<uint32_t>& among,
                                                                  double radius, double extra_clear) const {
    SweepResult out;
    double total = 0.0;
    for (const Piece& p : path.pieces) total += p.length();
    // The docs: clearance_margin of the path's length is left out at each end, but never more than the
    // agent's radius.
    const double left_out = std::min(settings_.clearance_margin * total, double(agent_.radius));
    const double keep_from = left_out + tol_.margin_band;
    const double keep_to = total - left_out - tol_.margin_band;
    if (keep_to <= keep_from) return out;
    const double touch_pad = tol_.touch_margin, clear_pad = tol_.clear_margin + extra_clear;

    auto body_at = [&](const Vec3d& p, double pad) {
        return UprightCylinder{p.x(), p.z(), p.y() + lift_ - pad, p.y() + agent_.height + pad, radius + pad};
    };
    double walked = 0.0;
    for (const Piece& piece : path.pieces) {
        const double s0 = std::max(walked, keep_from) - walked,
                     s1 = std::min(walked + piece.length(), keep_to) - walked;
        const double base = walked;
        walked += piece.length();
        if (s1 <= s0) continue;
        auto touches_at = [&](double u) {
            uint32_t tri = 0;
            const Vec3d p = piece.at(u);
            if (!any_touches(among, body_at(p, touch_pad), &tri, out.tests)) return false;
            out.result = Sweep::Touches;
            // Fraction of the path's length at u.
            const double k = u * double(piece.arc.size() - 1);
            const size_t lo = std::min(size_t(k), piece.arc.size() - 2);
            const double s = piece.arc[lo] + (k - double(lo)) * (piece.arc[lo + 1] - piece.arc[lo]);
            out.touch = BodyTouch{tri, p, (base + s) / total, radius};
            return true;
        };
        const double u_from = piece.u_at_length(s0), u_to = piece.u_at_length(s1);
        const auto n = static_cast<int>(std::max(1.0, std::ceil((s1 - s0) / tol_.sample_step)));
        // Static bodies at every cut first, in order: the first touch along the path is the one reported.
        std::vector<double> cuts(size_t(n) + 1);
        for (int k = 0; k <= n; ++k) cuts[size_t(k)] = u_from + (u_to - u_from) * double(k) / n;
        for (double u : cuts)
            if (touches_at(u)) return out;
        // Then what lies between the cuts: one cylinder holding every body along a piece.
        std::vector<std::pair<double, double>> stack;
        for (int k = n - 1; k >= 0; --k) stack.emplace_back(cuts[size_t(k)], cuts[size_t(k) + 1]);
        while (!stack.empty()) {
            const auto [u0, u1] = stack.back();
            stack.pop_back();
            const Vec3d a = piece.at(u0), b = piece.at(u1);
            double ylo, yhi;
            piece.y_range(u0, u1, ylo, yhi);
            const Vec2d mid(0.5 * (a.x() + b.x()), 0.5 * (a.z() + b.z()));
            const double half = 0.5 * std::hypot(b.x() - a.x(), b.z() - a.z());
            const UprightCylinder bound{mid.x(), mid.y(), ylo + lift_ - clear_pad, yhi + agent_.height + clear_pad,
                                        radius + clear_pad + half};
            if (!any_touches(among, bound, nullptr, out.tests)) continue;
            if ((b - a).norm() <= tol_.finest_step) {
                ++out.inconclusive_pieces;
                continue;
            }
            const double um = 0.5 * (u0 + u1);
            if (touches_at(um)) return out;
            stack.emplace_back(um, u1);
            stack.emplace_back(u0, um);
        }
    }
    if (out.inconclusive_pieces > 0) out.result = Sweep::Inconclusive;
    return out;
}

std::vector<Vec3d> IndependentLinkChecker::path_points(const Link& link, unsigned per_piece) const {
    LinkCheck found;
    found.rim_start = kNaN;
    if (link.kind == LinkKind::Drop) {
        Path probe_path;
        const Vec2d s2(link.start.x(), link.start.z()), e2(link.end.x(), link.end.z());
        std::vector<uint32_t> all(triangles_.size());
        for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
        if ((e2 - s2).norm() > 1e-6)
            found.rim_start = rim_along(all, s2, (e2 - s2).normalized(), link.start.y(), (e2 - s2).norm() + 2.0);
    }
    const Path path = documented_path(link, found);
    std::vector<Vec3d> out;
    for (const Piece& p : path.pieces)
        for (unsigned k = 0; k <= per_piece; ++k) out.push_back(p.at(double(k) / per_piece));
    return out;
}

LinkCheck IndependentLinkChecker::check(const Link& link) const {
    LinkCheck out;
    out.start_floor_y = out.end_floor_y = out.rim_start = out.rim_end = kNaN;
    out.gap = out.rise = out.drop = out.length = kNaN;
    if (link.kind != LinkKind::Jump && link.kind != LinkKind::Drop) {
        out.verdict = LinkVerdict::NotChecked;
        return out;
    }
    const double r = agent_.radius;
    const bool jump = link.kind == LinkKind::Jump;
    const Vec3d s = link.start.cast<double>(), e = link.end.cast<double>();
    const Vec2d s2(s.x(), s.z()), e2(e.x(), e.z());
    const double flat = (e2 - s2).norm();
    out.length = flat;

    // A first, generous set of nearby triangles: everything around the straight line and the fall.
    Path rough;
    {
        Piece p{s2, e2, s.y(), e.y() - s.y(), 0.0, {0.0, 1.0}};
        rough.pieces.push_back(p);
        Piece up{s2, e2, std::max(s.y(), e.y()), 0.0, 0.0, {0.0, 1.0}};
        up.y0 += settings_.jump_arc_height + 0.5;
        rough.pieces.push_back(up);
        if (!jump) {
            Piece apex{s2, Vec2d(link.apex.x(), link.apex.z()), s.y(), 0.0, 0.0, {0.0, 1.0}};
            rough.pieces.push_back(apex);
        }
    }
    const std::vector<uint32_t> near = candidates(rough, 2.0 * r + flat + 2.5);

    // Ends on the real floor.
    const double probe = 0.5;
    if (const auto f = floor_below(near, s.x(), s.z(), s.y() + probe, 2.0)) out.start_floor_y = *f;
    if (const auto f = floor_below(near, e.x(), e.z(), e.y() + probe, 2.0)) out.end_floor_y = *f;
    auto off_floor = [&](const char* which, double y, double floor) {
        std::ostringstream m;
        m.precision(3);
        m << std::fixed << which << " at y " << y;
        if (std::isnan(floor))
            m << " has no floor within 2 m below";
        else
            m << " is " << (y - floor) << " m above the floor under it (y " << floor << ")";
        out.problems.push_back(m.str());
        out.end_not_on_floor = true;
    };
    if (std::isnan(out.start_floor_y) || std::fabs(s.y() - out.start_floor_y) > tol_.floor_tolerance)
        off_floor("start", s.y(), out.start_floor_y);
    if (std::isnan(out.end_floor_y) || std::fabs(e.y() - out.end_floor_y) > tol_.floor_tolerance)
        off_floor("end", e.y(), out.end_floor_y);
    const double fs = std::isnan(out.start_floor_y) ? s.y() : out.start_floor_y;
    const double fe = std::isnan(out.end_floor_y) ? e.y() : out.end_floor_y;
    out.rise = std::max(0.0, fe - fs);
    out.drop = std::max(0.0, fs - fe);

    // Rims (the checker's own search) and the gap.
    if (flat > 1e-6) {
        const Vec2d heading = (e2 - s2) / flat;
        if (jump) {
            out.rim_start = rim_along(near, s2, heading, fs, flat);
            out.rim_end = rim_along(near, e2, -heading, fe, flat);
            if (std::isfinite(out.rim_start) && std::isfinite(out.rim_end))
                out.gap = std::max(0.0, flat - out.rim_start - out.rim_end);
        } else {
            // A drop's documented fall leaves the ground at its apex, 0.2 m past where the docs put the
            // rim on its heading (the rim found straight out from the edge, taken as a line along it):
            // the gap is from there to the landing. What the checker can see for itself is that the
            // ground has really fallen away by the apex (else the fall would start over the floor).
            const Vec2d apex2(link.apex.x(), link.apex.z());
            const Vec2d out_heading = (apex2 - s2).norm() > 0.01 ? Vec2d((apex2 - s2).normalized()) : heading;
            const double out_distance = (apex2 - s2).norm();
            out.rim_start = rim_along(near, s2, out_heading, fs, flat + 2.0);
            if (std::isfinite(out.rim_start) && out.rim_start <= out_distance + 0.02)
                out.gap = (e2 - (s2 + out_heading * std::max(0.0, out_distance - 0.2))).norm();
        }
    }

    // Figures.
    auto wrong = [&](const std::string& what, double recorded, double expected) {
        std::ostringstream m;
        m.precision(3);
        m << std::fixed << what << " recorded " << recorded << ", checker " << expected;
        out.problems.push_back(m.str());
        out.wrong_figures = true;
    };
    const LinkRequirements& q = link.requirements;
    if (std::fabs(q.rise - out.rise) > tol_.height_tolerance) wrong("rise", q.rise, out.rise);
    if (std::fabs(q.drop - out.drop) > tol_.height_tolerance) wrong("drop", q.drop, out.drop);
    if (std::isnan(out.gap)) {
        out.problems.push_back(jump ? "no gap: the checker finds floor all the way between the ends"
                                    : "the ground has not fallen away by the drop's apex");
        out.wrong_figures = true;
    } else if (std::fabs(q.gap - out.gap) > tol_.gap_tolerance) {
        wrong(jump ? "gap (rim to rim)" : "gap (rim to landing)", q.gap, out.gap);
    }
    if (std::fabs(q.length - out.length) > tol_.length_tolerance) wrong("length (end to end)", q.length, out.length);
    if (jump) {
        const double expected_apex = std::max(s.y(), e.y()) + settings_.jump_arc_height;
        if (std::fabs(link.apex.y() - expected_apex) > tol_.apex_tolerance)
            wrong("apex height", link.apex.y(), expected_apex);
    }
    // The settings' limits, on the figures the spec says they apply to.
    const double lt = tol_.limit_tolerance;
    if (jump) {
        if (std::isfinite(out.gap) && out.gap > settings_.max_jump_gap + tol_.gap_tolerance)
            wrong("gap beyond max_jump_gap", q.gap, out.gap);
        if (std::max(out.rise, out.drop) > settings_.max_jump_up + lt)
            wrong("rise beyond max_jump_up", q.rise + q.drop, std::max(out.rise, out.drop));
    } else {
        if (out.drop > settings_.max_drop_distance + lt) wrong("drop beyond max_drop_distance", q.drop, out.drop);
        if (out.drop <= agent_.max_climb - lt) wrong("drop no deeper than max_climb (walked)", q.drop, out.drop);
        if (out.rise > lt) wrong("a drop that rises", q.rise, out.rise);
    }

    // The body along the documented path.
    const Path path = documented_path(link, out);
    if (!path.valid) {
        out.problems.push_back("no documented path: " + path.why_not);
        out.wrong_figures = true;
    } else {
        for (const Piece& p : path.pieces) out.path_length += p.length();
        const std::vector<uint32_t> among = candidates(path, 2.0 * r + 0.01);
        const SweepResult agent = sweep(path, among, r, 0.0);
        out.cylinder_tests += agent.tests;
        out.inconclusive_pieces += agent.inconclusive_pieces;
        if (agent.result == Sweep::Touches) {
            out.touches = true;
            out.touch = agent.touch;
        } else if (agent.result == Sweep::Inconclusive) {
            out.inconclusive = true;
        }
        // A drop low enough to be jumped back up (bidirectional) promises that jump too: the arc from
        // its end up to its start, topping out jump_arc_height over the start.
        Path back;
        std::vector<uint32_t> back_among;
        if (!jump && link.bidirectional) {
            Link up = link;
            up.kind = LinkKind::Jump;
            std::swap(up.start, up.end);
            up.apex = up.end;
            up.apex.y() = std::max(link.start.y(), link.end.y()) + settings_.jump_arc_height;
            back = documented_path(up, out);
            back_among = candidates(back, 2.0 * r + 0.01);
            const SweepResult agent_back = sweep(back, back_among, r, 0.0);
            out.cylinder_tests += agent_back.tests;
            if (agent_back.result == Sweep::Touches) {
                out.problems.push_back("bidirectional, but the body touches the level on the jump back up");
                out.touches = true;
                out.touch = agent_back.touch;
            } else if (agent_back.result == Sweep::Inconclusive) {
                out.inconclusive = true;
            }
        }
        // Both ways must be clear for a width to count (the jump back up, for a bidirectional drop).
        auto sweep_both = [&](double radius, double pad) {
            SweepResult forward = sweep(path, among, radius, pad);
            if (back.pieces.empty() || forward.result != Sweep::Clear) return forward;
            const SweepResult reverse = sweep(back, back_among, radius, pad);
            forward.tests += reverse.tests;
            forward.result = reverse.result;
            forward.inconclusive_pieces += reverse.inconclusive_pieces;
            return forward;
        };
        // clearance_width: 2 x the widest of r, 1.5 r, 2 r whose body (and every narrower one) is clear.
        if (agent.result == Sweep::Clear && !out.touches) {
            out.clearance_width = float(2.0 * r);
            if (tol_.check_width) {
                for (double k : {1.5, 2.0}) {
                    const SweepResult wider = sweep_both(k * r, 0.0);
                    out.cylinder_tests += wider.tests;
                    if (wider.result != Sweep::Clear) {
                        // Overstating is what matters: the recorded width must be clear. An
                        // inconclusive wider body is not counted against the link.
                        const double recorded = q.clearance_width;
                        if (recorded > 2.0 * (k - 0.25) * r + 1e-4) {
                            if (wider.result == Sweep::Touches)
                                wrong("clearance_width (a body that wide touches)", recorded, out.clearance_width);
                            else {
                                out.inconclusive = true;
                                out.inconclusive_pieces += wider.inconclusive_pieces;
                            }
                        }
                        break;
                    }
                    out.clearance_width = float(2.0 * k * r);
                }
                // Understated only if the next wider body is clear with 5 mm to spare (a body that
                // clears by a hair may fairly be refused by a test with a 1 mm margin in floats).
                const double recorded = q.clearance_width;
                if (recorded < out.clearance_width - 1e-3) {
                    const double k = recorded < 3.0 * r - 1e-3 ? 1.5 : 2.0;
                    const SweepResult spare = sweep_both(k * r, 0.005);
                    out.cylinder_tests += spare.tests;
                    if (spare.result == Sweep::Clear)
                        wrong("clearance_width (a wider body is clear)", recorded, out.clearance_width);
                }
            }
        }
        if (q.clearance_width <= 0.0f) wrong("clearance_width of a kept link", q.clearance_width, out.clearance_width);
        const double ratio = q.clearance_width / (2.0 * r);
        if (q.clearance_width > 0.0f && std::fabs(ratio - 1.0) > 1e-3 && std::fabs(ratio - 1.5) > 1e-3 &&
            std::fabs(ratio - 2.0) > 1e-3)
            wrong("clearance_width not 2, 3 or 4 radii", q.clearance_width, out.clearance_width);
    }

    if (out.touches)
        out.verdict = LinkVerdict::Touches;
    else if (out.end_not_on_floor)
        out.verdict = LinkVerdict::EndNotOnFloor;
    else if (out.wrong_figures)
        out.verdict = LinkVerdict::WrongFigures;
    else if (out.inconclusive)
        out.verdict = LinkVerdict::Inconclusive;
    else
        out.verdict = LinkVerdict::Ok;
    return out;
}

}  // namespace nl::test
