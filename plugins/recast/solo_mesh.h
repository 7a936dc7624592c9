// The whole level as one Recast build (RecastDemo's Sample_SoloMesh).
#pragma once

#include "recast_pipeline.h"

namespace nl::recast {

// Runs the pipeline over the level's bounds, reporting its steps to `progress`. Throws BuildFailure:
// NOT_FOUND when nothing is walkable ("no walkable surface ...", saying when the triangles would be
// walkable turned over), CANCELLED from `progress`, and those of make_config, walkable_areas and
// build_polygons.
RecastPolygons build_solo_mesh(HostLogContext& context, const LevelTriangles& level, const nl_recast_settings& settings,
                               const nl_agent_type& agent, const BuildProgress& progress);

}  // namespace nl::recast
