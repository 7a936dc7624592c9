// navlink-agents-soak: a crowd of agents stepped for thousands of steps while other threads edit the
// links under their paths, regenerate them, add, remove, teleport, stop and re-send agents, plan
// queued paths and read every agent's state. Built and run under ThreadSanitizer by the test command.
//
// The crowd walks a procedural level of 12 x 12 m blocks (platforms across gaps, terraces, pillars,
// pits), each agent a walker, a jumper or a jumper who drops, with a new random destination whenever
// it arrives or fails. It fails when a call returns a status its documentation does not allow, when
// an agent's state is impossible (a position not finite, a state or reason out of range, an event of
// an agent that does not exist), when the link edits never reached an agent (no LINK_GONE replans),
// when no agent was ever sent to the island (a second navmesh joined to the level's by cross links:
// set_destination locates such a point over the cross links of every navmesh while the link editor
// frees their snapshots), or when a thread stops making progress for `--stall` seconds (the process aborts so the sanitizer
// or a debugger shows every thread).
//
//   navlink-agents-soak [--agents N] [--steps N] [--seconds S] [--workers N] [--stall S]
//
// It stops after --steps steps or --seconds seconds, whichever comes first, and prints what it did.
#include <navlink/navlink.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "generated_level_c.h"
#include "level_generator.h"
#include "soak_checks.h"

namespace {

using Clock = std::chrono::steady_clock;

nl::test::SoakFailures soak("navlink-agents-soak");

void fail(const std::string& what) { soak.fail(what); }
bool expect(nl_status status, const char* call, std::initializer_list<nl_status> allowed = {}) {
    return soak.expect(status, call, allowed);
}
using Worker = nl::test::SoakWorker;

struct Options {
    uint32_t agents = 1000;
    uint64_t steps = 10000;
    double seconds = 60;
    int32_t workers = 2;
    double stall = 60;
};

float random_in(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// The shared setup: a world, the level's navmesh and its generated links, polygon centres to aim at.
struct Soak {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    nl_navmesh_id island{};                          // 4 x 4 m, beside the level, joined to it by two cross links
    std::array<float, 3> shore{}, island_landing{};  // the cross links' ends, on the level and the island
    std::vector<std::array<float, 3>> centres;
    std::atomic<bool> stop{false};

    // A random point near a random polygon's centre (it may fall off the navmesh: NOT_FOUND).
    std::array<float, 3> somewhere(std::mt19937& rng) const {
        std::array<float, 3> p = centres[rng() % centres.size()];
        p[0] += random_in(rng, -0.5f, 0.5f);
        p[2] += random_in(rng, -0.5f, 0.5f);
        return p;
    }
};

nl_agent_capabilities body(uint32_t kind) {
    nl_agent_capabilities c = nl_default_agent_capabilities();
    c.radius = 0.4f;
    if (kind >= 1) c.max_jump_distance = 3.5f, c.max_jump_height = 1.5f;
    if (kind >= 2) c.max_drop_height = 6.0f;
    return c;
}

bool add_agent(Soak& s, std::mt19937& rng, uint32_t kind, nl_agent_id* out) {
    nl_agent_def def = nl_default_agent_def();
    def.navmesh = s.navmesh;
    def.capabilities = body(kind);
    const std::array<float, 3> at = s.somewhere(rng);
    std::memcpy(def.position, at.data(), sizeof def.position);
    def.user_data = kind;
    def.give_up_seconds = 5.0f;  // a crowd of a thousand on a small level: some give up, and are sent on
    return expect(nl_agent_add(s.world, &def, out), "nl_agent_add", {NL_STATUS_NOT_FOUND});
}

void send_somewhere(Soak& s, std::mt19937& rng, nl_agent_id agent) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        const std::array<float, 3> to = s.somewhere(rng);
        // INVALID_HANDLE: another thread removed the agent meanwhile.
        const nl_status status = nl_agent_set_destination(s.world, agent, to.data());
        if (!NL_FAILED(status) || status != (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND)) {
            expect(status, "nl_agent_set_destination", {NL_STATUS_INVALID_HANDLE});
            return;
        }
    }
}

struct Tally {
    uint64_t agent_steps = 0, arrivals = 0, failures = 0, take_offs = 0, landings = 0, waits = 0;
    uint64_t replans[NL_AGENT_REASON_CROWD + 1] = {};
    uint64_t failed_because[NL_AGENT_REASON_CROWD + 1] = {};
};

bool finite3(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// The stepping thread, as a game's main loop: one step, then the events and every agent's state read
// back; arrived or failed agents get a new destination.
void step_crowd(Soak& s, Worker& me, const Options& o, Tally& tally, std::atomic<uint64_t>& steps_done) {
    std::mt19937 rng(21);
    std::vector<nl_agent_event> events;
    std::vector<nl_agent_info> infos;
    const Clock::time_point end =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
    for (uint64_t step = 0; step < o.steps && Clock::now() < end && soak.count() == 0; ++step) {
        me.doing = "nl_world_step";
        expect(nl_world_step(s.world, 1.0f / 30.0f), "nl_world_step");
        me.doing = "nl_world_get_agent_events";
        uint32_t count = 0;
        expect(nl_world_get_agent_events(s.world, nullptr, 0, &count), "nl_world_get_agent_events (count)");
        events.assign(count, nl_agent_event_init());
        // Other threads cannot step: the events stay until this thread's next step.
        if (count &&
            expect(nl_world_get_agent_events(s.world, events.data(), count, &count), "nl_world_get_agent_events")) {
            for (const nl_agent_event& e : events) {
                if (e.kind == NL_AGENT_EVENT_ARRIVED) ++tally.arrivals;
                if (e.kind == NL_AGENT_EVENT_FAILED)
                    ++tally.failures, ++tally.failed_because[e.reason <= NL_AGENT_REASON_CROWD ? e.reason : 0];
                if (e.kind == NL_AGENT_EVENT_LINK_STARTED) ++tally.take_offs;
                if (e.kind == NL_AGENT_EVENT_LINK_FINISHED) ++tally.landings;
                if (e.kind == NL_AGENT_EVENT_REPLANNED)
                    ++tally.replans[e.reason <= NL_AGENT_REASON_CROWD ? e.reason : 0];
                if (e.kind == NL_AGENT_EVENT_WAITING) ++tally.waits;
                if (e.kind == NL_AGENT_EVENT_WAITING && e.reason != NL_AGENT_REASON_CROWD)
                    fail("a WAITING event with reason " + std::to_string(e.reason));
                if (e.kind < NL_AGENT_EVENT_PATH_READY || e.kind > NL_AGENT_EVENT_WAITING)
                    fail("an event of kind " + std::to_string(e.kind));
                if ((e.kind == NL_AGENT_EVENT_ARRIVED || e.kind == NL_AGENT_EVENT_FAILED) &&
                    nl_agent_is_valid(s.world, e.agent))
                    send_somewhere(s, rng, e.agent);
            }
        }
        me.doing = "nl_world_get_agents";
        // The churning thread adds agents between the count and the read: read until it fits.
        nl_status status = NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
        while (status == (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL)) {
            expect(nl_world_get_agents(s.world, nullptr, 0, &count), "nl_world_get_agents (count)");
            infos.assign(count + 8, nl_agent_info_init());
            status = nl_world_get_agents(s.world, infos.data(), count + 8, &count);
        }
        if (count && expect(status, "nl_world_get_agents")) {
            tally.agent_steps += count;
            for (uint32_t k = 0; k < count; ++k) {
                const nl_agent_info& info = infos[k];
                if (!finite3(info.position) || !finite3(info.velocity))
                    fail("agent " + std::to_string(k) + " is at a position or velocity that is not finite");
                if (info.state > NL_AGENT_FAILED || info.reason > NL_AGENT_REASON_CROWD)
                    fail("agent " + std::to_string(k) + " has state " + std::to_string(info.state) + ", reason " +
                         std::to_string(info.reason));
                if (info.state == NL_AGENT_IDLE) send_somewhere(s, rng, info.id);  // a stopped one, sent again
            }
        }
        steps_done = step + 1;
        ++me.steps;
    }
}

// Generated links disabled, enabled and removed, manual links added and removed where agents walk,
// and now and then the links generated again: every kind of change an agent's path must survive.
void edit_links(Soak& s, Worker& me, std::atomic<uint64_t>& edits) {
    std::mt19937 rng(22);
    std::vector<nl_link_id> manual;
    std::vector<nl_link> links;
    for (uint64_t i = 0; !s.stop; ++i) {
        const uint32_t what = rng() % 32;
        if (what == 0) {
            me.doing = "nl_navmesh_generate_links";
            expect(nl_navmesh_generate_links(s.world, s.navmesh, nullptr, nullptr, nullptr, nullptr),
                   "nl_navmesh_generate_links");
        } else if (what < 6) {
            me.doing = "nl_link_add (manual)";
            nl_link_def def = nl_default_link_def();
            const std::array<float, 3> a = s.somewhere(rng), b = s.somewhere(rng);
            std::memcpy(def.start, a.data(), sizeof def.start);
            std::memcpy(def.end, b.data(), sizeof def.end);
            def.bidirectional = uint8_t(rng() % 2);
            nl_link_id id{};
            // Points near polygon centres can still fall beyond 1 m of the navmesh.
            if (expect(nl_link_add(s.world, s.navmesh, &def, &id), "nl_link_add", {NL_STATUS_INVALID_ARGUMENT}))
                manual.push_back(id);
        } else if (what < 10 && !manual.empty()) {
            me.doing = "nl_link_remove (manual)";
            const size_t k = rng() % manual.size();
            // INVALID_HANDLE: removed below with the generated ones it picks from the navmesh's list.
            expect(nl_link_remove(s.world, manual[k]), "nl_link_remove", {NL_STATUS_INVALID_HANDLE});
            manual.erase(manual.begin() + long(k));
        } else {
            me.doing = "nl_navmesh_get_links";
            uint32_t count = 0;
            expect(nl_navmesh_get_links(s.world, s.navmesh, nullptr, 0, &count), "nl_navmesh_get_links (count)");
            links.assign(count, nl_link_init());
            // BUFFER_TOO_SMALL: a generation added links between the two calls.
            if (!count || !expect(nl_navmesh_get_links(s.world, s.navmesh, links.data(), count, &count),
                                  "nl_navmesh_get_links", {NL_STATUS_BUFFER_TOO_SMALL}))
                continue;
            const nl_link& link = links[rng() % count];
            if (what < 26) {
                me.doing = "nl_link_update (enable or disable)";
                nl_link_def def = nl_default_link_def();
                def.kind = link.kind;
                std::memcpy(def.start, link.start, sizeof def.start);
                std::memcpy(def.end, link.end, sizeof def.end);
                def.bidirectional = link.bidirectional;
                def.enabled = uint8_t(rng() % 3 != 0);
                def.requirements_as_given = 1;
                def.requirements = link.requirements;
                def.cost_modifier = link.cost_modifier;
                def.landing_navmesh = link.landing_navmesh;  // the island's cross link stays one
                def.tolerance = link.tolerance;
                // INVALID_HANDLE: removed or regenerated since it was read.
                expect(nl_link_update(s.world, link.id, &def), "nl_link_update", {NL_STATUS_INVALID_HANDLE});
            } else {
                me.doing = "nl_link_remove (generated)";
                expect(nl_link_remove(s.world, link.id), "nl_link_remove", {NL_STATUS_INVALID_HANDLE});
            }
        }
        ++edits;
        ++me.steps;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

// The island: a square navmesh 16 to 20 m west of the level's westernmost polygon centre (the shore),
// at its height, off the level's navmesh (checked: else a destination there would never be looked for
// across), and a manual cross link each way (cross links are one-way).
bool add_island(Soak& s) {
    s.shore = s.centres.front();
    for (const auto& c : s.centres)
        if (c[0] < s.shore[0]) s.shore = c;
    const float x0 = s.shore[0] - 20.0f, x1 = s.shore[0] - 16.0f, y = s.shore[1], z0 = s.shore[2] - 2.0f,
                z1 = s.shore[2] + 2.0f;
    const float vertices[12] = {x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0};  // counter-clockwise from above
    const uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = vertices;
    def.vertex_count = 4;
    def.indices = indices;
    def.polygon_count = 2;
    def.agent_type.radius = 0.4f;
    if (!expect(nl_navmesh_add(s.world, &def, &s.island), "nl_navmesh_add (the island)")) return false;
    s.island_landing = {s.shore[0] - 16.5f, y, s.shore[2]};
    const float points[9] = {x0, y, z0, x1, y, z1, s.island_landing[0], y, s.island_landing[2]};
    const float box[3] = {1.0f, 2.0f, 1.0f};  // set_destination's reach, and more
    nl_nav_point found[3];
    if (!expect(nl_navmesh_find_nearest(s.world, s.navmesh, points, 3, box, found), "nl_navmesh_find_nearest"))
        return false;
    for (const nl_nav_point& p : found)
        if (p.found) fail("the island lies on the level's navmesh: a destination there is not looked for across");
    return true;
}

// The cross link from `from` at `a` to `to` at `b` (the editor may have removed the last one).
void join(Soak& s, nl_navmesh_id from, const std::array<float, 3>& a, nl_navmesh_id to, const std::array<float, 3>& b) {
    nl_link_def def = nl_default_link_def();
    std::memcpy(def.start, a.data(), sizeof def.start);
    std::memcpy(def.end, b.data(), sizeof def.end);
    def.landing_navmesh = to;
    def.requirements_as_given = 1;  // and asks for nothing: a ferry every body takes
    nl_link_id id{};
    expect(nl_link_add(s.world, from, &def, &id), "nl_link_add (a cross link)");
}

// Agents sent to the island and back: a destination off the agent's own navmesh, located over the
// cross links of every navmesh, while the link editor replaces the level's links (and now and then
// removes a cross link: joined again here).
void send_across(Soak& s, Worker& me, std::atomic<uint64_t>& sent) {
    std::mt19937 rng(25);
    std::vector<nl_agent_info> infos;
    while (!s.stop) {
        me.doing = "nl_world_get_agents";
        uint32_t count = 0;
        expect(nl_world_get_agents(s.world, nullptr, 0, &count), "nl_world_get_agents (count)");
        infos.assign(count + 8, nl_agent_info_init());
        if (!count || !expect(nl_world_get_agents(s.world, infos.data(), count + 8, &count), "nl_world_get_agents",
                              {NL_STATUS_BUFFER_TOO_SMALL}))
            continue;
        const nl_agent_id agent = infos[rng() % count].id;
        me.doing = "nl_agent_set_destination (on the island)";
        const std::array<float, 3> to = {s.island_landing[0] - random_in(rng, 0.5f, 3.0f), s.island_landing[1],
                                         s.island_landing[2] + random_in(rng, -1.5f, 1.5f)};
        // NOT_FOUND: the editor removed the cross link to the island (or the agent stands on the
        // island, and the way back is gone); INVALID_HANDLE: the agent was removed meanwhile.
        const nl_status status = nl_agent_set_destination(s.world, agent, to.data());
        if (expect(status, "nl_agent_set_destination (on the island)",
                   {NL_STATUS_NOT_FOUND, NL_STATUS_INVALID_HANDLE})) {
            if (NL_SUCCEEDED(status)) ++sent;
            if (status == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND)) {
                me.doing = "nl_link_add (joining the island again)";
                join(s, s.navmesh, s.shore, s.island, s.island_landing);
                join(s, s.island, s.island_landing, s.navmesh, s.shore);
            }
        }
        ++me.steps;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// Agents added and removed, stopped, teleported, re-sent, given other bodies and speeds, between steps.
void churn_agents(Soak& s, Worker& me) {
    std::mt19937 rng(23);
    std::vector<nl_agent_id> mine;
    std::vector<nl_agent_info> infos;
    for (uint64_t i = 0; !s.stop; ++i) {
        const uint32_t what = rng() % 8;
        if (what == 0 || mine.empty()) {
            me.doing = "nl_agent_add";
            nl_agent_id id{};
            if (mine.size() < 50 && add_agent(s, rng, rng() % 3, &id)) {
                mine.push_back(id);
                send_somewhere(s, rng, id);
            }
        } else if (what == 1) {
            me.doing = "nl_agent_remove";
            const size_t k = rng() % mine.size();
            expect(nl_agent_remove(s.world, mine[k]), "nl_agent_remove");
            mine.erase(mine.begin() + long(k));
        } else {
            me.doing = "nl_world_get_agents";
            uint32_t count = 0;
            expect(nl_world_get_agents(s.world, nullptr, 0, &count), "nl_world_get_agents (count)");
            infos.assign(count, nl_agent_info_init());
            // Only this thread adds agents: the count stays (removals by no one else).
            if (!count || !expect(nl_world_get_agents(s.world, infos.data(), count, &count), "nl_world_get_agents"))
                continue;
            const nl_agent_id agent = infos[rng() % count].id;
            if (what == 2) {
                me.doing = "nl_agent_stop";
                expect(nl_agent_stop(s.world, agent), "nl_agent_stop", {NL_STATUS_INVALID_HANDLE});
            } else if (what == 3) {
                me.doing = "nl_agent_teleport";
                const std::array<float, 3> to = s.somewhere(rng);
                // INVALID_ARGUMENT: it is taking a link; NOT_FOUND: off the navmesh.
                expect(nl_agent_teleport(s.world, agent, to.data()), "nl_agent_teleport",
                       {NL_STATUS_INVALID_ARGUMENT, NL_STATUS_NOT_FOUND, NL_STATUS_INVALID_HANDLE});
            } else if (what == 4) {
                me.doing = "nl_agent_set_capabilities";
                const nl_agent_capabilities c = body(rng() % 3);
                expect(nl_agent_set_capabilities(s.world, agent, &c), "nl_agent_set_capabilities",
                       {NL_STATUS_INVALID_HANDLE});
            } else if (what == 5) {
                me.doing = "nl_agent_set_speed";
                expect(nl_agent_set_speed(s.world, agent, random_in(rng, 1, 6), random_in(rng, 4, 12)),
                       "nl_agent_set_speed", {NL_STATUS_INVALID_HANDLE});
            } else {
                me.doing = "nl_agent_get_corners / trajectory / info";
                std::vector<nl_path_point> corners(64, nl_path_point_init());
                expect(nl_agent_get_corners(s.world, agent, corners.data(), 64, &count), "nl_agent_get_corners",
                       {NL_STATUS_BUFFER_TOO_SMALL, NL_STATUS_INVALID_HANDLE});
                nl_agent_trajectory trajectory = nl_agent_trajectory_init();
                expect(nl_agent_get_trajectory(s.world, agent, &trajectory), "nl_agent_get_trajectory",
                       {NL_STATUS_INVALID_HANDLE});
                if (trajectory.kind > NL_TRAJECTORY_LINE || !std::isfinite(trajectory.elapsed))
                    fail("a trajectory of kind " + std::to_string(trajectory.kind));
                nl_agent_info info = nl_agent_info_init();
                expect(nl_agent_get_info(s.world, agent, &info), "nl_agent_get_info", {NL_STATUS_INVALID_HANDLE});
            }
        }
        ++me.steps;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// Paths planned through the queue beside the agents' own, with the same links changing under them.
void request_paths(Soak& s, Worker& me) {
    std::mt19937 rng(24);
    std::vector<nl_path_point> points(512, nl_path_point_init());
    for (uint64_t i = 0; !s.stop; ++i) {
        me.doing = "nl_path_find";
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = s.navmesh;
        const std::array<float, 3> a = s.somewhere(rng), b = s.somewhere(rng);
        std::memcpy(def.start, a.data(), sizeof def.start);
        std::memcpy(def.goal, b.data(), sizeof def.goal);
        def.capabilities = body(rng() % 3);
        nl_path_result result{};
        result.size = sizeof result;
        uint32_t count = 0;
        expect(nl_path_find(s.world, &def, &result, points.data(), uint32_t(points.size()), &count), "nl_path_find",
               {NL_STATUS_BUFFER_TOO_SMALL});
        ++me.steps;
    }
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string name = argv[i];
        const char* value = argv[i + 1];
        if (name == "--agents")
            o.agents = uint32_t(std::strtoul(value, nullptr, 10));
        else if (name == "--steps")
            o.steps = std::strtoull(value, nullptr, 10);
        else if (name == "--seconds")
            o.seconds = std::strtod(value, nullptr);
        else if (name == "--workers")
            o.workers = int32_t(std::strtol(value, nullptr, 10));
        else if (name == "--stall")
            o.stall = std::strtod(value, nullptr);
        else {
            std::fprintf(stderr, "navlink-agents-soak: unknown option %s\n", name.c_str());
            std::exit(2);
        }
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    Soak s;
    nl_world_def world_def = nl_default_world_def();
    world_def.worker_count = o.workers;
    world_def.path_worker_count = 1;
    if (!expect(nl_world_create(&world_def, &s.world), "nl_world_create")) return 1;

    // 5 x 5 blocks of 12 m with coarse ground cells: room for a thousand bodies, few triangles.
    const nl::levelgen::GeneratedLevel level = nl::levelgen::generate_large_level(7, 5, 2.0f);
    expect(nl::test::add_generated_level(s.world, level), "nl_mesh_add");
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.agent_type.radius = 0.4f;
    if (!expect(nl_navmesh_build(s.world, &build, &s.navmesh), "nl_navmesh_build")) return 1;
    nl_link_generation_report report{};
    report.size = sizeof report;
    expect(nl_navmesh_generate_links(s.world, s.navmesh, nullptr, nullptr, nullptr, &report),
           "nl_navmesh_generate_links");
    nl_navmesh_info info{};
    info.size = sizeof info;
    expect(nl_navmesh_get_info(s.world, s.navmesh, &info), "nl_navmesh_get_info");
    for (uint32_t p = 0; p < info.polygon_count; ++p) {
        nl_nav_polygon polygon = nl_nav_polygon_init();
        if (expect(nl_navmesh_get_polygon(s.world, s.navmesh, p, &polygon), "nl_navmesh_get_polygon"))
            s.centres.push_back({polygon.centre[0], polygon.centre[1], polygon.centre[2]});
    }

    if (s.centres.empty() || !add_island(s)) return 1;
    join(s, s.navmesh, s.shore, s.island, s.island_landing);
    join(s, s.island, s.island_landing, s.navmesh, s.shore);

    std::mt19937 rng(20);
    for (uint32_t k = 0; k < o.agents * 4 && info.polygon_count; ++k) {
        uint32_t count = 0;
        expect(nl_world_get_agents(s.world, nullptr, 0, &count), "nl_world_get_agents (count)");
        if (count >= o.agents) break;
        nl_agent_id id{};
        if (add_agent(s, rng, k % 3, &id)) send_somewhere(s, rng, id);
    }
    uint32_t added = 0;
    expect(nl_world_get_agents(s.world, nullptr, 0, &added), "nl_world_get_agents (count)");
    std::printf("navlink-agents-soak: %u agents on %u polygons, %u jumps and %u drops, %d workers\n", added,
                info.polygon_count, report.jump_links, report.drop_links, o.workers);
    if (added < o.agents) fail("only " + std::to_string(added) + " agents could be placed");

    Tally tally;
    std::atomic<uint64_t> steps_done{0}, edits{0}, sent_across{0};
    Worker stepper{"the stepping thread"}, editor{"the link editor"}, churner{"the agent churner"},
        requester{"the path requester"}, ferryman{"the island sender"};
    const Clock::time_point start = Clock::now();
    std::thread watchdog([&] {
        nl::test::watch_workers("navlink-agents-soak", s.stop, {&stepper, &editor, &churner, &requester, &ferryman},
                                o.stall);
    });
    std::thread t_across(send_across, std::ref(s), std::ref(ferryman), std::ref(sent_across));
    std::thread t_edit(edit_links, std::ref(s), std::ref(editor), std::ref(edits));
    std::thread t_churn(churn_agents, std::ref(s), std::ref(churner));
    std::thread t_paths(request_paths, std::ref(s), std::ref(requester));
    step_crowd(s, stepper, o, tally, steps_done);
    s.stop = true;
    for (std::thread* t : {&t_edit, &t_churn, &t_paths, &t_across, &watchdog}) t->join();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

    std::printf("  %llu steps (%llu agent-steps) in %.1f s with %llu link edits meanwhile\n",
                (unsigned long long)steps_done.load(), (unsigned long long)tally.agent_steps, seconds,
                (unsigned long long)edits.load());
    std::printf(
        "  %llu arrivals, %llu failures, %llu take-offs, %llu landings; replans: %llu destination, %llu link "
        "gone, %llu world changed, %llu off path, %llu capabilities\n",
        (unsigned long long)tally.arrivals, (unsigned long long)tally.failures, (unsigned long long)tally.take_offs,
        (unsigned long long)tally.landings, (unsigned long long)tally.replans[NL_AGENT_REASON_DESTINATION_SET],
        (unsigned long long)tally.replans[NL_AGENT_REASON_LINK_GONE],
        (unsigned long long)tally.replans[NL_AGENT_REASON_WORLD_CHANGED],
        (unsigned long long)tally.replans[NL_AGENT_REASON_OFF_PATH],
        (unsigned long long)tally.replans[NL_AGENT_REASON_CAPABILITIES_CHANGED]);
    std::printf(
        "  failures: %llu no path, %llu navmesh removed, %llu given up in counterflow, %llu other; %llu waits for "
        "room\n",
        (unsigned long long)tally.failed_because[NL_AGENT_REASON_NO_PATH],
        (unsigned long long)tally.failed_because[NL_AGENT_REASON_NAVMESH_REMOVED],
        (unsigned long long)tally.failed_because[NL_AGENT_REASON_CROWD],
        (unsigned long long)(tally.failures - tally.failed_because[NL_AGENT_REASON_NO_PATH] -
                             tally.failed_because[NL_AGENT_REASON_NAVMESH_REMOVED] -
                             tally.failed_because[NL_AGENT_REASON_CROWD]),
        (unsigned long long)tally.waits);
    // A hundred steps give the crowd time to reach links the editor changes.
    if (steps_done >= 100 &&
        tally.replans[NL_AGENT_REASON_LINK_GONE] + tally.replans[NL_AGENT_REASON_WORLD_CHANGED] == 0)
        fail("the link edits never reached an agent's path");
    if (steps_done >= 100 && tally.take_offs == 0) fail("no agent took a link");
    std::printf("  %llu agents sent to the island (a destination on another navmesh, over cross links)\n",
                (unsigned long long)sent_across.load());
    if (steps_done >= 100 && sent_across == 0) fail("no agent was sent to the island");
    nl_world_destroy(s.world);
    if (soak.count()) {
        std::fprintf(stderr, "navlink-agents-soak: %d failures\n", soak.count());
        return 1;
    }
    std::printf("navlink-agents-soak: passed\n");
    return 0;
}
