#include "navmesh/navmesh_builder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "level/level_hash.h"
#include "level/mesh_validation.h"
#include "navmesh/edge_pairs.h"
#include "navmesh/t_junctions.h"
#include "navmesh/vertex_welder.h"
#include "util/error.h"

namespace nl {

class NavMeshBuilder {
public:
    explicit NavMeshBuilder(const NavMeshInput& input) : in_(input) {}

    std::shared_ptr<const NavMesh> build() {
        validate();
        weld();
        make_polygons();
        join_t_junctions_of_polygons();
        connect();
        finish();
        return std::move(mesh_);
    }

private:
    uint32_t input_polygon_count() const {
        return in_.polygon_sizes.empty() ? static_cast<uint32_t>(in_.indices.size() / 3)
                                         : static_cast<uint32_t>(in_.polygon_sizes.size());
    }

    void validate() const {
        static const char axis[] = {'x', 'y', 'z'};
        if (in_.vertices.empty()) fail_field(ErrorCode::InvalidArgument, "vertex_count is 0");
        if (in_.indices.empty()) fail_field(ErrorCode::InvalidArgument, "polygon_count is 0");
        if (input_polygon_count() >= (1u << 28))
            fail_field(ErrorCode::InvalidArgument, "polygon_count is ", input_polygon_count(), " (at most 2^28 - 1)");
        for (size_t i = 0; i < in_.vertices.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                const float value = in_.vertices[i][k];
                if (!std::isfinite(value) || std::fabs(value) > kCoordinateLimit)
                    fail_field(ErrorCode::InvalidArgument, "vertices[", i, "].", axis[k], " = ", value,
                               " is not finite or beyond the coordinate limit");
            }
        }
        if (in_.polygon_sizes.empty() && in_.indices.size() % 3 != 0)
            fail_field(ErrorCode::InvalidArgument, "indices has ", in_.indices.size(), " entries, not 3 per triangle");
        size_t expected = 0;
        for (size_t p = 0; p < in_.polygon_sizes.size(); ++p) {
            const uint32_t n = in_.polygon_sizes[p];
            if (n < 3 || n > kMaxPolygonVertices)
                fail_field(ErrorCode::InvalidArgument, "polygon_vertex_counts[", p, "] = ", n, " (must be 3..",
                           kMaxPolygonVertices, ")");
            expected += n;
        }
        if (!in_.polygon_sizes.empty() && expected != in_.indices.size())
            fail_field(ErrorCode::InvalidArgument, "indices has ", in_.indices.size(),
                       " entries but the polygon sizes add up to ", expected);
        for (size_t i = 0; i < in_.indices.size(); ++i) {
            if (in_.indices[i] >= in_.vertices.size())
                fail_field(ErrorCode::InvalidArgument, "indices[", i, "] = ", in_.indices[i],
                           " is out of range (vertex_count = ", in_.vertices.size(), ")");
        }
        if (!in_.areas.empty() && in_.areas.size() != input_polygon_count())
            fail_field(ErrorCode::InvalidArgument, "areas has ", in_.areas.size(), " entries for ",
                       input_polygon_count(), " polygons");
        if (!(in_.weld_tolerance >= 0.0f && in_.weld_tolerance <= 1.0f))
            fail_field(ErrorCode::InvalidArgument, "weld_tolerance is ", in_.weld_tolerance, " (must be 0..1 m)");
        naming_fields("agent_type.", [&] { validate_agent(in_.agent_type); });
        validate_detail();
        validate_tiles();
    }

    void validate_tiles() const {
        const TileGrid& grid = in_.tiles.grid;
        if (!grid.tiled() && in_.tiles.tiles.empty() && in_.polygon_tiles.empty() && in_.on_tile_border.empty()) return;
        if (!(std::isfinite(grid.tile_width) && grid.tile_width > 0.0f && grid.tile_width <= kCoordinateLimit))
            fail_field(ErrorCode::InvalidArgument, "tile_width is ", grid.tile_width, " (must be > 0 m)");
        if (!std::isfinite(grid.origin_x) || !std::isfinite(grid.origin_z) ||
            std::fabs(grid.origin_x) > kCoordinateLimit || std::fabs(grid.origin_z) > kCoordinateLimit)
            fail_field(ErrorCode::InvalidArgument, "tile_origin is not finite or beyond the coordinate limit");
        if (in_.tiles.tiles.empty()) fail_field(ErrorCode::InvalidArgument, "tiles: a tile grid but no tile");
        for (size_t t = 0; t < in_.tiles.tiles.size(); ++t) {
            const TileCoord& at = in_.tiles.tiles[t];
            const double far = std::max({std::fabs(grid.line_x(at.x)), std::fabs(grid.line_x(int64_t(at.x) + 1)),
                                         std::fabs(grid.line_z(at.z)), std::fabs(grid.line_z(int64_t(at.z) + 1))});
            if (std::fabs(double(at.x)) > kMaxTileIndex || std::fabs(double(at.z)) > kMaxTileIndex ||
                !(far <= kCoordinateLimit))
                fail_field(ErrorCode::InvalidArgument, "tile_x, tile_z: tile (", at.x, ", ", at.z,
                           ") lies beyond the coordinate limit (or its index beyond 2^30)");
        }
        for (size_t t = 0; t + 1 < in_.tiles.tiles.size(); ++t)
            if (!(in_.tiles.tiles[t] < in_.tiles.tiles[t + 1]))
                fail_field(ErrorCode::InvalidArgument, "tiles[", t + 1, "] is out of row order or given twice");
        if (!in_.polygon_tiles.empty() && in_.polygon_tiles.size() != input_polygon_count())
            fail_field(ErrorCode::InvalidArgument, "polygon_tiles has ", in_.polygon_tiles.size(), " entries for ",
                       input_polygon_count(), " polygons");
        for (size_t p = 0; p < in_.polygon_tiles.size(); ++p)
            if (in_.polygon_tiles[p] >= in_.tiles.tiles.size())
                fail_field(ErrorCode::InvalidArgument, "polygon_tiles[", p, "] = ", in_.polygon_tiles[p],
                           " is out of range (", in_.tiles.tiles.size(), " tiles)");
        if (in_.polygon_tiles.empty() && in_.tiles.tiles.size() != 1)
            fail_field(ErrorCode::InvalidArgument, "polygon_tiles: ", in_.tiles.tiles.size(),
                       " tiles but no polygon's tile");
        if (!in_.on_tile_border.empty() && in_.on_tile_border.size() != in_.vertices.size())
            fail_field(ErrorCode::InvalidArgument, "on_tile_border has ", in_.on_tile_border.size(), " entries for ",
                       in_.vertices.size(), " vertices");
        if (!(in_.tile_border_height_tolerance >= 0.0f && in_.tile_border_height_tolerance <= 100.0f))
            fail_field(ErrorCode::InvalidArgument, "tile_border_height_tolerance is ",
                       in_.tile_border_height_tolerance);
    }

    void validate_detail() const {
        if (in_.detail_starts.empty()) {
            if (!in_.detail_indices.empty() || !in_.detail_vertices.empty())
                fail_field(ErrorCode::InvalidArgument,
                           "detail_triangle_starts: detail triangles are given without detail_triangle_starts");
            return;
        }
        if (in_.detail_starts.size() != input_polygon_count() + 1)
            fail_field(ErrorCode::InvalidArgument,
                       "detail_triangle_starts needs polygon_count + 1 = ", input_polygon_count() + 1, " entries");
        const uint32_t triangles = static_cast<uint32_t>(in_.detail_indices.size() / 3);
        if (in_.detail_starts.front() != 0 || in_.detail_starts.back() != triangles)
            fail_field(ErrorCode::InvalidArgument,
                       "detail_triangle_starts must run from 0 to the detail triangle count");
        for (size_t p = 0; p + 1 < in_.detail_starts.size(); ++p) {
            if (in_.detail_starts[p + 1] <= in_.detail_starts[p])
                fail_field(ErrorCode::InvalidArgument, "detail_triangle_starts[", p + 1,
                           "]: every polygon needs at least one detail triangle, in order");
            if (in_.detail_starts[p + 1] - in_.detail_starts[p] > kMaxDetailTriangles)
                fail_field(ErrorCode::InvalidArgument, "detail_triangle_starts[", p + 1, "]: polygon ", p, " has ",
                           in_.detail_starts[p + 1] - in_.detail_starts[p], " detail triangles (at most ",
                           kMaxDetailTriangles, ")");
        }
        for (size_t i = 0; i < in_.detail_vertices.size(); ++i) {
            if (!within_coordinate_limit(in_.detail_vertices[i]))
                fail_field(ErrorCode::InvalidArgument, "detail_vertices[", i,
                           "] is not finite or beyond the coordinate limit");
        }
        for (size_t i = 0; i < in_.detail_indices.size(); ++i) {
            if (in_.detail_indices[i] >= in_.detail_vertices.size())
                fail_field(ErrorCode::InvalidArgument, "detail_triangles[", i, "] = ", in_.detail_indices[i],
                           " is out of range (detail_vertex_count = ", in_.detail_vertices.size(), ")");
        }
    }

    // Welded vertices on the navmesh grid, renumbered densely in input order.
    void weld() {
        std::vector<Vec3> on_grid(in_.vertices.size());
        for (size_t i = 0; i < on_grid.size(); ++i) on_grid[i] = on_navmesh_grid(in_.vertices[i]);
        const std::vector<uint32_t> representative = weld_vertices(on_grid, in_.weld_tolerance);
        remap_.assign(in_.vertices.size(), kNoPolygon);
        for (uint32_t i = 0; i < representative.size(); ++i) {
            if (representative[i] != i) {
                ++mesh_->repairs_.welded_vertices;
                continue;
            }
            remap_[i] = static_cast<uint32_t>(mesh_->vertices_.size());
            mesh_->vertices_.push_back(on_grid[i]);
        }
        for (uint32_t i = 0; i < representative.size(); ++i) remap_[i] = remap_[representative[i]];
        if (in_.on_tile_border.empty()) return;
        on_tile_border_.assign(mesh_->vertices_.size(), 0);
        for (uint32_t i = 0; i < remap_.size(); ++i) on_tile_border_[remap_[i]] |= in_.on_tile_border[i];
    }

    void make_polygons() {
        NavMesh& m = *mesh_;
        m.first_corner_.push_back(0);
        const bool has_detail = !in_.detail_starts.empty();
        if (has_detail) m.detail_.push_back(NavMesh::DetailRange{0, 0});
        std::vector<uint32_t> detail_vertex_remap(in_.detail_vertices.size(),
                                                  kNoPolygon);  // input -> local, this polygon
        std::vector<uint32_t> remapped;                         // the input detail vertices this polygon remapped

        size_t offset = 0;
        const uint32_t count = input_polygon_count();
        std::vector<uint32_t> ring;
        for (uint32_t p = 0; p < count; ++p) {
            const uint32_t n = in_.polygon_sizes.empty() ? 3u : in_.polygon_sizes[p];
            ring.clear();
            for (uint32_t k = 0; k < n; ++k) {
                const uint32_t v = remap_[in_.indices[offset + k]];
                if (ring.empty() || ring.back() != v) ring.push_back(v);
            }
            offset += n;
            while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();

            const Vec3 normal = ring.size() >= 3
                                    ? fan_normal(m.vertices_, ring.data(), static_cast<uint32_t>(ring.size()))
                                    : Vec3::Zero();
            // Half the normal's y is the area seen from above: none means nothing to walk on.
            if (ring.size() < 3 || std::fabs(normal.y()) <= 2e-9f) {
                ++m.repairs_.dropped_polygons;
                continue;
            }
            if (normal.y() < 0.0f) {
                std::reverse(ring.begin(), ring.end());
                ++m.repairs_.flipped_polygons;
            }
            check_convex_from_above(ring, p);

            Aabb box;
            for (uint32_t v : ring) {
                m.corners_.push_back(v);
                box.grow(m.vertices_[v]);
            }
            m.first_corner_.push_back(static_cast<uint32_t>(m.corners_.size()));
            m.areas_.push_back(in_.areas.empty() ? 0 : in_.areas[p]);
            if (!in_.polygon_tiles.empty()) m.polygon_tiles_.push_back(in_.polygon_tiles[p]);
            if (has_detail) {
                // Each triangle corner as a byte: a corner of the polygon where the detail vertex lies
                // over it (the same x and z on the grid; its height is then the corner's, as Detour
                // keeps it), else the polygon's own next detail vertex.
                const uint32_t first_vertex = static_cast<uint32_t>(m.detail_vertices_.size());
                for (uint32_t t = in_.detail_starts[p]; t < in_.detail_starts[p + 1]; ++t) {
                    NavMesh::DetailTriangle tri;
                    for (int k = 0; k < 3; ++k) {
                        const uint32_t input = in_.detail_indices[3 * t + k];
                        uint32_t& local = detail_vertex_remap[input];
                        if (local == kNoPolygon) {
                            const Vec3 point = on_navmesh_grid(in_.detail_vertices[input]);
                            const auto at = std::find_if(ring.begin(), ring.end(), [&](uint32_t v) {
                                return m.vertices_[v].x() == point.x() && m.vertices_[v].z() == point.z();
                            });
                            if (at != ring.end()) {
                                local = static_cast<uint32_t>(at - ring.begin());
                            } else {
                                if (m.detail_vertices_.size() - first_vertex >= kMaxDetailVertices)
                                    fail_field(ErrorCode::InvalidArgument, "detail_triangle_starts[", p, "]: polygon ",
                                               p, " has more than ", kMaxDetailVertices,
                                               " detail vertices besides its corners");
                                local = static_cast<uint32_t>(ring.size() + m.detail_vertices_.size() - first_vertex);
                                m.detail_vertices_.push_back(point);
                            }
                            remapped.push_back(input);
                            box.grow(local < ring.size() ? m.vertices_[ring[local]] : point);
                        }
                        tri[k] = static_cast<uint8_t>(local);
                    }
                    m.detail_triangles_.push_back(tri);
                }
                for (uint32_t input : remapped) detail_vertex_remap[input] = kNoPolygon;
                remapped.clear();
                // The next polygon's range starts where this one's ends.
                m.detail_.push_back(NavMesh::DetailRange{static_cast<uint32_t>(m.detail_triangles_.size()),
                                                         static_cast<uint32_t>(m.detail_vertices_.size())});
            }
            m.polygon_bounds_.push_back(box);
        }
        if (m.polygon_count() == 0)
            fail_field(ErrorCode::InvalidArgument, "indices: all ", count, " polygons are degenerate");
    }

    // Navmesh polygons are 2.5D: convex in x-z, heights free (Recast's are not planar).
    void check_convex_from_above(const std::vector<uint32_t>& ring, uint32_t p) const {
        const size_t n = ring.size();
        double turning = 0.0;
        for (size_t k = 0; k < n; ++k) {
            const Vec3& a = mesh_->vertices_[ring[k]];
            const Vec3& b = mesh_->vertices_[ring[(k + 1) % n]];
            const Vec3& c = mesh_->vertices_[ring[(k + 2) % n]];
            const double e1x = b.x() - a.x(), e1z = b.z() - a.z(), e2x = c.x() - b.x(), e2z = c.z() - b.z();
            // With the normal up, every corner of a convex polygon turns the same way: (e1 x e2).y >= 0.
            const double cross_y = e1z * e2x - e1x * e2z;
            const double lengths = std::sqrt((e1x * e1x + e1z * e1z) * (e2x * e2x + e2z * e2z));
            // Corners on the navmesh grid moved up to 0.7 mm: a straight corner may turn by that much.
            const double grid_slack =
                1.5 * std::ldexp(1.0, kNavMeshGridExponent) * (std::hypot(e1x, e1z) + std::hypot(e2x, e2z));
            if (cross_y < -std::max(1e-4 * lengths, grid_slack))
                fail_field(ErrorCode::InvalidArgument, "indices: polygon ", p,
                           " is not convex seen from above (at corner ", (k + 1) % n, ")");
            turning += std::atan2(cross_y, e1x * e2x + e1z * e2z);
        }
        // A star (self-crossing) polygon turns every corner the same way but winds twice.
        constexpr double kTwoPi = 6.283185307179586;
        if (std::fabs(turning) > kTwoPi + 0.1)
            fail_field(ErrorCode::InvalidArgument, "indices: polygon ", p, " crosses itself");
    }

    // Edges that meet others at T-junctions get those corners (t_junctions.h), so that connect() pairs them.
    // The tolerance is the weld's, but at least the navmesh grid's rounding of a corner on a straight edge;
    // a weld tolerance of 0 takes the polygons' topology as given, and joins nothing either, but along
    // the lines between tiles (tile_join.h), where heights may differ by the body's climb.
    void join_t_junctions_of_polygons() {
        if (in_.weld_tolerance == 0.0f && on_tile_border_.empty()) return;
        NavMesh& m = *mesh_;
        const float on_grid = float(1.5 * std::ldexp(1.0, kNavMeshGridExponent));
        TJunctionTolerance tolerance;
        tolerance.anywhere = in_.weld_tolerance == 0.0f ? 0.0f : std::max(in_.weld_tolerance, on_grid);
        tolerance.on_tile_border = &on_tile_border_;
        tolerance.tile_border = on_grid;
        tolerance.tile_border_height = in_.tile_border_height_tolerance;
        JoinedPolygons joined =
            join_t_junctions(m.vertices_, m.first_corner_, m.corners_, tolerance, kMaxPolygonVertices);
        m.repairs_.t_junction_corners = joined.inserted;
        m.repairs_.t_junctions_left = joined.left_open;
        if (joined.inserted == 0) return;
        for (uint32_t p = 0; p < m.polygon_count(); ++p) {
            const uint32_t before = m.first_corner_[p + 1] - m.first_corner_[p];
            const uint32_t after = joined.first_corner[p + 1] - joined.first_corner[p];
            if (after == before) continue;
            for (uint32_t slot = joined.first_corner[p]; slot < joined.first_corner[p + 1]; ++slot)
                m.polygon_bounds_[p].grow(m.vertices_[joined.corners[slot]]);
            if (m.detail_.empty()) continue;
            // A detail triangle names a corner by its index, then its own vertices after the corners.
            for (uint32_t t = m.detail_[p].first_triangle; t < m.detail_[p + 1].first_triangle; ++t)
                for (uint8_t& local : m.detail_triangles_[t])
                    local = local < before ? joined.moved_corner[m.first_corner_[p] + local]
                                           : static_cast<uint8_t>(local + (after - before));
        }
        m.first_corner_ = std::move(joined.first_corner);
        m.corners_ = std::move(joined.corners);
    }

    // Portals, boundary edges and non-manifold edges, from the edges sorted by their vertex pair.
    void connect() {
        NavMesh& m = *mesh_;
        const std::vector<KeyedEdge> edges = edges_by_vertex_pair(m.first_corner_, m.corners_);
        m.neighbours_.assign(m.corners_.size(), kNoPolygon);
        m.on_outline_.assign(m.vertices_.size(), 0);
        for (size_t i = 0; i < edges.size();) {
            size_t j = i;
            while (j < edges.size() && edges[j].key == edges[i].key) ++j;
            if (j - i == 2) {
                m.neighbours_[edges[i].slot] = edges[i + 1].polygon;
                m.neighbours_[edges[i + 1].slot] = edges[i].polygon;
                ++m.portal_count_;
            } else {
                // A boundary edge, or one of three or more polygons (it connects none): the walkable surface ends.
                m.on_outline_[static_cast<uint32_t>(edges[i].key >> 32)] = 1;
                m.on_outline_[static_cast<uint32_t>(edges[i].key)] = 1;
            }
            if (j - i > 2) {
                ++m.repairs_.non_manifold_edges;  // no neighbours, not an outline either
            } else if (j - i == 1) {
                boundary_slots_.push_back(edges[i].slot);
            }
            i = j;
        }
        std::sort(boundary_slots_.begin(), boundary_slots_.end());
    }

    void finish() {
        NavMesh& m = *mesh_;
        uint32_t p = 0;
        for (uint32_t slot : boundary_slots_) {
            while (m.first_corner_[p + 1] <= slot) ++p;
            m.boundary_.push_back(NavMesh::EdgeRef{p, slot - m.first_corner_[p]});
        }
        for (const Aabb& box : m.polygon_bounds_) {
            m.bounds_.grow(box.min);
            m.bounds_.grow(box.max);
        }
        m.agent_ = in_.agent_type;
        m.tiles_ = in_.tiles;
        fingerprint_tiles(m);
        m.grid_.build(m.polygon_bounds_, m.bounds_);
        // A navmesh lives long and is never edited: give back what the building left spare.
        auto fit = [](auto&... arrays) { (arrays.shrink_to_fit(), ...); };
        fit(m.vertices_, m.first_corner_, m.corners_, m.neighbours_, m.areas_, m.on_outline_, m.polygon_bounds_,
            m.detail_vertices_, m.detail_triangles_, m.detail_, m.boundary_, m.polygon_tiles_);
    }

    // Each tile's polygons as joined, hashed (FNV-1a over each polygon's corner count and its corners'
    // coordinate bits, polygon after polygon): what tells an agent its path's tiles did not change.
    static void fingerprint_tiles(NavMesh& m) {
        if (m.polygon_tiles_.empty()) return;
        std::vector<Fnv1a64> h(m.tiles_.tiles.size());
        for (uint32_t p = 0; p + 1 < m.first_corner_.size(); ++p) {
            Fnv1a64& hash = h[m.polygon_tiles_[p]];
            hash.word(m.first_corner_[p + 1] - m.first_corner_[p]);
            for (uint32_t k = m.first_corner_[p]; k < m.first_corner_[p + 1]; ++k)
                for (int axis = 0; axis < 3; ++axis) hash.number(m.vertices_[m.corners_[k]][axis]);
        }
        m.tile_fingerprints_.resize(h.size());
        for (size_t t = 0; t < h.size(); ++t) m.tile_fingerprints_[t] = h[t].value();
    }

    const NavMeshInput& in_;
    std::shared_ptr<NavMesh> mesh_ = std::make_shared<NavMesh>();
    std::vector<uint32_t> remap_;
    std::vector<uint8_t> on_tile_border_;  // per welded vertex
    std::vector<uint32_t> boundary_slots_;
};

void validate_agent(const AgentType& a) {
    auto check = [&](float value, const char* name, bool ok) {
        if (!ok || !std::isfinite(value)) fail_field(ErrorCode::InvalidArgument, name, " is ", value);
    };
    check(a.radius, "radius", a.radius >= 0.0f && a.radius <= 100.0f);
    check(a.height, "height", a.height > 0.0f && a.height <= 100.0f);
    check(a.max_climb, "max_climb", a.max_climb >= 0.0f && a.max_climb <= 100.0f);
    check(a.max_slope, "max_slope", a.max_slope >= 0.0f && a.max_slope < 90.0f);
}

std::shared_ptr<const NavMesh> build_navmesh(const NavMeshInput& input) { return NavMeshBuilder(input).build(); }

NavMeshInput input_of(const NavMesh& m) {
    NavMeshInput in;
    in.vertices = m.vertices_;
    in.indices = m.corners_;
    in.polygon_sizes.reserve(m.polygon_count());
    for (uint32_t p = 0; p < m.polygon_count(); ++p)
        in.polygon_sizes.push_back(static_cast<uint8_t>(m.corner_count(p)));
    in.areas = m.areas_;
    in.weld_tolerance = 0.0f;
    in.agent_type = m.agent_;
    in.tiles = m.tiles_;
    in.polygon_tiles = m.polygon_tiles_;
    if (!m.detail_.empty()) {
        // Global detail vertices again: each polygon's own, and the corners its triangles use
        // (which the builder turns back into corners).
        in.detail_starts.reserve(m.detail_.size());
        for (uint32_t p = 0; p < m.polygon_count(); ++p) {
            in.detail_starts.push_back(m.detail_[p].first_triangle);
            const uint32_t base = static_cast<uint32_t>(in.detail_vertices.size());
            const uint32_t locals = m.corner_count(p) + (m.detail_[p + 1].first_vertex - m.detail_[p].first_vertex);
            for (uint32_t local = 0; local < locals; ++local)
                in.detail_vertices.push_back(m.detail_point(p, static_cast<uint8_t>(local)));
            for (uint32_t t = m.detail_[p].first_triangle; t < m.detail_[p + 1].first_triangle; ++t)
                for (uint8_t local : m.detail_triangles_[t]) in.detail_indices.push_back(base + local);
        }
        in.detail_starts.push_back(m.detail_.back().first_triangle);
    }
    return in;
}

}  // namespace nl
