// Merges vertices closer than a tolerance: hosts such as Unity repeat a vertex for every triangle
// that uses it, and polygons only connect through shared vertices.
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"

namespace nl {

// Returns, for every input vertex, the index of the earliest input vertex within `tolerance` of it
// (itself when there is none). Deterministic: depends only on the input order.
std::vector<uint32_t> weld_vertices(const std::vector<Vec3>& vertices, float tolerance);

}  // namespace nl
