// Tiles in and out of a tiled navmesh at run time (World::add_tile, World::remove_tile), each one step
// for everything else. What must hold: tiles loaded again in any order give the navmesh they made
// before, bit for bit; a path graph taken before a change still answers; a link with an end on a removed
// tile is out of every path until the tile is back; an agent on a removed tile waits with a reason and
// goes on when it is back; bad requests change nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "core_errors.h"
#include "core_world.h"
#include "level_generator.h"
#include "path/path_planner.h"

using nl::Vec3;

namespace {

// A floor 60 x 12 m in tiles of 32 cells (9.6 m): seven columns, two rows.
struct Corridor {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    nl::Handle navmesh;

    Corridor() {
        nl::levelgen::GeneratedLevel floor;
        floor.add_box(nl::levelgen::Box{{0.0f, -1.0f, 0.0f}, {60.0f, 0.0f, 12.0f}});
        nl::test::add_level(*world, floor);
        navmesh = nl::test::build_recast_navmesh(*world, nl::AgentType{}, "{\"tile_size\": 32}");
    }
    std::shared_ptr<const nl::NavMesh> mesh() const { return world->navmeshes().navmesh(navmesh); }
    nl::TileCoord tile_at(float x, float z) const { return mesh()->tiles().grid.tile_at(x, z); }
    nl::PathResult plan(const Vec3& start, const Vec3& goal) const {
        nl::PathQuery query;
        query.start = start;
        query.goal = goal;
        nl::PathResult result;
        const auto graph = world->navmeshes().path_graph(navmesh);
        nl::plan_path(*graph, query, nullptr, result);
        return result;
    }
};

bool has_event(const nl::World& world, nl::AgentEventKind kind, nl::AgentReason reason) {
    const auto events = world.agents().events();
    return std::any_of(events.begin(), events.end(),
                       [&](const nl::AgentEvent& e) { return e.kind == kind && e.reason == reason; });
}

}  // namespace

TEST_CASE("tiles removed and added again in any order give the navmesh they made, bit for bit") {
    Corridor c;
    const auto whole = c.mesh();
    const nl::TileInputs tiles = c.world->navmeshes().tile_inputs(c.navmesh);
    REQUIRE(tiles.size() == 14);
    std::mt19937 random(5);
    for (int round = 0; round < 3; ++round) {
        // Half the tiles out, in a random order, then back in another.
        std::vector<nl::TileCoord> out;
        for (const auto& t : tiles) out.push_back(t->tiles.tiles.front());
        std::shuffle(out.begin(), out.end(), random);
        out.resize(7);
        for (const nl::TileCoord& t : out) c.world->remove_tile(c.navmesh, t);
        CHECK(c.mesh()->tiles().tiles.size() == 7);
        std::shuffle(out.begin(), out.end(), random);
        for (const nl::TileCoord& t : out) {
            const auto input =
                std::find_if(tiles.begin(), tiles.end(), [&](const auto& i) { return i->tiles.tiles.front() == t; });
            c.world->add_tile(c.navmesh, **input);
        }
        CHECK(nl::test::same_navmesh(*c.mesh(), *whole));
    }
}

TEST_CASE("a removed tile cuts the paths through it; a graph taken before answers as before") {
    Corridor c;
    const auto before = c.world->navmeshes().path_graph(c.navmesh);
    const Vec3 start(3, 0, 6), goal(57, 0, 6);
    REQUIRE(c.plan(start, goal).outcome == nl::PathOutcome::Complete);
    const nl::TileCoord middle = c.tile_at(30, 6);
    const nl::TileCoord middle_other_row = c.tile_at(30, 11);
    c.world->remove_tile(c.navmesh, middle);
    CHECK(c.plan(start, goal).outcome == nl::PathOutcome::Complete);  // round through the other row
    c.world->remove_tile(c.navmesh, middle_other_row);
    CHECK(c.plan(start, goal).outcome != nl::PathOutcome::Complete);
    // A request that started before the change finishes on the navmesh it started on.
    nl::PathQuery query;
    query.start = start;
    query.goal = goal;
    nl::PathResult result;
    nl::plan_path(*before, query, nullptr, result);
    CHECK(result.outcome == nl::PathOutcome::Complete);
}

TEST_CASE("a tile change builds the new navmesh's path graph when paths were asked for, and none otherwise") {
    Corridor searched, never;
    searched.plan(Vec3(3, 0, 6), Vec3(57, 0, 6));
    REQUIRE(searched.world->navmeshes().has_path_graph(searched.navmesh));
    REQUIRE(!never.world->navmeshes().has_path_graph(never.navmesh));
    for (Corridor* c : {&searched, &never}) c->world->remove_tile(c->navmesh, c->tile_at(30, 6));
    // Ready for the next request, on the navmesh the change published (the graph before it went with it).
    CHECK(searched.world->navmeshes().has_path_graph(searched.navmesh));
    const auto graph = searched.world->navmeshes().path_graph(searched.navmesh);
    CHECK(graph->navmesh_ptr() == searched.mesh());
    CHECK(!never.world->navmeshes().has_path_graph(never.navmesh));
    for (Corridor* c : {&searched, &never}) c->world->remove_tile(c->navmesh, c->tile_at(40, 6));
    const auto again = searched.world->navmeshes().path_graph(searched.navmesh);
    CHECK(again->navmesh_ptr() == searched.mesh());
    CHECK(!never.world->navmeshes().has_path_graph(never.navmesh));
}

TEST_CASE("a link with an end on a removed tile is out of every path until the tile is back") {
    Corridor c;
    // A link from one end of the floor to the other, cheaper than walking.
    nl::Link link;
    link.kind = nl::LinkKind::Jump;
    link.start = Vec3(3, 0, 6);
    link.end = Vec3(57, 0, 6);
    link.apex = Vec3(30, 2, 6);
    link.cost_modifier = 0.1f;
    nl::settle_host_requirements(link, true);
    c.world->add_link(c.navmesh, link);
    auto uses_link = [&] {
        nl::PathQuery query;
        query.start = Vec3(3, 0, 5);
        query.goal = Vec3(57, 0, 5);
        query.capabilities.max_jump_distance = 100.0f;
        query.capabilities.max_jump_height = 10.0f;
        query.capabilities.max_drop_height = 10.0f;
        nl::PathResult result;
        const auto graph = c.world->navmeshes().path_graph(c.navmesh);
        nl::plan_path(*graph, query, nullptr, result);
        return result.outcome == nl::PathOutcome::Complete && result.links_used == 1;
    };
    REQUIRE(uses_link());
    const nl::TileCoord landing = c.tile_at(57, 6);
    const nl::TileInputs tiles = c.world->navmeshes().tile_inputs(c.navmesh);
    const auto landing_tile =
        *std::find_if(tiles.begin(), tiles.end(), [&](const auto& t) { return t->tiles.tiles.front() == landing; });
    c.world->remove_tile(c.navmesh, landing);
    CHECK_FALSE(uses_link());
    CHECK(nl::test::links_of(*c.world, c.navmesh).size() == 1);  // kept, parked
    c.world->add_tile(c.navmesh, *landing_tile);
    CHECK(uses_link());
}

TEST_CASE("an agent on a removed tile waits with a reason, and walks on when the tile is back") {
    Corridor c;
    nl::AgentDef def;
    def.navmesh = c.navmesh;
    def.position = Vec3(5, 0, 6);
    const nl::Handle agent = c.world->add_agent(def);
    c.world->agents().set_destination(c.world->navmeshes(), agent, Vec3(55, 0, 6));
    for (int i = 0; i < 10; ++i) c.world->step(0.1f);
    const nl::TileCoord under = c.tile_at(c.world->agents().info(agent).position.x(), 6);
    const nl::TileInputs tiles = c.world->navmeshes().tile_inputs(c.navmesh);
    const auto its_tile =
        *std::find_if(tiles.begin(), tiles.end(), [&](const auto& t) { return t->tiles.tiles.front() == under; });
    c.world->remove_tile(c.navmesh, under);
    c.world->step(0.1f);
    CHECK(has_event(*c.world, nl::AgentEventKind::Waiting, nl::AgentReason::TileUnloaded));
    const Vec3 stood = c.world->agents().info(agent).position;
    for (int i = 0; i < 20; ++i) c.world->step(0.1f);
    const nl::AgentInfo waiting = c.world->agents().info(agent);
    CHECK(waiting.state == nl::AgentState::Waiting);
    CHECK(waiting.reason == nl::AgentReason::TileUnloaded);
    CHECK((waiting.position - stood).norm() < 1e-4f);
    c.world->add_tile(c.navmesh, *its_tile);
    c.world->step(0.1f);
    CHECK(has_event(*c.world, nl::AgentEventKind::Replanned, nl::AgentReason::WorldChanged));
    bool arrived = false;
    for (int i = 0; i < 400 && !arrived; ++i) {
        c.world->step(0.1f);
        arrived = c.world->agents().info(agent).state == nl::AgentState::Arrived;
    }
    CHECK(arrived);
}

TEST_CASE("an agent whose path crosses a removed tile plans again; agents elsewhere keep walking") {
    Corridor c;
    nl::AgentDef def;
    def.navmesh = c.navmesh;
    def.position = Vec3(5, 0, 3);
    const nl::Handle crossing = c.world->add_agent(def);
    c.world->agents().set_destination(c.world->navmeshes(), crossing, Vec3(55, 0, 3));
    for (int i = 0; i < 5; ++i) c.world->step(0.1f);
    c.world->remove_tile(c.navmesh, c.tile_at(30, 3));
    c.world->step(0.1f);
    CHECK(has_event(*c.world, nl::AgentEventKind::Replanned, nl::AgentReason::WorldChanged));
    bool arrived = false;
    for (int i = 0; i < 400 && !arrived; ++i) {
        c.world->step(0.1f);
        arrived = c.world->agents().info(crossing).state == nl::AgentState::Arrived;
    }
    CHECK(arrived);  // round through the other row
}

TEST_CASE("an agent whose path keeps off the changed tiles keeps its path; one over them plans again") {
    Corridor c;
    nl::AgentDef def;
    def.navmesh = c.navmesh;
    def.position = Vec3(3, 0, 3);
    const nl::Handle west = c.world->add_agent(def);  // along the first row, in the three western tiles
    c.world->agents().set_destination(c.world->navmeshes(), west, Vec3(25, 0, 3));
    def.position = Vec3(35, 0, 3);
    const nl::Handle east = c.world->add_agent(def);  // along the first row, to the eastern end
    c.world->agents().set_destination(c.world->navmeshes(), east, Vec3(58, 0, 3));
    for (int i = 0; i < 5; ++i) c.world->step(0.1f);
    auto replanned = [&](nl::Handle agent) {
        const auto events = c.world->agents().events();
        return std::any_of(events.begin(), events.end(), [&](const nl::AgentEvent& e) {
            return e.agent == agent && e.kind == nl::AgentEventKind::Replanned;
        });
    };
    // A tile on the east agent's way (it goes round through the other row), far from the west's.
    c.world->remove_tile(c.navmesh, c.tile_at(50, 3));
    c.world->step(0.1f);
    CHECK_FALSE(replanned(west));
    CHECK(replanned(east));
    bool arrived = false;
    for (int i = 0; i < 400 && !arrived; ++i) {
        c.world->step(0.1f);
        CHECK_FALSE(replanned(west));
        arrived = c.world->agents().info(west).state == nl::AgentState::Arrived &&
                  c.world->agents().info(east).state == nl::AgentState::Arrived;
    }
    CHECK(arrived);
}

TEST_CASE("tile requests that cannot be met are refused and change nothing") {
    Corridor c;
    const auto before = c.mesh();
    const nl::TileInputs tiles = c.world->navmeshes().tile_inputs(c.navmesh);
    // Added twice.
    std::string message;
    CHECK(nl::test::code_of([&] { c.world->add_tile(c.navmesh, *tiles.front()); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("loaded already") != std::string::npos);
    // Removed twice.
    const nl::TileCoord first = tiles.front()->tiles.tiles.front();
    c.world->remove_tile(c.navmesh, first);
    CHECK(nl::test::code_of([&] { c.world->remove_tile(c.navmesh, first); }, &message) == nl::ErrorCode::NotFound);
    c.world->add_tile(c.navmesh, *tiles.front());
    CHECK(nl::test::same_navmesh(*c.mesh(), *before));
    // Another grid, another body.
    nl::NavMeshInput shifted = *tiles[1];
    shifted.tiles.grid.origin_x += 0.5f;
    c.world->remove_tile(c.navmesh, tiles[1]->tiles.tiles.front());
    CHECK(nl::test::code_of([&] { c.world->add_tile(c.navmesh, shifted); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("another grid") != std::string::npos);
    nl::NavMeshInput wider = *tiles[1];
    wider.agent_type.radius = 1.0f;
    CHECK(nl::test::code_of([&] { c.world->add_tile(c.navmesh, wider); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("another agent type") != std::string::npos);
    c.world->add_tile(c.navmesh, *tiles[1]);
    CHECK(nl::test::same_navmesh(*c.mesh(), *before));
    // The last tile; a solo navmesh; a removed navmesh.
    for (size_t t = 1; t < tiles.size(); ++t) c.world->remove_tile(c.navmesh, tiles[t]->tiles.tiles.front());
    CHECK(nl::test::code_of([&] { c.world->remove_tile(c.navmesh, first); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("last") != std::string::npos);
    const nl::Handle solo = nl::test::build_recast_navmesh(*c.world);
    CHECK(nl::test::code_of([&] { c.world->remove_tile(solo, first); }, &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("not tiled") != std::string::npos);
    c.world->navmeshes().remove(c.navmesh);
    CHECK(nl::test::code_of([&] { c.world->add_tile(c.navmesh, *tiles[1]); }) == nl::ErrorCode::InvalidHandle);
}

namespace {

nl::NavMeshBuildRequest tiles_request(const std::string& json) {
    nl::NavMeshBuildRequest request;
    request.builder = "recast";
    request.settings_json = json.c_str();  // borrowed: the caller keeps `json`
    request.settings_json_length = json.size();
    return request;
}

nl::Aabb box_xz(float x0, float z0, float x1, float z1) {
    nl::Aabb box;
    box.min = Vec3(x0, -10, z0);
    box.max = Vec3(x1, 10, z1);
    return box;
}

}  // namespace

TEST_CASE("tiles built again in a box: the same tiles from the same level, the box's alone from a changed one") {
    Corridor c;
    const auto whole = c.mesh();
    const nl::TileInputs before = c.world->navmeshes().tile_inputs(c.navmesh);
    const std::string json = "{\"tile_size\": 32}";
    // A tile removed and built again: the navmesh it made.
    const nl::TileCoord t = c.tile_at(30, 3);
    c.world->remove_tile(c.navmesh, t);
    c.world->build_tiles(c.navmesh, tiles_request(json), box_xz(30, 3, 30, 3));
    CHECK(nl::test::same_navmesh(*c.mesh(), *whole));

    // A wall across the corridor in that tile: only the tiles its box reaches are built again.
    nl::levelgen::GeneratedLevel wall;
    wall.add_box(nl::levelgen::Box{{30.0f, 0.0f, 0.0f}, {31.0f, 3.0f, 12.0f}});
    nl::test::add_level(*c.world, wall);
    c.world->build_tiles(c.navmesh, tiles_request(json), box_xz(30, 0, 31, 12));
    const nl::TileInputs after = c.world->navmeshes().tile_inputs(c.navmesh);
    REQUIRE(after.size() == before.size());
    int rebuilt = 0;
    for (size_t i = 0; i < after.size(); ++i) rebuilt += after[i] != before[i] ? 1 : 0;
    CHECK(rebuilt == 2);  // the column the wall stands in, both rows
    CHECK(c.plan(Vec3(3, 0, 6), Vec3(57, 0, 6)).outcome != nl::PathOutcome::Complete);

    // A box over nothing builds no tile and changes nothing.
    const auto walled = c.mesh();
    c.world->build_tiles(c.navmesh, tiles_request(json), box_xz(200, 200, 210, 210));
    CHECK(c.mesh() == walled);
}

TEST_CASE("tiles built with other settings or for another body are refused") {
    Corridor c;
    const auto before = c.mesh();
    std::string message;
    CHECK(nl::test::code_of(
              [&] { c.world->build_tiles(c.navmesh, tiles_request("{\"tile_size\": 64}"), box_xz(0, 0, 5, 5)); },
              &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("makes tiles of") != std::string::npos);
    CHECK(nl::test::code_of([&] { c.world->build_tiles(c.navmesh, tiles_request("{}"), box_xz(0, 0, 5, 5)); },
                            &message) == nl::ErrorCode::InvalidArgument);
    CHECK(message.find("tile_size is 0") != std::string::npos);
    nl::NavMeshBuildRequest wider = tiles_request("{\"tile_size\": 32}");
    const std::string keep = "{\"tile_size\": 32}";
    wider.settings_json = keep.c_str();
    wider.agent_type.radius = 1.0f;
    CHECK(nl::test::code_of([&] { c.world->build_tiles(c.navmesh, wider, box_xz(0, 0, 5, 5)); }, &message) ==
          nl::ErrorCode::InvalidArgument);
    CHECK(message.find("agent type") != std::string::npos);
    CHECK(c.mesh() == before);
}

TEST_CASE("a host's tiled navmesh grown from one tile and back is the navmesh its first tile made") {
    // Two 4 m tiles of one quad each, at slightly different heights (joined within the climb).
    auto quad_tile = [](int32_t x, float y) {
        nl::NavMeshInput in;
        in.tiles.grid = nl::TileGrid{0.0f, 0.0f, 4.0f};
        in.tiles.tiles.push_back(nl::TileCoord{x, 0});
        const float x0 = 4.0f * float(x);
        in.vertices = {Vec3(x0, y, 0), Vec3(x0, y, 4), Vec3(x0 + 4, y, 4), Vec3(x0 + 4, y, 0)};
        in.indices = {0, 1, 2, 3};
        in.polygon_sizes = {4};
        return in;
    };
    auto world = nl::test::make_world(1);
    const nl::Handle navmesh = world->add_navmesh(quad_tile(0, 0.0f));
    const auto alone = world->navmeshes().navmesh(navmesh);
    CHECK(alone->tiles().tiles.size() == 1);
    world->add_tile(navmesh, quad_tile(1, 0.2f));
    const auto grown = world->navmeshes().navmesh(navmesh);
    CHECK(grown->portal_count() == 1);
    world->remove_tile(navmesh, nl::TileCoord{1, 0});
    const auto back = world->navmeshes().navmesh(navmesh);
    CHECK(nl::test::same_navmesh(*back, *alone));
}
