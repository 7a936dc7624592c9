// What the benchmarks against Detour share: one Recast polygon mesh and detail mesh per level, made
// by the built-in Recast builder's pipeline (the one nl_navmesh_build runs, default settings and
// agent type), handed to NavLink through nl_navmesh_add and to Detour through dtCreateNavMeshData,
// and random points on it.
#pragma once

#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>
#include <navlink/navlink.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "solo_mesh.h"

namespace nl::bench {

struct RecastLevel {
    std::string name;
    nl_recast_settings settings = nl_default_recast_settings();
    nl_agent_type agent = nl_default_agent_type();
    nl::recast::RecastPolygons solo;
};

// Throws what the OBJ reader and the Recast pipeline throw. `radius`: the agent type's (0: the
// default agent type's); `cell_size`: Recast's voxel width (0: the default settings').
RecastLevel build_recast_level(const std::string& name, const std::vector<float>& vertices,
                               const std::vector<uint32_t>& indices, float radius = 0.0f, float cell_size = 0.0f);
RecastLevel build_recast_level_from_obj(const char* path);  // named after the file's stem

struct DetourMesh {
    dtNavMesh* mesh = dtAllocNavMesh();
    dtNavMeshQuery* query = dtAllocNavMeshQuery();
    int bytes = 0;
    DetourMesh() = default;
    DetourMesh(const DetourMesh&) = delete;
    DetourMesh& operator=(const DetourMesh&) = delete;
    ~DetourMesh() {
        dtFreeNavMeshQuery(query);
        dtFreeNavMesh(mesh);
    }
    // The ref of polygon `index` of the polygon mesh (one tile: the tile's base | index).
    dtPolyRef ref(uint32_t index) const;
};

// As RecastDemo's Sample_SoloMesh: every polygon walkable (flag 1), a BV tree, the detail mesh, a
// query with RecastDemo's node pool (2048). False when Detour refuses the data.
bool build_detour(RecastLevel& level, DetourMesh& out);

// Adds the polygon mesh to `world` as a navmesh of the level's agent type; false (with NavLink's
// last error on stderr) when nl_navmesh_add fails or NavLink keeps another polygon count than Recast
// made (the benchmarks compare polygon for polygon).
bool add_navlink_navmesh(nl_world* world, const RecastLevel& level, nl_navmesh_id* out_navmesh, uint32_t* out_polygons);

// A random point of polygon `polygon` (a random fan triangle, a uniform point in it), half a metre
// up so that both sides have to snap it down.
void random_point_in_polygon(const rcPolyMesh& pm, int polygon, std::mt19937& rng, float out[3]);
// The same over a random polygon of the whole mesh.
void random_point(const rcPolyMesh& pm, std::mt19937& rng, float out[3]);

// The polygons of the mesh's largest connected part (by polygon count; over shared edges), in
// index order: points drawn from them can reach each other by walking.
std::vector<int> largest_connected_polygons(const rcPolyMesh& pm);

}  // namespace nl::bench
