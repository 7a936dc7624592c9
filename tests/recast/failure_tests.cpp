// Levels with nothing to walk on, bad agents, grids beyond Recast's limits, a failing sink, and
// Recast's log reaching the host.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fake_host.h"
#include "host_log_context.h"
#include "recast_builder.h"
#include "shared_levels.h"
#include "test_levels.h"

using namespace nl::test;

namespace {

constexpr nl_status kNotFound = NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
constexpr nl_status kInvalid = NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;

void check_no_walkable_surface(const BuildOutcome& out) {
    CHECK(out.status == kNotFound);
    CHECK(out.sink_calls == 0);
    CAPTURE(out.error);
    CHECK(out.error.rfind("no walkable surface", 0) == 0);
}

}  // namespace

TEST_CASE("recast: a level with no walkable surface is NOT_FOUND, never an empty navmesh") {
    SUBCASE("a single vertical wall") {
        FakeHost host = QuadLevel().quad({0, 0, 0}, {10, 0, 0}, {10, 3, 0}, {0, 3, 0}).host();
        check_no_walkable_surface(run_build(host, default_build_def()));
    }
    SUBCASE("a floor steeper than max_slope, walkable once max_slope allows it") {
        // 50 degrees: the heights of neighbouring cells differ by 0.36 m, within max_climb (Recast's
        // ledge filter drops steeper ground whatever max_slope says).
        const float rise = 10.0f * std::tan(50.0f * 3.14159265f / 180.0f);
        FakeHost host = QuadLevel().quad({0, 0, 0}, {10, 0, 0}, {10, rise, 10}, {0, rise, 10}).host();
        check_no_walkable_surface(run_build(host, default_build_def()));
        nl_navmesh_build_def steep = default_build_def();
        steep.agent_type.max_slope = 55.0f;
        const BuildOutcome out = run_build(host, steep);
        CHECK_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
        CHECK(out.mesh.polygon_count() > 0);
    }
    SUBCASE("an empty level") {
        FakeHost host;
        check_no_walkable_surface(run_build(host, default_build_def()));
    }
    SUBCASE("a floor narrower than the agent") {
        FakeHost host = QuadLevel().floor(0, 0, 1.0f, 1.0f, 0).host();
        check_no_walkable_surface(run_build(host, default_build_def()));
    }
    SUBCASE("a floor under a ceiling lower than the agent") {
        FakeHost host = QuadLevel().floor(0, 0, 10, 10, 0).ceiling(-1, -1, 11, 11, 1.2f).host();
        check_no_walkable_surface(run_build(host, default_build_def()));
        nl_navmesh_build_def short_agent = default_build_def();
        short_agent.agent_type.height = 0.6f;
        short_agent.agent_type.max_climb = 0.2f;
        const BuildOutcome out = run_build(host, short_agent);
        CHECK_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
    }
    SUBCASE("a plain floor builds") {
        FakeHost host = QuadLevel().floor(0, 0, 10, 10, 0).host();
        const BuildOutcome out = run_build(host, default_build_def());
        REQUIRE_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
        CHECK(out.mesh.polygon_count() >= 1);
        // The radius is kept from the edges: corners near (0.6, 0.6) .. (9.4, 9.4), snapped to the grid.
        for (size_t i = 0; i < out.mesh.vertices.size(); i += 3) {
            CHECK(out.mesh.vertices[i] >= 0.5f);
            CHECK(out.mesh.vertices[i] <= 9.5f);
            CHECK(std::fabs(out.mesh.vertices[i + 1]) <= 0.21f);  // Recast's heights are span tops: up to a cell above
        }
    }
}

TEST_CASE("recast: bad agent types are INVALID_ARGUMENT naming the field") {
    FakeHost host = QuadLevel().floor(0, 0, 10, 10, 0).host();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    struct Case {
        nl_agent_type agent;
        const char* field;
    };
    const Case cases[] = {
        {{-0.1f, 2.0f, 0.9f, 45.0f}, "agent_type.radius"},
        {{nan, 2.0f, 0.9f, 45.0f}, "agent_type.radius"},
        {{inf, 2.0f, 0.9f, 45.0f}, "agent_type.radius"},
        {{0.6f, 0.0f, 0.9f, 45.0f}, "agent_type.height"},
        {{0.6f, -2.0f, 0.9f, 45.0f}, "agent_type.height"},
        {{0.6f, 2.0f, -0.5f, 45.0f}, "agent_type.max_climb"},
        {{0.6f, 2.0f, nan, 45.0f}, "agent_type.max_climb"},
        {{0.6f, 2.0f, 0.9f, 90.0f}, "agent_type.max_slope"},
        {{0.6f, 2.0f, 0.9f, -1.0f}, "agent_type.max_slope"},
        {{0.6f, 2.0f, 0.9f, nan}, "agent_type.max_slope"},
        // Beyond what Recast can represent at the default cell size.
        {{100.0f, 2.0f, 0.9f, 45.0f}, "agent_type.radius"},
        {{0.6f, 100.0f, 0.9f, 45.0f}, "agent_type.height"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.field);
        nl_navmesh_build_def def = default_build_def();
        def.agent_type = c.agent;
        const BuildOutcome out = run_build(host, def);
        CHECK(out.status == kInvalid);
        CHECK(out.sink_calls == 0);
        CAPTURE(out.error);
        CHECK(out.error.find(c.field) != std::string::npos);
    }
    // Zero radius and climb are fine.
    nl_navmesh_build_def def = default_build_def();
    def.agent_type = {0.0f, 2.0f, 0.0f, 0.0f};
    CHECK(run_build(host, def).status == kNotFound);  // slope 0: nothing is flatter than flat
    def.agent_type.max_slope = 10.0f;
    CHECK(run_build(host, def).status == NL_STATUS_SUCCESS);
}

TEST_CASE("recast: a grid beyond Recast's limits names the cell size to raise") {
    FakeHost wide = QuadLevel().floor(0, 0, 10000, 10, 0).host();
    const BuildOutcome out = run_build(wide, json_build_def(R"({"cell_size": 0.1})"));
    CHECK(out.status == kInvalid);
    CHECK(out.error.find("cell_size") != std::string::npos);

    FakeHost tall = QuadLevel().floor(0, 0, 10, 10, 0).floor(0, 0, 10, 10, 2000).host();
    const BuildOutcome tall_out = run_build(tall, default_build_def());
    CHECK(tall_out.status == kInvalid);
    CHECK(tall_out.error.find("cell_height") != std::string::npos);
    CHECK(run_build(tall, json_build_def(R"({"cell_height": 0.5})")).status == NL_STATUS_SUCCESS);

    // A cell so large the navmesh's vertices would lie beyond the coordinate limit (found by
    // navlink-fuzz-recast_settings: the builder handed over a navmesh 1.1e19 m high).
    FakeHost floor = QuadLevel().floor(0, 0, 10, 10, 0).host();
    const BuildOutcome huge_cell = run_build(floor, json_build_def(R"({"cell_height": 1.1e18})"));
    CHECK(huge_cell.status == kInvalid);
    CHECK(huge_cell.sink_calls == 0);
    CHECK(huge_cell.error.find("cell_height") != std::string::npos);
    CHECK(huge_cell.error.find("coordinate limit") != std::string::npos);
}

TEST_CASE("recast: a floor with more walkable cells than Recast indexes names the cell size to raise") {
    // 1,250 m at 0.3 m: 4,167 x 4,167 cells, past the 16,777,215 spans a compact heightfield indexes.
    // Watershed regions came out empty ("no walkable surface"), monotone ones left a third of it out.
    FakeHost floor = QuadLevel().floor(0, 0, 1250, 1250, 0).host();
    for (const char* partition : {"watershed", "monotone"}) {
        CAPTURE(partition);
        const BuildOutcome out =
            run_build(floor, json_build_def(std::string("{\"partition\": \"") + partition + "\"}"));
        CHECK(out.status == kInvalid);
        CHECK(out.sink_calls == 0);
        CAPTURE(out.error);
        CHECK(out.error.find("16777215") != std::string::npos);
        CHECK(out.error.find("raise cell_size to at least 0.306 m") != std::string::npos);
    }
    const BuildOutcome coarser = run_build(floor, json_build_def(R"({"cell_size": 1.0})"));
    CHECK_MESSAGE(coarser.status == NL_STATUS_SUCCESS, coarser.error);
    float depth = 0.0f;  // the whole floor, not a part of it
    for (size_t v = 2; v < coarser.mesh.vertices.size(); v += 3) depth = std::max(depth, coarser.mesh.vertices[v]);
    CHECK(depth > 1240.0f);
}

TEST_CASE("recast: the sink's status is the build's, and the sink is called once") {
    FakeHost host = QuadLevel().floor(0, 0, 10, 10, 0).host();
    const nl_status refused = NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
    const BuildOutcome out = run_build(host, default_build_def(), refused);
    CHECK(out.status == refused);
    CHECK(out.sink_calls == 1);
    CHECK(out.error.empty());  // the sink reports its own failure
}

TEST_CASE("recast: null arguments are refused") {
    FakeHost host = QuadLevel().floor(0, 0, 10, 10, 0).host();
    const nl_plugin_host table = host.table();
    nl_plugin_info info{};
    info.size = sizeof info;
    REQUIRE(nl::recast::plugin_entry(1, &table, &info) == NL_STATUS_SUCCESS);
    const nl_navmesh_build_def def = default_build_def();
    auto sink = [](void*, const nl_navmesh_def*) -> nl_status { return NL_STATUS_SUCCESS; };
    CHECK(info.navmesh_builder.build(nullptr, nullptr, &def, sink, nullptr) == kInvalid);
    CHECK(info.navmesh_builder.build(nullptr, &table, nullptr, sink, nullptr) == kInvalid);
    CHECK(info.navmesh_builder.build(nullptr, &table, &def, nullptr, nullptr) == kInvalid);
    CHECK(host.errors().size() == 2);
}

TEST_CASE("recast: Recast's warnings and errors reach the host's log, progress does not") {
    FakeHost host;
    const nl_plugin_host table = host.table();
    nl::recast::HostLogContext context(table);
    context.log(RC_LOG_PROGRESS, "progress %d", 1);
    context.log(RC_LOG_WARNING, "warning %d", 2);
    context.log(RC_LOG_ERROR, "rcBuildSomething: Out of memory %d", 3);
    const auto logs = host.logs();
    REQUIRE(logs.size() == 2);
    CHECK(logs[0] == std::to_string(NL_LOG_WARNING) + " recast: warning 2");
    CHECK(logs[1] == std::to_string(NL_LOG_ERROR) + " recast: rcBuildSomething: Out of memory 3");
    CHECK(context.last_error() == "rcBuildSomething: Out of memory 3");
}
