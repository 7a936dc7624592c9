// Embree's answers against the brute-force reference, on the shared levels and a procedural one,
// static and movable, under a transform, and with 1 and 2 threads.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <sstream>

#include "brute_force.h"
#include "io/obj_reader.h"
#include "level/level.h"
#include "util/task_system.h"
#include "level_generator.h"
#include "shared_levels.h"

using nl::Vec3;

namespace {

// A tie is a ray whose answer depends on rounding: it grazes a triangle edge within this distance.
constexpr double kEdgeTolerance = 1e-4;

struct Tally {
    int queries = 0;
    int agree = 0;
    int edge_ties = 0;
    int mismatches = 0;
    std::string first_mismatch;

    void mismatch(const std::string& what) {
        if (mismatches++ == 0) first_mismatch = what;
    }
    void check(const std::string& label) const {
        INFO(label, ": ", queries, " queries, ", agree, " agree, ", edge_ties,
             " edge ties; first mismatch: ", first_mismatch);
        CHECK(mismatches == 0);
        CHECK(edge_ties * 1000 <= queries);  // ties are rare, or the comparison is too lax to mean anything
        CHECK(agree + edge_ties == queries);
    }
};

nl::TriangleMesh transformed(const nl::TriangleMesh& mesh, const nl::Transform& t) {
    nl::TriangleMesh out = mesh;
    for (Vec3& v : out.vertices) v = t * v;
    return out;
}

std::vector<nl::Ray> random_rays(const nl::Aabb& box, uint32_t seed, int random_count, int down_count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    const Vec3 lo = box.min - 0.1f * (box.max - box.min);
    const Vec3 size = 1.2f * (box.max - box.min);
    auto point = [&] {
        return Vec3(lo.x() + unit(rng) * size.x(), lo.y() + unit(rng) * size.y(), lo.z() + unit(rng) * size.z());
    };
    std::vector<nl::Ray> rays;
    for (int i = 0; i < random_count; ++i) {
        Vec3 d(gauss(rng), gauss(rng), gauss(rng));
        const float max = (i % 2) ? std::numeric_limits<float>::infinity() : 0.5f + unit(rng) * size.norm();
        rays.push_back(nl::Ray{point(), d.normalized(), max});
    }
    for (int i = 0; i < down_count; ++i) {  // the probes link generation will cast most
        Vec3 o = point();
        o.y() = box.max.y() + 1.0f;
        rays.push_back(nl::Ray{o, Vec3(0, -1, 0), std::numeric_limits<float>::infinity()});
    }
    return rays;
}

Tally compare_rays(const nl::TriangleMesh& world, const std::vector<nl::Ray>& rays,
                   const std::vector<nl::RayHit>& hits) {
    Tally tally;
    for (size_t i = 0; i < rays.size(); ++i) {
        const nl::Ray& ray = rays[i];
        const nl::RayHit& got = hits[i];
        const auto ref = nl::test::closest_hit(world, ray.origin, ray.direction, ray.max_distance);
        ++tally.queries;
        std::ostringstream where;
        where << "ray " << i << " origin " << ray.origin.transpose() << " dir " << ray.direction.transpose();
        const double tol = 1e-4 * (1.0 + (ref ? ref->distance : 0.0));
        // Embree's own triangle, widened a little: does it really lie where Embree says?
        std::optional<nl::test::ReferenceHit> own;
        if (got.hit)
            own = nl::test::intersect_triangle(world, got.triangle, ray.origin, ray.direction, 1e30, kEdgeTolerance);
        const bool own_consistent = own && std::fabs(own->distance - got.distance) <= tol;

        if (got.hit && !own_consistent) {
            tally.mismatch(where.str() + ": Embree's triangle is not where it says");
        } else if (got.hit && ref) {
            if (std::fabs(got.distance - ref->distance) <= tol) {
                ++tally.agree;
            } else if ((got.distance > ref->distance && ref->edge_margin < kEdgeTolerance) ||
                       (got.distance < ref->distance && own->edge_margin < kEdgeTolerance)) {
                ++tally.edge_ties;
            } else {
                tally.mismatch(where.str() + ": distances " + std::to_string(got.distance) + " vs " +
                               std::to_string(ref->distance));
            }
        } else if (got.hit && !ref) {
            if (own->edge_margin < kEdgeTolerance)
                ++tally.edge_ties;
            else
                tally.mismatch(where.str() + ": Embree hit, reference missed");
        } else if (!got.hit && ref) {
            if (ref->edge_margin < kEdgeTolerance)
                ++tally.edge_ties;
            else
                tally.mismatch(where.str() + ": Embree missed, reference hit at " + std::to_string(ref->distance));
        } else {
            ++tally.agree;
        }
        if (got.hit && own_consistent) {
            // Point and normal follow from the triangle.
            const nl::Triangle& t = world.triangles[got.triangle];
            const Vec3 n = (world.vertices[t[1]] - world.vertices[t[0]])
                               .cross(world.vertices[t[2]] - world.vertices[t[0]])
                               .normalized();
            if ((got.normal - n).norm() > 1e-3f) tally.mismatch(where.str() + ": normal differs");
            if ((got.point - (ray.origin + ray.direction * got.distance)).norm() > 1e-3f)
                tally.mismatch(where.str() + ": point differs");
        }
    }
    return tally;
}

std::vector<nl::Segment> random_segments(const nl::Aabb& box, uint32_t seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const Vec3 size = box.max - box.min;
    auto point = [&] {
        return Vec3(box.min.x() + unit(rng) * size.x(), box.min.y() + unit(rng) * size.y(),
                    box.min.z() + unit(rng) * size.z());
    };
    std::vector<nl::Segment> segments;
    for (int i = 0; i < count; ++i) {
        const Vec3 from = point();
        // Mix long and short segments: short ones are what clearance checks cast.
        const Vec3 to = (i % 2) ? point() : Vec3(from + (point() - from) * 0.1f);
        segments.push_back(nl::Segment{from, to});
    }
    return segments;
}

Tally compare_segments(const nl::TriangleMesh& world, const std::vector<nl::Segment>& segments,
                       const std::vector<uint8_t>& blocked) {
    Tally tally;
    for (size_t i = 0; i < segments.size(); ++i) {
        const auto ref = nl::test::segment_occlusion(world, segments[i].from, segments[i].to);
        ++tally.queries;
        if ((blocked[i] != 0) == ref.blocked)
            ++tally.agree;
        else if (ref.least_edge_margin < kEdgeTolerance || ref.least_end_distance < kEdgeTolerance)
            ++tally.edge_ties;
        else
            tally.mismatch("segment " + std::to_string(i) +
                           (blocked[i] ? ": Embree blocked, reference clear" : ": Embree clear, reference blocked"));
    }
    return tally;
}

void check_level_against_reference(const std::string& label, const nl::TriangleMesh& mesh,
                                   const nl::Transform& transform, uint32_t flags, int ray_count) {
    auto tasks = nl::make_tbb_task_system(2);
    nl::Level level(*tasks);
    const nl::Handle h = level.add_mesh(mesh, transform, flags, 0);
    const nl::TriangleMesh world = transformed(mesh, transform);
    const nl::Aabb box = level.info(h).bounds;

    const auto rays = random_rays(box, 17, ray_count, ray_count / 3);
    std::vector<nl::RayHit> hits(rays.size());
    level.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.data());
    int hit_count = 0;
    for (const auto& hit : hits) {
        hit_count += hit.hit;
        if (hit.hit && hit.mesh != h) FAIL_CHECK("a hit reports another mesh");
    }
    CHECK(hit_count > static_cast<int>(rays.size()) / 10);  // the rays really meet the level
    compare_rays(world, rays, hits).check(label + " rays");

    const auto segments = random_segments(box, 23, ray_count);
    std::vector<uint8_t> blocked(segments.size());
    level.segments_blocked(segments.data(), static_cast<uint32_t>(segments.size()), blocked.data());
    int blocked_count = 0;
    for (uint8_t b : blocked) blocked_count += b;
    CHECK(blocked_count > 0);
    CHECK(blocked_count < static_cast<int>(segments.size()));
    compare_segments(world, segments, blocked).check(label + " segments");
}

nl::Transform sample_transform() {
    nl::Transform t = nl::Transform::Identity();
    t.translate(Vec3(12.5f, -3.0f, 40.0f));
    t.rotate(Eigen::AngleAxisf(0.6f, Vec3(0.2f, 1.0f, 0.1f).normalized()));
    t.scale(Vec3(1.5f, 0.8f, 1.2f));
    return t;
}

}  // namespace

TEST_CASE("ray and segment queries match the brute-force reference on every shared level") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty()) {
        if (nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir().string());
        MESSAGE("shared levels not found in ", nl::test::levels_dir().string(), ": skipped");
        return;
    }
    CHECK(levels.size() >= 7);
    for (const auto& path : levels) {
        const nl::TriangleMesh mesh = nl::read_obj_file(path.string());
        check_level_against_reference(path.stem().string(), mesh, nl::Transform::Identity(), 0, 3000);
    }
}

TEST_CASE("queries match the reference under a transform, for static and movable meshes") {
    const auto level = nl::levelgen::generate_default_level(7);
    nl::TriangleMesh mesh;
    for (size_t i = 0; i < level.positions.size(); i += 3)
        mesh.vertices.emplace_back(level.positions[i], level.positions[i + 1], level.positions[i + 2]);
    for (size_t i = 0; i < level.indices.size(); i += 3)
        mesh.triangles.push_back({level.indices[i], level.indices[i + 1], level.indices[i + 2]});
    check_level_against_reference("procedural static", mesh, sample_transform(), 0, 2000);
    check_level_against_reference("procedural movable", mesh, sample_transform(), nl::kMeshMovable, 2000);

    const auto levels = nl::test::shared_levels();
    for (const auto& path : levels) {
        if (path.stem() != "dungeon") continue;
        const nl::TriangleMesh dungeon = nl::read_obj_file(path.string());
        check_level_against_reference("dungeon movable", dungeon, sample_transform(), nl::kMeshMovable, 1500);
    }
}

TEST_CASE("results are identical with 1 and 2 threads") {
    const auto gen = nl::levelgen::generate_field_level(3, 20, 20);
    nl::TriangleMesh mesh;
    for (size_t i = 0; i < gen.positions.size(); i += 3)
        mesh.vertices.emplace_back(gen.positions[i], gen.positions[i + 1], gen.positions[i + 2]);
    for (size_t i = 0; i < gen.indices.size(); i += 3)
        mesh.triangles.push_back({gen.indices[i], gen.indices[i + 1], gen.indices[i + 2]});

    std::vector<std::vector<nl::RayHit>> hits;
    std::vector<std::vector<uint8_t>> blocked;
    for (int threads : {1, 2}) {
        auto tasks = nl::make_tbb_task_system(threads);
        nl::Level level(*tasks);
        const nl::Handle h = level.add_mesh(mesh, nl::Transform::Identity(), 0, 0);
        const auto rays = random_rays(level.info(h).bounds, 5, 50000, 10000);
        const auto segments = random_segments(level.info(h).bounds, 6, 50000);
        hits.emplace_back(rays.size());
        blocked.emplace_back(segments.size());
        level.cast_rays(rays.data(), static_cast<uint32_t>(rays.size()), hits.back().data());
        level.segments_blocked(segments.data(), static_cast<uint32_t>(segments.size()), blocked.back().data());
    }
    int differ = 0;
    for (size_t i = 0; i < hits[0].size(); ++i) {
        const auto &a = hits[0][i], &b = hits[1][i];
        differ += a.hit != b.hit || a.distance != b.distance || a.triangle != b.triangle || a.normal != b.normal;
    }
    CHECK(differ == 0);
    CHECK(blocked[0] == blocked[1]);
}

TEST_CASE("the level refuses calls from inside a parallel task, where waiting for its lock could hang") {
    auto tasks = nl::make_tbb_task_system(2);
    nl::Level level(*tasks);
    nl::TriangleMesh floor;
    floor.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)};
    floor.triangles = {{0, 1, 2}};
    const nl::Handle h = level.add_mesh(floor, nl::Transform::Identity(), 0, 0);
    CHECK(!nl::TaskSystem::inside_task());
    std::atomic<int> refused{0}, bodies{0};
    tasks->parallel_for(64, 1, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            ++bodies;
            CHECK(nl::TaskSystem::inside_task());
            try {
                level.contains(h);
            } catch (const nl::Error& e) {
                if (e.code() == nl::ErrorCode::Internal) ++refused;
            }
        }
    });
    CHECK(bodies == 64);
    CHECK(refused == 64);
    CHECK(!nl::TaskSystem::inside_task());
    CHECK(level.contains(h));  // and from the calling thread it answers
}
