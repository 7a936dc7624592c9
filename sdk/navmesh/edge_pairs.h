// A navmesh's polygon edges keyed by their vertex pair and sorted, so that the edges of one pair stand
// together: two of them make a portal (the builder's connect()), one alone is an edge no other matches
// (outline, or a T-junction to join: t_junctions.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace nl {

struct KeyedEdge {
    uint64_t key;   // the vertex pair, smaller first
    uint32_t slot;  // index into the corners of the edge's first corner
    uint32_t polygon;
};

// The edges of polygons p (corners[first_corner[p]] .. corners[first_corner[p + 1] - 1], closed) by key,
// then by slot.
inline std::vector<KeyedEdge> edges_by_vertex_pair(const std::vector<uint32_t>& first_corner,
                                                   const std::vector<uint32_t>& corners) {
    std::vector<KeyedEdge> edges;
    edges.reserve(corners.size());
    for (uint32_t p = 0; p + 1 < first_corner.size(); ++p) {
        for (uint32_t slot = first_corner[p]; slot < first_corner[p + 1]; ++slot) {
            const uint32_t a = corners[slot], b = corners[slot + 1 < first_corner[p + 1] ? slot + 1 : first_corner[p]];
            edges.push_back({(uint64_t(std::min(a, b)) << 32) | std::max(a, b), slot, p});
        }
    }
    std::sort(edges.begin(), edges.end(),
              [](const KeyedEdge& x, const KeyedEdge& y) { return x.key != y.key ? x.key < y.key : x.slot < y.slot; });
    return edges;
}

}  // namespace nl
