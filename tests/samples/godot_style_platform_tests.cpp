// The Godot-style harness with moving platforms: MovingPlatform nodes move their meshes every physics
// frame, and the NavigationAgents riding them arrive, having waited for the platforms at the
// gangways, got on and off by them, and ridden along; the scene plays the same on any thread count.
#include <doctest/doctest.h>

#include <cmath>

#include "moving_platforms.h"
#include "platforms_scene.h"

using namespace nl::godot_style;

namespace {

constexpr double kDelta = 1.0 / 60.0;

bool all_done(const PlatformsScene& scene) {
    for (const NavigationAgent* a : scene.agents)
        if (!a->arrived() && !a->failed()) return false;
    return true;
}

// The gangways the agent took, in order, as "<gangway> (<platform>)"; a link not a gangway is "?".
std::vector<std::string> gangways_taken(const PlatformsScene& scene, const NavigationAgent& agent) {
    std::vector<nl::samples::MovingPlatform> platforms;
    for (const MovingPlatform* p : scene.platforms) platforms.push_back(p->platform());
    std::vector<std::string> out;
    for (const TakenLink& t : agent.taken_links()) {
        const auto gangway = nl::samples::find_gangway(platforms, t.link.id);
        out.push_back(gangway ? gangway->gangway->name : "?");
    }
    return out;
}

double waited_at(const NavigationAgent& agent, size_t link) {
    return link < agent.taken_links().size() ? agent.taken_links()[link].waited : -1.0;
}

}  // namespace

TEST_CASE(
    "passengers ride the platforms: they wait for the shuttle and the lift, get on and off by the gangways, and "
    "arrive") {
    PlatformsScene scene = build_platforms_scene(1);
    REQUIRE(scene.agents.size() == 4);
    REQUIRE(scene.platforms.size() == 3);
    scene.tree->run_until([&] { return all_done(scene); }, kDelta, 90.0);
    const NavigationAgent& ferry = *scene.agents[0];
    const NavigationAgent& disc_rider = *scene.agents[1];
    const NavigationAgent& disc_crosser = *scene.agents[2];
    const NavigationAgent& lift = *scene.agents[3];
    for (const NavigationAgent* a : scene.agents) {
        INFO(a->name());
        CHECK(a->arrived());
    }
    // The shuttle had left when its rider came: it waited at the gangway, rode across, and jumped
    // up the far ledge's step.
    CHECK(gangways_taken(scene, ferry) == std::vector<std::string>{"gangway onto the shuttle", "jump off the shuttle"});
    CHECK(waited_at(ferry, 0) > 5.0);
    REQUIRE(ferry.taken_links().size() == 2);
    CHECK(ferry.taken_links()[1].as == NL_LINK_JUMP);
    CHECK(ferry.position()[1] > scene.level.passengers[0].destination[1]);  // on the higher ledge
    // The lift was on its way down: its rider waited for it, and again on it for the way off at the top.
    CHECK(gangways_taken(scene, lift) == std::vector<std::string>{"gangway onto the lift", "gangway off the lift"});
    CHECK(waited_at(lift, 0) > 1.0);
    CHECK(waited_at(lift, 1) > 3.0);
    CHECK(lift.position()[1] > scene.level.passengers[3].start[1] + 3.5);  // on the upper floor
    // The disc's way on holds however it stands; its way off once a turn, and the crosser waited on it.
    CHECK(gangways_taken(scene, disc_crosser) == std::vector<std::string>{"walk onto the disc", "walk off the disc"});
    CHECK(waited_at(disc_crosser, 1) > 1.0);
    CHECK(gangways_taken(scene, disc_rider) == std::vector<std::string>{"walk onto the disc"});
}

TEST_CASE("an agent that arrived on the turning disc rides it: it stays where it stood on it") {
    PlatformsScene scene = build_platforms_scene(1);
    const NavigationAgent& rider = *scene.agents[1];
    scene.tree->run_until([&] { return rider.arrived(); }, kDelta, 30.0);
    REQUIRE(rider.arrived());
    const nl::samples::Timetable& disc = scene.platforms[1]->layout().timetable;
    const Vec3 before = rider.position();
    const nl::samples::Point axis = disc.at(0.0).position;
    const float radius = std::hypot(before[0] - axis[0], before[2] - axis[2]);
    scene.tree->run_until([] { return false; }, kDelta, 4.0);  // a quarter of a turn
    const Vec3 after = rider.position();
    CHECK(std::hypot(after[0] - before[0], after[2] - before[2]) > 1.0);  // carried round
    CHECK(std::hypot(after[0] - axis[0], after[2] - axis[2]) == doctest::Approx(radius).epsilon(0.01));  // on the disc
    CHECK(rider.arrived());
}

TEST_CASE("the platforms scene plays the same on 1 and 2 threads") {
    std::vector<Vec3> positions[2];
    for (int32_t workers : {1, 2}) {
        PlatformsScene scene = build_platforms_scene(1, workers);
        scene.tree->run_until([] { return false; }, kDelta, 12.0);
        for (const NavigationAgent* a : scene.agents) positions[workers - 1].push_back(a->position());
    }
    CHECK(positions[0] == positions[1]);
}
