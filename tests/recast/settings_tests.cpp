// Settings: by struct and by JSON give the same navmesh; bad settings fail with the documented status
// and the field named through set_error, before anything is built.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "fake_host.h"
#include "recast_builder.h"
#include "test_levels.h"

using namespace nl::test;

namespace {

FakeHost test_host() {
    // Two floors joined by a ramp, with a pillar: enough for settings to change the result.
    QuadLevel level;
    level.floor(0, 0, 12, 12, 0)
        .quad({12, 0, 0}, {18, 1.5f, 0}, {18, 1.5f, 12}, {12, 0, 12})
        .floor(18, 0, 30, 12, 1.5f)
        .quad({5, 0, 5}, {5, 3, 5}, {6, 3, 5}, {6, 0, 5})
        .floor(5, 5, 6, 6, 3);
    return level.host();
}

nl_recast_settings custom_settings() {
    nl_recast_settings s = nl::recast::default_settings();
    s.cell_size = 0.25f;
    s.cell_height = 0.15f;
    s.region_min_size = 4;
    s.region_merge_size = 10;
    s.edge_max_length = 8;
    s.edge_max_error = 1.1f;
    s.vertices_per_polygon = 4;
    s.detail_sample_distance = 4;
    s.detail_sample_max_error = 2;
    s.partition = NL_RECAST_PARTITION_MONOTONE;
    s.filter_ledge_spans = 0;
    return s;
}

const char* kCustomJson = R"({
  "cell_size": 0.25, "cell_height": 0.15, "region_min_size": 4, "region_merge_size": 10,
  "edge_max_length": 8, "edge_max_error": 1.1, "vertices_per_polygon": 4,
  "detail_sample_distance": 4, "detail_sample_max_error": 2, "partition": "monotone",
  "filter_low_hanging_obstacles": true, "filter_ledge_spans": false, "filter_walkable_low_height_spans": true
})";

}  // namespace

TEST_CASE("recast settings by struct and by JSON give the same navmesh") {
    FakeHost host = test_host();
    const BuildOutcome defaults = run_build(host, default_build_def());
    REQUIRE_MESSAGE(defaults.status == NL_STATUS_SUCCESS, defaults.error);

    // The defaults, spelled out either way, are the defaults.
    nl_recast_settings s = nl::recast::default_settings();
    nl_navmesh_build_def def = default_build_def();
    def.settings = &s;
    CHECK(run_build(host, def).mesh == defaults.mesh);
    CHECK(run_build(host, json_build_def("{}")).mesh == defaults.mesh);

    s = custom_settings();
    const BuildOutcome by_struct = run_build(host, def);
    REQUIRE_MESSAGE(by_struct.status == NL_STATUS_SUCCESS, by_struct.error);
    const std::string json = kCustomJson;
    const BuildOutcome by_json = run_build(host, json_build_def(json));
    REQUIRE_MESSAGE(by_json.status == NL_STATUS_SUCCESS, by_json.error);
    CHECK(by_struct.mesh == by_json.mesh);
    CHECK_FALSE(by_struct.mesh == defaults.mesh);
    for (uint8_t n : by_json.mesh.vertex_counts) CHECK(n <= 4);

    // JSON applies over the struct: the struct's cell size plus JSON's other fields.
    nl_recast_settings partial = nl::recast::default_settings();
    partial.cell_size = 0.25f;
    partial.cell_height = 0.15f;
    const std::string rest = R"({"region_min_size": 4, "region_merge_size": 10, "edge_max_length": 8,
        "edge_max_error": 1.1, "vertices_per_polygon": 4, "detail_sample_distance": 4,
        "detail_sample_max_error": 2, "partition": 1, "filter_ledge_spans": false, "cell_size": 0.25})";
    nl_navmesh_build_def mixed = json_build_def(rest);
    mixed.settings = &partial;
    CHECK(run_build(host, mixed).mesh == by_struct.mesh);
}

TEST_CASE("recast settings struct: a newer, longer struct is read up to what this builder knows") {
    FakeHost host = test_host();
    struct Longer {
        nl_recast_settings known;
        float future_field;
    } longer{custom_settings(), 42.0f};
    longer.known.size = sizeof longer;
    nl_navmesh_build_def def = default_build_def();
    def.settings = &longer;
    const BuildOutcome out = run_build(host, def);
    REQUIRE_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
    nl_recast_settings plain = custom_settings();
    def.settings = &plain;
    CHECK(run_build(host, def).mesh == out.mesh);
}

TEST_CASE("recast settings struct: bad size or field is INVALID_ARGUMENT naming it") {
    FakeHost host = test_host();
    struct Case {
        const char* name;
        void (*edit)(nl_recast_settings&);
        const char* field;
    };
    const Case cases[] = {
        {"size too small", [](nl_recast_settings& s) { s.size = offsetof(nl_recast_settings, reserved); },
         "settings.size"},
        {"size zero", [](nl_recast_settings& s) { s.size = 0; }, "settings.size"},
        {"cell_size 0", [](nl_recast_settings& s) { s.cell_size = 0; }, "settings.cell_size"},
        {"cell_height NaN", [](nl_recast_settings& s) { s.cell_height = std::nanf(""); }, "settings.cell_height"},
        {"vertices 7", [](nl_recast_settings& s) { s.vertices_per_polygon = 7; }, "settings.vertices_per_polygon"},
        {"vertices 2", [](nl_recast_settings& s) { s.vertices_per_polygon = 2; }, "settings.vertices_per_polygon"},
        {"partition 3", [](nl_recast_settings& s) { s.partition = 3; }, "settings.partition"},
        {"filter 2", [](nl_recast_settings& s) { s.filter_ledge_spans = 2; }, "settings.filter_ledge_spans"},
        {"edge_max_error -1", [](nl_recast_settings& s) { s.edge_max_error = -1; }, "settings.edge_max_error"},
        {"region_min_size huge", [](nl_recast_settings& s) { s.region_min_size = 1e6f; }, "settings.region_min_size"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.name);
        nl_recast_settings s = nl::recast::default_settings();
        c.edit(s);
        nl_navmesh_build_def def = default_build_def();
        def.settings = &s;
        const BuildOutcome out = run_build(host, def);
        CHECK(out.status == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
        CHECK(out.sink_calls == 0);
        CAPTURE(out.error);
        CHECK(out.error.find(c.field) != std::string::npos);
    }
}

namespace {

std::string repeated(const std::string& text, size_t times) {
    std::string out;
    for (size_t i = 0; i < times; ++i) out += text;
    return out;
}

}  // namespace

TEST_CASE("recast settings JSON: malformed, unknown, mistyped or out-of-range values are refused") {
    FakeHost host = test_host();
    constexpr nl_status kInvalid = NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    constexpr nl_status kParse = NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR;
    struct Case {
        std::string json;
        nl_status status;
        std::vector<std::string> mentions;  // substrings the set_error message must contain
    };
    const Case cases[] = {
        {R"({"cell_size": 0.3,)", kParse, {"settings_json", "malformed", "line 1, column 19"}},
        {"{\n  \"cell_size\" 0.3\n}", kParse, {"settings_json", "line 2"}},
        {"not json", kParse, {"settings_json", "column"}},
        {"", kParse, {"settings_json"}},
        {R"({"cell_sizes": 0.3})", kInvalid, {"settings_json", "unknown key \"cell_sizes\""}},
        {R"({"size": 48})", kInvalid, {"unknown key \"size\""}},
        {R"({"reserved": 0})", kInvalid, {"unknown key \"reserved\""}},
        {R"({"cell_size": "0.3"})", kInvalid, {"settings_json: cell_size", "number"}},
        {R"({"cell_size": null})", kInvalid, {"settings_json: cell_size"}},
        {R"({"cell_size": 0})", kInvalid, {"settings_json: cell_size", "> 0"}},
        {R"({"cell_size": -0.3})", kInvalid, {"settings_json: cell_size"}},
        {R"({"cell_size": 1e39})", kInvalid, {"settings_json: cell_size", "finite"}},
        {R"({"cell_height": 0.0})", kInvalid, {"settings_json: cell_height"}},
        {R"({"region_min_size": -1})", kInvalid, {"settings_json: region_min_size"}},
        {R"({"edge_max_length": -12})", kInvalid, {"settings_json: edge_max_length"}},
        {R"({"detail_sample_max_error": [1]})", kInvalid, {"settings_json: detail_sample_max_error"}},
        {R"({"vertices_per_polygon": 7})", kInvalid, {"settings_json: vertices_per_polygon", "3..6"}},
        {R"({"vertices_per_polygon": 2})", kInvalid, {"settings_json: vertices_per_polygon"}},
        {R"({"vertices_per_polygon": -6})", kInvalid, {"settings_json: vertices_per_polygon"}},
        {R"({"vertices_per_polygon": 18446744073709551615})", kInvalid, {"settings_json: vertices_per_polygon"}},
        {R"({"vertices_per_polygon": 4.5})", kInvalid, {"settings_json: vertices_per_polygon", "integer"}},
        {R"({"partition": "voronoi"})", kInvalid, {"settings_json: partition", "watershed"}},
        {R"({"partition": 3})", kInvalid, {"settings_json: partition"}},
        {R"({"partition": true})", kInvalid, {"settings_json: partition"}},
        {R"({"filter_ledge_spans": 1})", kInvalid, {"settings_json: filter_ledge_spans", "true or false"}},
        {R"({"filter_low_hanging_obstacles": "yes"})", kInvalid, {"settings_json: filter_low_hanging_obstacles"}},
        {R"({"cell_size": 1e400})", kInvalid, {"settings_json: cell_size is 1e400", "beyond the range"}},
        {R"({"edge_max_error": -1E+999})", kInvalid, {"settings_json: edge_max_error"}},
        {"{\"vertices_per_polygon\": " + std::string(100000, '[') + std::string(100000, ']') + "}",
         kInvalid,
         {"settings_json: vertices_per_polygon[0]", "64 levels"}},
        {"{\"vertices_per_polygon\": [" + repeated("7, ", 100000) + "7]}",
         kInvalid,
         {"settings_json: vertices_per_polygon", "an array of 100001 values"}},
        {"{\"partition\": \"" + repeated("voronoi", 100000) + "\"}",
         kInvalid,
         {"settings_json: partition", "(got \"voronoivoronoi", "...\")"}},
        {"{\"" + repeated("cell", 100000) + "\": 1}", kInvalid, {"settings_json: unknown key \"cellcell"}},
        {R"([0.3, 0.2])", kInvalid, {"settings_json", "object"}},
        {R"("cell_size")", kInvalid, {"settings_json", "object"}},
    };
    for (const Case& c : cases) {
        const std::string start = c.json.substr(0, 80);
        CAPTURE(start);
        const BuildOutcome out = run_build(host, json_build_def(c.json));
        CHECK(out.status == c.status);
        CHECK(out.sink_calls == 0);
        CAPTURE(out.error);
        for (const std::string& m : c.mentions) CHECK(out.error.find(m) != std::string::npos);
        CHECK(out.error.size() < 400);  // a message quotes a value short, however long the value
    }

    // The length is what counts, not a NUL: a JSON object followed by bytes beyond the length is fine,
    // and a NULL pointer with a length is refused.
    const std::string padded = R"({"cell_size": 0.3}garbage)";
    nl_navmesh_build_def def = json_build_def(padded);
    def.settings_json_length = std::strlen(R"({"cell_size": 0.3})");
    CHECK(run_build(host, def).status == NL_STATUS_SUCCESS);
    def.settings_json = nullptr;
    const BuildOutcome null_json = run_build(host, def);
    CHECK(null_json.status == kInvalid);
    CHECK(null_json.error.find("settings_json") != std::string::npos);
}
