// Reachability maps on cell-map navmeshes whose islands are known exactly: walls, excluded areas,
// narrow passages, one-way and two-way links, long chains; and on random maps, where the map must
// agree with the search on every pair.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "core_world.h"
#include "path/polygon_astar.h"
#include "path/path_planner.h"
#include "path/reachability.h"

using nl::Vec3;

namespace {

struct Map {
    std::unique_ptr<nl::World> world;
    nl::Handle navmesh;

    explicit Map(const std::vector<std::string>& rows, float agent_radius = 0.0f)
        : world(nl::test::make_world(1)), navmesh(world->add_navmesh(nl::test::cell_navmesh(rows, agent_radius))) {}

    std::shared_ptr<const nl::PathGraph> graph() const { return world->navmeshes().path_graph(navmesh); }

    // A one-way link between the centres of cells from_x and to_x (columns) of row `row`, needing a
    // drop of `drop` metres.
    nl::Handle link(uint32_t from_x, uint32_t to_x, float drop = 1.0f, bool both_ways = false, uint32_t row = 0) {
        nl::Link l;
        l.kind = nl::LinkKind::Drop;
        l.start = Vec3(from_x + 0.5f, 0.0f, row + 0.5f);
        l.end = Vec3(to_x + 0.5f, 0.0f, row + 0.5f);
        l.apex = l.start;
        l.bidirectional = both_ways;
        l.requirements.drop = drop;
        l.requirements.gap = 0.1f;
        nl::settle_host_requirements(l, true);
        return world->add_link(navmesh, l);
    }
};

nl::AgentCapabilities body(float max_drop = 0.0f, float radius = 0.0f) {
    nl::AgentCapabilities a;
    a.radius = radius;
    a.max_drop_height = max_drop;
    a.max_jump_height = max_drop;                         // two-way drops climbed back are jumps of the same height
    a.max_jump_distance = max_drop > 0.0f ? 1.0f : 0.0f;  // over their gap
    return a;
}

std::vector<uint32_t> reachable(const nl::ReachabilityMap& map, uint32_t from) {
    std::vector<uint32_t> out;
    map.reachable_polygons(from, out);
    return out;
}

}  // namespace

TEST_CASE("walls split a navmesh into islands; each reaches only itself") {
    // Polygons: 0 1 | 2 3 4 | 5 (cells of one row, '#' no navmesh).
    Map m({"..#...#."});
    const auto map = m.graph()->reachability(body(), {});
    CHECK(map->island_count() == 3);
    CHECK(map->island(0) == 0);
    CHECK(map->island(1) == 0);
    CHECK(map->island(2) == 1);
    CHECK(map->island(4) == 1);
    CHECK(map->island(5) == 2);
    CHECK(map->reaches(0, 1));
    CHECK(map->reaches(1, 0));
    CHECK(map->reaches(2, 4));
    CHECK_FALSE(map->reaches(1, 2));
    CHECK_FALSE(map->reaches(4, 5));
    CHECK(map->reaches(5, 5));
    CHECK(reachable(*map, 3) == std::vector<uint32_t>{2, 3, 4});
    CHECK(reachable(*map, 5) == std::vector<uint32_t>{5});
    CHECK(map->has_closure());
}

TEST_CASE("one-way links order the islands; the closure follows chains; a cycle of links is one island") {
    // Islands A (polygons 0-1, columns 0-1), B (2-3, columns 3-4), C (4-5, columns 6-7), D (6-7).
    Map m({"..#..#..#.."});
    m.link(1, 3);  // A -> B, one way
    m.link(4, 6);  // B -> C
    const auto walker = m.graph()->reachability(body(), {});
    CHECK(walker->island_count() == 4);
    CHECK_FALSE(walker->reaches(0, 2));

    const auto dropper = m.graph()->reachability(body(1.0f), {});
    CHECK(dropper->island_count() == 4);
    CHECK(dropper->reaches(0, 2));
    CHECK(dropper->reaches(0, 5));  // A -> B -> C
    CHECK_FALSE(dropper->reaches(2, 0));
    CHECK_FALSE(dropper->reaches(5, 2));
    CHECK_FALSE(dropper->reaches(0, 7));  // D: no link leads there
    CHECK(reachable(*dropper, 1) == std::vector<uint32_t>{0, 1, 2, 3, 4, 5});
    CHECK(reachable(*dropper, 3) == std::vector<uint32_t>{2, 3, 4, 5});

    // C -> A closes a cycle: A, B and C become one island.
    m.link(7, 0);
    const auto cycled = m.graph()->reachability(body(1.0f), {});
    CHECK(cycled->island_count() == 2);
    CHECK(cycled->reaches(5, 1));
    CHECK(cycled->reaches(2, 0));
    CHECK(cycled->island(0) == cycled->island(5));
    CHECK_FALSE(cycled->reaches(0, 6));

    // A link deeper than the body's drop is not taken; a two-way one needs the climb back too.
    Map two({"..#.."});
    two.link(1, 3, 2.0f, true);
    CHECK_FALSE(two.graph()->reachability(body(1.0f), {})->reaches(0, 2));
    nl::AgentCapabilities down_only = body(2.0f);
    down_only.max_jump_height = 0.0f;
    const auto down = two.graph()->reachability(down_only, {});
    CHECK(down->reaches(0, 3));
    CHECK_FALSE(down->reaches(3, 0));
    CHECK(two.graph()->reachability(body(2.0f), {})->reaches(3, 0));
}

TEST_CASE("an excluded area is a wall to walk into but a body standing in it walks out") {
    // Polygons 0 1 2(area 2) 3 4.
    Map m({"..2.."});
    const std::vector<float> keep_out{1.0f, 1.0f, 0.0f};
    const auto map = m.graph()->reachability(body(), keep_out);
    CHECK(map->island_count() == 2);
    CHECK(map->island(2) == nl::ReachabilityMap::kNoIsland);
    CHECK_FALSE(map->reaches(0, 3));
    CHECK_FALSE(map->reaches(0, 2));
    CHECK(map->reaches(2, 0));
    CHECK(map->reaches(2, 4));
    CHECK(map->reaches(2, 2));
    CHECK(reachable(*map, 2) == std::vector<uint32_t>{0, 1, 2, 3, 4});
    CHECK(reachable(*map, 4) == std::vector<uint32_t>{3, 4});
    // Costly but not excluded: one island.
    CHECK(m.graph()->reachability(body(), {1.0f, 1.0f, 50.0f})->island_count() == 1);
}

TEST_CASE("a passage narrower than a wider body is closed to it") {
    // A 1 m passage between two rooms; the navmesh was built for a radius of 0.
    Map m({"...", "...", "#.#", "...", "..."});
    // Polygons 0-5 the first room, 6 the passage, 7-12 the second room.
    CHECK(m.graph()->reachability(body(0.0f, 0.4f), {})->reaches(0, 12));  // needs 0.8 m
    const auto wide = m.graph()->reachability(body(0.0f, 0.6f), {});       // needs 1.2 m
    CHECK_FALSE(wide->reaches(0, 12));
    CHECK_FALSE(wide->reaches(0, 6));

    // The exact fit: a body needing the passage's whole metre is kept out (a millimetre to spare is
    // the rule: kPortalSlack), one needing 2 mm less goes through; the search agrees with the map.
    for (const std::pair<float, bool>& fit : {std::pair{0.5f, false}, std::pair{0.499f, true}}) {
        const float radius = fit.first;  // (clang: a structured binding cannot be captured by INFO)
        const bool open = fit.second;
        INFO("radius ", radius);
        CHECK(m.graph()->reachability(body(0.0f, radius), {})->reaches(0, 12) == open);
        nl::PathQuery q;
        q.start = Vec3(1.5f, 0.0f, 0.5f);
        q.goal = Vec3(1.5f, 0.0f, 4.5f);
        q.capabilities = body(0.0f, radius);
        q.accept_partial = true;
        nl::PathResult result;
        nl::plan_path(*m.graph(), q, nullptr, result);
        CHECK((result.outcome == nl::PathOutcome::Complete) == open);
    }
    CHECK(wide->reaches(0, 5));
}

TEST_CASE("bodies of one class share a map; an edit makes a new graph with new maps") {
    Map m({"..#.."});
    m.link(1, 3);
    const auto graph = m.graph();
    const auto a = graph->reachability(body(1.0f), {});
    const auto b = graph->reachability(body(1.5f), {});  // takes the same links
    CHECK(a == b);
    CHECK(graph->reachability_map_count() == 1);
    const auto walker = graph->reachability(body(), {});
    CHECK(walker != a);
    CHECK(graph->reachability_map_count() == 2);
    CHECK(graph->reachability(body(), {1.0f}) == walker);  // area 0 at cost 1: nothing excluded
    // Widths that close the same portals share a map: every 1 m portal of the row is closed to a
    // body 0.55 m or 0.6 m wider than the navmesh's; none to one 0.1 m wider.
    const auto wide = graph->reachability(body(1.0f, 0.55f), {});
    CHECK(graph->reachability(body(1.0f, 0.6f), {}) == wide);
    CHECK(wide != a);
    CHECK(graph->reachability(body(1.0f, 0.1f), {}) == a);
    CHECK_FALSE(wide->reaches(0, 1));

    m.link(3, 1);
    const auto edited = m.graph();
    CHECK(edited != graph);
    CHECK(edited->reachability_map_count() == 0);
    CHECK(edited->reachability(body(1.0f), {})->reaches(3, 0));
    CHECK_FALSE(a->reaches(3, 0));  // the old map still describes the old links
}

TEST_CASE("a path request that does not accept partial paths fails at once for a goal out of reach") {
    // The first request searches (it never builds a map first) and leaves the map built; the next
    // ones are answered without a search.
    Map m({"...#..."});
    nl::PathQuery q;
    q.start = Vec3(0.5f, 0.0f, 0.5f);
    q.goal = Vec3(6.5f, 0.0f, 0.5f);
    q.capabilities = body();
    q.accept_partial = false;
    nl::PathResult result;
    CHECK(m.graph()->reachability_map_count() == 0);
    nl::plan_path(*m.graph(), q, nullptr, result);
    CHECK(result.outcome == nl::PathOutcome::NoPath);
    CHECK(result.nodes_visited == 2);  // the search never enters the dead end at the wall: no way on from it
    CHECK(m.graph()->reachability_map_count() == 1);
    q.goal = Vec3(5.5f, 0.0f, 0.5f);
    nl::plan_path(*m.graph(), q, nullptr, result);
    CHECK(result.outcome == nl::PathOutcome::NoPath);
    CHECK(result.nodes_visited == 0);
    // A search cut short by max_nodes builds nothing: it did not see everything.
    Map capped({"...#..."});
    q.max_nodes = 1;
    nl::plan_path(*capped.graph(), q, nullptr, result);
    CHECK(result.outcome == nl::PathOutcome::NoPath);
    CHECK(capped.graph()->reachability_map_count() == 0);
    q.max_nodes = 0;
    q.accept_partial = true;
    nl::plan_path(*m.graph(), q, nullptr, result);
    CHECK(result.outcome == nl::PathOutcome::Partial);
    CHECK(result.nodes_visited == 3);
}

TEST_CASE("beyond kMaxClosureIslands linked islands the map walks the island graph, with the same answers") {
    // A chain of islands, each joined to the next by a one-way link: cells 0, 2, 4, ... of one row.
    const uint32_t islands = nl::ReachabilityMap::kMaxClosureIslands + 10;
    std::string row;
    for (uint32_t i = 0; i < islands; ++i) row += i + 1 < islands ? ".#" : ".";
    Map m({row});
    for (uint32_t i = 0; i + 1 < islands; ++i) m.link(2 * i, 2 * i + 2);
    const auto map = m.graph()->reachability(body(1.0f), {});
    CHECK(map->island_count() == islands);
    CHECK_FALSE(map->has_closure());
    CHECK(map->reaches(0, islands - 1));
    CHECK(map->reaches(islands / 2, islands - 1));
    CHECK_FALSE(map->reaches(islands - 1, 0));
    CHECK_FALSE(map->reaches(islands / 2, islands / 2 - 1));
    CHECK(reachable(*map, islands - 3) == std::vector<uint32_t>{islands - 3, islands - 2, islands - 1});
}

TEST_CASE("on random maps with random links and areas the map agrees with the search on every pair") {
    std::mt19937 random(20261203);
    for (int trial = 0; trial < 6; ++trial) {
        std::vector<std::string> rows(10, std::string(12, '.'));
        for (std::string& r : rows) {
            for (char& c : r) {
                const uint32_t roll = random() % 100;
                c = roll < 28 ? '#' : roll < 36 ? '2' : roll < 40 ? '3' : '.';
            }
        }
        Map m(rows);
        const uint32_t polygons = m.graph()->navmesh().polygon_count();
        if (polygons < 2) continue;
        std::vector<std::pair<uint32_t, uint32_t>> cells;
        for (uint32_t r = 0; r < rows.size(); ++r) {
            for (uint32_t c = 0; c < rows[r].size(); ++c) {
                if (rows[r][c] != '#') cells.emplace_back(c, r);
            }
        }
        for (int l = 0; l < 10; ++l) {
            const auto& [x0, z0] = cells[random() % cells.size()];
            const auto& [x1, z1] = cells[random() % cells.size()];
            nl::Link link;
            link.kind = nl::LinkKind::Drop;
            link.start = Vec3(x0 + 0.5f, 0.0f, z0 + 0.5f);
            link.end = Vec3(x1 + 0.5f, 0.0f, z1 + 0.5f);
            link.apex = link.start;
            link.bidirectional = random() % 3 == 0;
            link.requirements.drop = float(random() % 3);  // 0, 1 or 2 m
            link.requirements.gap = 0.1f;
            nl::settle_host_requirements(link, true);
            m.world->add_link(m.navmesh, link);
        }
        const auto graph = m.graph();
        const std::vector<std::vector<float>> costs{{}, {1.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 3.0f, 0.0f}};
        for (const float drop : {0.0f, 1.0f, 2.0f}) {
            for (const std::vector<float>& area_costs : costs) {
                nl::PathQuery q;
                q.capabilities = body(drop);
                q.area_costs = area_costs;
                const auto map = graph->reachability(q.capabilities, q.area_costs);
                for (uint32_t from = 0; from < polygons; ++from) {
                    std::vector<uint32_t> listed;
                    map->reachable_polygons(from, listed);
                    std::vector<uint32_t> searched;
                    for (uint32_t to = 0; to < polygons; ++to) {
                        const nl::NavPoint start{true, graph->navmesh().centre(from), 0.0f, from};
                        const nl::NavPoint goal{true, graph->navmesh().centre(to), 0.0f, to};
                        nl::CorridorSearch corridor;
                        nl::find_corridor(*graph, q, start, goal, nullptr, corridor);
                        INFO("trial ", trial, " drop ", drop, " costs ", area_costs.size(), " from ", from, " to ", to);
                        REQUIRE(map->reaches(from, to) == corridor.reached_goal);
                        if (corridor.reached_goal) searched.push_back(to);
                    }
                    REQUIRE(listed == searched);
                }
            }
        }
    }
}
