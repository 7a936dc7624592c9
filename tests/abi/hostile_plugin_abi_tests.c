/*
 * The hostile cases of navlink/plugin.h, the plugin ABI: nl_plugin_register with entry functions
 * that refuse, or describe themselves wrongly.
 */
#include "hostile_fixtures.h"

#include <navlink/plugin.h>

#include <stddef.h>

/* Entry functions that refuse, or describe themselves wrongly: nothing is registered. */
static nl_status entry_refuses(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)info;
    host->set_error(host->context, "this plugin always refuses");
    return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
}
static nl_status entry_newer(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)host;
    (void)info;
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}
static nl_status build_nothing(void* state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                               nl_navmesh_sink_fn* sink, void* context) {
    (void)state;
    (void)host;
    (void)def;
    (void)sink;
    (void)context;
    return NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
}

/* A description made wrong field by field (from a builder named "hostile"). */
typedef struct wrong_plugin {
    const char* what;
    nl_status detail;
    const char* needle;
    const char* name;
    uint32_t abi_version;
    uint32_t kinds;
    int no_build;
} wrong_plugin;
static const wrong_plugin k_wrong_plugins[] = {
    {"entry describes no name", NL_STATUS_INVALID_ARGUMENT, "name", NULL, NL_PLUGIN_ABI_VERSION,
     NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes an empty name", NL_STATUS_INVALID_ARGUMENT, "name", "", NL_PLUGIN_ABI_VERSION,
     NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes the name of the built-in builder", NL_STATUS_INVALID_ARGUMENT, "recast", "recast",
     NL_PLUGIN_ABI_VERSION, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes ABI version 0", NL_STATUS_VERSION_MISMATCH, "version", "hostile", 0u, NL_PLUGIN_NAVMESH_BUILDER,
     0},
    {"entry describes an ABI version newer than the host's", NL_STATUS_VERSION_MISMATCH, "version", "hostile",
     NL_PLUGIN_ABI_VERSION + 1u, NL_PLUGIN_NAVMESH_BUILDER, 0},
    {"entry describes a builder without a build function", NL_STATUS_INVALID_ARGUMENT, "build", "hostile",
     NL_PLUGIN_ABI_VERSION, NL_PLUGIN_NAVMESH_BUILDER, 1},
    {"entry describes unknown kinds", NL_STATUS_INVALID_ARGUMENT, "kinds", "hostile", NL_PLUGIN_ABI_VERSION, 0x80u, 0},
    {"entry describes a link kind without a generate function", NL_STATUS_INVALID_ARGUMENT, "link kind", "hostile",
     NL_PLUGIN_ABI_VERSION, NL_PLUGIN_LINK_KIND, 0},
};
static const wrong_plugin* g_wrong;
static nl_status entry_wrong(uint32_t version, const nl_plugin_host* host, nl_plugin_info* info) {
    (void)version;
    (void)host;
    info->abi_version = g_wrong->abi_version;
    info->name = g_wrong->name;
    info->kinds = g_wrong->kinds;
    info->navmesh_builder.build = g_wrong->no_build ? NULL : build_nothing;
    return NL_STATUS_SUCCESS;
}

static void plugin_register_fails_with(nl_plugin_entry_fn* entry, nl_status detail, const char* needle) {
    nl_plugin_id out;
    fill(&out, sizeof out);
    EXPECT_FAILURE(A.world, nl_plugin_register(A.world, entry, &out), detail, needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
}

static void group_plugin_register(void) {
    size_t i;
    g_wrong = &k_wrong_plugins[0];
    CASE("nl_plugin_register", "world NULL") {
        nl_plugin_id out;
        fill(&out, sizeof out);
        EXPECT_INVALID(NULL, nl_plugin_register(NULL, entry_refuses, &out), "world");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    CASE("nl_plugin_register", "entry NULL") { plugin_register_fails_with(NULL, NL_STATUS_INVALID_ARGUMENT, "entry"); }
    CASE("nl_plugin_register", "out_id NULL") {
        EXPECT_INVALID(A.world, nl_plugin_register(A.world, entry_refuses, NULL), "out_id");
    }
    CASE("nl_plugin_register", "entry refuses (with a reason)") {
        plugin_register_fails_with(entry_refuses, NL_STATUS_INTERNAL_ERROR, "this plugin always refuses");
    }
    CASE("nl_plugin_register", "entry speaks no common version") {
        plugin_register_fails_with(entry_newer, NL_STATUS_VERSION_MISMATCH, "version");
    }
    for (i = 0; i < sizeof k_wrong_plugins / sizeof *k_wrong_plugins; ++i) {
        CASE("nl_plugin_register", "%s", k_wrong_plugins[i].what) {
            g_wrong = &k_wrong_plugins[i];
            plugin_register_fails_with(entry_wrong, k_wrong_plugins[i].detail, k_wrong_plugins[i].needle);
        }
    }
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"plugin_register", group_plugin_register},
};
const hostile_part hostile_plugin_abi_part = {k_groups, sizeof k_groups / sizeof *k_groups};
