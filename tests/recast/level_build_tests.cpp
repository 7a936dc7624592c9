// Navmeshes built from the shared levels: every one builds and is well formed, the polygon counts are
// those of Detour's reference build, every partition works, and builds may run at once.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <thread>

#include "fake_host.h"
#include "mesh_checks.h"
#include "shared_levels.h"

using namespace nl::test;

TEST_CASE("recast builds a well-formed navmesh on every shared level") {
    const auto levels = shared_levels();
    if (levels.empty() && levels_required()) FAIL("no shared levels in " << levels_dir().string());
    // Polygon counts of the README's Detour reference build (same defaults, solo tile).
    const std::map<std::string, int> reference = {{"nav_test", 153}, {"dungeon", 118}, {"undulating", 216}};
    int checked_references = 0;
    for (const auto& path : levels) {
        const std::string stem = path.stem().string();
        CAPTURE(stem);
        FakeHost host = FakeHost::from_obj(path);
        const nl_navmesh_build_def def = default_build_def();
        const BuildOutcome out = run_build(host, def);
        REQUIRE_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
        CHECK(out.sink_calls == 1);
        check_navmesh(out.mesh, host, def.agent_type);
        const uint32_t up = count_upward_polygons(out.mesh);
        MESSAGE(stem, ": ", host.triangle_count(), " triangles -> ", out.mesh.polygon_count(), " polygons, ",
                out.mesh.vertex_count(), " vertices, ", out.mesh.detail_starts.back(), " detail triangles, ", up,
                " facing up, ", out.milliseconds, " ms");
        CHECK(up == out.mesh.polygon_count());  // corners counter-clockwise seen from above, as navlink.h wants
        const auto ref = reference.find(stem);
        if (ref != reference.end()) {
            ++checked_references;
            const double ratio = double(out.mesh.polygon_count()) / ref->second;
            MESSAGE(stem, ": ", out.mesh.polygon_count(), " polygons vs Detour reference ", ref->second, " (ratio ",
                    ratio, ")");
            CHECK(std::fabs(ratio - 1.0) <= 0.15);
        }
    }
    if (!levels.empty()) CHECK(checked_references == 3);
}

TEST_CASE("recast monotone and layer partitions build") {
    const auto path = shared_level("nav_test");
    if (path.empty()) return;
    FakeHost host = FakeHost::from_obj(path);
    for (const std::string partition : {"\"watershed\"", "\"monotone\"", "\"layers\"", "1", "2"}) {
        CAPTURE(partition);
        const std::string json = "{\"partition\": " + partition + "}";
        const BuildOutcome out = run_build(host, json_build_def(json));
        REQUIRE_MESSAGE(out.status == NL_STATUS_SUCCESS, out.error);
        check_navmesh(out.mesh, host, default_agent());
        MESSAGE("nav_test partition ", partition, ": ", out.mesh.polygon_count(), " polygons, ", out.milliseconds,
                " ms");
    }
}

TEST_CASE("recast detail sampling can be disabled and polygons limited to triangles") {
    const auto path = shared_level("dungeon");
    if (path.empty()) return;
    FakeHost host = FakeHost::from_obj(path);
    const BuildOutcome plain = run_build(host, json_build_def(R"({"detail_sample_distance": 0})"));
    REQUIRE_MESSAGE(plain.status == NL_STATUS_SUCCESS, plain.error);
    check_navmesh(plain.mesh, host, default_agent());
    const BuildOutcome sampled = run_build(host, default_build_def());
    REQUIRE(sampled.status == NL_STATUS_SUCCESS);
    CHECK(plain.mesh.polygon_count() == sampled.mesh.polygon_count());
    CHECK(plain.mesh.detail_vertices.size() <= sampled.mesh.detail_vertices.size());

    const BuildOutcome triangles = run_build(host, json_build_def(R"({"vertices_per_polygon": 3})"));
    REQUIRE_MESSAGE(triangles.status == NL_STATUS_SUCCESS, triangles.error);
    check_navmesh(triangles.mesh, host, default_agent());
    for (uint8_t n : triangles.mesh.vertex_counts) CHECK(n == 3);
    CHECK(triangles.mesh.polygon_count() > sampled.mesh.polygon_count());
}

TEST_CASE("recast builds run at once give the same navmeshes as one after another") {
    const auto a_path = shared_level("nav_test");
    const auto b_path = shared_level("dungeon");
    if (a_path.empty() || b_path.empty()) return;
    FakeHost a = FakeHost::from_obj(a_path);
    FakeHost b = FakeHost::from_obj(b_path);
    const BuildOutcome a_alone = run_build(a, default_build_def());
    const BuildOutcome b_alone = run_build(b, default_build_def());
    REQUIRE(a_alone.status == NL_STATUS_SUCCESS);
    REQUIRE(b_alone.status == NL_STATUS_SUCCESS);

    BuildOutcome a_together, b_together, a_again;
    std::thread ta([&] { a_together = run_build(a, default_build_def()); });
    std::thread tb([&] { b_together = run_build(b, default_build_def()); });
    std::thread tc([&] { a_again = run_build(a, default_build_def()); });  // same host, concurrently
    ta.join();
    tb.join();
    tc.join();
    CHECK(a_together.status == NL_STATUS_SUCCESS);
    CHECK(b_together.status == NL_STATUS_SUCCESS);
    CHECK(a_again.status == NL_STATUS_SUCCESS);
    CHECK(a_together.mesh == a_alone.mesh);
    CHECK(a_again.mesh == a_alone.mesh);
    CHECK(b_together.mesh == b_alone.mesh);
}
