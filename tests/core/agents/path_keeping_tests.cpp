// An agent pushed off its path keeps it while it still sees the point it heads for, as Detour's
// corridor re-anchors on the polygon it was pushed onto (dtPathCorridor::movePosition), and plans again
// only once that point is behind a wall; a corner it can see past is skipped (the corridor shortens
// when a shortcut opens). Known answers on two rooms joined by a 2 m door (x = 0, z within 0.4 m once
// eroded by the body's 0.6 m).
#include <doctest/doctest.h>

#include <memory>
#include <vector>

#include "agents/agent_motion.h"
#include "agents/crowd.h"
#include "crowd_scenarios.h"
#include "world/world.h"

namespace {

using nl::Agent;
using nl::AgentState;
using nl::Vec3;

constexpr float kDt = 1.0f / 30.0f;

struct Rooms {
    nl::World world{nl::WorldSettings{}};
    nl::Handle handle;
    nl::HeldPtr<const nl::NavMesh> navmesh;
    Rooms()
        : handle(world.add_navmesh(nl::test::rooms_with_door(10.0f, 2.0f, 0.5f, 0.6f))),
          navmesh(world.navmeshes().navmesh(handle)) {}
};

// A walker at `at` on its way along `points` toward points[next].
Agent walker(const nl::NavMesh& navmesh, const Vec3& at, const std::vector<Vec3>& points, uint32_t next) {
    Agent a;
    a.def.capabilities.radius = 0.6f;
    a.state = AgentState::Walking;
    const nl::NavPoint here = navmesh.find_nearest(at, Vec3(1.0f, 2.0f, 1.0f));
    REQUIRE(here.found);
    a.position = here.point;
    a.polygon = here.polygon;
    for (const Vec3& p : points) {
        nl::PathPoint point;
        point.position = p;
        point.segment = nl::kSegmentWalk;
        a.path.push_back(point);
    }
    a.next = next;
    a.has_destination = true;
    a.destination = points.back();
    return a;
}

// One move of `a`, alone in its crowd.
void move_alone(Agent& a, const nl::NavMesh& navmesh) {
    nl::CrowdSnapshot crowd;
    nl::snapshot_crowd({&a}, crowd);
    nl::move_agent(a, 0, kDt, navmesh, crowd);
}

}  // namespace

TEST_CASE("path keeping: pushed 3 m off its leg, an agent that still sees the point it heads for keeps its path") {
    Rooms rooms;
    // Its leg runs along z = 0 to (-2, 0, 0); it stands 3 m aside (more than its radius and a metre).
    Agent a = walker(*rooms.navmesh, Vec3(-5.0f, 0.0f, 3.0f),
                     {Vec3(-8.0f, 0.0f, 0.0f), Vec3(-2.0f, 0.0f, 0.0f), Vec3(8.0f, 0.0f, 0.0f)}, 1);
    const Vec3 before = a.position;
    move_alone(a, *rooms.navmesh);
    CHECK_FALSE(a.off_path);
    CHECK(a.next == 1);
    CHECK(a.path.size() == 3);
    // It walked toward (-2, 0, 0) from where it stands (not back to its leg first).
    const Vec3 went = a.position - before, toward = Vec3(-2.0f, 0.0f, 0.0f) - before;
    CHECK(went.dot(toward) > 0.0f);
}

TEST_CASE("path keeping: pushed where a wall hides the point it heads for, an agent plans again") {
    Rooms rooms;
    // Heading through the door for (8, 0, 0), from 3 m aside of its leg: the wall is between.
    Agent a = walker(*rooms.navmesh, Vec3(-5.0f, 0.0f, 3.0f),
                     {Vec3(-8.0f, 0.0f, 0.0f), Vec3(-2.0f, 0.0f, 0.0f), Vec3(8.0f, 0.0f, 0.0f)}, 2);
    move_alone(a, *rooms.navmesh);
    CHECK(a.off_path);
}

TEST_CASE("path keeping: a corner an agent can see past is behind it: it heads straight for the next") {
    Rooms rooms;
    // Pushed to where (-2, 0, 0) is in sight, the detour corner (-5, 0, -3) is no longer on its way.
    Agent a = walker(*rooms.navmesh, Vec3(-6.0f, 0.0f, 1.0f),
                     {Vec3(-8.0f, 0.0f, 0.0f), Vec3(-5.0f, 0.0f, -3.0f), Vec3(-2.0f, 0.0f, 0.0f)}, 1);
    move_alone(a, *rooms.navmesh);
    CHECK_FALSE(a.off_path);
    CHECK(a.next == 2);
    // Behind the wall's end, the corner of the door stays a corner: from (-5, 0, 3), (3, 0, 0) through
    // the door is out of sight and the corner at the door's mouth is kept.
    Agent b = walker(*rooms.navmesh, Vec3(-5.0f, 0.0f, 3.0f),
                     {Vec3(-8.0f, 0.0f, 3.0f), Vec3(-1.0f, 0.0f, 0.3f), Vec3(3.0f, 0.0f, -6.0f)}, 1);
    move_alone(b, *rooms.navmesh);
    CHECK(b.next == 1);
}
