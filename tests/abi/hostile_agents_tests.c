/*
 * The hostile cases of navlink/agents.h: A.agent walks across the gap (its path planned),
 * A.flyer is on a link over it.
 */
#include "hostile_fixtures.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

static const float k_agent_goal[3] = {8.0f, 0.0f, -1.0f}; /* on the far platform */
static const float k_agent_spot[3] = {-7.0f, 0.0f, 1.0f}; /* on the near platform */

/* An agent's info, read after the checks of a case (it records a status of its own). */
static nl_agent_info agent_info(nl_agent_id id) {
    nl_agent_info info = nl_agent_info_init();
    const nl_status status = nl_agent_get_info(A.world, id, &info);
    EXPECT(status == NL_STATUS_SUCCESS, "nl_agent_get_info: %s", nl_get_last_error_message());
    return info;
}

static int finite3(const float* p) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

/* The navmesh point nearest `p` on A's navmesh is within `within` metres of it. */
static int on_navmesh(nl_navmesh_id navmesh, const float* p, float within) {
    const float extents[3] = {within, within, within};
    nl_nav_point near;
    memset(&near, 0, sizeof near);
    return NL_SUCCEEDED(nl_navmesh_find_nearest(A.world, navmesh, p, 1, extents, &near)) && near.found;
}

/* nl_agent_add: the def's navmesh is its id. */
static const nl_agent_def* g_agent_def;
static nl_status agent_add_id_call(nl_world* w, raw_id id, void* out) {
    nl_agent_def def = *g_agent_def;
    def.navmesh = AS(nl_navmesh_id, id);
    return nl_agent_add(w, &def, (nl_agent_id*)out);
}
static nl_status agent_add_def_call(nl_world* world, const void* def, void* out) {
    return nl_agent_add(world, (const nl_agent_def*)def, (nl_agent_id*)out);
}
/* An added agent stands idle, valid; removed again, the world is as it was. */
static void remove_agent_out(const void* out) {
    nl_agent_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_agent_is_valid(A.world, id) == 1, "the new agent is not valid");
    EXPECT(agent_info(id).state == NL_AGENT_IDLE, "the new agent is not idle");
    EXPECT_OK(nl_agent_remove(A.world, id));
}
static const def_function k_agent_add = {
    "nl_agent_add", agent_add_def_call, sizeof(nl_agent_id), remove_agent_out, 0, 0, 1};

static const float_field k_agent_def_floats[] = {
    FLOAT_FIELD(nl_agent_def, height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_jump_distance, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_jump_height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.max_drop_height, 1),
    FLOAT_FIELD(nl_agent_def, capabilities.radius, 1),
    FLOAT_FIELD(nl_agent_def, max_speed, 1),
    FLOAT_FIELD(nl_agent_def, max_acceleration, 1),
    FLOAT_FIELD(nl_agent_def, gravity, 1),
    FLOAT_FIELD(nl_agent_def, takeoff_speed, 1),
    FLOAT_FIELD(nl_agent_def, position, 3),
    FLOAT_FIELD(nl_agent_def, give_up_seconds, 1),
};

#define SET_U8(type, member, v)                                 \
    {                                                           \
        offsetof(type, member), sizeof(uint8_t), { .u32 = (v) } \
    }
static const def_case k_agent_defs[] = {
    {"def->size small (8 short of the first release)",
     INVALID,
     "def->size",
     {SET_U32(nl_agent_def, size, (uint32_t)offsetof(nl_agent_def, give_up_seconds) - 8u)}},
    {"def->size of the first release (allowed: give_up_seconds its default)",
     ALLOWED,
     NULL,
     {SET_U32(nl_agent_def, size, (uint32_t)offsetof(nl_agent_def, give_up_seconds))}},
    {"def->size odd (sizeof + 1: no struct's size)",
     INVALID,
     "def->size",
     {SET_U32(nl_agent_def, size, (uint32_t)sizeof(nl_agent_def) + 1u)}},
    {"def->height 0", INVALID, "def->height", {SET_F32(nl_agent_def, height, 0.0f)}},
    {"def->height negative", INVALID, "def->height", {SET_F32(nl_agent_def, height, -2.0f)}},
    {"def->max_speed 0", INVALID, "def->max_speed", {SET_F32(nl_agent_def, max_speed, 0.0f)}},
    {"def->max_speed negative", INVALID, "def->max_speed", {SET_F32(nl_agent_def, max_speed, -3.5f)}},
    {"def->max_acceleration 0", INVALID, "def->max_acceleration", {SET_F32(nl_agent_def, max_acceleration, 0.0f)}},
    {"def->max_acceleration negative",
     INVALID,
     "def->max_acceleration",
     {SET_F32(nl_agent_def, max_acceleration, -8.0f)}},
    {"def->gravity 0", INVALID, "def->gravity", {SET_F32(nl_agent_def, gravity, 0.0f)}},
    {"def->gravity negative (upward)", INVALID, "def->gravity", {SET_F32(nl_agent_def, gravity, -9.81f)}},
    {"def->takeoff_speed negative", INVALID, "def->takeoff_speed", {SET_F32(nl_agent_def, takeoff_speed, -1.0f)}},
    {"def->give_up_seconds negative", INVALID, "def->give_up_seconds", {SET_F32(nl_agent_def, give_up_seconds, -1.0f)}},
    {"def->give_up_seconds 5 (allowed)", ALLOWED, NULL, {SET_F32(nl_agent_def, give_up_seconds, 5.0f)}},
    {"def->capabilities.max_jump_distance negative",
     INVALID,
     "def->capabilities.max_jump_distance",
     {SET_F32(nl_agent_def, capabilities.max_jump_distance, -1.0f)}},
    {"def->capabilities.max_jump_height negative",
     INVALID,
     "def->capabilities.max_jump_height",
     {SET_F32(nl_agent_def, capabilities.max_jump_height, -1.0f)}},
    {"def->capabilities.max_drop_height negative",
     INVALID,
     "def->capabilities.max_drop_height",
     {SET_F32(nl_agent_def, capabilities.max_drop_height, -1.0f)}},
    {"def->capabilities.radius negative",
     INVALID,
     "def->capabilities.radius",
     {SET_F32(nl_agent_def, capabilities.radius, -0.4f)}},
    {"def->position off the navmesh (10 m above)",
     NL_STATUS_NOT_FOUND,
     "def->position is not on the navmesh",
     {SET_F32(nl_agent_def, position[1], 10.0f)}},
    {"def->position off the navmesh (nothing within 25 m)",
     NL_STATUS_NOT_FOUND,
     "def->position is not on the navmesh",
     {SET_F32(nl_agent_def, position[0], 100.0f)}},
    {"def->position beyond the limit (2e9)", INVALID, "def->position", {SET_F32(nl_agent_def, position[2], 2.0e9f)}},
    {"def->position 1 m above the navmesh (allowed: put on it)",
     ALLOWED,
     NULL,
     {SET_F32(nl_agent_def, position[1], 1.0f)}},
    {"def->capabilities.radius 0 (allowed: a point body)",
     ALLOWED,
     NULL,
     {SET_F32(nl_agent_def, capabilities.radius, 0.0f)}},
    {"def->takeoff_speed 12 (allowed: a jump's time from it)",
     ALLOWED,
     NULL,
     {SET_F32(nl_agent_def, takeoff_speed, 12.0f)}},
    {"def->avoidance 0 (allowed)", ALLOWED, NULL, {SET_U8(nl_agent_def, avoidance, 0u)}},
};
#undef SET_U8

static void group_agent_add(void) {
    static const id_function f = {
        "nl_agent_add", "def->navmesh", "out_id", sizeof(nl_agent_id), 0, 0, agent_add_id_call, 0};
    const nl_agent_def valid = jumper_def(A.navmesh, -6.0f, -1.0f);
    g_agent_def = &valid;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    def_function_cases(&k_agent_add, &valid, sizeof valid);
    def_cases("nl_agent_add", &valid, sizeof valid, k_agent_defs, sizeof k_agent_defs / sizeof *k_agent_defs,
              def_refuses, def_accepts);
    bad_float_fields("nl_agent_add", "def", &valid, sizeof valid, k_agent_def_floats,
                     sizeof k_agent_def_floats / sizeof *k_agent_def_floats, def_refuses);
    CASE("nl_agent_add", "def->navmesh the lift's (allowed: an agent of another navmesh)") {
        nl_agent_def def = jumper_def(A.host_navmesh, 42.0f, 0.0f);
        nl_agent_id id;
        memset(&id, 0, sizeof id);
        EXPECT_OK(nl_agent_add(A.world, &def, &id));
        remove_agent_out(&id);
    }
}

/* The functions that take an agent id, with a valid rest (a point on the navmesh, capabilities). */
static const float* g_agent_point = k_agent_goal;
static nl_agent_capabilities g_agent_capabilities;
ID_CALL(agent_remove_call, nl_agent_id, nl_agent_remove)
ID_VALID_CALL(agent_is_valid_call, nl_agent_id, nl_agent_is_valid)
ID_CALL(agent_stop_call, nl_agent_id, nl_agent_stop)
static nl_status agent_set_destination_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_destination(w, AS(nl_agent_id, id), g_agent_point);
}
static nl_status agent_teleport_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_teleport(w, AS(nl_agent_id, id), g_agent_point);
}
static nl_status agent_set_capabilities_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_capabilities(w, AS(nl_agent_id, id), &g_agent_capabilities);
}
static nl_status agent_set_speed_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_agent_set_speed(w, AS(nl_agent_id, id), 5.0f, 10.0f);
}
ID_OUT_CALL(agent_get_info_call, nl_agent_id, nl_agent_info, nl_agent_get_info)
ID_OUT_CALL(agent_get_trajectory_call, nl_agent_id, nl_agent_trajectory, nl_agent_get_trajectory)
/* Corners into 16 elements of the right size (only the id is wrong), the count untouched too. */
static nl_status agent_corners_id_call(nl_world* w, raw_id id, void* out) {
    uint32_t count;
    nl_status status;
    fill(&count, sizeof count);
    status = nl_agent_get_corners(w, AS(nl_agent_id, id), (nl_path_point*)out, 16u, &count);
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}
static const id_function k_agent_functions[] = {
    {"nl_agent_remove", "agent", NULL, 0, 0, 0, agent_remove_call, 0},
    {"nl_agent_is_valid", "agent", NULL, 0, 0, 1, agent_is_valid_call, 0},
    {"nl_agent_set_destination", "agent", NULL, 0, 0, 0, agent_set_destination_call, 0},
    {"nl_agent_stop", "agent", NULL, 0, 0, 0, agent_stop_call, 0},
    {"nl_agent_teleport", "agent", NULL, 0, 0, 0, agent_teleport_call, 0},
    {"nl_agent_set_capabilities", "agent", NULL, 0, 0, 0, agent_set_capabilities_call, 0},
    {"nl_agent_set_speed", "agent", NULL, 0, 0, 0, agent_set_speed_call, 0},
    {"nl_agent_get_info", "agent", "out_info", sizeof(nl_agent_info), 1, 0, agent_get_info_call, 0},
    {"nl_agent_get_corners", "agent", "out_points", sizeof(nl_path_point), 1, 0, agent_corners_id_call, 1},
    {"nl_agent_get_trajectory", "agent", "out_trajectory", sizeof(nl_agent_trajectory), 1, 0, agent_get_trajectory_call,
     0},
};

/* An id of another kind passed as an agent's: refused as any bad id (an nl_agent_is_valid answers 0). */
static void wrong_kind_case(const id_function* f, const char* what, raw_id id) {
    CASE(f->function, "%s wrong kind (%s)%s", f->param, what, f->answers ? " (an answer, not an error)" : "") {
        aligned_buffer out;
        nl_status status;
        const size_t skip = f->growable ? sizeof(uint32_t) : 0u;
        fill(out.bytes, sizeof out.bytes);
        if (f->growable) set_size(out.bytes, (uint32_t)f->out_size);
        status = f->call(A.world, id, f->out_name ? out.bytes : NULL);
        if (f->answers)
            EXPECT_OK(status);
        else
            EXPECT_BAD_HANDLE(A.world, status, "agent");
        EXPECT_UNTOUCHED(out.bytes + skip, sizeof out.bytes - skip, f->out_name ? f->out_name : "memory");
    }
}

/* The id cases of an agent function: the world NULL, the output NULL, every bad id, and ids of the
   other kinds, A's navmesh id last: it sits in a slot of the same number and counter as A's agent,
   and only the kind each id carries tells them apart. */
static void agent_id_cases(size_t which) {
    const id_function* f = &k_agent_functions[which];
    g_agent_capabilities = jumper_def(A.navmesh, 0.0f, 0.0f).capabilities;
    g_agent_point = which == 4 ? k_agent_spot : k_agent_goal;
    id_cases(f, RAW(A.agent), RAW(A.stale_agent), RAW(B.agent));
    wrong_kind_case(f, "A's link id", RAW(A.link));
    wrong_kind_case(f, "A's plugin id", RAW(A.plugin));
    wrong_kind_case(f, "A's path ticket", RAW(A.pending_ticket));
    wrong_kind_case(f, "B's navmesh id", RAW(B.navmesh));
    wrong_kind_case(f, "A's navmesh id", RAW(A.navmesh));
}

static void group_agent_remove(void) { agent_id_cases(0); }
static void group_agent_is_valid(void) {
    CASE("nl_agent_is_valid", "agent live (1, the record SUCCESS)") {
        fail_on_purpose();
        EXPECT(nl_agent_is_valid(A.world, A.agent) == 1 && nl_agent_is_valid(A.world, A.flyer) == 1,
               "a live agent is not valid");
        EXPECT(nl_get_last_status() == NL_STATUS_SUCCESS, "the record is not SUCCESS");
    }
    agent_id_cases(1);
}
static void group_agent_stop(void) { agent_id_cases(3); }

/* nl_agent_set_destination and nl_agent_teleport: the point made bad; nothing changes (the
   fingerprint: a refused destination is not kept, a refused teleport moves nobody). */
typedef nl_status agent_point_fn(nl_world* world, nl_agent_id agent, const float* point);
static void agent_point_cases(const char* function, agent_point_fn* call, const float* valid) {
    size_t v;
    int k;
    CASE(function, "point NULL") { EXPECT_INVALID(A.world, call(A.world, A.agent, NULL), "point"); }
    CASE(function, "point NULL (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, call(A.world, A.stale_agent, NULL), "agent");
    }
    for (k = 0; k < 3; ++k) {
        for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
            CASE(function, "point[%d] %s", k, k_bad_floats[v].name) {
                float p[3];
                memcpy(p, valid, sizeof p);
                p[k] = k_bad_floats[v].value;
                EXPECT_INVALID(A.world, call(A.world, A.agent, p), "point");
            }
        }
    }
    CASE(function, "point[2] beyond the limit (2e9)") {
        float p[3];
        memcpy(p, valid, sizeof p);
        p[2] = 2.0e9f;
        EXPECT_INVALID(A.world, call(A.world, A.agent, p), "point");
    }
    CASE(function, "point off the navmesh (10 m above: NOT_FOUND, nothing kept)") {
        float p[3];
        memcpy(p, valid, sizeof p);
        p[1] = 10.0f;
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND, "point is not on the navmesh");
    }
    CASE(function, "point off the navmesh (over the gap, 20 m above the pit's floor)") {
        const float p[3] = {0.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND, "point is not on the navmesh");
    }
    CASE(function, "point off the navmesh (nothing within 25 m)") {
        const float p[3] = {200.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, call(A.world, A.agent, p), NL_STATUS_NOT_FOUND,
                       "point is not on the navmesh (nothing within 25 m)");
    }
}

static void group_agent_set_destination(void) {
    agent_point_cases("nl_agent_set_destination", nl_agent_set_destination, k_agent_goal);
    CASE("nl_agent_set_destination", "agent in the air (allowed: it lands first, then plans)") {
        nl_agent_info info;
        EXPECT_OK(nl_agent_set_destination(A.world, A.flyer, k_agent_goal));
        info = agent_info(A.flyer);
        EXPECT(in_the_air(info.state) && info.has_destination && fabsf(info.destination[0] - k_agent_goal[0]) < 0.5f,
               "state %u, has_destination %u", (unsigned)info.state, (unsigned)info.has_destination);
        fixture_refresh();
    }
    agent_id_cases(2);
}

static void group_agent_teleport(void) {
    agent_point_cases("nl_agent_teleport", nl_agent_teleport, k_agent_spot);
    CASE("nl_agent_teleport", "agent in the air (taking a link: refused, nothing changed)") {
        EXPECT_INVALID(A.world, nl_agent_teleport(A.world, A.flyer, k_agent_spot), "taking a link");
    }
    CASE("nl_agent_teleport", "agent in the air, point off the navmesh (NOT_FOUND)") {
        const float p[3] = {200.0f, 0.0f, 0.0f};
        EXPECT_FAILURE(A.world, nl_agent_teleport(A.world, A.flyer, p), NL_STATUS_NOT_FOUND, "not on the navmesh");
    }
    agent_id_cases(4);
}

/* nl_agent_set_capabilities: each figure NaN, infinite, negative; refused with nothing changed. */
static const float_field k_capability_floats[] = {
    FLOAT_FIELD(nl_agent_capabilities, max_jump_distance, 1),
    FLOAT_FIELD(nl_agent_capabilities, max_jump_height, 1),
    FLOAT_FIELD(nl_agent_capabilities, max_drop_height, 1),
    FLOAT_FIELD(nl_agent_capabilities, radius, 1),
};
static const def_case k_capability_defs[] = {
    {"capabilities->max_jump_distance negative",
     INVALID,
     "max_jump_distance",
     {SET_F32(nl_agent_capabilities, max_jump_distance, -1.0f)}},
    {"capabilities->max_jump_height negative",
     INVALID,
     "max_jump_height",
     {SET_F32(nl_agent_capabilities, max_jump_height, -1.0f)}},
    {"capabilities->max_drop_height negative",
     INVALID,
     "max_drop_height",
     {SET_F32(nl_agent_capabilities, max_drop_height, -1.0f)}},
    {"capabilities->radius negative", INVALID, "radius", {SET_F32(nl_agent_capabilities, radius, -0.4f)}},
    {"capabilities->radius -0 (allowed: 0)", ALLOWED, NULL, {SET_F32(nl_agent_capabilities, radius, -0.0f)}},
    {"capabilities->max_jump_distance 0 (allowed: no jumps, it plans again)",
     ALLOWED,
     NULL,
     {SET_F32(nl_agent_capabilities, max_jump_distance, 0.0f)}},
};
static void capabilities_refused(const void* capabilities, nl_status detail, const char* needle) {
    EXPECT_FAILURE(A.world, nl_agent_set_capabilities(A.world, A.agent, (const nl_agent_capabilities*)capabilities),
                   detail, needle);
}
/* Accepted: the agent keeps walking (it plans again); the worlds as they are now are the reference. */
static void capabilities_accepted(const void* capabilities) {
    nl_agent_info info;
    EXPECT_OK(nl_agent_set_capabilities(A.world, A.agent, (const nl_agent_capabilities*)capabilities));
    info = agent_info(A.agent);
    EXPECT(info.state == NL_AGENT_WALKING && info.has_destination, "state %u", (unsigned)info.state);
    fixture_refresh();
}

static void group_agent_set_capabilities(void) {
    const nl_agent_capabilities valid = jumper_def(A.navmesh, 0.0f, 0.0f).capabilities;
    CASE("nl_agent_set_capabilities", "capabilities NULL") {
        EXPECT_INVALID(A.world, nl_agent_set_capabilities(A.world, A.agent, NULL), "capabilities");
    }
    CASE("nl_agent_set_capabilities", "capabilities NULL (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_capabilities(A.world, A.stale_agent, NULL), "agent");
    }
    bad_float_fields("nl_agent_set_capabilities", "capabilities", &valid, sizeof valid, k_capability_floats,
                     sizeof k_capability_floats / sizeof *k_capability_floats, capabilities_refused);
    def_cases("nl_agent_set_capabilities", &valid, sizeof valid, k_capability_defs,
              sizeof k_capability_defs / sizeof *k_capability_defs, capabilities_refused, capabilities_accepted);
    agent_id_cases(5);
}

/* nl_agent_set_speed: each figure NaN, infinite, 0 and negative; refused with nothing changed. */
static void group_agent_set_speed(void) {
    static const struct {
        const char* what;
        float value;
    } bad[] = {{"NaN", NAN}, {"inf", INFINITY}, {"-inf", -INFINITY}, {"0", 0.0f}, {"-0", -0.0f}, {"negative", -1.0f}};
    size_t v;
    int k;
    for (k = 0; k < 2; ++k) {
        for (v = 0; v < sizeof bad / sizeof *bad; ++v) {
            const char* name = k == 0 ? "max_speed" : "max_acceleration";
            CASE("nl_agent_set_speed", "%s %s", name, bad[v].what) {
                const float speed = k == 0 ? bad[v].value : 5.0f, acceleration = k == 1 ? bad[v].value : 10.0f;
                EXPECT_INVALID(A.world, nl_agent_set_speed(A.world, A.agent, speed, acceleration), name);
            }
        }
    }
    CASE("nl_agent_set_speed", "max_speed NaN (agent stale too: the id is reported)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_speed(A.world, A.stale_agent, NAN, 10.0f), "agent");
    }
    agent_id_cases(6);
}

/* Every agent of A: its state finite, standing on its navmesh or on its link's trajectory. */
static void expect_agents_sane(const char* when) {
    nl_agent_info infos[8];
    uint32_t n = 0, i;
    memset(infos, 0, sizeof infos);
    infos[0].size = sizeof infos[0];
    EXPECT(NL_SUCCEEDED(nl_world_get_agents(A.world, infos, 8, &n)), "nl_world_get_agents: %s",
           nl_get_last_error_message());
    for (i = 0; i < n && i < 8; ++i) {
        const nl_agent_info* a = &infos[i];
        EXPECT(finite3(a->position) && finite3(a->velocity) && isfinite(a->link_progress),
               "%s: agent %u at (%g, %g, %g), velocity (%g, %g, %g)", when, (unsigned)i, a->position[0], a->position[1],
               a->position[2], a->velocity[0], a->velocity[1], a->velocity[2]);
        EXPECT(a->state <= NL_AGENT_FAILED, "%s: agent %u in state %u", when, (unsigned)i, (unsigned)a->state);
        if (!in_the_air(a->state))
            EXPECT(on_navmesh(A.navmesh, a->position, 0.5f), "%s: agent %u at (%g, %g, %g) is off its navmesh", when,
                   (unsigned)i, a->position[0], a->position[1], a->position[2]);
    }
}

static void group_world_step(void) {
    static const struct {
        const char* what;
        float dt;
    } bad[] = {{"dt NaN", NAN},
               {"dt inf", INFINITY},
               {"dt -inf", -INFINITY},
               {"dt negative (-0.1)", -0.1f},
               {"dt negative (-FLT_TRUE_MIN: barely)", -FLT_TRUE_MIN},
               {"dt negative (-FLT_MAX)", -FLT_MAX}};
    size_t i;
    CASE("nl_world_step", "world NULL") { EXPECT_INVALID(NULL, nl_world_step(NULL, 0.1f), "world"); }
    for (i = 0; i < sizeof bad / sizeof *bad; ++i) {
        CASE("nl_world_step", "%s (refused: nobody moves, the last step's events stay)", bad[i].what) {
            EXPECT_INVALID(A.world, nl_world_step(A.world, bad[i].dt), "dt");
        }
    }
    CASE("nl_world_step", "dt 0 (allowed: nothing changes, the last step's events stay)") {
        EXPECT_OK(nl_world_step(A.world, 0.0f));
    }
    CASE("nl_world_step", "dt -0 (allowed: 0)") { EXPECT_OK(nl_world_step(A.world, -0.0f)); }
    CASE("nl_world_step", "dt FLT_TRUE_MIN (allowed: a step too short to move)") {
        EXPECT_OK(nl_world_step(A.world, FLT_TRUE_MIN));
        expect_agents_sane("after a denormal step");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (1e6 s: allowed; every agent finite, on its navmesh)") {
        EXPECT_OK(nl_world_step(A.world, 1.0e6f));
        expect_agents_sane("after 1e6 s");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (FLT_MAX: allowed; every agent finite, on its navmesh)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_agent_id walker;
        memset(&walker, 0, sizeof walker);
        EXPECT_OK(nl_agent_add(A.world, &def, &walker));
        EXPECT_OK(nl_agent_set_destination(A.world, walker, k_agent_goal));
        EXPECT_OK(nl_world_step(A.world, 0.001f)); /* its path */
        EXPECT_OK(nl_world_step(A.world, FLT_MAX));
        expect_agents_sane("after FLT_MAX s");
        EXPECT_OK(nl_world_step(A.world, FLT_MAX));
        expect_agents_sane("after twice FLT_MAX s");
        fixture_refresh();
    }
    CASE("nl_world_step", "dt huge (1 s) with max_speed and max_acceleration FLT_MAX (allowed; every agent finite)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_agent_id runner;
        memset(&runner, 0, sizeof runner);
        EXPECT_OK(nl_agent_add(A.world, &def, &runner));
        EXPECT_OK(nl_agent_set_speed(A.world, runner, FLT_MAX, FLT_MAX));
        EXPECT_OK(nl_agent_set_destination(A.world, runner, k_agent_goal));
        EXPECT_OK(nl_world_step(A.world, 1.0f));
        expect_agents_sane("after 1 s at FLT_MAX m/s");
        EXPECT_OK(nl_world_step(A.world, 1.0f));
        expect_agents_sane("after 2 s at FLT_MAX m/s");
        fixture_refresh();
    }
}

static nl_status agent_info_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_agent_get_info(A.world, A.agent, (nl_agent_info*)out);
}

static void group_agent_get_info(void) {
    CASE("nl_agent_get_info", "agent live (allowed: its id, state, user_data)") {
        nl_agent_info info;
        fill(&info, sizeof info);
        info.size = sizeof info;
        EXPECT_OK(nl_agent_get_info(A.world, A.agent, &info));
        EXPECT(info.size == sizeof info && info.id.index1 == A.agent.index1 && info.id.revision == A.agent.revision &&
                   info.state == NL_AGENT_WALKING && info.user_data == 7u && info.has_destination == 1u &&
                   info.corners_ahead > 0u && finite3(info.position),
               "size %u, state %u, user_data %llu", (unsigned)info.size, (unsigned)info.state,
               (unsigned long long)info.user_data);
    }
    agent_id_cases(7);
    out_element_sizes("nl_agent_get_info", "out_info", sizeof(nl_agent_info), agent_info_into);
}

static nl_status get_agents(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_agents(w, (nl_agent_info*)out, capacity, count);
}
static nl_status agents_into(void* out, uint32_t* written) {
    return nl_world_get_agents(A.world, (nl_agent_info*)out, 256u, written);
}

static void group_world_get_agents(void) {
    g_growable_items = 1;
    world_list_cases("nl_world_get_agents", "out_infos", sizeof(nl_agent_info), 2u, get_agents);
    g_growable_items = 0;
    out_element_sizes("nl_world_get_agents", "out_infos", sizeof(nl_agent_info), agents_into);
}

static uint32_t corner_count(nl_agent_id agent) {
    uint32_t n = 0;
    if (NL_FAILED(nl_agent_get_corners(A.world, agent, NULL, 0, &n))) fixture_failed("nl_agent_get_corners");
    return n;
}
static nl_status call_corners(void* out, uint32_t capacity, uint32_t* count) {
    return nl_agent_get_corners(A.world, A.agent, (nl_path_point*)out, capacity, count);
}
static nl_status corners_into(void* out, uint32_t* written) {
    return nl_agent_get_corners(A.world, A.agent, (nl_path_point*)out, 256u, written);
}

static void group_agent_get_corners(void) {
    const uint32_t corners = corner_count(A.agent);
    if (corners == 0u) fixture_failed("the walker has no corners ahead");
    agent_id_cases(8);
    g_growable_items = 1;
    list_cases("nl_agent_get_corners", "out_points", sizeof(nl_path_point), corners, call_corners);
    g_growable_items = 0;
    out_element_sizes("nl_agent_get_corners", "out_points", sizeof(nl_path_point), corners_into);
    CASE("nl_agent_get_corners", "agent idle (allowed: no path, 0 corners, nothing written)") {
        const nl_agent_def def = jumper_def(A.navmesh, -6.0f, -1.0f);
        nl_path_point points[4];
        nl_agent_id idle;
        uint32_t count = 0xdeadbeefu;
        memset(&idle, 0, sizeof idle);
        fill(points, sizeof points);
        points[0].size = sizeof points[0];
        EXPECT_OK(nl_agent_add(A.world, &def, &idle));
        EXPECT_OK(nl_agent_get_corners(A.world, idle, points, 4, &count));
        EXPECT(count == 0u, "out_count = %u", (unsigned)count);
        EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
        EXPECT_OK(nl_agent_remove(A.world, idle));
    }
}

static nl_status trajectory_into(void* out) {
    return nl_agent_get_trajectory(A.world, A.flyer, (nl_agent_trajectory*)out);
}

static void group_agent_get_trajectory(void) {
    CASE("nl_agent_get_trajectory", "agent on the ground (allowed: kind NONE, the rest zero)") {
        nl_agent_trajectory t, zero;
        fill(&t, sizeof t);
        t.size = sizeof t;
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.agent, &t));
        memset(&zero, 0, sizeof zero);
        zero.size = sizeof zero;
        EXPECT(memcmp(&t, &zero, sizeof t) == 0, "kind %u, duration %g: not all zero", (unsigned)t.kind, t.duration);
    }
    CASE("nl_agent_get_trajectory", "agent in the air (allowed: its link's trajectory)") {
        nl_agent_trajectory t;
        const nl_agent_info info = agent_info(A.flyer);
        fill(&t, sizeof t);
        t.size = sizeof t;
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.flyer, &t));
        EXPECT(t.kind == NL_TRAJECTORY_ARC || t.kind == NL_TRAJECTORY_FALL || t.kind == NL_TRAJECTORY_LINE, "kind %u",
               (unsigned)t.kind);
        EXPECT(t.link.index1 == info.link.index1 && t.link.revision == info.link.revision && t.link.index1 != 0u,
               "the trajectory's link is not the agent's");
        EXPECT(isfinite(t.duration) && t.duration > 0.0f && t.elapsed >= 0.0f && t.elapsed <= t.duration &&
                   finite3(t.from) && finite3(t.to) && finite3(t.apex),
               "duration %g, elapsed %g", t.duration, t.elapsed);
    }
    CASE("nl_agent_get_trajectory", "out_trajectory->size 0 (agent on the ground: refused all the same)") {
        nl_agent_trajectory t;
        fill(&t, sizeof t);
        t.size = 0;
        EXPECT_INVALID(A.world, nl_agent_get_trajectory(A.world, A.agent, &t), "out_trajectory->size");
        EXPECT_UNTOUCHED_AFTER_SIZE(&t, sizeof t, "out_trajectory");
    }
    agent_id_cases(9);
    out_sizes("nl_agent_get_trajectory", "out_trajectory", sizeof(nl_agent_trajectory), trajectory_into);
}

static nl_status get_agent_events(const nl_world* w, void* out, uint32_t capacity, uint32_t* count) {
    return nl_world_get_agent_events(w, (nl_agent_event*)out, capacity, count);
}
static nl_status agent_events_into(void* out, uint32_t* written) {
    return nl_world_get_agent_events(A.world, (nl_agent_event*)out, 256u, written);
}

static void group_world_get_agent_events(void) {
    g_growable_items = 1;
    world_list_cases("nl_world_get_agent_events", "out_events", sizeof(nl_agent_event), A.agent_events,
                     get_agent_events);
    g_growable_items = 0;
    out_element_sizes("nl_world_get_agent_events", "out_events", sizeof(nl_agent_event), agent_events_into);
}

/* An agent whose navmesh is removed: at the next step it fails, with one FAILED event
   (NAVMESH_REMOVED); the calls that need its navmesh say so, the others answer; nothing crashes. */
static int failed_events_of(nl_agent_id agent) {
    nl_agent_event events[16];
    uint32_t n = 0, i;
    int failed = 0;
    memset(events, 0, sizeof events);
    events[0].size = sizeof events[0];
    EXPECT(NL_SUCCEEDED(nl_world_get_agent_events(A.world, events, 16, &n)), "nl_world_get_agent_events: %s",
           nl_get_last_error_message());
    for (i = 0; i < n && i < 16; ++i) {
        if (events[i].agent.index1 != agent.index1 || events[i].agent.revision != agent.revision) continue;
        EXPECT(events[i].kind == NL_AGENT_EVENT_FAILED && events[i].reason == NL_AGENT_REASON_NAVMESH_REMOVED &&
                   events[i].user_data == 7u,
               "event kind %u, reason %u", (unsigned)events[i].kind, (unsigned)events[i].reason);
        ++failed;
    }
    return failed;
}

static void expect_failed_for_navmesh(nl_agent_id agent) {
    const nl_agent_info info = agent_info(agent);
    EXPECT(info.state == NL_AGENT_FAILED && info.reason == NL_AGENT_REASON_NAVMESH_REMOVED && finite3(info.position) &&
               info.velocity[0] == 0.0f && info.velocity[1] == 0.0f && info.velocity[2] == 0.0f,
           "state %u, reason %u", (unsigned)info.state, (unsigned)info.reason);
}

static void group_agent_navmesh_removed(void) {
    const nl_navmesh_def quad = quad_navmesh_def();
    static const float lift_goal[3] = {43.5f, 0.0f, 1.5f};
    const nl_agent_def def = jumper_def(A.host_navmesh, 40.5f, -1.5f);
    nl_navmesh_id doomed;
    nl_agent_id lost;
    memset(&doomed, 0, sizeof doomed);
    memset(&lost, 0, sizeof lost);
    CASE("nl_world_step", "agent's navmesh removed (allowed: it fails, with one FAILED event; the others go on)") {
        nl_agent_def on_doomed = def;
        EXPECT_OK(nl_navmesh_add(A.world, &quad, &doomed));
        on_doomed.navmesh = doomed;
        EXPECT_OK(nl_agent_add(A.world, &on_doomed, &lost));
        EXPECT_OK(nl_agent_set_destination(A.world, lost, lift_goal));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        EXPECT(agent_info(lost).state == NL_AGENT_WALKING, "the agent on the doomed navmesh does not walk");
        EXPECT_OK(nl_navmesh_remove(A.world, doomed));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(lost);
        EXPECT(failed_events_of(lost) == 1, "not one FAILED event");
        EXPECT(agent_info(A.agent).state != NL_AGENT_FAILED && in_the_air(agent_info(A.flyer).state),
               "the others stopped");
        fixture_refresh();
    }
    CASE("nl_agent_set_destination", "agent's navmesh removed (INVALID_HANDLE naming it, nothing changed)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_set_destination(A.world, lost, lift_goal), "agent's navmesh");
    }
    CASE("nl_agent_teleport", "agent's navmesh removed (INVALID_HANDLE naming it, nothing changed)") {
        EXPECT_BAD_HANDLE(A.world, nl_agent_teleport(A.world, lost, lift_goal), "agent's navmesh");
    }
    CASE("nl_agent_get_info", "agent's navmesh removed (allowed: FAILED, NAVMESH_REMOVED)") {
        expect_failed_for_navmesh(lost);
    }
    CASE("nl_agent_get_corners", "agent's navmesh removed (allowed: no corners)") {
        uint32_t count = 0xdeadbeefu;
        EXPECT_OK(nl_agent_get_corners(A.world, lost, NULL, 0, &count));
        EXPECT(count == 0u, "out_count = %u", (unsigned)count);
    }
    CASE("nl_agent_get_trajectory", "agent's navmesh removed (allowed: kind NONE)") {
        nl_agent_trajectory t = nl_agent_trajectory_init();
        EXPECT_OK(nl_agent_get_trajectory(A.world, lost, &t));
        EXPECT(t.kind == NL_TRAJECTORY_NONE, "kind %u", (unsigned)t.kind);
    }
    CASE("nl_agent_set_speed", "agent's navmesh removed (allowed: it stays FAILED)") {
        EXPECT_OK(nl_agent_set_speed(A.world, lost, 2.0f, 4.0f));
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_set_capabilities", "agent's navmesh removed (allowed: it stays FAILED)") {
        const nl_agent_capabilities c = nl_default_agent_capabilities();
        EXPECT_OK(nl_agent_set_capabilities(A.world, lost, &c));
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_stop", "agent's navmesh removed (allowed: it stays FAILED, no second event)") {
        EXPECT_OK(nl_agent_stop(A.world, lost));
        expect_failed_for_navmesh(lost);
        EXPECT(agent_info(lost).has_destination == 0u, "the destination is kept");
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(lost);
        EXPECT(failed_events_of(lost) == 0, "a second FAILED event");
        fixture_refresh();
    }
    CASE("nl_world_step", "agent's navmesh removed, stepped again (allowed: no second event)") {
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        EXPECT(failed_events_of(lost) == 0, "a second FAILED event");
        expect_failed_for_navmesh(lost);
        fixture_refresh();
    }
    CASE("nl_agent_remove", "agent's navmesh removed (allowed: removed, then stale)") {
        EXPECT_OK(nl_agent_remove(A.world, lost));
        EXPECT(nl_agent_is_valid(A.world, lost) == 0, "still valid");
        EXPECT_BAD_HANDLE(A.world, nl_agent_remove(A.world, lost), "agent");
        fixture_refresh();
    }
    CASE("nl_world_step", "agent in the air, its navmesh removed (allowed: it fails at once, off the link)") {
        nl_agent_trajectory t = nl_agent_trajectory_init();
        EXPECT_OK(nl_navmesh_remove(A.world, A.navmesh));
        EXPECT_OK(nl_world_step(A.world, 0.05f));
        expect_failed_for_navmesh(A.flyer);
        expect_failed_for_navmesh(A.agent);
        EXPECT(failed_events_of(A.flyer) == 1 && failed_events_of(A.agent) == 1, "not one FAILED event each");
        EXPECT_OK(nl_agent_get_trajectory(A.world, A.flyer, &t));
        EXPECT(t.kind == NL_TRAJECTORY_NONE, "kind %u", (unsigned)t.kind);
        fixture_refresh();
    }
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"agent_add", group_agent_add},
    {"agent_remove", group_agent_remove},
    {"agent_is_valid", group_agent_is_valid},
    {"agent_set_destination", group_agent_set_destination},
    {"agent_stop", group_agent_stop},
    {"agent_teleport", group_agent_teleport},
    {"agent_set_capabilities", group_agent_set_capabilities},
    {"agent_set_speed", group_agent_set_speed},
    {"world_step", group_world_step},
    {"agent_get_info", group_agent_get_info},
    {"world_get_agents", group_world_get_agents},
    {"agent_get_corners", group_agent_get_corners},
    {"agent_get_trajectory", group_agent_get_trajectory},
    {"world_get_agent_events", group_world_get_agent_events},
    {"agent_navmesh_removed", group_agent_navmesh_removed},
};
const hostile_part hostile_agents_part = {k_groups, sizeof k_groups / sizeof *k_groups};
