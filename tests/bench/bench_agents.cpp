// navlink-bench-agents [options] [--field N] [LEVEL.obj...]: NavLink's agents (nl_agent_* and
// nl_world_step) against DetourCrowd (librecast-dev's libDetourCrowd: dtCrowd) on the same Recast
// polygon mesh, side by side in one run.
//
// What is compared, exactly:
// - The navmesh: the polygon mesh and detail mesh the built-in Recast builder's pipeline makes with
//   default settings and agent type (radius 0.6 m, height 2 m), handed to NavLink through
//   nl_navmesh_add and to Detour through dtCreateNavMeshData (recast_detour.h, as navlink-bench-path).
//   No links: NavLink generates none and Detour's mesh has no off-mesh connections, so both walk the
//   same polygons and nothing else.
// - The crowd: for each level, 100, 1,000 and 5,000 agents (--agents a,b,c), all with the navmesh's
//   radius and height, max speed 3.5 m/s and max acceleration 8 m/s^2 (nl_default_agent_def's).
//   Start points and destinations are random points (a random polygon, a uniform point in one of its
//   fan triangles, half a metre up) of the polygon mesh's largest connected part, so every
//   destination can be reached; each side snaps them with its own nearest-point query (nl_agent_add
//   and nl_agent_set_destination locate them; Detour's findNearestPoly with half extents 2, 4, 2).
//   Agent i's k-th destination comes from a generator seeded with (level seed, i, k), so all sides
//   send agent i to the same places in the same order whenever they arrive. An arrival draws the
//   next destination at once, between steps and outside the timing.
// - NavLink: worlds with worker_count 1 and 2 (and path_worker_count 0), agents with
//   nl_default_agent_def (avoidance on: DetourCrowd's dtObstacleAvoidanceQuery between bodies with
//   dtCrowd::init's default parameters, the 6 nearest within 12 radii; the walls are kept by the
//   navmesh and the surface move, not sampled), agent_paths_per_step at its default (32 full
//   paths planned per step at most). Arrival: NL_AGENT_EVENT_ARRIVED (within 5 cm of the
//   destination); an agent that fails (NL_AGENT_EVENT_FAILED) is counted and sent on too.
// - DetourCrowd: dtCrowd::init(agents, radius, navmesh), every agent with RecastDemo's crowd tool
//   defaults: DT_CROWD_ANTICIPATE_TURNS | DT_CROWD_OPTIMIZE_VIS | DT_CROWD_OPTIMIZE_TOPO |
//   DT_CROWD_OBSTACLE_AVOIDANCE, separation off (separationWeight 2, unused), collisionQueryRange
//   12 radii, pathOptimizationRange 30 radii, obstacle avoidance parameter set 0 left as
//   dtCrowd::init sets it (velBias 0.4, weights 2 / 0.75 / 0.75 / 2.5, horizon 2.5 s, adaptive
//   sampling with 7 divisions, 2 rings, depth 5: the same parameters NavLink uses; RecastDemo's
//   "high quality" preset would be 7 / 3 / 3). DetourCrowd also samples the navmesh's boundary
//   segments near each agent, and plans paths its own way: a 20-iteration search at once, then the
//   rest through its path queue (100 search iterations per update in Debian's build), corridors of
//   256 polygons at most. Arrival: within 10 cm (x-z) of the target it was sent to (DetourCrowd has
//   no arrival state; its speed falls linearly to zero over the last two radii).
// - Timing: every side runs the same steps at the same dt (default 0.05 s) in lockstep, one step of
//   each in turn (the order rotating), so a shared machine's interruptions fall on all of them
//   alike. After --warm steps (default 200, untimed: NavLink plans 32 paths a step, so 5,000 agents
//   all have their first path after 157 steps; DetourCrowd gives each a 20-iteration path at once),
//   --steps steps (default 200) are timed: the
//   wall time of each nl_world_step and of each dtCrowd::update alone (not the host's re-targeting);
//   a side's figure is its median step (robust to the bursts of other work on a shared machine;
//   --verbose prints the means too).
//
// One row per level and agent count:
//   level polys agents nl_1t_us nl_2t_us dcrowd_us dc/nl1 dc/nl2 nl1/nl2 arrivals (nl, dc) fails_nl
//   waiting (nl, dc) moving (nl, dc) same
// *_us: microseconds per agent-step (the median timed step's wall time / agents). dc/nl1 and dc/nl2: how many
// times faster NavLink is than DetourCrowd (the target: >= 1 on one thread, >= 1.8 on two).
// arrivals: in the timed steps. waiting: agents at the end still waiting for a path (NavLink
// NL_AGENT_WAITING; DetourCrowd a target requesting or waiting for its path queue). moving: agents at
// the end faster than 0.1 m/s. area: m^2 (x-z) of the part the agents walk; fill: the
// bodies' discs over that area (near or past 100%, they cannot help overlapping: the small shared
// levels are far too small for 1,000 bodies of radius 0.6 m; undulating and --field levels are not). same: the two NavLink worlds ended bit-identical (positions,
// velocities, states), as nl_world_step promises for any thread count.
//
// --only nl1|nl2|dcrowd runs one side alone (for a profiler); --paths-per-step N sets NavLink's
// agent_paths_per_step (default: the world's, 32); --field N adds the procedural level
// nl::levelgen::generate_large_level(1, N) (N x N blocks of 12 m), named "large-N".
#include <DetourCommon.h>
#include <DetourCrowd.h>
#include <navlink/navlink.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "clock.h"
#include "level_generator.h"
#include "destinations.h"
#include "crowd_params.h"
#include "recast_detour.h"
#include "spread.h"

namespace {

using nl::bench::median;

constexpr float kHalfExtents[3] = {2.0f, 4.0f, 2.0f};
constexpr float kDetourArrive = 0.1f;  // m, x-z
constexpr float kMovingSpeed = 0.1f;   // m/s

struct Options {
    int warm = 200;
    int steps = 200;
    float dt = 0.05f;
    std::vector<int> counts{100, 1000, 5000};
    bool nl1 = true, nl2 = true, dcrowd = true;
    uint32_t paths_per_step = 0;  // NavLink's agent_paths_per_step; 0: the world's default
    bool verbose = false;         // NavLink's event counts, both sides' mean speed and distance left, on stderr
};

bool fail(const std::string& level, const char* what) {
    std::fprintf(stderr, "navlink-bench-agents: %s: %s: %s\n", level.c_str(), what, nl_get_last_error_message());
    return false;
}

struct NavLinkSide {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    std::vector<nl_agent_id> ids;
    std::vector<uint32_t> trips;  // destinations drawn so far, per agent
    std::vector<nl_agent_event> events;
    std::vector<nl_agent_info> infos;
    std::vector<double> step_ms;  // the timed steps
    long arrivals = 0, failures = 0, refused = 0;
    long kinds[8] = {};    // timed events by kind
    long reasons[8] = {};  // timed replans by reason

    NavLinkSide() = default;
    NavLinkSide(const NavLinkSide&) = delete;
    NavLinkSide& operator=(const NavLinkSide&) = delete;
    ~NavLinkSide() { nl_world_destroy(world); }

    bool setup(const nl::bench::RecastLevel& level, int workers, int count, const nl::bench::Destinations& where,
               uint32_t paths_per_step) {
        nl_world_def def = nl_default_world_def();
        def.worker_count = workers;
        def.path_worker_count = 0;
        if (paths_per_step > 0) def.agent_paths_per_step = paths_per_step;
        if (NL_FAILED(nl_world_create(&def, &world))) return fail(level.name, "nl_world_create");
        uint32_t polygons = 0;
        if (!nl::bench::add_navlink_navmesh(world, level, &navmesh, &polygons)) return false;
        ids.resize(count);
        trips.assign(count, 1);
        for (int i = 0; i < count; ++i) {
            nl_agent_def agent = nl_default_agent_def();
            agent.navmesh = navmesh;
            agent.height = level.agent.height;
            agent.capabilities.radius = level.agent.radius;
            agent.user_data = uint64_t(i);
            where.point(uint32_t(i), 0, agent.position);
            if (NL_FAILED(nl_agent_add(world, &agent, &ids[i]))) return fail(level.name, "nl_agent_add");
            send(uint32_t(i), where);
        }
        return true;
    }

    // Sends agent i to its next destination (one off the navmesh, which cannot happen with points
    // drawn on it, is counted and skipped).
    void send(uint32_t i, const nl::bench::Destinations& where) {
        for (int attempt = 0; attempt < 4; ++attempt) {
            float goal[3];
            where.point(i, trips[i]++, goal);
            if (NL_SUCCEEDED(nl_agent_set_destination(world, ids[i], goal))) return;
            ++refused;
        }
    }

    void step(float dt, bool timed, const nl::bench::Destinations& where) {
        const double t0 = nl::samples::now_ms();
        nl_world_step(world, dt);
        const double t1 = nl::samples::now_ms();
        if (timed) step_ms.push_back(t1 - t0);
        uint32_t count = 0;
        nl_world_get_agent_events(world, nullptr, 0, &count);
        events.assign(count, nl_agent_event_init());
        if (count > 0) nl_world_get_agent_events(world, events.data(), count, &count);
        for (const nl_agent_event& e : events) {
            if (timed && e.kind < 8) ++kinds[e.kind];
            if (timed && e.kind == NL_AGENT_EVENT_REPLANNED && e.reason < 8) ++reasons[e.reason];
            if (e.kind != NL_AGENT_EVENT_ARRIVED && e.kind != NL_AGENT_EVENT_FAILED) continue;
            if (timed) (e.kind == NL_AGENT_EVENT_ARRIVED ? arrivals : failures) += 1;
            send(uint32_t(e.user_data), where);
        }
    }

    void read_infos() {
        uint32_t count = 0;
        nl_world_get_agents(world, nullptr, 0, &count);
        infos.assign(count, nl_agent_info_init());
        nl_world_get_agents(world, infos.data(), count, &count);
    }
    long waiting() const {
        return std::count_if(infos.begin(), infos.end(),
                             [](const nl_agent_info& a) { return a.state == NL_AGENT_WAITING; });
    }
    long moving() const {
        return std::count_if(infos.begin(), infos.end(), [](const nl_agent_info& a) {
            return std::hypot(a.velocity[0], a.velocity[2]) > kMovingSpeed;
        });
    }
};

bool same_agents(const NavLinkSide& a, const NavLinkSide& b) {
    if (a.infos.size() != b.infos.size()) return false;
    for (size_t i = 0; i < a.infos.size(); ++i) {
        const nl_agent_info &x = a.infos[i], &y = b.infos[i];
        if (std::memcmp(x.position, y.position, sizeof x.position) != 0 ||
            std::memcmp(x.velocity, y.velocity, sizeof x.velocity) != 0 || x.state != y.state)
            return false;
    }
    return true;
}

struct DetourCrowdSide {
    const nl::bench::DetourMesh* mesh = nullptr;
    dtCrowd* crowd = dtAllocCrowd();
    std::vector<uint32_t> trips;
    std::vector<double> step_ms;  // the timed steps
    long arrivals = 0, refused = 0;

    DetourCrowdSide() = default;
    DetourCrowdSide(const DetourCrowdSide&) = delete;
    DetourCrowdSide& operator=(const DetourCrowdSide&) = delete;
    ~DetourCrowdSide() { dtFreeCrowd(crowd); }

    bool setup(const nl::bench::RecastLevel& level, const nl::bench::DetourMesh& detour, int count,
               const nl::bench::Destinations& where) {
        mesh = &detour;
        if (!crowd || !crowd->init(count, level.agent.radius, detour.mesh)) return fail(level.name, "dtCrowd::init");
        const dtCrowdAgentParams params = nl::bench::detour_crowd_agent(level);
        trips.assign(count, 1);
        const dtQueryFilter filter;
        for (int i = 0; i < count; ++i) {
            float start[3], nearest[3];
            dtPolyRef ref = 0;
            where.point(uint32_t(i), 0, start);
            mesh->query->findNearestPoly(start, kHalfExtents, &filter, &ref, nearest);
            if (!ref || crowd->addAgent(nearest, &params) != i) {
                std::fprintf(stderr, "navlink-bench-agents: %s: dtCrowd::addAgent failed\n", level.name.c_str());
                return false;
            }
            send(uint32_t(i), where);
        }
        return true;
    }

    void send(uint32_t i, const nl::bench::Destinations& where) {
        const dtQueryFilter filter;
        for (int attempt = 0; attempt < 4; ++attempt) {
            float goal[3], nearest[3];
            dtPolyRef ref = 0;
            where.point(i, trips[i]++, goal);
            mesh->query->findNearestPoly(goal, kHalfExtents, &filter, &ref, nearest);
            if (ref && crowd->requestMoveTarget(int(i), ref, nearest)) return;
            ++refused;
        }
    }

    void step(float dt, bool timed, const nl::bench::Destinations& where) {
        const double t0 = nl::samples::now_ms();
        crowd->update(dt, nullptr);
        const double t1 = nl::samples::now_ms();
        if (timed) step_ms.push_back(t1 - t0);
        for (int i = 0; i < crowd->getAgentCount(); ++i) {
            const dtCrowdAgent* ag = crowd->getAgent(i);
            if (!ag->active || ag->targetState != DT_CROWDAGENT_TARGET_VALID) continue;
            if (dtVdist2DSqr(ag->npos, ag->targetPos) > kDetourArrive * kDetourArrive) continue;
            if (timed) ++arrivals;
            send(uint32_t(i), where);
        }
    }

    long waiting() const {
        long n = 0;
        for (int i = 0; i < crowd->getAgentCount(); ++i) {
            const int s = crowd->getAgent(i)->targetState;
            n += s == DT_CROWDAGENT_TARGET_REQUESTING || s == DT_CROWDAGENT_TARGET_WAITING_FOR_QUEUE ||
                 s == DT_CROWDAGENT_TARGET_WAITING_FOR_PATH;
        }
        return n;
    }
    long moving() const {
        long n = 0;
        for (int i = 0; i < crowd->getAgentCount(); ++i) n += dtVlen(crowd->getAgent(i)->vel) > kMovingSpeed;
        return n;
    }
};

double mean(const std::vector<double>& values) {
    double total = 0.0;
    for (const double v : values) total += v;
    return values.empty() ? std::nan("") : total / values.size();
}

std::string figure(double value, const char* format = "%.2f") {
    if (!(value == value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

bool run(nl::bench::RecastLevel& level, uint32_t seed, const Options& options) {
    nl::bench::DetourMesh detour;
    if (!nl::bench::build_detour(level, detour)) {
        std::fprintf(stderr, "navlink-bench-agents: %s: Detour could not build its navmesh\n", level.name.c_str());
        return false;
    }
    nl::bench::Destinations where;
    where.pm = level.solo.polygons.get();
    where.polygons = nl::bench::largest_connected_polygons(*level.solo.polygons);
    where.seed = seed;
    for (const int count : options.counts) {
        NavLinkSide nl1, nl2;
        DetourCrowdSide dc;
        if (options.nl1 && !nl1.setup(level, 1, count, where, options.paths_per_step)) return false;
        if (options.nl2 && !nl2.setup(level, 2, count, where, options.paths_per_step)) return false;
        if (options.dcrowd && !dc.setup(level, detour, count, where)) return false;
        const int total = options.warm + options.steps;
        for (int s = 0; s < total; ++s) {
            const bool timed = s >= options.warm;
            for (int turn = 0; turn < 3; ++turn) {
                switch ((s + turn) % 3) {
                    case 0:
                        if (options.nl1) nl1.step(options.dt, timed, where);
                        break;
                    case 1:
                        if (options.nl2) nl2.step(options.dt, timed, where);
                        break;
                    default:
                        if (options.dcrowd) dc.step(options.dt, timed, where);
                        break;
                }
            }
        }
        if (options.nl1) nl1.read_infos();
        if (options.nl2) nl2.read_infos();
        const double nan = std::nan("");
        const double us1 = options.nl1 ? median(nl1.step_ms) * 1000.0 / count : nan;
        const double us2 = options.nl2 ? median(nl2.step_ms) * 1000.0 / count : nan;
        const double usd = options.dcrowd ? median(dc.step_ms) * 1000.0 / count : nan;
        const NavLinkSide& nl = options.nl1 ? nl1 : nl2;
        const bool any_nl = options.nl1 || options.nl2;
        std::printf(
            "%-18s %6d %6d %9s %9s %9s %7s %7s %7s %7s %6s %6s %6s %6s %6s %6s %7s %6s %5s\n", level.name.c_str(),
            level.solo.polygons->npolys, count, figure(us1).c_str(), figure(us2).c_str(), figure(usd).c_str(),
            figure(usd / us1).c_str(), figure(usd / us2).c_str(), figure(us1 / us2).c_str(),
            any_nl ? std::to_string(nl.arrivals).c_str() : "-",
            options.dcrowd ? std::to_string(dc.arrivals).c_str() : "-",
            any_nl ? std::to_string(nl.failures).c_str() : "-", any_nl ? std::to_string(nl.waiting()).c_str() : "-",
            options.dcrowd ? std::to_string(dc.waiting()).c_str() : "-",
            any_nl ? std::to_string(nl.moving()).c_str() : "-",
            options.dcrowd ? std::to_string(dc.moving()).c_str() : "-", figure(where.area(), "%.0f").c_str(),
            figure(100.0 * count * M_PI * level.agent.radius * level.agent.radius / where.area(), "%.0f%%").c_str(),
            options.nl1 && options.nl2 ? (same_agents(nl1, nl2) && nl1.arrivals == nl2.arrivals ? "yes" : "NO") : "-");
        std::fflush(stdout);
        if (options.verbose && any_nl)
            std::fprintf(
                stderr,
                "  NavLink events (timed): path_ready=%ld link_started=%ld arrived=%ld failed=%ld replanned=%ld "
                "(link_gone=%ld world_changed=%ld off_path=%ld)\n",
                nl.kinds[NL_AGENT_EVENT_PATH_READY], nl.kinds[NL_AGENT_EVENT_LINK_STARTED],
                nl.kinds[NL_AGENT_EVENT_ARRIVED], nl.kinds[NL_AGENT_EVENT_FAILED], nl.kinds[NL_AGENT_EVENT_REPLANNED],
                nl.reasons[NL_AGENT_REASON_LINK_GONE], nl.reasons[NL_AGENT_REASON_WORLD_CHANGED],
                nl.reasons[NL_AGENT_REASON_OFF_PATH]);
        if (options.verbose) {
            const double nl1_mean = options.nl1 ? mean(nl1.step_ms) * 1000.0 / count : nan;
            const double nl2_mean = options.nl2 ? mean(nl2.step_ms) * 1000.0 / count : nan;
            const double dc_mean = options.dcrowd ? mean(dc.step_ms) * 1000.0 / count : nan;
            std::fprintf(stderr,
                         "  means over the timed steps (us per agent-step): NavLink 1t %s, 2t %s, DetourCrowd %s\n",
                         figure(nl1_mean).c_str(), figure(nl2_mean).c_str(), figure(dc_mean).c_str());
            double nl_speed = 0, nl_left = 0, dc_speed = 0, dc_left = 0;
            for (const nl_agent_info& a : nl.infos) {
                nl_speed += std::hypot(a.velocity[0], a.velocity[2]);
                nl_left += std::hypot(a.position[0] - a.destination[0], a.position[2] - a.destination[2]);
            }
            for (int i = 0; options.dcrowd && i < count; ++i) {
                const dtCrowdAgent* ag = dc.crowd->getAgent(i);
                dc_speed += dtVlen(ag->vel);
                dc_left += std::sqrt(dtVdist2DSqr(ag->npos, ag->targetPos));
            }
            if (any_nl)
                std::fprintf(stderr, "  at the end, NavLink: mean speed %.2f m/s, mean distance left %.1f m\n",
                             nl_speed / count, nl_left / count);
            if (options.dcrowd)
                std::fprintf(stderr, "  at the end, DetourCrowd: mean speed %.2f m/s, mean distance left %.1f m\n",
                             dc_speed / count, dc_left / count);
        }
        if (nl.refused + dc.refused > 0)
            std::fprintf(stderr, "navlink-bench-agents: %s: destinations refused: NavLink %ld, Detour %ld\n",
                         level.name.c_str(), nl.refused, dc.refused);
    }
    return true;
}

int usage() {
    std::fprintf(stderr,
                 "usage: navlink-bench-agents [--agents N,N,...] [--warm STEPS] [--steps STEPS] [--dt SECONDS]\n"
                 "                            [--only nl1|nl2|dcrowd] [--paths-per-step N] [--verbose]\n"
                 "                            [--field N] [LEVEL.obj...]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    std::vector<std::string> objs;
    std::vector<int> fields;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto number = [&](long lo, long hi, long& out) {
            if (i + 1 >= argc) return false;
            char* end = nullptr;
            out = std::strtol(argv[++i], &end, 10);
            return *end == '\0' && out >= lo && out <= hi;
        };
        long n = 0;
        if (arg == "--field") {
            if (!number(1, 1000, n)) return usage();
            fields.push_back(int(n));
        } else if (arg == "--warm") {
            if (!number(0, 1000000, n)) return usage();
            options.warm = int(n);
        } else if (arg == "--steps") {
            if (!number(1, 1000000, n)) return usage();
            options.steps = int(n);
        } else if (arg == "--dt") {
            if (i + 1 >= argc) return usage();
            options.dt = std::strtof(argv[++i], nullptr);
            if (!(options.dt > 0.0f && options.dt <= 1.0f)) return usage();
        } else if (arg == "--agents") {
            if (i + 1 >= argc) return usage();
            options.counts.clear();
            std::stringstream list(argv[++i]);
            std::string item;
            while (std::getline(list, item, ',')) {
                const long count = std::strtol(item.c_str(), nullptr, 10);
                if (count < 1 || count > 60000) return usage();  // dtCrowd's proximity grid holds 16-bit ids
                options.counts.push_back(int(count));
            }
            if (options.counts.empty()) return usage();
        } else if (arg == "--paths-per-step") {
            if (!number(1, 1000000, n)) return usage();
            options.paths_per_step = uint32_t(n);
        } else if (arg == "--verbose") {
            options.verbose = true;
        } else if (arg == "--only") {
            if (i + 1 >= argc) return usage();
            const std::string side = argv[++i];
            options.nl1 = side == "nl1";
            options.nl2 = side == "nl2";
            options.dcrowd = side == "dcrowd";
            if (!options.nl1 && !options.nl2 && !options.dcrowd) return usage();
        } else if (!arg.empty() && arg[0] == '-') {
            return usage();
        } else {
            objs.push_back(arg);
        }
    }
    if (objs.empty() && fields.empty()) return usage();
    std::printf(
        "# steps=%d (after %d untimed) dt=%.3f; *_us: microseconds per agent-step; dc/nlN: DetourCrowd's time over "
        "NavLink's on N threads\n",
        options.steps, options.warm, options.dt);
    std::printf("%-18s %6s %6s %9s %9s %9s %7s %7s %7s %7s %6s %6s %6s %6s %6s %6s %7s %6s %5s\n", "level", "polys",
                "agents", "nl_1t_us", "nl_2t_us", "dcrowd_us", "dc/nl1", "dc/nl2", "nl1/nl2", "arr_nl", "arr_dc",
                "fail", "wait_nl", "wait_dc", "mov_nl", "mov_dc", "area", "fill", "same");
    bool ok = true;
    uint32_t seed = 1;
    for (const std::string& path : objs) {
        try {
            nl::bench::RecastLevel level = nl::bench::build_recast_level_from_obj(path.c_str());
            ok = run(level, seed++, options) && ok;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-agents: %s: %s\n", path.c_str(), e.what());
            ok = false;
        }
    }
    for (const int blocks : fields) {
        try {
            const nl::levelgen::GeneratedLevel generated = nl::levelgen::generate_large_level(1, uint32_t(blocks));
            nl::bench::RecastLevel level = nl::bench::build_recast_level("large-" + std::to_string(blocks),
                                                                         generated.positions, generated.indices);
            ok = run(level, seed++, options) && ok;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-agents: large-%d: %s\n", blocks, e.what());
            ok = false;
        }
    }
    return ok ? 0 : 1;
}
