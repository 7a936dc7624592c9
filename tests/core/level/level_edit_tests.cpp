// Registering, moving and removing meshes, and queries running while that happens.
#include <doctest/doctest.h>

#include <atomic>
#include <thread>

#include "level/level.h"
#include "util/error.h"

using nl::Vec3;

namespace {

nl::TriangleMesh floor_quad(float size) {
    nl::TriangleMesh m;
    m.vertices = {Vec3(0, 0, 0), Vec3(size, 0, 0), Vec3(size, 0, size), Vec3(0, 0, size)};
    m.triangles = {{0, 2, 1}, {0, 3, 2}};  // counter-clockwise seen from above: normal +Y
    return m;
}

nl::RayHit cast_down(const nl::Level& level, float x, float z) {
    const nl::Ray ray{Vec3(x, 100.0f, z), Vec3(0, -1, 0), std::numeric_limits<float>::infinity()};
    nl::RayHit hit;
    level.cast_rays(&ray, 1, &hit);
    return hit;
}

nl::Transform lift(float y) {
    nl::Transform t = nl::Transform::Identity();
    t.translate(Vec3(0, y, 0));
    return t;
}

}  // namespace

TEST_CASE("a floor is hit from above with exact distance, point, normal and triangle") {
    auto tasks = nl::make_tbb_task_system(1);
    nl::Level level(*tasks);
    const nl::Handle h = level.add_mesh(floor_quad(10), lift(2.0f), 0, 42);
    const nl::RayHit hit = cast_down(level, 7.0f, 2.0f);
    REQUIRE(hit.hit);
    CHECK(hit.distance == doctest::Approx(98.0f));
    CHECK(hit.point.y() == doctest::Approx(2.0f));
    CHECK(hit.normal.y() == doctest::Approx(1.0f));
    CHECK(hit.mesh == h);
    CHECK(hit.triangle == 0);  // (7, 2) lies in triangle {0, 2, 1}
    CHECK(cast_down(level, 2.0f, 7.0f).triangle == 1);
    CHECK_FALSE(cast_down(level, 11.0f, 2.0f).hit);
    CHECK(level.info(h).user_data == 42);
    CHECK(level.info(h).bounds.min.y() == doctest::Approx(2.0f));
}

TEST_CASE("moving a static and a movable mesh: queries see the new place") {
    auto tasks = nl::make_tbb_task_system(2);
    nl::Level level(*tasks);
    const nl::Handle fixed = level.add_mesh(floor_quad(4), lift(0.0f), 0, 0);
    nl::Transform far = nl::Transform::Identity();
    far.translate(Vec3(20, 1, 0));
    const nl::Handle platform = level.add_mesh(floor_quad(4), far, nl::kMeshMovable, 0);
    CHECK(cast_down(level, 21, 1).mesh == platform);
    CHECK(cast_down(level, 21, 1).point.y() == doctest::Approx(1.0f));

    far.translate(Vec3(0, 3, 0));
    level.set_transform(platform, far);
    CHECK(cast_down(level, 21, 1).point.y() == doctest::Approx(4.0f));

    level.set_transform(fixed, lift(-2.0f));
    CHECK(cast_down(level, 1, 1).point.y() == doctest::Approx(-2.0f));
    CHECK(level.info(fixed).bounds.max.y() == doctest::Approx(-2.0f));

    // A rotated movable mesh reports a world-space normal.
    nl::Transform tilted = nl::Transform::Identity();
    tilted.translate(Vec3(20, 1, 0));
    tilted.rotate(Eigen::AngleAxisf(0.3f, Vec3::UnitZ()));
    level.set_transform(platform, tilted);
    const nl::RayHit hit = cast_down(level, 21, 1);
    REQUIRE(hit.mesh == platform);
    CHECK((hit.normal - tilted.linear() * Vec3::UnitY()).norm() < 1e-5f);
}

TEST_CASE("removal frees the mesh; stale handles are refused; geometry ids are reused safely") {
    auto tasks = nl::make_tbb_task_system(1);
    nl::Level level(*tasks);
    const nl::Handle a = level.add_mesh(floor_quad(4), lift(0.0f), 0, 0);
    const nl::Handle b = level.add_mesh(floor_quad(4), lift(1.0f), nl::kMeshMovable, 0);
    CHECK(cast_down(level, 1, 1).mesh == b);
    level.remove_mesh(b);
    CHECK(cast_down(level, 1, 1).mesh == a);
    CHECK_THROWS_AS(level.remove_mesh(b), nl::Error);
    CHECK_THROWS_AS(level.set_transform(b, lift(0)), nl::Error);
    CHECK_THROWS_AS(level.info(b), nl::Error);
    CHECK_FALSE(level.contains(b));

    level.remove_mesh(a);
    CHECK_FALSE(cast_down(level, 1, 1).hit);
    const nl::Handle c = level.add_mesh(floor_quad(4), lift(5.0f), 0, 0);
    CHECK_FALSE(level.contains(a));
    CHECK(cast_down(level, 1, 1).mesh == c);
    CHECK(level.meshes().size() == 1);
}

TEST_CASE("a failed registration changes nothing") {
    auto tasks = nl::make_tbb_task_system(1);
    nl::Level level(*tasks);
    level.add_mesh(floor_quad(4), lift(0.0f), 0, 0);
    nl::TriangleMesh bad = floor_quad(4);
    bad.triangles[1][0] = 9;
    CHECK_THROWS_AS(level.add_mesh(bad, lift(1.0f), 0, 0), nl::Error);
    CHECK_THROWS_AS(level.add_mesh(floor_quad(4), lift(1.0f), 0x80, 0), nl::Error);
    CHECK(level.meshes().size() == 1);
    CHECK(cast_down(level, 1, 1).point.y() == doctest::Approx(0.0f));
}

TEST_CASE("queries from several threads while another thread adds, moves and removes meshes") {
    auto tasks = nl::make_tbb_task_system(2);
    nl::Level level(*tasks);
    level.add_mesh(floor_quad(10), lift(0.0f), 0, 0);
    std::atomic<bool> stop{false};
    std::atomic<int> bad{0};
    std::vector<std::thread> readers;
    for (int r = 0; r < 2; ++r) {
        readers.emplace_back([&] {
            std::vector<nl::Ray> rays(64, nl::Ray{Vec3(5, 50, 5), Vec3(0, -1, 0), 1000.0f});
            std::vector<nl::RayHit> hits(rays.size());
            while (!stop) {
                level.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.data());
                for (const auto& h : hits) {
                    // The ground floor is always there; a moving platform may be above it.
                    if (!h.hit || h.point.y() < -1e-4f) ++bad;
                }
            }
        });
    }
    for (int i = 0; i < 200; ++i) {
        const nl::Handle p = level.add_mesh(floor_quad(10), lift(1.0f + i % 7), (i % 2) ? nl::kMeshMovable : 0u, 0);
        level.set_transform(p, lift(2.0f + i % 5));
        level.remove_mesh(p);
    }
    stop = true;
    for (auto& t : readers) t.join();
    CHECK(bad == 0);
    CHECK(level.meshes().size() == 1);
}
