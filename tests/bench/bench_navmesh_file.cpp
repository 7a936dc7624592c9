// navlink-bench-navmesh-file [--large N] LEVEL.obj...: baked navmesh files against their anchors,
// measured in one run per level. The level's navmesh is built by nl_navmesh_build (the Recast
// builder, default settings: the anchor for load time), its links generated with the default
// settings, the whole saved with nl_navmesh_save and loaded back with nl_navmesh_load into a new
// world. Detour's navmesh data is made by dtCreateNavMeshData from the same Recast polygon mesh
// (recast_detour.h, as navlink-bench-path): the anchor for bytes, of the file and of the navmesh in
// memory (the loaded navmesh plus its link index, read from the world's internals as
// navlink-bench-path reads them). One line per level:
//   level polys links file_bytes detour_bytes file/detour memory_bytes memory/detour build_ms load_ms
//   load/build same
// build_ms and load_ms are the best of 20 runs on a level of fewer than 1,000 polygons (their
// times are tens of microseconds), of 3 on larger ones, of 1 past a million triangles;
// `same` says the loaded navmesh has the saved one's polygons and links, and saves to the same bytes.
// --large N adds nl::levelgen::generate_large_level(1, N) (N x N blocks of 12 m; N = 40 gives about
// 1.9 million triangles), named "large-N".
#include <navlink/navlink.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "clock.h"
#include "path/path_graph.h"
#include "level_generator.h"
#include "recast_detour.h"
#include "world.h"

namespace {

struct Level {
    std::string name;
    std::string obj;                         // a file, or
    nl::levelgen::GeneratedLevel generated;  // triangles made here
};

bool add_level(nl_world* world, const Level& level) {
    nl_mesh_id mesh{};
    if (!level.obj.empty()) return NL_SUCCEEDED(nl_mesh_add_obj_file(world, level.obj.c_str(), nullptr, &mesh));
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = level.generated.positions.data();
    def.vertex_count = level.generated.vertex_count();
    def.indices = level.generated.indices.data();
    def.triangle_count = level.generated.triangle_count();
    return NL_SUCCEEDED(nl_mesh_add(world, &def, &mesh));
}

std::vector<uint8_t> saved(nl_world* world, nl_navmesh_id navmesh) {
    size_t size = 0;
    if (NL_FAILED(nl_navmesh_save(world, navmesh, nullptr, 0, &size))) return {};
    std::vector<uint8_t> out(size);
    if (NL_FAILED(nl_navmesh_save(world, navmesh, out.data(), out.size(), &size))) return {};
    return out;
}

uint32_t link_count(nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    nl_navmesh_get_links(world, navmesh, nullptr, 0, &count);
    return count;
}

bool measure(const Level& level) {
    auto failed = [&](const char* what) {
        std::fprintf(stderr, "navlink-bench-navmesh-file: %s: %s: %s\n", level.name.c_str(), what,
                     nl_get_last_error_message());
        return false;
    };
    // Detour's data for the same polygon mesh.
    nl::bench::RecastLevel recast =
        level.obj.empty()
            ? nl::bench::build_recast_level(level.name, level.generated.positions, level.generated.indices)
            : nl::bench::build_recast_level_from_obj(level.obj.c_str());
    nl::bench::DetourMesh detour;
    if (!nl::bench::build_detour(recast, detour)) {
        std::fprintf(stderr, "navlink-bench-navmesh-file: %s: Detour refused the polygon mesh\n", level.name.c_str());
        return false;
    }

    nl_world* world = nullptr;
    nl_world* game = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world)) || NL_FAILED(nl_world_create(nullptr, &game)))
        return failed("world");
    if (!add_level(world, level)) return failed("level");
    const int polygons = recast.solo.polygons->npolys;
    const int runs = level.generated.triangle_count() > 1000000 ? 1 : polygons < 1000 ? 20 : 3;
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh{};
    double build_ms = 1e300;
    for (int run = 0; run < runs; ++run) {
        nl_navmesh_id id{};
        const double start = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_build(world, &build, &id))) return failed("build");
        build_ms = std::min(build_ms, nl::samples::now_ms() - start);
        if (run > 0) nl_navmesh_remove(world, navmesh);
        navmesh = id;
    }
    if (NL_FAILED(nl_navmesh_generate_links(world, navmesh, nullptr, nullptr, nullptr, nullptr)))
        return failed("links");
    const std::vector<uint8_t> file = saved(world, navmesh);
    if (file.empty()) return failed("save");

    double load_ms = 1e300;
    nl_navmesh_id loaded{};
    for (int run = 0; run < runs; ++run) {
        nl_navmesh_id id{};
        const double start = nl::samples::now_ms();
        if (NL_FAILED(nl_navmesh_load(game, file.data(), file.size(), nullptr, &id))) return failed("load");
        load_ms = std::min(load_ms, nl::samples::now_ms() - start);
        if (run > 0) nl_navmesh_remove(game, loaded);
        loaded = id;
    }
    nl_navmesh_info a{}, b{};
    a.size = b.size = sizeof a;
    nl_navmesh_get_info(world, navmesh, &a);
    nl_navmesh_get_info(game, loaded, &b);
    const bool same = a.polygon_count == b.polygon_count && a.vertex_count == b.vertex_count &&
                      link_count(world, navmesh) == link_count(game, loaded) && saved(game, loaded) == file;
    const auto graph = game->core->navmeshes().path_graph(nl::Handle{loaded.index1, loaded.revision});
    const size_t memory = graph->navmesh().memory_bytes() + graph->link_index_bytes();
    std::printf("%-18s %8u %6u %11zu %12d %11.3f %12zu %13.3f %9.1f %8.2f %9.4f %4s\n", level.name.c_str(),
                a.polygon_count, link_count(world, navmesh), file.size(), detour.bytes,
                double(file.size()) / detour.bytes, memory, double(memory) / detour.bytes, build_ms, load_ms,
                load_ms / build_ms, same ? "yes" : "NO");
    if (a.polygon_count != uint32_t(polygons))
        std::printf("  (note: Detour's data holds %d polygons, NavLink's navmesh %u)\n", polygons, a.polygon_count);
    nl_world_destroy(game);
    nl_world_destroy(world);
    return same;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<Level> levels;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--large") && i + 1 < argc) {
            const int blocks = std::atoi(argv[++i]);
            Level level;
            level.name = "large-" + std::to_string(blocks);
            level.generated = nl::levelgen::generate_large_level(1, uint32_t(blocks));
            levels.push_back(std::move(level));
            continue;
        }
        Level level;
        level.obj = argv[i];
        const char* slash = std::strrchr(argv[i], '/');
        level.name = slash ? slash + 1 : argv[i];
        if (level.name.size() > 4 && level.name.compare(level.name.size() - 4, 4, ".obj") == 0)
            level.name.resize(level.name.size() - 4);
        levels.push_back(std::move(level));
    }
    if (levels.empty()) {
        std::fprintf(stderr, "usage: navlink-bench-navmesh-file [--large N] LEVEL.obj...\n");
        return 2;
    }
    std::printf(
        "Baked navmesh files: bytes (of the file, and of the loaded navmesh plus link index in memory) against\n"
        "Detour's navmesh data for the same Recast polygon mesh, load time against building the navmesh with\n"
        "the Recast builder, in this run.\n");
    std::printf("%-18s %8s %6s %11s %12s %11s %12s %13s %9s %8s %9s %4s\n", "level", "polys", "links", "file_bytes",
                "detour_bytes", "file/detour", "memory_bytes", "memory/detour", "build_ms", "load_ms", "load/build",
                "same");
    bool ok = true;
    for (const Level& level : levels) {
        try {
            ok = measure(level) && ok;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-bench-navmesh-file: %s: %s\n", level.name.c_str(), e.what());
            ok = false;
        }
    }
    return ok ? 0 : 1;
}
