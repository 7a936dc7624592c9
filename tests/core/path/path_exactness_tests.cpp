// The exact cheapest route (tests/support/shortest_path_reference.h) on cell maps whose answers are
// known, and the path search against it on random maps: a body as thin as the navmesh's agent
// without links, with random links, a wider body (a margin that narrows and closes portals), and a
// wider body with links. Every pair: the search finds a path exactly when the reference finds a
// route, is never cheaper (a search that is would cut through a wall) and is within 0.1% of it
// (issue 20): compared by x-z length without links, by cost with them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core_world.h"
#include "path/path_planner.h"
#include "path/any_angle_search.h"
#include "shortest_path_reference.h"

using nl::Vec3;

namespace {

struct Map {
    std::unique_ptr<nl::World> world;
    nl::Handle navmesh;

    explicit Map(const std::vector<std::string>& rows)
        : world(nl::test::make_world(1)), navmesh(world->add_navmesh(nl::test::cell_navmesh(rows, 0.0f))) {}
    // The cells scaled and moved by `place` (x-z): corners no longer on round numbers, so rays along
    // walls meet corners only within rounding.
    template <typename Place>
    Map(const std::vector<std::string>& rows, const Place& place) : world(nl::test::make_world(1)) {
        nl::NavMeshInput input = nl::test::cell_navmesh(rows, 0.0f);
        for (Vec3& v : input.vertices) v = place(v);
        navmesh = world->add_navmesh(std::move(input));
    }

    std::shared_ptr<const nl::PathGraph> graph() const { return world->navmeshes().path_graph(navmesh); }

    // A link between two points of the map (y = 0) asking for a drop of `drop` metres (as given, with
    // a gap of 0.1 m): taken down by a body that drops that far, climbed back (bidirectional) by one
    // that jumps that high.
    nl::Handle link(const Vec3& from, const Vec3& to, float drop, bool both_ways = false, float cost_modifier = 1.0f,
                    nl::LinkKind kind = nl::LinkKind::Drop, float clearance_width = 0.0f) {
        nl::Link l;
        l.kind = kind;
        l.start = from;
        l.end = to;
        l.apex = from;
        l.bidirectional = both_ways;
        l.cost_modifier = cost_modifier;
        l.requirements.drop = drop;
        l.requirements.gap = 0.1f;
        l.requirements.clearance_width = clearance_width;
        nl::settle_host_requirements(l, true);
        return world->add_link(navmesh, l);
    }
};

// A body of this radius that drops and jumps up to 1 m, over gaps up to 1 m.
nl::PathQuery body(float radius = 0.0f) {
    nl::PathQuery query;
    query.capabilities.radius = radius;
    query.capabilities.max_drop_height = 1.0f;
    query.capabilities.max_jump_height = 1.0f;
    query.capabilities.max_jump_distance = 1.0f;
    query.search_half_extents = Vec3(0.1f, 1.0f, 0.1f);
    return query;
}

nl::PathResult plan(const nl::PathGraph& graph, nl::PathQuery query, const Vec3& start, const Vec3& goal) {
    query.start = start;
    query.goal = goal;
    nl::PathResult result;
    nl::plan_path(graph, query, nullptr, result);
    return result;
}

// The path's length seen from above (a link's chord counted as walked: for paths without links).
std::string describe(const nl::PathResult& result) {
    std::string s =
        "outcome " + std::to_string(uint32_t(result.outcome)) + ", cost " + std::to_string(result.cost) + ":";
    for (const nl::PathPoint& p : result.points)
        s += " (" + std::to_string(p.position.x()) + ", " + std::to_string(p.position.z()) + ")" +
             (p.segment ? "[link " + std::to_string(p.segment) + "]" : "");
    return s;
}

std::vector<std::string> random_rows(std::mt19937& random) {
    std::vector<std::string> rows(10, std::string(12, '.'));
    for (std::string& r : rows) {
        for (char& c : r) c = random() % 100 < 22 ? '#' : '.';
    }
    return rows;
}

// A random point of each open cell, away from its edges.
std::vector<Vec3> cell_points(const std::vector<std::string>& rows, std::mt19937& random) {
    std::vector<Vec3> points;
    for (uint32_t r = 0; r < rows.size(); ++r) {
        for (uint32_t c = 0; c < rows[r].size(); ++c) {
            if (rows[r][c] == '.')
                points.emplace_back(c + 0.25f + 0.5f * float(random() % 100) / 100.0f, 0.0f,
                                    r + 0.25f + 0.5f * float(random() % 100) / 100.0f);
        }
    }
    return points;
}

struct Tally {
    int pairs = 0;                   // with a route
    int none = 0;                    // without (both agree)
    int within = 0;                  // within 0.1%
    int links = 0;                   // paths the search takes a link on
    double worst = 0.0;              // the search's largest excess over the reference, relative
    double cheaper = 0.0;            // the most the search's is below the reference's (>= 0), absolute
    double off_cost = 0.0;           // without links: the most the search's cost and its path's x-z length differ
    double nodes_per_polygon = 0.0;  // the exact search's interval nodes per polygon it entered, at most

    void report(const std::string& what) const {
        MESSAGE(what, ": search within 0.1% of the reference on ", within, " of ", pairs, " pairs (", none,
                " more without a route in both, ", links, " paths over links); worst +", 100.0 * worst, "%, at most ",
                cheaper, " below it");
        if (links == 0) MESSAGE(what, ": the search's cost and its path's x-z length apart by at most ", off_cost);
        MESSAGE(what, ": at most ", nodes_per_polygon, " search nodes per polygon entered");
    }
};

// Random pairs of the map's cell points: the search against the reference, by cost with links (the
// x-z walk plus the links' costs), by the path's x-z length without.
void compare(const Map& map, const nl::PathQuery& query, const std::vector<Vec3>& points, int count, bool by_cost,
             std::mt19937& random, Tally& tally, const std::string& label) {
    const auto graph = map.graph();
    const nl::test::ShortestPathReference reference(*graph, query);
    std::vector<Vec3> bends;
    for (int k = 0; k < count; ++k) {
        const Vec3 start = points[random() % points.size()], goal = points[random() % points.size()];
        const nl::PathResult result = plan(*graph, query, start, goal);
        const std::optional<double> cheapest = reference.length(start, goal, &bends);
        // INFO keeps references: to named strings, no temporaries.
        const std::string searched = describe(result), answer = cheapest ? std::to_string(*cheapest) : "none";
        std::string route;
        for (const Vec3& b : bends) route += " (" + std::to_string(b.x()) + ", " + std::to_string(b.z()) + ")";
        INFO(label, " from (", start.x(), ", ", start.z(), ") to (", goal.x(), ", ", goal.z(), "): search ", searched,
             "; reference ", answer, " by", route);
        REQUIRE((result.outcome == nl::PathOutcome::Complete) == cheapest.has_value());
        if (!cheapest) {
            ++tally.none;
            continue;
        }
        ++tally.pairs;
        // The exact search alone finds it (a way it missed would be the corridor search's path).
        nl::PathQuery alone = query;
        alone.start = start;
        alone.goal = goal;
        nl::CorridorSearch exact;
        nl::find_shortest_corridor(*graph, alone, graph->navmesh().find_nearest(start, query.search_half_extents),
                                   graph->navmesh().find_nearest(goal, query.search_half_extents), 1.0f, nullptr,
                                   exact);
        CHECK(exact.reached_goal);
        tally.nodes_per_polygon =
            std::max(tally.nodes_per_polygon, double(exact.search_nodes) / std::max(1u, exact.nodes_visited));
        if (result.links_used > 0) ++tally.links;
        const double found = by_cost ? double(result.cost) : nl::test::xz_length(result);
        CHECK(found >= *cheapest - 1e-4);
        tally.cheaper = std::max(tally.cheaper, *cheapest - found);
        if (result.links_used == 0)
            tally.off_cost = std::max(tally.off_cost, std::fabs(double(result.cost) - nl::test::xz_length(result)));
        const double excess = found / std::max(*cheapest, 1e-6) - 1.0;
        CHECK(excess <= 1e-3);
        tally.worst = std::max(tally.worst, excess);
        if (excess <= 1e-3) ++tally.within;
    }
}

}  // namespace

TEST_CASE("the shortest walk reference: straight, round one corner, round a pillar, none") {
    Map corner({"...", "##.", "##."});
    const nl::test::ShortestPathReference around_corner(corner.graph()->navmesh());
    CHECK(*around_corner.length(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 0.5f)) == doctest::Approx(2.0).epsilon(1e-9));
    // Round the reflex corner (2, 1): twice sqrt(1.5^2 + 0.5^2).
    CHECK(*around_corner.length(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 2.5f)) ==
          doctest::Approx(2 * std::sqrt(2.5)).epsilon(1e-9));
    CHECK_FALSE(around_corner.walkable(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 2.5f)));
    CHECK(around_corner.walkable(Vec3(0.0f, 0, 0.0f), Vec3(3.0f, 0, 0.0f)));  // along the outline

    Map pillar({".....", ".....", "..#..", ".....", "....."});
    const nl::test::ShortestPathReference around_pillar(pillar.graph()->navmesh());
    // Past the pillar's corners (2, 2) and (3, 2): 2 sqrt(1.5^2 + 0.5^2) + 1.
    CHECK(*around_pillar.length(Vec3(0.5f, 0, 2.5f), Vec3(4.5f, 0, 2.5f)) ==
          doctest::Approx(2 * std::sqrt(2.5) + 1).epsilon(1e-9));

    Map apart({"..#.."});
    CHECK_FALSE(
        nl::test::ShortestPathReference(apart.graph()->navmesh()).length(Vec3(0.5f, 0, 0.5f), Vec3(4.5f, 0, 0.5f)));

    // Two cells touching at a corner alone: no way between them.
    Map diagonal({".#", "#."});
    CHECK_FALSE(
        nl::test::ShortestPathReference(diagonal.graph()->navmesh()).length(Vec3(0.5f, 0, 0.5f), Vec3(1.5f, 0, 1.5f)));
}

TEST_CASE("the shortest walk reference: a wider body crosses portals within their narrowed openings") {
    // Round the corner (2, 1) with a margin of 0.25: the portals that end there open 0.25 m away from
    // it, at (2, 0.75) below and (2.25, 1) beside.
    Map corner({"...", "##.", "##."});
    const nl::PathQuery wide = body(0.25f);
    const nl::test::ShortestPathReference reference(*corner.graph(), wide);
    CHECK(reference.margin() == doctest::Approx(0.25f));
    std::vector<Vec3> bends;
    const double expected = std::hypot(1.5, 0.25) + std::hypot(0.25, 0.25) + std::hypot(0.25, 1.5);
    CHECK(*reference.length(Vec3(0.5f, 0, 0.5f), Vec3(2.5f, 0, 2.5f), &bends) ==
          doctest::Approx(expected).epsilon(1e-6));
    REQUIRE(bends.size() == 2);
    CHECK(bends[0].x() == doctest::Approx(2.0f));
    CHECK(bends[0].z() == doctest::Approx(0.75f));
    CHECK(bends[1].x() == doctest::Approx(2.25f));
    CHECK(bends[1].z() == doctest::Approx(1.0f));
    // Past the corner closer than the margin: not for this body, fine for a thin one.
    CHECK_FALSE(reference.walkable(Vec3(0.5f, 0, 0.9f), Vec3(2.1f, 0, 0.9f)));
    CHECK(
        nl::test::ShortestPathReference(corner.graph()->navmesh()).walkable(Vec3(0.5f, 0, 0.9f), Vec3(2.1f, 0, 0.9f)));

    // A one-cell passage closes for a margin of half a cell or more.
    Map passage({"...", "#.#", "..."});
    CHECK(nl::test::ShortestPathReference(*passage.graph(), body(0.45f))
              .length(Vec3(1.5f, 0, 0.5f), Vec3(1.5f, 0, 2.5f)));
    CHECK_FALSE(
        nl::test::ShortestPathReference(*passage.graph(), body(0.5f)).length(Vec3(1.5f, 0, 0.5f), Vec3(1.5f, 0, 2.5f)));
}

TEST_CASE("the shortest walk reference: its bend points are every place a cheapest route turns") {
    // Against a reference that may bend at every vertex and every narrowed portal end.
    std::mt19937 random(77);
    for (int trial = 0; trial < 3; ++trial) {
        const std::vector<std::string> rows = random_rows(random);
        Map m(rows);
        const std::vector<Vec3> points = cell_points(rows, random);
        for (int i = 0; i < 6; ++i)
            m.link(points[random() % points.size()], points[random() % points.size()], float(random() % 2), i % 2 == 0,
                   0.5f + float(i % 3));
        const auto graph = m.graph();
        for (const float radius : {0.0f, 0.3f, 0.55f}) {
            nl::PathQuery query = body(radius);
            query.link_cost = 0.25f;
            const nl::test::ShortestPathReference bends_only(*graph, query), every_vertex(*graph, query, true);
            CHECK(bends_only.node_count() < every_vertex.node_count());
            for (int k = 0; k < 25; ++k) {
                const Vec3 start = points[random() % points.size()], goal = points[random() % points.size()];
                const std::optional<double> a = bends_only.length(start, goal), b = every_vertex.length(start, goal);
                INFO("trial ", trial, " radius ", radius, " from (", start.x(), ", ", start.z(), ") to (", goal.x(),
                     ", ", goal.z(), ")");
                REQUIRE(a.has_value() == b.has_value());
                if (a) CHECK(*a == doctest::Approx(*b).epsilon(1e-9));
            }
        }
    }
}

// `maps` random maps, each placed by `place`: `trial` adds to each what it asks for (links) and
// compares random pairs on it. Every pair within 0.1%, and at least `least_pairs` with a route.
template <typename Place, typename Trial>
void random_map_trials(uint32_t seed, int maps, const Place& place, const std::string& label, int least_pairs,
                       const Trial& trial) {
    std::mt19937 random(seed);
    Tally tally;
    for (int index = 0; index < maps; ++index) {
        const std::vector<std::string> rows = random_rows(random);
        Map m(rows, place);
        std::vector<Vec3> points = cell_points(rows, random);
        for (Vec3& p : points) p = place(p);
        trial(index, m, points, random, tally);
    }
    tally.report(label);
    CHECK(tally.within == tally.pairs);
    CHECK(tally.pairs > least_pairs);
}

const auto kAsBuilt = [](const Vec3& v) { return v; };

TEST_CASE("on random maps the search is never shorter than the shortest walk") {
    random_map_trials(2026, 12, kAsBuilt, "no links, no margin", 1500,
                      [](int index, Map& m, const std::vector<Vec3>& points, std::mt19937& random, Tally& tally) {
                          compare(m, body(0.0f), points, 250, false, random, tally, "trial " + std::to_string(index));
                      });
}

TEST_CASE("on random maps turned, scaled and moved the search is the shortest walk") {
    // Corners off round numbers and walls at an angle: a walk down a straight wall from one corner
    // reaches the next only within rounding, and must still bend there (dungeon lost such ways).
    const float c = std::cos(0.3f), s = std::sin(0.3f);
    const auto place = [&](const Vec3& v) {
        return Vec3(1.984375f + 0.7312f * (c * v.x() - s * v.z()), v.y(),
                    -31.2412f + 0.7312f * (s * v.x() + c * v.z()));
    };
    random_map_trials(2030, 12, place, "turned, scaled and moved", 1500,
                      [](int index, Map& m, const std::vector<Vec3>& points, std::mt19937& random, Tally& tally) {
                          compare(m, body(0.0f), points, 250, false, random, tally, "trial " + std::to_string(index));
                      });
}

TEST_CASE("on random maps with links the search's cost is the cheapest route's") {
    const float modifiers[] = {0.5f, 0.8f, 1.0f, 1.5f, 3.0f};
    random_map_trials(2027, 12, kAsBuilt, "links, no margin", 1500,
                      [&](int index, Map& m, const std::vector<Vec3>& points, std::mt19937& random, Tally& tally) {
                          // Jumps and drops between random cells: some both ways, some cheaper per metre
                          // than walking, some dearer; drops of 2 m are beyond the body (can_take).
                          for (int l = 0; l < 12; ++l) {
                              const Vec3 from = points[random() % points.size()], to = points[random() % points.size()];
                              m.link(from, to, float(random() % 3), random() % 3 == 0, modifiers[random() % 5],
                                     random() % 2 ? nl::LinkKind::Drop : nl::LinkKind::Jump);
                          }
                          nl::PathQuery query = body(0.0f);
                          query.link_cost = 0.1f * float(1 + random() % 5);
                          compare(m, query, points, 250, true, random, tally, "trial " + std::to_string(index));
                      });
}

TEST_CASE("on random maps with links a wider body's cost is the cheapest route's") {
    // Links as above, some too narrow for the wider bodies (clearance 0.8 m against 2 x radius).
    const float modifiers[] = {0.5f, 1.0f, 2.0f};
    const float radii[] = {0.3f, 0.45f, 0.55f};
    random_map_trials(
        2029, 6, kAsBuilt, "links, margin 0.3 to 0.55", 500,
        [&](int index, Map& m, const std::vector<Vec3>& points, std::mt19937& random, Tally& tally) {
            for (int l = 0; l < 12; ++l) {
                const Vec3 from = points[random() % points.size()], to = points[random() % points.size()];
                m.link(from, to, float(random() % 2), random() % 3 == 0, modifiers[random() % 3], nl::LinkKind::Jump,
                       random() % 3 == 0 ? 0.8f : 0.0f);
            }
            nl::PathQuery query = body(radii[index % 3]);
            query.link_cost = 0.3f;
            compare(m, query, points, 200, true, random, tally,
                    "trial " + std::to_string(index) + " radius " + std::to_string(query.capabilities.radius));
        });
}

TEST_CASE("on random maps a wider body's path is the shortest walk through narrowed portals") {
    const float radii[] = {0.15f, 0.3f, 0.45f, 0.55f};
    random_map_trials(2028, 12, kAsBuilt, "margin 0.15 to 0.55", 1000,
                      [&](int index, Map& m, const std::vector<Vec3>& points, std::mt19937& random, Tally& tally) {
                          const float radius = radii[index % 4];
                          compare(m, body(radius), points, 250, false, random, tally,
                                  "trial " + std::to_string(index) + " radius " + std::to_string(radius));
                      });
}

// What walking a path costs on a cell map with these area costs, seen from above, each stretch
// along a cell border at the dearer side's rate: at least what the planner counts for it.
double dearest_side_cost(const std::vector<std::string>& rows, const std::vector<float>& costs,
                         const nl::PathResult& path) {
    auto rate_at = [&](double x, double z) {
        float rate = 0.0f;
        const bool on_x = std::fabs(x - std::round(x)) < 1e-6, on_z = std::fabs(z - std::round(z)) < 1e-6;
        for (int dx = on_x ? -1 : 0; dx <= 0; ++dx) {
            for (int dz = on_z ? -1 : 0; dz <= 0; ++dz) {
                const long c = on_x ? std::lround(x) + dx : long(std::floor(x)),
                           r = on_z ? std::lround(z) + dz : long(std::floor(z));
                if (r < 0 || r >= long(rows.size()) || c < 0 || c >= long(rows[r].size())) continue;
                const char cell = rows[r][c];
                if (cell == '.')
                    rate = std::max(rate, costs[0]);
                else if (cell >= '0' && cell <= '9')
                    rate = std::max(rate, costs[size_t(cell - '0')]);
            }
        }
        return rate;
    };
    double cost = 0.0;
    for (size_t i = 1; i < path.points.size(); ++i) {
        const Vec3 a = path.points[i - 1].position, b = path.points[i].position;
        std::vector<double> cuts = {0.0, 1.0};
        for (int axis : {0, 2}) {
            const double from = a[axis], to = b[axis];
            for (double line = std::ceil(std::min(from, to)); line <= std::max(from, to); line += 1.0)
                if (to != from) cuts.push_back((line - from) / (to - from));
        }
        std::sort(cuts.begin(), cuts.end());
        const double length = std::hypot(double(b.x()) - a.x(), double(b.z()) - a.z());
        for (size_t k = 1; k < cuts.size(); ++k) {
            const double t = 0.5 * (cuts[k - 1] + cuts[k]);
            cost +=
                (cuts[k] - cuts[k - 1]) * length * rate_at(a.x() + t * (b.x() - a.x()), a.z() + t * (b.z() - a.z()));
        }
    }
    return cost;
}

TEST_CASE(
    "on random maps with areas of different costs a path costs at most the dearest rate over the cheapest times the "
    "cheapest route") {
    // The bound issue 20 asks for where no exact search applies: between the shortest walk at the
    // cheapest rate, which no route undercuts, and that walk at the dearest rate, which the planner's
    // choice never exceeds (it takes the corridor search's path only when that is cheaper).
    std::mt19937 random(2032);
    const std::vector<float> costs = {1.0f, 2.5f, 4.0f};
    int pairs = 0, bent_by_costs = 0;
    double worst = 0.0;  // the most a path's cost is over the cheapest rate times the shortest walk
    for (int index = 0; index < 8; ++index) {
        std::vector<std::string> rows = random_rows(random);
        for (std::string& r : rows)
            for (char& c : r)
                if (c == '.' && random() % 100 < 40) c = random() % 2 ? '1' : '2';
        const Map m(rows);
        const auto graph = m.graph();
        const nl::test::ShortestPathReference reference(*graph, body());
        const std::vector<Vec3> points = cell_points(rows, random);
        for (int k = 0; k < 150; ++k) {
            const Vec3 start = points[random() % points.size()], goal = points[random() % points.size()];
            nl::PathQuery query = body();
            query.area_costs = costs;
            const nl::PathResult result = plan(*graph, query, start, goal);
            const std::optional<double> shortest = reference.length(start, goal);
            INFO("map ", index, " from (", start.x(), ", ", start.z(), ") to (", goal.x(), ", ", goal.z(),
                 "): ", describe(result));
            REQUIRE((result.outcome == nl::PathOutcome::Complete) == shortest.has_value());
            if (!shortest) continue;
            ++pairs;
            CHECK(result.cost >= 1.0 * *shortest * (1.0 - 1e-5) - 1e-4);
            CHECK(result.cost <= 4.0 * *shortest * (1.0 + 1e-5) + 1e-4);
            CHECK(result.length >= *shortest * (1.0 - 1e-5) - 1e-4);
            // Never dearer than the shortest walk (planned without costs) at these costs.
            nl::PathQuery walker = body();
            const double walk = dearest_side_cost(rows, costs, plan(*graph, walker, start, goal));
            CHECK(result.cost <= walk * (1.0 + 1e-4) + 1e-4);
            worst = std::max(worst, result.cost / std::max(*shortest, 1e-6));
            bent_by_costs += nl::test::xz_length(result) > *shortest * (1.0 + 1e-3) ? 1 : 0;
        }
    }
    MESSAGE(pairs, " pairs; ", bent_by_costs, " paths longer than the shortest walk to pay less; cost at most ", worst,
            " x the shortest walk");
    CHECK(pairs > 500);
    CHECK(bent_by_costs > 0);  // the costs do steer paths
}

TEST_CASE("in a hall of pillars on grid lines the exact search's nodes stay a few per polygon") {
    // Pillar corners in rows and columns: a walk along a grid line reaches a corner as cheaply past
    // each corner before it, the same way. Bending there once (not once per corner behind) keeps the
    // nodes few; doubling at each corner in a row made hundreds per polygon.
    std::vector<std::string> rows(15, std::string(31, '.'));
    for (size_t r = 1; r + 1 < rows.size(); r += 2)
        for (size_t c = 1; c + 1 < rows[r].size(); c += 2) rows[r][c] = '#';
    const Map m(rows);
    const auto graph = m.graph();
    std::mt19937 random(2031);
    const std::vector<Vec3> points = cell_points(rows, random);
    const nl::test::ShortestPathReference reference(*graph, body());
    double most = 0.0;
    for (int k = 0; k < 300; ++k) {
        const Vec3 start = points[random() % points.size()], goal = points[random() % points.size()];
        nl::PathQuery query = body();
        query.start = start, query.goal = goal;
        nl::CorridorSearch exact;
        nl::find_shortest_corridor(*graph, query, graph->navmesh().find_nearest(start, query.search_half_extents),
                                   graph->navmesh().find_nearest(goal, query.search_half_extents), 1.0f, nullptr,
                                   exact);
        REQUIRE(exact.reached_goal);
        most = std::max(most, double(exact.search_nodes) / exact.nodes_visited);
        const std::optional<double> cheapest = reference.length(start, goal);
        REQUIRE(cheapest);
        CHECK(double(exact.cost) == doctest::Approx(*cheapest).epsilon(1e-5));
    }
    MESSAGE("at most ", most, " search nodes per polygon entered");
    CHECK(most < 16.0);
}

TEST_CASE("a one-way drop that is the only way: a path down it, none back") {
    // Two ledges apart; a drop from (2.5, 0.5) to (4.5, 0.5).
    Map m({"...#..."});
    m.link(Vec3(2.5f, 0, 0.5f), Vec3(4.5f, 0, 0.5f), 1.0f);
    const auto graph = m.graph();
    nl::PathQuery query = body();
    query.link_cost = 0.5f;
    const nl::test::ShortestPathReference reference(*graph, query);
    const nl::PathResult down = plan(*graph, query, Vec3(0.5f, 0, 0.5f), Vec3(6.5f, 0, 0.5f));
    const std::string searched = describe(down);
    INFO(searched);
    REQUIRE(down.outcome == nl::PathOutcome::Complete);
    CHECK(down.links_used == 1);
    // Walk 2, drop 2 (+0.5), walk 2.
    CHECK(down.cost == doctest::Approx(6.5f).epsilon(1e-5));
    CHECK(*reference.length(Vec3(0.5f, 0, 0.5f), Vec3(6.5f, 0, 0.5f)) == doctest::Approx(6.5).epsilon(1e-6));
    query.accept_partial = false;
    CHECK(plan(*graph, query, Vec3(6.5f, 0, 0.5f), Vec3(0.5f, 0, 0.5f)).outcome == nl::PathOutcome::NoPath);
    CHECK_FALSE(reference.length(Vec3(6.5f, 0, 0.5f), Vec3(0.5f, 0, 0.5f)));
    // A body that drops less far has no way down either.
    nl::PathQuery timid = body();
    timid.capabilities.max_drop_height = 0.5f;
    timid.accept_partial = false;
    CHECK(plan(*graph, timid, Vec3(0.5f, 0, 0.5f), Vec3(6.5f, 0, 0.5f)).outcome == nl::PathOutcome::NoPath);
    CHECK_FALSE(nl::test::ShortestPathReference(*graph, timid).length(Vec3(0.5f, 0, 0.5f), Vec3(6.5f, 0, 0.5f)));
}

TEST_CASE("a link is taken when it is cheaper than walking round, not when its cost modifier makes it dearer") {
    // From (0.5, 0.5) to (0.5, 2.5) past a wall with its gap at the far end; a jump across the wall
    // from (1.5, 0.5) to (1.5, 2.5).
    const std::vector<std::string> rows{".....", "####.", "....."};
    const Vec3 start(0.5f, 0, 0.5f), goal(0.5f, 0, 2.5f);
    // Round the wall's corners (4, 1) and (4, 2): 2 sqrt(3.5^2 + 0.5^2) + 1.
    const double round = 2 * std::sqrt(12.5) + 1;
    for (const float modifier : {1.0f, 10.0f}) {
        Map m(rows);
        m.link(Vec3(1.5f, 0, 0.5f), Vec3(1.5f, 0, 2.5f), 0.0f, true, modifier, nl::LinkKind::Jump);
        const auto graph = m.graph();
        nl::PathQuery query = body();
        query.capabilities.max_jump_distance = 3.0f;
        query.link_cost = 0.5f;
        const nl::test::ShortestPathReference reference(*graph, query);
        const nl::PathResult result = plan(*graph, query, start, goal);
        const std::string searched = describe(result);
        INFO("modifier ", modifier, ": ", searched);
        REQUIRE(result.outcome == nl::PathOutcome::Complete);
        if (modifier == 1.0f) {
            // Walk 1, jump 2 (+0.5), walk 1.
            CHECK(result.links_used == 1);
            CHECK(result.cost == doctest::Approx(4.5f).epsilon(1e-5));
            CHECK(*reference.length(start, goal) == doctest::Approx(4.5).epsilon(1e-6));
            // Back the same way (the link goes both ways).
            CHECK(plan(*graph, query, goal, start).cost == doctest::Approx(4.5f).epsilon(1e-5));
        } else {
            // The jump would cost 1 + 20.5 + 1.
            CHECK(result.links_used == 0);
            CHECK(result.cost == doctest::Approx(round).epsilon(1e-5));
            CHECK(nl::test::xz_length(result) == doctest::Approx(round).epsilon(1e-5));
            CHECK(*reference.length(start, goal) == doctest::Approx(round).epsilon(1e-6));
        }
    }
}

TEST_CASE("a wider body goes round a passage closed to it") {
    // Rows 0-1 and 3-4 (two cells wide) join through row 2's one-cell gap at column 1 and its
    // two-cell gap at columns 5-6.
    Map m({"........", "........", "#.###..#", "........", "........"});
    const auto graph = m.graph();
    const Vec3 start(1.5f, 0, 0.5f), goal(1.5f, 0, 4.5f);
    // A thin body goes straight through the narrow gap.
    const nl::PathResult thin = plan(*graph, body(0.0f), start, goal);
    REQUIRE(thin.outcome == nl::PathOutcome::Complete);
    CHECK(nl::test::xz_length(thin) == doctest::Approx(4.0).epsilon(1e-6));
    // A body 0.55 m wider closes it (1 m < 2 x 0.55 m) and goes round the wall's end at column 4:
    // the portal into (5, 1) at x = 5 opens from z = 1 to 1.45 (0.55 m from the outline vertex
    // (5, 2)), the one into (5, 2) at z = 2 from x = 5.55; so it bends at (5, 1.45), (5.55, 2),
    // (5.55, 3) and (5, 3.55): 2 (|(3.5, 0.95)| + |(0.55, 0.55)|) + 1.
    const double expected = 2 * (std::hypot(3.5, 0.95) + std::hypot(0.55, 0.55)) + 1;
    const nl::PathQuery wide = body(0.55f);
    const nl::PathResult result = plan(*graph, wide, start, goal);
    const std::string searched = describe(result);
    INFO(searched);
    REQUIRE(result.outcome == nl::PathOutcome::Complete);
    CHECK(nl::test::xz_length(result) == doctest::Approx(expected).epsilon(1e-5));
    std::vector<Vec3> bends;
    CHECK(*nl::test::ShortestPathReference(*graph, wide).length(start, goal, &bends) ==
          doctest::Approx(expected).epsilon(1e-6));
    CHECK(bends.size() == 4);
}
