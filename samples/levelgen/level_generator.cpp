#include "level_generator.h"

#include <random>
#include <sstream>

namespace nl::levelgen {
namespace {

// Deterministic across platforms (std::uniform_real_distribution is not).
class Random {
public:
    explicit Random(uint32_t seed) : engine_(seed) {}
    float uniform(float lo, float hi) {
        const double unit = static_cast<double>(engine_() - engine_.min()) /
                            (static_cast<double>(engine_.max() - engine_.min()) + 1.0);
        return lo + static_cast<float>(unit) * (hi - lo);
    }

private:
    std::mt19937 engine_;
};

Box box(float x0, float y0, float z0, float x1, float y1, float z1) { return Box{{x0, y0, z0}, {x1, y1, z1}}; }

}  // namespace

void GeneratedLevel::add_box(const Box& b) {
    const auto base = vertex_count();
    for (int i = 0; i < 8; ++i) {
        positions.push_back((i & 1) ? b.max[0] : b.min[0]);
        positions.push_back((i & 2) ? b.max[1] : b.min[1]);
        positions.push_back((i & 4) ? b.max[2] : b.min[2]);
    }
    // Corner i has x from bit 0, y from bit 1, z from bit 2. Each face: two triangles, outward CCW.
    static const uint32_t faces[6][4] = {
        {0, 4, 6, 2},  // -x
        {1, 3, 7, 5},  // +x
        {0, 1, 5, 4},  // -y
        {2, 6, 7, 3},  // +y
        {0, 2, 3, 1},  // -z
        {4, 5, 7, 6},  // +z
    };
    for (const auto& f : faces) {
        for (uint32_t k : {f[0], f[1], f[2], f[0], f[2], f[3]}) indices.push_back(base + k);
    }
    boxes.push_back(b);
}

std::string GeneratedLevel::to_obj() const {
    std::ostringstream out;
    out << "# NavLink procedural level: " << vertex_count() << " vertices, " << triangle_count() << " triangles\n";
    for (size_t i = 0; i < positions.size(); i += 3)
        out << "v " << positions[i] << ' ' << positions[i + 1] << ' ' << positions[i + 2] << '\n';
    for (size_t i = 0; i < indices.size(); i += 3)
        out << "f " << indices[i] + 1 << ' ' << indices[i + 1] + 1 << ' ' << indices[i + 2] + 1 << '\n';
    return out.str();
}

GeneratedLevel generate_default_level(uint32_t seed) {
    Random rng(seed);
    GeneratedLevel level;
    const float thickness = 0.5f;
    const float depth = 6.0f;  // platforms run along +x, 6 m deep in z

    // Start platform, then platforms across gaps of increasing width at varying heights.
    float x = 0.0f;
    float top = 0.0f;
    const float gaps[] = {rng.uniform(1.5f, 2.0f), rng.uniform(2.5f, 3.0f), rng.uniform(4.0f, 5.0f)};
    const float rises[] = {0.0f, rng.uniform(0.5f, 1.0f), rng.uniform(-0.5f, 0.5f)};
    float length = rng.uniform(8.0f, 10.0f);
    level.add_box(box(x, top - thickness, 0.0f, x + length, top, depth));
    x += length;
    for (int i = 0; i < 3; ++i) {
        x += gaps[i];
        top += rises[i];
        length = rng.uniform(6.0f, 8.0f);
        level.add_box(box(x, top - thickness, 0.0f, x + length, top, depth));
        x += length;
    }
    const float end_x = x;

    // Lower floor under everything: falling into a gap lands here, 3 to 4 m down.
    const float floor_y = -rng.uniform(3.0f, 4.0f);
    level.add_box(box(-2.0f, floor_y - thickness, -14.0f, end_x + 2.0f, floor_y, depth + 2.0f));

    // A ledge from the start platform down to the lower floor (drop), and a stair route back up,
    // built in front of the platforms (negative z) so walkers can go round every gap.
    const float stair_x = 2.0f;
    const int steps = 10;
    const float step_rise = -floor_y / steps;
    for (int s = 0; s < steps; ++s) {
        const float y = floor_y + step_rise * (s + 1);
        level.add_box(box(stair_x + s * 0.4f, floor_y, -4.0f, stair_x + (s + 1) * 0.4f, y, -1.0f));
    }
    level.add_box(box(stair_x + steps * 0.4f, -thickness, -4.0f, stair_x + steps * 0.4f + 2.0f, 0.0f, 0.0f));

    // A wall standing in the second gap's landing zone blocks that jump on one side (z in [0, 2]).
    const float wall_x = level.boxes[2].min[0];
    level.add_box(box(wall_x - 0.3f, level.boxes[2].max[1], 0.0f, wall_x, level.boxes[2].max[1] + 3.0f, 2.0f));

    // A low ceiling over the first gap (z in [4, 6]): an arc through it would hit.
    const float gap1_start = level.boxes[0].max[0];
    const float gap1_end = level.boxes[1].min[0];
    level.add_box(box(gap1_start - 0.5f, 1.2f, 4.0f, gap1_end + 0.5f, 1.5f, depth));

    // A narrow corridor (0.8 m wide) on the lower floor, between two long walls.
    const float corridor_z = -10.0f;
    level.add_box(box(4.0f, floor_y, corridor_z - 1.0f, 14.0f, floor_y + 2.5f, corridor_z - 0.4f));
    level.add_box(box(4.0f, floor_y, corridor_z + 0.4f, 14.0f, floor_y + 2.5f, corridor_z + 1.0f));
    return level;
}

GeneratedLevel generate_field_level(uint32_t seed, uint32_t columns, uint32_t rows) {
    Random rng(seed);
    GeneratedLevel level;
    const float cell = 4.0f;
    level.add_box(box(-1.0f, -1.0f, -1.0f, columns * cell + 1.0f, 0.0f, rows * cell + 1.0f));
    for (uint32_t r = 0; r < rows; ++r) {
        for (uint32_t c = 0; c < columns; ++c) {
            const float x0 = c * cell + rng.uniform(0.2f, 0.8f);
            const float z0 = r * cell + rng.uniform(0.2f, 0.8f);
            const float size = rng.uniform(1.5f, 2.8f);
            const float height = rng.uniform(0.3f, 4.0f);
            level.add_box(box(x0, 0.0f, z0, x0 + size, height, z0 + size));
        }
    }
    return level;
}

}  // namespace nl::levelgen
