// Polygons that meet at T-junctions (a tile border, Unity's exported triangulation) are joined: the long
// edge gets the other side's corners, so the polygons connect and paths cross as if there were no border.
// What must not join: a corner off the edge's line or height, a weld tolerance of 0, a polygon with no
// room for the corners.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core_world.h"
#include "navmesh/navmesh_builder.h"
#include "navmesh/walk_graph.h"
#include "path/path_planner.h"

using nl::NavMeshInput;
using nl::Vec3;

namespace {

// Two "tiles" side by side: on the left one quad [0, 2] x [0, 2]; on the right `rows` quads of
// [2, 4] x [2k/rows, 2(k+1)/rows], their corners on x = 2 lying on the left quad's edge. The right side
// is `lift` m higher and its corners on x = 2 are `shift` m further along x.
NavMeshInput two_tiles(int rows, float lift = 0.0f, float shift = 0.0f) {
    NavMeshInput in;
    auto vertex = [&](float x, float y, float z) {
        in.vertices.push_back(Vec3(x, y, z));
        return static_cast<uint32_t>(in.vertices.size() - 1);
    };
    // Counter-clockwise seen from above (+y): x right, z down the picture.
    const uint32_t a = vertex(0, 0, 0), b = vertex(0, 0, 2), c = vertex(2, 0, 2), d = vertex(2, 0, 0);
    in.indices.insert(in.indices.end(), {a, b, c, d});
    in.polygon_sizes.push_back(4);
    for (int k = 0; k < rows; ++k) {
        const float z0 = 2.0f * k / rows, z1 = 2.0f * (k + 1) / rows;
        const uint32_t p = vertex(2 + shift, lift, z0), q = vertex(2 + shift, lift, z1), r = vertex(4, lift, z1),
                       s = vertex(4, lift, z0);
        in.indices.insert(in.indices.end(), {p, q, r, s});
        in.polygon_sizes.push_back(4);
    }
    in.weld_tolerance = 0.001f;
    return in;
}

// Whether every polygon is reached from polygon 0 through portals.
bool all_connected(const nl::NavMesh& navmesh) {
    const nl::WalkGraph walk(navmesh);
    for (uint32_t p = 1; p < navmesh.polygon_count(); ++p)
        if (walk.surface(p) != walk.surface(0)) return false;
    return true;
}

}  // namespace

TEST_CASE("a quad whose edge meets two quads at a T-junction connects to both, and paths cross it straight") {
    const NavMeshInput in = two_tiles(2);
    const auto navmesh = nl::build_navmesh(in);
    REQUIRE(navmesh->polygon_count() == 3);
    CHECK(navmesh->corner_count(0) == 5);  // the corner (2, 0, 1) joined its right edge
    CHECK(navmesh->repairs().t_junction_corners == 1);
    CHECK(navmesh->repairs().t_junctions_left == 0);
    CHECK(navmesh->portal_count() == 3);  // left-upper, left-lower, upper-lower
    CHECK(all_connected(*navmesh));

    // Before the join the same polygons were three islands: a weld tolerance of 0 takes them as given.
    NavMeshInput as_given = in;
    as_given.weld_tolerance = 0.0f;
    const auto unjoined = nl::build_navmesh(as_given);
    CHECK(unjoined->corner_count(0) == 4);
    CHECK(unjoined->portal_count() == 1);
    CHECK(!all_connected(*unjoined));

    // A path from the left quad to the far corner of the right side is one straight run: no detour at
    // the border, no partial path.
    auto world = nl::test::make_world(1);
    const nl::Handle id = world->add_navmesh(in);
    nl::PathQuery query;
    query.start = Vec3(0.5f, 0.0f, 0.5f);
    query.goal = Vec3(3.5f, 0.0f, 1.7f);
    query.capabilities.radius = 0.0f;
    query.accept_partial = false;
    nl::PathResult result;
    const auto graph = world->navmeshes().path_graph(id);
    nl::plan_path(*graph, query, nullptr, result);
    REQUIRE(result.outcome == nl::PathOutcome::Complete);
    CHECK(result.points.size() == 2);
    CHECK(result.length == doctest::Approx(std::hypot(3.0f, 1.2f)).epsilon(1e-4));
}

TEST_CASE("many rows meet one edge: every corner joins while the polygon has room, else the edge stays a wall") {
    // 12 rows put 11 corners on the left quad's edge: 4 + 11 = 15 corners, within the 16 allowed.
    const auto twelve = nl::build_navmesh(two_tiles(12));
    CHECK(twelve->corner_count(0) == 15);
    CHECK(twelve->repairs().t_junction_corners == 11);
    CHECK(all_connected(*twelve));

    // 14 rows would need 13 corners (17 in all): the edge is left as it was, and counted.
    const auto fourteen = nl::build_navmesh(two_tiles(14));
    CHECK(fourteen->corner_count(0) == 4);
    CHECK(fourteen->repairs().t_junction_corners == 0);
    CHECK(fourteen->repairs().t_junctions_left == 1);
    CHECK(!all_connected(*fourteen));
}

TEST_CASE("corners beside the edge's line or above its height do not join it") {
    // 5 mm higher, or 5 mm along x, with a 1 mm tolerance: a step and a gap, not a border.
    for (const std::pair<float, float>& off : {std::pair{0.005f, 0.0f}, std::pair{0.0f, 0.005f}}) {
        const float lift = off.first, shift = off.second;
        CAPTURE(lift);
        CAPTURE(shift);
        const auto navmesh = nl::build_navmesh(two_tiles(2, lift, shift));
        CHECK(navmesh->corner_count(0) == 4);
        CHECK(navmesh->repairs().t_junction_corners == 0);
        CHECK(!all_connected(*navmesh));
    }
    // Within the tolerance they join (the corner keeps its own height).
    const auto close = nl::build_navmesh(two_tiles(2, 0.0005f, 0.0f));
    CHECK(close->repairs().t_junction_corners == 1);
    CHECK(all_connected(*close));
}

TEST_CASE("a joined polygon's detail triangles still give its heights") {
    // The left quad with a detail mesh that raises its middle to y = 0.5: four triangles around a detail
    // vertex at its centre, over its four corners (which the join renumbers).
    NavMeshInput in = two_tiles(2);
    in.detail_vertices = {Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(2, 0, 2), Vec3(2, 0, 0), Vec3(1, 0.5f, 1)};
    in.detail_indices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    in.detail_starts = {0, 4};
    for (int k = 0; k < 2; ++k) {  // the right quads: flat, two triangles each over their own corners
        const uint32_t base = static_cast<uint32_t>(in.detail_vertices.size());
        const float z0 = float(k), z1 = float(k + 1);
        in.detail_vertices.insert(in.detail_vertices.end(),
                                  {Vec3(2, 0, z0), Vec3(2, 0, z1), Vec3(4, 0, z1), Vec3(4, 0, z0)});
        in.detail_indices.insert(in.detail_indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        in.detail_starts.push_back(in.detail_starts.back() + 2);
    }
    const auto navmesh = nl::build_navmesh(in);
    REQUIRE(navmesh->corner_count(0) == 5);
    CHECK(all_connected(*navmesh));
    const nl::NavPoint centre = navmesh->find_nearest(Vec3(1.0f, 0.4f, 1.0f), Vec3(0.1f, 1.0f, 0.1f));
    REQUIRE(centre.found);
    CHECK(centre.polygon == 0);
    CHECK(centre.point.y() == doctest::Approx(0.5f).epsilon(1e-3));
    const nl::NavPoint edge = navmesh->find_nearest(Vec3(1.5f, 0.3f, 1.0f), Vec3(0.1f, 1.0f, 0.1f));
    REQUIRE(edge.found);
    CHECK(edge.point.y() == doctest::Approx(0.25f).epsilon(1e-3));
}
