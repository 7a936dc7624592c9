// A level given in other units than metres, or with z up (issue 33): its walls' height and width
// against the body's, and its floor read with y up and with z up (level/frame_check.h). Known
// answers: the default level and every shared level as given (nothing to say), in centimetres
// (walls a hundred times too tall), in kilometres' numbers (narrower than a body) and given with z
// up (more floor with z up, except the two closed rooms, which measure alike both ways); and a
// mesh registered with its units and up axis is brought into metres with y up.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "generated_mesh.h"
#include "io/obj_reader.h"
#include "level/frame_check.h"
#include "level_generator.h"
#include "shared_levels.h"
#include "world/world.h"

namespace {

using nl::TriangleMesh;
using nl::Vec3;

constexpr float kHeight = 2.0f;

nl::FrameEstimate estimate(const TriangleMesh& mesh) {
    std::vector<uint32_t> all(mesh.triangles.size());
    std::iota(all.begin(), all.end(), 0u);
    return nl::estimate_frame(mesh, all, all, 45.0f, kHeight);
}

TriangleMesh scaled(TriangleMesh mesh, float units_per_metre) {
    for (Vec3& v : mesh.vertices) v *= units_per_metre;
    return mesh;
}

// NavLink's (x, y, z) given with z up: (x, -z, y).
TriangleMesh given_z_up(TriangleMesh mesh) {
    for (Vec3& v : mesh.vertices) v = Vec3(v.x(), -v.z(), v.y());
    return mesh;
}

void check_as_given(const TriangleMesh& level) {
    const nl::FrameEstimate e = estimate(level);
    MESSAGE("walls " << e.wall_height << " m, " << e.across << " m across, floor " << e.floor_y_up << " m2 with y up, "
                     << e.floor_z_up << " m2 with z up");
    CHECK_FALSE(nl::looks_larger_than_metres(e, kHeight));
    CHECK_FALSE(nl::looks_smaller_than_metres(e, kHeight));
    CHECK_FALSE(nl::looks_z_up(e));
    CHECK(nl::looks_larger_than_metres(estimate(scaled(level, 100.0f)), kHeight));
    CHECK(nl::looks_smaller_than_metres(estimate(scaled(level, 0.001f)), kHeight));
}

}  // namespace

TEST_CASE("frame: the default level as given, in centimetres, in kilometres and with z up") {
    const TriangleMesh level = nl::test::to_triangle_mesh(nl::levelgen::generate_default_level(1));
    check_as_given(level);
    const nl::FrameEstimate z_up = estimate(given_z_up(level));
    CHECK(nl::looks_z_up(z_up));
    CHECK_FALSE(nl::looks_larger_than_metres(z_up, kHeight));  // its walls measured with z up
    // In centimetres and z up: both, the walls measured with z up.
    const nl::FrameEstimate both = estimate(given_z_up(scaled(level, 100.0f)));
    CHECK(nl::looks_z_up(both));
    CHECK(nl::looks_larger_than_metres(both, kHeight));
    CHECK(both.wall_height == doctest::Approx(100.0f * estimate(level).wall_height).epsilon(0.01));
}

TEST_CASE("frame: a flat floor has no walls and is never taken for other units or z up") {
    nl::levelgen::GeneratedLevel floor;
    floor.add_ground_grid(0.0f, 0.0f, 3000.0f, 3000.0f, 100.0f, [](float, float) { return 0.0f; });
    const nl::FrameEstimate e = estimate(nl::test::to_triangle_mesh(floor));
    CHECK(e.wall_height == 0.0f);
    CHECK_FALSE(nl::looks_larger_than_metres(e, kHeight));
    CHECK_FALSE(nl::looks_z_up(e));
}

TEST_CASE(
    "frame: every shared level as given says nothing; in other units or z up it is told, the closed rooms' axis "
    "excepted") {
    const std::vector<std::string> closed_rooms = {"dotrecast_convex.obj", "dotrecast_house.obj"};
    const auto levels = nl::test::shared_levels();
    if (levels.empty() && !nl::test::levels_required()) return;
    REQUIRE_FALSE(levels.empty());
    for (const auto& path : levels) {
        CAPTURE(path.filename().string());
        const TriangleMesh level = nl::read_obj_file(path.string());
        check_as_given(level);
        const nl::FrameEstimate e = estimate(given_z_up(level));
        MESSAGE(path.filename().string() << " given z up: floor " << e.floor_y_up << " m2 with y up, " << e.floor_z_up
                                         << " m2 with z up");
        const bool closed =
            std::find(closed_rooms.begin(), closed_rooms.end(), path.filename().string()) != closed_rooms.end();
        CHECK(nl::looks_z_up(e) == !closed);
    }
}

TEST_CASE("frame: a mesh registered in centimetres with z up is brought into metres with y up") {
    nl::World world{nl::WorldSettings{}};
    TriangleMesh quad;
    quad.vertices = {Vec3(0, 0, 0), Vec3(200, 0, 0), Vec3(200, 300, 50), Vec3(0, 300, 50)};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    nl::MeshFrame frame;
    frame.metres_per_unit = 0.01f;
    frame.up = nl::UpAxis::Z;
    const nl::Handle h = world.level().add_mesh(quad, nl::Transform::Identity(), 0, 0, 0, frame);
    const nl::MeshInfo info = world.level().info(h);
    CHECK(info.frame.metres_per_unit == 0.01f);
    CHECK(info.frame.up == nl::UpAxis::Z);
    // (x, y, z) -> (x, z, -y), then metres.
    CHECK(info.bounds.min.isApprox(Vec3(0.0f, 0.0f, -3.0f), 1e-5f));
    CHECK(info.bounds.max.isApprox(Vec3(2.0f, 0.5f, 0.0f), 1e-5f));
    // Not said: as given.
    const nl::Handle plain = world.level().add_mesh(quad, nl::Transform::Identity(), 0, 0);
    CHECK(world.level().info(plain).bounds.max.isApprox(Vec3(200.0f, 300.0f, 50.0f)));
    CHECK(world.level().info(plain).frame.up == nl::UpAxis::NotSaid);
}
