// The point-location grid on navmeshes whose polygon sizes differ by orders of magnitude: its memory
// stays proportional to the polygon count, and its answers are the brute-force search's.
#include <doctest/doctest.h>

#include <random>

#include "navmesh/navmesh_builder.h"

using nl::NavMeshInput;
using nl::Vec3;

namespace {

// A triangle with its right angle at (x, y, z) and legs `size` along +x and +z, facing up.
void add_triangle(NavMeshInput& in, float x, float y, float z, float size) {
    const auto first = static_cast<uint32_t>(in.vertices.size());
    in.vertices.insert(in.vertices.end(), {Vec3(x, y, z), Vec3(x, y, z + size), Vec3(x + size, y, z)});
    in.indices.insert(in.indices.end(), {first, first + 1, first + 2});
}

// Answers of find_nearest against find_nearest_brute_force at random points of [0, side]^2.
int disagreements(const nl::NavMesh& mesh, float side, int queries, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xz(-1.0f, side + 1.0f), y(-2.0f, 12.0f), extent(0.1f, 4.0f);
    int differ = 0;
    for (int i = 0; i < queries; ++i) {
        const Vec3 p(xz(rng), y(rng), xz(rng));
        const Vec3 h(extent(rng), extent(rng), extent(rng));
        const nl::NavPoint fast = mesh.find_nearest(p, h), slow = mesh.find_nearest_brute_force(p, h);
        differ += fast.found != slow.found || fast.polygon != slow.polygon || fast.point != slow.point;
    }
    return differ;
}

}  // namespace

TEST_CASE("a few polygons spanning a navmesh of many small ones keep the grid small") {
    // Issue 12's navmesh, scaled down: 100,000 triangles of 0.5 m spread over 1 km, and 100 triangles
    // spanning the whole kilometre. A single grid with cells for the small ones listed every large
    // one in each of its 400,000 cells (160 MB; at 2,000,000 and 537 the offsets wrapped and the
    // grid wrote outside its array).
    NavMeshInput in;
    constexpr int kSide = 316;
    constexpr float kPitch = 1000.0f / kSide;
    for (int row = 0; row < kSide; ++row)
        for (int column = 0; column < kSide; ++column) add_triangle(in, column * kPitch, 0.0f, row * kPitch, 0.5f);
    for (int i = 0; i < 100; ++i) add_triangle(in, 0.0f, 1.0f + 0.1f * float(i), 0.0f, 1000.0f);
    const auto mesh = nl::build_navmesh(in);
    REQUIRE(mesh->polygon_count() == kSide * kSide + 100);

    // Everything the navmesh holds, grid included, in a few hundred bytes per polygon.
    MESSAGE("navmesh of ", mesh->polygon_count(), " polygons: ", mesh->memory_bytes(), " bytes");
    CHECK(mesh->memory_bytes() < 400 * size_t(mesh->polygon_count()));
    CHECK(disagreements(*mesh, 1000.0f, 300, 5) == 0);
}

TEST_CASE("point location on polygons of every size from 5 cm to 200 m matches brute force") {
    NavMeshInput in;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> where(0.0f, 300.0f), height(0.0f, 10.0f), exponent(-3.0f, 7.6f);
    for (int i = 0; i < 3000; ++i) add_triangle(in, where(rng), height(rng), where(rng), std::exp2(exponent(rng)));
    // Copies of some at the same place: equal answers go to the lower polygon index.
    for (int i = 0; i < 200; ++i) {
        const uint32_t* corners = &in.indices[3 * size_t(i)];
        add_triangle(in, in.vertices[corners[0]].x(), in.vertices[corners[0]].y() + 0.01f, in.vertices[corners[0]].z(),
                     in.vertices[corners[2]].x() - in.vertices[corners[0]].x());
    }
    const auto mesh = nl::build_navmesh(in);
    CHECK(disagreements(*mesh, 300.0f, 20000, 9) == 0);
}
