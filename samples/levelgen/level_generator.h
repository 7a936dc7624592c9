// Procedural levels with known features (platforms, gaps, ledges, stairs, walls, ceilings,
// corridors), as plain vertex/index arrays. No NavLink dependency: samples pass the arrays through
// the C ABI, tests through the core, and both can write them as OBJ.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nl::levelgen {

struct Box {
    float min[3];
    float max[3];
};

struct GeneratedLevel {
    std::vector<float> positions;   // x y z per vertex, Y up, metres
    std::vector<uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside
    std::vector<Box> boxes;         // the solid boxes the triangles were made from

    uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size() / 3); }
    uint32_t triangle_count() const { return static_cast<uint32_t>(indices.size() / 3); }

    // Adds a closed box (12 triangles, outward-facing).
    void add_box(const Box& box);
    // Writes Wavefront OBJ text (positions and triangular faces).
    std::string to_obj() const;
};

// The default demo level: a row of platforms at several heights separated by gaps of several widths,
// a ledge to drop from, a stair route around, a wall that blocks one jump, a low ceiling over a gap and
// a narrow corridor. `seed` varies sizes and heights within ranges that keep every feature present.
GeneratedLevel generate_default_level(uint32_t seed);

// A large field of `columns` x `rows` pillars and platforms at random heights, for benchmarks
// (about 12 triangles per box, subdivided floors included).
GeneratedLevel generate_field_level(uint32_t seed, uint32_t columns, uint32_t rows);

}  // namespace nl::levelgen
