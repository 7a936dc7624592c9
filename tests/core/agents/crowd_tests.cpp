// Crowds with known answers (tests/support/crowd_scenarios.h), counted as a player sees them: every
// agent arrives within the scenario's time, none stands WALKING (slower than 0.1 m/s) for 5 s, and
// bodies on the ground overlap by at most a few centimetres; the same bit for bit on 1 and 2 threads
// (a step shares agents between threads 64 at a time: the big door scenario is what that compares).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "crowd_scenarios.h"
#include "world/world.h"

namespace {

using nl::AgentState;
using nl::Handle;
using nl::Vec3;
using nl::test::CrowdOutcome;
using nl::test::CrowdScenario;

constexpr float kDt = 1.0f / 30.0f;
constexpr float kStuckSeconds = 5.0f;

float distance_xz(const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); }

struct Run {
    CrowdOutcome outcome;
    std::vector<nl::AgentInfo> last;  // every agent's state at the end, for comparing thread counts
};

Run run(const CrowdScenario& s, int workers) {
    nl::WorldSettings settings;
    settings.worker_count = workers;
    nl::World world(std::move(settings));
    const Handle navmesh = world.add_navmesh(s.navmesh);
    std::vector<Handle> ids;
    for (const nl::test::CrowdAgent& a : s.agents) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = a.start;
        def.capabilities.radius = s.radius;
        def.max_speed = s.max_speed;
        def.max_acceleration = s.max_acceleration;
        ids.push_back(world.agents().add(world.navmeshes(), def));
        world.agents().set_destination(world.navmeshes(), ids.back(), a.goal);
    }
    const size_t n = ids.size();
    std::vector<uint8_t> arrived(n, 0), stuck(n, 0);
    std::vector<float> since(n, 0.0f);  // when it was last seen other than standing WALKING
    Run r;
    double overlap_sum = 0;
    size_t overlaps = 0;
    const int steps = int(s.seconds / kDt);
    for (int step = 1; step <= steps; ++step) {
        world.step(kDt);
        const float now = float(step) * kDt;
        const std::vector<nl::AgentInfo> infos = world.agents().infos();
        for (size_t i = 0; i < n; ++i) {
            const nl::AgentInfo& a = infos[i];
            if (a.state == AgentState::Arrived) arrived[i] = 1;
            // Stuck as a host sees it: standing WALKING (slower than 0.1 m/s) for 5 s on end. A body
            // held up says WAITING (for room) instead, and one that moves is not standing.
            if (a.state != AgentState::Walking || std::hypot(a.velocity.x(), a.velocity.z()) >= 0.1f) since[i] = now;
            if (now - since[i] > kStuckSeconds) stuck[i] = 1;
            for (size_t j = i + 1; j < n; ++j) {
                const float overlap = 2 * s.radius - distance_xz(a.position, infos[j].position);
                if (overlap <= 0) continue;
                r.outcome.deepest_overlap = std::max(r.outcome.deepest_overlap, overlap);
                overlap_sum += overlap;
                ++overlaps;
            }
        }
        if (r.outcome.all_arrived_at < 0 && std::count(arrived.begin(), arrived.end(), 1) == long(n))
            r.outcome.all_arrived_at = now;
        r.last = infos;
    }
    r.outcome.arrived = int(std::count(arrived.begin(), arrived.end(), 1));
    r.outcome.never_arrived = int(n) - r.outcome.arrived;
    r.outcome.stuck = int(std::count(stuck.begin(), stuck.end(), 1));
    r.outcome.mean_overlap = overlaps ? float(overlap_sum / double(overlaps)) : 0.0f;
    return r;
}

// Runs the scenario on 1 and 2 threads, checks the two ended alike, and the crowd's figures.
void check(const CrowdScenario& s) {
    const Run one = run(s, 1), two = run(s, 2);
    const CrowdOutcome& o = one.outcome;
    MESSAGE(s.name << ": " << o.arrived << " of " << s.agents.size() << " arrived (all by " << o.all_arrived_at
                   << " s), " << o.stuck << " stuck, deepest overlap " << o.deepest_overlap << " m, mean "
                   << o.mean_overlap << " m");
    REQUIRE(one.last.size() == two.last.size());
    for (size_t i = 0; i < one.last.size(); ++i) {
        CHECK(one.last[i].position == two.last[i].position);
        CHECK(one.last[i].state == two.last[i].state);
    }
    for (size_t i = 0; i < one.last.size(); ++i)
        if (one.last[i].state != AgentState::Arrived)
            MESSAGE("agent " << i << " ends " << int(one.last[i].state) << " reason " << int(one.last[i].reason)
                             << " at " << one.last[i].position.transpose() << " speed " << one.last[i].velocity.norm()
                             << ", sent to " << s.agents[i].goal.transpose());
    CHECK(o.never_arrived == 0);
    CHECK(o.stuck == 0);
    CHECK(o.deepest_overlap <= 0.05f);
}

}  // namespace

TEST_CASE("crowd: two agents sent head-on to one point both arrive, touching at most") {
    check(nl::test::one_point(2, 8.0f));
}

TEST_CASE("crowd: two agents sent to one point at 90 degrees both arrive") {
    check(nl::test::one_point(2, 8.0f, true));
}

TEST_CASE("crowd: eight agents in a ring sent to their centre all arrive around it") {
    check(nl::test::one_point(8, 8.0f));
}

TEST_CASE("crowd: twenty-four agents sent to one point all arrive around it") { check(nl::test::one_point(24, 10.0f)); }

TEST_CASE("crowd: three on each side of a 2 m door all get through in counterflow") {
    check(nl::test::door_counterflow(3, 2.0f));
}

TEST_CASE("crowd: ten on each side of a 2 m door all get through in counterflow") {
    check(nl::test::door_counterflow(10, 2.0f));
}

TEST_CASE("crowd: twenty through a 2 m door one way all get through") {
    check(nl::test::door_counterflow(20, 2.0f, false));
}

TEST_CASE("crowd: a hundred and forty at a door in counterflow move the same on 1 and 2 threads") {
    // 70 a side: more than two of the step's 64-agent shares, so two threads really share them.
    CrowdScenario s = nl::test::door_counterflow(70, 2.0f);
    s.seconds = 20.0f;  // not all get through in that time: this compares the threads
    const Run one = run(s, 1), two = run(s, 2);
    MESSAGE(s.name << ": " << one.outcome.arrived << " arrived in 20 s, deepest overlap " << one.outcome.deepest_overlap
                   << " m");
    REQUIRE(one.last.size() == 140);
    for (size_t i = 0; i < one.last.size(); ++i) {
        CHECK(one.last[i].position == two.last[i].position);
        CHECK(one.last[i].velocity == two.last[i].velocity);
        CHECK(one.last[i].state == two.last[i].state);
    }
    // Pressed 70 deep against a door, bodies still sink 7 cm at the deepest (the 5 cm of the other
    // scenarios holds up to ten a side): issue 32's closing note.
    CHECK(one.outcome.deepest_overlap <= 0.1f);
}

TEST_CASE("crowd: ten from each end of two 5 m corridors crossing at 90 degrees all get through") {
    check(nl::test::corridor(10, 5.0f, true));
}

namespace {

// Two agents head-on in a corridor too narrow for them to pass (1.6 m: the walkable strip the body's
// radius leaves is 0.4 m wide), each giving its destination up after `give_up` seconds (0: never).
// Returns, per agent, the step's events and states over `seconds`.
struct NarrowRun {
    std::vector<std::vector<nl::AgentEvent>> events;  // per agent
    std::vector<std::vector<nl::AgentInfo>> states;   // per agent, every step
};

NarrowRun head_on_in_narrow_corridor(const float give_up[2], float seconds) {
    const CrowdScenario s = nl::test::corridor(1, 1.6f, false);
    REQUIRE(s.agents.size() == 2);
    nl::WorldSettings settings;
    settings.worker_count = 1;
    nl::World world(std::move(settings));
    const Handle navmesh = world.add_navmesh(s.navmesh);
    std::vector<Handle> ids;
    for (size_t i = 0; i < 2; ++i) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = s.agents[i].start;
        def.capabilities.radius = s.radius;
        def.user_data = i;
        def.give_up_seconds = give_up[i];
        ids.push_back(world.agents().add(world.navmeshes(), def));
        world.agents().set_destination(world.navmeshes(), ids.back(), s.agents[i].goal);
    }
    NarrowRun r;
    r.events.resize(2);
    r.states.resize(2);
    for (int step = 0; step < int(seconds / kDt); ++step) {
        world.step(kDt);
        for (const nl::AgentEvent& e : world.agents().events()) r.events[e.user_data].push_back(e);
        const std::vector<nl::AgentInfo> infos = world.agents().infos();
        for (size_t i = 0; i < 2; ++i) r.states[i].push_back(infos[i]);
    }
    return r;
}

size_t count_events(const std::vector<nl::AgentEvent>& events, nl::AgentEventKind kind, nl::AgentReason reason) {
    return size_t(std::count_if(events.begin(), events.end(),
                                [&](const nl::AgentEvent& e) { return e.kind == kind && e.reason == reason; }));
}

}  // namespace

TEST_CASE("crowd: two head-on in a corridor too narrow to pass say they wait for room, and never stand WALKING still") {
    const float never[2] = {0.0f, 0.0f};
    const NarrowRun r = head_on_in_narrow_corridor(never, 40.0f);
    for (size_t i = 0; i < 2; ++i) {
        CAPTURE(i);
        // They meet, and one at least waits for the other (stuck, or stepping back to give way).
        CHECK(count_events(r.events[i], nl::AgentEventKind::Waiting, nl::AgentReason::Crowd) >= 1);
        CHECK(count_events(r.events[i], nl::AgentEventKind::Failed, nl::AgentReason::Crowd) == 0);
        float standing_walking = 0.0f, longest = 0.0f;
        bool waited = false;
        for (const nl::AgentInfo& a : r.states[i]) {
            // A host reads every wait for room as WAITING with the reason CROWD; and a body that reads
            // WALKING is walking (slower than 0.1 m/s for at most a second: turning, starting).
            if (a.state == AgentState::Waiting && a.reason == nl::AgentReason::Crowd) waited = true;
            if (a.state == AgentState::Walking && std::hypot(a.velocity.x(), a.velocity.z()) < 0.1f)
                standing_walking += kDt;
            else
                standing_walking = 0.0f;
            longest = std::max(longest, standing_walking);
        }
        CHECK(waited);
        CHECK(longest <= 1.0f);
        CHECK(r.states[i].back().state != AgentState::Failed);
    }
}

TEST_CASE("crowd: of two head-on in a corridor too narrow to pass, the one told to gives its destination up") {
    const float first_gives_up[2] = {4.0f, 0.0f};
    const NarrowRun r = head_on_in_narrow_corridor(first_gives_up, 40.0f);
    CHECK(count_events(r.events[0], nl::AgentEventKind::Failed, nl::AgentReason::Crowd) == 1);
    CHECK(count_events(r.events[1], nl::AgentEventKind::Failed, nl::AgentReason::Crowd) == 0);
    // It failed once held up 4 s without getting 1 m nearer: not before it met the other (they start
    // 27 m apart and walk 3.5 m/s), and not long after.
    size_t failed_at = 0;
    while (failed_at < r.states[0].size() && r.states[0][failed_at].state != AgentState::Failed) ++failed_at;
    REQUIRE(failed_at < r.states[0].size());
    const float when = float(failed_at + 1) * kDt;
    MESSAGE("gave up at " << when << " s");
    CHECK(when >= 4.0f + 3.0f);
    CHECK(when <= 30.0f);
    CHECK(r.states[0].back().state == AgentState::Failed);
    CHECK(r.states[0].back().reason == nl::AgentReason::Crowd);
}

TEST_CASE("crowd: a queue through a door, all one way, never gives up however long it waits") {
    CrowdScenario s = nl::test::door_counterflow(20, 2.0f, false);
    nl::WorldSettings settings;
    settings.worker_count = 1;
    nl::World world(std::move(settings));
    const Handle navmesh = world.add_navmesh(s.navmesh);
    for (const nl::test::CrowdAgent& a : s.agents) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = a.start;
        def.capabilities.radius = s.radius;
        def.give_up_seconds = 1.0f;  // held up 1 s in counterflow would do
        const Handle id = world.agents().add(world.navmeshes(), def);
        world.agents().set_destination(world.navmeshes(), id, a.goal);
    }
    size_t waits = 0, failures = 0, arrivals = 0;
    for (int step = 0; step < int(s.seconds / kDt); ++step) {
        world.step(kDt);
        for (const nl::AgentEvent& e : world.agents().events()) {
            waits += e.kind == nl::AgentEventKind::Waiting;
            failures += e.kind == nl::AgentEventKind::Failed;
            if (e.kind == nl::AgentEventKind::Failed)
                MESSAGE("failed: reason " << int(e.reason) << " at " << step * kDt);
            arrivals += e.kind == nl::AgentEventKind::Arrived;
        }
    }
    MESSAGE(waits << " waits for room, " << arrivals << " arrivals");
    CHECK(waits >= 1);  // the queue did wait
    CHECK(failures == 0);
    CHECK(arrivals == s.agents.size());
}
