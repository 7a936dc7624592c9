// The standard Recast solo-mesh pipeline (RecastDemo's Sample_SoloMesh::handleBuild): voxelise the
// level, filter, partition into regions, trace contours, build the polygon mesh and its detail mesh.
#pragma once

#include <Recast.h>

#include "build_progress.h"
#include "host_log_context.h"
#include "level_triangles.h"
#include "navlink/navlink.h"
#include "navlink/recast.h"
#include "recast_memory.h"

namespace nl::recast {

struct SoloMesh {
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

// Runs the pipeline, reporting its steps to `progress`. Throws BuildFailure: NOT_FOUND when nothing
// is walkable ("no walkable surface ...", saying when the triangles would be walkable turned over),
// INVALID_ARGUMENT for a mesh area beyond kMaxRecastArea, CANCELLED from `progress`, OUT_OF_MEMORY
// or INTERNAL_ERROR naming the Recast step that failed, and make_config's.
SoloMesh build_solo_mesh(HostLogContext& context, const LevelTriangles& level, const nl_recast_settings& settings,
                         const nl_agent_type& agent, const BuildProgress& progress);

}  // namespace nl::recast
