// Level::triangles_to_build_in_columns: what a build or content hash of some tiles reads, found through
// Embree. It must be exactly what filtering Level::triangles_to_build gives: the same triangles in the
// same order with the same corners and areas (so a tile built or hashed from it is bit for bit one of a
// whole build), and the bounds of all of it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "generated_mesh.h"
#include "level/level.h"
#include "level/level_hash.h"
#include "level_generator.h"

using nl::Vec3;

namespace {

struct Corners {
    std::vector<std::array<Vec3, 3>> triangles;
    std::vector<uint8_t> areas;
};

Corners corners_of(const nl::BuildTriangles& b) {
    Corners out;
    for (size_t i = 0; i < b.mesh.triangles.size(); ++i) {
        const nl::Triangle& t = b.mesh.triangles[i];
        out.triangles.push_back({b.mesh.vertices[t[0]], b.mesh.vertices[t[1]], b.mesh.vertices[t[2]]});
        out.areas.push_back(b.areas[i]);
    }
    return out;
}

Corners filtered(const nl::BuildTriangles& all, const nl::Columns& columns) {
    const Corners every = corners_of(all);
    Corners out;
    for (size_t i = 0; i < every.triangles.size(); ++i) {
        const auto& [a, b, c] = every.triangles[i];
        if (!columns.met_by(a, b, c)) continue;
        out.triangles.push_back(every.triangles[i]);
        out.areas.push_back(every.areas[i]);
    }
    return out;
}

// The same triangles, each with corners of its own: the level hash sees corners, not how they are shared.
nl::BuildTriangles as_build(const Corners& c) {
    nl::BuildTriangles out;
    for (const auto& t : c.triangles) {
        const auto first = uint32_t(out.mesh.vertices.size());
        out.mesh.vertices.insert(out.mesh.vertices.end(), t.begin(), t.end());
        out.mesh.triangles.push_back({first, first + 1, first + 2});
    }
    out.areas = c.areas;
    return out;
}

}  // namespace

TEST_CASE("triangles_to_build_in_columns gives what filtering triangles_to_build gives, in its order") {
    const nl::TriangleMesh ground = nl::test::to_triangle_mesh(nl::levelgen::generate_default_level(3));
    auto tasks = nl::make_tbb_task_system(2);
    nl::Level level(*tasks);
    // Static meshes: plain, moved and mirrored (its triangles turned), an obstacle, one with an area;
    // and meshes builds leave out: not in the navmesh, movable.
    nl::Transform mirrored = nl::Transform::Identity();
    mirrored.translate(Vec3(30.0f, 0.5f, -4.0f));
    mirrored.scale(Vec3(-1.0f, 1.0f, 1.2f));
    nl::Transform turned = nl::Transform::Identity();
    turned.translate(Vec3(-12.0f, 2.0f, 18.0f));
    turned.rotate(Eigen::AngleAxisf(0.7f, Vec3::UnitY()));
    level.add_mesh(ground, nl::Transform::Identity(), 0, 0);
    level.add_mesh(ground, mirrored, 0, 0);
    level.add_mesh(ground, turned, nl::kMeshObstacle, 0);
    level.add_mesh(ground, turned * mirrored, 0, 0, 7);
    level.add_mesh(ground, mirrored * turned, nl::kMeshNotInNavMesh, 0);
    const nl::Handle movable = level.add_mesh(ground, turned, nl::kMeshMovable, 0);
    const nl::BuildTriangles all = level.triangles_to_build(nl::Handle{});
    nl::Aabb whole;
    for (const Vec3& v : all.mesh.vertices) whole.grow(v);

    std::mt19937 rng(17);
    std::uniform_real_distribution<double> at(-40.0, 60.0), width(0.0, 25.0);
    int empty = 0, some = 0;
    for (int trial = 0; trial < 300; ++trial) {
        nl::Columns columns;
        columns.min_x = at(rng);
        columns.min_z = at(rng);
        columns.max_x = columns.min_x + (trial % 10 == 0 ? 0.0 : width(rng));
        columns.max_z = columns.min_z + width(rng);
        if (trial == 0) columns = nl::Columns{-1e6, -1e6, 1e6, 1e6};
        nl::Aabb bounds;
        const nl::BuildTriangles in_columns = level.triangles_to_build_in_columns(nl::Handle{}, columns, bounds);
        const Corners expected = filtered(all, columns);
        const Corners got = corners_of(in_columns);
        REQUIRE(got.triangles.size() == expected.triangles.size());
        CHECK(got.triangles == expected.triangles);
        CHECK(got.areas == expected.areas);
        CHECK(bounds.min == whole.min);
        CHECK(bounds.max == whole.max);
        // Only the vertices its triangles use.
        std::vector<int> used(in_columns.mesh.vertices.size(), 0);
        for (const nl::Triangle& t : in_columns.mesh.triangles)
            for (uint32_t c : t) used[c] = 1;
        CHECK(std::count(used.begin(), used.end(), 0) == 0);
        CHECK(nl::level_hash(in_columns) == nl::level_hash(as_build(expected)));
        (expected.triangles.empty() ? empty : some) += 1;
    }
    MESSAGE(some, " columns met triangles, ", empty, " none");
    CHECK(some > 100);
    CHECK(empty > 10);

    // A carrier's mesh, in its own space.
    const nl::BuildTriangles own = level.triangles_to_build(movable);
    nl::Aabb bounds;
    const nl::Columns some_columns{-3.0, -3.0, 4.0, 5.0};
    CHECK(corners_of(level.triangles_to_build_in_columns(movable, some_columns, bounds)).triangles ==
          filtered(own, some_columns).triangles);
    // Refused: not finite, min > max.
    CHECK_THROWS_AS(level.triangles_to_build_in_columns(nl::Handle{}, nl::Columns{0.0, 0.0, NAN, 1.0}, bounds),
                    nl::Error);
    CHECK_THROWS_AS(level.triangles_to_build_in_columns(nl::Handle{}, nl::Columns{2.0, 0.0, 1.0, 1.0}, bounds),
                    nl::Error);
}
