// navlink-bench-rays LEVEL.obj...: throughput of the batch ray queries through the C ABI, on 1 and 2
// worker threads, with the same rays in the same run. One line per level:
//   level=NAME tris=N rays=N closest_1t_mps=X closest_2t_mps=X occluded_1t_mps=X occluded_2t_mps=X
// (mps: million queries per second, best of 3 runs).
#include <navlink/navlink.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include "clock.h"

namespace {

struct Batch {
    std::vector<nl_ray> rays;
    std::vector<nl_segment> segments;
};

Batch make_batch(const nl_mesh_info& info, uint32_t count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    Batch b;
    b.rays.resize(count);
    b.segments.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) {
            const float lo = info.bounds_min[k], span = info.bounds_max[k] - info.bounds_min[k];
            b.rays[i].origin[k] = lo + unit(rng) * span;
            b.rays[i].direction[k] = gauss(rng);
            b.segments[i].from[k] = b.rays[i].origin[k];
            b.segments[i].to[k] = lo + unit(rng) * span;
        }
        b.rays[i].max_distance = INFINITY;
    }
    return b;
}

template <typename Fn>
double best_ms(Fn&& fn) {
    double best = 1e300;
    for (int run = 0; run < 3; ++run) {
        const double start = nl::samples::now_ms();
        fn();
        best = std::min(best, nl::samples::now_ms() - start);
    }
    return best;
}

bool measure(const char* path, uint32_t count) {
    double closest[2], occluded[2];
    uint32_t triangles = 0;
    for (int threads = 1; threads <= 2; ++threads) {
        nl_world_def def = nl_default_world_def();
        def.worker_count = threads;
        nl_world* world = nullptr;
        nl_mesh_id mesh{};
        if (NL_FAILED(nl_world_create(&def, &world)) || NL_FAILED(nl_mesh_add_obj_file(world, path, nullptr, &mesh))) {
            std::fprintf(stderr, "navlink-bench-rays: %s: %s\n", path, nl_get_last_error_message());
            nl_world_destroy(world);
            return false;
        }
        nl_mesh_info info{};
        info.size = sizeof info;
        nl_mesh_get_info(world, mesh, &info);
        triangles = info.triangle_count;
        const Batch batch = make_batch(info, count);
        std::vector<nl_ray_hit> hits(count, nl_ray_hit_init());
        std::vector<uint8_t> blocked(count);
        nl_world_cast_rays(world, batch.rays.data(), 1, hits.data());  // builds the BVH outside the timing
        closest[threads - 1] = best_ms([&] { nl_world_cast_rays(world, batch.rays.data(), count, hits.data()); });
        occluded[threads - 1] =
            best_ms([&] { nl_world_segments_blocked(world, batch.segments.data(), count, blocked.data()); });
        nl_world_destroy(world);
    }
    auto mps = [&](double ms) { return count / ms / 1000.0; };
    std::printf(
        "level=%s tris=%u rays=%u closest_1t_mps=%.2f closest_2t_mps=%.2f occluded_1t_mps=%.2f occluded_2t_mps=%.2f\n",
        std::filesystem::path(path).stem().c_str(), triangles, count, mps(closest[0]), mps(closest[1]),
        mps(occluded[0]), mps(occluded[1]));
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: navlink-bench-rays LEVEL.obj...\n");
        return 2;
    }
    bool ok = true;
    for (int i = 1; i < argc; ++i) ok = measure(argv[i], 1000000) && ok;
    return ok ? 0 : 1;
}
