#include "navmesh/vertex_welder.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace nl {
namespace {

struct CellKey {
    int64_t x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellHash {
    size_t operator()(const CellKey& k) const {
        uint64_t h = static_cast<uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
        h ^= static_cast<uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
        h ^= static_cast<uint64_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
        return static_cast<size_t>(h);
    }
};

}  // namespace

std::vector<uint32_t> weld_vertices(const std::vector<Vec3>& vertices, float tolerance) {
    const auto count = static_cast<uint32_t>(vertices.size());
    std::vector<uint32_t> representative(count);
    // Cells as wide as the tolerance: a vertex's matches lie in its own cell or the 26 around it.
    // With tolerance 0 only exact duplicates weld, found in the vertex's own (tiny) cell.
    // Never finer than a micrometre: within the coordinate limit the cell keys then stay far inside
    // int64 (1e9 m / 1e-6 m = 1e15), and float positions are coarser than that anyway.
    const double cell = std::max(double(tolerance), 1e-6);
    const double tolerance_sq = double(tolerance) * tolerance;
    std::unordered_map<CellKey, std::vector<uint32_t>, CellHash> cells;
    cells.reserve(count);
    const int reach = tolerance > 0.0f ? 1 : 0;
    for (uint32_t i = 0; i < count; ++i) {
        const Vec3& v = vertices[i];
        const CellKey key{static_cast<int64_t>(std::floor(v.x() / cell)),
                          static_cast<int64_t>(std::floor(v.y() / cell)),
                          static_cast<int64_t>(std::floor(v.z() / cell))};
        uint32_t match = i;
        for (int dz = -reach; dz <= reach && match == i; ++dz) {
            for (int dy = -reach; dy <= reach && match == i; ++dy) {
                for (int dx = -reach; dx <= reach && match == i; ++dx) {
                    const auto it = cells.find(CellKey{key.x + dx, key.y + dy, key.z + dz});
                    if (it == cells.end()) continue;
                    for (uint32_t candidate : it->second) {
                        const double d = (vertices[candidate] - v).cast<double>().squaredNorm();
                        if (tolerance > 0.0f ? d <= tolerance_sq : d == 0.0) {
                            match = candidate;
                            break;
                        }
                    }
                }
            }
        }
        representative[i] = match;
        if (match == i) cells[key].push_back(i);
    }
    return representative;
}

}  // namespace nl
