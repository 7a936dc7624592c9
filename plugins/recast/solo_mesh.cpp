#include "solo_mesh.h"

#include <vector>

namespace nl::recast {

RecastPolygons build_solo_mesh(HostLogContext& context, const LevelTriangles& level, const nl_recast_settings& s,
                               const nl_agent_type& agent, const BuildProgress& progress) {
    const int ntris = level.triangle_count();
    if (ntris == 0) no_walkable_surface(agent, "the level has no triangles");
    float bmin[3];
    float bmax[3];
    rcCalcBounds(level.vertices.data(), level.vertex_count(), bmin, bmax);
    const rcConfig cfg = make_config(s, agent, bmin, bmax);

    progress.report(0.04f, "marking walkable triangles");
    const std::vector<unsigned char> areas = walkable_areas(context, level, cfg, agent);
    // Recast takes int indices; uint32_t indices below INT_MAX (checked on fetch) read the same.
    const int* tris = reinterpret_cast<const int*>(level.indices.data());
    return build_polygons(context, level, tris, areas.data(), ntris, cfg, s, agent, &progress);
}

}  // namespace nl::recast
