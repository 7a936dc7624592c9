// Path search and string pulling on host navmeshes drawn as cell maps, where the right path is
// known exactly: straight runs, turns round corners, agent radius, areas, islands, links.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <cmath>
#include <string>
#include <vector>

#include "cell_navmesh.h"

namespace {

// A world holding one cell-map navmesh (cell_navmesh.h).
struct CellMap {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};

    explicit CellMap(const std::vector<std::string>& rows, float agent_radius = 0.0f, int path_workers = 0) {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        def.path_worker_count = path_workers;
        REQUIRE(nl_world_create(&def, &world) == NL_STATUS_SUCCESS);
        const nl::test::CellNavmesh cells(rows, agent_radius);
        REQUIRE_MESSAGE(nl_navmesh_add(world, &cells.def, &navmesh) == NL_STATUS_SUCCESS, nl_get_last_error_message());
    }
    ~CellMap() { nl_world_destroy(world); }

    nl_path_request_def request(float sx, float sz, float gx, float gz) const {
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = navmesh;
        def.start[0] = sx, def.start[2] = sz;
        def.goal[0] = gx, def.goal[2] = gz;
        def.agent.radius = 0.0f;  // as thin as the navmesh assumes: no margin
        return def;
    }
};

struct Path {
    nl_status status = 0;
    nl_path_result result{};
    std::vector<nl_path_point> points;

    std::string describe() const {
        std::string s = "outcome " + std::to_string(result.outcome) + ", length " + std::to_string(result.length) + ":";
        for (const nl_path_point& p : points)
            s += " (" + std::to_string(p.position[0]) + ", " + std::to_string(p.position[1]) + ", " +
                 std::to_string(p.position[2]) + ")" + (p.segment ? "[link " + std::to_string(p.segment) + "]" : "");
        return s;
    }
};

Path find(nl_world* world, const nl_path_request_def& def) {
    Path path;
    path.result.size = sizeof(nl_path_result);
    uint32_t count = 0;
    path.status = nl_path_find(world, &def, &path.result, nullptr, 0, &count);
    if (NL_FAILED(path.status)) return path;
    path.points.resize(count, nl_path_point_init());
    path.status = nl_path_find(world, &def, &path.result, path.points.data(), count, &count);
    return path;
}

void check_point(const nl_path_point& p, float x, float z) {
    CHECK(p.position[0] == doctest::Approx(x).epsilon(1e-4));
    CHECK(p.position[2] == doctest::Approx(z).epsilon(1e-4));
}

}  // namespace

TEST_CASE("a straight run is two points and its length") {
    CellMap map({"......"});
    const Path p = find(map.world, map.request(0.5f, 0.5f, 5.5f, 0.5f));
    INFO(p.describe());
    REQUIRE(p.status == NL_STATUS_SUCCESS);
    CHECK(p.result.outcome == NL_PATH_COMPLETE);
    REQUIRE(p.points.size() == 2);
    check_point(p.points[0], 0.5f, 0.5f);
    check_point(p.points[1], 5.5f, 0.5f);
    CHECK(p.result.length == doctest::Approx(5.0f));
    CHECK(p.result.cost == doctest::Approx(5.0f));
    CHECK(p.points[0].segment == NL_SEGMENT_WALK);
    CHECK(p.points[0].link.index1 == 0);

    // 1 m wide, for a body 1.2 m wide: no way through.
    nl_path_request_def wide = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    wide.agent.radius = 0.6f;
    wide.accept_partial = 0;
    CHECK(find(map.world, wide).result.outcome == NL_PATH_NO_PATH);
}

TEST_CASE("a U-turn bends at the two inner corners, and a wider agent keeps its distance from them") {
    CellMap map({".....", "####.", "....."});
    const float turn = 2.0f * std::sqrt(3.5f * 3.5f + 0.5f * 0.5f);
    {
        const Path p = find(map.world, map.request(0.5f, 0.5f, 0.5f, 2.5f));
        INFO(p.describe());
        REQUIRE(p.points.size() == 4);
        check_point(p.points[1], 4.0f, 1.0f);
        check_point(p.points[2], 4.0f, 2.0f);
        CHECK(p.result.length == doctest::Approx(turn + 1.0f));
        CHECK(p.points[1].polygon != p.points[0].polygon);
    }
    {
        // The navmesh was made for radius 0: a 0.25 m body crosses each portal 0.25 m from the
        // outline, so it rounds the corners on a chamfer.
        nl_path_request_def def = map.request(0.5f, 0.5f, 0.5f, 2.5f);
        def.agent.radius = 0.25f;
        const Path p = find(map.world, def);
        INFO(p.describe());
        REQUIRE(p.points.size() == 6);
        check_point(p.points[1], 4.0f, 0.75f);
        check_point(p.points[2], 4.25f, 1.0f);
        check_point(p.points[3], 4.25f, 2.0f);
        check_point(p.points[4], 4.0f, 2.25f);
    }
    {
        // The same navmesh declared as made for radius 0.25: a 0.25 agent fits it as it is.
        CellMap eroded({".....", "####.", "....."}, 0.25f);
        nl_path_request_def def = eroded.request(0.5f, 0.5f, 0.5f, 2.5f);
        def.agent.radius = 0.25f;
        const Path p = find(eroded.world, def);
        REQUIRE(p.points.size() == 4);
        check_point(p.points[1], 4.0f, 1.0f);
    }
}

TEST_CASE("a wide agent takes the long way round a corridor narrower than its body") {
    // The direct way, through column 4 of rows 2-4, is 1 m wide; the way round, columns 8-9, is 2 m.
    CellMap map({"..........", "..........", "####.###..", "####.###..", "####.###..", "..........", ".........."});
    nl_path_request_def def = map.request(4.5f, 1.0f, 4.5f, 6.0f);
    def.agent.radius = 0.4f;
    const Path narrow = find(map.world, def);
    INFO(narrow.describe());
    REQUIRE(narrow.result.outcome == NL_PATH_COMPLETE);
    CHECK(narrow.points.size() == 2);
    CHECK(narrow.result.length == doctest::Approx(5.0f));

    def.agent.radius = 0.6f;
    const Path wide = find(map.world, def);
    INFO(wide.describe());
    REQUIRE(wide.result.outcome == NL_PATH_COMPLETE);
    CHECK(wide.result.length > 10.0f);
    for (const nl_path_point& p : wide.points) {
        if (p.position[2] > 2.0f && p.position[2] < 5.0f) CHECK(p.position[0] >= 8.6f - 1e-4f);
    }

    def.agent.radius = 1.1f;  // wider than any way through
    def.accept_partial = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
}

TEST_CASE("area costs steer the path and NL_AREA_EXCLUDED keeps it out") {
    // A shortcut of area 2 through the middle; the way round the wall is longer.
    CellMap map({".....", ".###.", "2222.", ".###.", "....."});
    nl_path_request_def def = map.request(0.5f, 0.5f, 0.5f, 4.5f);
    const Path through = find(map.world, def);
    INFO(through.describe());
    CHECK(through.result.length == doctest::Approx(4.0f));

    const float costs[3] = {1.0f, 1.0f, 10.0f};
    def.area_costs = costs;
    def.area_cost_count = 3;
    const Path expensive = find(map.world, def);
    INFO(expensive.describe());
    CHECK(expensive.result.length > 8.0f);
    CHECK(expensive.result.cost < 4.0f * 10.0f);

    const float excluded[3] = {1.0f, 1.0f, NL_AREA_EXCLUDED};
    def.area_costs = excluded;
    const Path avoided = find(map.world, def);
    CHECK(avoided.result.length > 8.0f);
    for (const nl_path_point& p : avoided.points) CHECK_FALSE((p.position[2] > 2.0f && p.position[2] < 3.0f && p.position[0] < 4.0f));
}

TEST_CASE("an unreachable goal gives a partial path to the nearest reachable point, or no path") {
    CellMap map({"...#...."});
    nl_path_request_def def = map.request(0.5f, 0.5f, 6.5f, 0.5f);
    const Path partial = find(map.world, def);
    INFO(partial.describe());
    CHECK(partial.status == (NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(partial.result.outcome == NL_PATH_PARTIAL);
    REQUIRE(partial.points.size() == 2);
    check_point(partial.points.back(), 3.0f, 0.5f);
    CHECK(partial.result.goal[0] == doctest::Approx(6.5f));

    def.accept_partial = 0;
    const Path none = find(map.world, def);
    CHECK(none.status == NL_STATUS_SUCCESS);
    CHECK(none.result.outcome == NL_PATH_NO_PATH);
    CHECK(none.points.empty());
}

TEST_CASE("ends that do not snap to the navmesh have their own outcomes") {
    CellMap map({"...."});
    CHECK(find(map.world, map.request(-10.0f, 0.5f, 3.5f, 0.5f)).result.outcome == NL_PATH_START_OFF_NAVMESH);
    CHECK(find(map.world, map.request(0.5f, 0.5f, 30.0f, 0.5f)).result.outcome == NL_PATH_GOAL_OFF_NAVMESH);
    nl_path_request_def def = map.request(0.5f, 0.5f, 3.5f, 0.5f);
    def.start[1] = 10.0f;  // above the default box of +-4 m
    CHECK(find(map.world, def).result.outcome == NL_PATH_START_OFF_NAVMESH);
    def.search_half_extents[1] = 20.0f;
    CHECK(find(map.world, def).result.outcome == NL_PATH_COMPLETE);
}

TEST_CASE("max_nodes bounds the search") {
    CellMap map({"....................", "...................."});
    nl_path_request_def def = map.request(0.5f, 0.5f, 19.5f, 1.5f);
    def.max_nodes = 5;
    const Path p = find(map.world, def);
    CHECK(p.result.outcome == NL_PATH_PARTIAL);
    CHECK(p.result.out_of_nodes == 1);
    CHECK(p.result.nodes_visited <= 5);
    def.max_nodes = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_COMPLETE);
}

TEST_CASE("links join islands for the agents whose bodies can take them") {
    CellMap map({"...#...#..."});
    nl_link_def jump = nl_default_link_def();
    jump.kind = NL_LINK_JUMP;
    jump.start[0] = 2.9f, jump.start[2] = 0.5f;
    jump.end[0] = 4.1f, jump.end[2] = 0.5f;
    jump.bidirectional = 1;
    nl_link_id jump_id{};
    REQUIRE(nl_link_add(map.world, map.navmesh, &jump, &jump_id) == NL_STATUS_SUCCESS);
    nl_link_def drop = nl_default_link_def();
    drop.kind = NL_LINK_DROP;
    drop.start[0] = 8.1f, drop.start[2] = 0.5f;  // declared as a drop of 2 m (the map is flat)
    drop.end[0] = 6.9f, drop.end[2] = 0.5f;
    drop.requirements_as_given = 1;
    drop.requirements.gap = 0.2f;
    drop.requirements.drop = 2.0f;
    drop.bidirectional = 1;
    nl_link_id drop_id{};
    REQUIRE(nl_link_add(map.world, map.navmesh, &drop, &drop_id) == NL_STATUS_SUCCESS);

    nl_path_request_def def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);  // a walker
    def.agent.max_jump_distance = 1.0f;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);  // the gap is 1.2 m
    def.agent.max_jump_distance = 1.5f;
    Path p = find(map.world, def);
    INFO(p.describe());
    REQUIRE(p.result.outcome == NL_PATH_COMPLETE);
    REQUIRE(p.points.size() == 4);
    CHECK(p.result.links_used == 1);
    CHECK(p.points[1].segment == NL_LINK_JUMP);
    CHECK(p.points[1].link.index1 == jump_id.index1);
    CHECK(p.points[1].link.generation == jump_id.generation);
    CHECK(p.points[1].reversed == 0);
    check_point(p.points[1], 2.9f, 0.5f);
    check_point(p.points[2], 4.1f, 0.5f);
    CHECK(p.points[2].segment == NL_SEGMENT_WALK);

    // Back the other way over the bidirectional link.
    p = find(map.world, map.request(5.5f, 0.5f, 0.5f, 0.5f));
    CHECK(p.result.outcome == NL_PATH_PARTIAL);  // a walker again
    def = map.request(5.5f, 0.5f, 0.5f, 0.5f);
    def.agent.max_jump_distance = 1.5f;
    p = find(map.world, def);
    REQUIRE(p.points.size() == 4);
    CHECK(p.points[1].reversed == 1);
    check_point(p.points[1], 4.1f, 0.5f);

    // Down the drop needs only the drop height; back up it is a jump of 2 m rise.
    def = map.request(9.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
    def.agent.max_drop_height = 2.0f;
    p = find(map.world, def);
    INFO(p.describe());
    REQUIRE(p.result.outcome == NL_PATH_COMPLETE);
    CHECK(p.points[1].segment == NL_LINK_DROP);
    def = map.request(5.5f, 0.5f, 9.5f, 0.5f);
    def.accept_partial = 0;
    def.agent.max_drop_height = 2.0f;
    def.agent.max_jump_distance = 1.0f;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
    def.agent.max_jump_height = 2.0f;
    p = find(map.world, def);
    REQUIRE(p.result.outcome == NL_PATH_COMPLETE);
    CHECK(p.points[1].segment == NL_LINK_JUMP);  // a drop climbed back is a jump
    CHECK(p.points[1].reversed == 1);
    CHECK(p.points[1].link.index1 == drop_id.index1);

    // A disabled link is not used; a costly one still is when it is the only way.
    nl_link_def disabled = jump;
    disabled.enabled = 0;
    REQUIRE(nl_link_update(map.world, jump_id, &disabled) == NL_STATUS_SUCCESS);
    def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.agent.max_jump_distance = 1.5f;
    def.accept_partial = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
    nl_link_def costly = jump;
    costly.cost_modifier = 50.0f;
    REQUIRE(nl_link_update(map.world, jump_id, &costly) == NL_STATUS_SUCCESS);
    def.link_cost = 7.0f;
    p = find(map.world, def);
    REQUIRE(p.result.outcome == NL_PATH_COMPLETE);
    // Walk 2.4 m, jump 1.2 m at 50 times the cost, plus the cost of taking a link, walk 1.4 m.
    CHECK(p.result.cost == doctest::Approx(2.4f + 1.2f * 50.0f + 7.0f + 1.4f).epsilon(1e-3));
}

TEST_CASE("a manual link may ask only for an ability: requirements taken as given, not from its ends") {
    CellMap map({"...#..."});
    nl_link_def ladder = nl_default_link_def();
    ladder.kind = NL_LINK_FIRST_PLUGIN_KIND + 1;
    ladder.start[0] = 2.9f, ladder.start[2] = 0.5f;
    ladder.end[0] = 4.1f, ladder.end[2] = 0.5f;
    ladder.requirements_as_given = 1;
    ladder.requirements.abilities = 0x2;
    nl_link_id id{};
    REQUIRE(nl_link_add(map.world, map.navmesh, &ladder, &id) == NL_STATUS_SUCCESS);
    nl_link got = nl_link_init();
    REQUIRE(nl_link_get(map.world, id, &got) == NL_STATUS_SUCCESS);
    CHECK(got.requirements.gap == 0.0f);
    CHECK(got.requirements.length == doctest::Approx(1.2f));  // measured: it was left 0

    nl_path_request_def def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = 0;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);  // no ability
    def.agent.abilities = 0x2;                                      // and no jump at all
    CHECK(find(map.world, def).result.outcome == NL_PATH_COMPLETE);

    // The same link measured from its ends asks for a 1.2 m jump as well.
    ladder.requirements_as_given = 0;
    REQUIRE(nl_link_update(map.world, id, &ladder) == NL_STATUS_SUCCESS);
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
    def.agent.max_jump_distance = 1.2f;
    CHECK(find(map.world, def).result.outcome == NL_PATH_COMPLETE);
}

TEST_CASE("ability bits and clearance width filter links") {
    CellMap map({"...#..."});
    nl_link_def climb = nl_default_link_def();
    climb.kind = NL_LINK_FIRST_PLUGIN_KIND + 5;
    climb.start[0] = 2.9f, climb.start[2] = 0.5f;
    climb.end[0] = 4.1f, climb.end[2] = 0.5f;
    climb.requirements.gap = 0.0f;
    climb.requirements.rise = 0.0f;
    climb.requirements.drop = 0.0f;
    climb.requirements.abilities = 0x4;
    climb.requirements.clearance_width = 1.0f;
    nl_link_id id{};
    REQUIRE(nl_link_add(map.world, map.navmesh, &climb, &id) == NL_STATUS_SUCCESS);
    nl_path_request_def def = map.request(0.5f, 0.5f, 5.5f, 0.5f);
    def.accept_partial = 0;
    def.agent.max_jump_distance = 2.0f;  // the gap is computed from the ends: 1.2 m
    def.agent.radius = 0.3f;
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
    def.agent.abilities = 0x5;
    const Path p = find(map.world, def);
    REQUIRE(p.result.outcome == NL_PATH_COMPLETE);
    CHECK(p.points[1].segment == NL_LINK_FIRST_PLUGIN_KIND + 5);
    def.agent.radius = 0.6f;  // 1.2 m wide body, link measured clear for 1.0 m
    CHECK(find(map.world, def).result.outcome == NL_PATH_NO_PATH);
}
