// The exact shortest walk between two points of a navmesh, seen from above: the slow,
// trusted side of the path search's comparisons (issue 20). A shortest path in a polygonal domain
// bends only at corners of its outline, so the answer is Dijkstra over the visibility graph of the
// outline's corners and the two ends. Visibility is decided in the plane and independently of the
// library's walks: a segment is walkable when every piece between its crossings with polygon edges has
// its middle inside some polygon and each piece is reached from the one before through polygons
// around their cut point that share edges (two polygons touching at a corner alone have no portal:
// no walk squeezes through there), never stepping onto another floor above or below. Agent radius
// equal to the navmesh's (no margin), no links, no area costs: lengths are x-z metres, the quantity
// the funnel minimises.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "navmesh/navmesh.h"

namespace nl::test {

class ShortestPathReference {
public:
    explicit ShortestPathReference(const NavMesh& navmesh);

    // The shortest walk's x-z length from `start` to `goal` (both on the navmesh, seen from above),
    // or nothing when no walk joins them; `bends` (optional) receives the corners it bends at.
    std::optional<double> length(const Vec3& start, const Vec3& goal, std::vector<Vec3>* bends = nullptr) const;

    // Whether the straight segment from a to b stays on the navmesh, seen from above.
    bool walkable(const Vec3& a, const Vec3& b) const;

private:
    // The polygons holding a point (on an edge: both), seen from above.
    void containing(double x, double z, std::vector<uint32_t>& out) const;
    // The polygons of `after` a walk in `before` reaches at a cut point held by the polygons
    // `at_cut`: through them from shared edge to shared edge.
    void reached_from(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after,
                      const std::vector<uint32_t>& at_cut, std::vector<uint32_t>& out) const;
    // The polygons holding a point whose surface there is within the navmesh agent's climb of it.
    void on_floor(const Vec3& point, std::vector<uint32_t>& out) const;

    const NavMesh& navmesh_;
    std::vector<Vec3> corners_;                   // the outline's corners: where a shortest walk may bend
    std::vector<std::vector<double>> corner_distance_;  // corner to corner, walkable pairs (else infinity)
};

}  // namespace nl::test
