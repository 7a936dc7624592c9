// Procedural levels with known features (platforms, gaps, ledges, stairs, walls, ceilings,
// corridors), as plain vertex/index arrays. No NavLink dependency: samples pass the arrays through
// the C ABI, tests through the core, and both can write them as OBJ.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace nl::levelgen {

struct Box {
    float min[3];
    float max[3];
};

// A named point of a generated level, on a walkable surface (the demo's start and goal).
struct Marker {
    std::string name;
    float position[3];
};

struct GeneratedLevel {
    std::vector<float> positions;   // x y z per vertex, Y up, metres
    std::vector<uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside
    std::vector<Box> boxes;         // the solid boxes the triangles were made from (a tessellated
                                    // ground, add_ground_grid, is not one of them)
    std::vector<Marker> markers;    // named points, if the generator has any

    // The marker called `name`, or nullptr.
    const Marker* marker(const std::string& name) const;

    uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size() / 3); }
    uint32_t triangle_count() const { return static_cast<uint32_t>(indices.size() / 3); }

    // Adds a closed box (12 triangles, outward-facing).
    void add_box(const Box& box);
    // Adds an open, finely tessellated ground surface over [x0, x1] x [z0, z1] in cells of about
    // `cell` metres (two triangles each, facing up), its height at (x, z) given by `height`.
    template <typename HeightFn>
    void add_ground_grid(float x0, float z0, float x1, float z1, float cell, HeightFn height);
    // Writes Wavefront OBJ text (positions and triangular faces).
    std::string to_obj() const;
};

// The default demo level: a row of four platforms at several heights (boxes 0 to 3, along +x, z in
// [0, 6]) separated by gaps of several widths (1.4-1.8 m, 2.8-3.2 m, and 0.8-1.1 m with the last
// platform 2.0-2.4 m lower: a drop), a lower floor under everything (box 4) with ledges all round to
// drop from, a stair route around (stairs from the lower floor to the first, second and last
// platforms), a wall that blocks one side of the second jump, a low ceiling over one side of the first
// gap and a narrow corridor on the lower floor. Markers "start" (on the first platform) and "goal" (on
// the last) are the demo's route; "ladder_bottom" and "ladder_top" a place for a ladder (a manual
// link) from the lower floor to the last platform's stair landing. `seed` varies sizes and heights within ranges that keep every
// feature present.
GeneratedLevel generate_default_level(uint32_t seed);

// A large field of `columns` x `rows` pillars and platforms at random heights, for benchmarks
// (about 12 triangles per box, subdivided floors included).
GeneratedLevel generate_field_level(uint32_t seed, uint32_t columns, uint32_t rows);

// A large, detailed level for the link benchmark: `blocks` x `blocks` blocks of 12 x 12 m on one
// finely tessellated, gently undulating ground (cells of `ground_cell` metres: 1,152 triangles per
// block at the default 0.5 m, so 14 x 14 blocks make about 235,000 triangles), each block holding one
// feature with link opportunities: platform pairs across gaps of 1 to 3.5 m, terraces stepping up
// 1.2 m, parkour pillars (some too tall to drop from), a jump blocked by a wall or a low slab, a deck
// around a pit reached by stairs, a tower with a ledge, or open ground with a low wall. Ledges look
// onto the ground 1 to 7 m below, and neighbouring blocks' platforms sometimes face each other across
// a jumpable gap.
GeneratedLevel generate_large_level(uint32_t seed, uint32_t blocks, float ground_cell = 0.5f);

template <typename HeightFn>
void GeneratedLevel::add_ground_grid(float x0, float z0, float x1, float z1, float cell, HeightFn height) {
    const auto nx = static_cast<uint32_t>(std::max(1.0f, (x1 - x0) / cell + 0.5f));
    const auto nz = static_cast<uint32_t>(std::max(1.0f, (z1 - z0) / cell + 0.5f));
    const uint32_t base = vertex_count();
    for (uint32_t j = 0; j <= nz; ++j) {
        for (uint32_t i = 0; i <= nx; ++i) {
            const float x = x0 + (x1 - x0) * static_cast<float>(i) / static_cast<float>(nx);
            const float z = z0 + (z1 - z0) * static_cast<float>(j) / static_cast<float>(nz);
            positions.push_back(x);
            positions.push_back(height(x, z));
            positions.push_back(z);
        }
    }
    for (uint32_t j = 0; j < nz; ++j) {
        for (uint32_t i = 0; i < nx; ++i) {
            const uint32_t a = base + j * (nx + 1) + i, b = a + 1, c = a + (nx + 1), d = c + 1;
            // Counter-clockwise seen from above (+y): a (x, z), c (x, z+1), d (x+1, z+1), b (x+1, z).
            for (uint32_t k : {a, c, d, a, d, b}) indices.push_back(k);
        }
    }
}

}  // namespace nl::levelgen
