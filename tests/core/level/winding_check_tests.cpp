// A level wound the wrong way round (issue 33): per mesh, the floor a body could stand on measured as
// given and turned over (level/winding_check.h). Known answers: the default level, a terrain and the
// shared levels, each as given and turned over; a box and a room seen from inside, which measure alike
// both ways and are never taken for turned over; a build on a turned-over level says so in the log
// and in what the navmesh was made for.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "generated_mesh.h"
#include "io/obj_reader.h"
#include "level_generator.h"
#include "level/winding_check.h"
#include "shared_levels.h"
#include "world/world.h"

namespace {

using nl::TriangleMesh;
using nl::Vec3;

TriangleMesh mesh_of(const nl::levelgen::GeneratedLevel& level) { return nl::test::to_triangle_mesh(level); }

TriangleMesh turned_over(TriangleMesh mesh) {
    for (nl::Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

nl::WindingEstimate estimate(const TriangleMesh& mesh) {
    return nl::estimate_winding(mesh, 0, mesh.triangles.size(), 45.0f, 2.0f);
}

}  // namespace

TEST_CASE("winding: the default level looks turned over only when it is") {
    const TriangleMesh level = mesh_of(nl::levelgen::generate_default_level(1));
    const nl::WindingEstimate given = estimate(level), turned = estimate(turned_over(level));
    MESSAGE("as given: floor " << given.floor_as_given << " m2, turned over " << given.floor_turned_over << " m2");
    CHECK_FALSE(nl::looks_turned_over(given));
    CHECK(nl::looks_turned_over(turned));
    // Turning it over swaps the two (up to the columns' rounding on shared edges).
    CHECK(turned.floor_as_given == doctest::Approx(given.floor_turned_over).epsilon(0.1));
    CHECK(turned.floor_turned_over == doctest::Approx(given.floor_as_given).epsilon(0.01));
}

TEST_CASE("winding: a terrain's floor is all on one side") {
    nl::levelgen::GeneratedLevel terrain;
    terrain.add_ground_grid(0.0f, 0.0f, 20.0f, 20.0f, 1.0f,
                            [](float x, float z) { return 0.3f * std::sin(x) * std::cos(0.5f * z); });
    const TriangleMesh mesh = mesh_of(terrain);
    const nl::WindingEstimate given = estimate(mesh);
    CHECK(given.floor_as_given == doctest::Approx(400.0f).epsilon(0.05));
    CHECK(given.floor_turned_over == 0.0f);
    CHECK_FALSE(nl::looks_turned_over(given));
    CHECK(nl::looks_turned_over(estimate(turned_over(mesh))));
}

TEST_CASE(
    "winding: a tall box, or a room seen from inside, measures alike both ways and is never taken for turned over") {
    nl::levelgen::GeneratedLevel box;
    box.add_box({{0.0f, 0.0f, 0.0f}, {6.0f, 3.0f, 4.0f}});
    const TriangleMesh outside = mesh_of(box), inside = turned_over(outside);
    const nl::WindingEstimate from_outside = estimate(outside), from_inside = estimate(inside);
    // Its top, under the sky, as given; its floor inside, under its 3 m ceiling, turned over.
    CHECK(from_outside.floor_as_given == doctest::Approx(24.0f).epsilon(0.05));
    CHECK(from_outside.floor_turned_over == doctest::Approx(24.0f).epsilon(0.05));
    CHECK_FALSE(nl::looks_turned_over(from_outside));
    CHECK_FALSE(nl::looks_turned_over(from_inside));
    // A slab too thin to stand under: only its top is a floor.
    nl::levelgen::GeneratedLevel slab;
    slab.add_box({{0.0f, -1.0f, 0.0f}, {6.0f, 0.0f, 4.0f}});
    CHECK(estimate(mesh_of(slab)).floor_turned_over == 0.0f);
    CHECK(nl::looks_turned_over(estimate(turned_over(mesh_of(slab)))));
}

// Every shared level as given is never taken for turned over. Turned over, the open ones are; the
// two built as closed rooms (floors under ceilings) measure alike both ways, as a room seen from
// inside does, and are not: their winding cannot be told from their shape.
TEST_CASE("winding: no shared level looks turned over as given, and the open ones do turned over") {
    const std::vector<std::string> closed_rooms = {"dotrecast_convex.obj", "dungeon.obj"};
    const auto levels = nl::test::shared_levels();
    if (levels.empty() && !nl::test::levels_required()) return;
    REQUIRE_FALSE(levels.empty());
    for (const auto& path : levels) {
        CAPTURE(path.filename().string());
        const TriangleMesh level = nl::read_obj_file(path.string());
        const nl::WindingEstimate given = estimate(level), turned = estimate(turned_over(level));
        MESSAGE(path.filename().string() << ": floor as given " << given.floor_as_given << " m2, turned over "
                                         << given.floor_turned_over << " m2");
        CHECK_FALSE(nl::looks_turned_over(given));
        const bool closed =
            std::find(closed_rooms.begin(), closed_rooms.end(), path.filename().string()) != closed_rooms.end();
        CHECK(nl::looks_turned_over(turned) == !closed);
    }
}
