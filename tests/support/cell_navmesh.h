// A host navmesh drawn as a map of 1 m cells, for tests that need a navmesh whose paths are known
// exactly. Header-only and C ABI only, so tests linking the shared library use it too.
#pragma once

#include <navlink/navlink.h>

#include <string>
#include <utility>
#include <vector>

namespace nl::test {

// Row r of the map is z in [r, r + 1], column c is x in [c, c + 1], at y = 0. '.' is area 0, a digit
// is that area, anything else is no navmesh. The arrays back `def`, which borrows them.
struct CellNavmesh {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    std::vector<uint8_t> counts;
    std::vector<uint8_t> areas;
    nl_navmesh_def def = nl_default_navmesh_def();

    CellNavmesh(const std::vector<std::string>& rows, float agent_radius) {
        for (size_t r = 0; r < rows.size(); ++r) {
            for (size_t c = 0; c < rows[r].size(); ++c) {
                const char cell = rows[r][c];
                if (cell != '.' && (cell < '0' || cell > '9')) continue;
                const float x0 = float(c), x1 = x0 + 1, z0 = float(r), z1 = z0 + 1;
                // Counter-clockwise seen from above (y up): +z first, then +x.
                for (const auto& [x, z] : {std::pair{x0, z0}, {x0, z1}, {x1, z1}, {x1, z0}}) {
                    indices.push_back(uint32_t(vertices.size() / 3));
                    vertices.insert(vertices.end(), {x, 0.0f, z});
                }
                counts.push_back(4);
                areas.push_back(cell == '.' ? 0 : uint8_t(cell - '0'));
            }
        }
        def.vertices = vertices.data();
        def.vertex_count = uint32_t(vertices.size() / 3);
        def.indices = indices.data();
        def.polygon_vertex_counts = counts.data();
        def.polygon_count = uint32_t(counts.size());
        def.areas = areas.data();
        def.agent.radius = agent_radius;
    }
    CellNavmesh(const CellNavmesh&) = delete;
    CellNavmesh& operator=(const CellNavmesh&) = delete;
};

}  // namespace nl::test
