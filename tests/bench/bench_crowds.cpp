// navlink-bench-crowds [--threads 1|2] [--only NAME] [--seconds S] [--covers P,P,...] [--give-up G]
//                      [--navlink-only] [LEVEL.obj...]:
// NavLink's agents against DetourCrowd in crowd scenarios with known answers
// (tests/support/crowd_scenarios.h), and with random destinations on real levels at P% of the walkable
// area covered by bodies (default 5, 10, 20 and 40)
// (S seconds each, default 60; each agent sent on to its next point when it arrives), side by side in
// one run. On a level, "never arrived" counts the agents that reached none of their destinations.
// On a level, NavLink's agents give their destination up after G seconds held up in counterflow
// (nl_agent_def.give_up_seconds; default 10, 0: never) and are sent on to the next point, as a host
// whose agents roam would; in the scenarios they never give up (the default). --navlink-only skips
// DetourCrowd on the levels.
//
// What is compared, exactly:
// - The place: each scenario's boxes (a floor 1 m thick, walls 2.5 m high), built by the built-in
//   Recast builder's pipeline with default settings and agent type (radius 0.6 m, height 2 m; the
//   bottleneck scenarios radius 0.25 m, people's size in the published experiments); the
//   same polygon mesh goes to NavLink (nl_navmesh_add) and to Detour (dtCreateNavMeshData), as in
//   navlink-bench-agents (recast_detour.h).
// - The agents: the scenario's starts and goals, bodies of the navmesh's radius and height, max speed
//   3.5 m/s and acceleration 8 m/s^2 (nl_default_agent_def's) on both sides. NavLink: a world of
//   --threads workers (default 1), agents with avoidance on. DetourCrowd: RecastDemo's crowd tool
//   flags (anticipate turns, optimise visibility and topology, obstacle avoidance), its default
//   avoidance parameters, collision query range 12 radii, path optimisation range 30 radii.
// - Steps of 1/30 s for the scenario's time, each side's step timed alone (nl_world_step,
//   dtCrowd::update).
//
// One row per scenario and side:
//   arrived: agents that arrived at least once. NavLink: NL_AGENT_EVENT_ARRIVED. DetourCrowd has no
//     arrival: an agent counts as arrived when it is within 0.1 m of its target, or slower than
//     0.1 m/s within the circle its goal's group packs into (r * sqrt((k - 1) / 0.9069) plus half a
//     radius, k the agents sent to the same point): the same bound NavLink's arrival rule keeps.
//   stuck: agents that, not yet arrived, went 5 s without getting 0.1 m nearer their goal.
//   all_by: seconds until every agent had arrived ("-" if some never did).
//   deepest, mean: overlap of two bodies (the sum of radii less their distance, x-z), over every
//     overlapping pair of every step, metres; on a level from 5 s on (the bodies are put down at
//     random points, some on others, and pushed apart in the first steps), and only between bodies
//     less than a body's height apart in y (undulating's overhangs hold floors over floors).
//   flow: for the door scenarios, bodies through the door per metre of its width per second, from the
//     first to the last crossing of its middle.
//   us_step: microseconds per agent-step (the steps' total wall time over steps times agents).
#include <DetourCommon.h>
#include <DetourCrowd.h>
#include <navlink/navlink.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "clock.h"
#include "agents/neighbours.h"
#include "crowd_scenarios.h"
#include "destinations.h"
#include "level_generator.h"
#include "crowd_params.h"
#include "recast_detour.h"

namespace {

using nl::test::CrowdScenario;

constexpr float kDt = 1.0f / 30.0f;
constexpr float kArrive = 0.1f;    // m, x-z
constexpr float kProgress = 0.1f;  // m
constexpr float kStuck = 5.0f;     // s
constexpr float kStill = 0.1f;     // m/s
constexpr float kSettling = 5.0f;  // s: bodies put down at random points on a level, some on others, part meanwhile
constexpr float kHalfExtents[3] = {2.0f, 4.0f, 2.0f};

struct Outcome {
    int arrived = 0, stuck = 0, agents = 0;
    float all_by = -1.0f, deepest = 0.0f, mean = 0.0f, flow = -1.0f;
    double us_step = 0.0;
};

// What both sides measure the same way, step by step, from positions and velocities.
struct Tally {
    const CrowdScenario* scenario;
    float door = 0.0f;  // metres; 0: not a door scenario
    std::vector<uint8_t> arrived, stuck;
    std::vector<float> best, since, tolerance;
    std::vector<float> side;  // the sign of x at the start: a crossing of x = 0 flips it
    std::vector<float> crossings;
    double overlap_sum = 0.0;
    long overlaps = 0;
    Outcome out;

    explicit Tally(const CrowdScenario& s, float door_width) : scenario(&s), door(door_width) {
        const size_t n = s.agents.size();
        arrived.assign(n, 0);
        stuck.assign(n, 0);
        since.assign(n, 0.0f);
        for (size_t i = 0; i < n; ++i) {
            const auto& a = s.agents[i];
            best.push_back(std::hypot(a.start.x() - a.goal.x(), a.start.z() - a.goal.z()));
            side.push_back(a.start.x() < 0 ? -1.0f : 1.0f);
            int k = 0;
            for (const auto& b : s.agents)
                k += std::hypot(a.goal.x() - b.goal.x(), a.goal.z() - b.goal.z()) < 2 * s.radius;
            tolerance.push_back(k > 1 ? s.radius * std::sqrt(float(k - 1) / 0.9069f) + 0.5f * s.radius : kArrive);
        }
        out.agents = int(n);
    }

    // Positions and velocities (x y z each) after the step ending at `now`; `says_arrived[i]`: the
    // side's own word (NavLink's event), or -1 for the geometric rule.
    void add(float now, const std::vector<float>& positions, const std::vector<float>& velocities,
             const std::vector<int>& says_arrived) {
        const CrowdScenario& s = *scenario;
        const size_t n = s.agents.size();
        for (size_t i = 0; i < n; ++i) {
            const float* p = &positions[3 * i];
            const float d = std::hypot(p[0] - s.agents[i].goal.x(), p[2] - s.agents[i].goal.z());
            const float speed = std::hypot(velocities[3 * i], velocities[3 * i + 2]);
            const bool here =
                says_arrived[i] >= 0 ? says_arrived[i] == 1 : (d < kArrive || (d < tolerance[i] && speed < kStill));
            if (here) arrived[i] = 1;
            if (d < best[i] - kProgress || arrived[i]) best[i] = std::min(best[i], d), since[i] = now;
            if (!arrived[i] && now - since[i] > kStuck) stuck[i] = 1;
            if (door > 0.0f && (p[0] < 0 ? -1.0f : 1.0f) != side[i]) side[i] = -side[i], crossings.push_back(now);
            for (size_t j = i + 1; j < n; ++j) {
                const float* q = &positions[3 * j];
                const float overlap = 2 * s.radius - std::hypot(p[0] - q[0], p[2] - q[2]);
                if (overlap <= 0.0f) continue;
                out.deepest = std::max(out.deepest, overlap);
                overlap_sum += overlap;
                ++overlaps;
            }
        }
        if (out.all_by < 0 && std::count(arrived.begin(), arrived.end(), 1) == long(n)) out.all_by = now;
    }

    Outcome finish(double total_ms, int steps) {
        out.arrived = int(std::count(arrived.begin(), arrived.end(), 1));
        out.stuck = int(std::count(stuck.begin(), stuck.end(), 1));
        out.mean = overlaps ? float(overlap_sum / double(overlaps)) : 0.0f;
        if (door > 0.0f && crossings.size() > 1)
            out.flow = float(crossings.size() - 1) / (crossings.back() - crossings.front()) / door;
        out.us_step = 1000.0 * total_ms / double(steps) / double(std::max<size_t>(1, scenario->agents.size()));
        return out;
    }
};

// One NavLink step of kDt, timed alone; then its events and every agent's state. Returns its ms.
double step_navlink(nl_world* world, std::vector<nl_agent_event>& events, std::vector<nl_agent_info>& infos) {
    const double t0 = nl::samples::now_ms();
    nl_world_step(world, kDt);
    const double ms = nl::samples::now_ms() - t0;
    uint32_t count = 0;
    nl_world_get_agent_events(world, nullptr, 0, &count);
    events.assign(count, nl_agent_event_init());
    if (count) nl_world_get_agent_events(world, events.data(), count, &count);
    infos[0] = nl_agent_info_init();
    nl_world_get_agents(world, infos.data(), uint32_t(infos.size()), &count);
    return ms;
}

bool run_navlink(const nl::bench::RecastLevel& level, const CrowdScenario& s, int threads, Tally& tally) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = threads;
    def.path_worker_count = 0;
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(&def, &world))) return false;
    nl_navmesh_id navmesh{};
    uint32_t polygons = 0;
    bool ok = nl::bench::add_navlink_navmesh(world, level, &navmesh, &polygons);
    const size_t n = s.agents.size();
    std::vector<nl_agent_id> ids(n);
    for (size_t i = 0; ok && i < n; ++i) {
        nl_agent_def agent = nl_default_agent_def();
        agent.navmesh = navmesh;
        agent.height = level.agent.height;
        agent.capabilities.radius = level.agent.radius;
        agent.max_speed = s.max_speed;
        agent.max_acceleration = s.max_acceleration;
        agent.user_data = i;
        std::memcpy(agent.position, s.agents[i].start.data(), sizeof agent.position);
        ok = NL_SUCCEEDED(nl_agent_add(world, &agent, &ids[i])) &&
             NL_SUCCEEDED(nl_agent_set_destination(world, ids[i], s.agents[i].goal.data()));
    }
    if (!ok)
        std::fprintf(stderr, "navlink-bench-crowds: %s: NavLink: %s\n", s.name.c_str(), nl_get_last_error_message());
    std::vector<float> positions(3 * n), velocities(3 * n);
    std::vector<int> says(n, 0);
    std::vector<nl_agent_info> infos(n, nl_agent_info_init());
    std::vector<nl_agent_event> events;
    double total = 0.0;
    const int steps = int(s.seconds / kDt);
    for (int step = 1; ok && step <= steps; ++step) {
        total += step_navlink(world, events, infos);
        for (const nl_agent_event& e : events)
            if (e.kind == NL_AGENT_EVENT_ARRIVED) says[e.user_data] = 1;
        for (size_t i = 0; i < n; ++i) {
            std::memcpy(&positions[3 * i], infos[i].position, 3 * sizeof(float));
            std::memcpy(&velocities[3 * i], infos[i].velocity, 3 * sizeof(float));
        }
        tally.add(float(step) * kDt, positions, velocities, says);
    }
    nl_world_destroy(world);
    tally.out.us_step = total;  // finished below
    return ok;
}

// One DetourCrowd update of kDt, timed alone; then every agent's position and velocity. Returns its ms.
double step_detour_crowd(dtCrowd* crowd, std::vector<float>& positions, std::vector<float>& velocities) {
    const double t0 = nl::samples::now_ms();
    crowd->update(kDt, nullptr);
    const double ms = nl::samples::now_ms() - t0;
    for (size_t i = 0; 3 * i < positions.size(); ++i) {
        const dtCrowdAgent* a = crowd->getAgent(int(i));
        std::memcpy(&positions[3 * i], a->npos, 3 * sizeof(float));
        std::memcpy(&velocities[3 * i], a->vel, 3 * sizeof(float));
    }
    return ms;
}

bool run_detour_crowd(nl::bench::RecastLevel& level, const CrowdScenario& s, Tally& tally, double& total) {
    nl::bench::DetourMesh detour;
    if (!nl::bench::build_detour(level, detour)) return false;
    dtCrowd* crowd = dtAllocCrowd();
    const size_t n = s.agents.size();
    bool ok = crowd && crowd->init(int(n), level.agent.radius, detour.mesh);
    dtCrowdAgentParams params = nl::bench::detour_crowd_agent(level);
    params.maxSpeed = s.max_speed;
    params.maxAcceleration = s.max_acceleration;
    const dtQueryFilter filter;
    for (size_t i = 0; ok && i < n; ++i) {
        float nearest[3], target[3];
        dtPolyRef ref = 0, goal = 0;
        detour.query->findNearestPoly(s.agents[i].start.data(), kHalfExtents, &filter, &ref, nearest);
        detour.query->findNearestPoly(s.agents[i].goal.data(), kHalfExtents, &filter, &goal, target);
        ok = ref && goal && crowd->addAgent(nearest, &params) == int(i) &&
             crowd->requestMoveTarget(int(i), goal, target);
    }
    if (!ok) std::fprintf(stderr, "navlink-bench-crowds: %s: DetourCrowd would not take the agents\n", s.name.c_str());
    std::vector<float> positions(3 * n), velocities(3 * n);
    const std::vector<int> geometric(n, -1);
    const int steps = int(s.seconds / kDt);
    for (int step = 1; ok && step <= steps; ++step) {
        total += step_detour_crowd(crowd, positions, velocities);
        tally.add(float(step) * kDt, positions, velocities, geometric);
    }
    dtFreeCrowd(crowd);
    return ok;
}

std::string figure(float value, const char* format) {
    if (value < 0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, double(value));
    return text;
}

void print(const char* side, const Outcome& o) {
    std::printf(
        "  %-11s %3d/%-3d arrived %3d stuck  all_by %6s s  deepest %.3f m  mean %.3f m  flow %5s /m/s  %6.2f "
        "us/agent-step\n",
        side, o.arrived, o.agents, o.stuck, figure(o.all_by, "%.1f").c_str(), double(o.deepest), double(o.mean),
        figure(o.flow, "%.2f").c_str(), o.us_step);
}

struct Case {
    CrowdScenario scenario;
    float door = 0.0f;
    float cell_size = 0.0f;  // Recast's voxel width (0: its default)
};

constexpr float kPeopleCells = 0.05f;  // m: Recast cells for the bottleneck experiments' doors

// A crowd on a real level: bodies that cover `cover` of the walkable area, each sent to a random
// reachable point and to the next one whenever it arrives (or, NavLink, fails).
struct LevelTally {
    size_t n;
    float radius, height;
    std::vector<long> arrivals;
    std::vector<float> best, since;
    std::vector<uint8_t> stuck;
    double overlap_sum = 0.0;
    long overlaps = 0;
    float deepest = 0.0f;

    LevelTally(size_t agents, float r, float h)
        : n(agents),
          radius(r),
          height(h),
          arrivals(agents, 0),
          best(agents, 1e9f),
          since(agents, 0.0f),
          stuck(agents, 0) {}

    // A new goal for agent i at `now`: its progress is measured afresh.
    void retarget(size_t i, float now) { best[i] = 1e9f, since[i] = now; }
    void add(float now, const std::vector<float>& positions, const std::vector<float>& goals) {
        std::vector<nl::Vec3> at(n);
        for (size_t i = 0; i < n; ++i) at[i] = nl::Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        nl::NeighbourGrid grid;
        grid.build(at, std::vector<uint8_t>(n, 1), 3 * radius);
        for (size_t i = 0; i < n; ++i) {
            const float d = std::hypot(at[i].x() - goals[3 * i], at[i].z() - goals[3 * i + 2]);
            if (d < best[i] - kProgress) best[i] = d, since[i] = now;
            if (now - since[i] > kStuck) stuck[i] = 1;
            grid.visit(at[i], 2 * radius, [&](uint32_t j) {
                // A body on a floor over another's (undulating has overhangs) is not in contact with it.
                if (j <= i || now < kSettling || std::fabs(at[i].y() - at[j].y()) >= height) return;
                const float overlap = 2 * radius - std::hypot(at[i].x() - at[j].x(), at[i].z() - at[j].z());
                if (overlap <= 0.0f) return;
                deepest = std::max(deepest, overlap);
                overlap_sum += overlap;
                ++overlaps;
            });
        }
    }
    void print(const char* side, double total_ms, int steps) const {
        long total = 0, never = 0;
        for (const long a : arrivals) total += a, never += a == 0;
        std::printf(
            "  %-11s %6ld arrivals %4ld/%-4zu never arrived %4ld stuck  deepest %.3f m  mean %.3f m  %6.2f "
            "us/agent-step\n",
            side, total, never, n, long(std::count(stuck.begin(), stuck.end(), 1)), double(deepest),
            overlaps ? overlap_sum / double(overlaps) : 0.0, 1000.0 * total_ms / double(steps) / double(n));
    }
};

void run_level(nl::bench::RecastLevel& level, float cover, float seconds, int threads, float give_up,
               bool navlink_only) {
    nl::bench::Destinations where;
    where.pm = level.solo.polygons.get();
    where.polygons = nl::bench::largest_connected_polygons(*level.solo.polygons);
    where.seed = 7;
    const float r = level.agent.radius;
    const size_t n = size_t(std::lround(cover * where.area() / (M_PI * r * r)));
    if (n < 2) return;
    const int steps = int(seconds / kDt);
    std::printf(
        "%s, %.0f%% covered (%zu agents, %.0f s, random destinations, a new one on arrival; NavLink's give up after "
        "%.0f s in counterflow)\n",
        level.name.c_str(), double(100 * cover), n, double(seconds), double(give_up));
    std::vector<float> positions(3 * n), velocities(3 * n), goals(3 * n);
    std::vector<uint32_t> trips(n, 1);
    {  // NavLink
        nl_world_def def = nl_default_world_def();
        def.worker_count = threads;
        def.path_worker_count = 0;
        nl_world* world = nullptr;
        nl_navmesh_id navmesh{};
        uint32_t polygons = 0;
        if (NL_FAILED(nl_world_create(&def, &world)) ||
            !nl::bench::add_navlink_navmesh(world, level, &navmesh, &polygons))
            return;
        std::vector<nl_agent_id> ids(n);
        LevelTally tally(n, r, level.agent.height);
        auto send = [&](size_t i, float now) {
            for (int attempt = 0; attempt < 4; ++attempt) {
                where.point(uint32_t(i), trips[i]++, &goals[3 * i]);
                if (NL_SUCCEEDED(nl_agent_set_destination(world, ids[i], &goals[3 * i]))) break;
            }
            tally.retarget(i, now);
        };
        for (size_t i = 0; i < n; ++i) {
            nl_agent_def agent = nl_default_agent_def();
            agent.navmesh = navmesh;
            agent.height = level.agent.height;
            agent.capabilities.radius = r;
            agent.user_data = i;
            agent.give_up_seconds = give_up;
            where.point(uint32_t(i), 0, agent.position);
            if (NL_FAILED(nl_agent_add(world, &agent, &ids[i]))) return;
            send(i, 0.0f);
        }
        std::vector<nl_agent_info> infos(n, nl_agent_info_init());
        std::vector<nl_agent_event> events;
        double total = 0.0;
        for (int step = 1; step <= steps; ++step) {
            const float now = float(step) * kDt;
            total += step_navlink(world, events, infos);
            for (const nl_agent_event& e : events) {
                if (e.kind != NL_AGENT_EVENT_ARRIVED && e.kind != NL_AGENT_EVENT_FAILED) continue;
                tally.arrivals[e.user_data] += e.kind == NL_AGENT_EVENT_ARRIVED;
                send(e.user_data, now);
            }
            for (size_t i = 0; i < n; ++i) std::memcpy(&positions[3 * i], infos[i].position, 3 * sizeof(float));
            tally.add(now, positions, goals);
        }
        nl_world_destroy(world);
        tally.print("NavLink", total, steps);
    }
    if (!navlink_only) {  // DetourCrowd, arriving within 0.1 m of its target (it has no arrival of its own)
        nl::bench::DetourMesh detour;
        if (!nl::bench::build_detour(level, detour)) return;
        dtCrowd* crowd = dtAllocCrowd();
        if (!crowd || !crowd->init(int(n), r, detour.mesh)) return;
        const dtCrowdAgentParams params = nl::bench::detour_crowd_agent(level);
        const dtQueryFilter filter;
        LevelTally tally(n, r, level.agent.height);
        std::fill(trips.begin(), trips.end(), 1u);
        auto send = [&](size_t i, float now) {
            for (int attempt = 0; attempt < 4; ++attempt) {
                float nearest[3];
                dtPolyRef ref = 0;
                where.point(uint32_t(i), trips[i]++, &goals[3 * i]);
                detour.query->findNearestPoly(&goals[3 * i], kHalfExtents, &filter, &ref, nearest);
                if (ref && crowd->requestMoveTarget(int(i), ref, nearest)) {
                    std::memcpy(&goals[3 * i], nearest, sizeof nearest);
                    break;
                }
            }
            tally.retarget(i, now);
        };
        for (size_t i = 0; i < n; ++i) {
            float start[3], nearest[3];
            dtPolyRef ref = 0;
            where.point(uint32_t(i), 0, start);
            detour.query->findNearestPoly(start, kHalfExtents, &filter, &ref, nearest);
            if (!ref || crowd->addAgent(nearest, &params) != int(i)) return;
            send(i, 0.0f);
        }
        double total = 0.0;
        for (int step = 1; step <= steps; ++step) {
            const float now = float(step) * kDt;
            total += step_detour_crowd(crowd, positions, velocities);
            for (size_t i = 0; i < n; ++i) {
                if (std::hypot(positions[3 * i] - goals[3 * i], positions[3 * i + 2] - goals[3 * i + 2]) < kArrive) {
                    ++tally.arrivals[i];
                    send(i, now);
                }
            }
            tally.add(now, positions, goals);
        }
        dtFreeCrowd(crowd);
        tally.print("DetourCrowd", total, steps);
    }
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 1;
    float seconds = 60.0f, give_up = 10.0f;
    bool navlink_only = false;
    std::string only;
    std::vector<std::string> levels;
    std::vector<float> covers{0.05f, 0.10f, 0.20f, 0.40f};
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        if (name.rfind("--", 0) != 0) {
            levels.push_back(name);
        } else if (i + 1 < argc && name == "--threads") {
            threads = std::atoi(argv[++i]);
        } else if (i + 1 < argc && name == "--only") {
            only = argv[++i];
        } else if (name == "--navlink-only") {
            navlink_only = true;
        } else if (i + 1 < argc && name == "--give-up") {
            give_up = float(std::atof(argv[++i]));
        } else if (i + 1 < argc && name == "--seconds") {
            seconds = float(std::atof(argv[++i]));
        } else if (i + 1 < argc && name == "--covers") {
            covers.clear();
            std::istringstream list(argv[++i]);
            for (std::string percent; std::getline(list, percent, ',');) covers.push_back(std::stof(percent) / 100.0f);
        } else {
            std::fprintf(stderr,
                         "usage: navlink-bench-crowds [--threads 1|2] [--only NAME] [--seconds S] [--covers P,P,...] "
                         "[--give-up G] "
                         "[--navlink-only] [LEVEL.obj...]\n");
            return 2;
        }
    }
    std::vector<Case> cases;
    cases.push_back({nl::test::one_point(2, 8.0f)});
    cases.push_back({nl::test::one_point(2, 8.0f, true)});
    cases.push_back({nl::test::one_point(8, 8.0f)});
    cases.push_back({nl::test::one_point(24, 10.0f)});
    for (const int per_side : {3, 10, 50}) cases.push_back({nl::test::door_counterflow(per_side, 2.0f), 2.0f});
    cases.push_back({nl::test::door_counterflow(50, 2.0f, false), 2.0f});
    cases.push_back({nl::test::corridor(10, 5.0f, false)});
    cases.push_back({nl::test::corridor(10, 5.0f, true)});
    // Bottlenecks as in the published experiments (Seyfried et al. 2009, Kretz et al. 2006): people
    // about 0.5 m across (radius 0.25 m here) at a person's free walking speed (1.34 m/s; 2.7 m/s^2,
    // that speed in half a second), doors 0.8 to 3 m (one at a time below about 1 m), 50 through one
    // way, on a navmesh of 5 cm cells
    // (at the default 30 cm, doors 40 cm apart in width open alike once eroded).
    for (const float width : {0.8f, 1.0f, 1.2f, 1.6f, 2.0f, 2.5f, 3.0f}) {
        Case c{nl::test::door_counterflow(50, width, false, 0.25f), width, kPeopleCells};
        c.scenario.name += ", people (radius 0.25 m, 1.34 m/s), door " + figure(width, "%.1f") + " m";
        c.scenario.max_speed = 1.34f;
        c.scenario.max_acceleration = 2.7f;
        cases.push_back(c);
    }
    std::printf(
        "navlink-bench-crowds: NavLink on %d thread%s against DetourCrowd, steps of 1/30 s, bodies of radius 0.6 m "
        "unless said\n",
        threads, threads == 1 ? "" : "s");
    int failures = 0;
    for (Case& c : cases) {
        const CrowdScenario& s = c.scenario;
        if (!only.empty() && s.name.find(only) == std::string::npos) continue;
        nl::levelgen::GeneratedLevel geometry;
        for (const auto& [lo, hi] : s.boxes) geometry.add_box({{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}});
        nl::bench::RecastLevel level =
            nl::bench::build_recast_level(s.name, geometry.positions, geometry.indices, s.radius, c.cell_size);
        Tally nl_tally(s, c.door), dc_tally(s, c.door);
        double dc_ms = 0.0;
        if (!run_navlink(level, s, threads, nl_tally) || !run_detour_crowd(level, s, dc_tally, dc_ms)) {
            ++failures;
            continue;
        }
        const int steps = int(s.seconds / kDt);
        const Outcome nl_outcome = nl_tally.finish(nl_tally.out.us_step, steps),
                      dc_outcome = dc_tally.finish(dc_ms, steps);
        std::printf("%s (%zu agents, %.0f s)\n", s.name.c_str(), s.agents.size(), double(s.seconds));
        print("NavLink", nl_outcome);
        print("DetourCrowd", dc_outcome);
        std::fflush(stdout);
    }
    // Real levels: random destinations at 5, 10, 20 and 40% of the walkable area covered by bodies.
    for (const std::string& path : levels) {
        nl::bench::RecastLevel level = nl::bench::build_recast_level_from_obj(path.c_str());
        for (const float cover : covers) run_level(level, cover, seconds, threads, give_up, navlink_only);
    }
    return failures ? 1 : 0;
}
