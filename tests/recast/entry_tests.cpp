// The plugin's entry function: version negotiation and what it says about itself; the defaults.
#include <doctest/doctest.h>

#include <cstring>
#include <string>

#include "fake_host.h"
#include "recast_builder.h"

using nl::test::FakeHost;

TEST_CASE("recast plugin entry describes a navmesh builder speaking ABI version 1") {
    FakeHost host;
    const nl_plugin_host table = host.table();
    for (uint32_t host_version : {1u, 2u, 100u}) {
        nl_plugin_info info{};
        info.size = sizeof info;
        REQUIRE(nl::recast::plugin_entry(host_version, &table, &info) == NL_STATUS_SUCCESS);
        CHECK(info.abi_version == NL_PLUGIN_ABI_VERSION);
        REQUIRE((info.name != nullptr));
        CHECK(std::string(info.name) == "recast");
        REQUIRE((info.version != nullptr));
        CHECK(std::strlen(info.version) > 0);
        REQUIRE((info.description != nullptr));
        CHECK(std::strlen(info.description) > 0);
        CHECK(std::strchr(info.description, '\n') == nullptr);
        CHECK(info.kinds == NL_PLUGIN_NAVMESH_BUILDER);
        CHECK((info.navmesh_builder.build != nullptr));
        CHECK((info.destroy == nullptr));
    }
    CHECK(host.errors().empty());
}

TEST_CASE("recast plugin entry refuses host ABI version 0") {
    FakeHost host;
    const nl_plugin_host table = host.table();
    nl_plugin_info info{};
    info.size = sizeof info;
    CHECK(nl::recast::plugin_entry(0, &table, &info) == (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH));
    CHECK((info.name == nullptr));
    CHECK((info.navmesh_builder.build == nullptr));
    CHECK(host.last_error().find("version") != std::string::npos);
    // A short info struct is refused too, never written past its size.
    nl_plugin_info short_info{};
    short_info.size = offsetof(nl_plugin_info, navmesh_builder);
    CHECK(nl::recast::plugin_entry(1, &table, &short_info) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(nl::recast::plugin_entry(1, &table, nullptr) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
}

TEST_CASE("recast default settings are RecastDemo's solo mesh") {
    const nl_recast_settings s = nl::recast::default_settings();
    CHECK(s.size == sizeof(nl_recast_settings));
    CHECK(s.cell_size == doctest::Approx(0.3f));
    CHECK(s.cell_height == doctest::Approx(0.2f));
    CHECK(s.region_min_size == 8.0f);
    CHECK(s.region_merge_size == 20.0f);
    CHECK(s.edge_max_length == 12.0f);
    CHECK(s.edge_max_error == doctest::Approx(1.3f));
    CHECK(s.vertices_per_polygon == 6);
    CHECK(s.detail_sample_distance == 6.0f);
    CHECK(s.detail_sample_max_error == 1.0f);
    CHECK(s.partition == NL_RECAST_PARTITION_WATERSHED);
    CHECK(s.filter_low_hanging_obstacles == 1);
    CHECK(s.filter_ledge_spans == 1);
    CHECK(s.filter_walkable_low_height_spans == 1);
    CHECK(s.reserved == 0);
}
