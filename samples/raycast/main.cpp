// navlink-raycast: loads a level (an OBJ file, or the generated default level), casts a grid of rays
// down onto it through the C ABI, draws the heights it found as text, and measures batch throughput.
#include <navlink/navlink.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "clock.h"
#include "level_generator.h"

namespace {

int fail(const char* what) {
    std::fprintf(stderr, "navlink-raycast: %s: %s\n", what, nl_get_last_error_message());
    return 2;
}

void print_height_map(const std::vector<nl_ray_hit>& hits, int columns, int rows, float lo, float hi) {
    static const char ramp[] = " .:-=+*#%@";
    for (int r = 0; r < rows; ++r) {
        std::string line;
        for (int c = 0; c < columns; ++c) {
            const nl_ray_hit& h = hits[size_t(r) * columns + c];
            if (!h.hit) {
                line += ' ';
                continue;
            }
            const float t = hi > lo ? (h.point[1] - lo) / (hi - lo) : 0.5f;
            line += ramp[1 + std::lround(t * 8.0f)];
        }
        std::printf("  |%s|\n", line.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 || (argc == 2 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")))) {
        std::printf(
            "usage: navlink-raycast [LEVEL.obj]\n"
            "Loads LEVEL.obj (default: the generated demo level), casts rays down onto it and\n"
            "prints a height map and the ray throughput of the batch queries.\n");
        return argc > 2 ? 2 : 0;
    }
    const nl_version v = nl_get_version();
    std::printf("NavLink %d.%d.%d\n", v.major, v.minor, v.patch);

    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world))) return fail("creating the world");

    nl_mesh_id mesh{};
    std::string name;
    const double load_start = nl::samples::now_ms();
    if (argc == 2) {
        name = argv[1];
        if (NL_FAILED(nl_mesh_add_obj_file(world, argv[1], nullptr, &mesh))) {
            const int code = fail("loading the level");
            nl_world_destroy(world);
            return code;
        }
    } else {
        name = "generated default level (seed 1)";
        const auto level = nl::levelgen::generate_default_level(1);
        nl_mesh_def def = nl_default_mesh_def();
        def.vertices = level.positions.data();
        def.vertex_count = level.vertex_count();
        def.indices = level.indices.data();
        def.triangle_count = level.triangle_count();
        if (NL_FAILED(nl_mesh_add(world, &def, &mesh))) {
            const int code = fail("registering the level");
            nl_world_destroy(world);
            return code;
        }
    }
    nl_mesh_info info{};
    info.size = sizeof info;
    nl_mesh_get_info(world, mesh, &info);
    std::printf(
        "level: %s\n  %u triangles (%u degenerate skipped), bounds (%.1f %.1f %.1f) .. (%.1f %.1f %.1f), loaded in "
        "%.1f ms\n",
        name.c_str(), info.triangle_count, info.degenerate_triangle_count, info.bounds_min[0], info.bounds_min[1],
        info.bounds_min[2], info.bounds_max[0], info.bounds_max[1], info.bounds_max[2],
        nl::samples::now_ms() - load_start);

    // A grid of rays straight down over the level's footprint: the top surface, as a height map.
    const int columns = 72, rows = 28;
    std::vector<nl_ray> grid;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            nl_ray ray{};
            ray.origin[0] = info.bounds_min[0] + (c + 0.5f) * (info.bounds_max[0] - info.bounds_min[0]) / columns;
            ray.origin[1] = info.bounds_max[1] + 1.0f;
            ray.origin[2] = info.bounds_min[2] + (r + 0.5f) * (info.bounds_max[2] - info.bounds_min[2]) / rows;
            ray.direction[1] = -1.0f;
            ray.max_distance = INFINITY;
            grid.push_back(ray);
        }
    }
    std::vector<nl_ray_hit> hits(grid.size(), nl_ray_hit_init());
    const double first_start = nl::samples::now_ms();
    if (NL_FAILED(nl_world_cast_rays(world, grid.data(), uint32_t(grid.size()), hits.data())))
        return fail("casting rays");
    const double first_ms = nl::samples::now_ms() - first_start;  // includes building the BVH
    size_t hit_count = 0;
    for (const auto& h : hits) hit_count += h.hit;
    std::printf("top-down height map (%d x %d rays, %zu hit; first query with BVH build %.1f ms):\n", columns, rows,
                hit_count, first_ms);
    print_height_map(hits, columns, rows, info.bounds_min[1], info.bounds_max[1]);

    // Throughput: a million random rays and segments inside the level, in one batch each.
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    const uint32_t count = 1000000;
    std::vector<nl_ray> rays(count);
    std::vector<nl_segment> segments(count);
    for (uint32_t i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) {
            const float lo = info.bounds_min[k], span = info.bounds_max[k] - info.bounds_min[k];
            rays[i].origin[k] = lo + unit(rng) * span;
            rays[i].direction[k] = gauss(rng);
            segments[i].from[k] = rays[i].origin[k];
            segments[i].to[k] = lo + unit(rng) * span;
        }
        rays[i].max_distance = INFINITY;
    }
    std::vector<nl_ray_hit> random_hits(count, nl_ray_hit_init());
    std::vector<uint8_t> blocked(count);
    double start = nl::samples::now_ms();
    if (NL_FAILED(nl_world_cast_rays(world, rays.data(), count, random_hits.data()))) return fail("casting rays");
    const double rays_ms = nl::samples::now_ms() - start;
    start = nl::samples::now_ms();
    if (NL_FAILED(nl_world_segments_blocked(world, segments.data(), count, blocked.data())))
        return fail("testing segments");
    const double segments_ms = nl::samples::now_ms() - start;
    size_t blocked_count = 0;
    for (uint8_t b : blocked) blocked_count += b;
    std::printf(
        "%u random rays: %.1f ms (%.2f Mrays/s); %u random segments: %.1f ms (%.2f M/s), %.0f%% blocked; %d worker "
        "threads\n",
        count, rays_ms, count / rays_ms / 1000.0, count, segments_ms, count / segments_ms / 1000.0,
        100.0 * blocked_count / count, nl_world_get_worker_count(world));
    nl_world_destroy(world);
    return 0;
}
