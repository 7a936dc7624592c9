#include "level_generator.h"

#include <cmath>
#include <random>
#include <sstream>

namespace nl::levelgen {
namespace {

// Deterministic across platforms (std::uniform_real_distribution is not).
class Random {
public:
    explicit Random(uint32_t seed) : engine_(seed) {}
    float uniform(float lo, float hi) {
        const double unit =
            static_cast<double>(engine_() - engine_.min()) / (static_cast<double>(engine_.max() - engine_.min()) + 1.0);
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

const Marker* GeneratedLevel::marker(const std::string& name) const {
    for (const Marker& m : markers)
        if (m.name == name) return &m;
    return nullptr;
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

namespace {

// Stairs between a platform's front side (z < 0) and the lower floor: a landing 2 m wide against the
// platform, then steps going down towards +x. Every step rises at most 0.35 m, well within the
// default agent's max_climb, so walkers go up and down without a link.
void add_stairs_down_from(GeneratedLevel& level, const Box& platform, float floor_y) {
    const float top = platform.max[1];
    const float landing_x0 = platform.min[0] + 0.5f, landing_x1 = landing_x0 + 2.0f;
    level.add_box(box(landing_x0, top - 0.5f, -4.0f, landing_x1, top, 0.0f));
    const int steps = static_cast<int>(std::ceil((top - floor_y) / 0.35f));
    const float rise = (top - floor_y) / static_cast<float>(steps);
    for (int s = 1; s < steps; ++s) {
        const float x0 = landing_x1 + 0.4f * static_cast<float>(s - 1);
        level.add_box(box(x0, floor_y, -4.0f, x0 + 0.4f, top - rise * static_cast<float>(s), -1.0f));
    }
}

}  // namespace

GeneratedLevel generate_default_level(uint32_t seed) {
    Random rng(seed);
    GeneratedLevel level;
    const float thickness = 0.5f;
    const float depth = 6.0f;  // platforms run along +x, 6 m deep in z (z in [0, 6])

    // Four platforms in a row (boxes 0 to 3). With Recast's default agent the navmesh edges sit 0.6 to
    // 0.9 m inside each rim, so a jump across a gap is the gap plus 1.2 to 1.8 m end to end. The ranges
    // keep the gaps apart: the first (1.4-1.8 m, rim to rim) is jumped by a short jumper (2 m gaps), the
    // second (2.8-3.2 m) only by a long one (3.5 m), and the third is narrow but 2.0-2.4 m deep: a
    // one-way drop onto the last platform, too high to jump back up.
    const float gaps[] = {rng.uniform(1.4f, 1.8f), rng.uniform(2.8f, 3.2f), rng.uniform(0.8f, 1.1f)};
    const float rises[] = {0.0f, rng.uniform(0.6f, 1.0f), -rng.uniform(2.0f, 2.4f)};
    float x = 0.0f;
    float top = 0.0f;
    float length = rng.uniform(8.0f, 10.0f);
    level.add_box(box(x, top - thickness, 0.0f, x + length, top, depth));
    x += length;
    for (int i = 0; i < 3; ++i) {
        x += gaps[i];
        top += rises[i];
        length = rng.uniform(7.0f, 8.0f);  // room for a landing and a flight of stairs in front
        level.add_box(box(x, top - thickness, 0.0f, x + length, top, depth));
        x += length;
    }
    const float end_x = x;

    // Lower floor under everything (box 4): falling into a gap lands here, 3.5 to 4 m down.
    const float floor_y = -rng.uniform(3.5f, 4.0f);
    level.add_box(box(-2.0f, floor_y - thickness, -14.0f, end_x + 2.0f, floor_y, depth + 2.0f));

    // Stairs from the lower floor up to the start platform, built in front of it (negative z), rising
    // towards +x to a landing against the platform: the walkers' way down.
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

    // The stair route around every gap: down from the second platform (for jumpers that cannot drop)
    // and up to the last one (for everyone).
    add_stairs_down_from(level, level.boxes[1], floor_y);
    add_stairs_down_from(level, level.boxes[3], floor_y);

    // Where the demo sends its agents: from the start platform to the last one.
    const Box& first = level.boxes[0];
    const Box& last = level.boxes[3];
    level.markers.push_back({"start", {first.min[0] + 2.0f, first.max[1], 3.0f}});
    level.markers.push_back({"goal", {0.5f * (last.min[0] + last.max[0]) + 1.0f, last.max[1], 3.5f}});
    // Where a host could hang a ladder (a manual link): from the lower floor up the west side of the
    // last platform's stair landing, a shortcut past the last flight of stairs.
    level.markers.push_back({"ladder_bottom", {last.min[0] - 0.8f, floor_y, -2.5f}});
    level.markers.push_back({"ladder_top", {last.min[0] + 1.5f, last.max[1], -2.5f}});
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

GeneratedLevel generate_large_level(uint32_t seed, uint32_t blocks, float ground_cell) {
    Random rng(seed);
    GeneratedLevel level;
    const float block = 12.0f;
    const float extent = blocks * block;
    // Gentle waves (at most about 8 degrees of slope, 0.16 m up or down): walkable everywhere.
    auto ground = [](float x, float z) {
        return 0.12f * std::sin(0.31f * x) * std::cos(0.23f * z) + 0.04f * std::sin(1.1f * x + 0.7f * z);
    };
    level.add_ground_grid(0.0f, 0.0f, extent, extent, ground_cell, ground);

    const float base = -1.0f;  // every solid reaches below the ground
    for (uint32_t bz = 0; bz < blocks; ++bz) {
        for (uint32_t bx = 0; bx < blocks; ++bx) {
            const float ox = bx * block, oz = bz * block;
            const bool flip = rng.uniform(0.0f, 1.0f) < 0.5f;  // features run along x or along z
            // A box in block-local coordinates (u along the feature, v across it), y absolute.
            auto put = [&](float u0, float y0, float v0, float u1, float y1, float v1) {
                if (flip)
                    level.add_box(box(ox + v0, y0, oz + u0, ox + v1, y1, oz + u1));
                else
                    level.add_box(box(ox + u0, y0, oz + v0, ox + u1, y1, oz + v1));
            };
            const auto kind = static_cast<int>(rng.uniform(0.0f, 7.0f));
            switch (kind) {
                case 0: {  // two platforms across a gap (jumpable below about 2.8 m, given the agent radius)
                    const float length = rng.uniform(3.5f, 4.5f), gap = rng.uniform(1.0f, 3.5f);
                    const float v0 = rng.uniform(1.0f, 3.0f), v1 = v0 + rng.uniform(4.0f, 7.0f);
                    const float top = rng.uniform(1.2f, 3.5f), other = top + rng.uniform(-0.8f, 0.8f);
                    put(1.0f, base, v0, 1.0f + length, top, v1);
                    put(1.0f + length + gap, base, v0, 11.0f, other, v1);
                    break;
                }
                case 1: {  // terraces stepping up 1.2 m (too high to walk up), with small gaps between
                    const float first = rng.uniform(1.0f, 1.4f), depth = rng.uniform(5.0f, 9.0f);
                    float u = 1.5f;
                    for (int step = 0; step < 3; ++step) {
                        put(u, base, 1.5f, u + 2.8f, first + 1.2f * step, 1.5f + depth);
                        u += 2.8f + rng.uniform(0.0f, 0.8f);
                    }
                    break;
                }
                case 2: {  // parkour pillars: a 2 x 2 grid, some too tall to drop from
                    const float size = rng.uniform(2.5f, 3.0f);
                    const float gap_u = rng.uniform(1.0f, 2.5f), gap_v = rng.uniform(1.0f, 2.5f);
                    for (int i = 0; i < 2; ++i)
                        for (int j = 0; j < 2; ++j) {
                            const float u0 = 1.5f + i * (size + gap_u), v0 = 1.5f + j * (size + gap_v);
                            put(u0, base, v0, u0 + size, rng.uniform(1.0f, 7.0f), v0 + size);
                        }
                    break;
                }
                case 3: {  // a 2 m jump blocked by a wall in the gap, or by a low slab over it
                    const float top = rng.uniform(1.5f, 2.5f), v1 = rng.uniform(7.0f, 10.0f);
                    put(1.0f, base, 1.0f, 5.0f, top, v1);
                    put(7.0f, base, 1.0f, 11.0f, top, v1);
                    if (rng.uniform(0.0f, 1.0f) < 0.5f)
                        put(5.8f, base, 0.5f, 6.2f, top + 3.0f, v1 + 0.5f);
                    else
                        put(3.5f, top + 1.6f, 0.5f, 8.5f, top + 2.0f, v1 + 0.5f);
                    break;
                }
                case 4: {  // a deck around a pit (jumped across, or dropped into), with stairs up to it
                    const float top = rng.uniform(2.4f, 3.0f);
                    const float p0 = rng.uniform(4.0f, 4.5f), p1 = p0 + rng.uniform(2.5f, 3.0f);
                    const float q0 = rng.uniform(4.5f, 5.5f), q1 = q0 + rng.uniform(2.5f, 3.0f);
                    put(2.0f, base, 2.0f, 11.0f, top, p0);   // in front of the pit
                    put(2.0f, base, p1, 11.0f, top, 10.5f);  // behind it
                    put(2.0f, base, p0, q0, top, p1);        // beside it
                    put(q1, base, p0, 11.0f, top, p1);       // on its other side
                    const int steps = static_cast<int>(std::ceil(top / 0.3f));
                    const float tread = 1.7f / steps;
                    for (int k = 0; k < steps; ++k)  // in front of the deck, rising towards it
                        put(4.0f, base, 0.3f + tread * k, 7.0f, top * (k + 1) / steps, 2.0f);
                    break;
                }
                case 5: {  // open ground with a low wall (too high to step over, too thin to stand on)
                    const float v = rng.uniform(3.0f, 9.0f), u0 = rng.uniform(1.0f, 3.0f),
                                u1 = rng.uniform(8.0f, 11.0f);
                    put(u0, base, v, u1, 1.2f, v + 0.3f);
                    break;
                }
                default: {  // a tower with a ledge part-way down
                    const float top = rng.uniform(5.5f, 7.0f), ledge = rng.uniform(2.5f, 3.5f);
                    put(1.5f, base, 2.0f, 7.5f, top, 9.0f);
                    put(7.5f, base, 2.0f, 10.5f, ledge, 9.0f);
                    break;
                }
            }
        }
    }
    return level;
}

}  // namespace nl::levelgen
