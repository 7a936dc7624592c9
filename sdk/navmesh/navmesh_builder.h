// Turns a host's (or a builder plugin's) polygons into a NavMesh: validates, welds, orients,
// connects, finds the outline, indexes.
#pragma once

#include <memory>
#include <vector>

#include "navmesh/navmesh.h"
#include "navmesh/tiles.h"

namespace nl {

struct NavMeshInput {
    std::vector<Vec3> vertices;
    std::vector<uint32_t> indices;       // polygon corners, polygon after polygon
    std::vector<uint8_t> polygon_sizes;  // corners per polygon; empty means all triangles
    std::vector<uint8_t> areas;          // per polygon; empty means area 0
    float weld_tolerance = 0.001f;
    AgentType agent_type;
    std::vector<Vec3> detail_vertices;
    std::vector<uint32_t> detail_indices;  // 3 per detail triangle
    std::vector<uint32_t> detail_starts;   // polygon_count + 1 offsets in triangles; empty = no detail
    // Tiles: one tile (its grid and coordinate) as a builder or host hands it, or those join_tiles
    // joined (tile_join.h), with each polygon's index into tiles.tiles; solo: no grid, both empty.
    TileLayout tiles;
    std::vector<uint32_t> polygon_tiles;
    // From join_tiles: per vertex, 1 on a line between tiles, and how far two tiles' border corners may
    // be apart in height and still be joined as T-junctions.
    std::vector<uint8_t> on_tile_border;
    float tile_border_height_tolerance = 0.0f;
};

// Throws InvalidArgument naming the bad field of the input ("vertices[3].y", "agent_type.radius": a
// failure about a field, see fail_field) and adds nothing anywhere: the result is a new, complete
// navmesh or an exception.
std::shared_ptr<const NavMesh> build_navmesh(const NavMeshInput& input);

// The input that builds `navmesh` again: its vertices, polygons, areas, agent and detail as they are
// (welded, oriented, without the polygons the builder dropped), with a weld tolerance of 0.
NavMeshInput input_of(const NavMesh& navmesh);

// Throws InvalidArgument about the bad field ("radius is -1").
void validate_agent(const AgentType& agent);

}  // namespace nl
