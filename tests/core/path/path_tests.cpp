// Path search and string pulling on host navmeshes drawn as cell maps, where the right path is
// known exactly: straight runs, turns round corners, agent radius, areas, islands, links.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core_world.h"
#include "path/path_planner.h"

using nl::Vec3;

namespace {

// A world holding one cell-map navmesh (core_world.h).
struct CellMap {
    std::unique_ptr<nl::World> world;
    nl::Handle navmesh;

    explicit CellMap(const std::vector<std::string>& rows, float agent_radius = 0.0f)
        : world(nl::test::make_world(1)), navmesh(world->add_navmesh(nl::test::cell_navmesh(rows, agent_radius))) {}

    nl::PathQuery request(float sx, float sz, float gx, float gz) const {
        nl::PathQuery q;
        q.start = Vec3(sx, 0.0f, sz);
        q.goal = Vec3(gx, 0.0f, gz);
        q.capabilities.radius = 0.0f;  // as thin as the navmesh assumes: no margin
        return q;
    }

    // A link as nl_link_add makes it of an nl_link_def between these points of the map (y = 0): the
    // higher end as its apex; requirements measured from the ends, or taken as given (with the length
    // measured when given as 0).
    nl::Link link(float x0, float x1, nl::LinkKind kind, bool as_given = false,
                  const nl::LinkRequirements& given = nl::LinkRequirements{}) const {
        nl::Link l;
        l.kind = kind;
        l.start = Vec3(x0, 0.0f, 0.5f);
        l.end = Vec3(x1, 0.0f, 0.5f);
        l.apex = l.start.y() > l.end.y() ? l.start : l.end;
        l.requirements = given;
        nl::settle_host_requirements(l, as_given);
        return l;
    }
};

struct Path {
    nl::PathResult result;

    std::string describe() const {
        std::string s =
            "outcome " + std::to_string(uint32_t(result.outcome)) + ", length " + std::to_string(result.length) + ":";
        for (const nl::PathPoint& p : result.points)
            s += " (" + std::to_string(p.position[0]) + ", " + std::to_string(p.position[1]) + ", " +
                 std::to_string(p.position[2]) + ")" + (p.segment ? "[link " + std::to_string(p.segment) + "]" : "");
        return s;
    }
};

// Plans on the navmesh and its links as they are now (the snapshot nl_path_find reads).
Path find(const CellMap& map, const nl::PathQuery& query) {
    Path path;
    const auto graph = map.world->navmeshes().path_graph(map.navmesh);
    nl::plan_path(*graph, query, nullptr, path.result);
    return path;
}

void check_point(const nl::PathPoint& p, float x, float z) {
    // Corners are navmesh vertices, kept on the navmesh grid (1/1024 m).
    CHECK(std::fabs(p.position[0] - x) <= 0.0005f);
    CHECK(std::fabs(p.position[2] - z) <= 0.0005f);
}

}  // namespace

TEST_CASE("a straight run is two points and its length") {
    CellMap map({"......"});
    const Path p = find(map, map.request(0.5f, 0.5f, 5.5f, 0.5f));
    INFO(p.describe());
    CHECK(p.result.outcome == nl::PathOutcome::Complete);
    REQUIRE(p.result.points.size() == 2);
    check_point(p.result.points[0], 0.5f, 0.5f);
    check_point(p.result.points[1], 5.5f, 0.5f);
    CHECK(p.result.length == doctest::Approx(5.0f));
    CHECK(p.result.cost == doctest::Approx(5.0f));
    CHECK(p.result.points[0].segment == nl::kSegmentWalk);
    CHECK(p.result.points[0].link.index1 == 0);

    // 1 m wide, for a body 1.2 m wide: no way through.
    nl::PathQuery wide = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    wide.capabilities.radius = 0.6f;
    wide.accept_partial = false;
    CHECK(find(map, wide).result.outcome == nl::PathOutcome::NoPath);
}

TEST_CASE("a U-turn bends at the two inner corners, and a wider agent keeps its distance from them") {
    CellMap map({".....", "####.", "....."});
    const float turn = 2.0f * std::sqrt(3.5f * 3.5f + 0.5f * 0.5f);
    {
        const Path p = find(map, map.request(0.5f, 0.5f, 0.5f, 2.5f));
        INFO(p.describe());
        REQUIRE(p.result.points.size() == 4);
        check_point(p.result.points[1], 4.0f, 1.0f);
        check_point(p.result.points[2], 4.0f, 2.0f);
        CHECK(p.result.length == doctest::Approx(turn + 1.0f));
        CHECK(p.result.points[1].polygon != p.result.points[0].polygon);
    }
    {
        // The navmesh was made for radius 0: a 0.25 m body crosses each portal 0.25 m from the
        // outline, so it rounds the corners on a chamfer.
        nl::PathQuery def = map.request(0.5f, 0.5f, 0.5f, 2.5f);
        def.capabilities.radius = 0.25f;
        const Path p = find(map, def);
        INFO(p.describe());
        REQUIRE(p.result.points.size() == 6);
        check_point(p.result.points[1], 4.0f, 0.75f);
        check_point(p.result.points[2], 4.25f, 1.0f);
        check_point(p.result.points[3], 4.25f, 2.0f);
        check_point(p.result.points[4], 4.0f, 2.25f);
    }
    {
        // The same navmesh declared as made for radius 0.25: a 0.25 agent fits it as it is.
        CellMap eroded({".....", "####.", "....."}, 0.25f);
        nl::PathQuery def = eroded.request(0.5f, 0.5f, 0.5f, 2.5f);
        def.capabilities.radius = 0.25f;
        const Path p = find(eroded, def);
        REQUIRE(p.result.points.size() == 4);
        check_point(p.result.points[1], 4.0f, 1.0f);
    }
}

TEST_CASE("a wide agent takes the long way round a corridor narrower than its body") {
    // The direct way, through column 4 of rows 2-4, is 1 m wide; the way round, columns 8-9, is 2 m.
    CellMap map({"..........", "..........", "####.###..", "####.###..", "####.###..", "..........", ".........."});
    nl::PathQuery def = map.request(4.5f, 1.0f, 4.5f, 6.0f);
    def.capabilities.radius = 0.4f;
    const Path narrow = find(map, def);
    INFO(narrow.describe());
    REQUIRE(narrow.result.outcome == nl::PathOutcome::Complete);
    CHECK(narrow.result.points.size() == 2);
    CHECK(narrow.result.length == doctest::Approx(5.0f));

    def.capabilities.radius = 0.6f;
    const Path wide = find(map, def);
    INFO(wide.describe());
    REQUIRE(wide.result.outcome == nl::PathOutcome::Complete);
    CHECK(wide.result.length > 10.0f);
    for (const nl::PathPoint& p : wide.result.points) {
        if (p.position[2] > 2.0f && p.position[2] < 5.0f) CHECK(p.position[0] >= 8.6f - 1e-4f);
    }

    def.capabilities.radius = 1.1f;  // wider than any way through
    def.accept_partial = false;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
}

TEST_CASE("area costs steer the path and NL_AREA_EXCLUDED keeps it out") {
    // (NL_AREA_EXCLUDED is the area cost 0.)
    // A shortcut of area 2 through the middle; the way round the wall is longer.
    CellMap map({".....", ".###.", "2222.", ".###.", "....."});
    nl::PathQuery def = map.request(0.5f, 0.5f, 0.5f, 4.5f);
    const Path through = find(map, def);
    INFO(through.describe());
    CHECK(through.result.length == doctest::Approx(4.0f));

    def.area_costs = {1.0f, 1.0f, 10.0f};
    const Path expensive = find(map, def);
    INFO(expensive.describe());
    CHECK(expensive.result.length > 8.0f);
    CHECK(expensive.result.cost < 4.0f * 10.0f);

    def.area_costs = {1.0f, 1.0f, 0.0f};
    const Path avoided = find(map, def);
    CHECK(avoided.result.length > 8.0f);
    for (const nl::PathPoint& p : avoided.result.points)
        CHECK_FALSE((p.position[2] > 2.0f && p.position[2] < 3.0f && p.position[0] < 4.0f));
}

TEST_CASE("an unreachable goal gives a partial path to the nearest reachable point, or no path") {
    CellMap map({"...#...."});
    nl::PathQuery def = map.request(0.5f, 0.5f, 6.5f, 0.5f);
    const Path partial = find(map, def);
    INFO(partial.describe());
    // Its C status, SUCCESS | PARTIAL_RESULT, and no path's plain SUCCESS: abi.paths.find_synchronous.
    CHECK(partial.result.outcome == nl::PathOutcome::Partial);
    REQUIRE(partial.result.points.size() == 2);
    check_point(partial.result.points.back(), 3.0f, 0.5f);
    CHECK(partial.result.goal[0] == doctest::Approx(6.5f));

    def.accept_partial = false;
    const Path none = find(map, def);
    CHECK(none.result.outcome == nl::PathOutcome::NoPath);
    CHECK(none.result.points.empty());
}

TEST_CASE("a partial path ends at the nearest point the body reaches, over the links it can take, built map or not") {
    // Three islands; a one-way drop from the first into the second. The goal is on the third.
    CellMap map({"..#..#..", "..#..#.."});
    nl::LinkRequirements declared;
    declared.gap = 0.2f;
    declared.drop = 2.0f;
    map.world->add_link(map.navmesh, map.link(1.9f, 3.1f, nl::LinkKind::Drop, true, declared));
    const auto graph = map.world->navmeshes().path_graph(map.navmesh);

    nl::PathQuery walker = map.request(0.5f, 0.2f, 7.5f, 1.5f);
    nl::PathQuery dropper = walker;
    dropper.capabilities.max_drop_height = 3.0f;
    for (const nl::PathQuery& body : {walker, dropper}) {
        const bool drops = body.capabilities.max_drop_height > 0.0f;
        CAPTURE(drops);
        const size_t maps_before = graph->reachability_map_count();
        const Path first = find(map, body);  // searches everything, then builds the body's map
        CHECK(graph->reachability_map_count() == maps_before + 1);
        const Path again = find(map, body);  // reads the map at once
        INFO(first.describe());
        INFO(again.describe());
        for (const Path* p : {&first, &again}) {
            CHECK(p->result.outcome == nl::PathOutcome::Partial);
            CHECK(p->result.goal[0] == doctest::Approx(7.5f));  // the goal asked for, as snapped
            REQUIRE_FALSE(p->result.points.empty());
            // The nearest point: the rim of the first island, or of the second for a body that drops.
            check_point(p->result.points.back(), drops ? 5.0f : 2.0f, 1.5f);
            CHECK(p->result.links_used == (drops ? 1u : 0u));
        }
        REQUIRE(first.result.points.size() == again.result.points.size());
        for (size_t i = 0; i < first.result.points.size(); ++i)
            CHECK(first.result.points[i].position == again.result.points[i].position);
        CHECK(first.result.cost == again.result.cost);
        // A straight walk when no link is taken: its cost is its length.
        if (!drops) CHECK(first.result.cost == doctest::Approx(std::hypot(1.5f, 1.3f)));
    }
}

TEST_CASE("ends that do not snap to the navmesh have their own outcomes") {
    CellMap map({"...."});
    CHECK(find(map, map.request(-10.0f, 0.5f, 3.5f, 0.5f)).result.outcome == nl::PathOutcome::StartOffNavMesh);
    CHECK(find(map, map.request(0.5f, 0.5f, 30.0f, 0.5f)).result.outcome == nl::PathOutcome::GoalOffNavMesh);
    nl::PathQuery def = map.request(0.5f, 0.5f, 3.5f, 0.5f);
    def.start.y() = 10.0f;  // above the default box of +-4 m
    CHECK(find(map, def).result.outcome == nl::PathOutcome::StartOffNavMesh);
    def.search_half_extents.y() = 20.0f;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::Complete);
}

TEST_CASE("max_nodes bounds the search") {
    CellMap map({"....................", "...................."});
    nl::PathQuery def = map.request(0.5f, 0.5f, 19.5f, 1.5f);
    def.max_nodes = 5;
    const Path p = find(map, def);
    CHECK(p.result.outcome == nl::PathOutcome::Partial);
    CHECK(p.result.out_of_nodes);
    CHECK(p.result.nodes_visited <= 5);
    def.max_nodes = 0;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::Complete);
}

TEST_CASE("links join islands for the agents whose bodies can take them") {
    CellMap map({"...#...#..."});
    nl::Link jump = map.link(2.9f, 4.1f, nl::LinkKind::Jump);
    jump.bidirectional = true;
    const nl::Handle jump_id = map.world->add_link(map.navmesh, jump);
    nl::LinkRequirements declared;  // declared as a drop of 2 m (the map is flat)
    declared.gap = 0.2f;
    declared.drop = 2.0f;
    nl::Link drop = map.link(8.1f, 6.9f, nl::LinkKind::Drop, true, declared);
    drop.bidirectional = true;
    const nl::Handle drop_id = map.world->add_link(map.navmesh, drop);

    nl::PathQuery def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = false;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);  // a walker
    def.capabilities.max_jump_distance = 1.0f;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);  // the gap is 1.2 m
    def.capabilities.max_jump_distance = 1.5f;
    Path p = find(map, def);
    INFO(p.describe());
    REQUIRE(p.result.outcome == nl::PathOutcome::Complete);
    REQUIRE(p.result.points.size() == 4);
    CHECK(p.result.links_used == 1);
    CHECK(p.result.points[1].segment == uint32_t(nl::LinkKind::Jump));
    CHECK(p.result.points[1].link.index1 == jump_id.index1);
    CHECK(p.result.points[1].link.revision == jump_id.revision);
    CHECK_FALSE(p.result.points[1].reversed);
    check_point(p.result.points[1], 2.9f, 0.5f);
    check_point(p.result.points[2], 4.1f, 0.5f);
    CHECK(p.result.points[2].segment == nl::kSegmentWalk);

    // Back the other way over the bidirectional link.
    p = find(map, map.request(5.5f, 0.5f, 0.5f, 0.5f));
    CHECK(p.result.outcome == nl::PathOutcome::Partial);  // a walker again
    def = map.request(5.5f, 0.5f, 0.5f, 0.5f);
    def.capabilities.max_jump_distance = 1.5f;
    p = find(map, def);
    REQUIRE(p.result.points.size() == 4);
    CHECK(p.result.points[1].reversed);
    check_point(p.result.points[1], 4.1f, 0.5f);

    // Down the drop needs only the drop height; back up it is a jump of 2 m rise.
    def = map.request(9.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = false;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
    def.capabilities.max_drop_height = 2.0f;
    p = find(map, def);
    INFO(p.describe());
    REQUIRE(p.result.outcome == nl::PathOutcome::Complete);
    CHECK(p.result.points[1].segment == uint32_t(nl::LinkKind::Drop));
    def = map.request(5.5f, 0.5f, 9.5f, 0.5f);
    def.accept_partial = false;
    def.capabilities.max_drop_height = 2.0f;
    def.capabilities.max_jump_distance = 1.0f;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
    def.capabilities.max_jump_height = 2.0f;
    p = find(map, def);
    REQUIRE(p.result.outcome == nl::PathOutcome::Complete);
    CHECK(p.result.points[1].segment == uint32_t(nl::LinkKind::Jump));  // a drop climbed back is a jump
    CHECK(p.result.points[1].reversed);
    CHECK(p.result.points[1].link.index1 == drop_id.index1);

    // A disabled link is not used; a costly one still is when it is the only way.
    nl::Link disabled = jump;
    disabled.enabled = false;
    map.world->update_link(jump_id, disabled);
    def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.capabilities.max_jump_distance = 1.5f;
    def.accept_partial = false;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
    nl::Link costly = jump;
    costly.cost_modifier = 50.0f;
    map.world->update_link(jump_id, costly);
    def.link_cost = 7.0f;
    p = find(map, def);
    REQUIRE(p.result.outcome == nl::PathOutcome::Complete);
    // Walk 2.4 m, jump 1.2 m at 50 times the cost, plus the cost of taking a link, walk 1.4 m.
    CHECK(p.result.cost == doctest::Approx(2.4f + 1.2f * 50.0f + 7.0f + 1.4f).epsilon(1e-3));
}

TEST_CASE("a manual link may ask only for an ability: requirements taken as given, not from its ends") {
    CellMap map({"...#..."});
    nl::LinkRequirements ability;
    ability.abilities = 0x2;
    const nl::LinkKind ladder_kind = static_cast<nl::LinkKind>(uint32_t(nl::LinkKind::FirstPluginKind) + 1);
    nl::Link ladder = map.link(2.9f, 4.1f, ladder_kind, true, ability);
    const nl::Handle id = map.world->add_link(map.navmesh, ladder);
    // The world keeps it as given (that nl_link_add measures a length left 0: abi.links.manual).
    const auto links = map.world->navmeshes().links(map.navmesh);
    const nl::Link got = links->front().link;
    CHECK(got.requirements.gap == 0.0f);
    CHECK(got.requirements.length == doctest::Approx(1.2f));  // measured: it was left 0

    nl::PathQuery def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = false;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);  // no ability
    def.capabilities.abilities = 0x2;                                 // and no jump at all
    CHECK(find(map, def).result.outcome == nl::PathOutcome::Complete);

    // The same link measured from its ends asks for a 1.2 m jump as well.
    ladder = map.link(2.9f, 4.1f, ladder_kind, false, ability);
    map.world->update_link(id, ladder);
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
    def.capabilities.max_jump_distance = 1.2f;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::Complete);
}

TEST_CASE("ability bits and clearance width filter links") {
    CellMap map({"...#..."});
    nl::LinkRequirements needs;
    needs.gap = 0.0f;
    needs.rise = 0.0f;
    needs.drop = 0.0f;
    needs.abilities = 0x4;
    needs.clearance_width = 1.0f;
    // Not as given (nl_link_def's default): gap, rise and drop measured from the ends.
    map.world->add_link(
        map.navmesh,
        map.link(2.9f, 4.1f, static_cast<nl::LinkKind>(uint32_t(nl::LinkKind::FirstPluginKind) + 5), false, needs));
    nl::PathQuery def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = false;
    def.capabilities.max_jump_distance = 2.0f;  // the gap is computed from the ends: 1.2 m
    def.capabilities.radius = 0.3f;
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
    def.capabilities.abilities = 0x5;
    const Path p = find(map, def);
    REQUIRE(p.result.outcome == nl::PathOutcome::Complete);
    CHECK(p.result.points[1].segment == uint32_t(nl::LinkKind::FirstPluginKind) + 5);
    def.capabilities.radius = 0.6f;  // 1.2 m wide body, link measured clear for 1.0 m
    CHECK(find(map, def).result.outcome == nl::PathOutcome::NoPath);
}
