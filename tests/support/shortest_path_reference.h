// The exact cheapest way between two points of a navmesh, seen from above, for one body with its
// links: the slow, trusted side of the path search's comparisons (issue 20). It shares no code with
// the library's searches (corridor, exact corridor, string pulling); it reads the navmesh, and takes
// the rules of the game from the two functions that define them: portal_span (where a body wider
// than the navmesh's agent may cross a portal) and can_take (which links a body may take).
//
// What it computes. The body's margin is m = max(0, body radius - navmesh agent radius). A polygon is
// open to the body unless its area costs it 0 (excluded); every open polygon must cost the same per
// metre, c (1 by default; the reference refuses areas of different costs). An allowed walk is a chain
// of straight pieces, each inside (or on the edge of) one open polygon seen from above, that passes
// from a polygon to its neighbour only across their shared edge and only within that edge's opening
// portal_span(navmesh, p, k, m) (with m = 0 the whole edge; an edge portal_span closes, an edge to an
// excluded polygon or to none is a wall). Two polygons touching at a corner alone have no way between
// them, and no walk steps onto another floor above or below (it starts on the polygons holding the
// start within the navmesh agent's max_climb of it). A link (enabled, both ends on this navmesh) is
// taken in each direction the body can_take it (the start to the end; the end to the start too when
// bidirectional) whose landing polygon is open: the walk reaches its take-off point in the take-off
// polygon (link.start_polygon, or end_polygon reversed), and goes on from its landing point in the
// landing polygon. The cost of a route is c times the x-z length walked plus, per link taken, its 3D
// length |to - from| times link.cost_modifier plus the query's link_cost. `length` is the cheapest
// cost over all routes of walks and links from start to goal (with no links and c = 1: the shortest
// walk's x-z length, what the funnel minimises).
//
// How. Dijkstra (A* with the straight distance times the cheapest rate per metre as its estimate)
// over the points where a cheapest route can turn: the start, the goal, each usable link's take-off
// and landing points, and the bend points: with m = 0 the navmesh vertices where the open polygons
// round them fill more than half a turn and a wall ends (the reflex corners of the outline and of
// excluded areas); with m > 0 the ends portal_span moves (the narrowed portal ends, where a blocked
// stretch of portal ends) and the vertices off the outline where a wall (a closed portal, an edge to
// an excluded polygon) ends. A cheapest route bends only where an obstacle ends or turns: the walls
// are the outline, edges to excluded polygons, closed portals and, with m > 0, each portal's stretch
// within m of an outline end; at an outline vertex itself a wider body never bends (every portal
// there is narrowed away from it, and within one convex polygon bending gains nothing). With
// `every_vertex` the bend points are instead every vertex plus every narrowed portal end: slower, for
// checking that set. Walk edges join any two of these points whose straight segment is an allowed
// walk (decided piece by piece between the segment's crossings with polygon edges, each crossing
// allowed through the polygons round the crossing point whose shared edges' openings hold it, within
// 1e-6 m); a point that several groups of polygons hold with no allowed way between them (a closed
// portal's end) is one node per group. Link edges join take-off to landing.
//
// Not thread-safe: it remembers which pairs of points see each other across calls.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "links/link_snapshot.h"
#include "navmesh/navmesh.h"
#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl::test {

class ShortestPathReference {
public:
    // A body as thin as the navmesh's agent (margin 0), no links, every area open at cost 1.
    explicit ShortestPathReference(const NavMesh& navmesh);
    // The body of `query` (agent: radius and capabilities, link_cost, area_costs; its ends are not
    // read) on the navmesh with these links (their start_polygon/end_polygon as placed on it).
    ShortestPathReference(const NavMesh& navmesh, const PathQuery& query, const LinkSnapshot& links = {},
                          bool every_vertex = false);
    // The same with the graph's navmesh and links.
    ShortestPathReference(const PathGraph& graph, const PathQuery& query, bool every_vertex = false);

    // The cheapest route's cost from `start` to `goal` (see above: with no links and every area at
    // cost 1, the shortest walk's x-z length), or nothing when no route joins them; `bends` (optional)
    // receives the points it turns at, take-off and landing points included.
    std::optional<double> length(const Vec3& start, const Vec3& goal, std::vector<Vec3>* bends = nullptr) const;

    // Whether the straight segment from a to b is an allowed walk for the body, seen from above.
    bool walkable(const Vec3& a, const Vec3& b) const;

    float margin() const { return margin_; }
    // How many points a route may turn at (bend points, take-off and landing points).
    size_t node_count() const { return nodes_.size(); }

private:
    struct Flat {
        double x, z;
    };
    struct Node {
        Vec3 point;
        Flat at;
        std::vector<uint32_t> polygons;  // the polygons the route is in there (one group)
    };
    struct Opening {  // an edge's opening to the body, from its polygon's side
        bool open = false;
        Flat left{0, 0}, right{0, 0};  // seen from above
        Vec3 left_point = Vec3::Zero(), right_point = Vec3::Zero();
    };
    struct LinkEdge {
        uint32_t takeoff, landing;  // node indices
        double cost;
    };

    void build(const PathQuery& query, const LinkSnapshot& links, bool every_vertex);
    Flat corner_at(uint32_t p, uint32_t k) const { return flat_[first_[p] + k]; }
    // The open polygons among `among` (all when null) holding a point, seen from above.
    void containing(const Flat& q, const std::vector<uint32_t>* among, std::vector<uint32_t>& out) const;
    // The open polygons holding a point whose surface there is within the navmesh agent's climb of it.
    void on_floor(const Vec3& point, std::vector<uint32_t>& out) const;
    // The groups of `polygons` (all holding point x) the body passes between at x.
    std::vector<std::vector<uint32_t>> groups(const Flat& x, const std::vector<uint32_t>& polygons) const;
    // Whether the body may pass from polygon p across its edge k at point x.
    bool crosses_at(uint32_t p, uint32_t k, const Flat& x) const;
    // The polygons of `after` a walk in `before` reaches at point x held by the polygons `at_x`:
    // through them, across shared edges whose openings hold x.
    void reached_from(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after,
                      const std::vector<uint32_t>& at_x, const Flat& x, std::vector<uint32_t>& out) const;
    // Whether the straight walk from a (in the polygons `from`) to b (ending in one of `to`) is allowed.
    bool walk_joins(const Flat& a, const std::vector<uint32_t>& from, const Flat& b,
                    const std::vector<uint32_t>& to) const;
    bool nodes_see(uint32_t i, uint32_t j) const;
    std::vector<Node> nodes_at(const Vec3& point) const;

    const NavMesh& navmesh_;
    float margin_ = 0.0f;
    double walk_rate_ = 1.0;       // cost per metre walked
    double cheapest_rate_ = 1.0;   // the smallest cost per metre of walking or any usable link
    std::vector<uint32_t> first_;  // per polygon + 1: offsets into flat_ and openings_ (edge_index order)
    std::vector<Flat> flat_;       // corners seen from above
    std::vector<Opening> openings_;
    std::vector<uint8_t> open_;  // per polygon: not excluded
    std::vector<double> box_;    // per polygon: min x, min z, max x, max z
    std::vector<Node> nodes_;    // bend points, then take-off and landing points
    std::vector<LinkEdge> link_edges_;
    std::vector<std::vector<uint32_t>> links_from_;  // per node: its link_edges_
    mutable std::vector<int8_t> sees_;               // nodes_ x nodes_: -1 not yet known, 0 no, 1 yes
};

// The x-z length a path walks, what the reference's length is without links: the sum of its
// points' distances seen from above.
double xz_length(const PathResult& result);

}  // namespace nl::test
