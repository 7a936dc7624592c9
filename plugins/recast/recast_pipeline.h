// One Recast build over a box of the level (RecastDemo's Sample_SoloMesh::handleBuild, and the body of
// Sample_TileMesh::buildTileMesh): voxelise, filter, partition into regions, trace contours, build the
// polygon mesh and its detail mesh. The solo mesh runs it once over the whole level, the tiled mesh
// once per tile over the tile and its border.
#pragma once

#include <string>
#include <vector>

#include <Recast.h>

#include "build_progress.h"
#include "host_log_context.h"
#include "level_triangles.h"
#include "navlink/navlink.h"
#include "navlink/recast.h"
#include "recast_memory.h"

namespace nl::recast {

struct RecastPolygons {
    PolyMeshPtr polygons;      // at least one polygon
    PolyMeshDetailPtr detail;  // one sub-mesh per polygon
};

// The rcConfig RecastDemo derives from the settings and the agent, over the given bounds. Throws
// INVALID_ARGUMENT when the grid is beyond Recast's limits (cell_size / cell_height too small for
// the level, agent radius too many cells), naming the setting to change.
rcConfig make_config(const nl_recast_settings& settings, const nl_agent_type& agent, const float* bmin,
                     const float* bmax);

// The largest NavLink area the builder carries: Recast keeps 6 bits of area, 0 of them "not
// walkable", so NavLink's area a is Recast's a + 1.
constexpr unsigned kMaxRecastArea = RC_WALKABLE_AREA - 1;

// Throws BuildFailure NOT_FOUND: "no walkable surface for <the agent>: <why>".
[[noreturn]] void no_walkable_surface(const nl_agent_type& agent, const std::string& why);

// Which triangles an agent may walk on, as Recast areas: walkable ones (flat enough, not an
// obstacle's) carry their mesh's area + 1, the rest RC_NULL_AREA. Fails NOT_FOUND when none is,
// saying why: every flat triangle an obstacle's, or fronts that face down (wound the other way);
// INVALID_ARGUMENT for a mesh area beyond kMaxRecastArea.
std::vector<unsigned char> walkable_areas(HostLogContext& context, const LevelTriangles& level, const rcConfig& cfg,
                                          const nl_agent_type& agent);

// The pipeline over cfg's box (cfg.borderSize cells of it are the neighbours' border), from the `ntris`
// triangles `tris` (3 indices into level.vertices each) with their Recast areas. Reports its steps to
// `progress` when given (then throws CANCELLED from it). Throws BuildFailure: NOT_FOUND when nothing in
// the box is walkable, OUT_OF_MEMORY or INTERNAL_ERROR naming the Recast step that failed,
// INVALID_ARGUMENT when the box holds more walkable cells than Recast indexes.
RecastPolygons build_polygons(HostLogContext& context, const LevelTriangles& level, const int* tris,
                              const unsigned char* areas, int ntris, const rcConfig& cfg,
                              const nl_recast_settings& settings, const nl_agent_type& agent,
                              const BuildProgress* progress);

}  // namespace nl::recast
