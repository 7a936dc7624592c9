// What a navmesh holds, read back through the C ABI into plain arrays: its polygons, its outline and
// its links. Pictures draw these; the CLI counts them.
#pragma once

#include <navlink/navlink.h>

#include <vector>

namespace nl::samples {

struct NavmeshContents {
    std::vector<float> vertices;  // x y z per vertex
    std::vector<nl_nav_polygon> polygons;
    std::vector<nl_boundary_edge> boundary_edges;
    std::vector<nl_link> links;
};

// Throws SampleError.
NavmeshContents read_navmesh_contents(const nl_world* world, nl_navmesh_id navmesh);

// Just the links (two-call pattern).
std::vector<nl_link> read_links(const nl_world* world, nl_navmesh_id navmesh);

}  // namespace nl::samples
