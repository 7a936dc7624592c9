// Agents driven through the core: they follow their paths on the surface, take links along the very
// trajectories the generator checked (never through the level), check a link before take-off and
// never mid-air, avoid each other, and a step's result is the same bit for bit on 1 or 2 threads.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core_world.h"
#include "generated_mesh.h"
#include "level_generator.h"
#include "world/world.h"

namespace {

using nl::AgentEventKind;
using nl::AgentState;
using nl::Handle;
using nl::Vec3;

// A polygon from x-z corners (counter-clockwise seen from above) at height y.
void add_polygon(nl::NavMeshInput& in, const std::vector<std::pair<float, float>>& corners, float y = 0.0f) {
    for (const auto& [x, z] : corners) {
        in.indices.push_back(uint32_t(in.vertices.size()));
        in.vertices.emplace_back(x, y, z);
    }
    in.polygon_sizes.push_back(uint8_t(corners.size()));
}

// Two 4 x 10 m platforms 1 m thick (tops at y = 0), 2 m apart along x, and a 2 m wide bridge between
// them at the far end (z 8-10): a walker goes round by the bridge, a jumper jumps the gap.
struct GapLevel {
    std::unique_ptr<nl::World> world;
    Handle navmesh;
    nl::LinkGenerationReport report;

    explicit GapLevel(int workers = 1, bool generate = true) {
        nl::WorldSettings settings;
        settings.worker_count = workers;
        world = std::make_unique<nl::World>(std::move(settings));
        nl::levelgen::GeneratedLevel level;
        level.add_box({{0, -1, 0}, {4, 0, 10}});
        level.add_box({{6, -1, 0}, {10, 0, 10}});
        level.add_box({{4, -1, 8}, {6, 0, 10}});
        world->level().add_mesh(nl::test::to_triangle_mesh(level), nl::Transform::Identity(), 0, 0);
        const float r = 0.3f;
        nl::NavMeshInput in;
        add_polygon(in, {{r, r}, {r, 8}, {4 - r, 8}, {4 - r, r}});
        add_polygon(in, {{r, 8}, {r, 10 - r}, {4, 10 - r}, {4, 8}, {4 - r, 8}});
        add_polygon(in, {{4, 8}, {4, 10 - r}, {6, 10 - r}, {6, 8}});
        add_polygon(in, {{6, 8}, {6, 10 - r}, {10 - r, 10 - r}, {10 - r, 8}, {6 + r, 8}});
        add_polygon(in, {{6 + r, r}, {6 + r, 8}, {10 - r, 8}, {10 - r, r}});
        in.agent_type.radius = r;
        in.agent_type.height = 2.0f;
        navmesh = world->add_navmesh(in);
        if (generate)
            report = world->generate_links(navmesh, nl::LinkSettings{}, {}, [](float, const char*) { return true; });
    }

    Handle add_agent(const Vec3& at, float jump = 0.0f, uint64_t user = 0) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = at;
        def.capabilities.radius = 0.3f;
        def.capabilities.max_jump_distance = jump;
        def.capabilities.max_jump_height = jump > 0.0f ? 1.0f : 0.0f;
        def.user_data = user;
        return world->agents().add(world->navmeshes(), def);
    }

    // Steps until every agent has arrived or failed, or `seconds` passed; records the events.
    std::vector<nl::AgentEvent> run(float seconds, float dt = 1.0f / 30.0f,
                                    const std::function<void(int)>& each_step = nullptr) {
        std::vector<nl::AgentEvent> all;
        for (int i = 0; i * dt < seconds; ++i) {
            world->step(dt);
            const auto events = world->agents().events();
            all.insert(all.end(), events.begin(), events.end());
            if (each_step) each_step(i);
            bool done = true;
            for (const nl::AgentInfo& a : world->agents().infos())
                done = done &&
                       (a.state == AgentState::Arrived || a.state == AgentState::Failed || a.state == AgentState::Idle);
            if (done) break;
        }
        return all;
    }
};

size_t count_events(const std::vector<nl::AgentEvent>& events, Handle agent, AgentEventKind kind) {
    size_t n = 0;
    for (const nl::AgentEvent& e : events) n += e.agent == agent && e.kind == kind;
    return n;
}

// A manual jump across the gap at z = 2, from x = 3.6 to 6.4 (edge to edge of the two platforms),
// `both_ways` or one way.
Handle add_jump(nl::World& world, Handle navmesh, bool both_ways) {
    nl::Link jump;
    jump.kind = nl::LinkKind::Jump;
    jump.start = Vec3(3.6f, 0.0f, 2.0f);
    jump.end = Vec3(6.4f, 0.0f, 2.0f);
    jump.bidirectional = both_ways;
    nl::set_requirements_from_ends(jump);
    return world.add_link(navmesh, jump);
}
Handle add_jump(GapLevel& g, bool both_ways) { return add_jump(*g.world, g.navmesh, both_ways); }

float distance_xz(const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); }

}  // namespace

TEST_CASE("a walker goes round by the bridge while a jumper jumps the gap; both arrive on the surface") {
    GapLevel g;
    REQUIRE(g.report.jump_links > 0);
    const Vec3 start(1.0f, 0.0f, 2.0f), goal(9.0f, 0.0f, 2.0f);
    const Handle walker = g.add_agent(start, 0.0f, 1);
    const Handle jumper = g.add_agent(start + Vec3(0.0f, 0.0f, 1.0f), 3.0f, 2);
    g.world->agents().set_destination(g.world->navmeshes(), walker, goal);
    g.world->agents().set_destination(g.world->navmeshes(), jumper, goal + Vec3(0.0f, 0.0f, 1.0f));

    float walker_max_z = 0.0f;
    bool on_surface = true;
    const auto events = g.run(20.0f, 1.0f / 30.0f, [&](int) {
        const nl::AgentInfo w = g.world->agents().info(walker);
        walker_max_z = std::max(walker_max_z, w.position.z());
        for (const nl::AgentInfo& a : g.world->agents().infos())
            if (a.state == AgentState::Walking) on_surface = on_surface && std::fabs(a.position.y()) < 1e-3f;
    });
    const nl::AgentInfo w = g.world->agents().info(walker), j = g.world->agents().info(jumper);
    CHECK(w.state == AgentState::Arrived);
    CHECK(j.state == AgentState::Arrived);
    CHECK(distance_xz(w.position, goal) < 0.1f);
    CHECK(walker_max_z > 8.0f);  // by the bridge
    CHECK(count_events(events, walker, AgentEventKind::LinkStarted) == 0);
    CHECK(count_events(events, jumper, AgentEventKind::LinkStarted) == 1);
    CHECK(count_events(events, jumper, AgentEventKind::LinkFinished) == 1);
    CHECK(count_events(events, walker, AgentEventKind::PathReady) == 1);
    CHECK(count_events(events, walker, AgentEventKind::Arrived) == 1);
    CHECK(on_surface);
}

TEST_CASE("a body on a generated link never meets the level: segments through it clear at every step") {
    GapLevel g;
    nl::Level& level = g.world->level();
    std::vector<Handle> jumpers;
    for (int k = 0; k < 4; ++k) {
        jumpers.push_back(g.add_agent(Vec3(1.0f, 0.0f, 1.0f + 1.5f * k), 3.0f));
        g.world->agents().set_destination(g.world->navmeshes(), jumpers.back(), Vec3(9.0f, 0.0f, 1.0f + 1.5f * k));
    }
    std::vector<Vec3> before(jumpers.size());
    for (size_t k = 0; k < jumpers.size(); ++k) before[k] = g.world->agents().info(jumpers[k]).position;
    int flying_steps = 0, blocked = 0;
    g.run(20.0f, 1.0f / 60.0f, [&](int) {
        for (size_t k = 0; k < jumpers.size(); ++k) {
            const nl::AgentInfo a = g.world->agents().info(jumpers[k]);
            if (a.state == AgentState::Jumping || a.state == AgentState::Falling) {
                ++flying_steps;
                // The body's axis from its last position to this one, at three heights above its feet.
                std::vector<nl::Segment> axis;
                for (float h : {0.35f, 1.0f, 1.9f})
                    axis.push_back(nl::Segment{before[k] + Vec3(0, h, 0), a.position + Vec3(0, h, 0)});
                std::vector<uint8_t> hit(axis.size());
                level.segments_blocked(axis.data(), uint32_t(axis.size()), hit.data());
                for (uint8_t b : hit) blocked += b;
            }
            before[k] = a.position;
        }
    });
    CHECK(flying_steps > 20);
    CHECK(blocked == 0);
    for (Handle j : jumpers) CHECK(g.world->agents().info(j).state == AgentState::Arrived);
}

TEST_CASE("a link removed while an agent walks toward it: it plans again before take-off, never in the air") {
    GapLevel g(1, false);
    const Handle link = add_jump(g, true);
    const Handle agent = g.add_agent(Vec3(1.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), agent, Vec3(9.0f, 0.0f, 2.0f));
    g.world->step(1.0f / 30.0f);
    REQUIRE(g.world->agents().corners(agent).size() >= 2);
    g.world->step(1.0f / 30.0f);
    g.world->navmeshes().remove_link(link);
    bool flew = false;
    const auto events = g.run(20.0f, 1.0f / 30.0f,
                              [&](int) { flew = flew || g.world->agents().info(agent).state == AgentState::Jumping; });
    CHECK_FALSE(flew);
    CHECK(count_events(events, agent, AgentEventKind::Replanned) >= 1);
    CHECK(count_events(events, agent, AgentEventKind::LinkStarted) == 0);
    CHECK(g.world->agents().info(agent).state == AgentState::Arrived);  // round by the bridge

    // Mid-air: the link goes while the agent flies it; it lands on the arc's end all the same.
    const Handle again = add_jump(g, true);
    const Handle second = g.add_agent(Vec3(1.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), second, Vec3(9.0f, 0.0f, 2.0f));  // where the first stands
    bool removed = false;
    float landed_x = 0.0f;
    const auto mid_air = g.run(20.0f, 1.0f / 60.0f, [&](int) {
        const nl::AgentInfo a = g.world->agents().info(second);
        if (!removed && a.state == AgentState::Jumping && a.link_progress > 0.3f) {
            g.world->navmeshes().remove_link(again);
            removed = true;
        }
        if (removed && landed_x == 0.0f && a.state != AgentState::Jumping) landed_x = a.position.x();
    });
    INFO("state ", int(g.world->agents().info(second).state), " at ", g.world->agents().info(second).position.x(), ", ",
         g.world->agents().info(second).position.z(), " corners ", g.world->agents().info(second).corners_ahead);
    CHECK(removed);
    CHECK(landed_x == doctest::Approx(6.4f).epsilon(1e-3));
    CHECK(count_events(mid_air, second, AgentEventKind::LinkFinished) == 1);
    CHECK(g.world->agents().info(second).state == AgentState::Arrived);  // beside the first, as near as it lets
    CHECK(distance_xz(g.world->agents().info(second).position, Vec3(9.0f, 0.0f, 2.0f)) < 2 * 0.3f + 0.1f);  // touching
}

TEST_CASE("results are the same bit for bit on 1 and 2 threads after 1,000 steps of a crowd") {
    auto simulate = [](int workers) {
        GapLevel g(workers);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> z(0.5f, 9.5f);
        std::vector<Handle> agents;
        for (int k = 0; k < 60; ++k) {
            const bool left = k % 2 == 0;
            agents.push_back(g.add_agent(Vec3(left ? 1.0f + (k % 5) * 0.5f : 7.0f + (k % 5) * 0.5f, 0.0f, z(rng)),
                                         k % 3 == 0 ? 3.0f : 0.0f));
            g.world->agents().set_destination(g.world->navmeshes(), agents.back(),
                                              Vec3(left ? 8.5f : 1.5f, 0.0f, z(rng)));
        }
        for (int step = 0; step < 1000; ++step) {
            g.world->step(1.0f / 60.0f);
            if (step % 250 == 0) {
                for (size_t k = 0; k < agents.size(); k += 7)
                    g.world->agents().set_destination(g.world->navmeshes(), agents[k],
                                                      Vec3(k % 2 ? 2.0f : 8.0f, 0.0f, z(rng)));
            }
        }
        std::vector<float> state;
        for (const nl::AgentInfo& a : g.world->agents().infos()) {
            state.insert(state.end(), {a.position.x(), a.position.y(), a.position.z(), a.velocity.x(), a.velocity.z(),
                                       float(a.state)});
        }
        return state;
    };
    const std::vector<float> one = simulate(1), two = simulate(2);
    REQUIRE(one.size() == two.size());
    CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)) == 0);
}

TEST_CASE("two agents walking head-on through a corridor pass each other without overlapping") {
    GapLevel g(1, false);
    const Handle a = g.add_agent(Vec3(1.0f, 0.0f, 9.0f)), b = g.add_agent(Vec3(9.0f, 0.0f, 9.0f));
    g.world->agents().set_destination(g.world->navmeshes(), a, Vec3(9.0f, 0.0f, 9.0f));
    g.world->agents().set_destination(g.world->navmeshes(), b, Vec3(1.0f, 0.0f, 9.0f));
    float closest = 1e9f;
    g.run(20.0f, 1.0f / 30.0f, [&](int) {
        closest =
            std::min(closest, distance_xz(g.world->agents().info(a).position, g.world->agents().info(b).position));
    });
    CHECK(g.world->agents().info(a).state == AgentState::Arrived);
    CHECK(g.world->agents().info(b).state == AgentState::Arrived);
    CHECK(closest > 0.5f);  // two 0.3 m bodies: 0.6 m apart when touching
}

TEST_CASE("at the step it takes off, an agent stands on its trajectory's start, and on the curve after") {
    GapLevel g(1, false);
    add_jump(g, false);
    const Handle agent = g.add_agent(Vec3(1.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), agent, Vec3(9.0f, 0.0f, 2.0f));
    int in_air = 0;
    for (int i = 0; i < 300 && g.world->agents().info(agent).state != AgentState::Arrived; ++i) {
        g.world->step(1.0f / 30.0f);
        const nl::Agents::Flight flight = g.world->agents().flight(agent);
        if (!flight.motion) continue;
        const Vec3 on_curve = flight.motion->at(flight.elapsed);
        CHECK((g.world->agents().info(agent).position - on_curve).norm() < 1e-5f);
        if (in_air++ == 0) CHECK((g.world->agents().info(agent).position - flight.motion->from()).norm() < 1e-5f);
    }
    CHECK(in_air > 0);
    CHECK(g.world->agents().info(agent).state == AgentState::Arrived);
}

TEST_CASE("two agents at one link's take-off: one flies to the landing at a time") {
    GapLevel g(1, false);
    add_jump(g, false);
    const Handle a = g.add_agent(Vec3(2.5f, 0.0f, 1.5f), 3.0f), b = g.add_agent(Vec3(2.5f, 0.0f, 2.5f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), a, Vec3(9.0f, 0.0f, 1.0f));
    g.world->agents().set_destination(g.world->navmeshes(), b, Vec3(9.0f, 0.0f, 3.0f));
    int both_in_air = 0, waited = 0;
    g.run(30.0f, 1.0f / 60.0f, [&](int) {
        const nl::AgentInfo x = g.world->agents().info(a), y = g.world->agents().info(b);
        both_in_air += x.state == AgentState::Jumping && y.state == AgentState::Jumping;
        waited += x.state == AgentState::Waiting || y.state == AgentState::Waiting;
    });
    CHECK(both_in_air == 0);
    CHECK(waited > 0);
    CHECK(g.world->agents().info(a).state == AgentState::Arrived);
    CHECK(g.world->agents().info(b).state == AgentState::Arrived);
}

TEST_CASE("bad input: a clear error, or a failed agent with its event; never a crash") {
    GapLevel g(1, false);
    const Handle agent = g.add_agent(Vec3(1.0f, 0.0f, 2.0f));
    nl::Agents& agents = g.world->agents();
    CHECK_THROWS_AS(g.world->step(NAN), nl::Error);
    CHECK_THROWS_AS(g.world->step(-1.0f), nl::Error);
    CHECK_THROWS_AS(g.world->step(INFINITY), nl::Error);
    CHECK_THROWS_AS(agents.set_speed(agent, -1.0f, 1.0f), nl::Error);
    CHECK_THROWS_AS(agents.set_destination(g.world->navmeshes(), agent, Vec3(50.0f, 0.0f, 50.0f)), nl::Error);
    CHECK_FALSE(agents.info(agent).has_destination);  // an off-navmesh destination is not kept
    CHECK_THROWS_AS(agents.info(Handle{99, 1}), nl::Error);
    nl::AgentDef off;
    off.navmesh = g.navmesh;
    off.position = Vec3(5.0f, 0.0f, 2.0f);  // over the gap
    try {
        agents.add(g.world->navmeshes(), off);
        FAIL("an agent off the navmesh was added");
    } catch (const nl::Error& e) {
        CHECK(e.code() == nl::ErrorCode::NotFound);
        CHECK(std::string(e.what()).find("nearest navmesh point is") != std::string::npos);
    }
    agents.set_destination(g.world->navmeshes(), agent, Vec3(3.0f, 0.0f, 5.0f));
    g.world->step(0.1f);
    g.world->navmeshes().remove(g.navmesh);
    g.world->step(0.1f);
    CHECK(agents.info(agent).state == AgentState::Failed);
    CHECK(agents.info(agent).reason == nl::AgentReason::NavMeshRemoved);
    const auto events = agents.events();
    REQUIRE(events.size() == 1);
    CHECK(events[0].kind == AgentEventKind::Failed);
    agents.remove(agent);
    CHECK_FALSE(agents.contains(agent));
    CHECK_THROWS_AS(agents.remove(agent), nl::Error);
}

TEST_CASE("an agent that failed for another reason fails again, with its event, when its navmesh is removed") {
    // Two squares 2 m apart and no link: a walker sent across goes as near as it can and fails NO_PATH.
    nl::World world{nl::WorldSettings{}};
    nl::NavMeshInput in;
    add_polygon(in, {{0, 0}, {0, 4}, {4, 4}, {4, 0}});
    add_polygon(in, {{6, 0}, {6, 4}, {10, 4}, {10, 0}});
    in.agent_type.radius = 0.3f;
    in.agent_type.height = 2.0f;
    const Handle navmesh = world.add_navmesh(in);
    nl::AgentDef def;
    def.navmesh = navmesh;
    def.position = Vec3(1.0f, 0.0f, 2.0f);
    const Handle agent = world.agents().add(world.navmeshes(), def);
    world.agents().set_destination(world.navmeshes(), agent, Vec3(8.0f, 0.0f, 2.0f));
    for (int i = 0; i < 300 && world.agents().info(agent).state != AgentState::Failed; ++i) world.step(1.0f / 30.0f);
    REQUIRE(world.agents().info(agent).state == AgentState::Failed);
    REQUIRE(world.agents().info(agent).reason == nl::AgentReason::NoPath);

    world.navmeshes().remove(navmesh);
    world.step(1.0f / 30.0f);
    CHECK(world.agents().info(agent).state == AgentState::Failed);
    CHECK(world.agents().info(agent).reason == nl::AgentReason::NavMeshRemoved);
    const auto events = world.agents().events();
    REQUIRE(events.size() == 1);
    CHECK(events[0].kind == AgentEventKind::Failed);
    CHECK(events[0].reason == nl::AgentReason::NavMeshRemoved);
    world.step(1.0f / 30.0f);
    CHECK(world.agents().events().empty());  // said once
}

TEST_CASE("on a Recast navmesh the body never pops: no step moves it farther than its speed and fall allow") {
    // Recast's detail surface stands up to a few decimetres above the level's floor, where link ends
    // lie: the feet ease between the two before a take-off and after a landing.
    const nl::levelgen::GeneratedLevel level = nl::levelgen::generate_default_level(1);
    nl::test::RecastWorld r = nl::test::recast_world(level, 1);
    r.world->generate_links(r.navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
    nl::AgentDef def;
    def.navmesh = r.navmesh;
    def.position = Vec3(level.marker("start")->position);
    def.capabilities.max_jump_distance = 3.5f;  // the demo's long jumper
    def.capabilities.max_jump_height = 1.5f;
    def.capabilities.max_drop_height = 4.0f;
    const Handle agent = r.world->agents().add(r.world->navmeshes(), def);
    r.world->agents().set_destination(r.world->navmeshes(), agent, Vec3(level.marker("goal")->position));

    const float dt = 1.0f / 60.0f;
    Vec3 before = r.world->agents().info(agent).position;
    float worst_rise = 0.0f, worst_drop = 0.0f, worst_across = 0.0f;
    int take_offs = 0;
    bool arrived = false, was_walking = false;
    for (int step = 0; step < 60 * 60 && !arrived; ++step) {
        r.world->step(dt);
        for (const nl::AgentEvent& e : r.world->agents().events()) take_offs += e.kind == AgentEventKind::LinkStarted;
        const nl::AgentInfo a = r.world->agents().info(agent);
        arrived = a.state == AgentState::Arrived;
        const Vec3 move = a.position - before;
        const bool walked = a.state == AgentState::Walking && was_walking;
        was_walking = a.state == AgentState::Walking;
        if (walked) worst_across = std::max(worst_across, distance_xz(a.position, before) / dt);
        // Up at most a jump's launch speed (or a walk up a slope) in one step; down at most a fall's.
        worst_rise = std::max(worst_rise, move.y() / dt);
        worst_drop = std::max(worst_drop, -move.y() / dt);
        before = a.position;
    }
    CHECK(arrived);
    CHECK(take_offs == 3);  // two jumps and a drop, as navlink demo plans it
    CHECK(worst_across <= def.max_speed * 1.01f);
    // A jump's launch: up to sqrt(2 g h) for an arc of 1.5 m over the higher end (about 6.6 m/s).
    CHECK(worst_rise < 8.0f);
    // A 2 m drop ends at sqrt(2 g 2) = 6.3 m/s; a pop of 0.3 m in one step would read 18 m/s.
    CHECK(worst_drop < 8.0f);
}

TEST_CASE(
    "bodies on a landing never hold a link forever: two jumpers crossing a two-way link both arrive, "
    "and one standing on a landing does not stop the jump") {
    GapLevel g(1, false);
    add_jump(g, true);
    // The two ends of the link, one jumper heading each way (the walk round by the bridge is longer).
    const Handle east = g.add_agent(Vec3(3.0f, 0.0f, 2.0f), 3.0f), west = g.add_agent(Vec3(7.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), east, Vec3(9.0f, 0.0f, 2.0f));
    g.world->agents().set_destination(g.world->navmeshes(), west, Vec3(1.0f, 0.0f, 2.0f));
    int crossing_in_air = 0;
    const auto events = g.run(30.0f, 1.0f / 60.0f, [&](int) {
        crossing_in_air += g.world->agents().info(east).state == AgentState::Jumping &&
                           g.world->agents().info(west).state == AgentState::Jumping;
    });
    CHECK(g.world->agents().info(east).state == AgentState::Arrived);
    CHECK(g.world->agents().info(west).state == AgentState::Arrived);
    CHECK(count_events(events, east, AgentEventKind::LinkStarted) +
              count_events(events, west, AgentEventKind::LinkStarted) ==
          2);
    CHECK(crossing_in_air == 0);  // one after the other: two bodies never cross in the air

    GapLevel h(1, false);
    add_jump(h, false);
    h.add_agent(Vec3(6.4f, 0.0f, 2.0f));  // idle on the landing, forever
    const Handle jumper = h.add_agent(Vec3(1.0f, 0.0f, 2.0f), 3.0f);
    h.world->agents().set_destination(h.world->navmeshes(), jumper, Vec3(9.0f, 0.0f, 2.0f));
    const auto jumped = h.run(30.0f, 1.0f / 60.0f);
    CHECK(count_events(jumped, jumper, AgentEventKind::LinkStarted) == 1);
    CHECK(h.world->agents().info(jumper).state == AgentState::Arrived);
}

TEST_CASE("a path that starts on a take-off takes the link; stopped in the air, an agent lands and stands") {
    GapLevel g(1, false);
    add_jump(g, false);
    const Handle on_takeoff = g.add_agent(Vec3(3.6f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), on_takeoff, Vec3(9.0f, 0.0f, 2.0f));
    bool stopped = false;
    const auto events = g.run(20.0f, 1.0f / 60.0f, [&](int) {
        if (!stopped && g.world->agents().info(on_takeoff).state == AgentState::Jumping) {
            g.world->agents().stop(on_takeoff);
            stopped = true;
        }
    });
    REQUIRE(stopped);
    const nl::AgentInfo after = g.world->agents().info(on_takeoff);
    CHECK(after.state == AgentState::Idle);  // not WALKING with nowhere to go
    CHECK(after.position.x() > 6.0f);        // it landed across the gap
    CHECK(after.link.is_null());
    CHECK(count_events(events, on_takeoff, AgentEventKind::LinkFinished) == 1);
}

TEST_CASE("a two-way link made one-way is not taken against its way; new capabilities revive a body that had no path") {
    GapLevel g(1, false);
    const Handle link = add_jump(g, true);
    const Handle back = g.add_agent(Vec3(9.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), back, Vec3(1.0f, 0.0f, 2.0f));
    g.world->step(1.0f / 60.0f);
    REQUIRE(count_events(g.world->agents().events(), back, AgentEventKind::PathReady) == 1);
    REQUIRE_FALSE(g.world->agents().corners(back).empty());
    nl::Link one_way = g.world->navmeshes().link(link).second;
    one_way.bidirectional = false;
    g.world->update_link(link, one_way);
    const auto events = g.run(30.0f, 1.0f / 60.0f);
    CHECK(count_events(events, back, AgentEventKind::LinkStarted) == 0);  // walked round by the bridge
    CHECK(g.world->agents().info(back).state == AgentState::Arrived);
    CHECK(g.world->agents().info(back).link.is_null());

    // Two platforms with no bridge: a walker fails with no path; able to jump, it plans again and arrives.
    nl::WorldSettings settings;
    settings.worker_count = 1;
    nl::World world(std::move(settings));
    nl::NavMeshInput in;
    add_polygon(in, {{0.3f, 0.3f}, {0.3f, 3.7f}, {3.7f, 3.7f}, {3.7f, 0.3f}});
    add_polygon(in, {{6.3f, 0.3f}, {6.3f, 3.7f}, {9.7f, 3.7f}, {9.7f, 0.3f}});
    in.agent_type.radius = 0.3f;
    const Handle navmesh = world.add_navmesh(in);
    add_jump(world, navmesh, false);
    nl::AgentDef def;
    def.navmesh = navmesh;
    def.position = Vec3(1.0f, 0.0f, 2.0f);
    def.capabilities.radius = 0.3f;
    const Handle walker = world.agents().add(world.navmeshes(), def);
    world.agents().set_destination(world.navmeshes(), walker, Vec3(9.0f, 0.0f, 2.0f));
    for (int i = 0; i < 300 && world.agents().info(walker).state != AgentState::Failed; ++i) world.step(1.0f / 30.0f);
    REQUIRE(world.agents().info(walker).state == AgentState::Failed);
    nl::AgentCapabilities jumper = def.capabilities;
    jumper.max_jump_distance = 3.0f;
    jumper.max_jump_height = 1.0f;
    world.agents().set_capabilities(walker, jumper);
    for (int i = 0; i < 600 && world.agents().info(walker).state != AgentState::Arrived; ++i) world.step(1.0f / 30.0f);
    CHECK(world.agents().info(walker).state == AgentState::Arrived);
}

TEST_CASE("a body wider than its navmesh's is said once per radius, with the margin it keeps") {
    std::vector<std::string> warnings;
    nl::WorldSettings settings;
    settings.logger = nl::Logger(
        [&](nl::LogLevel level, std::optional<nl::ErrorCode>, const std::string& message) {
            if (level == nl::LogLevel::Warning) warnings.push_back(message);
        },
        nl::LogLevel::Warning);
    nl::World world(std::move(settings));
    nl::NavMeshInput in;
    add_polygon(in, {{0, 0}, {0, 10}, {10, 10}, {10, 0}});
    in.agent_type.radius = 0.6f;
    in.agent_type.height = 2.0f;
    const Handle navmesh = world.add_navmesh(in);
    auto add = [&](float radius) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = Vec3(5.0f, 0.0f, 5.0f);
        def.capabilities.radius = radius;
        world.add_agent(def);
    };
    add(0.6f);
    add(0.4f);
    CHECK(warnings.empty());
    add(1.5f);
    add(1.5f);
    REQUIRE(warnings.size() == 1);
    CHECK_MESSAGE(warnings[0].find("agents of radius 1.5 m on a navmesh built for radius 0.6 m") == 0, warnings[0]);
    CHECK(warnings[0].find("keep 0.9 m more from walls") != std::string::npos);
    CHECK(warnings[0].find("cannot pass where the navmesh is narrower than 1.8 m") != std::string::npos);
    CHECK(warnings[0].find("nl_path_explain") != std::string::npos);
    add(1.0f);
    CHECK(warnings.size() == 2);
}

TEST_CASE(
    "an agent's corners start where it is: a straight walk is two points, and in the air the first is the link it "
    "flies") {
    GapLevel g;
    const Handle walker = g.add_agent(Vec3(1.0f, 0.0f, 2.0f));
    g.world->agents().set_destination(g.world->navmeshes(), walker, Vec3(3.0f, 0.0f, 5.0f));
    g.world->step(1.0f / 30.0f);
    g.world->step(1.0f / 30.0f);
    const std::vector<nl::PathPoint> walk = g.world->agents().corners(walker);
    REQUIRE(walk.size() == 2);
    CHECK(walk[0].position.isApprox(g.world->agents().info(walker).position, 1e-5f));
    CHECK(walk[0].segment == nl::kSegmentWalk);
    CHECK(walk[1].position.isApprox(Vec3(3.0f, walk[1].position.y(), 5.0f), 1e-3f));
    CHECK(g.world->agents().info(walker).corners_ahead == 1);

    const Handle jumper = g.add_agent(Vec3(1.0f, 0.0f, 2.0f), 3.0f);
    g.world->agents().set_destination(g.world->navmeshes(), jumper, Vec3(9.0f, 0.0f, 2.0f));
    bool checked_in_air = false;
    for (int i = 0; i < 600 && !checked_in_air; ++i) {
        g.world->step(1.0f / 60.0f);
        const nl::AgentInfo info = g.world->agents().info(jumper);
        if (info.state != AgentState::Jumping) continue;
        const std::vector<nl::PathPoint> flying = g.world->agents().corners(jumper);
        REQUIRE(flying.size() >= 2);
        CHECK(flying[0].position.isApprox(info.position, 1e-4f));
        CHECK(flying[0].segment == uint32_t(nl::LinkKind::Jump));
        CHECK(flying[0].link == info.link);
        CHECK(flying.size() == info.corners_ahead + 1);
        checked_in_air = true;
    }
    CHECK(checked_in_air);
    g.run(20.0f);
    CHECK(g.world->agents().corners(walker).empty());  // arrived: nothing left to reach
}
