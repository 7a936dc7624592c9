// The standard Recast solo-mesh pipeline (RecastDemo's Sample_SoloMesh::handleBuild): voxelise the
// level, filter, partition into regions, trace contours, build the polygon mesh and its detail mesh.
#pragma once

#include <Recast.h>

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

// Runs the pipeline. Throws BuildFailure: NOT_FOUND when nothing is walkable ("no walkable surface
// ..."), OUT_OF_MEMORY or INTERNAL_ERROR naming the Recast step that failed, and make_config's.
SoloMesh build_solo_mesh(HostLogContext& context, const LevelTriangles& level, const nl_recast_settings& settings,
                         const nl_agent_type& agent);

}  // namespace nl::recast
