#include "level/level_hash.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace nl {

std::string level_hash_text(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

void Fnv1a64::word(uint32_t w) {
    for (int i = 0; i < 4; ++i) {
        h_ ^= (w >> (8 * i)) & 0xffu;
        h_ *= 1099511628211ull;
    }
}

void Fnv1a64::number(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    word(bits);
}

void Fnv1a64::text(const std::string& t) {
    word(static_cast<uint32_t>(t.size()));
    for (unsigned char c : t) word(c);
}

uint64_t level_hash(const BuildTriangles& level) {
    const TriangleMesh& mesh = level.mesh;
    Fnv1a64 h;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (uint32_t corner : mesh.triangles[i])
            for (int axis = 0; axis < 3; ++axis) h.number(mesh.vertices[corner][axis]);
        if (level.areas[i] != 0) h.word(level.areas[i]);
    }
    return h.value();
}

}  // namespace nl
