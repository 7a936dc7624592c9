// A tiled navmesh's tiles in a picture: each loaded tile's square outlined along the grid lines between
// tiles, and the navmesh's own edges that lie on those lines (where its tiles were joined, or where a
// tile ends) drawn over it at their heights. A solo navmesh has none, and looks as it always did.
#pragma once

#include <string>
#include <vector>

#include "link_shape.h"
#include "navmesh_contents.h"

namespace nl::picture {

struct TileBorders {
    std::vector<std::array<Point3, 2>> squares;  // the loaded tiles' sides, each once, within the map
    std::vector<std::array<Point3, 2>> seams;    // navmesh polygon edges along the tile lines
};

// The borders of `navmesh`'s loaded tiles: their squares at `height` (seen from an angle, it matters),
// cut to the map (x and z within the level's box `lo`..`hi`: the last tiles of a row reach past it).
TileBorders tile_borders(const samples::NavmeshContents& navmesh, float height, const float lo[3], const float hi[3]);

// "tile borders (12 tiles of 9.6 m)"; empty for a solo navmesh.
std::string tile_borders_text(const samples::NavmeshContents& navmesh);

}  // namespace nl::picture
