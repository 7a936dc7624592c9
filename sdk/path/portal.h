// The part of a portal (an edge shared by two polygons) a body can pass through: a body wider than
// the navmesh's agent keeps the difference away from outline corners, the way Recast erodes the
// navmesh by the agent radius. Used by the search (which portals are open) and by string pulling
// (where the path may bend), so both agree.
#pragma once

#include <cmath>

#include "navmesh/navmesh.h"

namespace nl {

struct PortalSpan {
    Vec3 left;
    Vec3 right;
};

// How much wider than the body needs a narrowed portal must be to stay open. Without it a portal
// exactly twice the margin wide (a 1 m corridor for a body 0.5 m wider than the navmesh's) would stay
// open or close by float rounding of its width, and when open be a pinhole of no width.
constexpr float kPortalSlack = 0.001f;

// The opening from polygon p across its edge k (corner k to k + 1), seen walking out of p: left and
// right as the walker sees them. False if `margin` leaves no room: the portal is not at least
// kPortalSlack wider than the margins at its outline ends.
inline bool portal_span(const NavMesh& navmesh, uint32_t p, uint32_t k, float margin, PortalSpan& span) {
    const uint32_t n = navmesh.corner_count(p);
    const uint32_t a = navmesh.corner(p, k), b = navmesh.corner(p, k + 1 == n ? 0 : k + 1);
    // Corners run counter-clockwise seen from above (x right, z up), so walking out across a -> b,
    // a is on the left.
    span.left = navmesh.vertex(a);
    span.right = navmesh.vertex(b);
    if (margin <= 0.0f) return true;
    const bool left_on_outline = navmesh.on_outline(a), right_on_outline = navmesh.on_outline(b);
    if (!left_on_outline && !right_on_outline) return true;
    const Vec3 across = span.right - span.left;
    const float width = std::sqrt(across.x() * across.x() + across.z() * across.z());
    const float needed = margin * (float(left_on_outline) + float(right_on_outline));
    if (width < needed + kPortalSlack) return false;
    const Vec3 step = across * (margin / width);
    if (left_on_outline) span.left += step;
    if (right_on_outline) span.right -= step;
    return true;
}

}  // namespace nl
