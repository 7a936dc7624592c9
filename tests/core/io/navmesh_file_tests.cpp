// The baked navmesh file (io/navmesh_file.h): a navmesh and its links saved and loaded are the same,
// bit for bit (navmeshes keep their coordinates on the grid the file stores exactly), answer the same
// queries, say what they were made for, and any damaged, foreign or future file is refused with the
// reason, leaving the world as it was.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core_errors.h"
#include "core_world.h"
#include "io/link_json.h"
#include "io/navmesh_file.h"
#include "level/level_hash.h"
#include "path/path_planner.h"

namespace {

using nl::Handle;
using nl::Vec3;

// The default level with its Recast navmesh, generated links and one manual link of the host's.
struct Baked {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    Handle navmesh;
    std::vector<uint8_t> file;

    Baked() {
        nl::test::add_level(*world, nl::levelgen::generate_default_level(7));
        navmesh = nl::test::build_recast_navmesh(*world);
        world->generate_links(navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
        const auto held = world->navmeshes().navmesh(navmesh);
        const nl::NavMesh& mesh = *held;
        nl::Link manual;
        manual.start = mesh.centre(0);
        manual.end = mesh.centre(mesh.polygon_count() - 1);
        manual.cost_modifier = 2.5f;
        manual.user_data = 0x123456789abcull;
        manual.bidirectional = true;
        nl::set_requirements_from_ends(manual);
        manual.requirements.abilities = 5;
        world->add_link(navmesh, manual);
        file = save();
    }
    std::vector<uint8_t> save() const {
        std::vector<nl::Link> links;
        for (const nl::StoredLink& l : nl::test::links_of(*world, navmesh)) links.push_back(l.link);
        const auto mesh = world->navmeshes().navmesh(navmesh);
        return nl::write_navmesh_file(*mesh, links, world->navmeshes().made_for(navmesh), false);
    }
};

// Rewrites the checksum after an edit, so a test reaches the check after it.
void fix_checksum(std::vector<uint8_t>& file) {
    const uint32_t crc = nl::navmesh_file_checksum(file.data(), file.size());
    std::memcpy(file.data() + 24, &crc, 4);
}

}  // namespace

TEST_CASE("a baked navmesh loads as the same polygons and links, bit for bit, and answers the same paths") {
    Baked b;
    const nl::NavMeshFile read = nl::read_navmesh_file(b.file.data(), b.file.size());
    CHECK(read.version == nl::kNavMeshFileVersion);
    CHECK(read.quantum == doctest::Approx(1.0 / 1024));
    auto other = nl::test::make_world(2);
    nl::test::add_level(*other, nl::levelgen::generate_default_level(7));
    const Handle loaded = other->load_navmesh(read);

    const auto held_a = b.world->navmeshes().navmesh(b.navmesh), held_c = other->navmeshes().navmesh(loaded);
    const nl::NavMesh& a = *held_a;
    const nl::NavMesh& c = *held_c;
    REQUIRE(c.polygon_count() == a.polygon_count());
    REQUIRE(c.vertex_count() == a.vertex_count());
    CHECK(c.portal_count() == a.portal_count());
    CHECK(c.boundary_edge_count() == a.boundary_edge_count());
    float worst = 0.0f;
    for (uint32_t v = 0; v < a.vertex_count(); ++v)
        worst = std::max(worst, (a.vertex(v) - c.vertex(v)).cwiseAbs().maxCoeff());
    MESSAGE(a.polygon_count() << " polygons, " << a.vertex_count() << " vertices: " << b.file.size()
                              << " bytes; worst coordinate error " << worst * 1000.0f << " mm");
    CHECK(worst == 0.0f);
    for (uint32_t p = 0; p < a.polygon_count(); ++p) {
        REQUIRE(c.corner_count(p) == a.corner_count(p));
        for (uint32_t k = 0; k < a.corner_count(p); ++k) {
            CHECK(c.corner(p, k) == a.corner(p, k));
            CHECK(c.neighbour(p, k) == a.neighbour(p, k));
        }
        CHECK(c.area(p) == a.area(p));
    }

    const std::vector<nl::StoredLink> before = nl::test::links_of(*b.world, b.navmesh),
                                      after = nl::test::links_of(*other, loaded);
    REQUIRE(after.size() == before.size());
    for (size_t i = 0; i < before.size(); ++i) {
        const nl::Link &x = before[i].link, &y = after[i].link;
        CHECK(y.kind == x.kind);
        CHECK(y.start == x.start);
        CHECK(y.end == x.end);
        CHECK(y.apex == x.apex);
        CHECK(y.start_polygon == x.start_polygon);
        CHECK(y.end_polygon == x.end_polygon);
        CHECK(y.bidirectional == x.bidirectional);
        CHECK(y.generated == x.generated);
        CHECK(y.cost_modifier == x.cost_modifier);
        CHECK(y.arc_height == x.arc_height);
        CHECK(y.user_data == x.user_data);
        CHECK(y.requirements.gap == x.requirements.gap);
        CHECK(y.requirements.clearance_width == x.requirements.clearance_width);
        CHECK(y.requirements.abilities == x.requirements.abilities);
    }

    // Paths between 300 random pairs of polygon centres, for a jumper that may take every link.
    std::mt19937 random(11);
    std::uniform_int_distribution<uint32_t> pick(0, a.polygon_count() - 1);
    const auto graph_a = b.world->navmeshes().path_graph(b.navmesh), graph_c = other->navmeshes().path_graph(loaded);
    int same = 0;
    float longest_difference = 0.0f;
    for (int i = 0; i < 300; ++i) {
        nl::PathQuery q;
        q.start = a.centre(pick(random));
        q.goal = a.centre(pick(random));
        q.capabilities.radius = a.agent().radius;
        q.capabilities.max_jump_distance = 10.0f;
        q.capabilities.max_jump_height = 5.0f;
        q.capabilities.max_drop_height = 10.0f;
        nl::PathResult ra, rc;
        nl::plan_path(*graph_a, q, nullptr, ra);
        nl::plan_path(*graph_c, q, nullptr, rc);
        CHECK(rc.outcome == ra.outcome);
        longest_difference = std::max(longest_difference, std::fabs(rc.length - ra.length));
        same += rc.outcome == ra.outcome && rc.length == ra.length && rc.points.size() == ra.points.size();
    }
    MESSAGE(same << " of 300 paths the same; largest length difference " << longest_difference * 1000.0f << " mm");
    CHECK(same == 300);
}

TEST_CASE("a baked file says what it was made for: the body, the builder, the level's hash and the link settings") {
    Baked b;
    const nl::NavMeshFile read = nl::read_navmesh_file(b.file.data(), b.file.size());
    CHECK(read.navmesh.agent_type.radius == nl::AgentType{}.radius);
    CHECK(read.navmesh.agent_type.height == nl::AgentType{}.height);
    CHECK(read.made_for.builder == "recast");
    // Built with no settings given, it records every setting it used.
    const nlohmann::json used = nlohmann::json::parse(read.made_for.builder_settings);
    CHECK(used.size() == 15);
    CHECK(used["tile_size"] == 0);
    CHECK(used["cell_size"] == 0.3);
    CHECK(used["partition"] == "watershed");
    CHECK(used["filter_ledge_spans"] == true);
    CHECK(read.made_for.level_hash == nl::level_hash(b.world->level().triangles_to_build(Handle{})));
    CHECK(read.made_for.level_hash != 0);
    nl::LinkSettings settings;
    settings.max_jump_gap = 1.0f;  // not the default: the record must be read back, not assumed
    nl::apply_settings_json(read.made_for.links.settings, settings);
    CHECK(settings.max_jump_gap == nl::LinkSettings{}.max_jump_gap);
    CHECK(settings.drop_angles == nl::LinkSettings{}.drop_angles);
    CHECK_FALSE(read.writer.empty());
    CHECK_FALSE(read.rides_carrier);
    // The record travels with the navmesh: a loaded one saves it again.
    auto other = nl::test::make_world(1);
    const Handle loaded = other->load_navmesh(read);
    CHECK(other->navmeshes().made_for(loaded).level_hash == read.made_for.level_hash);
    CHECK(other->navmeshes().made_for(loaded).links.settings == read.made_for.links.settings);
    CHECK(other->navmeshes().made_for(loaded).builder_settings == read.made_for.builder_settings);
    // The link-kind plugins that ran are kept as recorded; a record that is not an object is refused.
    nl::NavMeshProvenance with_plugins = read.made_for;
    with_plugins.links.plugins = R"({"rope":{"plugin":"ropes","settings":{"length":3},"version":"1"}})";
    const auto held = b.world->navmeshes().navmesh(b.navmesh);
    const nl::NavMesh& mesh = *held;
    const std::vector<uint8_t> plugged = nl::write_navmesh_file(mesh, {}, with_plugins, false);
    CHECK(nl::read_navmesh_file(plugged.data(), plugged.size()).made_for.links.plugins == with_plugins.links.plugins);
    CHECK(nl::made_for_json(nl::read_navmesh_file(plugged.data(), plugged.size())).find(R"("link_plugins":{"rope")") !=
          std::string::npos);
    with_plugins.links.plugins = "[]";
    const std::vector<uint8_t> listed = nl::write_navmesh_file(mesh, {}, with_plugins, false);
    std::string message;
    CHECK(nl::test::code_of([&] { nl::read_navmesh_file(listed.data(), listed.size()); }, &message) ==
          nl::ErrorCode::Parse);
    CHECK_MESSAGE(message.find("the link-kind plugins are not a JSON object") != std::string::npos, message);
    // Whatever bytes a file names its builder with, describing it says so in valid JSON (the fuzzer
    // found a name that is not UTF-8 made the description fail).
    nl::NavMeshProvenance odd = b.world->navmeshes().made_for(b.navmesh);
    odd.builder =
        "r\xb3"
        "cast";
    const std::vector<uint8_t> file = nl::write_navmesh_file(mesh, {}, odd, false);
    const std::string json = nl::made_for_json(nl::read_navmesh_file(file.data(), file.size()));
    CHECK_MESSAGE(json.find("r\xef\xbf\xbd"
                            "cast") != std::string::npos,
                  json);
}

TEST_CASE("a truncated, corrupted, foreign or future navmesh file is refused with the reason") {
    Baked b;
    const std::vector<uint8_t>& good = b.file;
    std::string message;
    // Every length short of the whole file.
    int tries = 0, refused = 0;
    for (size_t n = 0; n < good.size(); n += (n < 256 ? 1 : 97), ++tries) {
        const nl::ErrorCode code = nl::test::code_of([&] { nl::read_navmesh_file(good.data(), n); }, &message);
        refused += code == nl::ErrorCode::Parse || code == nl::ErrorCode::VersionMismatch;
        if (n > 8) CHECK_MESSAGE(message.find("truncated") != std::string::npos, message);
    }
    CHECK(refused == tries);
    // A flipped bit anywhere after the header.
    for (size_t at = nl::kNavMeshFileHeaderBytes; at < good.size(); at += 131) {
        std::vector<uint8_t> bad = good;
        bad[at] ^= 0x10;
        CHECK(nl::test::code_of([&] { nl::read_navmesh_file(bad.data(), bad.size()); }, &message) ==
              nl::ErrorCode::Parse);
        CHECK_MESSAGE(message.find("corrupted") != std::string::npos, message);
    }
    // Not a navmesh file at all; a links JSON file.
    const std::string json = nl::test::save_links_json(*b.world, b.navmesh);
    CHECK(nl::test::code_of([&] { nl::read_navmesh_file(reinterpret_cast<const uint8_t*>(json.data()), json.size()); },
                            &message) == nl::ErrorCode::VersionMismatch);
    CHECK_MESSAGE(message.find("not a NavLink navmesh file") != std::string::npos, message);
    // A future version.
    std::vector<uint8_t> future = good;
    future[8] = 2;
    CHECK(nl::test::code_of([&] { nl::read_navmesh_file(future.data(), future.size()); }, &message) ==
          nl::ErrorCode::VersionMismatch);
    CHECK_MESSAGE(message.find("newer") != std::string::npos, message);
    // Sizes that claim more than the file holds, the checksum made right: refused before allocating.
    // (What reads well but is wrong, the build and the links' placement refuse: the fuzz target.)
    int damaged = 0;
    for (size_t at = nl::kNavMeshFileHeaderBytes; at + 8 < good.size(); at += 7) {
        std::vector<uint8_t> bad = good;
        for (int k = 0; k < 5; ++k) bad[at + k] = 0xff;  // a varint that reads as billions, or bytes beyond
        fix_checksum(bad);
        try {
            nl::read_navmesh_file(bad.data(), bad.size());
        } catch (const nl::Error& e) {
            CHECK_MESSAGE(e.code() == nl::ErrorCode::Parse, e.what());
            ++damaged;
        }
    }
    CHECK(damaged > 0);
}

TEST_CASE("a file whose link no longer fits is refused with the link named, and the world keeps what it had") {
    Baked b;
    nl::NavMeshFile read = nl::read_navmesh_file(b.file.data(), b.file.size());
    read.links[3].start = Vec3(900, 0, 900);
    auto other = nl::test::make_world(1);
    std::string message;
    CHECK(nl::test::code_of([&] { other->load_navmesh(read); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK_MESSAGE(message.find("links[3].start") != std::string::npos, message);
    CHECK(other->navmeshes().handles().empty());
    // A navmesh that rode a moving mesh needs the mesh; one that did not refuses one.
    read = nl::read_navmesh_file(b.file.data(), b.file.size());
    read.rides_carrier = true;
    CHECK(nl::test::code_of([&] { other->load_navmesh(read); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK_MESSAGE(message.find("give the mesh it rides") != std::string::npos, message);
    CHECK(other->navmeshes().handles().empty());
}

TEST_CASE("navmesh coordinates are kept on the 1/1024 m grid, and a file holds them exactly at any size") {
    for (const float size : {3.0f, 500.0f, 2.0e4f, 9.0e6f}) {
        nl::NavMeshInput in;
        in.vertices = {
            {-size, 1, -size}, {-size, 1, size}, {size, 2, size}, {size, 2, -size}, {0.3337f * size, 1.5f, 0.1f}};
        in.indices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
        in.polygon_sizes = {3, 3, 3, 3};
        const auto mesh = nl::build_navmesh(in);
        float snapped = 0.0f;  // how far the builder moved a vertex onto the grid
        for (uint32_t v = 0; v < mesh->vertex_count(); ++v) {
            snapped = std::max(snapped, (mesh->vertex(v) - in.vertices[v]).cwiseAbs().maxCoeff());
            CHECK(mesh->vertex(v) == nl::on_navmesh_grid(mesh->vertex(v)));
        }
        const std::vector<uint8_t> file = nl::write_navmesh_file(*mesh, {}, {}, false);
        const nl::NavMeshFile read = nl::read_navmesh_file(file.data(), file.size());
        const float across = 2.0f * size;
        MESSAGE(across << " m across: " << file.size() << " bytes, vertices moved onto the grid by at most "
                       << snapped * 1000.0f << " mm");
        CHECK(snapped <= std::ldexp(1.0f, -11));
        for (size_t v = 0; v < read.navmesh.vertices.size(); ++v)
            CHECK(read.navmesh.vertices[v] == mesh->vertex(uint32_t(v)));
        CHECK(read.quantum == std::ldexp(1.0f, -10));
    }
}

TEST_CASE(
    "a links file says the body its links were made for: another body's navmesh refuses it, or takes it when asked") {
    Baked b;
    nl::AgentType narrow;
    narrow.radius = 0.3f;
    const Handle other = nl::test::build_recast_navmesh(*b.world, narrow);
    const auto mesh = b.world->navmeshes().navmesh(b.navmesh);
    const nl::LinksFileProvenance made_for{mesh->agent(), b.world->navmeshes().made_for(b.navmesh).links};
    std::vector<nl::Link> links;
    for (const nl::StoredLink& l : nl::test::links_of(*b.world, b.navmesh)) links.push_back(l.link);
    const std::string json = nl::links_to_json(links, &made_for);
    const nl::LinksFile file = nl::read_links_json(json);
    REQUIRE(file.made_for);
    CHECK(file.made_for->agent_type.radius == nl::AgentType{}.radius);
    CHECK(file.made_for->made_with.settings == made_for.made_with.settings);
    nl::LinksFileProvenance plugged = made_for;
    plugged.made_with.plugins = R"({"rope":{"plugin":"ropes","settings":{},"version":"1"}})";
    CHECK(nl::read_links_json(nl::links_to_json(links, &plugged)).made_for->made_with.plugins ==
          plugged.made_with.plugins);

    std::string message;
    CHECK(nl::test::code_of([&] { b.world->load_links_file(other, file, false); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK_MESSAGE(message.find("radius 0.6 m") != std::string::npos, message);
    CHECK_MESSAGE(message.find("radius 0.3 m") != std::string::npos, message);
    CHECK(nl::test::links_of(*b.world, other).empty());  // nothing loaded
    // Asked to, it loads them (with a warning to the log).
    b.world->load_links_file(other, file, true);
    CHECK(nl::test::links_of(*b.world, other).size() == links.size());
    // The navmesh of the same body takes them as they are; a file that says no body too.
    b.world->load_links_file(b.navmesh, file, false);
    CHECK(nl::test::links_of(*b.world, b.navmesh).size() == links.size());
    b.world->load_links_file(other, nl::read_links_json(nl::links_to_json(links)), false);
}
