// The level in square tiles (RecastDemo's Sample_TileMesh): each tile one Recast build over the
// triangles within it and a border, built in parallel on the host's task system (run_tasks) and handed
// over in row order, so that the navmesh the host joins is the same for any thread count.
#pragma once

#include <array>
#include <functional>
#include <optional>

#include "navmesh_export.h"
#include "recast_pipeline.h"

namespace nl::recast {

// Builds every tile of the level's grid (settings.tile_size cells a side, from the level's lower
// corner), or those `def` asks for (asks_for_tiles: a block of its navmesh's grid), and calls `hand`
// with each that has polygons, in row order (z, then x), on this thread. Throws BuildFailure: NOT_FOUND
// when no tile of the level has a walkable surface (or walkable_areas finds none; for tiles asked for,
// none is a success), INVALID_ARGUMENT for a tile_border out of range, a grid of more than kMaxTiles
// tiles, or settings whose tiles are not as wide as those asked for, CANCELLED from `progress` (asked
// between groups of tiles), and a tile's OUT_OF_MEMORY or INTERNAL_ERROR naming it.
void build_tiled_mesh(HostLogContext& context, const nl_plugin_host& host, const LevelTriangles& level,
                      const nl_recast_settings& settings, const nl_navmesh_build_def& def,
                      const BuildProgress& progress, const std::function<void(const NavMeshExport& tile)>& hand);

// The columns of the level (min x, min z, max x, max z) that the tiles `def` asks for read: those
// tiles and their borders. Nothing when `def` asks for the whole level (or its grid is not finite).
std::optional<std::array<double, 4>> columns_to_read(const nl_recast_settings& settings,
                                                     const nl_navmesh_build_def& def);

// Whether `def` asks for some tiles of a navmesh's grid (nl_navmesh_build_tiles), not a whole navmesh.
bool asks_for_tiles(const nl_navmesh_build_def& def);

// The most tiles one build makes.
constexpr double kMaxTiles = double(1 << 22);

}  // namespace nl::recast
