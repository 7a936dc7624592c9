// navlink-surfaces-soak: agents riding three moving surfaces (a shuttle sliding to and fro as it
// rolls, a turning disc, a lift going up and down) and walking a static floor, while four threads
// plan paths on the moving navmeshes (nl_path_find, and nl_path_request planned by the path workers)
// and read agents' corners and locate points beside them, a host thread moves the three surfaces
// without pause (nl_mesh_set_transform) and the main thread steps the world and reads every agent.
// Built and run under ThreadSanitizer by the test command.
//
// The shuttle's navmesh is built by Recast on it (nl_navmesh_build with def.surface), the disc's and
// the lift's are handed over in their own space (nl_navmesh_add with def.surface). It fails when a
// call returns a status its documentation does not allow; when an agent on a surface is off its
// navmesh there (its carrier_position lies outside the navmesh's box in the surface's space by more
// than 5 cm: the box of a flat navmesh is its plane too), or its world position is not that point
// moved by the surface's pose of one of the moves the mover made during the read; when a path on a
// moving navmesh has a carrier_position outside that box, or world points that are not its surface
// points moved by one rigid transform (the distances between consecutive points differ); when an
// agent's corner read meanwhile is off its navmesh's box; when a queued request finishes other than
// exactly once; or when a thread stops making progress for `--stall` seconds (the process aborts,
// so the sanitizer or a debugger shows every thread).
//
//   navlink-surfaces-soak [--seconds S] [--agents N] [--workers N] [--stall S]
//
// --agents: agents on each surface and on the floor (40). It prints what it did and checked.
#include <navlink/navlink.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cell_navmesh.h"
#include "generated_level_c.h"
#include "level_generator.h"
#include "rigid_pose.h"
#include "soak_checks.h"

namespace {

using Clock = std::chrono::steady_clock;
using nl::test::RigidPose;

nl::test::SoakFailures soak("navlink-surfaces-soak");

void fail(const std::string& what) { soak.fail(what); }
bool expect(nl_status status, const char* call, std::initializer_list<nl_status> allowed = {}) {
    return soak.expect(status, call, allowed);
}
using Worker = nl::test::SoakWorker;

constexpr float kRadius = 0.3f;
constexpr float kGive = 0.05f;  // m off the navmesh's box that still counts as on it (rounding, detail heights)
constexpr int kSurfaces = 3;    // the moving ones; the floor is number kSurfaces
const char* const kNames[kSurfaces + 1] = {"shuttle", "disc", "lift", "floor"};

struct Options {
    double seconds = 20;
    uint32_t agents = 40;
    int32_t workers = 2;
    double stall = 60;
};

float random_in(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// Where moving surface `s` is `t` seconds in, computed from t alone (never accumulated).
RigidPose pose_at(int s, double t) {
    if (s == 0)
        return RigidPose::at(float(20.0 + 10.0 * std::sin(0.5 * t)), 3.0f, -20.0f, 0.0f,
                             float(0.04 * std::sin(1.3 * t)));
    if (s == 1) return RigidPose::at(0.0f, 1.5f, 20.0f, float(std::fmod(0.8 * t, 2.0 * M_PI)));
    return RigidPose::at(-25.0f, float(1.0 + 3.0 * (1.0 - std::cos(0.9 * t))), 0.0f, 0.0f);
}

struct Soak {
    nl_world* world = nullptr;
    nl_mesh_id meshes[kSurfaces]{};
    nl_navmesh_id navmeshes[kSurfaces + 1]{};
    float box_min[kSurfaces + 1][3]{}, box_max[kSurfaces + 1][3]{};  // each navmesh's, in its own space
    std::vector<nl_agent_id> agents;                                 // never removed: the path threads read them
    std::vector<int> agent_surfaces;
    std::atomic<bool> stop{false};
    Clock::time_point start = Clock::now();
    // The mover's numbered moves: move m put every surface at pose_at(k, times[m % kHistory]); the
    // number is published before the move is made, so a reader that saw m before reading agents saw
    // move m - 1 made whole, and none after the number it sees next.
    static constexpr uint64_t kHistory = 4096;
    std::atomic<uint64_t> moves_published{0};
    std::array<std::atomic<double>, kHistory> times{};

    double seconds() const { return std::chrono::duration<double>(Clock::now() - start).count(); }

    // The surface's transform now (the identity for the floor).
    RigidPose pose(int s) const {
        if (s == kSurfaces) return RigidPose{};
        nl_mesh_info info{};
        info.size = sizeof info;
        expect(nl_mesh_get_info(world, meshes[s], &info), "nl_mesh_get_info");
        return RigidPose::of(info.transform);
    }
    // Inside the navmesh's box, in its own space, give included.
    bool inside(int s, const float* local) const {
        for (int k = 0; k < 3; ++k)
            if (!(local[k] >= box_min[s][k] - kGive && local[k] <= box_max[s][k] + kGive)) return false;
        return true;
    }
    // A random point of the navmesh's box at its floor, in the world where the surface is now (it may
    // fall off the disc, or the surface may move on before it is located: NOT_FOUND).
    std::array<float, 3> somewhere(int s, std::mt19937& rng) const {
        const float local[3] = {random_in(rng, box_min[s][0] + 0.3f, box_max[s][0] - 0.3f), box_min[s][1],
                                random_in(rng, box_min[s][2] + 0.3f, box_max[s][2] - 0.3f)};
        std::array<float, 3> world_point;
        pose(s).to_world(local, world_point.data());
        return world_point;
    }
};

// A disc of `sides` sides, its top at y = 0 (a fan facing up), 0.5 m thick.
nl::levelgen::GeneratedLevel disc_mesh(float radius, uint32_t sides) {
    nl::levelgen::GeneratedLevel level;
    level.positions = {0, 0, 0, 0, -0.5f, 0};
    for (uint32_t k = 0; k < sides; ++k) {
        const float a = float(2.0 * M_PI * k / sides);
        level.positions.insert(level.positions.end(), {radius * std::cos(a), 0, radius * std::sin(a)});
        level.positions.insert(level.positions.end(), {radius * std::cos(a), -0.5f, radius * std::sin(a)});
    }
    for (uint32_t k = 0; k < sides; ++k) {
        const uint32_t top = 2 + 2 * k, bottom = top + 1, next_top = 2 + 2 * ((k + 1) % sides),
                       next_bottom = next_top + 1;
        level.indices.insert(level.indices.end(), {0, next_top, top, 1, bottom, next_bottom});
        level.indices.insert(level.indices.end(), {top, next_top, next_bottom, top, next_bottom, bottom});
    }
    return level;
}

bool add_mesh(Soak& s, const nl::levelgen::GeneratedLevel& level, uint32_t flags, nl_mesh_id* out) {
    return expect(nl::test::add_generated_level(s.world, level, flags, nullptr, out), "nl_mesh_add");
}

// The floor and the shuttle built by Recast, the disc's fan and the lift's cells handed over, each
// surface at the identity meanwhile, so that each navmesh's box in the world is its box in its space.
bool set_up(Soak& s, const Options& o) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = o.workers;
    def.path_worker_count = 2;
    if (!expect(nl_world_create(&def, &s.world), "nl_world_create")) return false;
    nl::levelgen::GeneratedLevel floor, shuttle, lift;
    floor.add_box({{-40, -1, -40}, {40, 0, 40}});
    shuttle.add_box({{-8, -0.5f, -3}, {8, 0, 3}});
    lift.add_box({{0, -0.5f, 0}, {6, 0, 6}});
    nl_mesh_id floor_mesh{};
    if (!add_mesh(s, floor, 0, &floor_mesh) || !add_mesh(s, shuttle, NL_MESH_MOVABLE, &s.meshes[0]) ||
        !add_mesh(s, disc_mesh(6.0f, 24), NL_MESH_MOVABLE, &s.meshes[1]) ||
        !add_mesh(s, lift, NL_MESH_MOVABLE, &s.meshes[2]))
        return false;

    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.agent_type.radius = kRadius;
    if (!expect(nl_navmesh_build(s.world, &build, &s.navmeshes[kSurfaces]), "nl_navmesh_build (floor)")) return false;
    build.carrier = s.meshes[0];
    if (!expect(nl_navmesh_build(s.world, &build, &s.navmeshes[0]), "nl_navmesh_build (shuttle)")) return false;

    std::vector<float> fan = {0, 0, 0};
    std::vector<uint32_t> corners;
    const uint32_t sides = 24;
    for (uint32_t k = 0; k < sides; ++k) {
        const float a = float(2.0 * M_PI * k / sides), rim = 6.0f - kRadius;
        fan.insert(fan.end(), {rim * std::cos(a), 0, rim * std::sin(a)});
        corners.insert(corners.end(), {0, 1 + (k + 1) % sides, 1 + k});  // counter-clockwise seen from above
    }
    nl_navmesh_def disc = nl_default_navmesh_def();
    disc.vertices = fan.data();
    disc.vertex_count = uint32_t(fan.size() / 3);
    disc.indices = corners.data();
    disc.polygon_count = sides;
    disc.agent_type.radius = kRadius;
    disc.carrier = s.meshes[1];
    if (!expect(nl_navmesh_add(s.world, &disc, &s.navmeshes[1]), "nl_navmesh_add (disc)")) return false;
    nl::test::CellNavmesh cells(std::vector<std::string>(6, std::string(6, '.')), kRadius);
    cells.def.carrier = s.meshes[2];
    if (!expect(nl_navmesh_add(s.world, &cells.def, &s.navmeshes[2]), "nl_navmesh_add (lift)")) return false;

    for (int k = 0; k <= kSurfaces; ++k) {
        nl_navmesh_info info{};
        info.size = sizeof info;
        if (!expect(nl_navmesh_get_info(s.world, s.navmeshes[k], &info), "nl_navmesh_get_info")) return false;
        std::memcpy(s.box_min[k], info.bounds_min, sizeof info.bounds_min);
        std::memcpy(s.box_max[k], info.bounds_max, sizeof info.bounds_max);
    }
    for (int k = 0; k < kSurfaces; ++k)
        if (!expect(nl_mesh_set_transform(s.world, s.meshes[k], pose_at(k, 0.0).m), "nl_mesh_set_transform"))
            return false;
    return true;
}

void send_somewhere(Soak& s, std::mt19937& rng, nl_agent_id agent, int surface) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        const std::array<float, 3> to = s.somewhere(surface, rng);
        const nl_status status = nl_agent_set_destination(s.world, agent, to.data());
        if (status != (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND)) {
            expect(status, "nl_agent_set_destination");
            return;
        }
    }
}

// The host's physics thread: every surface moved to where it is now, again and again.
void move_surfaces(Soak& s, Worker& me, std::atomic<uint64_t>& moves) {
    while (!s.stop) {
        const double t = s.seconds();
        const uint64_t m = s.moves_published.load() + 1;
        s.times[m % Soak::kHistory].store(t);
        s.moves_published.store(m);
        for (int k = 0; k < kSurfaces; ++k) {
            me.doing = kNames[k];
            expect(nl_mesh_set_transform(s.world, s.meshes[k], pose_at(k, t).m), "nl_mesh_set_transform");
        }
        moves += kSurfaces;
        ++me.steps;
        // A pause now and then, so the stepping thread sees the surfaces still across its reads.
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
}

struct PathTally {
    std::atomic<uint64_t> found{0}, queued{0}, checked{0}, off{0}, corners{0};
};

float distance(const float* a, const float* b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// A path's points on surface s: each carrier_position within its navmesh's box, and the world points
// the surface points moved by one rigid transform (consecutive distances the same in both).
void check_path(const Soak& s, int surface, const nl_path_result& result, const std::vector<nl_path_point>& points,
                uint32_t count, PathTally& tally) {
    if (result.outcome == NL_PATH_START_OFF_NAVMESH || result.outcome == NL_PATH_GOAL_OFF_NAVMESH) {
        ++tally.off;  // the surface moved on between the ends' choice and the search
        return;
    }
    if (result.outcome != NL_PATH_COMPLETE && result.outcome != NL_PATH_PARTIAL) {
        fail(std::string("a path on the ") + kNames[surface] + " ended with outcome " + std::to_string(result.outcome));
        return;
    }
    if (count != result.point_count || count == 0) fail("a path's point count is " + std::to_string(count));
    for (uint32_t k = 0; k < count; ++k) {
        const nl_path_point& p = points[k];
        if (!s.inside(surface, p.carrier_position))
            fail(std::string("a path point on the ") + kNames[surface] + " is outside its navmesh in its space: (" +
                 std::to_string(p.carrier_position[0]) + ", " + std::to_string(p.carrier_position[1]) + ", " +
                 std::to_string(p.carrier_position[2]) + ")");
        if (k == 0) continue;
        const nl_path_point& q = points[k - 1];
        const float in_world = distance(p.position, q.position),
                    on_surface = distance(p.carrier_position, q.carrier_position);
        if (std::fabs(in_world - on_surface) > 1e-3f)
            fail(std::string("a path on the ") + kNames[surface] + " has a segment of " + std::to_string(on_surface) +
                 " m on the surface and " + std::to_string(in_world) + " m in the world");
    }
    ++tally.checked;
}

struct Completion {
    std::atomic<int> calls{0};
    nl_path_ticket ticket{};
    int surface = 0;
};

void on_done(void* user, nl_path_ticket, nl_path_outcome) { static_cast<Completion*>(user)->calls.fetch_add(1); }

// Waits for a queued request, checks its path and that it called back once, and releases it.
void retire(Soak& s, Worker& me, Completion& c, std::vector<nl_path_point>& points, PathTally& tally) {
    me.doing = "nl_path_poll (waiting for a queued request)";
    nl_path_outcome outcome = NL_PATH_PENDING;
    while (expect(nl_path_poll(s.world, c.ticket, &outcome), "nl_path_poll") && outcome == NL_PATH_PENDING)
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    // The outcome can be seen a moment before the callback has run.
    while (c.calls.load() == 0) std::this_thread::yield();
    if (c.calls.load() != 1) fail("a request called back " + std::to_string(c.calls.load()) + " times");
    me.doing = "nl_path_get_result";
    nl_path_result result = nl_path_result_init();
    uint32_t count = 0;
    if (expect(nl_path_get_result(s.world, c.ticket, &result, points.data(), uint32_t(points.size()), &count),
               "nl_path_get_result", {NL_STATUS_BUFFER_TOO_SMALL}))
        check_path(s, c.surface, result, points, count, tally);
    expect(nl_path_release(s.world, c.ticket), "nl_path_release");
}

// What a host's other threads read meanwhile: a random agent's corners (each within its navmesh's box,
// in its space) and the navmesh points of a path's ends, located where the surface is now.
void read_beside(Soak& s, Worker& me, std::mt19937& rng, const nl_path_request_def& def, int surface,
                 std::vector<nl_path_point>& points, PathTally& tally) {
    me.doing = "nl_agent_get_corners";
    const size_t k = s.agents.empty() ? 0 : rng() % s.agents.size();
    uint32_t count = 0;
    if (!s.agents.empty() &&
        expect(nl_agent_get_corners(s.world, s.agents[k], points.data(), uint32_t(points.size()), &count),
               "nl_agent_get_corners", {NL_STATUS_BUFFER_TOO_SMALL})) {
        for (uint32_t c = 0; c < count; ++c)
            if (!s.inside(s.agent_surfaces[k], points[c].carrier_position))
                fail(std::string("a corner of an agent on the ") + kNames[s.agent_surfaces[k]] + " is off its navmesh");
        tally.corners += count;
    }
    me.doing = "nl_navmesh_find_nearest";
    const float ends[6] = {def.start[0], def.start[1], def.start[2], def.goal[0], def.goal[1], def.goal[2]};
    nl_nav_point found[2];
    expect(nl_navmesh_find_nearest(s.world, s.navmeshes[surface], ends, 2, def.search_half_extents, found),
           "nl_navmesh_find_nearest");
}

// Paths between random points of a random moving surface, given in the world where it is now:
// planned at once, or queued (eight at most waiting) for the path workers; and now and then the
// reads beside them.
void request_paths(Soak& s, Worker& me, unsigned seed, PathTally& tally) {
    std::mt19937 rng(seed);
    std::vector<nl_path_point> points(256, nl_path_point_init());
    std::deque<std::unique_ptr<Completion>> waiting;
    for (uint64_t i = 0; !s.stop; ++i) {
        const int surface = int(rng() % kSurfaces);
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = s.navmeshes[surface];
        def.capabilities.radius = kRadius;
        const std::array<float, 3> a = s.somewhere(surface, rng), b = s.somewhere(surface, rng);
        std::memcpy(def.start, a.data(), sizeof def.start);
        std::memcpy(def.goal, b.data(), sizeof def.goal);
        if (i % 2 == 0) {
            me.doing = "nl_path_find";
            nl_path_result result = nl_path_result_init();
            uint32_t count = 0;
            if (expect(nl_path_find(s.world, &def, &result, points.data(), uint32_t(points.size()), &count),
                       "nl_path_find", {NL_STATUS_BUFFER_TOO_SMALL})) {
                ++tally.found;
                check_path(s, surface, result, points, count, tally);
            }
        } else {
            me.doing = "nl_path_request";
            auto c = std::make_unique<Completion>();
            c->surface = surface;
            def.callback = on_done;
            def.user = c.get();
            if (expect(nl_path_request(s.world, &def, &c->ticket), "nl_path_request")) {
                ++tally.queued;
                waiting.push_back(std::move(c));
            }
            if (waiting.size() > 8) {
                retire(s, me, *waiting.front(), points, tally);
                waiting.pop_front();
            }
        }
        if (i % 8 == 7) read_beside(s, me, rng, def, surface, points, tally);
        ++me.steps;
    }
    for (const auto& c : waiting) retire(s, me, *c, points, tally);
}

struct AgentTally {
    uint64_t steps = 0, checked = 0, placed = 0, arrivals = 0, failures = 0;
};

bool finite3(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Whether `world` is `local` moved by surface s's pose of one of the mover's moves first..last.
bool placed_by_a_move(const Soak& soak, int s, const float* world, const float* local, uint64_t first, uint64_t last) {
    constexpr float kRounding = 2e-3f;  // m: float rounding of a transform at tens of metres
    for (uint64_t m = first; m <= last; ++m) {
        float moved[3];
        pose_at(s, soak.times[m % Soak::kHistory].load()).to_world(local, moved);
        if (distance(moved, world) <= kRounding) return true;
    }
    return false;
}

// The game's main loop: a step, the events, then every agent read and checked against where its
// surface is, the surfaces' transforms read just before and after the agents.
void step_agents(Soak& s, Worker& me, const Options& o, AgentTally& tally) {
    std::mt19937 rng(31);
    std::vector<nl_agent_event> events;
    std::vector<nl_agent_info> infos;
    while (s.seconds() < o.seconds && soak.count() == 0) {
        me.doing = "nl_world_step";
        expect(nl_world_step(s.world, 1.0f / 60.0f), "nl_world_step");
        me.doing = "nl_world_get_agent_events";
        uint32_t count = 0;
        expect(nl_world_get_agent_events(s.world, nullptr, 0, &count), "nl_world_get_agent_events (count)");
        events.assign(count, nl_agent_event_init());
        if (count &&
            expect(nl_world_get_agent_events(s.world, events.data(), count, &count), "nl_world_get_agent_events")) {
            for (const nl_agent_event& e : events) {
                if (e.kind == NL_AGENT_EVENT_ARRIVED) ++tally.arrivals;
                if (e.kind == NL_AGENT_EVENT_FAILED) ++tally.failures;
                if (e.kind == NL_AGENT_EVENT_ARRIVED || e.kind == NL_AGENT_EVENT_FAILED)
                    send_somewhere(s, rng, e.agent, int(e.user_data));
            }
        }
        me.doing = "nl_world_get_agents";
        expect(nl_world_get_agents(s.world, nullptr, 0, &count), "nl_world_get_agents (count)");
        infos.assign(count, nl_agent_info_init());
        const uint64_t before = s.moves_published.load();
        if (count) expect(nl_world_get_agents(s.world, infos.data(), count, &count), "nl_world_get_agents");
        const uint64_t after = s.moves_published.load();
        // The moves the agents may have been read at: the last made whole before, to the last begun.
        const uint64_t first = before > 0 ? before - 1 : 0;
        const bool history = after - first < Soak::kHistory / 2;  // else the ring was written over meanwhile
        for (uint32_t i = 0; i < count; ++i) {
            const nl_agent_info& a = infos[i];
            const int surface = int(a.user_data);
            if (!finite3(a.position) || !finite3(a.velocity) || !finite3(a.carrier_position))
                fail("an agent's position, surface position or velocity is not finite");
            if (a.state == NL_AGENT_IDLE) send_somewhere(s, rng, a.id, surface);
            // Where it stands in its surface's space, as the host parents it (carrier_position). Not
            // its world position taken back through nl_mesh_get_info's transform: a move publishes
            // the mesh's transform a moment before its navmeshes' (nl_mesh_set_transform), so two
            // reads of the transform that agree do not say the agents were read at that pose (this
            // check failed so under load, all 40 agents on the lift 0.063 m below it).
            if (!s.inside(surface, a.carrier_position))
                fail(std::string("an agent on the ") + kNames[surface] + " is off its navmesh there: (" +
                     std::to_string(a.carrier_position[0]) + ", " + std::to_string(a.carrier_position[1]) + ", " +
                     std::to_string(a.carrier_position[2]) + ") in its space, state " + std::to_string(a.state));
            tally.placed += surface < kSurfaces && history;
            if (surface < kSurfaces && history &&
                !placed_by_a_move(s, surface, a.position, a.carrier_position, first, after))
                fail(std::string("an agent on the ") + kNames[surface] + " at (" + std::to_string(a.position[0]) +
                     ", " + std::to_string(a.position[1]) + ", " + std::to_string(a.position[2]) +
                     ") is not its surface position moved to where the surface was during the read (moves " +
                     std::to_string(first) + " to " + std::to_string(after) + ")");
            if (surface == kSurfaces && distance(a.position, a.carrier_position) != 0.0f)
                fail("an agent on the floor, which rides nothing, has a surface position that is not its position");
            ++tally.checked;
        }
        ++tally.steps;
        ++me.steps;
    }
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string name = argv[i];
        const char* value = argv[i + 1];
        if (name == "--seconds")
            o.seconds = std::strtod(value, nullptr);
        else if (name == "--agents")
            o.agents = uint32_t(std::strtoul(value, nullptr, 10));
        else if (name == "--workers")
            o.workers = int32_t(std::strtol(value, nullptr, 10));
        else if (name == "--stall")
            o.stall = std::strtod(value, nullptr);
        else {
            std::fprintf(stderr, "usage: navlink-surfaces-soak [--seconds S] [--agents N] [--workers N] [--stall S]\n");
            std::exit(2);
        }
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    Soak s;
    if (!set_up(s, o)) return 1;
    std::mt19937 rng(30);
    for (int surface = 0; surface <= kSurfaces; ++surface) {
        uint32_t placed = 0;
        for (uint32_t attempt = 0; attempt < o.agents * 8 && placed < o.agents; ++attempt) {
            nl_agent_def def = nl_default_agent_def();
            def.navmesh = s.navmeshes[surface];
            def.capabilities.radius = kRadius;
            def.user_data = uint64_t(surface);
            const std::array<float, 3> at = s.somewhere(surface, rng);
            std::memcpy(def.position, at.data(), sizeof def.position);
            nl_agent_id id{};
            // NOT_FOUND: a point of the disc's box beyond its rim.
            if (!expect(nl_agent_add(s.world, &def, &id), "nl_agent_add", {NL_STATUS_NOT_FOUND})) continue;
            s.agents.push_back(id);
            s.agent_surfaces.push_back(surface);
            ++placed;
        }
        if (placed < o.agents)
            fail(std::string("only ") + std::to_string(placed) + " agents could be placed on the " + kNames[surface]);
    }
    std::printf(
        "navlink-surfaces-soak: %u agents on each of the shuttle, disc, lift and floor, %d workers, 2 path workers\n",
        o.agents, o.workers);

    std::atomic<uint64_t> moves{0};
    std::atomic<bool> joined{false};  // the watchdog also sees the threads finish their last requests
    PathTally paths;
    AgentTally agents;
    Worker stepper{"the stepping thread"}, mover{"the surface mover"};
    Worker requesters[4] = {{"path requester 1"}, {"path requester 2"}, {"path requester 3"}, {"path requester 4"}};
    std::thread watchdog([&] {
        nl::test::watch_workers("navlink-surfaces-soak", joined,
                                {&stepper, &mover, &requesters[0], &requesters[1], &requesters[2], &requesters[3]},
                                o.stall);
    });
    std::thread t_move(move_surfaces, std::ref(s), std::ref(mover), std::ref(moves));
    std::vector<std::thread> t_paths;
    for (unsigned k = 0; k < 4; ++k)
        t_paths.emplace_back(request_paths, std::ref(s), std::ref(requesters[k]), 40 + k, std::ref(paths));
    step_agents(s, stepper, o, agents);
    s.stop = true;
    t_move.join();
    for (std::thread& t : t_paths) t.join();
    joined = true;
    watchdog.join();

    std::printf(
        "  %llu steps in %.1f s, %llu surface moves meanwhile; %llu agents checked on their navmesh, %llu on a "
        "moving one where the surface was during the read; %llu arrivals, %llu failures\n",
        (unsigned long long)agents.steps, s.seconds(), (unsigned long long)moves.load(),
        (unsigned long long)agents.checked, (unsigned long long)agents.placed, (unsigned long long)agents.arrivals,
        (unsigned long long)agents.failures);
    std::printf(
        "  paths: %llu found at once, %llu queued, %llu checked, %llu with an end off the moved navmesh; %llu "
        "agent corners checked beside them\n",
        (unsigned long long)paths.found.load(), (unsigned long long)paths.queued.load(),
        (unsigned long long)paths.checked.load(), (unsigned long long)paths.off.load(),
        (unsigned long long)paths.corners.load());
    if (agents.steps >= 10 && o.agents > 0 && (agents.checked == 0 || agents.placed == 0))
        fail("no agent was ever checked");
    if (agents.steps >= 10 && paths.checked == 0) fail("no path on a moving navmesh was checked");
    nl_world_destroy(s.world);
    if (soak.count()) {
        std::fprintf(stderr, "navlink-surfaces-soak: %d failures\n", soak.count());
        return 1;
    }
    std::printf("navlink-surfaces-soak: passed\n");
    return 0;
}
