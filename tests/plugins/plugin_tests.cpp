// Plugins through the public C ABI only: the built-in Recast builder is listed, a builder loaded from
// a shared library builds navmeshes, and every way a load can fail gives its own status and message.
#include <doctest/doctest.h>
#include <navlink/navlink.h>
#include <navlink/plugin.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "generated_level_c.h"

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
    REQUIRE(nl::test::add_generated_level(world, level) == NL_STATUS_SUCCESS);
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
    CHECK(nl_plugin_load(w.world, TEST_PLUGIN_BAD_ANSWER_PATH, &id) ==
          (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH));
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

namespace {

// A 2.5 m block standing on a wide floor: too high to step, low enough to climb.
struct BlockScene {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    BlockScene() {
        REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
        nl::levelgen::GeneratedLevel level;
        level.add_box({{-10, -1, -10}, {20, 0, 20}});
        level.add_box({{0, 0, 0}, {6, 2.5f, 10}});
        REQUIRE(nl::test::add_generated_level(world, level) == NL_STATUS_SUCCESS);
        const nl_navmesh_build_def build = nl_default_navmesh_build_def();
        REQUIRE(nl_navmesh_build(world, &build, &navmesh) == NL_STATUS_SUCCESS);
    }
    ~BlockScene() { nl_world_destroy(world); }
    std::string generate_error;  // the last error message right after the last generation

    std::vector<nl_link> generate(const char* plugin_json, nl_status expected = NL_STATUS_SUCCESS) {
        nl_link_settings settings = nl_default_link_settings();
        settings.plugin_settings_json = plugin_json;
        settings.plugin_settings_json_length = plugin_json ? std::strlen(plugin_json) : 0;
        nl_link_generation_report report{};
        report.size = sizeof report;
        CHECK_MESSAGE(nl_navmesh_generate_links(world, navmesh, &settings, nullptr, nullptr, &report) == expected,
                      nl_get_last_error_message());
        generate_error = nl_get_last_error_message();
        uint32_t count = 0;
        nl_navmesh_get_links(world, navmesh, nullptr, 0, &count);
        std::vector<nl_link> links(count, nl_link_init());
        nl_navmesh_get_links(world, navmesh, links.data(), count, &count);
        return links;
    }
};

std::vector<nl_link> of_kind(const std::vector<nl_link>& links, nl_link_kind kind) {
    std::vector<nl_link> out;
    for (const nl_link& l : links)
        if (l.kind == kind) out.push_back(l);
    return out;
}

}  // namespace

TEST_CASE("the climb link kind, loaded as a plugin, links the foot of a wall to its top") {
    BlockScene s;
    CHECK(of_kind(s.generate(nullptr), NL_LINK_FIRST_PLUGIN_KIND).empty());  // not loaded yet

    nl_plugin_id climb{};
    REQUIRE_MESSAGE(nl_plugin_load(s.world, CLIMB_PLUGIN_PATH, &climb) == NL_STATUS_SUCCESS, last_error());
    const nl_plugin_description d = describe(s.world, climb);
    CHECK(d.kinds == NL_PLUGIN_LINK_KIND);

    const auto links = s.generate(nullptr);
    const auto climbs = of_kind(links, NL_LINK_FIRST_PLUGIN_KIND);
    REQUIRE(!climbs.empty());
    CHECK(!of_kind(links, NL_LINK_DROP).empty());  // the built-in kinds are still generated
    for (const nl_link& l : climbs) {
        CHECK(l.generated == 1);
        CHECK(l.bidirectional == 1);
        CHECK(l.requirements.abilities == 1u);
        CHECK(l.start[1] < 0.6f);  // on the floor
        CHECK(l.end[1] > 2.3f);    // on top of the block
        // A climb asks for the ability, not for a jump's height (requirements_as_given = 1), so a
        // body that cannot jump climbs it; its length is still the ends'.
        CHECK(l.requirements.rise == 0.0f);
        CHECK(l.requirements.drop == 0.0f);
        CHECK(l.requirements.gap == 0.0f);
        // (Measured before its ends were put on the navmesh grid: within a millimetre of them.)
        CHECK(std::fabs(l.requirements.length - std::hypot(l.end[0] - l.start[0], l.end[2] - l.start[2])) <= 0.001f);
        CHECK(l.cost_modifier == 2.0f);
        // The top end lies over the block.
        CHECK(l.end[0] > 0.0f);
        CHECK(l.end[0] < 6.0f);
    }
    // Four sides of a 6 x 10 m block, sampled every metre: about 30 climbs.
    CHECK(climbs.size() >= 20);

    // Settings reach the plugin: a lower limit than the block has no climb; another ability bit.
    CHECK(of_kind(s.generate("{\"climb\": {\"max_height\": 2.0}}"), NL_LINK_FIRST_PLUGIN_KIND).empty());
    for (const nl_link& l : of_kind(s.generate("{\"climb\": {\"ability_bit\": 3}}"), NL_LINK_FIRST_PLUGIN_KIND))
        CHECK(l.requirements.abilities == 8u);

    // A bad plugin setting fails the generation with the plugin's reason; the links stay as they were.
    const size_t before = s.generate(nullptr).size();
    s.generate("{\"climb\": {\"max_hieght\": 2}}", NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT);
    CHECK(s.generate_error.find("max_hieght") != std::string::npos);
    CHECK(s.generate_error.find("link-kind plugin 'climb'") != std::string::npos);
    uint32_t count = 0;
    nl_navmesh_get_links(s.world, s.navmesh, nullptr, 0, &count);
    CHECK(count == before);
}

TEST_CASE("plugin settings that are too deep, beyond a double or not an object are refused before any work") {
    BlockScene s;
    nl_plugin_id climb{};
    REQUIRE_MESSAGE(nl_plugin_load(s.world, CLIMB_PLUGIN_PATH, &climb) == NL_STATUS_SUCCESS, last_error());
    const size_t before = s.generate(nullptr).size();
    constexpr nl_status kInvalid = NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    struct Case {
        std::string json;
        std::vector<std::string> mentions;
    };
    const Case cases[] = {
        // Re-serialised for the plugin, this one overflowed the stack.
        {"{\"climb\": {\"max_height\": " + std::string(100000, '[') + std::string(100000, ']') + "}}",
         {"plugin_settings_json: climb.max_height[0]", "64 levels"}},
        {"{\"climb\": {\"max_height\": 1e400}}", {"plugin_settings_json: climb.max_height is 1e400"}},
        {"{\"climb\": 3}", {"\"climb\" must be a JSON object", "not 3"}},
        {"{\"climb\": [1, 2]}", {"\"climb\" must be a JSON object", "not an array of 2 values"}},
        {"{\"not_loaded\": \"x\"}", {"\"not_loaded\" must be a JSON object"}},
        // Settings for a kind no loaded plugin provides would change nothing: a misspelling is named.
        {"{\"clmb\": {\"max_height\": 3}}",
         {"no loaded link-kind plugin provides the kind \"clmb\"", "(loaded: 'climb')"}},
    };
    for (const Case& c : cases) {
        CAPTURE(c.json.substr(0, 60));
        s.generate(c.json.c_str(), kInvalid);
        for (const std::string& m : c.mentions)
            CHECK_MESSAGE(s.generate_error.find(m) != std::string::npos, s.generate_error);
        CHECK(s.generate_error.size() < 300);
        uint32_t count = 0;
        nl_navmesh_get_links(s.world, s.navmesh, nullptr, 0, &count);
        CHECK(count == before);
    }
}

TEST_CASE("plugin settings for a plugin that is not loaded are refused, naming what is loaded") {
    BlockScene s;
    s.generate("{\"climb\": {\"max_height\": 3}}", NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE(s.generate_error.find("no loaded link-kind plugin provides the kind \"climb\" (loaded: none)") !=
                      std::string::npos,
                  s.generate_error);
    s.generate("{}");  // no plugin settings: the built-in kinds alone
    // Cross links run no plugin, but their plugin settings are checked the same way.
    nl_link_settings settings = nl_default_link_settings();
    static const char climb[] = "{\"climb\": {}}";
    settings.plugin_settings_json = climb;
    settings.plugin_settings_json_length = sizeof climb - 1;
    CHECK(nl_navmesh_generate_cross_links(s.world, s.navmesh, s.navmesh, 0.5f, &settings, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_MESSAGE(
        std::string(nl_get_last_error_message()).find("no loaded link-kind plugin provides the kind \"climb\"") !=
            std::string::npos,
        nl_get_last_error_message());
}
