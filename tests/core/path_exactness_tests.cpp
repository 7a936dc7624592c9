// The exact shortest walk (tests/support/shortest_path_reference.h) on cell maps whose answers are
// known, and the path search against it on random maps: never shorter than the shortest walk (a
// search that is would cut through a wall), and how often it is within 0.1% of it (issue 20's measure;
// reported, not yet required).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core_world.h"
#include "path/path_planner.h"
#include "shortest_path_reference.h"

using nl::Vec3;

namespace {

struct Map {
    std::unique_ptr<nl::World> world;
    nl::Handle navmesh;

    explicit Map(const std::vector<std::string>& rows)
        : world(nl::test::make_world(1)), navmesh(world->add_navmesh(nl::test::cell_navmesh(rows, 0.0f))) {}

    std::shared_ptr<const nl::PathGraph> graph() const { return world->navmeshes().path_graph(navmesh); }
};

}  // namespace

TEST_CASE("the shortest walk reference: straight, round one corner, round a pillar, none") {
    Map corner({"...", "##.", "##."});
    const nl::test::ShortestPathReference around_corner(corner.graph()->navmesh());
    CHECK(*around_corner.length(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 0.5f)) == doctest::Approx(2.0).epsilon(1e-9));
    // Round the reflex corner (2, 1): twice sqrt(1.5^2 + 0.5^2).
    CHECK(*around_corner.length(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 2.5f)) == doctest::Approx(2 * std::sqrt(2.5)).epsilon(1e-9));
    CHECK_FALSE(around_corner.walkable(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 2.5f)));
    CHECK(around_corner.walkable(Vec3(0.0f, 0, 0.0f), Vec3(3.0f, 0, 0.0f)));  // along the outline

    Map pillar({".....", ".....", "..#..", ".....", "....."});
    const nl::test::ShortestPathReference around_pillar(pillar.graph()->navmesh());
    // Past the pillar's corners (2, 2) and (3, 2): 2 sqrt(1.5^2 + 0.5^2) + 1.
    CHECK(*around_pillar.length(Vec3(0.5f, 0, 2.5f), Vec3(4.5f, 0, 2.5f)) ==
          doctest::Approx(2 * std::sqrt(2.5) + 1).epsilon(1e-9));

    Map apart({"..#.."});
    CHECK_FALSE(nl::test::ShortestPathReference(apart.graph()->navmesh()).length(Vec3(0.5f, 0, 0.5f), Vec3(4.5f, 0, 0.5f)));
}

TEST_CASE("on random maps the search is never shorter than the shortest walk") {
    std::mt19937 random(2026);
    int pairs = 0, within = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 8; ++trial) {
        std::vector<std::string> rows(10, std::string(12, '.'));
        for (std::string& r : rows) {
            for (char& c : r) c = random() % 100 < 22 ? '#' : '.';
        }
        Map m(rows);
        const auto graph = m.graph();
        const nl::test::ShortestPathReference reference(graph->navmesh());
        std::vector<Vec3> cells;
        for (uint32_t r = 0; r < rows.size(); ++r) {
            for (uint32_t c = 0; c < rows[r].size(); ++c) {
                if (rows[r][c] == '.') cells.emplace_back(c + 0.25f + 0.5f * float(random() % 100) / 100.0f, 0.0f,
                                                          r + 0.25f + 0.5f * float(random() % 100) / 100.0f);
            }
        }
        for (int k = 0; k < 60; ++k) {
            const Vec3 start = cells[random() % cells.size()], goal = cells[random() % cells.size()];
            nl::PathQuery query;
            query.start = start;
            query.goal = goal;
            query.agent.radius = 0.0f;
            query.search_half_extents = Vec3(0.1f, 1.0f, 0.1f);
            nl::PathResult result;
            nl::plan_path(*graph, query, nullptr, result);
            const std::optional<double> shortest = reference.length(start, goal);
            INFO("trial ", trial, " from (", start.x(), ", ", start.z(), ") to (", goal.x(), ", ", goal.z(), ")");
            REQUIRE((result.outcome == nl::PathOutcome::Complete) == shortest.has_value());
            if (!shortest) continue;
            ++pairs;
            CHECK(result.length >= *shortest - 1e-4);
            const double excess = result.length / std::max(*shortest, 1e-6) - 1.0;
            worst = std::max(worst, excess);
            if (excess <= 1e-3) ++within;
        }
    }
    MESSAGE("search within 0.1% of the shortest walk on ", within, " of ", pairs, " pairs; worst +", 100.0 * worst, "%");
    CHECK(pairs > 200);
}
