// Navmeshes of the shared levels, end to end through the C ABI: built with the Recast plugin, and
// handed over by a "host" as Unity would (triangles with repeated vertices). Both must pass the
// structural checks, and point location must agree with the brute-force search.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <chrono>
#include <random>

#include "navmesh_checks.h"
#include "shared_levels.h"
#include "world.h"

namespace {

std::shared_ptr<const nl::NavMesh> navmesh_of(nl_world* world, nl_navmesh_id id) {
    return world->core->navmeshes().navmesh(nl::Handle{id.index1, id.generation});
}

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
        nl_world* world = nullptr;
        REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
        nl_mesh_id level{};
        REQUIRE(nl_mesh_add_obj_file(world, path.c_str(), nullptr, &level) == NL_STATUS_SUCCESS);

        const nl_navmesh_build_def build = nl_default_navmesh_build_def();
        nl_navmesh_id built{};
        const auto start = std::chrono::steady_clock::now();
        const nl_status status = nl_navmesh_build(world, &build, &built);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        REQUIRE_MESSAGE(status == NL_STATUS_SUCCESS, nl_get_last_error_message());
        const auto recast = navmesh_of(world, built);
        CHECK(nl::test::check_navmesh(*recast) == "");
        MESSAGE(name, ": recast ", recast->polygon_count(), " polygons, ", recast->boundary_edges().size(),
                " boundary edges, ", recast->portal_count(), " portals, built in ", ms, " ms");
        check_point_location(*recast, name + " recast");

        // The same polygons handed over as a Unity host would: fan triangles, every vertex repeated.
        std::vector<float> soup;
        std::vector<uint32_t> indices;
        for (uint32_t p = 0; p < recast->polygon_count(); ++p) {
            for (uint32_t k = 1; k + 1 < recast->corner_count(p); ++k) {
                for (uint32_t c : {0u, k, k + 1}) {
                    const nl::Vec3& v = recast->vertex(recast->corner(p, c));
                    indices.push_back(static_cast<uint32_t>(soup.size() / 3));
                    soup.insert(soup.end(), {v.x(), v.y(), v.z()});
                }
            }
        }
        nl_navmesh_def def = nl_default_navmesh_def();
        def.vertices = soup.data();
        def.vertex_count = static_cast<uint32_t>(soup.size() / 3);
        def.indices = indices.data();
        def.polygon_count = static_cast<uint32_t>(indices.size() / 3);
        nl_navmesh_id hosted{};
        REQUIRE_MESSAGE(nl_navmesh_add(world, &def, &hosted) == NL_STATUS_SUCCESS, nl_get_last_error_message());
        const auto host = navmesh_of(world, hosted);
        CHECK(nl::test::check_navmesh(*host) == "");
        // Welding restores the shared vertices, so the outline is the same as Recast's.
        CHECK(host->boundary_edges().size() == recast->boundary_edges().size());
        CHECK(host->vertex_count() == recast->vertex_count());
        check_point_location(*host, name + " host");
        nl_world_destroy(world);
    }
}

TEST_CASE("a level with no walkable surface is a clear failure, not an empty navmesh") {
    nl_world* world = nullptr;
    REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
    const float wall[] = {0, 0, 0, 0, 3, 0, 4, 3, 0, 4, 0, 0};
    const uint32_t quad[] = {0, 1, 2, 0, 2, 3};
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = wall;
    def.vertex_count = 4;
    def.indices = quad;
    def.triangle_count = 2;
    nl_mesh_id id{};
    REQUIRE(nl_mesh_add(world, &def, &id) == NL_STATUS_SUCCESS);
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh{};
    CHECK(nl_navmesh_build(world, &build, &navmesh) == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    CHECK(std::string(nl_get_last_error_message()).find("walkable") != std::string::npos);
    uint32_t count = 9;
    CHECK(nl_world_get_navmeshes(world, nullptr, 0, &count) == NL_STATUS_SUCCESS);
    CHECK(count == 0);
    nl_world_destroy(world);
}
