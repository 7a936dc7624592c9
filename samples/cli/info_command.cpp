// navlink info: what a baked navmesh file, a tile's file or a tile bake's folder holds and what it was made
// for.
#include <cstdio>
#include <string>
#include <vector>

#include "arguments.h"
#include "commands.h"
#include "help_text.h"
#include "navmesh_files.h"
#include "sample_error.h"
#include "tile_bake.h"

namespace nl::cli {

namespace {

// A tile bake's folder: the grid, then each tile's file, links and content hash, each file checked whole
// and against the index.
int print_tile_bake(const std::string& folder, bool json) {
    const TileBakeIndex index = read_tile_bake(folder);
    size_t links = 0, polygons = 0;
    uint64_t bytes = 0;
    std::vector<samples::NavmeshFileContents> files;
    for (const TileBakeEntry& e : index.tiles) {
        files.push_back(samples::describe_navmesh_file(folder + "/" + e.file));
        const nl_navmesh_file_info& i = files.back().info;
        if (!i.is_tile || i.tile.x != e.tile.x || i.tile.z != e.tile.z || i.content_hash != e.hash)
            throw samples::SampleError(folder + "/" + e.file + ": not the tile (" + std::to_string(e.tile.x) + ", " +
                                       std::to_string(e.tile.z) + ") with the hash the index says");
        links += i.link_count;
        polygons += i.polygon_count;
        bytes += i.file_size;
    }
    if (json) {
        std::printf("%s\n", files.front().made_for_json.c_str());
        return 0;
    }
    std::printf("%s: NavLink tile bake, %zu tiles of %g m from (%g, %g), %llu bytes\n", folder.c_str(),
                index.tiles.size(), double(index.tile_width), double(index.tile_origin[0]),
                double(index.tile_origin[1]), static_cast<unsigned long long>(bytes));
    std::printf("navmesh: %zu polygons; links: %zu (each in the file of the tile it starts on)\n", polygons, links);
    std::printf("    tile        file                         polygons  links  bytes     content hash\n");
    for (size_t k = 0; k < files.size(); ++k) {
        const TileBakeEntry& e = index.tiles[k];
        const nl_navmesh_file_info& i = files[k].info;
        const std::string tile = "(" + std::to_string(e.tile.x) + ", " + std::to_string(e.tile.z) + ")";
        std::printf("    %-11s %-28s %8u %6u %6llu  %016llx\n", tile.c_str(), e.file.c_str(), i.polygon_count,
                    i.link_count, static_cast<unsigned long long>(i.file_size),
                    static_cast<unsigned long long>(e.hash));
    }
    std::printf("made with: %s\n", files.front().made_for_json.c_str());
    return 0;
}

}  // namespace

int run_info(int argc, char** argv) {
    const samples::Arguments args("navlink info", "info", argc, argv, 2, {{"json", false}});
    if (args.wants_help()) {
        std::fputs(kInfoHelp, stdout);
        return 0;
    }
    args.expect_positional(1, "NAVMESH.nlnav");
    const std::string& path = args.positional()[0];
    if (is_tile_bake(path)) return print_tile_bake(path, args.has("json"));
    const samples::NavmeshFileContents file = samples::describe_navmesh_file(path);
    const nl_navmesh_file_info& i = file.info;
    if (args.has("json")) {
        std::printf("%s\n", file.made_for_json.c_str());
        return 0;
    }
    std::printf("%s: NavLink navmesh file, format version %u, %llu bytes\n", path.c_str(), i.version,
                static_cast<unsigned long long>(i.file_size));
    std::printf("navmesh: %u polygons, %u vertices, %u detail triangles; coordinates in steps of %g m%s\n",
                i.polygon_count, i.vertex_count, i.detail_triangle_count, double(i.quantum),
                i.rides_carrier ? " (in the space of the movable mesh it rode)" : "");
    std::printf("links: %u (%u generated, %u added by the host)\n", i.link_count, i.generated_link_count,
                i.link_count - i.generated_link_count);
    std::printf("made for a body of radius %g m, height %g m, climbing %g m, slopes up to %g degrees\n",
                double(i.agent_type.radius), double(i.agent_type.height), double(i.agent_type.max_climb),
                double(i.agent_type.max_slope));
    if (i.level_hash)
        std::printf("built from a level whose hash is %016llx\n", static_cast<unsigned long long>(i.level_hash));
    else
        std::printf("handed over by the host (not built from a level)\n");
    if (i.is_tile)
        std::printf("a tile's file: tile (%d, %d) of a grid of %g m from (%g, %g), content hash %016llx\n", i.tile.x,
                    i.tile.z, double(i.tile_width), double(i.tile_origin_x), double(i.tile_origin_z),
                    static_cast<unsigned long long>(i.content_hash));
    std::printf("made with: %s\n", file.made_for_json.c_str());
    return 0;
}

}  // namespace nl::cli
