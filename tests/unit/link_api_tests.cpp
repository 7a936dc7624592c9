// Links through the C ABI: generation replaces generated links only, manual links live beside them,
// edits, stale ids, JSON round trips, settings from JSON, cancelling, the generation report.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <cmath>
#include <string>
#include <vector>

#include "generated_level_c.h"

namespace {

struct Fixture {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};

    Fixture() {
        REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
        REQUIRE(nl::test::add_generated_level(world, nl::levelgen::generate_default_level(2)) == NL_STATUS_SUCCESS);
        const nl_navmesh_build_def build = nl_default_navmesh_build_def();
        REQUIRE_MESSAGE(nl_navmesh_build(world, &build, &navmesh) == NL_STATUS_SUCCESS, nl_get_last_error_message());
    }
    ~Fixture() { nl_world_destroy(world); }

    std::vector<nl_link> links() const {
        uint32_t count = 0;
        REQUIRE(nl_navmesh_get_links(world, navmesh, nullptr, 0, &count) == NL_STATUS_SUCCESS);
        std::vector<nl_link> out(count, nl_link_init());
        REQUIRE(nl_navmesh_get_links(world, navmesh, out.data(), count, &count) == NL_STATUS_SUCCESS);
        return out;
    }
    nl_link_generation_report generate(const nl_link_settings* settings = nullptr) {
        nl_link_generation_report report{};
        report.size = sizeof report;
        REQUIRE_MESSAGE(nl_navmesh_generate_links(world, navmesh, settings, nullptr, nullptr, &report) == NL_STATUS_SUCCESS,
                        nl_get_last_error_message());
        return report;
    }
    // A point on the navmesh: the centre of polygon 0.
    nl_nav_polygon polygon(uint32_t p) const {
        nl_nav_polygon out = nl_nav_polygon_init();
        REQUIRE(nl_navmesh_get_polygon(world, navmesh, p, &out) == NL_STATUS_SUCCESS);
        return out;
    }
};

size_t count_generated(const std::vector<nl_link>& links, bool generated) {
    size_t n = 0;
    for (const nl_link& l : links) n += (l.generated != 0) == generated;
    return n;
}

std::string last_error() { return nl_get_last_error_message(); }

}  // namespace

TEST_CASE("generation fills the report; regeneration replaces generated links and keeps manual ones") {
    Fixture f;
    const nl_link_generation_report report = f.generate();
    const auto links = f.links();
    CHECK(links.size() == report.jump_links + report.drop_links);
    CHECK(report.jump_links > 0);
    CHECK(report.drop_links > 0);
    CHECK(report.samples >= report.takeoff_points);
    CHECK(report.rays_cast > report.samples);
    CHECK(report.milliseconds_total >= report.milliseconds_jumps);
    for (const nl_link& l : links) {
        CHECK(l.generated == 1);
        CHECK(l.enabled == 1);
        CHECK((l.kind == NL_LINK_JUMP || l.kind == NL_LINK_DROP));
        CHECK(l.start_polygon != NL_NO_POLYGON);
        CHECK(l.end_polygon != NL_NO_POLYGON);
        CHECK(l.requirements.clearance_width > 0.0f);
        CHECK(nl_link_is_valid(f.world, l.id) == 1);
    }

    // A manual link between the centres of two polygons.
    const nl_nav_polygon a = f.polygon(0), b = f.polygon(1);
    nl_link_def def = nl_default_link_def();
    std::copy(a.centre, a.centre + 3, def.start);
    std::copy(b.centre, b.centre + 3, def.end);
    def.bidirectional = 1;
    def.cost_modifier = 2.5f;
    def.user_data = 77;
    nl_link_id manual{};
    REQUIRE(nl_link_add(f.world, f.navmesh, &def, &manual) == NL_STATUS_SUCCESS);
    nl_link got = nl_link_init();
    REQUIRE(nl_link_get(f.world, manual, &got) == NL_STATUS_SUCCESS);
    CHECK(got.kind == NL_LINK_MANUAL);
    CHECK(got.generated == 0);
    CHECK(got.user_data == 77);
    CHECK(got.cost_modifier == 2.5f);
    CHECK(got.requirements.gap > 0.0f);  // computed from the ends

    // Regenerating: the same generated links again (deterministic), the manual link untouched.
    const nl_link old_first = links.front();
    f.generate();
    const auto again = f.links();
    CHECK(count_generated(again, true) == links.size());
    CHECK(count_generated(again, false) == 1);
    CHECK(nl_link_is_valid(f.world, manual) == 1);
    CHECK(nl_link_is_valid(f.world, old_first.id) == 0);  // generated links got new ids
    CHECK(nl_link_get(f.world, old_first.id, &got) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE));

    uint32_t removed = 0;
    REQUIRE(nl_navmesh_remove_generated_links(f.world, f.navmesh, &removed) == NL_STATUS_SUCCESS);
    CHECK(removed == links.size());
    CHECK(f.links().size() == 1);
}

TEST_CASE("manual links: refused off the navmesh or with bad values; updated; removed") {
    Fixture f;
    nl_link_def def = nl_default_link_def();
    const nl_nav_polygon a = f.polygon(0);
    std::copy(a.centre, a.centre + 3, def.start);
    std::copy(a.centre, a.centre + 3, def.end);
    def.end[1] += 50.0f;  // far above the navmesh
    nl_link_id id{};
    CHECK(nl_link_add(f.world, f.navmesh, &def, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("def->end is not within") != std::string::npos);
    def.end[1] -= 50.0f;
    def.start[0] = NAN;
    CHECK(nl_link_add(f.world, f.navmesh, &def, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("def->start") != std::string::npos);
    def.start[0] = a.centre[0];
    def.cost_modifier = -1.0f;
    CHECK(nl_link_add(f.world, f.navmesh, &def, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    def.cost_modifier = 1.0f;
    def.kind = 7;
    CHECK(nl_link_add(f.world, f.navmesh, &def, &id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    def.kind = NL_LINK_FIRST_PLUGIN_KIND + 3;
    def.requirements.abilities = 0x4;
    REQUIRE(nl_link_add(f.world, f.navmesh, &def, &id) == NL_STATUS_SUCCESS);
    CHECK(f.links().size() == 1);

    def.enabled = 0;
    REQUIRE(nl_link_update(f.world, id, &def) == NL_STATUS_SUCCESS);
    nl_link got = nl_link_init();
    REQUIRE(nl_link_get(f.world, id, &got) == NL_STATUS_SUCCESS);
    CHECK(got.enabled == 0);
    CHECK(got.requirements.abilities == 0x4);
    CHECK(got.kind == NL_LINK_FIRST_PLUGIN_KIND + 3);

    REQUIRE(nl_link_remove(f.world, id) == NL_STATUS_SUCCESS);
    CHECK(nl_link_remove(f.world, id) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE));
    CHECK(nl_link_update(f.world, id, &def) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE));
    CHECK(f.links().empty());

    // A removed navmesh takes its links with it.
    REQUIRE(nl_link_add(f.world, f.navmesh, &def, &id) == NL_STATUS_SUCCESS);
    REQUIRE(nl_navmesh_remove(f.world, f.navmesh) == NL_STATUS_SUCCESS);
    CHECK(nl_link_is_valid(f.world, id) == 0);
    uint32_t count = 0;
    CHECK(nl_navmesh_get_links(f.world, f.navmesh, nullptr, 0, &count) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE));
}

TEST_CASE("links round-trip through JSON; bad files are refused and change nothing") {
    Fixture f;
    f.generate();
    nl_link_def def = nl_default_link_def();
    const nl_nav_polygon a = f.polygon(0);
    std::copy(a.centre, a.centre + 3, def.start);
    std::copy(a.centre, a.centre + 3, def.end);
    def.user_data = 5;
    nl_link_id manual{};
    REQUIRE(nl_link_add(f.world, f.navmesh, &def, &manual) == NL_STATUS_SUCCESS);
    const auto before = f.links();

    size_t length = 0;
    REQUIRE(nl_navmesh_save_links_json(f.world, f.navmesh, nullptr, 0, &length) == NL_STATUS_SUCCESS);
    std::string json(length, '\0');
    char small[8];
    CHECK(nl_navmesh_save_links_json(f.world, f.navmesh, small, sizeof small, &length) ==
          (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL));
    std::vector<char> buffer(length + 1);
    REQUIRE(nl_navmesh_save_links_json(f.world, f.navmesh, buffer.data(), buffer.size(), &length) == NL_STATUS_SUCCESS);
    json.assign(buffer.data(), length);
    CHECK(json.find("\"format\": \"navlink-links\"") != std::string::npos);
    CHECK(json.find("\"requires\"") != std::string::npos);

    uint32_t loaded = 0;
    REQUIRE(nl_navmesh_load_links_json(f.world, f.navmesh, json.data(), json.size(), &loaded) == NL_STATUS_SUCCESS);
    CHECK(loaded == before.size());
    const auto after = f.links();
    REQUIRE(after.size() == before.size());
    for (size_t i = 0; i < after.size(); ++i) {
        CHECK(after[i].kind == before[i].kind);
        CHECK(after[i].generated == before[i].generated);
        CHECK(after[i].bidirectional == before[i].bidirectional);
        CHECK(after[i].user_data == before[i].user_data);
        for (int k = 0; k < 3; ++k) {
            CHECK(after[i].start[k] == doctest::Approx(before[i].start[k]));
            CHECK(after[i].end[k] == doctest::Approx(before[i].end[k]));
        }
        CHECK(after[i].requirements.gap == doctest::Approx(before[i].requirements.gap));
        CHECK(after[i].start_polygon == before[i].start_polygon);
    }

    const std::string broken = json.substr(0, json.size() / 2);
    CHECK(nl_navmesh_load_links_json(f.world, f.navmesh, broken.data(), broken.size(), &loaded) ==
          (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR));
    const std::string future = "{\"format\": \"navlink-links\", \"version\": 9, \"links\": []}";
    CHECK(nl_navmesh_load_links_json(f.world, f.navmesh, future.data(), future.size(), &loaded) ==
          (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH));
    const std::string bad_point =
        "{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"jump\", \"start\": [0, 0], \"end\": [1, 0, 1]}]}";
    CHECK(nl_navmesh_load_links_json(f.world, f.navmesh, bad_point.data(), bad_point.size(), &loaded) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("links[0].start") != std::string::npos);
    const std::string huge_cost =
        "{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"manual\", \"start\": [0, 0, 0], "
        "\"end\": [1, 0, 1], \"cost_modifier\": 1e39}]}";
    CHECK(nl_navmesh_load_links_json(f.world, f.navmesh, huge_cost.data(), huge_cost.size(), &loaded) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));  // beyond float: would become infinite
    CHECK(last_error().find("links[0].cost_modifier") != std::string::npos);
    CHECK(f.links().size() == before.size());  // nothing changed by the failures
}

TEST_CASE("settings from JSON: applied over the struct, unknown keys and bad values named") {
    nl_link_settings s = nl_default_link_settings();
    CHECK(s.size == sizeof s);
    CHECK(s.drop_angle_count == 3);
    const std::string good = "{\"max_jump_gap\": 6, \"drop_angles\": [0, 45], \"arc_segments\": 16}";
    REQUIRE(nl_link_settings_from_json(good.data(), good.size(), &s) == NL_STATUS_SUCCESS);
    CHECK(s.max_jump_gap == 6.0f);
    CHECK(s.drop_angle_count == 2);
    CHECK(s.drop_angles[1] == 45.0f);
    CHECK(s.arc_segments == 16);
    CHECK(s.max_jump_up == nl_default_link_settings().max_jump_up);

    const nl_link_settings kept = s;
    const std::string typo = "{\"max_link_distanse\": 6}";
    CHECK(nl_link_settings_from_json(typo.data(), typo.size(), &s) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("max_link_distanse") != std::string::npos);
    const std::string negative = "{\"max_jump_gap\": -1}";
    CHECK(nl_link_settings_from_json(negative.data(), negative.size(), &s) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("max_jump_gap") != std::string::npos);
    const std::string wrong_type = "{\"arc_segments\": \"many\"}";
    CHECK(nl_link_settings_from_json(wrong_type.data(), wrong_type.size(), &s) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    const std::string malformed = "{\"arc_segments\": ";
    CHECK(nl_link_settings_from_json(malformed.data(), malformed.size(), &s) == (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR));
    CHECK(s.max_jump_gap == kept.max_jump_gap);  // unchanged by failures
}

TEST_CASE("a cancelled generation changes nothing; progress runs from 0 to 1") {
    Fixture f;
    f.generate();
    const size_t before = f.links().size();
    struct Seen {
        float last = -1.0f;
        int calls = 0;
        bool monotonic = true;
        int cancel_after = -1;
    };
    auto progress = [](void* user, float fraction, const char*) -> int32_t {
        auto* seen = static_cast<Seen*>(user);
        seen->monotonic = seen->monotonic && fraction >= seen->last;
        seen->last = fraction;
        return seen->cancel_after < 0 || ++seen->calls <= seen->cancel_after;
    };
    Seen full;
    REQUIRE(nl_navmesh_generate_links(f.world, f.navmesh, nullptr, progress, &full, nullptr) == NL_STATUS_SUCCESS);
    CHECK(full.monotonic);
    CHECK(full.last == 1.0f);

    nl_link_settings settings = nl_default_link_settings();
    settings.max_jump_gap = 8.0f;  // would change the links
    Seen cancelled;
    cancelled.cancel_after = 3;
    CHECK(nl_navmesh_generate_links(f.world, f.navmesh, &settings, progress, &cancelled, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_CANCELLED));
    CHECK(f.links().size() == before);

    settings.max_jump_gap = -2.0f;
    CHECK(nl_navmesh_generate_links(f.world, f.navmesh, &settings, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("max_jump_gap") != std::string::npos);
}

TEST_CASE("a boundary that would need millions of take-off samples is refused before any work") {
    nl_world* world = nullptr;
    REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
    // One square polygon 200 km across: 800 km of boundary.
    const float vertices[] = {0, 0, 0, 0, 0, 200000, 200000, 0, 200000, 200000, 0, 0};
    const uint32_t indices[] = {0, 1, 2, 3};
    const uint8_t corners[] = {4};
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = vertices;
    def.vertex_count = 4;
    def.indices = indices;
    def.polygon_vertex_counts = corners;
    def.polygon_count = 1;
    nl_navmesh_id navmesh{};
    REQUIRE_MESSAGE(nl_navmesh_add(world, &def, &navmesh) == NL_STATUS_SUCCESS, nl_get_last_error_message());

    nl_link_settings settings = nl_default_link_settings();
    settings.sample_spacing = 0.05f;  // 16 million samples
    CHECK(nl_navmesh_generate_links(world, navmesh, &settings, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(std::string(nl_get_last_error_message()).find("sample_spacing") != std::string::npos);
    uint32_t count = 1;
    CHECK(nl_navmesh_get_links(world, navmesh, nullptr, 0, &count) == NL_STATUS_SUCCESS);
    CHECK(count == 0);
    nl_world_destroy(world);
}

TEST_CASE("loading JSON holds links to nl_link_add's rules: ends near the navmesh, requirements from the ends") {
    Fixture f;
    f.generate();
    const auto before = f.links();
    REQUIRE(!before.empty());
    const nl_nav_polygon a = f.polygon(0), b = f.polygon(1);
    auto point = [](const float* p, float lift) {
        return "[" + std::to_string(p[0]) + "," + std::to_string(p[1] + lift) + "," + std::to_string(p[2]) + "]";
    };
    auto file = [&](float lift) {
        return std::string(R"({"format": "navlink-links", "version": 1, "links": [)") +
               R"({"kind": "manual", "start": )" + point(a.centre, 0) + R"(, "end": )" + point(b.centre, 0) + "}," +
               R"({"kind": "manual", "start": )" + point(a.centre, lift) + R"(, "end": )" + point(b.centre, 0) + "}]}";
    };

    // The second link's start 10 m above the navmesh: refused, named, nothing changes.
    const std::string far = file(10.0f);
    CHECK(nl_navmesh_load_links_json(f.world, f.navmesh, far.data(), far.size(), nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(last_error().find("links[1].start") != std::string::npos);
    CHECK(f.links().size() == before.size());

    // On the navmesh, without "requires": gap, rise and drop come from the ends.
    const std::string near = file(0.0f);
    uint32_t count = 0;
    REQUIRE_MESSAGE(nl_navmesh_load_links_json(f.world, f.navmesh, near.data(), near.size(), &count) == NL_STATUS_SUCCESS,
                    last_error());
    CHECK(count == 2);
    const auto loaded = f.links();
    REQUIRE(loaded.size() == 2);
    const float dx = b.centre[0] - a.centre[0], dy = b.centre[1] - a.centre[1], dz = b.centre[2] - a.centre[2];
    CHECK(loaded[0].requirements.gap == doctest::Approx(std::sqrt(dx * dx + dz * dz)).epsilon(1e-4));
    CHECK(loaded[0].requirements.rise == doctest::Approx(std::max(0.0f, dy)).epsilon(1e-4));
    CHECK(loaded[0].requirements.drop == doctest::Approx(std::max(0.0f, -dy)).epsilon(1e-4));
    CHECK(loaded[0].start_polygon != NL_NO_POLYGON);
    CHECK(loaded[0].end_polygon != NL_NO_POLYGON);
}
