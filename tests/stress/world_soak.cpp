// navlink-world-soak: NavLink's thread-safe entry points at once, from ten threads, for a bounded
// time, with each of several worker counts. Two generators (full generations, box updates, and generations whose
// progress callback tries to generate the other navmesh: refused, never waited for), moves of a movable
// and of a static mesh with ray and segment queries after each, meshes added and removed (also from
// OBJ text), manual link edits, JSON saves and loads, queued and synchronous path requests with
// nl_path_process and point location beside them, navmeshes added and removed with requests on them,
// tiles of a tiled navmesh removed and built again while requests plan and agents walk on it,
// a log callback receiving the failures; at the end of each round the world is destroyed with
// requests still queued.
//
// It fails when any call returns a status its documentation does not allow, when a request finishes
// other than exactly once, or when a thread stops making progress for `--stall` seconds: a hang is
// reported with the thread that is stuck (and the process aborts, so a debugger or the sanitizer
// prints every thread), not left to the test's timeout. Built and run under ThreadSanitizer by the
// test command.
//
//   navlink-world-soak [--seconds S] [--stall S] [--workers N,N,...]
#include <navlink/navlink.h>
#include <navlink/recast.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cell_navmesh.h"
#include "generated_level_c.h"
#include "level_generator.h"
#include "soak_checks.h"

namespace {

using Clock = std::chrono::steady_clock;

nl::test::SoakFailures soak("navlink-world-soak");

void fail(const std::string& what) { soak.fail(what); }
bool expect(nl_status status, const char* call, std::initializer_list<nl_status> allowed = {}) {
    return soak.expect(status, call, allowed);
}
using Worker = nl::test::SoakWorker;

struct Round {
    nl_world* world = nullptr;
    std::atomic<uint64_t> logged{0};  // failures the world's log callback received
    nl_navmesh_id navmesh{};          // built by Recast from the level, for the default Recast agent
    nl_navmesh_id thin{};             // built for a thinner agent: a second navmesh to generate
    nl_navmesh_id tiled{};            // built in tiles, streamed out and in again while paths and agents use it
    nl_mesh_id platform{};            // movable
    nl_mesh_id crate{};               // static, moved anyway (its vertices are uploaded again)
    std::atomic<bool> stop{false};
};

float random_in(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

void translation(float (&m)[16], float x, float y, float z) {
    std::memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
    m[12] = x, m[13] = y, m[14] = z;
}

nl_mesh_id add_box(nl_world* world, const nl::levelgen::Box& box, uint32_t flags) {
    nl::levelgen::GeneratedLevel level;
    level.add_box(box);
    nl_mesh_id id{};
    expect(nl::test::add_generated_level(world, level, flags, nullptr, &id), "nl_mesh_add (box)");
    return id;
}

// A batch of rays down over the level and segments across it.
void query(nl_world* world, std::mt19937& rng) {
    std::vector<nl_ray> rays(64);
    for (nl_ray& r : rays) {
        r = nl_ray{{random_in(rng, -2, 38), 12, random_in(rng, -2, 12)}, {0, -1, 0}, 30};
    }
    std::vector<nl_ray_hit> hits(rays.size(), nl_ray_hit_init());
    expect(nl_world_cast_rays(world, rays.data(), uint32_t(rays.size()), hits.data()), "nl_world_cast_rays");
    std::vector<nl_segment> segments(64);
    for (nl_segment& s : segments) {
        s = nl_segment{{random_in(rng, -2, 38), 1, random_in(rng, -2, 12)},
                       {random_in(rng, -2, 38), 1, random_in(rng, -2, 12)}};
    }
    std::vector<uint8_t> blocked(segments.size());
    expect(nl_world_segments_blocked(world, segments.data(), uint32_t(segments.size()), blocked.data()),
           "nl_world_segments_blocked");
}

// A progress callback that tries to generate from inside the generation: refused at once, never a wait; two
// generators doing it crosswise, each for the other's navmesh, used to hang.
struct NestedGeneration {
    Round* round;
    nl_navmesh_id other;
    bool tried = false;
};

int32_t generate_from_progress(void* user, float, const char*) {
    NestedGeneration& n = *static_cast<NestedGeneration*>(user);
    if (!n.tried) {
        n.tried = true;
        const nl_status status = nl_navmesh_generate_links(n.round->world, n.other, nullptr, nullptr, nullptr, nullptr);
        if (status != (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT))
            fail(std::string("a generation from a progress callback returned ") + nl_status_string(status));
    }
    return 1;
}

// Generates `navmesh`: full generations, box updates, and generations whose progress callback tries to
// generate `other`.
void generate(Round& r, Worker& me, nl_navmesh_id navmesh, nl_navmesh_id other) {
    nl_link_settings settings = nl_default_link_settings();
    const float box_min[3] = {10, -2, -1}, box_max[3] = {20, 6, 8};
    for (uint64_t i = 0; !r.stop; ++i) {
        if (i % 3 == 2) {
            me.doing = "nl_navmesh_update_links_in_box";
            // NOT_FOUND: the link editor removed the generated links or loaded a JSON set since.
            expect(nl_navmesh_update_links_in_box(r.world, navmesh, box_min, box_max, nullptr, nullptr, nullptr),
                   "nl_navmesh_update_links_in_box", {NL_STATUS_NOT_FOUND});
        } else if (i % 3 == 1) {
            me.doing = "nl_navmesh_generate_links (generating the other navmesh from its progress callback)";
            NestedGeneration nested{&r, other};
            expect(nl_navmesh_generate_links(r.world, navmesh, &settings, generate_from_progress, &nested, nullptr),
                   "nl_navmesh_generate_links");
        } else {
            me.doing = "nl_navmesh_generate_links";
            expect(nl_navmesh_generate_links(r.world, navmesh, &settings, nullptr, nullptr, nullptr),
                   "nl_navmesh_generate_links");
        }
        ++me.steps;
    }
}

// The movable platform swings back and forth; each move is followed by queries, so every query
// commits a changed scene.
void move_platform(Round& r, Worker& me) {
    std::mt19937 rng(11);
    float m[16];
    for (uint64_t i = 0; !r.stop; ++i) {
        me.doing = "nl_mesh_set_transform (movable)";
        translation(m, 0, 0, float(i % 40) * 0.05f);
        expect(nl_mesh_set_transform(r.world, r.platform, m), "nl_mesh_set_transform (movable)");
        me.doing = "queries after a movable move";
        query(r.world, rng);
        ++me.steps;
    }
}

// A second editor: moves a static mesh (the static scene is rebuilt), adds and removes small meshes.
void edit_level(Round& r, Worker& me) {
    std::mt19937 rng(12);
    float m[16];
    std::vector<nl_mesh_id> added;
    for (uint64_t i = 0; !r.stop; ++i) {
        me.doing = "nl_mesh_set_transform (static)";
        translation(m, float(i % 10) * 0.1f, 0, 0);
        expect(nl_mesh_set_transform(r.world, r.crate, m), "nl_mesh_set_transform (static)");
        if (added.size() < 4 && rng() % 2) {
            me.doing = "nl_mesh_add";
            const float x = random_in(rng, 0, 30), z = random_in(rng, 0, 8);
            added.push_back(
                add_box(r.world, {{x, 20, z}, {x + 0.5f, 20.5f, z + 0.5f}}, rng() % 2 ? NL_MESH_MOVABLE : 0));
        } else if (!added.empty()) {
            me.doing = "nl_mesh_remove";
            expect(nl_mesh_remove(r.world, added.back()), "nl_mesh_remove");
            added.pop_back();
        }
        if (i % 8 == 0) {
            me.doing = "nl_mesh_add_obj_memory";
            static const char kObj[] = "v 30 5 30\nv 31 5 30\nv 30 5 31\nf 1 3 2\n";
            nl_mesh_id obj{};
            if (expect(nl_mesh_add_obj_memory(r.world, kObj, sizeof kObj - 1, nullptr, &obj), "nl_mesh_add_obj_memory"))
                expect(nl_mesh_remove(r.world, obj), "nl_mesh_remove (OBJ)");
        }
        me.doing = "queries after a static edit";
        query(r.world, rng);
        ++me.steps;
    }
}

// Manual links added, updated and removed; generated links removed; the links saved and loaded back.
void edit_links(Round& r, Worker& me) {
    std::mt19937 rng(13);
    std::vector<nl_link_id> live;
    std::vector<char> json;
    for (uint64_t i = 0; !r.stop; ++i) {
        const uint32_t what = rng() % 16;
        if (what < 8 || live.empty()) {
            me.doing = "nl_link_add";
            nl_link_def def = nl_default_link_def();
            def.kind = NL_LINK_MANUAL;
            // Two points on the first platform (x 0-6, y ~0, z 0-6 in the default level).
            def.start[0] = random_in(rng, 1, 4), def.start[2] = random_in(rng, 1, 5);
            def.end[0] = def.start[0] + 1, def.end[2] = def.start[2];
            nl_link_id id{};
            if (expect(nl_link_add(r.world, r.navmesh, &def, &id), "nl_link_add")) live.push_back(id);
        } else if (what < 11) {
            me.doing = "nl_link_update";
            nl_link link = nl_link_init();
            // INVALID_HANDLE: a JSON load below replaced every link since this one was added.
            if (expect(nl_link_get(r.world, live.back(), &link), "nl_link_get", {NL_STATUS_INVALID_HANDLE})) {
                nl_link_def def = nl_default_link_def();
                def.kind = NL_LINK_MANUAL;
                std::memcpy(def.start, link.start, sizeof def.start);
                std::memcpy(def.end, link.end, sizeof def.end);
                def.enabled = uint8_t(rng() % 2);
                expect(nl_link_update(r.world, live.back(), &def), "nl_link_update", {NL_STATUS_INVALID_HANDLE});
            }
        } else if (what < 14) {
            me.doing = "nl_link_remove";
            expect(nl_link_remove(r.world, live.back()), "nl_link_remove", {NL_STATUS_INVALID_HANDLE});
            live.pop_back();
        } else if (what == 14) {
            me.doing = "nl_navmesh_remove_generated_links";
            expect(nl_navmesh_remove_generated_links(r.world, r.navmesh, nullptr), "nl_navmesh_remove_generated_links");
        } else {
            me.doing = "nl_navmesh_save_links_json / load";
            size_t length = 0;
            nl_status status = NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
            // Links may change between measuring and writing: measure again until it fits.
            while (status == (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL)) {
                json.resize(length + 1024);
                status = nl_navmesh_save_links_json(r.world, r.navmesh, json.data(), json.size(), &length);
            }
            if (expect(status, "nl_navmesh_save_links_json")) {
                expect(nl_navmesh_load_links_json(r.world, r.navmesh, json.data(), length, 0, nullptr),
                       "nl_navmesh_load_links_json");
                live.clear();
            }
        }
        ++me.steps;
    }
}

struct Completion {
    std::atomic<int> calls{0};
};

void on_done(void* user, nl_path_ticket, nl_path_outcome) { static_cast<Completion*>(user)->calls.fetch_add(1); }

nl_path_request_def request_on(nl_navmesh_id navmesh, std::mt19937& rng, float x1, float z1) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    def.start[0] = random_in(rng, 0, x1), def.start[2] = random_in(rng, 0, z1);
    def.goal[0] = random_in(rng, 0, x1), def.goal[2] = random_in(rng, 0, z1);
    def.capabilities.max_jump_distance = rng() % 2 ? 4.0f : 0.0f;
    def.capabilities.max_jump_height = 1.0f;
    def.capabilities.max_drop_height = rng() % 2 ? 4.0f : 0.0f;
    def.capabilities.radius = 0.3f;
    return def;
}

// Queued requests with callbacks (some cancelled or released at once) and synchronous ones.
void request_paths(Round& r, Worker& me, unsigned seed, nl_navmesh_id navmesh) {
    std::mt19937 rng(seed);
    std::vector<std::unique_ptr<Completion>> done;
    std::vector<nl_path_ticket> tickets;
    std::vector<nl_path_point> points(256, nl_path_point_init());
    for (uint64_t i = 0; !r.stop; ++i) {
        nl_path_request_def def = request_on(navmesh, rng, 36, 10);
        if (i % 4 == 0) {
            me.doing = "nl_path_find";
            nl_path_result result{};
            result.size = sizeof result;
            uint32_t count = 0;
            expect(nl_path_find(r.world, &def, &result, points.data(), uint32_t(points.size()), &count), "nl_path_find",
                   {NL_STATUS_BUFFER_TOO_SMALL});
        } else {
            me.doing = "nl_path_request";
            done.push_back(std::make_unique<Completion>());
            def.callback = on_done;
            def.user = done.back().get();
            nl_path_ticket ticket{};
            if (!expect(nl_path_request(r.world, &def, &ticket), "nl_path_request")) {
                done.pop_back();
            } else if (i % 9 == 0) {
                expect(nl_path_cancel(r.world, ticket), "nl_path_cancel");
                tickets.push_back(ticket);
            } else if (i % 7 == 0) {
                expect(nl_path_release(r.world, ticket), "nl_path_release");
            } else {
                tickets.push_back(ticket);
            }
        }
        if (i % 16 == 0) {
            me.doing = "nl_path_process / nl_navmesh_find_nearest";
            uint32_t done = 0;
            nl_path_budget budget = nl_default_path_budget();
            budget.max_requests = 4;
            budget.max_milliseconds = 1.0;
            budget.max_search_nodes = 2000;
            expect(nl_path_process(r.world, &budget, &done), "nl_path_process");
            float points[3 * 16];
            for (float& p : points) p = random_in(rng, 0, 12);
            const float half[3] = {2, 4, 2};
            nl_nav_point near[16];
            expect(nl_navmesh_find_nearest(r.world, navmesh, points, 16, half, near), "nl_navmesh_find_nearest");
        }
        // Read back and release the older half now and then, so tickets do not pile up.
        if (tickets.size() > 64) {
            me.doing = "nl_path_poll / get_result / release";
            for (size_t k = 0; k < 32; ++k) {
                nl_path_outcome outcome = 0;
                expect(nl_path_poll(r.world, tickets[k], &outcome), "nl_path_poll");
                if (outcome != NL_PATH_PENDING) {
                    nl_path_result result{};
                    result.size = sizeof result;
                    uint32_t count = 0;
                    expect(nl_path_get_result(r.world, tickets[k], &result, points.data(), uint32_t(points.size()),
                                              &count),
                           "nl_path_get_result", {NL_STATUS_BUFFER_TOO_SMALL});
                }
                expect(nl_path_release(r.world, tickets[k]), "nl_path_release");
            }
            tickets.erase(tickets.begin(), tickets.begin() + 32);
        }
        ++me.steps;
    }
    // Every accepted request calls back exactly once; wait for the queue to finish them.
    me.doing = "waiting for this thread's requests";
    for (const auto& c : done) {
        const auto until = Clock::now() + std::chrono::seconds(60);
        while (c->calls.load() == 0 && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (c->calls.load() != 1) fail("a request called back " + std::to_string(c->calls.load()) + " times");
    }
    for (nl_path_ticket t : tickets) expect(nl_path_release(r.world, t), "nl_path_release");
}

// Host navmeshes added, generated, planned on and removed while their requests may still run.
void churn_navmeshes(Round& r, Worker& me) {
    std::mt19937 rng(14);
    std::vector<std::string> rows(12, std::string(12, '.'));
    for (std::string& row : rows) row[6] = '#';
    const nl::test::CellNavmesh cells(rows, 0.0f);
    std::vector<std::unique_ptr<Completion>> done;
    for (uint64_t i = 0; !r.stop; ++i) {
        me.doing = "nl_navmesh_add";
        nl_navmesh_id id{};
        if (!expect(nl_navmesh_add(r.world, &cells.def, &id), "nl_navmesh_add")) continue;
        for (int k = 0; k < 8; ++k) {
            me.doing = "nl_path_request (churned navmesh)";
            nl_path_request_def def = request_on(id, rng, 12, 12);
            done.push_back(std::make_unique<Completion>());
            def.callback = on_done;
            def.user = done.back().get();
            nl_path_ticket ticket{};
            if (expect(nl_path_request(r.world, &def, &ticket), "nl_path_request (churned navmesh)"))
                expect(nl_path_release(r.world, ticket), "nl_path_release");
            else
                done.pop_back();
        }
        if (i % 2) {
            me.doing = "nl_navmesh_generate_links (churned navmesh)";
            // Cell navmeshes have no level geometry under them: no links, but a full generation's locking.
            expect(nl_navmesh_generate_links(r.world, id, nullptr, nullptr, nullptr, nullptr),
                   "nl_navmesh_generate_links (churned navmesh)");
        }
        me.doing = "nl_navmesh_remove";
        expect(nl_navmesh_remove(r.world, id), "nl_navmesh_remove");
        ++me.steps;
    }
    me.doing = "waiting for this thread's requests";
    for (const auto& c : done) {
        const auto until = Clock::now() + std::chrono::seconds(60);
        while (c->calls.load() == 0 && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (c->calls.load() != 1)
            fail("a request on a removed navmesh called back " + std::to_string(c->calls.load()) + " times");
    }
}

// Tiles of the tiled navmesh removed and built again (nl_navmesh_build_tiles over the tile), one at a
// time, while requests plan on it and agents walk on it.
void stream_tiles(Round& r, Worker& me) {
    std::mt19937 rng(16);
    nl_recast_settings settings = nl_default_recast_settings();
    settings.tile_size = 32;
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.settings = &settings;
    std::vector<nl_tile_coord> tiles(256);
    while (!r.stop) {
        me.doing = "nl_navmesh_get_tiles";
        uint32_t count = 0;
        if (!expect(nl_navmesh_get_tiles(r.world, r.tiled, tiles.data(), uint32_t(tiles.size()), &count),
                    "nl_navmesh_get_tiles"))
            continue;
        nl_navmesh_info info = nl_navmesh_info_init();
        if (!expect(nl_navmesh_get_info(r.world, r.tiled, &info), "nl_navmesh_get_info (tiled)")) continue;
        const nl_tile_coord tile = tiles[rng() % count];
        me.doing = "nl_navmesh_remove_tile";
        expect(nl_navmesh_remove_tile(r.world, r.tiled, tile), "nl_navmesh_remove_tile", {NL_STATUS_INVALID_ARGUMENT});
        std::this_thread::sleep_for(std::chrono::milliseconds(rng() % 20));
        me.doing = "nl_navmesh_build_tiles";
        const float centre[3] = {info.tile_origin[0] + (float(tile.x) + 0.5f) * info.tile_width, 0.0f,
                                 info.tile_origin[1] + (float(tile.z) + 0.5f) * info.tile_width};
        expect(nl_navmesh_build_tiles(r.world, r.tiled, &build, centre, centre), "nl_navmesh_build_tiles");
        ++me.steps;
    }
}

// Agents walking on the tiled navmesh while its tiles come and go: destinations anywhere on it (NOT_FOUND
// where a tile is out), world steps.
void walk_on_tiles(Round& r, Worker& me) {
    std::mt19937 rng(17);
    std::vector<nl_agent_id> agents;
    for (int k = 0; k < 8; ++k) {
        nl_agent_def def = nl_default_agent_def();
        def.navmesh = r.tiled;
        def.position[0] = 2.0f + 4.0f * float(k % 4), def.position[2] = 2.0f + 3.0f * float(k / 4);
        nl_agent_id id{};
        me.doing = "nl_agent_add";
        if (expect(nl_agent_add(r.world, &def, &id), "nl_agent_add", {NL_STATUS_NOT_FOUND})) agents.push_back(id);
    }
    for (uint64_t i = 0; !r.stop; ++i) {
        if (i % 20 == 0) {
            for (nl_agent_id id : agents) {
                const float goal[3] = {random_in(rng, 0, 36), 0.0f, random_in(rng, 0, 10)};
                me.doing = "nl_agent_set_destination";
                expect(nl_agent_set_destination(r.world, id, goal), "nl_agent_set_destination", {NL_STATUS_NOT_FOUND});
            }
        }
        me.doing = "nl_world_step";
        expect(nl_world_step(r.world, 0.05f), "nl_world_step");
        ++me.steps;
    }
}

void on_log(void* user, nl_log_level, nl_status, const char*) { static_cast<Round*>(user)->logged.fetch_add(1); }

bool set_up(Round& r, int32_t workers) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    def.path_worker_count = 2;
    def.log_fn = on_log;
    def.log_user = &r;
    if (!expect(nl_world_create(&def, &r.world), "nl_world_create")) return false;
    const nl::levelgen::GeneratedLevel level = nl::levelgen::generate_default_level(1);
    if (!expect(nl::test::add_generated_level(r.world, level), "nl_mesh_add (level)")) return false;
    r.platform = add_box(r.world, {{8, -0.5f, 14}, {12, 0, 18}}, NL_MESH_MOVABLE);
    r.crate = add_box(r.world, {{30, 0, 14}, {31, 1, 15}}, 0);
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_build_def thin = nl_default_navmesh_build_def();
    thin.agent_type.radius = 0.3f;
    nl_recast_settings tile_settings = nl_default_recast_settings();
    tile_settings.tile_size = 32;
    nl_navmesh_build_def tiled = nl_default_navmesh_build_def();
    tiled.settings = &tile_settings;
    return expect(nl_navmesh_build(r.world, &build, &r.navmesh), "nl_navmesh_build") &&
           expect(nl_navmesh_build(r.world, &thin, &r.thin), "nl_navmesh_build (thin)") &&
           expect(nl_navmesh_build(r.world, &tiled, &r.tiled), "nl_navmesh_build (tiled)");
}

// Requests queued as the world goes: each still calls back exactly once (as cancelled or finished).
void destroy_with_requests_queued(Round& r) {
    std::mt19937 rng(15);
    std::vector<Completion> done(200);
    int accepted = 0;
    for (Completion& c : done) {
        nl_path_request_def def = request_on(r.navmesh, rng, 36, 10);
        def.callback = on_done;
        def.user = &c;
        nl_path_ticket ticket{};
        if (expect(nl_path_request(r.world, &def, &ticket), "nl_path_request (before destroy)"))
            ++accepted;
        else
            c.calls = 1;
    }
    nl_world_destroy(r.world);
    r.world = nullptr;
    int wrong = 0;
    for (const Completion& c : done) wrong += c.calls.load() != 1;
    if (wrong)
        fail(std::to_string(wrong) + " of " + std::to_string(accepted) +
             " requests queued at destroy did not call back once");
}

// Runs one round; aborts the process when a thread stalls.
void run_round(int32_t workers, double seconds, double stall_seconds) {
    Round r;
    if (!set_up(r, workers)) return;
    std::vector<std::unique_ptr<Worker>> workers_state;
    std::vector<std::thread> threads;
    auto start = [&](const char* name, auto&& body) {
        workers_state.push_back(std::make_unique<Worker>());
        Worker& w = *workers_state.back();
        w.name = name;
        threads.emplace_back([&r, &w, body] {
            body(r, w);
            w.doing = "finished";
        });
    };
    start("generator", [](Round& r, Worker& w) { generate(r, w, r.navmesh, r.thin); });
    start("second generator", [](Round& r, Worker& w) { generate(r, w, r.thin, r.navmesh); });
    start("platform mover", [](Round& r, Worker& w) { move_platform(r, w); });
    start("level editor", [](Round& r, Worker& w) { edit_level(r, w); });
    start("link editor", [](Round& r, Worker& w) { edit_links(r, w); });
    start("requester 1", [](Round& r, Worker& w) { request_paths(r, w, 21, r.navmesh); });
    start("requester 2", [](Round& r, Worker& w) { request_paths(r, w, 22, r.tiled); });
    start("tile streamer", [](Round& r, Worker& w) { stream_tiles(r, w); });
    start("walkers on tiles", [](Round& r, Worker& w) { walk_on_tiles(r, w); });
    start("navmesh churn", [](Round& r, Worker& w) { churn_navmeshes(r, w); });

    const auto begin = Clock::now();
    bool stalled = false;
    std::vector<uint64_t> last(workers_state.size(), 0);
    std::vector<Clock::time_point> moved(workers_state.size(), begin);
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        const auto now = Clock::now();
        if (!r.stop && std::chrono::duration<double>(now - begin).count() >= seconds) {
            r.stop = true;
            // Threads finish their current call and wait for their requests: give them a fresh stall window.
            std::fill(moved.begin(), moved.end(), now);
        }
        bool all_done = true;
        for (size_t i = 0; i < workers_state.size(); ++i) {
            const uint64_t steps = workers_state[i]->steps.load();
            const bool finished = std::strcmp(workers_state[i]->doing.load(), "finished") == 0;
            all_done = all_done && finished;
            if (steps != last[i] || finished) last[i] = steps, moved[i] = now;
            if (std::chrono::duration<double>(now - moved[i]).count() > stall_seconds) {
                std::fprintf(stderr, "navlink-world-soak: workers=%d: thread '%s' made no progress for %.0f s, in %s\n",
                             workers, workers_state[i]->name, stall_seconds, workers_state[i]->doing.load());
                stalled = true;
            }
        }
        if (stalled) {
            std::fflush(stderr);
            std::abort();  // a hang: let the sanitizer or a core dump show every thread
        }
        if (all_done) break;
    }
    for (std::thread& t : threads) t.join();
    uint64_t total = 0;
    std::string counts;
    for (const auto& w : workers_state) {
        total += w->steps;
        counts += std::string(" ") + w->name + "=" + std::to_string(w->steps.load());
    }
    destroy_with_requests_queued(r);
    std::printf("workers=%d logged=%llu seconds=%.1f steps=%llu:%s\n", workers,
                static_cast<unsigned long long>(r.logged.load()),
                std::chrono::duration<double>(Clock::now() - begin).count(), static_cast<unsigned long long>(total),
                counts.c_str());
    for (const auto& w : workers_state) {
        if (w->steps == 0) fail(std::string("thread '") + w->name + "' did nothing");
    }
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 4.0, stall = 30.0;
    std::vector<int32_t> worker_counts = {2, NL_WORKERS_AUTO, 1, 3};
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--seconds")
            seconds = std::atof(argv[i + 1]);
        else if (option == "--stall")
            stall = std::atof(argv[i + 1]);
        else if (option == "--workers") {
            worker_counts.clear();
            for (const char* p = argv[i + 1]; *p;) {
                char* end = nullptr;
                worker_counts.push_back(int32_t(std::strtol(p, &end, 10)));
                p = *end ? end + 1 : end;
            }
        } else {
            std::fprintf(stderr, "usage: navlink-world-soak [--seconds S] [--stall S] [--workers N,N,...]\n");
            return 2;
        }
    }
    for (int32_t workers : worker_counts) run_round(workers, seconds, stall);
    std::printf("failures=%d\n", soak.count());
    return soak.count() == 0 ? 0 : 1;
}
