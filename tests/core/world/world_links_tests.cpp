// A navmesh's links in the world: generation replaces generated links only, manual links live beside
// them, edits, stale ids, JSON round trips, settings from JSON, cancelling, the generation report.
// What the C layer adds on top (statuses, "def->" in messages, reading and checking nl_link_def and
// nl_link_settings, buffers too small, outputs untouched on failure) is tested from C in
// tests/abi/links_tests.c; each case below says where.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core_world.h"
#include "io/link_json.h"
#include "core_errors.h"

using nl::Handle;
using nl::Link;
using nl::Vec3;

namespace {

struct Fixture {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    Handle navmesh;

    Fixture() {
        nl::test::add_level(*world, nl::levelgen::generate_default_level(2));
        navmesh = nl::test::build_recast_navmesh(*world);
    }

    std::vector<nl::StoredLink> links() const { return nl::test::links_of(*world, navmesh); }
    nl::LinkGenerationReport generate(const nl::LinkSettings& settings = {}) {
        return world->generate_links(navmesh, settings, {}, nl::test::keep_going);
    }
    // The centre of polygon p: a point on the navmesh.
    Vec3 centre(uint32_t p) const {
        const auto mesh = world->navmeshes().navmesh(navmesh);
        return mesh->centre(p);
    }
};

// A manual link as nl_link_add makes it of nl_default_link_def() with these ends: requirements
// measured from the ends, the higher end as its apex.
Link manual_link(const Vec3& start, const Vec3& end) {
    Link l;
    l.start = start;
    l.end = end;
    l.apex = start.y() > end.y() ? start : end;
    nl::set_requirements_from_ends(l);
    return l;
}

size_t count_generated(const std::vector<nl::StoredLink>& links, bool generated) {
    size_t n = 0;
    for (const nl::StoredLink& l : links) n += l.link.generated == generated;
    return n;
}

// The code of the nl::Error `fn` throws; its message into `message`.

}  // namespace

TEST_CASE("generation fills the report; regeneration replaces generated links and keeps manual ones") {
    // From C (nl_link_is_valid, nl_link_get's INVALID_HANDLE for a replaced id): abi.links.generation_gap.
    Fixture f;
    const nl::LinkGenerationReport report = f.generate();
    const auto links = f.links();
    CHECK(links.size() == report.jump_links + report.drop_links);
    CHECK(report.jump_links > 0);
    CHECK(report.drop_links > 0);
    CHECK(report.samples >= report.takeoff_points);
    CHECK(report.rays_cast > report.samples);
    CHECK(report.milliseconds_total >= report.milliseconds_jumps);
    for (const nl::StoredLink& s : links) {
        const Link& l = s.link;
        CHECK(l.generated);
        CHECK(l.enabled);
        CHECK((l.kind == nl::LinkKind::Jump || l.kind == nl::LinkKind::Drop));
        CHECK(l.start_polygon != nl::kNoPolygon);
        CHECK(l.end_polygon != nl::kNoPolygon);
        CHECK(l.requirements.clearance_width > 0.0f);
        CHECK(f.world->navmeshes().contains_link(s.id));
    }

    // A manual link between the centres of two polygons.
    Link def = manual_link(f.centre(0), f.centre(1));
    def.bidirectional = true;
    def.cost_modifier = 2.5f;
    def.user_data = 77;
    const Handle manual = f.world->add_link(f.navmesh, def);
    const Link got = f.links().back().link;
    CHECK(f.links().back().id == manual);
    CHECK(got.kind == nl::LinkKind::Manual);
    CHECK_FALSE(got.generated);
    CHECK(got.user_data == 77);
    CHECK(got.cost_modifier == 2.5f);
    CHECK(got.requirements.gap > 0.0f);  // computed from the ends

    // Regenerating: the same generated links again (deterministic), the manual link untouched.
    const nl::StoredLink old_first = links.front();
    f.generate();
    const auto again = f.links();
    CHECK(count_generated(again, true) == links.size());
    CHECK(count_generated(again, false) == 1);
    CHECK(f.world->navmeshes().contains_link(manual));
    CHECK_FALSE(f.world->navmeshes().contains_link(old_first.id));  // generated links got new ids
    CHECK(nl::test::code_of([&] { f.world->navmeshes().remove_link(old_first.id); }) == nl::ErrorCode::InvalidHandle);

    CHECK(f.world->navmeshes().remove_generated_links(f.navmesh) == links.size());
    CHECK(f.links().size() == 1);
}

TEST_CASE("manual links: refused off the navmesh or with bad values; updated; removed") {
    // The def's values the C layer reads and refuses (a NaN start, a negative cost modifier, kind 7),
    // each named after "def->": abi.links.refusals; a removed link's id refused by nl_link_update and
    // nl_link_get: abi.links.manual.
    Fixture f;
    const Vec3 a = f.centre(0);
    Link def = manual_link(a, a + Vec3(0.0f, 50.0f, 0.0f));  // the end far above the navmesh
    std::string message;
    CHECK(nl::test::code_of([&] { f.world->add_link(f.navmesh, def); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("end is not within") != std::string::npos);
    def = manual_link(a, a);
    def.kind = static_cast<nl::LinkKind>(uint32_t(nl::LinkKind::FirstPluginKind) + 3);
    def.requirements.abilities = 0x4;
    const Handle id = f.world->add_link(f.navmesh, def);
    CHECK(f.links().size() == 1);

    def.enabled = false;
    f.world->update_link(id, def);
    const Link got = f.links().front().link;
    CHECK_FALSE(got.enabled);
    CHECK(got.requirements.abilities == 0x4);
    CHECK(uint32_t(got.kind) == uint32_t(nl::LinkKind::FirstPluginKind) + 3);

    f.world->navmeshes().remove_link(id);
    CHECK(nl::test::code_of([&] { f.world->navmeshes().remove_link(id); }) == nl::ErrorCode::InvalidHandle);
    CHECK(nl::test::code_of([&] { f.world->update_link(id, def); }) == nl::ErrorCode::InvalidHandle);
    CHECK(f.links().empty());

    // A removed navmesh takes its links with it.
    const Handle again = f.world->add_link(f.navmesh, def);
    f.world->navmeshes().remove(f.navmesh);
    CHECK_FALSE(f.world->navmeshes().contains_link(again));
    CHECK(nl::test::code_of([&] { f.world->navmeshes().links(f.navmesh); }) == nl::ErrorCode::InvalidHandle);
}

TEST_CASE("links round-trip through JSON; bad files are refused and change nothing") {
    // nl_navmesh_save_links_json's two calls and BUFFER_TOO_SMALL: abi.links.json.
    Fixture f;
    f.generate();
    Link def = manual_link(f.centre(0), f.centre(0));
    def.user_data = 5;
    f.world->add_link(f.navmesh, def);
    const auto before = f.links();

    const std::string json = nl::test::save_links_json(*f.world, f.navmesh);
    CHECK(json.find("\"format\": \"navlink-links\"") != std::string::npos);
    CHECK(json.find("\"requires\"") != std::string::npos);

    CHECK(nl::test::load_links_json(*f.world, f.navmesh, json) == before.size());
    const auto after = f.links();
    REQUIRE(after.size() == before.size());
    for (size_t i = 0; i < after.size(); ++i) {
        const Link &x = after[i].link, &y = before[i].link;
        CHECK(x.kind == y.kind);
        CHECK(x.generated == y.generated);
        CHECK(x.bidirectional == y.bidirectional);
        CHECK(x.user_data == y.user_data);
        for (int k = 0; k < 3; ++k) {
            CHECK(x.start[k] == doctest::Approx(y.start[k]));
            CHECK(x.end[k] == doctest::Approx(y.end[k]));
        }
        CHECK(x.requirements.gap == doctest::Approx(y.requirements.gap));
        CHECK(x.start_polygon == y.start_polygon);
    }

    auto load = [&](const std::string& text, std::string* message = nullptr) {
        return nl::test::code_of([&] { nl::test::load_links_json(*f.world, f.navmesh, text); }, message);
    };
    const std::string broken = json.substr(0, json.size() / 2);
    CHECK(load(broken) == nl::ErrorCode::Parse);
    CHECK(load("{\"format\": \"navlink-links\", \"version\": 9, \"links\": []}") == nl::ErrorCode::VersionMismatch);
    std::string message;
    CHECK(load("{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"jump\", \"start\": [0, 0], "
               "\"end\": [1, 0, 1]}]}",
               &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("links[0].start") != std::string::npos);
    CHECK(
        load("{\"format\": \"navlink-links\", \"version\": 1, \"links\": [{\"kind\": \"manual\", \"start\": [0, 0, 0], "
             "\"end\": [1, 0, 1], \"cost_modifier\": 1e39}]}",
             &message) == nl::ErrorCode::InvalidArgument);  // beyond float: would become infinite
    CHECK(message.find("links[0].cost_modifier") != std::string::npos);
    CHECK(f.links().size() == before.size());  // nothing changed by the failures
}

TEST_CASE("settings from JSON: applied over the struct, unknown keys and bad values named") {
    // nl_default_link_settings' size, and nl_link_settings_from_json leaving the struct as it was when
    // it refuses a JSON: abi.links.settings_json (and abi.links.defaults).
    nl::LinkSettings s;
    CHECK(s.drop_angles.size() == 3);
    nl::apply_settings_json("{\"max_jump_gap\": 6, \"drop_angles\": [0, 45], \"arc_segments\": 16}", s);
    CHECK(s.max_jump_gap == 6.0f);
    CHECK(s.drop_angles.size() == 2);
    CHECK(s.drop_angles[1] == 45.0f);
    CHECK(s.arc_segments == 16);
    CHECK(s.max_jump_up == nl::LinkSettings{}.max_jump_up);

    auto refused = [&](const std::string& json, std::string* message = nullptr) {
        nl::LinkSettings copy = s;
        return nl::test::code_of([&] { nl::apply_settings_json(json, copy); }, message);
    };
    std::string message;
    CHECK(refused("{\"max_link_distanse\": 6}", &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("max_link_distanse") != std::string::npos);
    CHECK(refused("{\"max_jump_gap\": -1}", &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("max_jump_gap") != std::string::npos);
    CHECK(refused("{\"arc_segments\": \"many\"}") == nl::ErrorCode::InvalidArgument);
    CHECK(refused("{\"arc_segments\": ") == nl::ErrorCode::Parse);
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
    auto progress_of = [](Seen& seen) {
        return [&seen](float fraction, const char*) {
            seen.monotonic = seen.monotonic && fraction >= seen.last;
            seen.last = fraction;
            return seen.cancel_after < 0 || ++seen.calls <= seen.cancel_after;
        };
    };
    Seen full;
    f.world->generate_links(f.navmesh, {}, {}, progress_of(full));
    CHECK(full.monotonic);
    CHECK(full.last == 1.0f);

    nl::LinkSettings settings;
    settings.max_jump_gap = 8.0f;  // would change the links
    Seen cancelled;
    cancelled.cancel_after = 3;
    CHECK(nl::test::code_of([&] { f.world->generate_links(f.navmesh, settings, {}, progress_of(cancelled)); }) ==
          nl::ErrorCode::Cancelled);
    CHECK(f.links().size() == before);

    settings.max_jump_gap = -2.0f;
    std::string message;
    CHECK(nl::test::code_of([&] { f.generate(settings); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("max_jump_gap") != std::string::npos);
}

TEST_CASE("a boundary that would need millions of take-off samples is refused before any work") {
    const auto world = nl::test::make_world(2);
    // One square polygon 200 km across: 800 km of boundary.
    nl::NavMeshInput square;
    square.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 200000), Vec3(200000, 0, 200000), Vec3(200000, 0, 0)};
    square.indices = {0, 1, 2, 3};
    square.polygon_sizes = {4};
    const Handle navmesh = world->add_navmesh(square);

    nl::LinkSettings settings;
    settings.sample_spacing = 0.05f;  // 16 million samples
    std::string message;
    CHECK(nl::test::code_of([&] { world->generate_links(navmesh, settings, {}, nl::test::keep_going); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("sample_spacing") != std::string::npos);
    const auto links = world->navmeshes().links(navmesh);
    CHECK(links->empty());
}

TEST_CASE("loading JSON holds links to nl_link_add's rules: ends near the navmesh, requirements from the ends") {
    Fixture f;
    f.generate();
    const auto before = f.links();
    REQUIRE(!before.empty());
    const Vec3 a = f.centre(0), b = f.centre(1);
    auto point = [](const Vec3& p, float lift) {
        return "[" + std::to_string(p[0]) + "," + std::to_string(p[1] + lift) + "," + std::to_string(p[2]) + "]";
    };
    auto file = [&](float lift) {
        return std::string(R"({"format": "navlink-links", "version": 1, "links": [)") +
               R"({"kind": "manual", "start": )" + point(a, 0) + R"(, "end": )" + point(b, 0) + "}," +
               R"({"kind": "manual", "start": )" + point(a, lift) + R"(, "end": )" + point(b, 0) + "}]}";
    };

    // The second link's start 10 m above the navmesh: refused, named, nothing changes.
    std::string message;
    CHECK(nl::test::code_of([&] { nl::test::load_links_json(*f.world, f.navmesh, file(10.0f)); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("links[1].start") != std::string::npos);
    CHECK(f.links().size() == before.size());

    // On the navmesh, without "requires": gap, rise and drop come from the ends.
    CHECK(nl::test::load_links_json(*f.world, f.navmesh, file(0.0f)) == 2);
    const auto loaded = f.links();
    REQUIRE(loaded.size() == 2);
    const float dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    const nl::LinkRequirements& r = loaded[0].link.requirements;
    CHECK(r.gap == doctest::Approx(std::sqrt(dx * dx + dz * dz)).epsilon(1e-4));
    CHECK(r.rise == doctest::Approx(std::max(0.0f, dy)).epsilon(1e-4));
    CHECK(r.drop == doctest::Approx(std::max(0.0f, -dy)).epsilon(1e-4));
    CHECK(loaded[0].link.start_polygon != nl::kNoPolygon);
    CHECK(loaded[0].link.end_polygon != nl::kNoPolygon);
}
