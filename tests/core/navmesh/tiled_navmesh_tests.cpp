// Tiled navmeshes: tiles of one grid joined into one navmesh (tile_join.h), and the Recast builder's
// tiled pipeline. What must hold: corners two tiles share become one and edges that meet at
// T-junctions on a border connect within the body's climb, and not beyond it; the join does not
// depend on the order tiles come in, nor the build on the thread count; paths over a tiled navmesh
// are exactly shortest across borders (the exact reference) and agree with the solo navmesh's; a level
// wider than a solo mesh allows builds in tiles.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core_errors.h"
#include "core_world.h"
#include "level_generator.h"
#include "navmesh/tile_join.h"
#include "path/path_planner.h"
#include "shortest_path_reference.h"

using nl::Vec3;

namespace {

using Tiles = std::vector<const nl::NavMeshInput*>;

// A tile of 4 m at (x, z) on a grid from the origin: quads given as their x-z corners at one height.
nl::NavMeshInput tile(int32_t x, int32_t z, const std::vector<std::vector<Vec3>>& quads) {
    nl::NavMeshInput in;
    in.tiles.grid = nl::TileGrid{0.0f, 0.0f, 4.0f};
    in.tiles.tiles.push_back(nl::TileCoord{x, z});
    in.weld_tolerance = 0.0f;
    for (const auto& quad : quads) {
        for (const Vec3& v : quad) {
            in.indices.push_back(static_cast<uint32_t>(in.vertices.size()));
            in.vertices.push_back(v);
        }
        in.polygon_sizes.push_back(static_cast<uint8_t>(quad.size()));
    }
    return in;
}

std::vector<Vec3> square(float x0, float z0, float x1, float z1, float y) {
    return {Vec3(x0, y, z0), Vec3(x0, y, z1), Vec3(x1, y, z1), Vec3(x1, y, z0)};
}

std::shared_ptr<const nl::NavMesh> joined(const std::vector<const nl::NavMeshInput*>& tiles) {
    return nl::build_navmesh(nl::join_tiles(tiles));
}

nl::PathResult plan(const nl::PathGraph& graph, const Vec3& start, const Vec3& goal) {
    nl::PathQuery query;
    query.start = start;
    query.goal = goal;
    query.search_half_extents = Vec3(0.5f, 2.0f, 0.5f);
    nl::PathResult result;
    nl::plan_path(graph, query, nullptr, result);
    return result;
}

bool same_navmesh(const nl::NavMesh& a, const nl::NavMesh& b) {
    if (a.vertex_count() != b.vertex_count() || a.polygon_count() != b.polygon_count()) return false;
    for (uint32_t v = 0; v < a.vertex_count(); ++v)
        if (a.vertex(v) != b.vertex(v)) return false;
    for (uint32_t p = 0; p < a.polygon_count(); ++p) {
        if (a.corner_count(p) != b.corner_count(p) || a.tile_of(p) != b.tile_of(p)) return false;
        for (uint32_t k = 0; k < a.corner_count(p); ++k)
            if (a.corner(p, k) != b.corner(p, k) || a.neighbour(p, k) != b.neighbour(p, k)) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("two tiles join along their border: shared corners welded, T-junctions joined within the climb") {
    // Tile (0, 0) is one quad; tile (1, 0) two, split at z = 2 and 0.1 m higher: its corner (4, 2) lies
    // on tile (0, 0)'s border edge, a T-junction.
    const nl::NavMeshInput left = tile(0, 0, {square(0, 0, 4, 4, 0.0f)});
    const nl::NavMeshInput right = tile(1, 0, {square(4, 0, 8, 2, 0.1f), square(4, 2, 8, 4, 0.1f)});
    const auto navmesh = joined({&left, &right});
    CHECK(navmesh->tiles().tiles.size() == 2);
    CHECK(navmesh->tiles().grid.tile_width == 4.0f);
    CHECK(navmesh->tile_of(0) == 0);
    CHECK(navmesh->tile_of(1) == 1);
    CHECK(navmesh->tile_of(2) == 1);
    // The corners at (4, 0) and (4, 4) are one each (the first tile's height); (4, 2) joined the edge.
    CHECK(navmesh->vertex_count() == 4 + 4);
    CHECK(navmesh->repairs().t_junction_corners == 1);
    CHECK(navmesh->portal_count() == 3);  // two across the border, one inside tile (1, 0)
    CHECK(navmesh->boundary_edge_count() == 3 + 2 * 2);

    // A path across the border is the straight line.
    nl::NavMeshInput solo_input = nl::join_tiles(Tiles{&left, &right});
    auto world = nl::test::make_world(1);
    const nl::Handle id = world->add_navmesh(solo_input);
    const auto graph = world->navmeshes().path_graph(id);
    const nl::PathResult result = plan(*graph, Vec3(1, 0, 1), Vec3(7, 0.1f, 3));
    REQUIRE(result.outcome == nl::PathOutcome::Complete);
    CHECK(nl::test::xz_length(result) == doctest::Approx(std::hypot(6.0, 2.0)).epsilon(1e-5));
}

TEST_CASE("tiles whose border heights are more than the climb apart do not join") {
    const nl::NavMeshInput left = tile(0, 0, {square(0, 0, 4, 4, 0.0f)});
    const nl::NavMeshInput right = tile(1, 0, {square(4, 0, 8, 2, 1.5f), square(4, 2, 8, 4, 1.5f)});
    const auto navmesh = joined({&left, &right});
    CHECK(navmesh->vertex_count() == 4 + 6);
    CHECK(navmesh->repairs().t_junction_corners == 0);
    CHECK(navmesh->portal_count() == 1);
    // Within the climb again (0.9 m), they do.
    const nl::NavMeshInput step = tile(1, 0, {square(4, 0, 8, 2, 0.85f), square(4, 2, 8, 4, 0.85f)});
    CHECK(joined({&left, &step})->portal_count() == 3);
}

TEST_CASE("corners off the border line are not border corners: tiles that only touch inside join nothing") {
    // Both tiles' polygons end 1 m short of the border: nothing lies on it, nothing connects.
    const nl::NavMeshInput left = tile(0, 0, {square(0, 0, 3, 4, 0.0f)});
    const nl::NavMeshInput right = tile(1, 0, {square(5, 0, 8, 4, 0.0f)});
    const auto navmesh = joined({&left, &right});
    CHECK(navmesh->portal_count() == 0);
    CHECK(navmesh->repairs().t_junction_corners == 0);
}

TEST_CASE("joining tiles does not depend on the order they come in") {
    const nl::NavMeshInput a = tile(0, 0, {square(0, 0, 4, 4, 0.0f)});
    const nl::NavMeshInput b = tile(1, 0, {square(4, 0, 8, 1, 0.05f), square(4, 1, 8, 4, 0.05f)});
    const nl::NavMeshInput c = tile(0, 1, {square(0, 4, 2, 8, 0.0f), square(2, 4, 4, 8, 0.0f)});
    const nl::NavMeshInput d = tile(1, 1, {square(4, 4, 8, 8, 0.1f)});
    const auto reference = joined({&a, &b, &c, &d});
    CHECK(reference->tiles().tiles.size() == 4);
    CHECK(reference->portal_count() >= 5);
    std::vector<const nl::NavMeshInput*> order = {&a, &b, &c, &d};
    std::sort(order.begin(), order.end());
    do {
        CHECK(same_navmesh(*joined(order), *reference));
    } while (std::next_permutation(order.begin(), order.end()));
}

TEST_CASE("tiles that cannot be joined are refused, naming the tile") {
    const nl::NavMeshInput a = tile(0, 0, {square(0, 0, 4, 4, 0.0f)});
    const nl::NavMeshInput twice = tile(0, 0, {square(0, 0, 4, 4, 0.0f)});
    CHECK(nl::test::message_of([&] { nl::join_tiles(Tiles{&a, &twice}); }).find("given twice") != std::string::npos);
    nl::NavMeshInput other_grid = tile(1, 0, {square(4, 0, 8, 4, 0.0f)});
    other_grid.tiles.grid.tile_width = 5.0f;
    CHECK(nl::test::message_of([&] {
              nl::join_tiles(Tiles{&a, &other_grid});
          }).find("another tile grid") != std::string::npos);
    nl::NavMeshInput other_body = tile(1, 0, {square(4, 0, 8, 4, 0.0f)});
    other_body.agent_type.radius = 0.3f;
    CHECK(nl::test::message_of([&] {
              nl::join_tiles(Tiles{&a, &other_body});
          }).find("another agent type") != std::string::npos);
    nl::NavMeshInput solo = tile(1, 0, {square(4, 0, 8, 4, 0.0f)});
    solo.tiles = nl::TileLayout{};
    CHECK(nl::test::message_of([&] { nl::join_tiles(Tiles{&a, &solo}); }).find("is not a tile") != std::string::npos);
    CHECK(nl::test::message_of([&] { nl::join_tiles(Tiles{}); }).find("none given") != std::string::npos);
}

namespace {

std::string tiles_json(int tile_size) { return "{\"tile_size\": " + std::to_string(tile_size) + "}"; }

struct Built {
    std::unique_ptr<nl::World> world;
    nl::Handle id;
    std::shared_ptr<const nl::NavMesh> navmesh;
};

Built build(const nl::levelgen::GeneratedLevel& level, int workers, const std::string& settings_json) {
    Built b;
    b.world = nl::test::make_world(workers);
    nl::test::add_level(*b.world, level);
    b.id = nl::test::build_recast_navmesh(*b.world, nl::AgentType{}, settings_json);
    b.navmesh = b.world->navmeshes().navmesh(b.id);
    return b;
}

}  // namespace

TEST_CASE("the Recast builder's tiles: the same navmesh for any thread count, borders joined") {
    const auto level = nl::levelgen::generate_default_level(7);
    const Built one = build(level, 1, tiles_json(24));
    const Built two = build(level, 2, tiles_json(24));
    CHECK(one.navmesh->tiles().tiles.size() > 4);
    CHECK(same_navmesh(*one.navmesh, *two.navmesh));
    // Every tile border a polygon edge meets is joined: none is left open for want of room.
    CHECK(one.navmesh->repairs().t_junctions_left == 0);
    MESSAGE(one.navmesh->tiles().tiles.size(), " tiles, ", one.navmesh->polygon_count(), " polygons, ",
            one.navmesh->repairs().t_junction_corners, " T-junction corners joined");
}

TEST_CASE("paths from and to points on portals are exactly shortest, tile borders and far coordinates included") {
    // A start located on an edge between two polygons (a point on a tile border, most often) lies on the
    // first portal of its corridor: the funnel must start beyond it, not turn at the portal's far end
    // (navlink-bench-tiles found walks 3 times too long on undulating.obj's tiles at x 5000).
    std::mt19937 random(3);
    for (const float offset : {0.0f, 5000.0f}) {
        for (const std::string& settings : {std::string(), tiles_json(32)}) {
            CAPTURE(offset);
            CAPTURE(settings);
            Built b;
            b.world = nl::test::make_world(1);
            nl::test::add_level(*b.world, nl::levelgen::generate_default_level(5), 0,
                                nl::Transform(Eigen::Translation3f(offset, 0.0f, offset)));
            b.id = nl::test::build_recast_navmesh(*b.world, nl::AgentType{}, settings);
            b.navmesh = b.world->navmeshes().navmesh(b.id);
            const auto graph = b.world->navmeshes().path_graph(b.id);
            const nl::test::ShortestPathReference reference(*b.navmesh);
            // Points on the portals: where an edge meets its neighbour, a random way along it.
            std::vector<Vec3> on_portals;
            for (uint32_t p = 0; p < b.navmesh->polygon_count(); ++p)
                for (uint32_t k = 0; k < b.navmesh->corner_count(p); ++k) {
                    if (b.navmesh->neighbour(p, k) == nl::kNoPolygon) continue;
                    const Vec3 u = b.navmesh->vertex(b.navmesh->corner(p, k));
                    const Vec3 v = b.navmesh->vertex(b.navmesh->corner(p, (k + 1) % b.navmesh->corner_count(p)));
                    on_portals.push_back(u + std::uniform_real_distribution<float>(0.1f, 0.9f)(random) * (v - u));
                }
            REQUIRE(on_portals.size() > 20);
            double worst = 0.0;
            int compared = 0;
            for (int k = 0; k < 200; ++k) {
                const Vec3 start = on_portals[random() % on_portals.size()];
                const Vec3 goal = k % 2 ? on_portals[random() % on_portals.size()]
                                        : b.navmesh->centre(uint32_t(random() % b.navmesh->polygon_count()));
                const nl::PathResult result = plan(*graph, start, goal);
                const std::optional<double> cheapest = reference.length(result.start, result.goal);
                if (!cheapest || result.outcome != nl::PathOutcome::Complete) continue;
                ++compared;
                const double found = nl::test::xz_length(result);
                INFO("from (", start.x(), ", ", start.y(), ", ", start.z(), ") to (", goal.x(), ", ", goal.y(), ", ",
                     goal.z(), "): ", found, " m against ", *cheapest);
                CHECK(found <= *cheapest * 1.001 + 1e-3);
                worst = std::max(worst, found / std::max(*cheapest, 1e-6) - 1.0);
            }
            CHECK(compared > 100);
            MESSAGE("offset ", offset, std::string(settings.empty() ? ", solo" : ", tiles of 32"), ": ", compared,
                    " pairs from points on portals, worst excess over the exact walk ", worst * 100.0, "%");
        }
    }
}

TEST_CASE("paths over tiled navmeshes are exactly shortest across borders and agree with the solo navmesh") {
    const auto level = nl::levelgen::generate_default_level(3);
    const Built solo = build(level, 1, "");
    const auto solo_graph = solo.world->navmeshes().path_graph(solo.id);
    const nl::test::ShortestPathReference solo_reference(*solo.navmesh);
    // Points: the solo navmesh's polygon centres.
    std::vector<Vec3> points;
    for (uint32_t p = 0; p < solo.navmesh->polygon_count(); ++p) points.push_back(solo.navmesh->centre(p));
    std::mt19937 random(11);
    // Tile sizes that put borders at every few metres of a path, each its own grid.
    for (int tile_size : {16, 23, 32, 48}) {
        CAPTURE(tile_size);
        const Built tiled = build(level, 2, tiles_json(tile_size));
        const auto graph = tiled.world->navmeshes().path_graph(tiled.id);
        const nl::test::ShortestPathReference reference(*tiled.navmesh);
        int pairs = 0, both = 0, reach_differs = 0;
        double worst_excess = 0.0, worst_solo_gap = 0.0;
        for (int k = 0; k < 120; ++k) {
            const Vec3 solo_start = points[random() % points.size()], solo_goal = points[random() % points.size()];
            // The same places on the tiled navmesh (a border may move its surface by a cell or two).
            const nl::NavPoint start_found = tiled.navmesh->find_nearest(solo_start, Vec3(0.5f, 1.0f, 0.5f));
            const nl::NavPoint goal_found = tiled.navmesh->find_nearest(solo_goal, Vec3(0.5f, 1.0f, 0.5f));
            if (!start_found.found || !goal_found.found) {
                ++reach_differs;
                continue;
            }
            // A point the border moved off the navmesh is now on its outline: taken a little inside.
            auto inside = [&](const nl::NavPoint& found) {
                const Vec3 towards = found.point + 0.05f * (tiled.navmesh->centre(found.polygon) - found.point);
                return tiled.navmesh->closest_point_on_polygon(found.polygon, towards);
            };
            const Vec3 start = inside(start_found), goal = inside(goal_found);
            const nl::PathResult result = plan(*graph, start, goal);
            const std::optional<double> cheapest = reference.length(start, goal);
            INFO("from (", start.x(), ", ", start.y(), ", ", start.z(), ") to (", goal.x(), ", ", goal.y(), ", ",
                 goal.z(), ")");
            // Exact on the tiled navmesh: found exactly when the reference finds a route, within 0.1%.
            REQUIRE((result.outcome == nl::PathOutcome::Complete) == cheapest.has_value());
            ++pairs;
            if (cheapest) {
                const double found = nl::test::xz_length(result);
                CHECK(found >= *cheapest - 1e-4);
                worst_excess = std::max(worst_excess, found / std::max(*cheapest, 1e-6) - 1.0);
            }
            // Against the solo navmesh of the same level: the same places reachable, by about the same
            // walk (tiles voxelise their borders on their own: corners move by up to a cell).
            const std::optional<double> solo_cheapest = solo_reference.length(solo_start, solo_goal);
            if (cheapest.has_value() != solo_cheapest.has_value()) {
                ++reach_differs;
            } else if (cheapest) {
                ++both;
                worst_solo_gap = std::max(worst_solo_gap, std::fabs(*cheapest - *solo_cheapest));
            }
        }
        CHECK(worst_excess <= 1e-3);
        CHECK(reach_differs == 0);
        CHECK(worst_solo_gap <= 1.0);
        MESSAGE("tile_size ", tile_size, ": ", tiled.navmesh->tiles().tiles.size(), " tiles; ", pairs, " pairs, ", both,
                " reachable, worst excess over the exact walk ", worst_excess * 100.0,
                "%, worst gap to the solo navmesh's walk ", worst_solo_gap, " m, reachability differs in ",
                reach_differs);
    }
}

TEST_CASE("a level wider than a solo mesh allows builds in tiles") {
    // A floor 20 km long: 66,667 cells of 0.3 m, more than Recast's 65,535 per side.
    nl::levelgen::GeneratedLevel strip;
    strip.add_box(nl::levelgen::Box{{0.0f, -1.0f, 0.0f}, {20000.0f, 0.0f, 6.0f}});
    auto world = nl::test::make_world(2);
    nl::test::add_level(*world, strip);
    const std::string solo_refused =
        nl::test::message_of([&] { nl::test::build_recast_navmesh(*world, nl::AgentType{}); });
    CHECK(solo_refused.find("build in tiles") != std::string::npos);
    const nl::Handle id = nl::test::build_recast_navmesh(*world, nl::AgentType{}, tiles_json(512));
    const auto navmesh = world->navmeshes().navmesh(id);
    CHECK(navmesh->tiles().tiles.size() == 131);  // ceil(66,667 / 512)
    CHECK(navmesh->bounds().max.x() > 19990.0f);
    // One walk from end to end, across every border.
    const auto graph = world->navmeshes().path_graph(id);
    const nl::PathResult result = plan(*graph, Vec3(5, 0, 3), Vec3(19995, 0, 3));
    REQUIRE(result.outcome == nl::PathOutcome::Complete);
    CHECK(nl::test::xz_length(result) == doctest::Approx(19990.0).epsilon(1e-4));
}
