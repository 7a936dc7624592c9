#include "tiled_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "build_failure.h"
#include "host_table.h"

namespace nl::recast {
namespace {

// Tiles built between two progress reports: a cancel waits for at most this many.
constexpr uint32_t kTilesPerGroup = 32;

// The tiles a build makes: a block of tiles_x by tiles_z from tile (first_x, first_z) of the grid from
// origin (the level's lower corner, or the navmesh's grid for some of its tiles).
struct TileGrid {
    double origin[2];  // x, z of tile (0, 0)'s lower corner
    float bmin[3];     // the level's bounds: its height range is every tile's
    float bmax[3];
    int tile_size;  // cells
    int border;     // cells
    float cs;
    int first_x = 0;
    int first_z = 0;
    int tiles_x;
    int tiles_z;

    double tile_width() const { return double(tile_size) * cs; }
    uint32_t tile_count() const { return uint32_t(tiles_x) * uint32_t(tiles_z); }
    // The grid coordinates of the block's tile `index` (row by row).
    int tile_x(uint32_t index) const { return first_x + int(index % uint32_t(tiles_x)); }
    int tile_z(uint32_t index) const { return first_z + int(index / uint32_t(tiles_x)); }
};

// A tile's border in cells: the settings', or the agent's radius + 3 as RecastDemo's.
int border_cells(const nl_recast_settings& s, const nl_agent_type& agent) {
    return s.tile_border ? int(s.tile_border) : int(std::ceil(double(agent.radius) / s.cell_size)) + 3;
}

// Recast's config for tile (tx, tz): the tile and its border, tile_size + 2 border cells a side.
rcConfig tile_config(const TileGrid& grid, const nl_recast_settings& s, const nl_agent_type& agent, int tx, int tz) {
    const double pad = double(grid.border) * grid.cs;
    const float lo[3] = {float(grid.origin[0] + tx * grid.tile_width() - pad), grid.bmin[1],
                         float(grid.origin[1] + tz * grid.tile_width() - pad)};
    const float hi[3] = {float(grid.origin[0] + (tx + 1) * grid.tile_width() + pad), grid.bmax[1],
                         float(grid.origin[1] + (tz + 1) * grid.tile_width() + pad)};
    rcConfig cfg = make_config(s, agent, lo, hi);
    cfg.tileSize = grid.tile_size;
    cfg.borderSize = grid.border;
    cfg.width = grid.tile_size + 2 * grid.border;
    cfg.height = grid.tile_size + 2 * grid.border;
    return cfg;
}

// Each tile's triangles (those whose box, seen from above, reaches into the tile or its border), as
// offsets into one array: tile t's are triangles[first[t] .. first[t + 1]).
struct TileTriangles {
    std::vector<uint32_t> first;
    std::vector<int> triangles;
};

TileTriangles triangles_by_tile(const LevelTriangles& level, const TileGrid& grid) {
    const double width = grid.tile_width();
    const double pad = double(grid.border) * grid.cs;
    // The block's tiles a triangle's box reaches, as indices within the block; a > b: none.
    auto range = [&](float lo, float hi, double origin, int first, int tiles, int& a, int& b) {
        const double from = std::floor((double(lo) - origin - pad) / width) - first;
        const double to = std::floor((double(hi) - origin + pad) / width) - first;
        a = int(std::clamp(from, 0.0, double(tiles)));
        b = int(std::clamp(to, -1.0, double(tiles - 1)));
    };
    TileTriangles out;
    out.first.assign(size_t(grid.tile_count()) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<uint32_t> next;
        if (pass == 1) {
            for (size_t t = 1; t < out.first.size(); ++t) out.first[t] += out.first[t - 1];
            out.triangles.resize(out.first.back());
            next.assign(out.first.begin(), out.first.end() - 1);
        }
        for (int t = 0; t < level.triangle_count(); ++t) {
            float lo_x = INFINITY, hi_x = -INFINITY, lo_z = INFINITY, hi_z = -INFINITY;
            for (int k = 0; k < 3; ++k) {
                const float* v = &level.vertices[3 * size_t(level.indices[3 * size_t(t) + k])];
                lo_x = std::min(lo_x, v[0]);
                hi_x = std::max(hi_x, v[0]);
                lo_z = std::min(lo_z, v[2]);
                hi_z = std::max(hi_z, v[2]);
            }
            int x0, x1, z0, z1;
            range(lo_x, hi_x, grid.origin[0], grid.first_x, grid.tiles_x, x0, x1);
            range(lo_z, hi_z, grid.origin[1], grid.first_z, grid.tiles_z, z0, z1);
            for (int z = z0; z <= z1; ++z)
                for (int x = x0; x <= x1; ++x) {
                    const size_t tile = size_t(z) * grid.tiles_x + x;
                    if (pass == 0) {
                        ++out.first[tile + 1];
                    } else {
                        out.triangles[next[tile]++] = t;
                    }
                }
        }
    }
    return out;
}

// What building one tile came to: its polygons, none, or the failure to report.
struct TileResult {
    std::optional<NavMeshExport> tile;
    nl_status failure = NL_STATUS_SUCCESS;
    std::string message;
    std::unique_ptr<HostLogContext> log;
};

struct TileJob {
    const nl_plugin_host* host;
    const LevelTriangles* level;
    const TileGrid* grid;
    const TileTriangles* by_tile;
    const std::vector<unsigned char>* areas;
    const nl_recast_settings* settings;
    const nl_agent_type* agent;
    uint32_t first_tile;
    std::vector<TileResult>* results;

    void build(uint32_t index) const noexcept {
        TileResult& result = (*results)[index];
        const uint32_t tile = first_tile + index;
        const int tx = grid->tile_x(tile), tz = grid->tile_z(tile);
        try {
            result.log = std::make_unique<HostLogContext>(*host, HostLogContext::Forwarding::Kept);
            const uint32_t first = by_tile->first[tile], count = by_tile->first[tile + 1] - first;
            if (count == 0) return;
            std::vector<int> tris;
            std::vector<unsigned char> tile_areas;
            tris.reserve(size_t(count) * 3);
            tile_areas.reserve(count);
            bool walkable = false;
            for (uint32_t i = first; i < first + count; ++i) {
                const int t = by_tile->triangles[i];
                for (int k = 0; k < 3; ++k) tris.push_back(int(level->indices[3 * size_t(t) + k]));
                tile_areas.push_back((*areas)[size_t(t)]);
                walkable = walkable || tile_areas.back() != RC_NULL_AREA;
            }
            if (!walkable) return;
            const rcConfig cfg = tile_config(*grid, *settings, *agent, tx, tz);
            const RecastPolygons polygons = build_polygons(*result.log, *level, tris.data(), tile_areas.data(),
                                                           int(count), cfg, *settings, *agent, nullptr);
            TilePlace place;
            place.origin_x = grid->origin[0];
            place.origin_z = grid->origin[1];
            place.first_cell_x = int64_t(tx) * grid->tile_size;
            place.first_cell_z = int64_t(tz) * grid->tile_size;
            place.tile_width = float(grid->tile_width());
            place.tile_x = tx;
            place.tile_z = tz;
            result.tile.emplace(*polygons.polygons, *polygons.detail, &place);
        } catch (const BuildFailure& e) {
            // A tile where nothing is walkable is an empty tile, not a failure.
            if ((e.status() & NL_STATUS_NOT_FOUND) == 0) {
                result.failure = e.status();
                result.message = e.what();
            }
        } catch (const std::bad_alloc&) {
            result.failure = NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
        } catch (...) {
            result.failure = NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
            result.message = "unknown exception";
        }
    }

    static void run(void* job, uint32_t index) { static_cast<const TileJob*>(job)->build(index); }
};

TileGrid plan_grid(const LevelTriangles& level, const nl_recast_settings& s, const nl_navmesh_build_def& def) {
    const nl_agent_type& agent = def.agent_type;
    TileGrid grid{};
    if (level.whole_bounds) {
        std::copy_n(level.whole_bounds->data(), 3, grid.bmin);
        std::copy_n(level.whole_bounds->data() + 3, 3, grid.bmax);
    } else if (level.vertex_count() > 0) {
        rcCalcBounds(level.vertices.data(), level.vertex_count(), grid.bmin, grid.bmax);
    }
    grid.origin[0] = grid.bmin[0];
    grid.origin[1] = grid.bmin[2];
    grid.cs = s.cell_size;
    grid.tile_size = int(s.tile_size);
    const int radius_cells = int(std::ceil(double(agent.radius) / s.cell_size));
    grid.border = border_cells(s, agent);
    if (s.tile_border && (grid.border < radius_cells + 1 || grid.border > grid.tile_size))
        fail(NL_STATUS_INVALID_ARGUMENT, "tile_border of ", s.tile_border,
             " cells must be at least the agent's radius (", radius_cells, " cells) + 1 and at most tile_size (",
             s.tile_size, "); 0 gives radius + 3");
    const double width = grid.tile_width();
    if (asks_for_tiles(def)) {
        // Some tiles of a navmesh's grid: its origin, and its width, which the settings must make.
        if (float(width) != def.tile_width)
            fail(NL_STATUS_INVALID_ARGUMENT, "tile_size ", s.tile_size, " cells of ", s.cell_size, " m makes tiles of ",
                 float(width), " m; the navmesh's are ", def.tile_width,
                 " m (build with the settings it was built with)");
        if (!std::isfinite(def.tile_origin_x) || !std::isfinite(def.tile_origin_z))
            fail(NL_STATUS_INVALID_ARGUMENT, "tile_origin_x and tile_origin_z must be finite");
        if (double(def.tile_columns) * def.tile_rows > kMaxTiles)
            fail(NL_STATUS_INVALID_ARGUMENT, def.tile_columns, " x ", def.tile_rows,
                 " tiles asked; one build makes at most ", kMaxTiles);
        grid.origin[0] = def.tile_origin_x;
        grid.origin[1] = def.tile_origin_z;
        grid.first_x = def.first_tile.x;
        grid.first_z = def.first_tile.z;
        grid.tiles_x = int(def.tile_columns);
        grid.tiles_z = int(def.tile_rows);
        return grid;
    }
    const double tiles_x = std::max(1.0, std::ceil((double(grid.bmax[0]) - grid.bmin[0]) / width));
    const double tiles_z = std::max(1.0, std::ceil((double(grid.bmax[2]) - grid.bmin[2]) / width));
    if (tiles_x * tiles_z > kMaxTiles)
        fail(NL_STATUS_INVALID_ARGUMENT, "tile_size ", s.tile_size, " cells of ", s.cell_size, " m makes ", tiles_x,
             " x ", tiles_z, " tiles; one build makes at most ", kMaxTiles, " (raise tile_size)");
    grid.tiles_x = int(tiles_x);
    grid.tiles_z = int(tiles_z);
    return grid;
}

}  // namespace

std::optional<std::array<double, 4>> columns_to_read(const nl_recast_settings& s, const nl_navmesh_build_def& def) {
    if (s.tile_size == 0 || !asks_for_tiles(def)) return std::nullopt;
    const double width = double(s.tile_size) * s.cell_size;
    // A cell more than the border, so that rounding never leaves out a triangle a tile would take.
    const double pad = double(border_cells(s, def.agent_type) + 1) * s.cell_size;
    const std::array<double, 4> columns{
        def.tile_origin_x + double(def.first_tile.x) * width - pad,
        def.tile_origin_z + double(def.first_tile.z) * width - pad,
        def.tile_origin_x + double(int64_t(def.first_tile.x) + def.tile_columns) * width + pad,
        def.tile_origin_z + double(int64_t(def.first_tile.z) + def.tile_rows) * width + pad};
    for (double c : columns)
        if (!std::isfinite(c)) return std::nullopt;  // the whole level: plan_grid names what is wrong
    return columns;
}

bool asks_for_tiles(const nl_navmesh_build_def& def) {
    return def.size >= offsetof(nl_navmesh_build_def, tile_rows) + sizeof def.tile_rows && def.tile_columns > 0 &&
           def.tile_rows > 0;
}

void build_tiled_mesh(HostLogContext& context, const nl_plugin_host& host, const LevelTriangles& level,
                      const nl_recast_settings& s, const nl_navmesh_build_def& def, const BuildProgress& progress,
                      const std::function<void(const NavMeshExport& tile)>& hand) {
    const nl_agent_type& agent = def.agent_type;
    const bool some = asks_for_tiles(def);
    if (level.triangle_count() == 0 && !some) no_walkable_surface(agent, "the level has no triangles");
    const TileGrid grid = plan_grid(level, s, def);  // the settings checked against the tiles asked for
    if (level.triangle_count() == 0) return;         // nothing there: no tile
    // The slope and the grid's limits are checked once, on the first tile's config.
    const rcConfig first = tile_config(grid, s, agent, grid.first_x, grid.first_z);
    progress.report(0.03f, "marking walkable triangles");
    std::vector<unsigned char> areas;
    try {
        areas = walkable_areas(context, level, first, agent);
    } catch (const BuildFailure& e) {
        if (some && (e.status() & NL_STATUS_NOT_FOUND)) return;  // nothing walkable: no tile
        throw;
    }
    progress.report(0.05f, "sorting the level's triangles into tiles");
    const TileTriangles by_tile = triangles_by_tile(level, grid);

    const uint32_t tiles = grid.tile_count();
    uint32_t handed = 0;
    std::vector<TileResult> results;
    for (uint32_t group = 0; group < tiles; group += kTilesPerGroup) {
        progress.report(0.05f + 0.9f * float(group) / float(tiles), "building tiles");
        const uint32_t count = std::min(kTilesPerGroup, tiles - group);
        results.clear();
        results.resize(count);
        TileJob job{&host, &level, &grid, &by_tile, &areas, &s, &agent, group, &results};
        if (NL_RECAST_HOST_OFFERS(host, run_tasks)) {
            const nl_status ran = host.run_tasks(host.context, count, &TileJob::run, &job);
            if (NL_FAILED(ran)) fail(ran & ~NL_STATUS_FAILURE, "the host's run_tasks failed");
        } else {
            for (uint32_t i = 0; i < count; ++i) job.build(i);
        }
        // In row order, whichever thread built them.
        for (uint32_t i = 0; i < count; ++i) {
            TileResult& result = results[i];
            if (result.log) result.log->forward_kept();
            if (NL_FAILED(result.failure)) {
                const uint32_t tile = group + i;
                fail(result.failure & ~NL_STATUS_FAILURE, "tile (", grid.tile_x(tile), ", ", grid.tile_z(tile),
                     "): ", result.message.empty() ? "out of memory" : result.message);
            }
            if (result.tile) {
                hand(*result.tile);
                ++handed;
            }
        }
    }
    if (handed == 0 && !some)
        no_walkable_surface(agent, "none of the " + std::to_string(tiles) +
                                       " tiles holds a walkable region after erosion and region_min_size");
}

}  // namespace nl::recast
