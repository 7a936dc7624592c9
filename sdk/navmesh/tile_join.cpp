#include "navmesh/tile_join.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "navmesh/navmesh_grid.h"
#include "util/error.h"

namespace nl {
namespace {

// A corner on a tile border is placed by both tiles from the same cell of the grid, but the float sums
// that place it may round differently: within this, it lies on the border.
const double kOnBorder = 1.5 * std::ldexp(1.0, kNavMeshGridExponent);

const TileCoord& place_of(const NavMeshInput& tile, size_t i) {
    if (!tile.tiles.grid.tiled() || tile.tiles.tiles.size() != 1)
        fail_field(ErrorCode::InvalidArgument, "tiles[", i, "] is not a tile (no tile grid or place)");
    return tile.tiles.tiles.front();
}

uint32_t polygons_of(const NavMeshInput& in) {
    return in.polygon_sizes.empty() ? static_cast<uint32_t>(in.indices.size() / 3)
                                    : static_cast<uint32_t>(in.polygon_sizes.size());
}

// Polygon p's detail: its own triangles, or a fan over its corners for a tile that has none (when
// another tile has, every polygon needs some).
void append_detail(const NavMeshInput& tile, size_t i, uint32_t p, size_t first_index, uint32_t corners,
                   NavMeshInput& out) {
    const uint32_t base = static_cast<uint32_t>(out.detail_vertices.size());
    if (tile.detail_starts.empty()) {
        for (uint32_t k = 0; k < corners; ++k)
            out.detail_vertices.push_back(tile.vertices[tile.indices[first_index + k]]);
        for (uint32_t k = 1; k + 1 < corners; ++k) {
            out.detail_indices.insert(out.detail_indices.end(), {base, base + k, base + k + 1});
        }
    } else {
        // The detail vertices a polygon's triangles use, copied in the order first used.
        if (tile.detail_starts.size() != polygons_of(tile) + 1)
            fail_field(ErrorCode::InvalidArgument, "tiles[", i,
                       "]: detail_triangle_starts needs polygon_count + 1 entries");
        const uint32_t first = tile.detail_starts[p], last = tile.detail_starts[p + 1];
        if (first > last || size_t(last) * 3 > tile.detail_indices.size())
            fail_field(ErrorCode::InvalidArgument, "tiles[", i, "]: detail_triangle_starts[", p + 1,
                       "] is out of order or range");
        std::vector<std::pair<uint32_t, uint32_t>> copied;  // tile's detail vertex -> out's
        for (uint32_t t = first; t < last; ++t)
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = tile.detail_indices[3 * size_t(t) + k];
                if (v >= tile.detail_vertices.size())
                    fail_field(ErrorCode::InvalidArgument, "tiles[", i, "]: detail_triangles[", 3 * size_t(t) + k,
                               "] is out of range");
                auto at = std::find_if(copied.begin(), copied.end(), [&](const auto& c) { return c.first == v; });
                if (at == copied.end()) {
                    copied.push_back({v, static_cast<uint32_t>(out.detail_vertices.size())});
                    out.detail_vertices.push_back(tile.detail_vertices[v]);
                    at = copied.end() - 1;
                }
                out.detail_indices.push_back(at->second);
            }
    }
    out.detail_starts.push_back(static_cast<uint32_t>(out.detail_indices.size() / 3));
}

}  // namespace

NavMeshInput join_tiles(const std::vector<const NavMeshInput*>& given) {
    if (given.empty()) fail_field(ErrorCode::InvalidArgument, "tiles: none given");
    std::vector<size_t> order(given.size());
    for (size_t i = 0; i < given.size(); ++i) {
        if (!given[i]) fail_field(ErrorCode::InvalidArgument, "tiles[", i, "] is null");
        place_of(*given[i], i);
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return std::make_tuple(given[a]->tiles.tiles[0], a) < std::make_tuple(given[b]->tiles.tiles[0], b);
    });
    const NavMeshInput& first = *given[order[0]];
    // Its climb decides which border corners join: a NaN one (a damaged file's) would join none, and
    // build_navmesh refuses it after the join anyway.
    naming_fields("agent_type.", [&] { validate_agent(first.agent_type); });
    NavMeshInput out;
    out.tiles.grid = first.tiles.grid;
    out.agent_type = first.agent_type;
    out.weld_tolerance = first.weld_tolerance;
    out.tile_border_height_tolerance = first.agent_type.max_climb;
    bool any_detail = false;
    for (size_t rank = 0; rank < order.size(); ++rank) {
        const size_t i = order[rank];
        const NavMeshInput& tile = *given[i];
        const TileCoord& at = place_of(tile, i);
        if (tile.tiles.grid != first.tiles.grid)
            fail_field(ErrorCode::InvalidArgument, "tiles[", i, "] (", at.x, ", ", at.z,
                       ") is on another tile grid than tile (", first.tiles.tiles[0].x, ", ", first.tiles.tiles[0].z,
                       ")");
        if (!same_agent_type(tile.agent_type, first.agent_type))
            fail_field(ErrorCode::InvalidArgument, "tiles[", i, "] (", at.x, ", ", at.z,
                       ") was built for another agent type than tile (", first.tiles.tiles[0].x, ", ",
                       first.tiles.tiles[0].z, ")");
        if (rank > 0 && out.tiles.tiles.back() == at)
            fail_field(ErrorCode::InvalidArgument, "tiles[", i, "]: tile (", at.x, ", ", at.z, ") is given twice");
        out.tiles.tiles.push_back(at);
        any_detail = any_detail || !tile.detail_starts.empty();
    }

    // Vertices, with the corners two tiles share on their border made one.
    struct BorderCorner {
        int64_t x, z;  // on the navmesh grid
        float y;
        uint32_t vertex;  // into the concatenation
    };
    std::vector<Vec3> all;
    std::vector<uint8_t> on_border;
    std::vector<uint32_t> tile_of_vertex;
    std::vector<BorderCorner> border;
    const double unit = std::ldexp(1.0, -kNavMeshGridExponent);
    const TileGrid& grid = out.tiles.grid;
    for (size_t rank = 0; rank < order.size(); ++rank) {
        const NavMeshInput& tile = *given[order[rank]];
        const TileCoord& at = out.tiles.tiles[rank];
        for (const Vec3& given_vertex : tile.vertices) {
            const Vec3 v = on_navmesh_grid(given_vertex);
            // Far from the origin, the tile width's float rounding adds up over the tiles to the line.
            auto near = [](double a, double line) { return std::fabs(a - line) <= kOnBorder + 1e-7 * std::fabs(line); };
            const bool on_line = near(v.x(), grid.line_x(at.x)) || near(v.x(), grid.line_x(int64_t(at.x) + 1)) ||
                                 near(v.z(), grid.line_z(at.z)) || near(v.z(), grid.line_z(int64_t(at.z) + 1));
            if (on_line)
                border.push_back(BorderCorner{std::llround(double(v.x()) * unit), std::llround(double(v.z()) * unit),
                                              v.y(), static_cast<uint32_t>(all.size())});
            all.push_back(v);
            on_border.push_back(on_line ? 1 : 0);
            tile_of_vertex.push_back(static_cast<uint32_t>(rank));
        }
    }
    std::vector<uint32_t> representative(all.size());
    for (uint32_t v = 0; v < all.size(); ++v) representative[v] = v;
    std::sort(border.begin(), border.end(), [](const BorderCorner& a, const BorderCorner& b) {
        return std::tie(a.x, a.z, a.y, a.vertex) < std::tie(b.x, b.z, b.y, b.vertex);
    });
    const float climb = out.tile_border_height_tolerance;
    for (size_t i = 0; i < border.size();) {
        // A run of corners at one x and z, from the lowest up; each cluster of heights within max_climb
        // of its lowest is one corner, placed by its earliest tile.
        size_t j = i;
        while (j < border.size() && border[j].x == border[i].x && border[j].z == border[i].z) ++j;
        for (size_t c = i; c < j;) {
            size_t d = c + 1;  // the lowest is in its own cluster, whatever the heights compare as
            uint32_t keep = border[c].vertex;
            while (d < j && border[d].y - border[c].y <= climb) {
                keep = std::min(keep, border[d].vertex);
                ++d;
            }
            for (size_t k = c; k < d; ++k)
                if (tile_of_vertex[border[k].vertex] != tile_of_vertex[keep] || border[k].vertex == keep)
                    representative[border[k].vertex] = keep;
            c = d;
        }
        i = j;
    }
    std::vector<uint32_t> renumbered(all.size(), 0);
    for (uint32_t v = 0; v < all.size(); ++v) {
        if (representative[v] != v) continue;
        renumbered[v] = static_cast<uint32_t>(out.vertices.size());
        out.vertices.push_back(all[v]);
        out.on_tile_border.push_back(on_border[v]);
    }

    // Polygons, areas, their tiles and their detail, tile after tile.
    uint32_t vertex_offset = 0;
    if (any_detail) out.detail_starts.push_back(0);
    for (size_t rank = 0; rank < order.size(); ++rank) {
        const NavMeshInput& tile = *given[order[rank]];
        const uint32_t count = polygons_of(tile);
        size_t index = 0;
        for (uint32_t p = 0; p < count; ++p) {
            const uint32_t corners = tile.polygon_sizes.empty() ? 3u : tile.polygon_sizes[p];
            if (index + corners > tile.indices.size())
                fail_field(ErrorCode::InvalidArgument, "tiles[", order[rank], "]: indices end inside polygon ", p);
            for (uint32_t k = 0; k < corners; ++k) {
                const uint32_t v = tile.indices[index + k];
                if (v >= tile.vertices.size())
                    fail_field(ErrorCode::InvalidArgument, "tiles[", order[rank], "]: indices[", index + k, "] = ", v,
                               " is out of range");
                out.indices.push_back(renumbered[representative[vertex_offset + v]]);
            }
            out.polygon_sizes.push_back(static_cast<uint8_t>(corners));
            out.areas.push_back(tile.areas.empty() ? 0 : tile.areas[p]);
            out.polygon_tiles.push_back(static_cast<uint32_t>(rank));
            if (any_detail) append_detail(tile, order[rank], p, index, corners, out);
            index += corners;
        }
        vertex_offset += static_cast<uint32_t>(tile.vertices.size());
    }
    return out;
}

NavMeshInput join_tiles(const TileInputs& tiles) {
    std::vector<const NavMeshInput*> given;
    given.reserve(tiles.size());
    for (const auto& tile : tiles) given.push_back(tile.get());
    return join_tiles(given);
}

void sort_in_row_order(TileInputs& tiles) {
    std::sort(tiles.begin(), tiles.end(),
              [](const auto& a, const auto& b) { return a->tiles.tiles.front() < b->tiles.tiles.front(); });
}

}  // namespace nl
