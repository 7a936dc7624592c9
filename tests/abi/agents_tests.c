/*
 * Agents (navlink.h): added on the navmesh, sent to destinations, moved by nl_world_step; a jumper
 * takes a generated jump while a walker goes round by the bridge, as the events and states read in
 * bulk say; the trajectory of a link mid-flight; bad input refused with nothing changed; the same
 * states on 1 and 2 workers.
 */
#include "abi_test.h"
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Two 4 x 10 m platforms (tops at y = 0) 2 m apart along x, and a bridge between them at z 8-10; the
   navmesh is their tops, set in 0.3 m from every rim (five convex polygons). */
typedef struct gap_level {
    nl_world* world;
    nl_navmesh_id navmesh;
    nl_link_generation_report report;
} gap_level;

static void add_quad(float* v, uint32_t* idx, uint8_t* counts, uint32_t* nv, uint32_t* ni, uint32_t* np,
                     const float (*corners)[2], uint8_t n) {
    uint8_t k;
    for (k = 0; k < n; ++k) {
        v[3 * *nv] = corners[k][0], v[3 * *nv + 1] = 0.0f, v[3 * *nv + 2] = corners[k][1];
        idx[(*ni)++] = (*nv)++;
    }
    counts[(*np)++] = n;
}

static gap_level make_gap_level(int32_t workers) {
    static const float lo[3][3] = {{0, -1, 0}, {6, -1, 0}, {4, -1, 8}},
                       hi[3][3] = {{4, 0, 10}, {10, 0, 10}, {6, 0, 10}};
    static const float a1[4][2] = {{0.3f, 0.3f}, {0.3f, 8}, {3.7f, 8}, {3.7f, 0.3f}};
    static const float a2[5][2] = {{0.3f, 8}, {0.3f, 9.7f}, {4, 9.7f}, {4, 8}, {3.7f, 8}};
    static const float bridge[4][2] = {{4, 8}, {4, 9.7f}, {6, 9.7f}, {6, 8}};
    static const float b2[5][2] = {{6, 8}, {6, 9.7f}, {9.7f, 9.7f}, {9.7f, 8}, {6.3f, 8}};
    static const float b1[4][2] = {{6.3f, 0.3f}, {6.3f, 8}, {9.7f, 8}, {9.7f, 0.3f}};
    float v[3 * 22];
    uint32_t idx[22], nv = 0, ni = 0, np = 0, i;
    uint8_t counts[5];
    nl_navmesh_def def = nl_default_navmesh_def();
    gap_level g;
    memset(&g, 0, sizeof g);
    g.world = make_world(workers);
    for (i = 0; i < 3; ++i) {
        nl_mesh_id mesh;
        CHECK_OK(add_box_mesh(g.world, lo[i], hi[i], 0u, &mesh));
    }
    add_quad(v, idx, counts, &nv, &ni, &np, a1, 4);
    add_quad(v, idx, counts, &nv, &ni, &np, a2, 5);
    add_quad(v, idx, counts, &nv, &ni, &np, bridge, 4);
    add_quad(v, idx, counts, &nv, &ni, &np, b2, 5);
    add_quad(v, idx, counts, &nv, &ni, &np, b1, 4);
    def.vertices = v;
    def.vertex_count = nv;
    def.indices = idx;
    def.polygon_vertex_counts = counts;
    def.polygon_count = np;
    def.agent_type.radius = 0.3f;
    CHECK_OK(nl_navmesh_add(g.world, &def, &g.navmesh));
    g.report = nl_link_generation_report_init();
    CHECK_OK(nl_navmesh_generate_links(g.world, g.navmesh, NULL, NULL, NULL, &g.report));
    return g;
}

static nl_agent_id add_agent(const gap_level* g, float x, float z, float jump, uint64_t user) {
    nl_agent_def def = nl_default_agent_def();
    nl_agent_id id = {0u, 0u};
    def.navmesh = g->navmesh;
    def.position[0] = x, def.position[1] = 0.0f, def.position[2] = z;
    def.capabilities.radius = 0.3f;
    def.capabilities.max_jump_distance = jump;
    def.capabilities.max_jump_height = jump > 0.0f ? 1.0f : 0.0f;
    def.user_data = user;
    CHECK_OK(nl_agent_add(g->world, &def, &id));
    return id;
}

static nl_agent_info info_of(nl_world* world, nl_agent_id agent) {
    nl_agent_info info = nl_agent_info_init();
    CHECK_OK(nl_agent_get_info(world, agent, &info));
    return info;
}

static int same_agent(nl_agent_id a, nl_agent_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

static void defaults(void) {
    const nl_agent_def def = nl_default_agent_def();
    CHECK(def.size == sizeof def);
    CHECK(def.height == 2.0f && def.max_speed == 3.5f && def.max_acceleration == 8.0f);
    CHECK(fabsf(def.gravity - 9.81f) < 1e-6f && def.takeoff_speed == 0.0f && def.avoidance == 1);
    CHECK(def.capabilities.radius == 0.6f && def.capabilities.max_jump_distance == 0.0f);
    CHECK(def.navmesh.index1 == 0u && def.user_data == 0u);
    CHECK(nl_default_world_def().agent_paths_per_step == 32u);
}

static void walker_and_jumper(void) {
    gap_level g = make_gap_level(2);
    const nl_agent_id walker = add_agent(&g, 1.0f, 2.0f, 0.0f, 11u), jumper = add_agent(&g, 1.0f, 3.0f, 3.0f, 22u);
    const float walker_goal[3] = {9.0f, 0.0f, 2.0f}, jumper_goal[3] = {9.0f, 0.0f, 3.0f};
    int step, walker_links = 0, jumper_started = 0, jumper_finished = 0, arrivals = 0, ready = 0, saw_trajectory = 0;
    float walker_max_z = 0.0f;
    CHECK(g.report.jump_links > 0u);
    CHECK_OK(nl_agent_set_destination(g.world, walker, walker_goal));
    CHECK_OK(nl_agent_set_destination(g.world, jumper, jumper_goal));
    for (step = 0; step < 30 * 20 && arrivals < 2; ++step) {
        nl_agent_event events[16];
        nl_agent_info infos[4];
        uint32_t n = 0, k;
        CHECK_OK(nl_world_step(g.world, 1.0f / 30.0f));
        events[0] = nl_agent_event_init();
        CHECK_OK(nl_world_get_agent_events(g.world, events, 16, &n));
        for (k = 0; k < n; ++k) {
            const int is_walker = same_agent(events[k].agent, walker);
            CHECK(events[k].size == sizeof events[k]);
            CHECK(events[k].user_data == (is_walker ? 11u : 22u));
            if (events[k].kind == NL_AGENT_EVENT_LINK_STARTED) is_walker ? ++walker_links : ++jumper_started;
            if (events[k].kind == NL_AGENT_EVENT_LINK_FINISHED && !is_walker) ++jumper_finished;
            if (events[k].kind == NL_AGENT_EVENT_ARRIVED) ++arrivals;
            if (events[k].kind == NL_AGENT_EVENT_PATH_READY) {
                ++ready;
                CHECK(events[k].reason == NL_AGENT_REASON_DESTINATION_SET);
            }
        }
        infos[0] = nl_agent_info_init();
        CHECK_OK(nl_world_get_agents(g.world, infos, 4, &n));
        CHECK(n == 2u);
        for (k = 0; k < n; ++k) {
            if (same_agent(infos[k].id, walker) && infos[k].position[2] > walker_max_z)
                walker_max_z = infos[k].position[2];
            if (same_agent(infos[k].id, jumper) && infos[k].state == NL_AGENT_JUMPING) {
                nl_agent_trajectory t = nl_agent_trajectory_init();
                CHECK_OK(nl_agent_get_trajectory(g.world, jumper, &t));
                CHECK(t.kind == NL_TRAJECTORY_ARC && t.duration > 0.0f && t.elapsed >= 0.0f && t.elapsed <= t.duration);
                CHECK(t.link.index1 == infos[k].link.index1 && t.apex[1] > t.from[1] && t.apex[1] > t.to[1]);
                CHECK(infos[k].link_progress >= 0.0f && infos[k].link_progress <= 1.0f);
                ++saw_trajectory;
            }
        }
    }
    CHECK(arrivals == 2 && ready == 2);
    CHECK(walker_links == 0 && walker_max_z > 8.0f); /* round by the bridge */
    CHECK(jumper_started == 1 && jumper_finished == 1 && saw_trajectory > 0);
    CHECK(info_of(g.world, walker).state == NL_AGENT_ARRIVED && info_of(g.world, jumper).state == NL_AGENT_ARRIVED);
    {
        /* On the ground: no trajectory. An arrived agent has no corners left. */
        nl_agent_trajectory t = nl_agent_trajectory_init();
        nl_path_point corners[4];
        uint32_t n = 77u;
        t.duration = 5.0f;
        CHECK_OK(nl_agent_get_trajectory(g.world, jumper, &t));
        CHECK(t.kind == NL_TRAJECTORY_NONE && t.link.index1 == 0u && t.duration == 0.0f && t.size == sizeof t);
        corners[0] = nl_path_point_init();
        CHECK_OK(nl_agent_get_corners(g.world, walker, corners, 4, &n));
        CHECK(n <= 1u);
    }
    nl_world_destroy(g.world);
}

static void bad_input(void) {
    gap_level g = make_gap_level(1);
    const nl_agent_id agent = add_agent(&g, 1.0f, 2.0f, 0.0f, 0u);
    const nl_agent_id null_id = {0u, 0u};
    const float off[3] = {5.0f, 0.0f, 2.0f}, nan_point[3] = {NAN, 0.0f, 0.0f}, goal[3] = {3.0f, 0.0f, 5.0f};
    nl_agent_def def = nl_default_agent_def();
    nl_agent_id out = {0u, 0u};
    nl_agent_event events[4];
    uint32_t n = 0;
    CHECK_INVALID(nl_world_step(g.world, NAN), "dt");
    CHECK_INVALID(nl_world_step(g.world, -0.1f), "dt");
    CHECK_INVALID(nl_world_step(g.world, INFINITY), "dt");
    CHECK_INVALID(nl_world_step(NULL, 0.1f), "world");
    CHECK_INVALID(nl_agent_set_speed(g.world, agent, -1.0f, 1.0f), "max_speed");
    CHECK_INVALID(nl_agent_set_speed(g.world, agent, 1.0f, NAN), "max_acceleration");
    CHECK_FAIL(nl_agent_set_destination(g.world, agent, off), NL_STATUS_NOT_FOUND, "nearest navmesh point");
    CHECK(info_of(g.world, agent).has_destination == 0); /* not kept */
    CHECK_INVALID(nl_agent_set_destination(g.world, agent, nan_point), "point");
    CHECK_INVALID(nl_agent_set_destination(g.world, agent, NULL), "point");
    CHECK_FAIL(nl_agent_set_destination(g.world, null_id, goal), NL_STATUS_INVALID_HANDLE, "agent");
    CHECK(nl_agent_is_valid(g.world, null_id) == 0);

    def.navmesh = g.navmesh;
    memcpy(def.position, off, sizeof off);
    CHECK_FAIL(nl_agent_add(g.world, &def, &out), NL_STATUS_NOT_FOUND, "def->position is not on the navmesh");
    def.position[0] = 1.0f;
    def.max_speed = -2.0f;
    CHECK_INVALID(nl_agent_add(g.world, &def, &out), "def->max_speed");
    def.max_speed = 3.0f;
    def.capabilities.radius = NAN;
    CHECK_INVALID(nl_agent_add(g.world, &def, &out), "def->capabilities.radius");
    def.capabilities.radius = 0.3f;
    def.size = 4;
    CHECK_INVALID(nl_agent_add(g.world, &def, &out), "def->size");
    CHECK(out.index1 == 0u);

    /* Its navmesh removed: the agent fails, with its event; nothing crashes. */
    CHECK_OK(nl_agent_set_destination(g.world, agent, goal));
    CHECK_OK(nl_world_step(g.world, 0.1f));
    CHECK_OK(nl_navmesh_remove(g.world, g.navmesh));
    CHECK_OK(nl_world_step(g.world, 0.1f));
    events[0] = nl_agent_event_init();
    CHECK_OK(nl_world_get_agent_events(g.world, events, 4, &n));
    CHECK(n == 1u && events[0].kind == NL_AGENT_EVENT_FAILED && events[0].reason == NL_AGENT_REASON_NAVMESH_REMOVED);
    CHECK(info_of(g.world, agent).state == NL_AGENT_FAILED);
    CHECK_OK(nl_agent_remove(g.world, agent));
    CHECK(nl_agent_is_valid(g.world, agent) == 0);
    CHECK_FAIL(nl_agent_remove(g.world, agent), NL_STATUS_INVALID_HANDLE, "agent");
    nl_world_destroy(g.world);
}

/* Thirty agents crossing both ways for 600 steps: the same states, bit for bit, on 1 and 2 workers. */
static void same_on_any_thread_count(void) {
    nl_agent_info result[2][32];
    int w;
    for (w = 0; w < 2; ++w) {
        gap_level g = make_gap_level(w + 1);
        uint32_t k, n = 0;
        int step;
        for (k = 0; k < 30; ++k) {
            const int left = k % 2 == 0;
            const float z = 0.6f + 0.3f * (float)k;
            const float goal[3] = {left ? 8.5f : 1.5f, 0.0f, 9.4f - 0.3f * (float)k};
            const nl_agent_id a = add_agent(&g, left ? 1.0f + 0.4f * (float)(k % 5) : 7.0f + 0.4f * (float)(k % 5), z,
                                            k % 3 == 0 ? 3.0f : 0.0f, k);
            CHECK_OK(nl_agent_set_destination(g.world, a, goal));
        }
        for (step = 0; step < 600; ++step) CHECK_OK(nl_world_step(g.world, 1.0f / 60.0f));
        result[w][0] = nl_agent_info_init();
        CHECK_OK(nl_world_get_agents(g.world, result[w], 32, &n));
        CHECK(n == 30u);
        /* Every handle's generation carries its world's tag, which differs from world to world. */
        for (k = 0; k < n; ++k) {
            result[w][k].id.revision = 0;
            result[w][k].link.revision = 0;
            result[w][k].navmesh.revision = 0;
            result[w][k].carrier.revision = 0;
        }
        nl_world_destroy(g.world);
    }
    CHECK_MSG(memcmp(result[0], result[1], 30 * sizeof result[0][0]) == 0,
              "1 and 2 workers moved the agents differently");
}

ABI_SECTION(agents, ABI_CASE(defaults), ABI_CASE(walker_and_jumper), ABI_CASE(bad_input),
            ABI_CASE(same_on_any_thread_count));
