#include "island_colors.h"

#include <algorithm>
#include <numeric>

#include "palette.h"
#include "sample_error.h"

namespace nl::picture {

IslandColors island_colors(const SceneIslands& islands) {
    IslandColors out;
    out.polygons.assign(islands.count, 0);
    for (uint32_t island : islands.of_polygon)
        if (island < islands.count) ++out.polygons[island];
    out.by_size.resize(islands.count);
    std::iota(out.by_size.begin(), out.by_size.end(), 0u);
    std::stable_sort(out.by_size.begin(), out.by_size.end(),
                     [&](uint32_t a, uint32_t b) { return out.polygons[a] > out.polygons[b]; });
    out.color.resize(islands.count);
    for (uint32_t rank = 0; rank < islands.count; ++rank) out.color[out.by_size[rank]] = palette::island(rank);
    return out;
}

Rgba IslandColors::of_polygon(const SceneIslands& islands, uint32_t polygon) const {
    const uint32_t island = polygon < islands.of_polygon.size() ? islands.of_polygon[polygon] : NL_NO_ISLAND;
    return island < color.size() ? color[island] : palette::kNoIsland;
}

std::string islands_text(const SceneIslands& islands) {
    return std::to_string(islands.count) + (islands.count == 1 ? " island" : " islands") + " for the " + islands.body;
}

SceneIslands read_islands(const nl_world* world, nl_navmesh_id navmesh, const nl_agent_capabilities& capabilities,
                          const std::string& body) {
    nl_query_filter filter = nl_default_query_filter();
    filter.capabilities = capabilities;
    SceneIslands out;
    out.body = body;
    uint32_t count = 0;
    samples::check(nl_navmesh_get_islands(world, navmesh, &filter, nullptr, 0, &count, nullptr),
                   "finding the navmesh's islands");
    out.of_polygon.resize(count);
    samples::check(nl_navmesh_get_islands(world, navmesh, &filter, out.of_polygon.data(), count, &count, &out.count),
                   "finding the navmesh's islands");
    return out;
}

}  // namespace nl::picture
