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

// --- Tiles: Detour's multi-tile navmesh, built as RecastDemo's Sample_TileMesh builds it ---

// A level cut into square tiles for Recast's tiled pipeline: the grid NavLink's Recast builder makes
// (tile (x, z) spans x in [origin_x + x * tile_width, + tile_width] and z alike, from the level's lower
// corner unless given), and the level's triangles binned by tile as Sample_TileMesh's chunky mesh
// does: those whose box, seen from above, reaches into the tile or its border.
struct TiledLevel {
    std::string name;
    nl_recast_settings settings = nl_default_recast_settings();  // tile_size > 0
    nl_agent_type agent = nl_default_agent_type();
    std::vector<float> vertices;  // x y z per vertex
    std::vector<int> indices;     // 3 per triangle
    float bmin[3] = {0, 0, 0};    // the level's bounds: their height range is every tile's
    float bmax[3] = {0, 0, 0};
    double origin_x = 0.0, origin_z = 0.0;
    double tile_width = 0.0;  // tile_size cells
    int border = 0;           // cells: tile_border, or the agent's radius in cells + 3 (RecastDemo's)
    int tiles_x = 0, tiles_z = 0;
    // Filled by bin_triangles: tile t's triangles (3 indices each) are triangles[3 * first[t] .. 3 * first[t + 1]).
    std::vector<size_t> first;
    std::vector<int> triangles;

    int tile_count() const { return tiles_x * tiles_z; }
};

// The level's bounds and grid (origin at its lower corner), settings.tile_size cells a tile; the
// triangles are not binned yet.
TiledLevel plan_tiled_level(const std::string& name, const std::vector<float>& vertices,
                            const std::vector<uint32_t>& indices, const nl_recast_settings& settings,
                            const nl_agent_type& agent);
// Sample_TileMesh's chunky mesh, as a flat grid of the tiles: what each tile's build reads.
void bin_triangles(TiledLevel& level);

// One tile's Detour data, owned by whoever holds it (free it with dtFree); null data when nothing in
// the tile is walkable. Throws what nl::recast::make_config throws, and std::runtime_error naming the
// Recast step that failed.
struct DetourTile {
    int x = 0, z = 0;
    unsigned char* data = nullptr;
    int bytes = 0;
    int polygons = 0;
};
// Sample_TileMesh::buildTileMesh: voxelise the tile and its border (triangles marked walkable by slope,
// tile by tile), filter, compact, erode, partition, contours, polygons, detail, dtCreateNavMeshData
// with a BV tree; every polygon walkable (flag 1). The rcConfig is nl::recast::make_config's over
// the tile and its border, as NavLink's tiles have it.
DetourTile build_detour_tile(const TiledLevel& level, int x, int z);

// A multi-tile dtNavMesh and the tile data it holds: tiles are added without DT_TILE_FREE_DATA, so
// removeTile hands their data back and a benchmark can add it again.
struct DetourTiles {
    DetourMesh navmesh;
    std::vector<DetourTile> tiles;  // those with data, in row order
    int tile_bits = 0, poly_bits = 0;
    DetourTiles() = default;
    DetourTiles(const DetourTiles&) = delete;
    DetourTiles& operator=(const DetourTiles&) = delete;
    ~DetourTiles();
    size_t data_bytes() const;
    int polygon_count() const;
};

// Builds every tile of the (binned) level, then initialises the navmesh for the grid (origin, tile
// width, as many tile and polygon bits as the tiles need: at most 22 between them with Debian's
// 32-bit refs) and adds them; a query with `max_nodes`. False, with the reason on stderr, when the
// tiles need more bits than a 32-bit ref has or Detour refuses a tile.
bool build_detour_tiles(const TiledLevel& level, DetourTiles& out, int max_nodes);

// A random point of polygon `polygon` of a Detour tile (a random fan triangle, a uniform point in
// it), half a metre up, as random_point_in_polygon.
void random_point_in_detour_polygon(const dtMeshTile& tile, int polygon, std::mt19937& rng, float out[3]);

// A random point of polygon `polygon` (a random fan triangle, a uniform point in it), half a metre
// up so that both sides have to snap it down.
void random_point_in_polygon(const rcPolyMesh& pm, int polygon, std::mt19937& rng, float out[3]);
// The same over a random polygon of the whole mesh.
void random_point(const rcPolyMesh& pm, std::mt19937& rng, float out[3]);

// The polygons of the mesh's largest connected part (by polygon count; over shared edges), in
// index order: points drawn from them can reach each other by walking.
std::vector<int> largest_connected_polygons(const rcPolyMesh& pm);

}  // namespace nl::bench
