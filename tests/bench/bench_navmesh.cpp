// navlink-bench-navmesh LEVEL.obj...: navmesh build and point location through the C ABI, with the
// built-in Recast builder and default settings. One line per level:
//   level=NAME tris=N polys=N vertices=N portals=N boundary_edges=N build_ms=X locate_us=X found_pct=X
// build_ms is the best of 3 builds; locate_us the time per query of a 100,000-point batch on one
// worker, search box half extents (2, 4, 2) m around points drawn in the navmesh bounds.
#include <navlink/navlink.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include "clock.h"

namespace {

bool measure(const char* path) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    nl_world* world = nullptr;
    nl_mesh_id mesh{};
    if (NL_FAILED(nl_world_create(&def, &world)) || NL_FAILED(nl_mesh_add_obj_file(world, path, nullptr, &mesh))) {
        std::fprintf(stderr, "navlink-bench-navmesh: %s: %s\n", path, nl_get_last_error_message());
        nl_world_destroy(world);
        return false;
    }
    nl_mesh_info mesh_info{};
    mesh_info.size = sizeof mesh_info;
    nl_mesh_get_info(world, mesh, &mesh_info);

    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh{};
    double best_ms = 1e300;
    for (int run = 0; run < 3; ++run) {
        nl_navmesh_id id{};
        const double start = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_build(world, &build, &id))) {
            std::fprintf(stderr, "navlink-bench-navmesh: %s: %s\n", path, nl_get_last_error_message());
            nl_world_destroy(world);
            return false;
        }
        best_ms = std::min(best_ms, nl::samples::now_ms() - start);
        if (run > 0) nl_navmesh_remove(world, navmesh);
        navmesh = id;
    }
    nl_navmesh_info info{};
    info.size = sizeof info;
    nl_navmesh_get_info(world, navmesh, &info);

    const uint32_t count = 100000;
    std::mt19937 rng(3);
    std::vector<float> points(3 * size_t(count));
    for (uint32_t i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) {
            std::uniform_real_distribution<float> u(info.bounds_min[k], info.bounds_max[k]);
            points[3 * size_t(i) + k] = u(rng);
        }
    }
    const float half_extents[3] = {2.0f, 4.0f, 2.0f};
    std::vector<nl_nav_point> out(count);
    double locate_ms = 1e300;
    for (int run = 0; run < 3; ++run) {
        const double start = nl::samples::now_ms();
        nl_navmesh_find_nearest(world, navmesh, points.data(), count, half_extents, out.data());
        locate_ms = std::min(locate_ms, nl::samples::now_ms() - start);
    }
    size_t found = 0;
    for (const nl_nav_point& p : out) found += p.found;
    std::printf(
        "level=%s tris=%u polys=%u vertices=%u portals=%u boundary_edges=%u build_ms=%.1f locate_us=%.3f "
        "found_pct=%.0f\n",
        std::filesystem::path(path).stem().c_str(), mesh_info.triangle_count, info.polygon_count, info.vertex_count,
        info.portal_count, info.boundary_edge_count, best_ms, 1000.0 * locate_ms / count, 100.0 * found / count);
    nl_world_destroy(world);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: navlink-bench-navmesh LEVEL.obj...\n");
        return 2;
    }
    bool ok = true;
    for (int i = 1; i < argc; ++i) ok = measure(argv[i]) && ok;
    return ok ? 0 : 1;
}
