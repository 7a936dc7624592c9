// A host navmesh drawn as a map of 1 m cells (cell_map.h), as an nl_navmesh_def, for tests that need
// a navmesh whose paths are known exactly. Header-only and C ABI only, so tests linking the shared
// library use it too.
#pragma once

#include <navlink/navlink.h>

#include <string>
#include <vector>

#include "cell_map.h"

namespace nl::test {

// The arrays back `def`, which borrows them.
struct CellNavmesh : CellMap {
    nl_navmesh_def def = nl_default_navmesh_def();

    CellNavmesh(const std::vector<std::string>& rows, float agent_radius) : CellMap(rows) {
        def.vertices = vertices.data();
        def.vertex_count = uint32_t(vertices.size() / 3);
        def.indices = indices.data();
        def.polygon_vertex_counts = counts.data();
        def.polygon_count = uint32_t(counts.size());
        def.areas = areas.data();
        def.agent_type.radius = agent_radius;
    }
    CellNavmesh(const CellNavmesh&) = delete;
    CellNavmesh& operator=(const CellNavmesh&) = delete;
};

}  // namespace nl::test
