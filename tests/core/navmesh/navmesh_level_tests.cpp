// Navmeshes of the shared levels, end to end through the core world: built with the Recast plugin, and
// handed over by a "host" as Unity would (triangles with repeated vertices). Both must pass the
// structural checks, and point location must agree with the brute-force search.
#include <doctest/doctest.h>

#include <chrono>
#include <random>

#include "core_errors.h"
#include "core_world.h"
#include "navmesh_checks.h"
#include "shared_levels.h"

namespace {

void check_point_location(const nl::NavMesh& mesh, const std::string& label) {
    std::mt19937 rng(5);
    const nl::Aabb& b = mesh.bounds();
    std::uniform_real_distribution<float> ux(b.min.x() - 2, b.max.x() + 2), uy(b.min.y() - 2, b.max.y() + 2),
        uz(b.min.z() - 2, b.max.z() + 2), extent(0.3f, 3.0f);
    int found = 0, differ = 0;
    for (int i = 0; i < 4000; ++i) {
        const nl::Vec3 p(ux(rng), uy(rng), uz(rng));
        const nl::Vec3 h(extent(rng), extent(rng), extent(rng));
        const nl::NavPoint fast = mesh.find_nearest(p, h), slow = mesh.find_nearest_brute_force(p, h);
        found += fast.found;
        differ += fast.found != slow.found || fast.polygon != slow.polygon || fast.point != slow.point;
    }
    INFO(label);
    CHECK(found > 200);
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("every shared level: Recast-built and host-provided navmeshes are sound; location matches brute force") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty()) {
        if (nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir().string());
        return;
    }
    for (const auto& path : levels) {
        const std::string name = path.stem().string();
        INFO(name);
        const auto world = nl::test::make_world();
        nl::test::add_obj_file(*world, path);

        const auto start = std::chrono::steady_clock::now();
        const nl::Handle built = nl::test::build_recast_navmesh(*world);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const auto recast = world->navmeshes().navmesh(built);
        CHECK(nl::test::check_navmesh(*recast) == "");
        MESSAGE(name, ": recast ", recast->polygon_count(), " polygons, ", recast->boundary_edges().size(),
                " boundary edges, ", recast->portal_count(), " portals, built in ", ms, " ms");
        check_point_location(*recast, name + " recast");

        // The same polygons handed over as a Unity host would: fan triangles, every vertex repeated.
        // (nl_default_navmesh_def's agent and weld tolerance: NavMeshInput's defaults.)
        nl::NavMeshInput soup;
        for (uint32_t p = 0; p < recast->polygon_count(); ++p) {
            for (uint32_t k = 1; k + 1 < recast->corner_count(p); ++k) {
                for (uint32_t c : {0u, k, k + 1}) {
                    soup.indices.push_back(static_cast<uint32_t>(soup.vertices.size()));
                    soup.vertices.push_back(recast->vertex(recast->corner(p, c)));
                }
            }
        }
        const nl::Handle hosted = world->add_navmesh(soup);
        const auto host = world->navmeshes().navmesh(hosted);
        CHECK(nl::test::check_navmesh(*host) == "");
        // Welding restores the shared vertices, so the outline is the same as Recast's.
        CHECK(host->boundary_edges().size() == recast->boundary_edges().size());
        CHECK(host->vertex_count() == recast->vertex_count());
        check_point_location(*host, name + " host");
    }
}

TEST_CASE("a level with no walkable surface is a clear failure, not an empty navmesh") {
    // Through the C ABI (NL_STATUS_NOT_FOUND, the message, no navmesh, out_id untouched):
    // abi.navmesh_build.recast.
    const auto world = nl::test::make_world();
    nl::TriangleMesh wall;
    wall.vertices = {nl::Vec3(0, 0, 0), nl::Vec3(0, 3, 0), nl::Vec3(4, 3, 0), nl::Vec3(4, 0, 0)};
    wall.triangles = {{0, 1, 2}, {0, 2, 3}};
    world->level().add_mesh(wall, nl::Transform::Identity(), 0, 0);
    std::string message;
    CHECK(nl::test::code_of([&] { nl::test::build_recast_navmesh(*world); }, &message) == nl::ErrorCode::NotFound);
    CHECK(message.find("walkable") != std::string::npos);
    CHECK(world->navmeshes().handles().empty());
}
