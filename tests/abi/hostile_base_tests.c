/*
 * The hostile cases of navlink/base.h: the version, the status strings and the last error
 * record. And the defaults of every part (the nl_default_* functions: they never fail, set `size`
 * and leave the record alone), in one group of their own.
 */
/* pthreads; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile_fixtures.h"
#include <navlink/recast.h>

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* ---------------------------------------------------------------------------------------------
 * Version, statuses and the last error
 * ------------------------------------------------------------------------------------------- */

static void group_version(void) {
    CASE("nl_get_version", "record untouched (never fails)") {
        nl_version v;
        fail_on_purpose();
        v = nl_get_version();
        EXPECT(v.major == NL_VERSION_MAJOR && v.minor == NL_VERSION_MINOR && v.patch == NL_VERSION_PATCH,
               "nl_get_version() = %d.%d.%d, the header says %d.%d.%d", (int)v.major, (int)v.minor, (int)v.patch,
               NL_VERSION_MAJOR, NL_VERSION_MINOR, NL_VERSION_PATCH);
        EXPECT(record_is_the_failure(), "nl_get_version changed the last error record");
    }
}

static void group_status_string(void) {
    static const nl_status statuses[] = {0u,
                                         UINT32_MAX,
                                         NL_STATUS_FAILURE,
                                         NL_STATUS_SUCCESS | NL_STATUS_FAILURE,
                                         NL_STATUS_IN_PROGRESS | NL_STATUS_FAILURE,
                                         NL_STATUS_DETAIL_MASK};
    static const char* names[] = {"status 0",
                                  "status huge (0xffffffff)",
                                  "status FAILURE without a detail",
                                  "status SUCCESS|FAILURE",
                                  "status IN_PROGRESS|FAILURE",
                                  "status DETAIL_MASK without a kind"};
    size_t i;
    for (i = 0; i < sizeof statuses / sizeof *statuses; ++i) {
        CASE("nl_status_string", "%s", names[i]) {
            const char* s;
            fail_on_purpose();
            s = nl_status_string(statuses[i]);
            EXPECT(s != NULL && s[0] != '\0', "nl_status_string(0x%08x) is NULL or empty", (unsigned)statuses[i]);
            EXPECT(record_is_the_failure(), "nl_status_string changed the last error record");
        }
    }
    CASE("nl_status_string", "status every single bit, alone and with FAILURE") {
        int bit;
        for (bit = 0; bit < 32; ++bit) {
            const char* alone = nl_status_string((nl_status)1u << bit);
            const char* failed = nl_status_string(NL_STATUS_FAILURE | ((nl_status)1u << bit));
            EXPECT(alone && alone[0] && failed && failed[0], "nl_status_string of bit %d is NULL or empty", bit);
        }
    }
}

static void* fresh_thread_record(void* out) {
    int* ok = (int*)out;
    const char* message = nl_get_last_error_message();
    *ok = nl_get_last_status() == NL_STATUS_SUCCESS && message != NULL && message[0] == '\0';
    (void)nl_mesh_remove(NULL, (nl_mesh_id){0u, 0u}); /* this thread's failure is its own */
    return NULL;
}

static void group_last_error(void) {
    static const char* functions[2] = {"nl_get_last_status", "nl_get_last_error_message"};
    int k;
    for (k = 0; k < 2; ++k) {
        CASE(functions[k], "thread fresh (SUCCESS and an empty message, never NULL), and per thread") {
            pthread_t thread;
            int ok = 0;
            fail_on_purpose();
            EXPECT(pthread_create(&thread, NULL, fresh_thread_record, &ok) == 0, "pthread_create failed");
            pthread_join(thread, NULL);
            EXPECT(ok,
                   "a thread that made no call has a last status other than SUCCESS, or a NULL or non-empty message");
            EXPECT(record_is_the_failure(), "another thread's failure changed this thread's record");
        }
    }
    CASE("nl_get_last_error_message", "record read twice (the getters do not touch it)") {
        fail_on_purpose();
        (void)nl_get_last_error_message();
        (void)nl_get_last_status();
        EXPECT(record_is_the_failure(), "reading the record changed it");
    }
}

/* ---------------------------------------------------------------------------------------------
 * Defaults: never fail, set `size`, leave the record alone
 * ------------------------------------------------------------------------------------------- */

#define DEFAULT_CASE(function, type, has_size)                                                      \
    CASE(#function, "record untouched (never fails)") {                                             \
        type value;                                                                                 \
        fail_on_purpose();                                                                          \
        value = function();                                                                         \
        EXPECT(record_is_the_failure(), #function " changed the last error record");                \
        if (has_size) {                                                                             \
            uint32_t size;                                                                          \
            memcpy(&size, &value, sizeof size);                                                     \
            EXPECT(size == sizeof(type), #function "().size = %u, not sizeof = %u", (unsigned)size, \
                   (unsigned)sizeof(type));                                                         \
        }                                                                                           \
    }

static void group_defaults(void) {
    DEFAULT_CASE(nl_default_world_def, nl_world_def, 1)
    DEFAULT_CASE(nl_default_mesh_def, nl_mesh_def, 1)
    DEFAULT_CASE(nl_default_navmesh_def, nl_navmesh_def, 1)
    DEFAULT_CASE(nl_default_navmesh_build_def, nl_navmesh_build_def, 1)
    DEFAULT_CASE(nl_default_navmesh_load_def, nl_navmesh_load_def, 1)
    DEFAULT_CASE(nl_default_recast_settings, nl_recast_settings, 1)
    DEFAULT_CASE(nl_default_link_def, nl_link_def, 1)
    DEFAULT_CASE(nl_default_link_settings, nl_link_settings, 1)
    DEFAULT_CASE(nl_default_path_request_def, nl_path_request_def, 1)
    DEFAULT_CASE(nl_default_path_budget, nl_path_budget, 1)
    DEFAULT_CASE(nl_default_agent_type, nl_agent_type, 0)
    DEFAULT_CASE(nl_default_agent_capabilities, nl_agent_capabilities, 0)
    DEFAULT_CASE(nl_default_agent_def, nl_agent_def, 1)
    CASE("nl_default_agent_type", "values as documented (0.6, 2, 0.9, 45)") {
        const nl_agent_type a = nl_default_agent_type();
        EXPECT(a.radius == 0.6f && a.height == 2.0f && a.max_climb == 0.9f && a.max_slope == 45.0f,
               "nl_default_agent_type() = {%g, %g, %g, %g}", a.radius, a.height, a.max_climb, a.max_slope);
    }
    CASE("nl_default_agent_def",
         "values as documented (a walker, height 2, 3.5 m/s, 8 m/s2, gravity 9.81, avoidance on)") {
        const nl_agent_def d = nl_default_agent_def();
        const nl_agent_capabilities c = nl_default_agent_capabilities();
        EXPECT(d.navmesh.index1 == 0u && d.navmesh.revision == 0u && d.height == 2.0f && d.max_speed == 3.5f &&
                   d.max_acceleration == 8.0f && d.gravity == 9.81f && d.takeoff_speed == 0.0f &&
                   d.position[0] == 0.0f && d.position[1] == 0.0f && d.position[2] == 0.0f && d.avoidance == 1u &&
                   d.user_data == 0u && memcmp(&d.capabilities, &c, sizeof c) == 0,
               "nl_default_agent_def() = {height %g, speed %g, acceleration %g, gravity %g, avoidance %u}", d.height,
               d.max_speed, d.max_acceleration, d.gravity, (unsigned)d.avoidance);
    }
    CASE("nl_default_agent_capabilities", "values as documented (a walker: radius 0.6, no jumps)") {
        const nl_agent_capabilities a = nl_default_agent_capabilities();
        EXPECT(a.radius == 0.6f && a.max_jump_distance == 0.0f && a.max_jump_height == 0.0f &&
                   a.max_drop_height == 0.0f && a.abilities == 0u,
               "nl_default_agent_capabilities() = {%g, %g, %g, %g}", a.max_jump_distance, a.max_jump_height,
               a.max_drop_height, a.radius);
    }
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"version", group_version},
    {"status_string", group_status_string},
    {"last_error", group_last_error},
    {"defaults", group_defaults},
};
const hostile_part hostile_base_part = {k_groups, sizeof k_groups / sizeof *k_groups};
