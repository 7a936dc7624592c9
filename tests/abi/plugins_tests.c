/*
 * Plugins (navlink.h): the built-in plugin listed and described, the two-call pattern, and
 * nl_plugin_load's refusals of files that are not plugins. (Plugins registered from this program, the
 * plugin side of the ABI, are in plugin_abi_tests.c.)
 */
#include "abi_test.h"
#include "navmesh_scene.h"

#include <navlink/plugin.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void listed(void) {
    nl_world* world = make_world(1);
    nl_plugin_id ids[4];
    uint32_t count = 0xdeadbeefu;
    nl_plugin_description d;

    CHECK_OK(nl_world_get_plugins(world, NULL, 0, &count));
    CHECK(count == 1);
    memset(ids, 0xcd, sizeof ids);
    CHECK_OK(nl_world_get_plugins(world, ids, 4, &count));
    CHECK(count == 1);
    CHECK(all_bytes(&ids[1], 3 * sizeof ids[0], 0xcd));
    d = describe(world, ids[0]);
    CHECK(d.size == sizeof d);
    CHECK(d.name != NULL && strcmp(d.name, "recast") == 0);
    CHECK(d.builtin == 1);
    CHECK(d.kinds == NL_PLUGIN_NAVMESH_BUILDER);
    CHECK(d.abi_version == NL_PLUGIN_ABI_VERSION);
    CHECK(d.version != NULL && d.version[0] != '\0');
    CHECK(d.description != NULL && d.description[0] != '\0');
    {
        /* The built-in plugin carries the library's version. */
        char expected[64];
        const nl_version v = nl_get_version();
        snprintf(expected, sizeof expected, "%d.%d.%d", (int)v.major, (int)v.minor, (int)v.patch);
        CHECK_MSG(d.version != NULL && strcmp(d.version, expected) == 0, "recast version \"%s\", library %s",
                  d.version ? d.version : "(null)", expected);
    }

    /* The two-call pattern. */
    memset(ids, 0xcd, sizeof ids);
    count = 0;
    CHECK_FAIL(nl_world_get_plugins(world, ids, 0, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 1);
    CHECK(all_bytes(ids, sizeof ids, 0xcd));
    count = 0xdeadbeefu;
    CHECK_INVALID(nl_world_get_plugins(world, NULL, 2, &count), "out_ids");
    CHECK_INVALID(nl_world_get_plugins(world, ids, 4, NULL), "out_count");
    CHECK_INVALID(nl_world_get_plugins(NULL, ids, 4, &count), "world");

    /* Description failures. */
    {
        const nl_plugin_id null_id = {0u, 0u}, far = {1000u, 1u};
        CHECK_OK(nl_world_get_plugins(world, ids, 4, &count));
        memset(&d, 0xab, sizeof d);
        d.size = 0;
        CHECK_INVALID(nl_plugin_get_description(world, ids[0], &d), "size");
        CHECK(d.kinds == 0xabababab);
        d.size = sizeof d;
        CHECK_INVALID(nl_plugin_get_description(world, ids[0], NULL), "out_description");
        CHECK_INVALID(nl_plugin_get_description(NULL, ids[0], &d), "world");
        CHECK_FAIL(nl_plugin_get_description(world, null_id, &d), NL_STATUS_INVALID_HANDLE,
                   "nl_plugin_get_description");
        CHECK_FAIL(nl_plugin_get_description(world, far, &d), NL_STATUS_INVALID_HANDLE, "nl_plugin_get_description");
        CHECK(d.kinds == 0xabababab);
    }

    /* nl_plugin_load: arguments, then files that are not plugins. */
    {
        nl_plugin_id out = {77u, 77u};
        const char* text_path = "navlink_abi_test_not_a_plugin.so";
        FILE* f;
        CHECK_INVALID(nl_plugin_load(world, NULL, &out), "path");
        CHECK_INVALID(nl_plugin_load(world, "navlink_abi_test_missing_plugin.so", NULL), "out_id");
        CHECK_INVALID(nl_plugin_load(NULL, "navlink_abi_test_missing_plugin.so", &out), "world");
        CHECK_FAIL(nl_plugin_load(world, "navlink_abi_test_missing_plugin.so", &out), NL_STATUS_NOT_FOUND,
                   "navlink_abi_test_missing_plugin.so");
        f = fopen(text_path, "wb");
        if (CHECK(f != NULL)) {
            fputs("this is not a shared library\n", f);
            fclose(f);
            CHECK_FAIL(nl_plugin_load(world, text_path, &out), NL_STATUS_IO_ERROR, text_path);
            remove(text_path);
        }
        CHECK(out.index1 == 77u && out.revision == 77u);
        CHECK(plugin_count(world) == 1);
    }
    nl_world_destroy(world);
}

ABI_SECTION(plugins, ABI_CASE(listed));
