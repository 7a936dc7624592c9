#include "level/level_hash.h"

#include <cstdio>
#include <cstring>

namespace nl {

std::string level_hash_text(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

uint64_t level_hash(const BuildTriangles& level) {
    const TriangleMesh& mesh = level.mesh;
    uint64_t h = 14695981039346656037ull;
    auto mix = [&h](uint32_t word) {
        for (int i = 0; i < 4; ++i) {
            h ^= (word >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (uint32_t corner : mesh.triangles[i])
            for (int axis = 0; axis < 3; ++axis) {
                uint32_t bits;
                const float v = mesh.vertices[corner][axis];
                std::memcpy(&bits, &v, 4);
                mix(bits);
            }
        if (level.areas[i] != 0) mix(level.areas[i]);
    }
    return h == 0 ? 1 : h;
}

}  // namespace nl
