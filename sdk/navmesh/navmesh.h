// A navmesh: convex (seen from above) polygons facing up, their adjacency, outline and surface
// detail, in flat arrays. Immutable once built, so any number of threads may read it and a query
// can keep its own reference (shared_ptr) while the world replaces it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "level/geometry.h"
#include "navmesh/navmesh_grid.h"
#include "navmesh/polygon_grid.h"
#include "navmesh/tiles.h"

namespace nl {

constexpr uint32_t kNoPolygon = 0xffffffffu;

constexpr uint32_t kMaxPolygonVertices = 16;
// A polygon's detail vertices besides its corners, at most (a detail triangle's corner is a byte).
constexpr uint32_t kMaxDetailVertices = 255 - kMaxPolygonVertices;
// A polygon's detail triangles, at most: a triangulation of 255 vertices has fewer.
constexpr uint32_t kMaxDetailTriangles = 512;

struct AgentType {
    float radius = 0.6f;
    float height = 2.0f;
    float max_climb = 0.9f;
    float max_slope = 45.0f;  // degrees
};

// Whether one body fits both (navmeshes eroded by the same radius, with the same headroom): a link
// or an agent made for one serves the other.
inline bool same_body(const AgentType& a, const AgentType& b) { return a.radius == b.radius && a.height == b.height; }
// Whether two navmeshes were made for the very same agent type: tiles of one navmesh must be.
inline bool same_agent_type(const AgentType& a, const AgentType& b) {
    return same_body(a, b) && a.max_climb == b.max_climb && a.max_slope == b.max_slope;
}

struct BoundaryEdge {
    Vec3 start;  // in the polygon's counter-clockwise order
    Vec3 end;
    Vec3 outward;  // unit, in the polygon's plane, away from it
    Vec3 normal;   // the polygon's unit normal
    uint32_t polygon;
    uint32_t edge;  // from corner `edge` to corner `edge + 1`
};

// What the builder repaired, for the host to see.
struct NavMeshRepairs {
    uint32_t welded_vertices = 0;
    uint32_t flipped_polygons = 0;
    uint32_t dropped_polygons = 0;
    uint32_t non_manifold_edges = 0;
    uint32_t t_junction_corners = 0;  // corners inserted where an edge met others at T-junctions (t_junctions.h)
    uint32_t t_junctions_left = 0;    // edges left unjoined: their polygon had no room for the corners
};

struct NavPoint {
    bool found = false;
    Vec3 point = Vec3::Zero();
    float distance = 0.0f;
    uint32_t polygon = kNoPolygon;
};

struct NavMeshInput;

// The sum of the fan's triangle normals over the ring of `count` vertex indices (Newell's normal,
// twice the area vector): its y is twice the ring's area seen from above, signed by its winding.
inline Vec3 fan_normal(const std::vector<Vec3>& vertices, const uint32_t* ring, uint32_t count) {
    const Vec3& origin = vertices[ring[0]];
    Vec3 n = Vec3::Zero();
    for (uint32_t k = 1; k + 1 < count; ++k) n += (vertices[ring[k]] - origin).cross(vertices[ring[k + 1]] - origin);
    return n;
}

class NavMesh {
public:
    uint32_t polygon_count() const { return static_cast<uint32_t>(first_corner_.size() - 1); }
    uint32_t corner_count(uint32_t p) const { return first_corner_[p + 1] - first_corner_[p]; }
    // Vertex index of corner `k` of polygon `p`.
    uint32_t corner(uint32_t p, uint32_t k) const { return corners_[first_corner_[p] + k]; }
    // Polygon across the edge from corner k to k + 1, or kNoPolygon.
    uint32_t neighbour(uint32_t p, uint32_t k) const { return neighbours_[first_corner_[p] + k]; }
    // Edge k of polygon p numbered across the navmesh (0 .. edge_count() - 1), for per-edge flags.
    uint32_t edge_index(uint32_t p, uint32_t k) const { return first_corner_[p] + k; }
    uint32_t edge_count() const { return first_corner_.back(); }
    // Polygon p's corner_count(p) neighbours, for loops over its edges.
    const uint32_t* neighbours_of(uint32_t p) const { return &neighbours_[first_corner_[p]]; }
    // Polygon p's corner_count(p) corners (vertex indices), counter-clockwise seen from above.
    const uint32_t* corners_of(uint32_t p) const { return &corners_[first_corner_[p]]; }
    const Vec3& vertex(uint32_t v) const { return vertices_[v]; }
    uint32_t vertex_count() const { return static_cast<uint32_t>(vertices_.size()); }
    uint8_t area(uint32_t p) const { return areas_[p]; }
    // Polygon p's unit normal, pointing up (from its corners: computed when asked, not stored).
    Vec3 normal(uint32_t p) const {
        return fan_normal(vertices_, &corners_[first_corner_[p]], corner_count(p)).normalized();
    }
    Vec3 centre(uint32_t p) const;
    const Aabb& polygon_bounds(uint32_t p) const { return polygon_bounds_[p]; }

    // True for a vertex on the navmesh's outline (a corner of a boundary or non-manifold edge):
    // a body wider than the navmesh's agent must keep away from it.
    bool on_outline(uint32_t v) const { return on_outline_[v] != 0; }

    // The outline, in polygon order. Stored as (polygon, edge) pairs and described on demand: the
    // description is seven times larger and only link generation and tools ask for it.
    uint32_t boundary_edge_count() const { return static_cast<uint32_t>(boundary_.size()); }
    BoundaryEdge boundary_edge(uint32_t i) const;
    std::vector<BoundaryEdge> boundary_edges() const;
    uint32_t portal_count() const { return portal_count_; }
    const AgentType& agent() const { return agent_; }
    const Aabb& bounds() const { return bounds_; }
    const NavMeshRepairs& repairs() const { return repairs_; }
    // The tiles it was joined from (tile_join.h), in row order; a solo navmesh has no grid and none.
    const TileLayout& tiles() const { return tiles_; }
    // Polygon p's tile, an index into tiles().tiles; 0 for a solo navmesh.
    uint32_t tile_of(uint32_t p) const { return polygon_tiles_.empty() ? 0 : polygon_tiles_[p]; }
    // A fingerprint of the polygons of the tile at `coord` as joined (their corners' coordinates, in
    // order): equal in two navmeshes when that tile's polygons are the same in both (a neighbour that
    // changed can move its border corners: then it differs). 0 when the tile is not loaded.
    uint64_t tile_fingerprint(const TileCoord& coord) const;

    // The navmesh point for `point` among the polygons overlapping `point +- half_extents`: on the
    // polygon straight below or above it within the agent's max_climb if there is one (as Detour's
    // findNearestPoly), else the closest.
    NavPoint find_nearest(const Vec3& point, const Vec3& half_extents) const;
    // The same by visiting every polygon: the reference the grid is tested against.
    NavPoint find_nearest_brute_force(const Vec3& point, const Vec3& half_extents) const;
    // The same over the whole navmesh, starting from the box: what a query that found nothing in its
    // box was missing. Not found only for a navmesh without polygons.
    NavPoint find_nearest_anywhere(const Vec3& point, const Vec3& half_extents) const;
    // As Detour: over the polygon (seen from above), the surface point straight below or above
    // `point`, at the detail height; elsewhere the nearest point of the polygon's outline.
    Vec3 closest_point_on_polygon(uint32_t p, const Vec3& point) const;
    bool over_polygon(uint32_t p, float x, float z) const;
    // Whether (x, z) lies within polygon p's bounds seen from above: outside them it is never over
    // the polygon, whatever the edge tests' float rounding says near the tip of a long, thin one.
    bool over_bounds(uint32_t p, float x, float z) const {
        const Aabb& box = polygon_bounds_[p];
        return x >= box.min.x() && x <= box.max.x() && z >= box.min.z() && z <= box.max.z();
    }
    // Heap bytes held, for comparing memory with other navmesh formats.
    size_t memory_bytes() const;
    // Height of polygon p's surface (detail triangles, or its own fan) at (x, z) over it.
    float surface_height(uint32_t p, float x, float z) const;

private:
    friend class NavMeshBuilder;
    friend NavMeshInput input_of(const NavMesh& navmesh);

    std::vector<Vec3> vertices_;
    std::vector<uint32_t> first_corner_;  // polygon_count + 1 offsets into corners_ / neighbours_
    std::vector<uint32_t> corners_;
    std::vector<uint32_t> neighbours_;
    std::vector<uint8_t> areas_;
    std::vector<uint8_t> on_outline_;  // per vertex
    std::vector<Aabb> polygon_bounds_;
    // Surface: detail triangles per polygon, when the source had them, as Detour keeps them: each
    // corner a byte, below the polygon's corner count one of its corners, from there one of its own
    // detail vertices (those that are not corners; at most kMaxDetailVertices per polygon).
    using DetailTriangle = std::array<uint8_t, 3>;
    struct DetailRange {
        uint32_t first_triangle;
        uint32_t first_vertex;
    };
    Vec3 detail_point(uint32_t p, uint8_t local) const {
        const uint32_t corners = corner_count(p);
        return local < corners ? vertices_[corner(p, local)]
                               : detail_vertices_[detail_[p].first_vertex + (local - corners)];
    }
    std::vector<Vec3> detail_vertices_;
    std::vector<DetailTriangle> detail_triangles_;
    std::vector<DetailRange> detail_;  // polygon_count + 1 ranges; empty when there is no detail
    struct EdgeRef {                   // four bytes: corners are fewer than 16, polygons fewer than 2^28
        uint32_t polygon : 28;
        uint32_t edge : 4;
    };
    std::vector<EdgeRef> boundary_;
    PolygonGrid grid_;
    uint32_t portal_count_ = 0;
    AgentType agent_;
    Aabb bounds_;
    NavMeshRepairs repairs_;
    TileLayout tiles_;
    std::vector<uint32_t> polygon_tiles_;      // per polygon when tiled
    std::vector<uint64_t> tile_fingerprints_;  // per tile of tiles_, when tiled
};

}  // namespace nl
