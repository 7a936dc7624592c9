// Link generation on procedural levels with known answers: the level is built from boxes, the
// navmesh by the Recast builder, the links by the generator.
#include <doctest/doctest.h>

#include <sstream>

#include "core_world.h"
#include "link_test_helpers.h"
#include "links/generate_links.h"

using nl::Link;
using nl::LinkKind;
using nl::levelgen::Box;

namespace {

struct Generated {
    std::vector<Link> links;
    nl::LinkGenerationReport report;

    std::vector<Link> of(LinkKind kind) const { return nl::test::links_of_kind(links, kind); }
    std::string describe() const {
        std::ostringstream s;
        s << links.size() << " links; samples " << report.samples << ", take-offs " << report.takeoff_points
          << ", jump candidates " << report.jump_candidates << ", drop candidates " << report.drop_candidates
          << "; rejected: wall " << report.rejected_wall << ", not ledge " << report.rejected_not_ledge << ", distance "
          << report.rejected_distance << ", rise " << report.rejected_rise << ", angle " << report.rejected_angle
          << ", no landing " << report.rejected_no_landing << ", clearance " << report.rejected_clearance
          << ", duplicate " << report.rejected_duplicate;
        for (const Link& l : links)
            s << "\n  " << (l.kind == LinkKind::Jump ? "jump" : "drop") << " (" << l.start.transpose() << ") -> ("
              << l.end.transpose() << ")" << (l.bidirectional ? " both ways" : "");
        return s.str();
    }
};

Generated generate(const std::vector<Box>& boxes, const nl::LinkSettings& settings = {},
                   nl::GenerationMethod method = nl::GenerationMethod::Indexed, int threads = 2) {
    nl::levelgen::GeneratedLevel level;
    for (const Box& b : boxes) level.add_box(b);
    const nl::test::RecastWorld w = nl::test::recast_world(level, threads);
    Generated out;
    out.links = nl::generate_links(*w.mesh, w.world->level(), w.world->tasks(), settings, method, out.report,
                                   [](float, const char*) { return true; });
    return out;
}

// Two 10 x 10 m platforms with tops at y = 0 and y = `rise`, `gap` apart along x, over a floor too
// deep to drop to (so only jumps can connect them).
std::vector<Box> two_platforms(float gap, float rise = 0.0f) {
    return {Box{{0, -1, 0}, {10, 0, 10}}, Box{{10 + gap, rise - 1, 0}, {20 + gap, rise, 10}},
            Box{{-5, -31, -5}, {25 + gap, -30, 15}}};
}

bool crosses_gap(const Link& l, float gap) {
    const float lo = std::min(l.start.x(), l.end.x()), hi = std::max(l.start.x(), l.end.x());
    return lo < 10.0f && hi > 10.0f + gap;
}

}  // namespace

TEST_CASE("a 2 m gap gets a bidirectional jump; nothing else is generated") {
    const Generated b = generate(two_platforms(2.0f));
    INFO(b.describe());
    const auto jumps = b.of(LinkKind::Jump);
    REQUIRE(!jumps.empty());
    CHECK(b.of(LinkKind::Drop).empty());
    for (const Link& l : jumps) {
        CHECK(l.bidirectional);
        CHECK(crosses_gap(l, 2.0f));
        // The gap is the rims' distance; the ends (the navmesh edges) sit an agent radius or more
        // back from the rims, on the floor.
        CHECK(l.requirements.gap == doctest::Approx(2.0f).epsilon(0.025));
        CHECK(l.requirements.length > 2.0f + 2 * 0.6f - 0.01f);
        CHECK(l.start.y() == doctest::Approx(0.0f).epsilon(1e-3));
        CHECK(l.end.y() == doctest::Approx(0.0f).epsilon(1e-3));
        CHECK(l.requirements.rise < 0.3f);
        CHECK(l.apex.y() > std::max(l.start.y(), l.end.y()) + 0.9f);
        CHECK(l.requirements.clearance_width >= 1.2f - 1e-4f);
    }
    // A 10 m edge sampled every metre, merged within 0.6 m: several jumps, not one per sample pair.
    CHECK(jumps.size() >= 3);
    CHECK(jumps.size() <= 12);
}

TEST_CASE("a 4.2 m gap is beyond max_jump_gap (4 m rim to rim): no link") {
    const Generated b = generate(two_platforms(4.2f));
    INFO(b.describe());
    CHECK(b.links.empty());
    CHECK(b.report.takeoff_points > 0);
}

TEST_CASE("a wall between the platforms, or a low ceiling over the gap, stops the jump") {
    auto walled = two_platforms(2.0f);
    walled.push_back(Box{{10.8f, -30, -1}, {11.2f, 4, 11}});
    const Generated w = generate(walled);
    INFO(w.describe());
    CHECK(w.of(LinkKind::Jump).empty());
    CHECK(w.report.rejected_clearance > 0);

    auto ceiling = two_platforms(2.0f);
    ceiling.push_back(Box{{8.5f, 1.6f, -1}, {13.5f, 2.0f, 11}});  // 1.6 m over the gap: a 2 m agent hits it
    const Generated c = generate(ceiling);
    INFO(c.describe());
    CHECK(c.of(LinkKind::Jump).empty());
}

TEST_CASE("a 3 m ledge gets a one-way drop; a ledge deeper than max_drop_distance gets none") {
    // An upper deck (top y = 3) standing on a wide floor (top y = 0).
    const std::vector<Box> ledge = {Box{{-10, -1, -10}, {20, 0, 20}}, Box{{0, 0, 0}, {6, 3, 10}}};
    const Generated b = generate(ledge);
    INFO(b.describe());
    const auto drops = b.of(LinkKind::Drop);
    REQUIRE(!drops.empty());
    for (const Link& l : drops) {
        CHECK_FALSE(l.bidirectional);
        CHECK(l.start.y() > l.end.y() + 2.5f);
        CHECK(l.requirements.drop == doctest::Approx(l.start.y() - l.end.y()));
        CHECK(l.requirements.rise == 0.0f);
    }
    CHECK(b.of(LinkKind::Jump).empty());

    const std::vector<Box> cliff = {Box{{-10, -1, -10}, {20, 0, 20}}, Box{{0, 0, 0}, {6, 7, 10}}};
    const Generated d = generate(cliff);
    INFO(d.describe());
    CHECK(d.of(LinkKind::Drop).empty());
}

TEST_CASE("a rise beyond max_jump_up: no jump, a drop one way only (down)") {
    // The right platform is 3 m higher, 1.5 m away; a floor under both at y = -1 lets nothing else
    // connect them... but too far down to matter: its top is far below.
    const Generated b = generate(two_platforms(1.5f, 3.0f));
    INFO(b.describe());
    CHECK(b.of(LinkKind::Jump).empty());
    const auto drops = b.of(LinkKind::Drop);
    REQUIRE(!drops.empty());
    for (const Link& l : drops) {
        CHECK_FALSE(l.bidirectional);
        CHECK(l.start.x() > 11.5f);  // from the high platform
        CHECK(l.end.x() < 10.0f);    // to the low one
    }
}

TEST_CASE("a drop within max_jump_up works both ways") {
    const Generated b = generate(two_platforms(1.0f, 1.2f));
    INFO(b.describe());
    // 1.2 m apart in height: an edge-to-edge jump, valid both ways.
    const auto jumps = b.of(LinkKind::Jump);
    REQUIRE(!jumps.empty());
    for (const Link& l : jumps) CHECK(l.bidirectional);
}

TEST_CASE("the spatial grid finds exactly what all pairs find, with 1 and 2 threads") {
    const auto level = nl::levelgen::generate_default_level(5);
    const Generated grid = generate(level.boxes, {}, nl::GenerationMethod::Indexed, 2);
    const Generated all = generate(level.boxes, {}, nl::GenerationMethod::BruteForce, 1);
    INFO(grid.describe());
    REQUIRE(grid.links.size() == all.links.size());
    CHECK(!grid.links.empty());
    for (size_t i = 0; i < grid.links.size(); ++i) {
        CHECK(grid.links[i].start == all.links[i].start);
        CHECK(grid.links[i].end == all.links[i].end);
        CHECK(grid.links[i].kind == all.links[i].kind);
    }
}
