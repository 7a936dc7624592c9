// Plugins through the public C ABI only: the built-in Recast builder is listed, a builder loaded from
// a shared library builds navmeshes, and every way a load can fail gives its own status and message.
#include <doctest/doctest.h>
#include <navlink/navlink.h>
#include <navlink/plugin.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "level_generator.h"

namespace {

struct World {
    nl_world* world = nullptr;
    World() { REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS); }
    ~World() { nl_world_destroy(world); }
};

std::string last_error() { return nl_get_last_error_message(); }

std::vector<nl_plugin_id> plugins_of(nl_world* world) {
    uint32_t count = 0;
    REQUIRE(nl_world_get_plugins(world, nullptr, 0, &count) == NL_STATUS_SUCCESS);
    std::vector<nl_plugin_id> ids(count);
    REQUIRE(nl_world_get_plugins(world, ids.data(), count, &count) == NL_STATUS_SUCCESS);
    return ids;
}

nl_plugin_description describe(nl_world* world, nl_plugin_id id) {
    nl_plugin_description d{};
    d.size = sizeof d;
    REQUIRE(nl_plugin_get_description(world, id, &d) == NL_STATUS_SUCCESS);
    return d;
}

// The default level, and how many of its triangles face up within the default max slope.
uint32_t add_default_level(nl_world* world) {
    const auto level = nl::levelgen::generate_default_level(3);
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = level.positions.data();
    def.vertex_count = level.vertex_count();
    def.indices = level.indices.data();
    def.triangle_count = level.triangle_count();
    nl_mesh_id id{};
    REQUIRE(nl_mesh_add(world, &def, &id) == NL_STATUS_SUCCESS);
    uint32_t up = 0;
    for (uint32_t t = 0; t < level.triangle_count(); ++t) {
        const float* a = &level.positions[3 * level.indices[3 * t]];
        const float* b = &level.positions[3 * level.indices[3 * t + 1]];
        const float* c = &level.positions[3 * level.indices[3 * t + 2]];
        const float ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
        up += ny > 0.0f;  // boxes: faces are exactly up, down or vertical
    }
    return up;
}

}  // namespace

TEST_CASE("every world lists the built-in Recast builder") {
    World w;
    const auto ids = plugins_of(w.world);
    REQUIRE(ids.size() == 1);
    const nl_plugin_description d = describe(w.world, ids[0]);
    CHECK(std::string(d.name) == "recast");
    CHECK(d.builtin == 1);
    CHECK(d.kinds == NL_PLUGIN_NAVMESH_BUILDER);
    CHECK(d.abi_version == NL_PLUGIN_ABI_VERSION);
}

TEST_CASE("a builder plugin loaded from a shared library builds a navmesh") {
    World w;
    const uint32_t expected = add_default_level(w.world);
    nl_plugin_id plugin{};
    REQUIRE_MESSAGE(nl_plugin_load(w.world, TEST_PLUGIN_OK_PATH, &plugin) == NL_STATUS_SUCCESS, last_error());
    const nl_plugin_description d = describe(w.world, plugin);
    CHECK(std::string(d.name) == "walkable-triangles");
    CHECK(std::string(d.version) == "1.0");
    CHECK(d.builtin == 0);
    CHECK(plugins_of(w.world).size() == 2);

    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.builder = "walkable-triangles";
    nl_navmesh_id navmesh{};
    REQUIRE_MESSAGE(nl_navmesh_build(w.world, &build, &navmesh) == NL_STATUS_SUCCESS, last_error());
    nl_navmesh_info info{};
    info.size = sizeof info;
    REQUIRE(nl_navmesh_get_info(w.world, navmesh, &info) == NL_STATUS_SUCCESS);
    CHECK(info.polygon_count == expected);
    CHECK(info.portal_count > 0);  // each box top is two triangles sharing a diagonal

    // Loading the same plugin again is refused by name; the first stays usable.
    nl_plugin_id again{};
    CHECK(nl_plugin_load(w.world, TEST_PLUGIN_OK_PATH, &again) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("already loaded") != std::string::npos);
    CHECK(plugins_of(w.world).size() == 2);
}

TEST_CASE("plugin load failures: missing file, not a library, no entry symbol, version mismatch") {
    World w;
    nl_plugin_id id{};
    CHECK(nl_plugin_load(w.world, "/nonexistent/plugin.so", &id) == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    CHECK(last_error().find("/nonexistent/plugin.so") != std::string::npos);

    const std::string text_file = std::string(TEST_BINARY_DIR) + "/not_a_library.so";
    std::FILE* f = std::fopen(text_file.c_str(), "w");
    REQUIRE(f);
    std::fputs("this is not an ELF file\n", f);
    std::fclose(f);
    CHECK(nl_plugin_load(w.world, text_file.c_str(), &id) == (NL_STATUS_FAILURE | NL_STATUS_IO_ERROR));
    CHECK(last_error().find("cannot load") != std::string::npos);

    CHECK(nl_plugin_load(w.world, TEST_PLUGIN_NO_ENTRY_PATH, &id) == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    CHECK(last_error().find("nl_plugin_entry") != std::string::npos);

    CHECK(nl_plugin_load(w.world, TEST_PLUGIN_TOO_NEW_PATH, &id) == (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH));
    CHECK(nl_plugin_load(w.world, TEST_PLUGIN_BAD_ANSWER_PATH, &id) == (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH));
    CHECK(last_error().find("answered ABI version 2") != std::string::npos);

    CHECK(nl_plugin_load(w.world, nullptr, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(nl_plugin_load(nullptr, TEST_PLUGIN_OK_PATH, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(plugins_of(w.world).size() == 1);  // nothing half-registered
}

namespace {

int destroyed = 0;

nl_status refuse_build(void*, const nl_plugin_host* host, const nl_navmesh_build_def*, nl_navmesh_sink_fn*, void*) {
    host->set_error(host->context, "settings_json: 'speed' is not a setting of this builder");
    return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
}

nl_status compiled_in_entry(uint32_t host_abi_version, const nl_plugin_host*, nl_plugin_info* info) {
    if (host_abi_version < 1) return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
    info->abi_version = 1;
    info->name = "picky";
    info->kinds = NL_PLUGIN_NAVMESH_BUILDER;
    info->navmesh_builder.build = refuse_build;
    info->destroy = [](void*) { ++destroyed; };
    return NL_STATUS_SUCCESS;
}

}  // namespace

TEST_CASE("a plugin compiled into the host registers directly, and its errors reach the caller") {
    destroyed = 0;
    {
        World w;
        add_default_level(w.world);
        nl_plugin_id id{};
        REQUIRE(nl_plugin_register(w.world, compiled_in_entry, &id) == NL_STATUS_SUCCESS);
        nl_navmesh_build_def build = nl_default_navmesh_build_def();
        build.builder = "picky";
        nl_navmesh_id navmesh{};
        CHECK(nl_navmesh_build(w.world, &build, &navmesh) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
        CHECK(last_error().find("'speed' is not a setting") != std::string::npos);
        uint32_t count = 1;
        CHECK(nl_world_get_navmeshes(w.world, nullptr, 0, &count) == NL_STATUS_SUCCESS);
        CHECK(count == 0);

        build.builder = "no-such-builder";
        CHECK(nl_navmesh_build(w.world, &build, &navmesh) == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
        CHECK(last_error().find("'recast'") != std::string::npos);  // the message lists what is there
        CHECK(destroyed == 0);
    }
    CHECK(destroyed == 1);  // the world's destruction released the plugin
}
