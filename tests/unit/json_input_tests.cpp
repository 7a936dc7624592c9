// Hostile JSON at the C ABI: documents nested past the depth limit, numbers no double holds and huge
// values are refused with INVALID_ARGUMENT naming the value, and no message quotes a huge value.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <string>

#include "cell_navmesh.h"

namespace {

constexpr nl_status kInvalid = NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;

std::string last_error() { return nl_get_last_error_message(); }

// `depth` arrays, one inside the other.
std::string nested(size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

nl_status settings_from(const std::string& json) {
    nl_link_settings settings = nl_default_link_settings();
    return nl_link_settings_from_json(json.data(), json.size(), &settings);
}

struct Navmesh {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    Navmesh() {
        REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
        const nl::test::CellNavmesh cells({"....", "...."}, 0.4f);
        REQUIRE(nl_navmesh_add(world, &cells.def, &navmesh) == NL_STATUS_SUCCESS);
    }
    ~Navmesh() { nl_world_destroy(world); }
    nl_status load(const std::string& json) const {
        uint32_t count = 0;
        return nl_navmesh_load_links_json(world, navmesh, json.data(), json.size(), &count);
    }
};

// A links file whose first link's `field` is `value`.
std::string links_with(const std::string& field, const std::string& value) {
    return "{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"manual\", \"start\": [0.5, 0, 0.5], "
           "\"end\": [1.5, 0, 0.5], \"" + field + "\": " + value + "}]}";
}

}  // namespace

TEST_CASE("link settings JSON: too deep, beyond a double, beyond a float or huge is named, never an internal error") {
    // 64 levels are read (and refused as a wrong type); 65 and 100,000 are refused as too deep.
    CHECK(settings_from("{\"drop_angles\": " + nested(63) + "}") == kInvalid);
    CHECK(last_error().find("levels") == std::string::npos);
    for (const size_t depth : {64, 100000}) {
        CAPTURE(depth);
        CHECK(settings_from("{\"drop_angles\": " + nested(depth) + "}") == kInvalid);
        CHECK(last_error().find("settings JSON: drop_angles") != std::string::npos);
        CHECK(last_error().find("64 levels") != std::string::npos);
    }
    CHECK(settings_from("{\"max_jump_gap\": 1e400}") == kInvalid);
    CHECK(last_error().find("max_jump_gap is 1e400") != std::string::npos);
    CHECK(settings_from("{\"drop_angles\": [0, -1e400]}") == kInvalid);
    CHECK(last_error().find("drop_angles[1]") != std::string::npos);
    // A double that no float holds is refused before it is converted (undefined behaviour).
    CHECK(settings_from("{\"drop_angles\": [1e300]}") == kInvalid);
    CHECK(last_error().find("drop_angles[0] must be a number within float range") != std::string::npos);

    const std::string long_key(100000, 'k');
    CHECK(settings_from("{\"" + long_key + "\": 1}") == kInvalid);
    CHECK(last_error().size() < 300);
    CHECK(last_error().find("is not a link generation setting") != std::string::npos);
}

TEST_CASE("links JSON: too deep or beyond a double is named by its path") {
    const Navmesh n;
    CHECK(n.load(links_with("user_data", nested(100000))) == kInvalid);
    CHECK(last_error().find("links JSON: links[0].user_data") != std::string::npos);
    CHECK(last_error().find("64 levels") != std::string::npos);
    CHECK(last_error().size() < 300);
    CHECK(n.load(links_with("cost_modifier", "-2e400")) == kInvalid);
    CHECK(last_error().find("links JSON: links[0].cost_modifier is -2e400") != std::string::npos);
    CHECK(n.load("{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"start\": [0, 1e999, 0]}]}") == kInvalid);
    CHECK(last_error().find("links[0].start[1]") != std::string::npos);
    CHECK(n.load(links_with("cost_modifier", "2")) == NL_STATUS_SUCCESS);  // the same file with a sane value loads
}
