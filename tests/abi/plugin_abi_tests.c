/*
 * The plugin side of the ABI (plugin.h): plugins compiled into this program and registered with
 * nl_plugin_register, what the host promises their entry functions and builders (the host table, a
 * zero-filled info, the level's triangles), version negotiation, refusals of plugins that describe
 * themselves wrongly, and builders that misbehave (a failure, never a crash, never a navmesh added).
 */
#include "abi_test.h"
#include "navmesh_scene.h"
#include "scene.h"

#include <navlink/plugin.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The test builder's behaviour, chosen per build through its settings struct. */
enum test_build_mode {
    MODE_GRID,               /* hands the grid to the sink and returns what the sink said */
    MODE_SINK_TWICE,         /* hands it twice, returns the second answer */
    MODE_SINK_TWICE_SUCCEED, /* hands it twice, returns success whatever the sink said */
    MODE_NO_SINK,            /* returns success without calling the sink */
    MODE_SINK_THEN_FAIL,     /* hands it over, then fails (NOT_FOUND) */
    MODE_BAD_INDEX,          /* hands over a grid with an index out of range, returns the sink's answer */
    MODE_BAD_INDEX_SUCCEED,  /* the same, returning success anyway */
    MODE_REPORT_ERROR,       /* set_error and INVALID_ARGUMENT, no sink */
    MODE_NULL_NAVMESH,       /* calls the sink with NULL */
    MODE_RECORD,             /* records the settings it used, then as MODE_GRID */
    MODE_RECORD_NOT_OBJECT,  /* records a JSON array as its settings, then as MODE_GRID */
    MODE_RECORD_NULL,        /* records NULL (refused), then as MODE_GRID */
    MODE_COLUMNS             /* reads the level in columns (get_build_triangles_in_columns), then as MODE_GRID */
};

static const char k_recorded_settings[] = "{\"flavour\": \"vanilla\", \"scoops\": 2}";

typedef struct test_builder_settings {
    uint32_t size;
    uint32_t mode;
} test_builder_settings;

typedef struct test_plugin_state {
    int entries_ok;   /* entry calls that returned success */
    int destroys;     /* destroy calls */
    int entry_checks; /* entry calls that saw the host table and a zero-filled info as promised */
    int builds;
    int build_checks; /* builds that saw their state, the host table and level triangle counts */
    nl_status sink_status[2];
    uint32_t level_vertices, level_triangles;
    nl_status short_copy_status; /* get_level_triangles with a buffer one vertex short */
    nl_agent_type agent;
    nl_status record_status;         /* record_build_settings in the last build */
    nl_status record_outside_status; /* record_build_settings from the entry function */
    /* MODE_COLUMNS: get_build_triangles_in_columns over all of the level, its -x side, nothing (far
       away), NULL, NaN and min > max columns, a short buffer; and from the entry function. */
    nl_status columns_status[7], columns_outside_status;
    uint32_t columns_triangles[3], columns_vertices[3];
    float columns_bounds[6];
} test_plugin_state;

static test_plugin_state g_plugin;

static int host_table_ok(uint32_t host_abi_version, const nl_plugin_host* host) {
    return host != NULL && host_abi_version == NL_PLUGIN_ABI_VERSION && host->size >= sizeof(nl_plugin_host) &&
           host->abi_version == NL_PLUGIN_ABI_VERSION && host->log != NULL && host->set_error != NULL &&
           host->get_level_triangles != NULL;
}

static void test_plugin_destroy(void* state) {
    if (state == &g_plugin) ++g_plugin.destroys;
}

static nl_status test_build(void* state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                            nl_navmesh_sink_fn* sink, void* sink_context) {
    test_plugin_state* self = (test_plugin_state*)state;
    const test_builder_settings* settings = (const test_builder_settings*)def->settings;
    const uint32_t mode = settings && settings->size >= sizeof *settings ? settings->mode : MODE_GRID;
    uint32_t bad_quads[16];
    nl_navmesh_def navmesh;
    nl_status status;
    ++self->builds;
    self->agent = def->agent_type;
    self->sink_status[0] = self->sink_status[1] = 0u;
    self->level_vertices = self->level_triangles = 0xdeadbeefu;
    self->short_copy_status = 0u;
    if (state == &g_plugin && host != NULL && host_table_ok(host->abi_version, host) &&
        NL_SUCCEEDED(
            host->get_level_triangles(host->context, NULL, 0, &self->level_vertices, NULL, 0, &self->level_triangles)))
        ++self->build_checks;
    if (self->level_vertices > 1 && self->level_vertices < 100 && self->level_triangles < 100) {
        float vertices[300];
        uint32_t indices[300], vertex_count = 0, triangle_count = 0;
        memset(vertices, 0, sizeof vertices);
        self->short_copy_status = host->get_level_triangles(host->context, vertices, self->level_vertices - 1,
                                                            &vertex_count, indices, 100, &triangle_count);
    }
    host->log(host->context, NL_LOG_DEBUG, "test builder: building");

    /* Filled by hand, as a plugin that uses no symbol of the library would. */
    memset(&navmesh, 0, sizeof navmesh);
    navmesh.size = (uint32_t)sizeof navmesh;
    navmesh.vertices = k_grid_vertices;
    navmesh.vertex_count = 9;
    navmesh.indices = k_grid_quads;
    navmesh.polygon_vertex_counts = k_quad_counts;
    navmesh.polygon_count = 4;
    navmesh.weld_tolerance = 0.001f;
    navmesh.agent_type = def->agent_type;
    self->record_status = 0u;
    switch (mode) {
        case MODE_RECORD:
            self->record_status =
                host->record_build_settings(host->context, k_recorded_settings, strlen(k_recorded_settings));
            return self->sink_status[0] = sink(sink_context, &navmesh);
        case MODE_RECORD_NOT_OBJECT:
            self->record_status = host->record_build_settings(host->context, "[1, 2]", 6);
            return self->sink_status[0] = sink(sink_context, &navmesh);
        case MODE_RECORD_NULL:
            self->record_status = host->record_build_settings(host->context, NULL, 4);
            return self->sink_status[0] = sink(sink_context, &navmesh);
        case MODE_COLUMNS: {
            static const double all[4] = {-1e4, -1e4, 1e4, 1e4}, minus_x[4] = {-20.0, -20.0, -10.0, 20.0},
                                far[4] = {1e4, 1e4, 2e4, 2e4}, not_finite[4] = {0.0, 0.0, 1.0, NAN},
                                crossed[4] = {1.0, 0.0, -1.0, 1.0};
            const double* asked[3] = {all, minus_x, far};
            float vertices[3 * 16];
            uint32_t indices[3 * 16], vertex_count = 0, triangle_count = 0, k;
            uint8_t areas[16];
            for (k = 0; k < 3; ++k) {
                self->columns_status[k] = host->get_build_triangles_in_columns(
                    host->context, asked[k], vertices, 16, &self->columns_vertices[k], indices, areas, 16,
                    &self->columns_triangles[k], k == 0 ? self->columns_bounds : NULL);
            }
            self->columns_status[3] = host->get_build_triangles_in_columns(
                host->context, NULL, vertices, 16, &vertex_count, indices, areas, 16, &triangle_count, NULL);
            self->columns_status[4] = host->get_build_triangles_in_columns(
                host->context, not_finite, vertices, 16, &vertex_count, indices, areas, 16, &triangle_count, NULL);
            self->columns_status[5] = host->get_build_triangles_in_columns(
                host->context, crossed, vertices, 16, &vertex_count, indices, areas, 16, &triangle_count, NULL);
            self->columns_status[6] = host->get_build_triangles_in_columns(
                host->context, all, vertices, 16, &vertex_count, indices, areas, 11, &triangle_count, NULL);
            return self->sink_status[0] = sink(sink_context, &navmesh);
        }
        case MODE_GRID: return self->sink_status[0] = sink(sink_context, &navmesh);
        case MODE_SINK_TWICE:
            self->sink_status[0] = sink(sink_context, &navmesh);
            return self->sink_status[1] = sink(sink_context, &navmesh);
        case MODE_SINK_TWICE_SUCCEED:
            self->sink_status[0] = sink(sink_context, &navmesh);
            self->sink_status[1] = sink(sink_context, &navmesh);
            return NL_STATUS_SUCCESS;
        case MODE_NO_SINK: return NL_STATUS_SUCCESS;
        case MODE_SINK_THEN_FAIL:
            self->sink_status[0] = sink(sink_context, &navmesh);
            host->set_error(host->context, "test builder: changed its mind after the sink");
            return NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
        case MODE_BAD_INDEX:
        case MODE_BAD_INDEX_SUCCEED:
            memcpy(bad_quads, k_grid_quads, sizeof bad_quads);
            bad_quads[6] = 99;
            navmesh.indices = bad_quads;
            status = self->sink_status[0] = sink(sink_context, &navmesh);
            return mode == MODE_BAD_INDEX ? status : NL_STATUS_SUCCESS;
        case MODE_REPORT_ERROR:
            host->set_error(host->context, "test builder: setting 'flavour' must be 'vanilla'");
            return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
        case MODE_NULL_NAVMESH: return self->sink_status[0] = sink(sink_context, NULL);
        default: return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
    }
}

/* Checks what the host promises an entry function, then describes the plugin. */
static int entry_preamble(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    /* The host zero-fills the info and sets its size. */
    if (host_table_ok(host_abi_version, host) && out_info->size == sizeof(nl_plugin_info) &&
        out_info->abi_version == 0 && out_info->name == NULL && out_info->version == NULL &&
        out_info->description == NULL && out_info->kinds == 0 && out_info->state == NULL && out_info->destroy == NULL &&
        out_info->navmesh_builder.build == NULL)
        ++g_plugin.entry_checks;
    g_plugin.record_outside_status = host->record_build_settings(host->context, "{}", 2);
    {
        static const double all[4] = {-1e4, -1e4, 1e4, 1e4};
        uint32_t vertex_count = 0, triangle_count = 0;
        g_plugin.columns_outside_status = host->get_build_triangles_in_columns(
            host->context, all, NULL, 0, &vertex_count, NULL, NULL, 0, &triangle_count, NULL);
    }
    out_info->abi_version = NL_PLUGIN_ABI_VERSION;
    out_info->version = "2.5.1";
    out_info->description = "C test builder: a 2 x 2 grid";
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER;
    out_info->state = &g_plugin;
    out_info->destroy = test_plugin_destroy;
    out_info->navmesh_builder.build = test_build;
    ++g_plugin.entries_ok;
    return 1;
}

static nl_status entry_builder(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-builder";
    return NL_STATUS_SUCCESS;
}

/* The same plugin under another name, so each world can hold two. */
static nl_status entry_builder_two(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-builder-2";
    return NL_STATUS_SUCCESS;
}

static nl_status entry_links_only(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-links";
    out_info->kinds = NL_PLUGIN_LINK_KIND;
    out_info->navmesh_builder.build = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_named_recast(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "recast";
    return NL_STATUS_SUCCESS;
}

static nl_status entry_version_mismatch(uint32_t host_abi_version, const nl_plugin_host* host,
                                        nl_plugin_info* out_info) {
    (void)host_abi_version;
    (void)out_info;
    host->set_error(host->context, "c-test-old needs plugin ABI 7");
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}

static nl_status entry_abi_zero(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-abi-zero";
    out_info->abi_version = 0;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_abi_newer(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-abi-newer";
    out_info->abi_version = host_abi_version + 1u;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_no_name(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_no_build(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-no-build";
    out_info->navmesh_builder.build = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_unknown_kind(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-unknown-kind";
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER | 0x100u;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_refuses(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    (void)host_abi_version;
    (void)out_info;
    host->set_error(host->context, "c-test-refuses: no licence");
    return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
}

/* One refused nl_plugin_register: `detail` naming `needle`, nothing registered, out_id untouched. */
#define CHECK_REGISTER_FAILS(world, entry, detail, needle) \
    check_register_fails((world), (entry), (detail), (needle), __FILE__, __LINE__)

static void check_register_fails(nl_world* world, nl_plugin_entry_fn* entry, nl_status detail, const char* needle,
                                 const char* file, int line) {
    const uint32_t before = plugin_count(world);
    nl_plugin_id out = {77u, 77u};
    const nl_status status = nl_plugin_register(world, entry, &out);
    check_fail_at(status, detail, needle, "nl_plugin_register", file, line);
    check_at(out.index1 == 77u && out.revision == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(plugin_count(world) == before, file, line, "a plugin was registered on failure (%s)", needle);
}

static void registered(void) {
    nl_world* world;
    nl_plugin_id builder = {0u, 0u}, links = {0u, 0u}, second = {0u, 0u};
    nl_plugin_description d;
    const char *name, *version, *description;
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    test_builder_settings settings;
    nl_navmesh_id id = {0u, 0u};
    memset(&g_plugin, 0, sizeof g_plugin);

    world = make_world(1);
    add_floor_box(world);
    CHECK_OK(nl_plugin_register(world, entry_builder, &builder));
    CHECK(builder.index1 != 0u);
    CHECK(g_plugin.entries_ok == 1 && g_plugin.entry_checks == 1);
    CHECK(plugin_count(world) == 2);
    {
        /* Built-in first, then in registration order. */
        nl_plugin_id ids[2];
        uint32_t count = 0;
        CHECK_OK(nl_world_get_plugins(world, ids, 2, &count));
        CHECK(count == 2 && same_plugin(ids[1], builder) && describe(world, ids[0]).builtin == 1);
    }
    d = describe(world, builder);
    CHECK(d.name != NULL && strcmp(d.name, "c-test-builder") == 0);
    CHECK(d.version != NULL && strcmp(d.version, "2.5.1") == 0);
    CHECK(d.description != NULL && strcmp(d.description, "C test builder: a 2 x 2 grid") == 0);
    CHECK(d.builtin == 0 && d.kinds == NL_PLUGIN_NAVMESH_BUILDER && d.abi_version == NL_PLUGIN_ABI_VERSION);
    name = d.name;
    version = d.version;
    description = d.description;

    /* Built through nl_navmesh_build with builder = its name: the builder got the def's agent, its
       state, the host's table and the level (the box: 8 vertices, 12 triangles). */
    def.builder = "c-test-builder";
    def.agent_type.radius = 0.35f;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(g_plugin.builds == 1 && g_plugin.build_checks == 1);
    CHECK(same_agent(g_plugin.agent, def.agent_type));
    CHECK_MSG(g_plugin.level_vertices == 8 && g_plugin.level_triangles == 12, "the level has %u vertices, %u triangles",
              (unsigned)g_plugin.level_vertices, (unsigned)g_plugin.level_triangles);
    CHECK(g_plugin.short_copy_status == (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL));
    CHECK(g_plugin.sink_status[0] == NL_STATUS_SUCCESS);
    check_grid_navmesh(world, id, 4, NULL, "built by the C test builder");
    CHECK(same_agent(navmesh_info(world, id).agent_type, def.agent_type));
    CHECK(navmesh_count(world) == 1);

    /* Registering it again is refused by name; so is a plugin named like the built-in one. */
    CHECK_REGISTER_FAILS(world, entry_builder, NL_STATUS_INVALID_ARGUMENT, "c-test-builder");
    CHECK_REGISTER_FAILS(world, entry_named_recast, NL_STATUS_INVALID_ARGUMENT, "recast");
    /* Version negotiation. */
    CHECK_REGISTER_FAILS(world, entry_version_mismatch, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    CHECK_REGISTER_FAILS(world, entry_abi_zero, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    CHECK_REGISTER_FAILS(world, entry_abi_newer, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    /* Plugins that describe themselves wrongly, or refuse to start. */
    CHECK_REGISTER_FAILS(world, entry_no_name, NL_STATUS_INVALID_ARGUMENT, "name");
    CHECK_REGISTER_FAILS(world, entry_no_build, NL_STATUS_INVALID_ARGUMENT, "c-test-no-build");
    CHECK_REGISTER_FAILS(world, entry_unknown_kind, NL_STATUS_INVALID_ARGUMENT, "c-test-unknown-kind");
    {
        const uint32_t before = plugin_count(world);
        nl_plugin_id out = {77u, 77u};
        const nl_status status = nl_plugin_register(world, entry_refuses, &out);
        CHECK(NL_FAILED(status));
        CHECK(strstr(nl_get_last_error_message(), "no licence") != NULL);
        CHECK(out.index1 == 77u && plugin_count(world) == before);
    }
    /* Arguments. */
    {
        nl_plugin_id out = {77u, 77u};
        CHECK_INVALID(nl_plugin_register(world, NULL, &out), "entry");
        CHECK_INVALID(nl_plugin_register(world, entry_builder_two, NULL), "out_id");
        CHECK_INVALID(nl_plugin_register(NULL, entry_builder_two, &out), "world");
        CHECK(out.index1 == 77u);
    }

    /* A plugin that says it provides a link kind but fills no link-kind table is refused; it is
       no builder either. */
    CHECK_INVALID(nl_plugin_register(world, entry_links_only, &links), "link kind");
    def.builder = "c-test-links";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "c-test-links");
    {
        nl_navmesh_id out = {77u, 77u};
        CHECK_FAIL(nl_navmesh_build(world, &def, &out), NL_STATUS_NOT_FOUND, "c-test-links");
        CHECK_THAT(strstr(nl_get_last_error_message(), "'c-test-builder'") != NULL &&
                       strstr(nl_get_last_error_message(), "'recast'") != NULL,
                   "nl_navmesh_build: an unknown builder's message lists the builders there are");
    }
    CHECK_OK(nl_plugin_register(world, entry_builder_two, &second));
    CHECK(plugin_count(world) == 3);

    /* The description's strings are the world's: still there, unchanged, after all of that. */
    CHECK(strcmp(name, "c-test-builder") == 0);
    CHECK(strcmp(version, "2.5.1") == 0);
    CHECK(strcmp(description, "C test builder: a 2 x 2 grid") == 0);
    d = describe(world, builder);
    CHECK(d.name == name || strcmp(d.name, name) == 0);

    /* A builder's own failure, with the reason it gave. */
    def.builder = "c-test-builder";
    settings.size = sizeof settings;
    settings.mode = MODE_REPORT_ERROR;
    def.settings = &settings;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "'flavour' must be 'vanilla'");
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "c-test-builder");

    /* A builder that hands over an invalid navmesh: the navmesh's problem is in the message. */
    settings.mode = MODE_BAD_INDEX;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        const nl_status status = nl_navmesh_build(world, &def, &out);
        CHECK_MSG(NL_FAILED(status), "nl_navmesh_build with a builder whose navmesh is invalid returned 0x%08x",
                  (unsigned)status);
        CHECK(NL_FAILED(g_plugin.sink_status[0]));
        CHECK_MSG(strstr(nl_get_last_error_message(), "indices[6]") != NULL, "message \"%s\" lacks indices[6]",
                  nl_get_last_error_message());
        CHECK(strstr(nl_get_last_error_message(), "nl_navmesh_build") != NULL);
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    settings.mode = MODE_BAD_INDEX_SUCCEED;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        const nl_status status = nl_navmesh_build(world, &def, &out);
        CHECK_THAT(NL_FAILED(status) && strstr(nl_get_last_error_message(), "indices[6]") != NULL,
                   "nl_navmesh_build: a builder that ignores the sink's refusal and returns success still fails, "
                   "with the navmesh's problem");
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    settings.mode = MODE_NULL_NAVMESH;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        CHECK(NL_FAILED(nl_navmesh_build(world, &def, &out)));
        CHECK(NL_FAILED(g_plugin.sink_status[0]));
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    /* The other misbehaving builders (sink twice, no sink, sink then failure) are in
       misbehaving_builders, after running once each in a child process. */

    /* What a build used, as the builder records it, is what a saved file says it was built with. A
       record that is not a JSON object fails the build (a builder bug), adding nothing; one refused
       (NULL) leaves the build recorded without settings (a struct alone is not recorded). */
    CHECK(g_plugin.record_outside_status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    settings.mode = MODE_RECORD;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(g_plugin.record_status == NL_STATUS_SUCCESS);
    CHECK_THAT(
        strstr(navmesh_made_for(world, id), "\"builder_settings\":{\"flavour\":\"vanilla\",\"scoops\":2}") != NULL,
        "a saved file says the settings the builder recorded");
    settings.mode = MODE_RECORD_NOT_OBJECT;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        CHECK_FAIL(nl_navmesh_build(world, &def, &out), NL_STATUS_INTERNAL_ERROR, "not a JSON object");
        CHECK(strstr(nl_get_last_error_message(), "c-test-builder") != NULL);
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    settings.mode = MODE_RECORD_NULL;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(g_plugin.record_status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_THAT(strstr(navmesh_made_for(world, id), "\"builder_settings\":null") != NULL,
               "a build that recorded nothing, given a settings struct, says no settings");

    /* The level in columns: the box (8 vertices, 12 triangles; x and z from -10 to 10, y from 0 to
       1) whole with its bounds; its -x side (every triangle but the +x face's two, which stay at
       x = 10), nothing far away; refusals of NULL, NaN and crossed columns, and outside a build; a
       buffer short of a triangle. */
    CHECK(g_plugin.columns_outside_status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    settings.mode = MODE_COLUMNS;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(g_plugin.columns_status[0] == NL_STATUS_SUCCESS && g_plugin.columns_status[1] == NL_STATUS_SUCCESS &&
          g_plugin.columns_status[2] == NL_STATUS_SUCCESS);
    CHECK_MSG(g_plugin.columns_triangles[0] == 12 && g_plugin.columns_vertices[0] == 8 &&
                  g_plugin.columns_triangles[1] == 10 && g_plugin.columns_vertices[1] == 8 &&
                  g_plugin.columns_triangles[2] == 0 && g_plugin.columns_vertices[2] == 0,
              "columns gave %u/%u, %u/%u, %u/%u triangles/vertices", (unsigned)g_plugin.columns_triangles[0],
              (unsigned)g_plugin.columns_vertices[0], (unsigned)g_plugin.columns_triangles[1],
              (unsigned)g_plugin.columns_vertices[1], (unsigned)g_plugin.columns_triangles[2],
              (unsigned)g_plugin.columns_vertices[2]);
    CHECK(g_plugin.columns_bounds[0] == -10.0f && g_plugin.columns_bounds[1] == 0.0f &&
          g_plugin.columns_bounds[2] == -10.0f && g_plugin.columns_bounds[3] == 10.0f &&
          g_plugin.columns_bounds[4] == 1.0f && g_plugin.columns_bounds[5] == 10.0f);
    CHECK(g_plugin.columns_status[3] == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(g_plugin.columns_status[4] == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(g_plugin.columns_status[5] == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(g_plugin.columns_status[6] == (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL));

    /* Still works after all the failures. */
    settings.mode = MODE_GRID;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    check_grid_navmesh(world, id, 4, NULL, "built after failures");
    def.settings = NULL;
    def.builder = "c-test-builder-2";
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(navmesh_count(world) == 6);

    /* Destroying the world destroys each plugin state the entry made, once. */
    nl_world_destroy(world);
    CHECK_MSG(g_plugin.destroys == g_plugin.entries_ok,
              "%d plugin states destroyed, %d made by successful entry calls (refused registrations included)",
              g_plugin.destroys, g_plugin.entries_ok);
    CHECK(g_plugin.entry_checks == g_plugin.entries_ok);

    /* Plugins are per world: a new world has only the built-in one, and takes the same names again. */
    world = make_world(1);
    CHECK(plugin_count(world) == 1);
    CHECK_OK(nl_plugin_register(world, entry_builder, &builder));
    CHECK(strcmp(describe(world, builder).name, "c-test-builder") == 0);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Misbehaving builders: a failure, never a crash, never a navmesh added behind the caller's back.
 * ------------------------------------------------------------------------------------------- */

static const struct misbehaviour {
    uint32_t mode;
    const char* what;
} k_misbehaviours[] = {
    {MODE_SINK_TWICE, "a builder that calls the sink twice (returning the second answer)"},
    {MODE_SINK_TWICE_SUCCEED, "a builder that calls the sink twice and returns success"},
    {MODE_NO_SINK, "a builder that returns success without calling the sink"},
    {MODE_SINK_THEN_FAIL, "a builder that fails after the sink took its navmesh"},
};

enum { k_misbehaviour_count = sizeof k_misbehaviours / sizeof k_misbehaviours[0] };

/* Runs misbehaviour `m` on a fresh world; 1 if the build failed and added nothing. */
static int run_misbehaviour(size_t m) {
    nl_world* world = make_world(1);
    nl_plugin_id plugin = {0u, 0u};
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    test_builder_settings settings;
    nl_navmesh_id out = {77u, 77u};
    nl_status status;
    int ok;
    settings.size = sizeof settings;
    settings.mode = k_misbehaviours[m].mode;
    def.builder = "c-test-builder";
    def.settings = &settings;
    if (NL_FAILED(nl_plugin_register(world, entry_builder, &plugin))) {
        nl_world_destroy(world);
        return 0;
    }
    status = nl_navmesh_build(world, &def, &out);
    ok = NL_FAILED(status) && nl_get_last_error_message()[0] != '\0' && out.index1 == 77u && navmesh_count(world) == 0;
    nl_world_destroy(world);
    return ok;
}

static void misbehaving_builders(void) {
    /* -1: the child crashed; 0: wrong answer; 1: a failure and nothing added. */
    int in_child[k_misbehaviour_count];
    size_t m;
    /* First each in a child, while this process has no threads. */
    for (m = 0; m < k_misbehaviour_count; ++m) {
        in_child[m] = run_forked(run_misbehaviour, m);
        CHECK_MSG(in_child[m] == 1, "%s: %s", k_misbehaviours[m].what,
                  in_child[m] < 0 ? "crashed, or a sanitizer stopped it"
                                  : "did not fail cleanly (a success, or a navmesh left in the world)");
    }
    for (m = 0; m < k_misbehaviour_count; ++m) {
        nl_world* world;
        nl_plugin_id plugin = {0u, 0u};
        nl_navmesh_build_def def = nl_default_navmesh_build_def();
        test_builder_settings settings;
        nl_navmesh_id out = {77u, 77u};
        nl_status status;
        if (!CHECK_MSG(in_child[m] >= 0, "%s crashed the process (in a child)", k_misbehaviours[m].what))
            continue; /* it would crash this process too */
        world = make_world(1);
        settings.size = sizeof settings;
        settings.mode = k_misbehaviours[m].mode;
        def.builder = "c-test-builder";
        def.settings = &settings;
        CHECK_OK(nl_plugin_register(world, entry_builder, &plugin));
        status = nl_navmesh_build(world, &def, &out);
        CHECK_MSG(NL_FAILED(status), "%s: nl_navmesh_build returned 0x%08x (%s)", k_misbehaviours[m].what,
                  (unsigned)status, nl_status_string(status));
        CHECK_MSG(strstr(nl_get_last_error_message(), "c-test-builder") != NULL,
                  "%s: the message names the builder: \"%s\"", k_misbehaviours[m].what, nl_get_last_error_message());
        CHECK_MSG(out.index1 == 77u && out.revision == 77u, "%s: out_id was written", k_misbehaviours[m].what);
        CHECK_MSG(navmesh_count(world) == 0, "%s: the failed build left %u navmesh(es) in the world",
                  k_misbehaviours[m].what, (unsigned)navmesh_count(world));
        nl_world_destroy(world);
    }
}

ABI_SECTION(plugin_abi, ABI_CASE(registered), ABI_CASE(misbehaving_builders));
