// A flight checked against the level as it will be when the body passes (agents/flight_check.h):
// meshes that move are placed where their motion carries them by the time the body gets there, so
// a pole that will cross the flight blocks it although it stands clear of it now, and a pole in the
// way now that will have gone by then does not. Each case has an exact answer with room to spare.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "agents/flight_check.h"
#include "agents/mesh_motion.h"
#include "level/level.h"

namespace {

using nl::Transform;
using nl::Vec3;

// An axis-aligned box as a closed triangle mesh.
nl::TriangleMesh box(const Vec3& lo, const Vec3& hi) {
    nl::TriangleMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        m.triangles.push_back({uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
        m.triangles.push_back({uint32_t(f[0]), uint32_t(f[2]), uint32_t(f[3])});
    }
    return m;
}

Transform at(const Vec3& p, float turned = 0.0f) {
    Transform t = Transform::Identity();
    t.translate(p);
    t.rotate(Eigen::AngleAxisf(turned, Vec3::UnitY()));
    return t;
}

// A 4 m jump along +x from the origin, 1 m above its ends at the top, for a body 0.3 m wide and
// 1.8 m tall: the body passes x = 2 at half its flight time.
struct Jump {
    std::unique_ptr<nl::TaskSystem> tasks = nl::make_tbb_task_system(1);
    nl::Level level{*tasks};
    nl::LinkMotion flight;
    static constexpr float kRadius = 0.3f, kHeight = 1.8f;

    Jump() : flight(link(), false, nl::BodyMotion{}) {}
    static nl::Link link() {
        nl::Link l;
        l.kind = nl::LinkKind::Jump;
        l.start = Vec3(0, 0, 0);
        l.end = Vec3(4, 0, 0);
        l.arc_height = 1.0f;
        return l;
    }
    // A pole 0.1 m square from below the arc to above it, movable, at `where`.
    nl::Handle add_pole(const Transform& where) {
        return level.add_mesh(box(Vec3(-0.05f, -1, -0.05f), Vec3(0.05f, 3, 0.05f)), where, nl::kMeshMovable, 0);
    }
    // The motion of `mesh` standing at `now`: its origin at `velocity`, turning at `turn` rad/s about +y.
    nl::MeshMotion motion(nl::Handle mesh, const Vec3& velocity, float turn = 0.0f) const {
        const nl::MeshInfo info = level.info(mesh);
        nl::MeshMotion m;
        m.mesh = mesh;
        m.now = info.transform;
        m.velocity = velocity;
        m.turn = Vec3(0, turn, 0);
        for (const nl::MovableMesh& movable : level.movable_meshes())
            if (movable.mesh == mesh) m.reach = movable.reach;
        return m;
    }
    bool clear(const std::vector<nl::MeshMotion>& moving, bool on_proven_arc = false) const {
        return nl::flight_is_clear(flight, kRadius, kHeight, level, moving, on_proven_arc);
    }
};

}  // namespace

TEST_CASE("a pole that will cross a flight when the body passes blocks it, though it stands clear of it now") {
    Jump j;
    const float half = 0.5f * j.flight.duration(), speed = 4.0f;
    // At x = 2, coming along +z at 4 m/s: at the middle of the flight it stands in the arc.
    const nl::Handle pole = j.add_pole(at(Vec3(2, 0, -speed * half)));
    REQUIRE(speed * half > 1.0f);                                     // now it is more than 1 m off the arc
    CHECK(j.clear({}));                                               // as it stands now: clear
    CHECK_FALSE(j.clear({j.motion(pole, Vec3(0, 0, speed))}));        // as it will be: blocked
    CHECK_FALSE(j.clear({j.motion(pole, Vec3(0, 0, speed))}, true));  // the link's proof does not cover it
    // Moving the other way, it is further off the arc when the body passes.
    CHECK(j.clear({j.motion(pole, Vec3(0, 0, -speed))}));
}

TEST_CASE("a pole in the way of a flight now that will be gone when the body passes does not block it") {
    Jump j;
    // At x = 3.5, on the arc now; the body reaches it after 7/8 of its flight, when the pole, at
    // 4 m/s along +z, stands about 3 m off it.
    const nl::Handle pole = j.add_pole(at(Vec3(3.5f, 0, 0)));
    CHECK_FALSE(j.clear({}));
    CHECK(j.clear({j.motion(pole, Vec3(0, 0, 4.0f))}));
    // Standing still there, it blocks the flight whatever the link was proven for.
    CHECK_FALSE(j.clear({j.motion(pole, Vec3::Zero())}, false));
}

TEST_CASE("an arm turning into a flight blocks it when it will stand across the arc as the body passes") {
    Jump j;
    // A wall 3 m long from a pivot at (2, 0, 2), along +x now (2 m off the arc); turning at a rate
    // that points it along -z, across the arc at x = 2, at half the flight time.
    const nl::Handle arm =
        j.level.add_mesh(box(Vec3(0, -1, -0.05f), Vec3(3, 3, 0.05f)), at(Vec3(2, 0, 2)), nl::kMeshMovable, 0);
    const float rate = 0.5f * float(M_PI) / (0.5f * j.flight.duration());
    CHECK(j.clear({}));
    CHECK_FALSE(j.clear({j.motion(arm, Vec3::Zero(), rate)}));
    // Turning the other way, it swings away from the arc.
    CHECK(j.clear({j.motion(arm, Vec3::Zero(), -rate)}));
}

TEST_CASE("mesh motions are read from two steps and carried on: a turning, travelling mesh is placed exactly") {
    auto tasks = nl::make_tbb_task_system(1);
    nl::Level level(*tasks);
    const nl::Handle disc =
        level.add_mesh(box(Vec3(-1, -0.1f, -1), Vec3(1, 0, 1)), at(Vec3(5, 0, 0)), nl::kMeshMovable, 0);
    nl::MeshMotions motions;
    motions.remember(level.movable_meshes(), 0.1f);
    // Over 0.1 s: 0.2 m along z and 0.05 rad about +y.
    level.set_transform(disc, at(Vec3(5, 0, 0.2f), 0.05f));
    const std::vector<nl::MeshMotion> now = motions.motions(level.movable_meshes());
    REQUIRE(now.size() == 1);
    CHECK(now[0].velocity.isApprox(Vec3(0, 0, 2.0f), 1e-4f));
    CHECK(now[0].turn.isApprox(Vec3(0, 0.5f, 0), 1e-3f));
    CHECK(now[0].fastest_point() == doctest::Approx(2.0f + 0.5f * std::sqrt(2.0f + 0.01f)).epsilon(1e-3));
    const Transform later = now[0].after(1.0f);
    const Transform expected = at(Vec3(5, 0, 2.2f), 0.55f);
    CHECK((later.matrix() - expected.matrix()).cwiseAbs().maxCoeff() < 1e-4f);
    // A mesh not seen at the last step stands still.
    nl::MeshMotions fresh;
    CHECK_FALSE(fresh.motions(level.movable_meshes())[0].moves());
}
