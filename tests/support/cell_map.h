// A navmesh drawn as a map of 1 m cells: the arrays alone, for tests of the core (core_world.h's
// cell_navmesh) and of the C ABI (cell_navmesh.h's CellNavmesh, whose def borrows them) alike.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace nl::test {

// Row r of the map is z in [r, r + 1], column c is x in [c, c + 1], at y = 0. '.' is area 0, a digit
// is that area, anything else is no navmesh. Each cell is a quad of its own four vertices.
struct CellMap {
    std::vector<float> vertices;  // x y z per vertex
    std::vector<uint32_t> indices;
    std::vector<uint8_t> counts;  // corners per polygon: 4
    std::vector<uint8_t> areas;

    explicit CellMap(const std::vector<std::string>& rows) {
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
    }
};

}  // namespace nl::test
