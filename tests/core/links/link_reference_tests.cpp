// The link generator against its brute-force reference: on every shared level and on a procedural
// level of a few thousand triangles, the spatial-grid candidate search (what World::generate_links
// uses) yields exactly the links that all pairs of take-off points yield on one worker, and the
// generator's result is the same, field for field, on one worker and on two.
#include <doctest/doctest.h>

#include <cstring>
#include <memory>
#include <sstream>
#include <string>

#include "core_world.h"
#include "level_generator.h"
#include "links/generate_links.h"
#include "link_test_helpers.h"
#include "shared_levels.h"

namespace {

// A level's geometry: an OBJ file, or generated arrays.
struct LevelSource {
    std::string name;
    std::string obj_path;
    const nl::levelgen::GeneratedLevel* generated = nullptr;
};

// The level in a world of `workers` threads.
std::unique_ptr<nl::World> load(const LevelSource& source, int workers) {
    auto world = nl::test::make_world(workers);
    if (source.generated)
        nl::test::add_level(*world, *source.generated);
    else
        nl::test::add_obj_file(*world, source.obj_path);
    return world;
}

bool bits_equal(const nl::Vec3& a, const nl::Vec3& b) {
    return std::memcmp(a.data(), b.data(), 3 * sizeof(float)) == 0;
}
bool bits_equal(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool identical(const nl::Link& a, const nl::Link& b) {
    const nl::LinkRequirements &x = a.requirements, &y = b.requirements;
    return a.kind == b.kind && bits_equal(a.start, b.start) && bits_equal(a.end, b.end) && bits_equal(a.apex, b.apex) &&
           a.bidirectional == b.bidirectional && a.generated == b.generated && a.enabled == b.enabled &&
           bits_equal(a.cost_modifier, b.cost_modifier) && a.user_data == b.user_data && bits_equal(x.gap, y.gap) &&
           bits_equal(x.rise, y.rise) && bits_equal(x.drop, y.drop) &&
           bits_equal(x.clearance_width, y.clearance_width) && x.abilities == y.abilities &&
           a.start_polygon == b.start_polygon && a.end_polygon == b.end_polygon;
}

std::string describe(const nl::Link& l) {
    std::ostringstream s;
    s.precision(9);
    s << (l.kind == nl::LinkKind::Jump   ? "jump"
          : l.kind == nl::LinkKind::Drop ? "drop"
                                         : "other")
      << " (" << l.start.transpose() << ") -> (" << l.end.transpose() << ")" << (l.bidirectional ? " both ways" : "")
      << " clearance " << l.requirements.clearance_width << " polygons " << l.start_polygon << " -> " << l.end_polygon;
    return s.str();
}

// Empty if equal, else what differs first.
std::string difference(const std::vector<nl::Link>& a, const std::vector<nl::Link>& b) {
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        if (!identical(a[i], b[i]))
            return "link " + std::to_string(i) + ": " + describe(a[i]) + " vs " + describe(b[i]);
    }
    if (a.size() != b.size()) return std::to_string(a.size()) + " links vs " + std::to_string(b.size());
    return {};
}

struct Generation {
    std::vector<nl::Link> links;
    nl::LinkGenerationReport report;
};

Generation generate(const nl::NavMesh& navmesh, nl::World& world, nl::GenerationMethod method) {
    Generation b;
    b.links = nl::generate_links(navmesh, world.level(), world.tasks(), nl::LinkSettings{}, method, b.report,
                                 [](float, const char*) { return true; });
    return b;
}

// Builds the navmesh once (Recast, defaults) and generates its links three ways on the same geometry.
void check_against_reference(const LevelSource& source, uint32_t& jumps, uint32_t& drops) {
    INFO("level ", source.name);
    const auto one = load(source, 1), two = load(source, 2);
    REQUIRE(one->tasks().thread_count() == 1);
    REQUIRE(two->tasks().thread_count() == 2);
    const auto navmesh = two->navmeshes().navmesh(nl::test::build_recast_navmesh(*two));

    const Generation grid_1 = generate(*navmesh, *one, nl::GenerationMethod::Indexed);
    const Generation grid_2 = generate(*navmesh, *two, nl::GenerationMethod::Indexed);
    const Generation all_pairs = generate(*navmesh, *one, nl::GenerationMethod::BruteForce);
    jumps = grid_1.report.jump_links;
    drops = grid_1.report.drop_links;
    MESSAGE(source.name, ": ", grid_1.links.size(), " links (", jumps, " jumps, ", drops, " drops) from ",
            grid_1.report.samples, " samples, ", grid_1.report.takeoff_points, " take-off points, ",
            grid_1.report.jump_candidates, " jump and ", grid_1.report.drop_candidates, " drop candidates");

    CHECK(jumps + drops == grid_1.links.size());
    const std::string reference_difference = difference(all_pairs.links, grid_1.links);
    CHECK_MESSAGE(reference_difference.empty(), "all pairs vs spatial grid: ", reference_difference);
    const std::string thread_difference = difference(grid_1.links, grid_2.links);
    CHECK_MESSAGE(thread_difference.empty(), "1 worker vs 2 workers: ", thread_difference);
    // The searches differ only in how pairs are found: every later stage saw the same work.
    CHECK(all_pairs.report.jump_candidates == grid_1.report.jump_candidates);
    CHECK(all_pairs.report.rejected_distance == grid_1.report.rejected_distance);
    CHECK(grid_2.report.rays_cast == grid_1.report.rays_cast);
}

}  // namespace

TEST_CASE("link generation equals the all-pairs reference and is the same on 1 and 2 workers: shared levels") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty()) {
        if (nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir().string());
        MESSAGE("no shared levels in ", nl::test::levels_dir().string(), ": skipped");
        return;
    }
    uint32_t total = 0;
    for (const auto& path : levels) {
        uint32_t jumps = 0, drops = 0;
        check_against_reference(LevelSource{path.stem().string(), path.string(), nullptr}, jumps, drops);
        total += jumps + drops;
    }
    CHECK(total > 0);  // the comparison compared something
}

TEST_CASE("link generation equals the all-pairs reference and is the same on 1 and 2 workers: procedural level") {
    // 4 x 4 blocks of gaps, terraces, pillars, blocked jumps, pits and towers on a 1 m tessellated
    // ground: about 5,000 triangles.
    const auto level = nl::levelgen::generate_large_level(7, 4, 1.0f);
    REQUIRE(level.triangle_count() > 3000);
    REQUIRE(level.triangle_count() < 10000);
    uint32_t jumps = 0, drops = 0;
    check_against_reference(
        LevelSource{"large-4 (seed 7, " + std::to_string(level.triangle_count()) + " triangles)", "", &level}, jumps,
        drops);
    CHECK(jumps > 0);
    CHECK(drops > 0);
}
