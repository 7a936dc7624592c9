// Tiles of one grid joined into the input of one navmesh: every query then works across the lines
// between tiles as if the navmesh had been built whole. Two tiles voxelised on their own may place the
// same border corner a voxel or two apart in height, and simplify their outlines differently along the
// line they share: the corners they share become one vertex here, and the navmesh builder joins the
// rest as T-junctions (t_junctions.h), within the body's max_climb in height.
#pragma once

#include <memory>
#include <vector>

#include "navmesh/navmesh_builder.h"

namespace nl {

// The tiles' polygons, vertices and detail in row order of their coordinates (whatever order they
// come in, the result is the same), with each polygon's tile (polygon_tiles) and each vertex's place
// on a tile border (on_tile_border). Each tile's input holds its place: tiles.grid and one coordinate
// in tiles.tiles. Throws InvalidArgument naming the tile: no place, another grid or agent type than
// the first tile's, a coordinate twice. Border corners are shared where two tiles put them at the same
// x and z (on the navmesh grid) within the agent's max_climb in height, at the height of the first
// tile in row order.
NavMeshInput join_tiles(const std::vector<const NavMeshInput*>& tiles);

// The tiles a tiled navmesh is joined from, each as it was built or handed over (its place in
// tiles.tiles[0]), in row order: what adding or removing one joins again.
using TileInputs = std::vector<std::shared_ptr<const NavMeshInput>>;
NavMeshInput join_tiles(const TileInputs& tiles);
// Sorts tiles in row order of their places.
void sort_in_row_order(TileInputs& tiles);

}  // namespace nl
