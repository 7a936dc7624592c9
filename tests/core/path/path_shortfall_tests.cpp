// Why a path falls short of its goal (path/path_shortfall.h, issue 33): procedural levels with one
// thing in the way each, and the reason with its figures. Known answers: a drop 4.2 m deep for a body
// that drops 4 m, a gap 2.5 m wide for one that jumps 2 m, a corridor too narrow for a wide body, an
// island without links, an island no link reaches, a search cut short by max_nodes; and the same
// levels with the limit lifted reach the goal and say nothing.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core_world.h"
#include "path/path_planner.h"
#include "path/path_shortfall.h"

using nl::levelgen::Box;

namespace {

struct Level {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    nl::Handle navmesh;

    Level(const std::vector<Box>& boxes, bool with_links) {
        nl::levelgen::GeneratedLevel level;
        for (const Box& b : boxes) level.add_box(b);
        nl::test::add_level(*world, level);
        navmesh = nl::test::build_recast_navmesh(*world);
        if (with_links) world->generate_links(navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
    }

    struct Explained {
        nl::PathResult result;
        nl::PathShortfallReport report;
        std::string text;
    };

    Explained explain(nl::Vec3 from, nl::Vec3 to, const nl::AgentCapabilities& agent, uint32_t max_nodes = 0) const {
        nl::PathQuery query;
        query.start = from;
        query.goal = to;
        query.capabilities = agent;
        query.max_nodes = max_nodes;
        Explained out;
        const auto graph = world->navmeshes().path_graph(navmesh);
        nl::plan_path(*graph, query, nullptr, out.result);
        out.report = nl::explain_shortfall(*graph, query, out.result);
        out.text = nl::describe(out.report, query);
        MESSAGE(out.text);
        return out;
    }
};

nl::AgentCapabilities body(float jump_distance, float jump_height, float drop, float radius = 0.6f) {
    nl::AgentCapabilities a;
    a.max_jump_distance = jump_distance;
    a.max_jump_height = jump_height;
    a.max_drop_height = drop;
    a.radius = radius;
    return a;
}

// A platform 4.2 m above a floor, no stairs: down only by a drop.
const std::vector<Box> kTower = {{{-10, -1, -10}, {20, 0, 10}}, {{0, 0, -3}, {6, 4.2f, 3}}};
const nl::Vec3 kOnTower(3, 4.2f, 0), kOnFloor(15, 0, 0);

}  // namespace

TEST_CASE("shortfall: a drop deeper than the body drops is named with its depth") {
    const Level tower(kTower, true);
    const auto short_drop = tower.explain(kOnTower, kOnFloor, body(0, 0, 4.0f));
    CHECK(short_drop.result.outcome == nl::PathOutcome::Partial);
    CHECK(short_drop.report.why == nl::PathShortfall::LinkBeyondBody);
    CHECK(short_drop.report.limit == nl::LinkLimit::DropHeight);
    CHECK(short_drop.report.needed > 4.0f);
    CHECK(short_drop.report.needed < 4.5f);
    CHECK(short_drop.report.has == 4.0f);
    CHECK(short_drop.report.link != nl::Handle{});
    CHECK(short_drop.report.link_start.y() == doctest::Approx(4.2f).epsilon(0.05));
    CHECK(short_drop.text.find("a drop at (") == 0);
    CHECK(short_drop.text.find("and the body drops 4 m (max_drop_height)") != std::string::npos);
    // Dropping 5 m, the body gets there, and there is nothing to say.
    const auto long_drop = tower.explain(kOnTower, kOnFloor, body(0, 0, 5.0f));
    CHECK(long_drop.result.outcome == nl::PathOutcome::Complete);
    CHECK(long_drop.report.why == nl::PathShortfall::None);
    CHECK(long_drop.text.empty());
}

TEST_CASE("shortfall: without links, the goal on another island says so") {
    const Level tower(kTower, false);
    const auto explained = tower.explain(kOnTower, kOnFloor, body(0, 0, 5.0f));
    CHECK(explained.report.why == nl::PathShortfall::NoLinks);
    CHECK(explained.text.find("the navmesh has no links") != std::string::npos);
}

TEST_CASE("shortfall: a gap wider than the body jumps is named with its width") {
    // Two platforms 2.5 m apart over a pit too deep to drop into.
    const Level gap({{{0, -1, 0}, {10, 0, 10}}, {{12.5f, -1, 0}, {22, 0, 10}}, {{-5, -31, -5}, {27, -30, 15}}}, true);
    const nl::Vec3 from(5, 0, 5), to(17, 0, 5);
    const auto short_jump = gap.explain(from, to, body(2.0f, 1.0f, 1.0f));
    CHECK(short_jump.report.why == nl::PathShortfall::LinkBeyondBody);
    CHECK(short_jump.report.limit == nl::LinkLimit::JumpDistance);
    CHECK(short_jump.report.needed > 2.0f);
    CHECK(short_jump.report.needed < 2.6f);
    CHECK(short_jump.report.has == 2.0f);
    CHECK(short_jump.text.find("(max_jump_distance)") != std::string::npos);
    CHECK(gap.explain(from, to, body(3.0f, 1.0f, 1.0f)).report.why == nl::PathShortfall::None);
}

TEST_CASE("shortfall: a body too wide for the corridor on the way says so; one that fits gets there") {
    // Two rooms joined by a corridor 1.6 m wide: the navmesh (radius 0.6) leaves 0.4 m of it.
    const Level rooms({{{-10, -1, -10}, {30, 0, 10}}, {{9, 0, -10}, {11, 3, -0.8f}}, {{9, 0, 0.8f}, {11, 3, 10}}},
                      false);
    const nl::Vec3 from(0, 0, 0), to(20, 0, 0);
    const auto wide = rooms.explain(from, to, body(0, 0, 0, 1.0f));
    CHECK(wide.report.why == nl::PathShortfall::BodyTooWide);
    CHECK(wide.report.needed == 1.0f);
    CHECK(wide.report.has == 0.6f);
    CHECK(wide.text.find("the body (radius 1 m) is too wide for the passages on the way") == 0);
    CHECK(rooms.explain(from, to, body(0, 0, 0, 0.6f)).report.why == nl::PathShortfall::None);
    // Cut short by max_nodes, the search says so before anything else.
    const auto cut = rooms.explain(from, to, body(0, 0, 0, 0.6f), 1);
    if (cut.result.outcome == nl::PathOutcome::Partial) CHECK(cut.report.why == nl::PathShortfall::OutOfNodes);
}

TEST_CASE("shortfall: an island no link reaches is not connected, whatever the body") {
    // The tower with its drops, and a second floor 40 m away that nothing joins.
    std::vector<Box> boxes = kTower;
    boxes.push_back({{60, -1, -10}, {80, 0, 10}});
    const Level level(boxes, true);
    const auto explained = level.explain(kOnTower, nl::Vec3(70, 0, 0), body(10, 10, 10));
    CHECK(explained.report.why == nl::PathShortfall::NotConnected);
    CHECK(explained.text ==
          "no passage or link leads to the goal, whatever the body could do (built for a body of radius 0.6 m, "
          "it leaves out passages narrower than 1.2 m)");
}
