// The broad phase of clearance sweeps: the triangle-box test, and Level::boxes_empty against a scan
// of every triangle, for static and movable meshes (rotated, unevenly scaled).
#include <doctest/doctest.h>

#include <random>
#include <string>

#include "brute_force.h"
#include "generated_mesh.h"
#include "level/level.h"
#include "level/oriented_box.h"
#include "level_generator.h"

using nl::Vec3;

namespace {

nl::OrientedBox random_box(std::mt19937& rng, const Vec3& centre, float spread, float size) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), extent(0.02f, size);
    const Eigen::Quaternionf turn = Eigen::Quaternionf::UnitRandom();
    nl::OrientedBox box;
    box.center = centre + spread * Vec3(unit(rng), unit(rng), unit(rng));
    box.axes = turn.toRotationMatrix();
    box.half_extents = Vec3(extent(rng), extent(rng), extent(rng));
    return box;
}

Vec3 point_in(std::mt19937& rng, const nl::OrientedBox& box) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    return box.center + box.axes * Vec3(unit(rng) * box.half_extents.x(), unit(rng) * box.half_extents.y(),
                                        unit(rng) * box.half_extents.z());
}

}  // namespace

TEST_CASE("triangle-box test: a triangle called apart from a box meets no segment inside it") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    nl::TriangleMesh one;
    one.triangles.push_back({0, 1, 2});
    int apart = 0, overlapping = 0, vertex_inside = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const nl::OrientedBox box = random_box(rng, Vec3::Zero(), 0.0f, 1.5f);
        one.vertices = {2.0f * Vec3(unit(rng), unit(rng), unit(rng)), 2.0f * Vec3(unit(rng), unit(rng), unit(rng)),
                        2.0f * Vec3(unit(rng), unit(rng), unit(rng))};
        const bool overlap = nl::triangle_overlaps_box(one.vertices[0], one.vertices[1], one.vertices[2], box);
        overlapping += overlap;
        // A vertex inside the box is an overlap.
        for (const Vec3& v : one.vertices) {
            const Vec3 local = box.axes.transpose() * (v - box.center);
            if ((local.cwiseAbs().array() <= box.half_extents.array()).all()) {
                ++vertex_inside;
                CHECK(overlap);
            }
        }
        if (overlap) continue;
        ++apart;
        for (int s = 0; s < 40; ++s) {
            const Vec3 from = point_in(rng, box), to = point_in(rng, box);
            const auto hit = nl::test::intersect_triangle(one, 0, from, to - from, 1.0);
            if (hit) FAIL_CHECK("a segment inside the box crosses a triangle called apart from it");
        }
    }
    INFO(apart, " apart, ", overlapping, " overlapping, ", vertex_inside, " vertices inside");
    CHECK(apart > 400);
    CHECK(overlapping > 400);
}

TEST_CASE("triangle-box test: known cases") {
    nl::OrientedBox box;
    box.half_extents = Vec3(1, 1, 1);
    // A big triangle through the middle, no vertex inside, no box corner on it.
    CHECK(nl::triangle_overlaps_box(Vec3(-10, 0, -10), Vec3(10, 0, -10), Vec3(0, 0, 10), box));
    // The same plane lifted clear of the box.
    CHECK_FALSE(nl::triangle_overlaps_box(Vec3(-10, 1.01f, -10), Vec3(10, 1.01f, -10), Vec3(0, 1.01f, 10), box));
    // Touching a face counts.
    CHECK(nl::triangle_overlaps_box(Vec3(-10, 1, -10), Vec3(10, 1, -10), Vec3(0, 1, 10), box));
    // Past a box edge, slanted: only an edge-by-axis cross product separates it.
    CHECK_FALSE(nl::triangle_overlaps_box(Vec3(2.2f, 0, -5), Vec3(0, 2.2f, -5), Vec3(1.2f, 1.2f, 5), box));
    // Degenerate (a sliver along a line through the box): not called apart.
    CHECK(nl::triangle_overlaps_box(Vec3(-3, 0, 0), Vec3(3, 0, 0), Vec3(0, 0, 0), box));
    // A rotated box: 45 degrees about y reaches sqrt(2) along x.
    box.axes = Eigen::AngleAxisf(0.785398f, Vec3::UnitY()).toRotationMatrix();
    CHECK(nl::triangle_overlaps_box(Vec3(1.3f, -5, -5), Vec3(1.3f, 5, -5), Vec3(1.3f, 0, 5), box));
    CHECK_FALSE(nl::triangle_overlaps_box(Vec3(1.5f, -5, -5), Vec3(1.5f, 5, -5), Vec3(1.5f, 0, 5), box));
}

TEST_CASE("boxes_empty agrees with every triangle, for static and movable meshes") {
    const nl::TriangleMesh mesh = nl::test::to_triangle_mesh(nl::levelgen::generate_default_level(3));
    nl::Transform moved = nl::Transform::Identity();
    moved.translate(Vec3(4.0f, 1.0f, -2.0f));
    moved.rotate(Eigen::AngleAxisf(0.5f, Vec3(0.3f, 1.0f, 0.2f).normalized()));
    moved.scale(Vec3(1.4f, 0.7f, 1.1f));
    for (const uint32_t flags : {0u, uint32_t(nl::kMeshMovable)}) {
        const std::string kind = flags ? "movable" : "static";
        INFO(kind);
        auto tasks = nl::make_tbb_task_system(2);
        nl::Level level(*tasks);
        const nl::Handle h = level.add_mesh(mesh, moved, flags, 0);
        const nl::Aabb bounds = level.info(h).bounds;
        nl::TriangleMesh world = mesh;
        for (Vec3& v : world.vertices) v = moved * v;

        std::mt19937 rng(flags + 5);
        std::vector<nl::OrientedBox> boxes;
        std::uniform_int_distribution<size_t> any_triangle(0, world.triangles.size() - 1);
        for (int i = 0; i < 3000; ++i) {
            if (i % 2) {
                boxes.push_back(random_box(rng, 0.5f * (bounds.min + bounds.max),
                                           0.5f * (bounds.max - bounds.min).maxCoeff(), 2.0f));
                continue;
            }
            // Near a surface: the cases that are decided by a few centimetres.
            const nl::Triangle& t = world.triangles[any_triangle(rng)];
            const Vec3 centroid = (world.vertices[t[0]] + world.vertices[t[1]] + world.vertices[t[2]]) / 3.0f;
            boxes.push_back(random_box(rng, centroid, 1.5f, 1.0f));
        }
        std::vector<uint8_t> empty(boxes.size());
        level.boxes_empty(boxes.data(), static_cast<uint32_t>(boxes.size()), empty.data());

        int empty_count = 0, mismatches = 0;
        for (size_t i = 0; i < boxes.size(); ++i) {
            bool touched = false;
            for (const nl::Triangle& t : world.triangles)
                if (nl::triangle_overlaps_box(world.vertices[t[0]], world.vertices[t[1]], world.vertices[t[2]],
                                              boxes[i])) {
                    touched = true;
                    break;
                }
            empty_count += empty[i];
            mismatches += (empty[i] != 0) == touched;
        }
        MESSAGE(kind, ": ", empty_count, " of ", boxes.size(), " boxes empty");
        CHECK(mismatches == 0);
        CHECK(empty_count > 300);
        CHECK(empty_count < 2700);

        // What the sweeps rely on: no segment inside an empty box is blocked.
        std::vector<nl::Segment> inside;
        for (size_t i = 0; i < boxes.size(); ++i)
            if (empty[i])
                for (int s = 0; s < 8; ++s)
                    inside.push_back(nl::Segment{point_in(rng, boxes[i]), point_in(rng, boxes[i])});
        std::vector<uint8_t> blocked(inside.size());
        level.segments_blocked(inside.data(), static_cast<uint32_t>(inside.size()), blocked.data());
        int blocked_count = 0;
        for (uint8_t b : blocked) blocked_count += b;
        CHECK(blocked_count == 0);
    }
}

TEST_CASE(
    "static_triangles gives the corners of the triangle each ray hit; nothing for misses, movable or removed meshes") {
    nl::TriangleMesh mesh = nl::test::to_triangle_mesh(nl::levelgen::generate_default_level(5));
    mesh.triangles.insert(mesh.triangles.begin(), {0, 0, 1});  // degenerate: dropped, so kept != input
    nl::Transform moved = nl::Transform::Identity();
    moved.translate(Vec3(-3.0f, 2.0f, 7.0f));
    moved.rotate(Eigen::AngleAxisf(0.8f, Vec3::UnitY()));
    moved.scale(Vec3(1.2f, 0.9f, 1.0f));
    for (const uint32_t flags : {0u, uint32_t(nl::kMeshMovable)}) {
        auto tasks = nl::make_tbb_task_system(2);
        nl::Level level(*tasks);
        const nl::Handle h = level.add_mesh(mesh, moved, flags, 0);
        const nl::Aabb b = level.info(h).bounds;
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> ux(b.min.x() - 2.0f, b.max.x() + 2.0f),
            uz(b.min.z() - 2.0f, b.max.z() + 2.0f);
        std::vector<nl::Ray> rays;
        for (int i = 0; i < 2000; ++i)
            rays.push_back(nl::Ray{Vec3(ux(rng), b.max.y() + 1.0f, uz(rng)), Vec3(0, -1, 0), 1000.0f});
        std::vector<nl::RayHit> hits(rays.size());
        level.cast_rays(rays.data(), uint32_t(rays.size()), hits.data());
        std::vector<std::optional<std::array<Vec3, 3>>> corners(hits.size());
        level.static_triangles(hits.data(), uint32_t(hits.size()), corners.data());
        int hit_count = 0, missed = 0;
        for (size_t i = 0; i < hits.size(); ++i) {
            const nl::RayHit& hit = hits[i];
            if (!hit.hit || flags) {
                CHECK(!corners[i]);
                missed += !hit.hit;
                hit_count += hit.hit;
                continue;
            }
            ++hit_count;
            REQUIRE(corners[i]);
            const auto& t = *corners[i];
            // The hit point lies in the triangle's plane, and the input triangle is the same one.
            const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
            CHECK(std::fabs(n.dot(hit.point - t[0])) < 1e-3f);
            const nl::Triangle& input = mesh.triangles[hit.triangle];
            CHECK(((moved * mesh.vertices[input[0]]) - t[0]).norm() < 1e-4f);
        }
        CHECK(hit_count > 400);
        CHECK(missed > 0);
        nl::RayHit bad = hits[0];
        bad.hit = true;
        bad.mesh = h;
        bad.primitive = 1u << 30;
        level.static_triangles(&bad, 1, corners.data());
        CHECK(!corners[0]);
        bad.primitive = 0;
        level.remove_mesh(h);
        level.static_triangles(&bad, 1, corners.data());
        CHECK(!corners[0]);
    }
}
