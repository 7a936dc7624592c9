#include "navmesh_checks.h"

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace nl::test {

std::string check_navmesh(const NavMesh& m) {
    std::ostringstream problem;
    std::map<std::pair<uint32_t, uint32_t>, int> owners;
    size_t edges = 0, linked = 0;
    for (uint32_t p = 0; p < m.polygon_count(); ++p) {
        const uint32_t n = m.corner_count(p);
        if (n < 3) return (problem << "polygon " << p << " has " << n << " corners", problem.str());
        if (std::fabs(m.normal(p).norm() - 1.0f) > 1e-4f || m.normal(p).y() <= 0.0f)
            return (problem << "polygon " << p << " normal " << m.normal(p).transpose() << " is not unit and up",
                    problem.str());
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t a = m.corner(p, k), b = m.corner(p, (k + 1) % n);
            ++owners[{std::min(a, b), std::max(a, b)}];
            ++edges;
            const uint32_t q = m.neighbour(p, k);
            if (q == kNoPolygon) continue;
            ++linked;
            bool back = false;
            for (uint32_t j = 0; j < m.corner_count(q); ++j) {
                const uint32_t c = m.corner(q, j), d = m.corner(q, (j + 1) % m.corner_count(q));
                if (((c == a && d == b) || (c == b && d == a)) && m.neighbour(q, j) == p) back = true;
            }
            if (!back)
                return (problem << "polygon " << p << " edge " << k << " -> " << q << " is not linked back",
                        problem.str());
        }
    }
    size_t boundary_owned = 0, non_manifold_slots = 0;
    for (const auto& [edge, count] : owners) {
        if (count == 1) ++boundary_owned;
        if (count >= 3) non_manifold_slots += count;
    }
    if (boundary_owned != m.boundary_edges().size())
        return (problem << boundary_owned << " edges have one owner but " << m.boundary_edges().size()
                        << " boundary edges were listed",
                problem.str());
    if (linked != 2 * size_t(m.portal_count()))
        return (problem << linked << " linked edge slots for " << m.portal_count() << " portals", problem.str());
    if (edges != m.boundary_edges().size() + 2 * size_t(m.portal_count()) + non_manifold_slots)
        return (problem << "edges do not add up: " << edges << " slots", problem.str());
    if (non_manifold_slots > 0 && m.repairs().non_manifold_edges == 0) return "non-manifold edges were not counted";

    const std::vector<BoundaryEdge> outline = m.boundary_edges();
    for (size_t i = 0; i < outline.size(); ++i) {
        const BoundaryEdge& e = outline[i];
        const uint32_t a = m.corner(e.polygon, e.edge),
                       b = m.corner(e.polygon, (e.edge + 1) % m.corner_count(e.polygon));
        if (owners[{std::min(a, b), std::max(a, b)}] != 1)
            return (problem << "boundary edge " << i << " has other owners", problem.str());
        if (m.vertex(a) != e.start || m.vertex(b) != e.end)
            return (problem << "boundary edge " << i << " ends differ from its polygon's", problem.str());
        const Vec3 along = (e.end - e.start).normalized();
        // Across the edge, and in the polygon's plane up to the polygon's own bend along this edge.
        if (std::fabs(e.outward.norm() - 1.0f) > 1e-4f || std::fabs(e.outward.dot(along)) > 1e-4f ||
            std::fabs(e.outward.dot(e.normal)) > std::fabs(along.dot(e.normal)) + 1e-4f)
            return (problem << "boundary edge " << i << " outward " << e.outward.transpose()
                            << " is not unit, across the edge, in the plane",
                    problem.str());
        // Seen from above, outward is on the other side of the edge than the polygon's centre.
        auto side = [&](const Vec3& d) { return double(along.z()) * d.x() - double(along.x()) * d.z(); };
        const double centre_side = side(m.centre(e.polygon) - e.start);
        const double outward_side = side(e.outward);
        if (centre_side * outward_side > 0.0 || (centre_side == 0.0 && outward_side == 0.0))
            return (problem << "boundary edge " << i << " outward points into polygon " << e.polygon, problem.str());
    }
    return "";
}

}  // namespace nl::test
