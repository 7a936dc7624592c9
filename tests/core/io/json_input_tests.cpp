// Hostile JSON: documents nested past the depth limit, numbers no double holds and huge values are
// refused as invalid arguments naming the value, and no message quotes a huge value. (The C layer's
// INVALID_ARGUMENT for them is the guard's mapping of ErrorCode::InvalidArgument, tested from C in
// tests/abi; each message reaches a C caller behind the function's name.)
#include <doctest/doctest.h>

#include <string>

#include "core_world.h"
#include "io/link_json.h"
#include "util/error.h"

namespace {

// A message from the core may be this long: with the C layer's function name in front (at most
// "nl_navmesh_load_links_json: ", 28 characters) it stays under the 300 a C caller is promised here.
constexpr size_t kShortMessage = 300 - 28;

// `depth` arrays, one inside the other.
std::string nested(size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// The code of reading the settings JSON over the defaults; its message into `message`.
nl::ErrorCode settings_from(const std::string& json, std::string& message) {
    nl::LinkSettings settings;
    message.clear();
    try {
        nl::apply_settings_json(json, settings);
    } catch (const nl::Error& e) {
        message = e.what();
        return e.code();
    }
    return nl::ErrorCode::Internal;  // not refused: no code of a refusal
}

struct Navmesh {
    std::unique_ptr<nl::World> world = nl::test::make_world();
    nl::Handle navmesh = world->add_navmesh(nl::test::cell_navmesh({"....", "...."}, 0.4f));

    // The code of loading the links file in place of the navmesh's links (Internal: it loaded).
    nl::ErrorCode load(const std::string& json, std::string& message) const {
        message.clear();
        try {
            nl::test::load_links_json(*world, navmesh, json);
        } catch (const nl::Error& e) {
            message = e.what();
            return e.code();
        }
        return nl::ErrorCode::Internal;
    }
};

// A links file whose first link's `field` is `value`.
std::string links_with(const std::string& field, const std::string& value) {
    return "{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"manual\", \"start\": [0.5, 0, "
           "0.5], "
           "\"end\": [1.5, 0, 0.5], \"" +
           field + "\": " + value + "}]}";
}

constexpr nl::ErrorCode kInvalid = nl::ErrorCode::InvalidArgument;

}  // namespace

TEST_CASE("link settings JSON: too deep, beyond a double, beyond a float or huge is named, never an internal error") {
    std::string last_error;
    // 64 levels are read (and refused as a wrong type); 65 and 100,000 are refused as too deep.
    CHECK(settings_from("{\"drop_angles\": " + nested(63) + "}", last_error) == kInvalid);
    CHECK(last_error.find("levels") == std::string::npos);
    for (const size_t depth : {64, 100000}) {
        CAPTURE(depth);
        CHECK(settings_from("{\"drop_angles\": " + nested(depth) + "}", last_error) == kInvalid);
        CHECK(last_error.find("settings JSON: drop_angles") != std::string::npos);
        CHECK(last_error.find("64 levels") != std::string::npos);
    }
    CHECK(settings_from("{\"max_jump_gap\": 1e400}", last_error) == kInvalid);
    CHECK(last_error.find("max_jump_gap is 1e400") != std::string::npos);
    CHECK(settings_from("{\"drop_angles\": [0, -1e400]}", last_error) == kInvalid);
    CHECK(last_error.find("drop_angles[1]") != std::string::npos);
    // A double that no float holds is refused before it is converted (undefined behaviour).
    CHECK(settings_from("{\"drop_angles\": [1e300]}", last_error) == kInvalid);
    CHECK(last_error.find("drop_angles[0] must be a number within float range") != std::string::npos);

    const std::string long_key(100000, 'k');
    CHECK(settings_from("{\"" + long_key + "\": 1}", last_error) == kInvalid);
    CHECK(last_error.size() < kShortMessage);
    CHECK(last_error.find("is not a link generation setting") != std::string::npos);
}

TEST_CASE("links JSON: too deep or beyond a double is named by its path") {
    const Navmesh n;
    std::string last_error;
    CHECK(n.load(links_with("user_data", nested(100000)), last_error) == kInvalid);
    CHECK(last_error.find("links JSON: links[0].user_data") != std::string::npos);
    CHECK(last_error.find("64 levels") != std::string::npos);
    CHECK(last_error.size() < kShortMessage);
    CHECK(n.load(links_with("cost_modifier", "-2e400"), last_error) == kInvalid);
    CHECK(last_error.find("links JSON: links[0].cost_modifier is -2e400") != std::string::npos);
    CHECK(n.load("{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"start\": [0, 1e999, 0]}]}",
                 last_error) == kInvalid);
    CHECK(last_error.find("links[0].start[1]") != std::string::npos);
    // The same file with a sane value loads.
    CHECK(n.load(links_with("cost_modifier", "2"), last_error) == nl::ErrorCode::Internal);
    CHECK(last_error.empty());
}
