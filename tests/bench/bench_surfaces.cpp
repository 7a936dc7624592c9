// navlink-bench-surfaces [--repeats N] [--frames N] [--paths N] [--agents N,N,...]: what a navmesh
// that rides a moving platform costs, through the C ABI, against what an engine without moving
// navmeshes pays at each move of the platform: building its navmesh again. One run, side by side.
//
// The platforms, each a movable mesh (NL_MESH_MOVABLE) with its top at y = 0 in its own space:
// - box-12: a 12 x 12 m box 0.5 m thick (12 triangles);
// - grid-40: a 40 x 40 m open grid of 0.5 m cells (12,800 triangles) carrying a lattice of 10 x 10
//   crates 1 x 1 x 1.5 m, 4 m apart (1,200 triangles more), so that paths turn around them.
// Each carries the navmesh the Recast builder makes on it (nl_navmesh_build with def.carrier; radius
// 0.3 m, other settings default) and moves along a rigid path: it sways, bobs, turns and rolls, its
// pose computed from the time, never accumulated. Its static copy is the same triangles as a static
// mesh at the identity in a world of its own, with the navmesh Recast builds there: the same
// polygons, in the coordinates of the moving navmesh's own space. Worlds have one worker.
//
// Rows, per platform; every figure is microseconds per call, min / median / max over --repeats
// repeats (7), each the mean over a batch:
// - rebuild: nl_navmesh_build on the surface, then nl_navmesh_remove of the navmesh it replaces, as
//   an engine without moving navmeshes would at every move (before even putting its agents on the
//   new navmesh). The anchor of the /rebuild column.
// - move: nl_mesh_set_transform of the platform with N agents on its navmesh (--agents: 0, 100 and
//   1,000, added as the count grows; the even ones walk to random points of the platform, sent on
//   at arrival outside the timing, the odd ones stand; radius 0.3 m, so 1,000 bodies overfill
//   box-12 as a packed ferry deck would), once per frame for --frames frames (40) after 20 untimed
//   ones. It updates the ray scene's instance and the surface's pose, and the mesh's world bounds
//   from every vertex (so its cost grows with the platform's vertices); the scene itself is
//   committed by the next ray query, and none runs here.
// - step, moving: nl_world_step (dt 1/60 s) in those frames, each after the move;
//   step, static: the same agents (same places and destinations, in the copy's coordinates)
//   stepped on the static copy, batch for batch with the moving ones.
// - path, moving: nl_path_find between --paths (200) random pairs of points of the platform, asked
//   in the world where the platform is (moved between repeats); path, static: the same pairs on the
//   static copy. "agree" counts pairs whose paths have the same points (carrier_position against the
//   copy's position, within 1 cm). On a turned platform the ends' search box ((2, 4, 2) m in world
//   axes) is searched as the box in the platform's axes that holds it: a larger box, more polygons.
// - links: see run_links (cross links generated for a docked platform against the level's own links).
// /rebuild: the row's median over the rebuild's median; /static: a moving row's median over its
// static twin's (what riding costs: 1.00 is nothing).
#include <navlink/navlink.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "clock.h"
#include "generated_level_c.h"
#include "level_generator.h"
#include "rigid_pose.h"
#include "spread.h"

namespace {

using nl::bench::Spread;
using nl::test::RigidPose;

constexpr float kRadius = 0.3f;
constexpr float kDt = 1.0f / 60.0f;
constexpr int kWarmFrames = 20;

struct Options {
    int repeats = 7;
    int frames = 40;
    int paths = 200;
    std::vector<int> counts{0, 100, 1000};
};

struct Platform {
    std::string name;
    nl::levelgen::GeneratedLevel mesh;  // in its own space
    float half = 0.0f;                  // its top spans [-half, half] in x and z
    float crates = 0.0f;                // the spacing of its crates, the first at -half + crates / 2; 0: none

    // Half a metre from every crate at least (their centres 1 m away on x or z).
    bool clear(float x, float z) const {
        if (crates == 0.0f) return true;
        auto off = [&](float v) { return std::fabs(std::remainder(v + half - 0.5f * crates, crates)); };
        return off(x) > 1.0f || off(z) > 1.0f;
    }
};

// Where the platform is at time t: swaying along x, bobbing, turning, rolling a little.
RigidPose platform_pose(double t) {
    return RigidPose::at(float(30.0 + 4.0 * std::sin(0.4 * t)), float(5.0 + 0.5 * std::sin(0.9 * t)), 0.0f,
                         float(std::fmod(0.3 * t, 2.0 * M_PI)), float(0.05 * std::sin(0.7 * t)));
}

// Agent i's k-th point of the platform (k = 0: where it starts), clear of the crates, in the
// platform's space: the same for both sides. Path pairs are drawn the same way.
struct Places {
    const Platform* platform = nullptr;
    uint32_t seed = 0;
    void point(uint32_t agent, uint32_t k, float out[3]) const {
        std::seed_seq sequence{seed, agent, k};
        std::mt19937 rng(sequence);
        std::uniform_real_distribution<float> across(-platform->half + 0.5f, platform->half - 0.5f);
        do out[0] = across(rng), out[1] = 0.0f, out[2] = across(rng);
        while (!platform->clear(out[0], out[2]));
    }
};

bool fail(const std::string& platform, const char* what) {
    std::fprintf(stderr, "navlink-bench-surfaces: %s: %s: %s\n", platform.c_str(), what, nl_get_last_error_message());
    return false;
}

// The platform in a world of its own: riding its movable mesh, or as the static copy (whose pose
// stays the identity, so the same code places points on both).
struct Side {
    std::string name;
    nl_world* world = nullptr;
    nl_mesh_id mesh{};
    nl_navmesh_id navmesh{};
    RigidPose pose;
    std::vector<nl_agent_id> agents;
    std::vector<uint32_t> trips;  // destinations drawn so far, per agent
    std::vector<nl_agent_event> events;

    Side() = default;
    Side(const Side&) = delete;
    Side& operator=(const Side&) = delete;
    ~Side() { nl_world_destroy(world); }

    bool setup(const Platform& platform, bool moving) {
        name = platform.name + (moving ? "" : " (static copy)");
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        def.path_worker_count = 0;
        if (NL_FAILED(nl_world_create(&def, &world))) return fail(name, "nl_world_create");
        if (moving) pose = platform_pose(0.0);
        if (NL_FAILED(nl::test::add_generated_level(world, platform.mesh, moving ? NL_MESH_MOVABLE : 0,
                                                    moving ? pose.m : nullptr, &mesh)))
            return fail(name, "nl_mesh_add");
        return build(moving, &navmesh);
    }
    bool build(bool on_surface, nl_navmesh_id* out) {
        nl_navmesh_build_def def = nl_default_navmesh_build_def();
        def.agent_type.radius = kRadius;
        if (on_surface) def.carrier = mesh;
        return NL_SUCCEEDED(nl_navmesh_build(world, &def, out)) || fail(name, "nl_navmesh_build");
    }
    uint32_t polygons() const {
        nl_navmesh_info info{};
        info.size = sizeof info;
        nl_navmesh_get_info(world, navmesh, &info);
        return info.polygon_count;
    }

    bool add_agents(size_t count, const Places& places) {
        for (uint32_t i = uint32_t(agents.size()); i < count; ++i) {
            nl_agent_def def = nl_default_agent_def();
            def.navmesh = navmesh;
            def.capabilities.radius = kRadius;
            def.user_data = i;
            float local[3];
            places.point(i, 0, local);
            pose.to_world(local, def.position);
            nl_agent_id id{};
            if (NL_FAILED(nl_agent_add(world, &def, &id))) return fail(name, "nl_agent_add");
            agents.push_back(id);
            trips.push_back(1);
            if (i % 2 == 0) send(i, places);
        }
        return true;
    }
    // Agent i to its next point, where that point of the platform is now.
    void send(uint32_t i, const Places& places) {
        float local[3], world_point[3];
        places.point(i, trips[i]++, local);
        pose.to_world(local, world_point);
        nl_agent_set_destination(world, agents[i], world_point);
    }
    // Sends on the walkers that arrived or failed in the last step.
    void drain_events(const Places& places) {
        uint32_t count = 0;
        nl_world_get_agent_events(world, nullptr, 0, &count);
        events.assign(count, nl_agent_event_init());
        if (count > 0) nl_world_get_agent_events(world, events.data(), count, &count);
        for (const nl_agent_event& e : events)
            if (e.kind == NL_AGENT_EVENT_ARRIVED || e.kind == NL_AGENT_EVENT_FAILED)
                send(uint32_t(e.user_data), places);
    }

    // One frame: the move (moving side only: `t` set), then the step; each call's time added in ms.
    void frame(double* t, const Places& places, double& move_ms, double& step_ms) {
        if (t) {
            *t += kDt;
            pose = platform_pose(*t);
            const double t0 = nl::samples::now_ms();
            nl_mesh_set_transform(world, mesh, pose.m);
            move_ms += nl::samples::now_ms() - t0;
        }
        const double t0 = nl::samples::now_ms();
        nl_world_step(world, kDt);
        step_ms += nl::samples::now_ms() - t0;
        drain_events(places);
    }

    bool find_path(const float local_start[3], const float local_goal[3], nl_path_result& result,
                   std::vector<nl_path_point>& points) {
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = navmesh;
        def.capabilities.radius = kRadius;
        pose.to_world(local_start, def.start);
        pose.to_world(local_goal, def.goal);
        result = nl_path_result_init();
        uint32_t count = 0;
        return NL_SUCCEEDED(nl_path_find(world, &def, &result, points.data(), uint32_t(points.size()), &count));
    }
};

// The same points: the moving side's in its surface's space, the copy's as they are.
bool same_path(const nl_path_result& a, const std::vector<nl_path_point>& moving, const nl_path_result& b,
               const std::vector<nl_path_point>& copy) {
    if (a.outcome != b.outcome || a.point_count != b.point_count) return false;
    for (uint32_t k = 0; k < a.point_count; ++k) {
        const float* p = moving[k].carrier_position;
        const float* q = copy[k].position;
        if (std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) > 0.01f) return false;
    }
    return true;
}

std::string figure(double value, const char* format) {
    if (!(value == value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

void row(const std::string& platform, const char* what, const std::string& agents, const Spread& s, double rebuild,
         double twin) {
    std::printf("%-8s %-15s %6s %11s %11s %11s %9s %8s\n", platform.c_str(), what, agents.c_str(),
                figure(s.min, "%.3f").c_str(), figure(s.median, "%.3f").c_str(), figure(s.max, "%.3f").c_str(),
                figure(s.median / rebuild, "%.2g").c_str(), figure(s.median / twin, "%.2f").c_str());
}

bool run(const Platform& platform, uint32_t seed, const Options& o) {
    Side moving, still;
    if (!moving.setup(platform, true) || !still.setup(platform, false)) return false;
    std::printf("# %s: %u triangles; navmesh %u polygons (static copy: %u)\n", platform.name.c_str(),
                platform.mesh.triangle_count(), moving.polygons(), still.polygons());
    const double nan = std::nan("");

    // The anchor: each rebuild replaces the last one (a navmesh of its own beside the agents').
    std::vector<double> rebuild_us;
    nl_navmesh_id last{};
    if (!moving.build(true, &last)) return false;
    for (int r = 0; r < o.repeats; ++r) {
        nl_navmesh_id next{};
        const double t0 = nl::samples::now_ms();
        if (!moving.build(true, &next)) return false;
        nl_navmesh_remove(moving.world, last);
        rebuild_us.push_back(1000.0 * (nl::samples::now_ms() - t0));
        last = next;
    }
    nl_navmesh_remove(moving.world, last);
    const Spread rebuild = nl::bench::spread(rebuild_us);
    row(platform.name, "rebuild", "-", rebuild, rebuild.median, nan);

    const Places places{&platform, seed};
    double t = 0.0;
    for (const int count : o.counts) {
        if (!moving.add_agents(size_t(count), places) || !still.add_agents(size_t(count), places)) return false;
        double ignored = 0.0;
        for (int f = 0; f < kWarmFrames; ++f) {
            moving.frame(&t, places, ignored, ignored);
            still.frame(nullptr, places, ignored, ignored);
        }
        std::vector<double> move_us, step_us, still_us;
        for (int r = 0; r < o.repeats; ++r) {
            double move_ms = 0.0, step_ms = 0.0, still_ms = 0.0;
            // Batch for batch, the order turning: a shared machine's interruptions fall on both alike.
            for (int side = 0; side < 2; ++side) {
                for (int f = 0; f < o.frames; ++f) {
                    if ((side + r) % 2 == 0)
                        moving.frame(&t, places, move_ms, step_ms);
                    else
                        still.frame(nullptr, places, ignored, still_ms);
                }
            }
            move_us.push_back(1000.0 * move_ms / o.frames);
            step_us.push_back(1000.0 * step_ms / o.frames);
            still_us.push_back(1000.0 * still_ms / o.frames);
        }
        const Spread still_step = nl::bench::spread(still_us);
        const std::string agents = std::to_string(count);
        row(platform.name, "move", agents, nl::bench::spread(move_us), rebuild.median, nan);
        row(platform.name, "step, moving", agents, nl::bench::spread(step_us), rebuild.median, still_step.median);
        row(platform.name, "step, static", agents, still_step, rebuild.median, still_step.median);
    }

    // Paths: pairs of their own, drawn before the timing; the platform moves between repeats.
    const Places draw{&platform, seed + 1000};
    std::vector<std::array<float, 6>> pairs(size_t(o.paths));
    for (uint32_t k = 0; k < pairs.size(); ++k) draw.point(k, 0, &pairs[k][0]), draw.point(k, 1, &pairs[k][3]);
    std::vector<nl_path_point> points(256, nl_path_point_init()), copy_points(256, nl_path_point_init());
    nl_path_result result{}, copy_result{};
    std::vector<double> path_us, copy_us;
    for (int r = 0; r < o.repeats; ++r) {
        t += 1.0;
        moving.pose = platform_pose(t);
        nl_mesh_set_transform(moving.world, moving.mesh, moving.pose.m);
        for (int side = 0; side < 2; ++side) {
            const bool on_moving = (side + r) % 2 == 0;
            Side& s = on_moving ? moving : still;
            const double t0 = nl::samples::now_ms();
            for (const auto& pair : pairs)
                if (!s.find_path(&pair[0], &pair[3], result, points)) return fail(s.name, "nl_path_find");
            (on_moving ? path_us : copy_us).push_back(1000.0 * (nl::samples::now_ms() - t0) / o.paths);
        }
    }
    int agree = 0;
    for (const auto& pair : pairs)
        if (moving.find_path(&pair[0], &pair[3], result, points) &&
            still.find_path(&pair[0], &pair[3], copy_result, copy_points))
            agree += same_path(result, points, copy_result, copy_points);
    const Spread copy_path = nl::bench::spread(copy_us);
    row(platform.name, "path, moving", "-", nl::bench::spread(path_us), nan, copy_path.median);
    row(platform.name, "path, static", "-", copy_path, nan, copy_path.median);
    std::printf("# %s: paths agree on %d of %d pairs\n", platform.name.c_str(), agree, o.paths);
    std::fflush(stdout);
    return true;
}

// Links: the platform docked 1 m off the edge of a static level (grid-40's triangles as a static
// mesh: ground, crates; beside it, 200 m along x, the shared level dungeon.obj, so that the level has
// links of its own to generate), its links to and from the level generated for where it stands
// (nl_navmesh_generate_cross_links, what a host calls when the platform comes to rest), against the
// anchor of generating the level's own links in full (nl_navmesh_generate_links), which is what
// regenerating without a bounded search would cost.
bool run_links(const Platform& level, const Platform& platform, const Options& o) {
    Side ground;
    ground.name = "links";
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    def.path_worker_count = 0;
    if (NL_FAILED(nl_world_create(&def, &ground.world))) return fail(ground.name, "nl_world_create");
    if (NL_FAILED(nl::test::add_generated_level(ground.world, level.mesh, 0, nullptr, &ground.mesh)))
        return fail(ground.name, "nl_mesh_add");
    const RigidPose aside = RigidPose::at(200.0f, 0.0f, 0.0f, 0.0f);
    nl_mesh_def dungeon = nl_default_mesh_def();
    dungeon.transform = aside.m;
    nl_mesh_id ignored{};
    if (NL_FAILED(nl_mesh_add_obj_file(ground.world, NAVLINK_LEVELS_DIR "/dungeon.obj", &dungeon, &ignored)))
        return fail(ground.name, "nl_mesh_add_obj_file");
    if (!ground.build(false, &ground.navmesh)) return false;
    Side deck;  // the platform, in the ground's world (which the ground side owns)
    deck.name = "links";
    deck.pose = RigidPose::at(level.half + 1.0f + platform.half, 0.0f, 0.0f, 0.0f, 0.0f);
    if (NL_FAILED(nl::test::add_generated_level(ground.world, platform.mesh, NL_MESH_MOVABLE, deck.pose.m, &deck.mesh)))
        return fail(deck.name, "nl_mesh_add");
    deck.world = ground.world;
    const bool built = deck.build(true, &deck.navmesh);
    deck.world = nullptr;
    if (!built) return false;
    nl_link_settings settings = nl_default_link_settings();
    std::vector<double> level_us, cross_us;
    nl_link_generation_report report = nl_link_generation_report_init();
    uint32_t level_links = 0, cross_links = 0;
    for (int r = 0; r < o.repeats; ++r) {
        double t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_generate_links(ground.world, ground.navmesh, &settings, nullptr, nullptr, &report)))
            return fail(ground.name, "nl_navmesh_generate_links");
        level_us.push_back(1000.0 * (nl::samples::now_ms() - t0));
        level_links = report.jump_links + report.drop_links;
        t0 = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_generate_cross_links(ground.world, ground.navmesh, deck.navmesh, 0.25f, &settings,
                                                      nullptr, nullptr, &report)))
            return fail(ground.name, "nl_navmesh_generate_cross_links");
        cross_us.push_back(1000.0 * (nl::samples::now_ms() - t0));
        cross_links = report.jump_links + report.drop_links;
    }
    std::printf(
        "# links: %s docked 1 m off the edge of %s (static, with dungeon.obj beside it): %u links of the level's own, "
        "%u between them; "
        "/rebuild here is over the level's full generation\n",
        platform.name.c_str(), level.name.c_str(), level_links, cross_links);
    const Spread whole = nl::bench::spread(level_us);
    const double nan = std::nan("");
    row("links", "level, full", "-", whole, whole.median, nan);
    row("links", "cross, docked", "-", nl::bench::spread(cross_us), whole.median, nan);
    std::fflush(stdout);
    return cross_links > 0 || fail(ground.name, "no cross link found for the docked platform");
}

std::vector<Platform> platforms() {
    std::vector<Platform> out(2);
    out[0].name = "box-12";
    out[0].mesh.add_box({{-6.0f, -0.5f, -6.0f}, {6.0f, 0.0f, 6.0f}});
    out[0].half = 6.0f;
    out[1].name = "grid-40";
    out[1].mesh.add_ground_grid(-20.0f, -20.0f, 20.0f, 20.0f, 0.5f, [](float, float) { return 0.0f; });
    out[1].half = 20.0f;
    out[1].crates = 4.0f;
    for (float x = -18.0f; x < 20.0f; x += 4.0f)
        for (float z = -18.0f; z < 20.0f; z += 4.0f)
            out[1].mesh.add_box({{x - 0.5f, 0.0f, z - 0.5f}, {x + 0.5f, 1.5f, z + 0.5f}});
    return out;
}

int usage() {
    std::fprintf(stderr, "usage: navlink-bench-surfaces [--repeats N] [--frames N] [--paths N] [--agents N,N,...]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) return usage();
        const char* value = argv[++i];
        const long n = std::strtol(value, nullptr, 10);
        if (arg == "--repeats" && n >= 1 && n <= 1000)
            o.repeats = int(n);
        else if (arg == "--frames" && n >= 1 && n <= 100000)
            o.frames = int(n);
        else if (arg == "--paths" && n >= 1 && n <= 100000)
            o.paths = int(n);
        else if (arg == "--agents") {
            o.counts.clear();
            std::stringstream list(value);
            std::string item;
            while (std::getline(list, item, ',')) {
                const long count = std::strtol(item.c_str(), nullptr, 10);
                if (count < 0 || count > 100000) return usage();
                o.counts.push_back(int(count));
            }
            std::sort(o.counts.begin(), o.counts.end());  // agents are added, never removed
        } else {
            return usage();
        }
    }
    std::printf(
        "# repeats=%d frames=%d paths=%d; microseconds per call (min, median, max over the repeats); "
        "/rebuild: median over the rebuild's; /static: median over the static copy's\n",
        o.repeats, o.frames, o.paths);
    std::printf("%-8s %-15s %6s %11s %11s %11s %9s %8s\n", "platform", "what", "agents", "min_us", "median_us",
                "max_us", "/rebuild", "/static");
    bool ok = true;
    uint32_t seed = 1;
    const std::vector<Platform> all = platforms();
    for (const Platform& p : all) ok = run(p, seed++, o) && ok;
    ok = run_links(all[1], all[0], o) && ok;
    return ok ? 0 : 1;
}
