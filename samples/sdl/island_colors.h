// The colour of each reachability island in a picture: the largest island the navmesh's usual
// green, the others in order of size the palette's other island colours (they repeat after eight).
#pragma once

#include <navlink/navlink.h>

#include <cstdint>
#include <string>
#include <vector>

#include "scene.h"

namespace nl::picture {

struct IslandColors {
    std::vector<uint32_t> polygons;  // per island: how many polygons it has
    std::vector<uint32_t> by_size;   // island numbers, largest first (ties: lower number first)
    std::vector<Rgba> color;         // per island

    // The fill of navmesh polygon `polygon`.
    Rgba of_polygon(const SceneIslands& islands, uint32_t polygon) const;
};

IslandColors island_colors(const SceneIslands& islands);

// "5 islands for the walker" (1 island...).
std::string islands_text(const SceneIslands& islands);

// The islands of the navmesh for a body with `capabilities` (nl_navmesh_get_islands), named `body`
// in the legend. Throws SampleError.
SceneIslands read_islands(const nl_world* world, nl_navmesh_id navmesh, const nl_agent_capabilities& capabilities,
                          const std::string& body);

}  // namespace nl::picture
