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

namespace {

// The triangles `keep` says, corner by corner, each followed by its area when that is not 0.
template <typename Keep>
uint64_t hash_triangles(const BuildTriangles& level, Keep&& keep) {
    const TriangleMesh& mesh = level.mesh;
    Fnv1a64 h;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (!keep(mesh.triangles[i])) continue;
        for (uint32_t corner : mesh.triangles[i])
            for (int axis = 0; axis < 3; ++axis) h.number(mesh.vertices[corner][axis]);
        if (level.areas[i] != 0) h.word(level.areas[i]);
    }
    return h.value();
}

}  // namespace

uint64_t level_hash(const BuildTriangles& level) {
    return hash_triangles(level, [](const auto&) { return true; });
}

uint64_t level_hash_in_columns(const BuildTriangles& level, double min_x, double min_z, double max_x, double max_z) {
    const auto& v = level.mesh.vertices;
    return hash_triangles(level, [&](const auto& t) {
        const double lo_x = std::min({v[t[0]].x(), v[t[1]].x(), v[t[2]].x()}),
                     hi_x = std::max({v[t[0]].x(), v[t[1]].x(), v[t[2]].x()}),
                     lo_z = std::min({v[t[0]].z(), v[t[1]].z(), v[t[2]].z()}),
                     hi_z = std::max({v[t[0]].z(), v[t[1]].z(), v[t[2]].z()});
        return lo_x <= max_x && hi_x >= min_x && lo_z <= max_z && hi_z >= min_z;
    });
}

}  // namespace nl
