// The Godot-style harness: a scripted scene in which NavLink's agents must arrive by the route their
// bodies allow, jumps follow their arcs, a removed link makes its user plan again before it gets
// there, and the scene plays the same on any number of threads.
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

// Where a crowd sent to one point stops (docs/agents.md, "Arriving among others"): each body at the
// point, or within the circle the whole group packs into around it, against a body that stands as
// near to it or nearer (touching: within half a radius, and a few centimetres the bodies were pushed
// by those arriving after them; the body at the point may be pushed off it by as much).
void check_crowded_arrival(const DemoScene& scene) {
    const float group = float(scene.agents.size());
    for (const NavigationAgent* a : scene.agents) {
        INFO(a->name());
        constexpr float kPushed = 0.05f;
        const float radius = a->profile().capabilities.radius, slack = 0.5f * radius + kPushed;
        const float own = horizontal_distance(a->position(), scene.target);
        bool stopped_by_crowd = false;
        for (const NavigationAgent* b : scene.agents) {
            const float reach = radius + b->profile().capabilities.radius + slack;
            stopped_by_crowd =
                stopped_by_crowd || (b != a && horizontal_distance(a->position(), b->position()) < reach &&
                                     horizontal_distance(b->position(), scene.target) <= own + slack);
        }
        CHECK((own < 0.1f + kPushed || stopped_by_crowd));
        CHECK(own <= radius * std::sqrt((group - 1.0f) / 0.9069f) + slack);
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
            a->path_ready.connect([&ready](const std::vector<nl_path_point>&) { ++ready; });
            a->target_reached.connect([&reached] { ++reached; });
        }
        scene.tree->run_until([&] { return all_done(scene); }, 1.0 / 60.0, 120.0);
        CHECK(ready >= 4);  // and again whenever the crowd at the start pushes one off its path
        CHECK(reached == 4);
        for (const NavigationAgent* a : scene.agents) {
            INFO(a->name());
            CHECK(a->arrived());
            check_within_capabilities(*a);
        }
        check_crowded_arrival(scene);
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
    REQUIRE(climber.taken_links().empty());  // still walking to the ladder
    const size_t replans = climber.replan_reasons().size();
    scene.tree->root()->remove_child(scene.ladder);
    scene.tree->run_frame(1.0 / 60.0);
    // At the first step after the ladder went, long before its foot.
    REQUIRE(climber.replan_reasons().size() == replans + 1);
    CHECK(climber.replan_reasons().back() == NL_AGENT_REASON_LINK_GONE);
    scene.tree->run_until([&] { return all_done(scene); }, 1.0 / 60.0, 120.0);
    CHECK(climber.arrived());
    CHECK(climber.taken_links().empty());
    check_crowded_arrival(scene);
}

TEST_CASE("the scene plays the same on 1 and 2 threads, and the tree tears down mid-scene") {
    std::vector<Vec3> positions[2];
    for (int32_t workers : {1, 2}) {
        DemoScene scene = build_demo_scene(1, workers);
        scene.tree->run_until([] { return false; }, 1.0 / 60.0, 6.0);
        for (const NavigationAgent* a : scene.agents) positions[workers - 1].push_back(a->position());
        // Every agent is sent again, and the tree is destroyed with the new paths unplanned.
        for (NavigationAgent* a : scene.agents) a->set_target_position(scene.target);
        scene.tree->run_frame(1.0 / 60.0);
        scene.tree.reset();
    }
    CHECK(positions[0] == positions[1]);
    CHECK(positions[0][2] != positions[0][0]);  // the scene moved: the long jumper is ahead of the walker
}
