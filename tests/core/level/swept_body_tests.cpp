// The exact body test against an independent reference (swept_body_reference.h): points of the
// triangle inside the swept body (an exact inside test per point), and distances to sampled points of
// the body's surface.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "generated_mesh.h"
#include "level/level.h"
#include "level/swept_body.h"
#include "level_generator.h"
#include "swept_body_reference.h"

using nl::Vec3;

using nl::test::inside;
using nl::test::sampled_distance;

TEST_CASE("swept body: never apart when the triangle reaches inside it, never touching when called apart") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), positive(0.05f, 1.0f);
    int apart = 0, overlapping = 0, unsettled_far = 0;
    for (int n = 0; n < 2000; ++n) {
        nl::SweptCylinder b;
        b.from = Vec3(unit(rng), unit(rng), unit(rng)) * 2.0f;
        b.to = b.from + Vec3(unit(rng), unit(rng), unit(rng)) * (n % 5 == 0 ? 0.0f : 3.0f);
        b.radius = n % 7 == 0 ? 0.0f : positive(rng) * 0.6f;
        b.low = positive(rng) * 0.3f;
        b.high = b.low + positive(rng) * 2.0f;
        const Vec3 centre = 0.5f * (b.from + b.to) + Vec3(unit(rng), unit(rng) + 1.0f, unit(rng)) * 1.5f;
        std::array<Vec3, 3> tri;
        for (Vec3& p : tri) p = centre + Vec3(unit(rng), unit(rng), unit(rng)) * (n % 3 == 0 ? 0.1f : 1.5f);
        const double margin = 1e-3;
        const bool is_apart = nl::proven_apart(b, tri, margin);
        const std::array<Eigen::Vector3d, 3> t{tri[0].cast<double>(), tri[1].cast<double>(), tri[2].cast<double>()};
        bool reaches_inside = false;
        for (int i = 0; i <= 30 && !reaches_inside; ++i)
            for (int j = 0; i + j <= 30; ++j)
                if (inside(b, t[0] + (t[1] - t[0]) * (i / 30.0) + (t[2] - t[0]) * (j / 30.0))) reaches_inside = true;
        const double upper = sampled_distance(b, t);
        if (reaches_inside) {
            ++overlapping;
            CHECK_MESSAGE(!is_apart, "case ", n, ": a point of the triangle is inside the body, yet called apart");
        }
        if (is_apart) {
            ++apart;
            CHECK_MESSAGE(upper > margin, "case ", n, ": called apart, but a point of the body is ", upper, " m away");
        } else if (!reaches_inside && upper > 0.05) {
            ++unsettled_far;  // a cleanly separated case the search failed to prove
            MESSAGE("case ", n, ": not proven apart, sampled distance ", upper);
        }
    }
    CHECK(apart > 300);
    CHECK(overlapping > 300);
    CHECK(unsettled_far == 0);
}

TEST_CASE("swept body: known cases, a thin bar, a pole between where lines would be, a face just inside the radius") {
    nl::SweptCylinder b{Vec3(0, 0, 0), Vec3(4, 0, 0), 0.3f, 0.3f, 1.8f};
    auto tri = [](Vec3 a, Vec3 b, Vec3 c) { return std::array<Vec3, 3>{a, b, c}; };
    const double m = 1e-3;
    // A 1 cm bar across the path at chest height: one of its faces.
    CHECK(!nl::proven_apart(b, tri(Vec3(2.0f, 1.20f, -1), Vec3(2.0f, 1.21f, -1), Vec3(2.0f, 1.20f, 1)), m));
    // The same bar above the head, and below the body's bottom.
    CHECK(nl::proven_apart(b, tri(Vec3(2.0f, 1.85f, -1), Vec3(2.0f, 1.86f, -1), Vec3(2.0f, 1.85f, 1)), m));
    CHECK(nl::proven_apart(b, tri(Vec3(2.0f, 0.20f, -1), Vec3(2.0f, 0.21f, -1), Vec3(2.0f, 0.20f, 1)), m));
    // A 2 cm pole standing 0.15 m to the side of the path (between lines at 0 and 0.3 m).
    CHECK(!nl::proven_apart(b, tri(Vec3(2.0f, 0, 0.15f), Vec3(2.02f, 0, 0.15f), Vec3(2.0f, 3, 0.15f)), m));
    // A wall face parallel to the path, 1 cm inside the radius, and 1 cm outside it.
    CHECK(!nl::proven_apart(b, tri(Vec3(-1, 0, 0.29f), Vec3(5, 0, 0.29f), Vec3(-1, 3, 0.29f)), m));
    CHECK(nl::proven_apart(b, tri(Vec3(-1, 0, 0.31f), Vec3(5, 0, 0.31f), Vec3(-1, 3, 0.31f)), m));
    // Touching exactly counts as a hit; just past the margin does not.
    CHECK(!nl::proven_apart(b, tri(Vec3(-1, 0, 0.3f), Vec3(5, 0, 0.3f), Vec3(-1, 3, 0.3f)), m));
    CHECK(!nl::proven_apart(b, tri(Vec3(-1, 0, 0.3005f), Vec3(5, 0, 0.3005f), Vec3(-1, 3, 0.3005f)), m));
    CHECK(nl::proven_apart(b, tri(Vec3(-1, 0, 0.302f), Vec3(5, 0, 0.302f), Vec3(-1, 3, 0.302f)), m));
    // Past the end of the stretch: the body at its end reaches a radius further.
    CHECK(!nl::proven_apart(b, tri(Vec3(4.25f, 0, -1), Vec3(4.25f, 0, 1), Vec3(4.25f, 3, 0)), m));
    CHECK(nl::proven_apart(b, tri(Vec3(4.35f, 0, -1), Vec3(4.35f, 0, 1), Vec3(4.35f, 3, 0)), m));
    // A large triangle the whole body is inside the bounds of, but the body misses its plane.
    CHECK(nl::proven_apart(b, tri(Vec3(-50, 2.5f, -50), Vec3(50, 2.5f, -50), Vec3(0, 2.5f, 50)), m));
    // A falling body (vertical stretch) meets a ledge's lip beside it.
    const nl::SweptCylinder fall{Vec3(0, 5, 0), Vec3(0, 0, 0), 0.3f, 0.3f, 1.8f};
    CHECK(!nl::proven_apart(fall, tri(Vec3(0.2f, 3, -1), Vec3(0.2f, 3, 1), Vec3(1, 3, 0)), m));
    CHECK(nl::proven_apart(fall, tri(Vec3(0.4f, 3, -1), Vec3(0.4f, 3, 1), Vec3(1, 3, 0)), m));
}

TEST_CASE("bodies_clear agrees with the exact test against every triangle, for static and movable meshes") {
    const nl::TriangleMesh mesh = nl::test::to_triangle_mesh(nl::levelgen::generate_default_level(3));
    nl::Transform moved = nl::Transform::Identity();
    moved.translate(Vec3(4.0f, 1.0f, -2.0f));
    moved.rotate(Eigen::AngleAxisf(0.3f, Vec3::UnitY()));
    const float radii[] = {0.3f, 0.45f, 0.6f};
    for (const uint32_t flags : {0u, uint32_t(nl::kMeshMovable)}) {
        INFO((flags ? "movable" : "static"));
        auto tasks = nl::make_tbb_task_system(2);
        nl::Level level(*tasks);
        const nl::Handle h = level.add_mesh(mesh, moved, flags, 0);
        const nl::Aabb bounds = level.info(h).bounds;
        nl::TriangleMesh world = mesh;
        for (Vec3& v : world.vertices) v = moved * v;
        std::mt19937 rng(flags + 9);
        std::uniform_real_distribution<float> x(bounds.min.x(), bounds.max.x()),
            y(bounds.min.y() - 1.0f, bounds.max.y() + 1.0f), z(bounds.min.z(), bounds.max.z()), step(-2.0f, 2.0f);
        std::vector<nl::BodyStretch> stretches;
        for (int i = 0; i < 1500; ++i) {
            nl::SweptCylinder body;
            body.from = Vec3(x(rng), y(rng), z(rng));
            body.to = body.from + Vec3(step(rng), i % 4 == 0 ? -3.0f : 0.5f * step(rng), step(rng));
            body.low = 0.3f;
            body.high = 1.8f;
            body.radius = radii[2];
            stretches.push_back(nl::BodyStretch{body, nl::bounds_of(body, 2.0f * nl::body_margin(body.from))});
        }
        std::vector<uint8_t> cleared(stretches.size());
        level.bodies_clear(stretches.data(), uint32_t(stretches.size()), radii, 3, cleared.data());
        int counts[4] = {}, mismatches = 0;
        for (size_t i = 0; i < stretches.size(); ++i) {
            uint32_t expected = 3;
            for (const nl::Triangle& t : world.triangles) {
                const std::array<Vec3, 3> tri{world.vertices[t[0]], world.vertices[t[1]], world.vertices[t[2]]};
                nl::SweptCylinder body = stretches[i].body;
                while (expected > 0) {
                    body.radius = radii[expected - 1];
                    if (nl::proven_apart(body, tri, nl::body_margin(body.from.cwiseAbs().cwiseMax(body.to.cwiseAbs()))))
                        break;
                    --expected;
                }
            }
            ++counts[cleared[i]];
            mismatches += cleared[i] != expected;
        }
        MESSAGE("cleared 0/1/2/3 radii: ", counts[0], " ", counts[1], " ", counts[2], " ", counts[3]);
        CHECK(mismatches == 0);
        CHECK(counts[0] > 100);
        CHECK(counts[3] > 100);
        CHECK(counts[1] + counts[2] > 10);
    }
}
