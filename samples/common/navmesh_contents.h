// What a navmesh holds, read back through the C ABI into plain arrays: its polygons, its outline, its
// links and, for a tiled navmesh, its grid and the tiles loaded. Pictures draw these; the CLI counts
// them.
#pragma once

#include <navlink/navlink.h>

#include <vector>

namespace nl::samples {

struct NavmeshContents {
    std::vector<float> vertices;  // x y z per vertex
    std::vector<nl_nav_polygon> polygons;
    std::vector<nl_boundary_edge> boundary_edges;
    std::vector<nl_link> links;
    // A tiled navmesh's grid (nl_navmesh_info.tile_width, tile_origin) and its loaded tiles in row
    // order (nl_navmesh_get_tiles); a solo navmesh has tile_width 0 and no tiles.
    float tile_width = 0.0f;
    float tile_origin[2] = {0.0f, 0.0f};
    std::vector<nl_tile_coord> tiles;

    bool tiled() const { return tile_width > 0.0f; }
};

// Throws SampleError.
NavmeshContents read_navmesh_contents(const nl_world* world, nl_navmesh_id navmesh);

// The coordinates of a tiled navmesh's loaded tiles (two-call pattern); none for a solo navmesh.
std::vector<nl_tile_coord> read_tiles(const nl_world* world, nl_navmesh_id navmesh);

// Just the links (two-call pattern).
std::vector<nl_link> read_links(const nl_world* world, nl_navmesh_id navmesh);

}  // namespace nl::samples
