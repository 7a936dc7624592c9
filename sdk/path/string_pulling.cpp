#include "path/string_pulling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nl {
namespace {

// Twice the signed area of triangle a b c in x-z, with Detour's sign (dtTriArea2D), so that the
// funnel below reads as Detour's: positive when c is on the walker's left looking along a -> b.
float area2(const Vec3& a, const Vec3& b, const Vec3& c) {
    const float abx = b.x() - a.x(), abz = b.z() - a.z();
    const float acx = c.x() - a.x(), acz = c.z() - a.z();
    return acx * abz - abx * acz;
}

bool same_xz(const Vec3& a, const Vec3& b) {
    const float dx = a.x() - b.x(), dz = a.z() - b.z();
    return dx * dx + dz * dz < 1e-12f;
}

// Whether p lies on the segment a b seen from above, within the rounding of coordinates that large.
bool on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const double abx = double(b.x()) - a.x(), abz = double(b.z()) - a.z();
    const double apx = double(p.x()) - a.x(), apz = double(p.z()) - a.z();
    const double t = std::clamp((apx * abx + apz * abz) / std::max(abx * abx + abz * abz, 1e-300), 0.0, 1.0);
    const double dx = apx - t * abx, dz = apz - t * abz;
    const double rounding =
        1e-5 + 4.0 * std::numeric_limits<float>::epsilon() * std::max({std::fabs(p.x()), std::fabs(p.z())});
    return dx * dx + dz * dz <= rounding * rounding;
}

}  // namespace

void pull_string(const Vec3& start, const Vec3& end, const std::vector<PortalSpan>& portals,
                 std::vector<PulledPoint>& out) {
    const uint32_t count = static_cast<uint32_t>(portals.size()) + 2;
    auto left_of = [&](uint32_t i) -> const Vec3& {
        return i == 0 ? start : i + 1 == count ? end : portals[i - 1].left;
    };
    auto right_of = [&](uint32_t i) -> const Vec3& {
        return i == 0 ? start : i + 1 == count ? end : portals[i - 1].right;
    };

    // A start on the first portals (located on an edge: a tile's border, most often) stands in the
    // polygons beyond them too, and the funnel starts there: from a start on a portal, both sides of
    // the funnel would lie along the portal's line, and the first portal end met on that line would
    // turn it (a walk out to the portal's end and back: undulating.obj's tiles, 41 m for 14).
    uint32_t first = 1;
    while (first + 1 < count && on_segment(start, portals[first - 1].left, portals[first - 1].right)) ++first;
    out.push_back({start, first - 1});
    Vec3 apex = start, left = start, right = start;
    uint32_t apex_index = first - 1, left_index = first - 1, right_index = first - 1;
    // A side of the funnel crossed the other: that side's end is a corner of the path, and the
    // funnel starts again from it (the loop resumes at the portal after it).
    auto turn_at = [&](const Vec3& corner, uint32_t corner_index) {
        apex = left = right = corner;
        apex_index = left_index = right_index = corner_index;
        out.push_back({corner, corner_index});
        return corner_index;
    };
    for (uint32_t i = first; i < count; ++i) {
        const Vec3& next_left = left_of(i);
        const Vec3& next_right = right_of(i);
        // Narrow the funnel from the right, unless that crosses the left side.
        if (area2(apex, right, next_right) <= 0.0f) {
            if (same_xz(apex, right) || area2(apex, left, next_right) > 0.0f) {
                right = next_right;
                right_index = i;
            } else {
                i = turn_at(left, left_index);
                continue;
            }
        }
        if (area2(apex, left, next_left) >= 0.0f) {
            if (same_xz(apex, left) || area2(apex, right, next_left) < 0.0f) {
                left = next_left;
                left_index = i;
            } else {
                i = turn_at(right, right_index);
                continue;
            }
        }
    }
    if (!same_xz(out.back().position, end) || out.size() == 1) {
        out.push_back({end, count - 1});
    } else {
        out.back() = {end, count - 1};
    }
}

WalkedLine walk_line(const std::vector<PulledPoint>& pulled, const std::vector<PortalSpan>& portals,
                     const std::vector<float>& rates) {
    WalkedLine walked;
    auto stretch = [&](const Vec3& from, const Vec3& to, size_t polygon) {
        walked.length += (to - from).norm();
        const double dx = double(to.x()) - from.x(), dz = double(to.z()) - from.z();
        walked.cost += std::sqrt(dx * dx + dz * dz) * rates[polygon];
    };
    for (size_t i = 1; i < pulled.size(); ++i) {
        const Vec3& from = pulled[i - 1].position;
        const Vec3& to = pulled[i].position;
        Vec3 here = from;
        // Pulled point j stands at portal j - 1: the line between two of them crosses the portals
        // after the first's and before the second's, the stretch before portal k lying in polygon k.
        size_t k = pulled[i - 1].portal;
        for (; k + 1 < pulled[i].portal && k < portals.size(); ++k) {
            const PortalSpan& span = portals[k];
            const float ex = span.right.x() - span.left.x(), ez = span.right.z() - span.left.z();
            const float dx = to.x() - from.x(), dz = to.z() - from.z();
            const float denominator = ex * dz - ez * dx;
            if (std::fabs(denominator) < 1e-12f) continue;  // along the portal: no crossing to add
            const float s = ((from.x() - span.left.x()) * dz - (from.z() - span.left.z()) * dx) / denominator;
            const Vec3 crossing = span.left + std::clamp(s, 0.0f, 1.0f) * (span.right - span.left);
            stretch(here, crossing, k);
            here = crossing;
        }
        stretch(here, to, std::min(k, portals.size()));
    }
    return walked;
}

}  // namespace nl
