/*
 * The hostile cases of navlink/plugins.h: plugins loaded from files, their descriptions, the
 * world's plugins.
 */
#include "hostile_fixtures.h"

#include <navlink/plugin.h>

#include <stdio.h>

static nl_status load_plugin_at(const char* path, void* out) {
    return nl_plugin_load(A.world, path, (nl_plugin_id*)out);
}

static void group_plugin_load(void) {
    static const char* made[] = {"not-a-library.so"};
    static const bad_path not_a_library = {"path not a library (a text file)", "not-a-library.so", NULL,
                                           NL_STATUS_IO_ERROR, "not-a-library.so"};
    char path[160];
    make_tmp();
    snprintf(path, sizeof path, "%s/not-a-library.so", g_tmp);
    write_file(path, "not an ELF file\n");
    CASE("nl_plugin_load", "world NULL") {
        nl_plugin_id out;
        fill(&out, sizeof out);
        EXPECT_INVALID(NULL, nl_plugin_load(NULL, path, &out), "world");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    CASE("nl_plugin_load", "out_id NULL") { EXPECT_INVALID(A.world, nl_plugin_load(A.world, path, NULL), "out_id"); }
    bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), k_bad_paths, BAD_PATH_COUNT);
    bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), &not_a_library, 1);
    if (g_library_path) {
        const bad_path no_entry = {"path a library without nl_plugin_entry (libnavlink.so)", NULL, g_library_path,
                                   NL_STATUS_NOT_FOUND, NL_PLUGIN_ENTRY_SYMBOL};
        bad_path_cases("nl_plugin_load", load_plugin_at, sizeof(nl_plugin_id), &no_entry, 1);
    }
    if (g_plugin_path) {
        CASE("nl_plugin_load", "path loaded twice (the name is taken)") {
            nl_plugin_id first = {0u, 0u};
            const bad_path twice = {"", NULL, g_plugin_path, NL_STATUS_INVALID_ARGUMENT, "already loaded"};
            EXPECT_OK(nl_plugin_load(A.world, g_plugin_path, &first));
            fixture_refresh();
            EXPECT_FAILURE(A.world, load_plugin_at(twice.path, &first), twice.detail, twice.needle);
        }
    }
    remove_tmp(made, 1);
}

static nl_status description_into(void* out) { return description_call(A.world, RAW(A.plugin), out); }

static void group_plugin_get_description(void) {
    static const id_function f = {"nl_plugin_get_description",
                                  "plugin",
                                  "out_description",
                                  sizeof(nl_plugin_description),
                                  1,
                                  0,
                                  description_call,
                                  0};
    id_cases(&f, RAW(A.plugin), (raw_id){0u, 0u}, RAW(B.plugin));
    out_sizes("nl_plugin_get_description", "out_description", sizeof(nl_plugin_description), description_into);
}

static void group_world_get_plugins(void) {
    world_list_cases("nl_world_get_plugins", "out_ids", sizeof(nl_plugin_id), 1u, get_plugins);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"plugin_load", group_plugin_load},
    {"plugin_get_description", group_plugin_get_description},
    {"world_get_plugins", group_world_get_plugins},
};
const hostile_part hostile_plugins_part = {k_groups, sizeof k_groups / sizeof *k_groups};
