// Links of a tiled navmesh, generated a tile at a time. A tile owns the generated links that start on
// it (on its polygons), and they are generated over the tile and the loaded tiles within
// link reach of it, so a tile's links depend on the tiles near it only: never on the order the tiles
// came in, nor on tiles beyond reach. A link may end on any tile within reach, not only a neighbour.
#pragma once

#include <vector>

#include "links/generate_links.h"
#include "navmesh/tile_join.h"
#include "navmesh/tiles.h"

namespace nl {

// How far (x-z) beyond its own square a tile's generation looks: the other end of every jump it
// weighs, and every walk that would make a jump needless, lie within this of the jump's take-off.
float tile_link_reach(const LinkSettings& settings);

// The tile a link belongs to: the tile of the polygon its start was placed on (Link::start_tile), else
// the one its start lies in (on a line between two, the higher one).
TileCoord owner_tile(const TileGrid& grid, const Link& link);

// The tiles of `loaded` whose squares lie within `reach` (x-z) of some tile of `around`, in row order.
std::vector<TileCoord> tiles_within_reach(const TileGrid& grid, const std::vector<TileCoord>& loaded,
                                          const std::vector<TileCoord>& around, float reach);
// The tiles of `loaded` whose squares lie within `reach` (x-z) of `box`, in row order.
std::vector<TileCoord> tiles_within_reach(const TileGrid& grid, const std::vector<TileCoord>& loaded, const Aabb& box,
                                          float reach);

// The generated links that the tiles `owners` own, each tile's as a generation over the navmesh joined
// from the tiles of `loaded` within tile_link_reach of it finds them (the level's geometry as it is
// now, the body of the tiles' agent type); in row order of their tiles, each tile's in generation
// order. A bidirectional jump starts at its lower end in (x, z, y) order, whichever end the generation
// found first. `report` is the generation's (the links: those kept). Throws as generate_links.
std::vector<Link> generate_tile_links(const TileInputs& loaded, const std::vector<TileCoord>& owners,
                                      const Level& level, TaskSystem& tasks, const LinkSettings& settings,
                                      LinkGenerationReport& report, GenerationProgress progress);

}  // namespace nl
