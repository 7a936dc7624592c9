// The Godot-style harness: a scripted scene in which every agent must arrive by the route its body
// allows, jumps follow their arcs, a removed link makes its user plan again, and path results from
// NavLink's worker threads reach the nodes through call_deferred.
#include <doctest/doctest.h>

#include <cmath>

#include "demo_scene.h"

using namespace nl::godot_style;

namespace {

bool all_done(const DemoScene& scene) {
    for (const NavigationAgent* a : scene.agents)
        if (!a->arrived() && !a->failed()) return false;
    return true;
}

float horizontal_distance(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[2] - b[2]); }

// What the agent's body asked of each link it took never exceeds what the body can do.
void check_within_capabilities(const NavigationAgent& agent) {
    const nl_agent_capabilities& c = agent.profile().capabilities;
    for (const TakenLink& t : agent.taken_links()) {
        const nl_link_requirements& r = t.link.requirements;
        const float rise = t.reversed ? r.drop : r.rise, drop = t.reversed ? r.rise : r.drop;
        INFO(agent.name() << " took a link of kind " << t.link.kind);
        if (t.as != NL_LINK_DROP) CHECK(r.gap <= c.max_jump_distance + 1e-4f);
        CHECK(rise <= c.max_jump_height + 1e-4f);
        CHECK(drop <= c.max_drop_height + 1e-4f);
        CHECK((r.abilities & ~c.abilities) == 0);
        if (t.as == NL_LINK_JUMP) {
            // The body went up through the jump's apex, above both ends.
            CHECK(t.peak_height >= t.apex_height - 0.02f);
            CHECK(t.peak_height > std::max(t.link.start[1], t.link.end[1]));
        }
    }
}

size_t count_taken(const NavigationAgent& agent, nl_segment_kind as) {
    size_t n = 0;
    for (const TakenLink& t : agent.taken_links()) n += t.as == as;
    return n;
}

}  // namespace

TEST_CASE("every agent arrives by the route its body allows") {
    for (uint32_t seed : {1u, 2u, 3u}) {
        INFO("seed " << seed);
        DemoScene scene = build_demo_scene(seed);
        REQUIRE(scene.agents.size() == 4);
        int ready = 0, reached = 0;
        for (NavigationAgent* a : scene.agents) {
            a->path_ready.connect([&ready](const nl::samples::PlannedPath&) { ++ready; });
            a->target_reached.connect([&reached] { ++reached; });
        }
        scene.tree->run_until([&] { return all_done(scene); }, 1.0 / 60.0, 120.0);
        CHECK(ready == 4);
        CHECK(reached == 4);
        for (const NavigationAgent* a : scene.agents) {
            INFO(a->name());
            CHECK(a->arrived());
            CHECK(horizontal_distance(a->position(), scene.target) < 0.3f);
            check_within_capabilities(*a);
        }
        const NavigationAgent& walker = *scene.agents[0];
        const NavigationAgent& short_jumper = *scene.agents[1];
        const NavigationAgent& long_jumper = *scene.agents[2];
        const NavigationAgent& climber = *scene.agents[3];
        // The walker walks, the round way by the stairs.
        CHECK(walker.taken_links().empty());
        // The short jumper jumps short gaps and never drops.
        CHECK(count_taken(short_jumper, NL_LINK_JUMP) >= 1);
        CHECK(count_taken(short_jumper, NL_LINK_DROP) == 0);
        // The long jumper makes a jump the short one could not, and drops.
        bool long_jump = false;
        for (const TakenLink& t : long_jumper.taken_links())
            long_jump = long_jump || (t.as == NL_LINK_JUMP && t.link.requirements.gap > 2.0f);
        CHECK(long_jump);
        CHECK(count_taken(long_jumper, NL_LINK_DROP) >= 1);
        // The climber takes the ladder, nothing else.
        REQUIRE(climber.taken_links().size() == 1);
        CHECK(climber.taken_links()[0].link.id.index1 == scene.ladder->id().index1);
        // Abler bodies get there sooner.
        CHECK(long_jumper.arrival_time() < short_jumper.arrival_time());
        CHECK(short_jumper.arrival_time() < walker.arrival_time());
        CHECK(climber.arrival_time() < walker.arrival_time());
    }
}

TEST_CASE("a ladder taken away before the climber reaches it: the climber plans again and walks") {
    DemoScene scene = build_demo_scene(1);
    NavigationAgent& climber = *scene.agents[3];
    scene.tree->run_until([] { return false; }, 1.0 / 60.0, 3.0);
    REQUIRE(climber.paths_requested() == 1);
    REQUIRE(climber.taken_links().empty());  // still walking to the ladder
    scene.tree->root()->remove_child(scene.ladder);
    scene.tree->run_until([&] { return all_done(scene); }, 1.0 / 60.0, 120.0);
    CHECK(climber.arrived());
    CHECK(climber.paths_requested() == 2);  // found the ladder gone at its foot
    CHECK(climber.taken_links().empty());
    CHECK(horizontal_distance(climber.position(), scene.target) < 0.3f);
}

TEST_CASE("with path worker threads, results cross to the tree's thread and the tree tears down mid-scene") {
    DemoScene scene = build_demo_scene(1, 2);
    auto all_following = [&] {
        for (const NavigationAgent* a : scene.agents)
            if (a->distance_travelled() == 0.0) return false;
        return true;
    };
    // Frames are paced in real time: a few tens of them are enough for the workers.
    scene.tree->run_until(all_following, 1.0 / 60.0, 5.0);
    CHECK(all_following());
    // Every agent asks again, and the tree is destroyed with the requests in flight.
    for (NavigationAgent* a : scene.agents) a->set_target_position(scene.target);
    scene.tree.reset();
}
