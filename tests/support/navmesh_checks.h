// Structural checks every navmesh must pass, whatever made it.
#pragma once

#include <string>

#include "navmesh/navmesh.h"

namespace nl::test {

// Returns "" when the navmesh is sound, else the first problem found:
//  - polygons: >= 3 corners, unit normal pointing up, convex seen from above;
//  - adjacency: symmetric, across the same two vertices;
//  - every edge is a portal (2 owners), a boundary edge (1 owner) or non-manifold (3+), and the
//    counts add up to the number of polygon edges;
//  - boundary edges: outward is unit, perpendicular to the edge and to the normal, and points away
//    from the polygon (a point just outside the edge's middle is not inside the polygon from above).
std::string check_navmesh(const NavMesh& mesh);

}  // namespace nl::test
