// Random start points and destinations on a Recast polygon mesh that every side of a benchmark draws
// alike: agent i's k-th point comes from a generator seeded with (seed, i, k), on the mesh's largest
// connected part, so every destination can be reached by walking.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "recast_detour.h"

namespace nl::bench {

// Agent i's k-th point (k = 0: its start), the same for every side.
struct Destinations {
    const rcPolyMesh* pm = nullptr;
    std::vector<int> polygons;  // the largest connected part
    uint32_t seed = 0;

    void point(uint32_t agent, uint32_t k, float out[3]) const {
        std::seed_seq sequence{seed, agent, k};
        std::mt19937 rng(sequence);
        std::uniform_int_distribution<size_t> pick(0, polygons.size() - 1);
        nl::bench::random_point_in_polygon(*pm, polygons[pick(rng)], rng, out);
    }

    // The x-z area of the part, m^2 (how crowded `count` bodies make it).
    double area() const {
        double total = 0.0;
        for (const int p : polygons) {
            const unsigned short* poly = &pm->polys[size_t(p) * 2 * pm->nvp];
            int n = 0;
            while (n < pm->nvp && poly[n] != RC_MESH_NULL_IDX) ++n;
            for (int k = 1; k + 1 < n; ++k) {
                const unsigned short *a = &pm->verts[3 * poly[0]], *b = &pm->verts[3 * poly[k]],
                                     *c = &pm->verts[3 * poly[k + 1]];
                const double abx = b[0] - a[0], abz = b[2] - a[2], acx = c[0] - a[0], acz = c[2] - a[2];
                total += 0.5 * std::fabs(abx * acz - abz * acx) * pm->cs * pm->cs;
            }
        }
        return total;
    }
};

}  // namespace nl::bench
