// navlink info: what a baked navmesh file holds and what it was made for.
#include <cstdio>

#include "arguments.h"
#include "commands.h"
#include "help_text.h"
#include "navmesh_files.h"
#include "sample_error.h"

namespace nl::cli {

int run_info(int argc, char** argv) {
    const samples::Arguments args("navlink info", "info", argc, argv, 2, {{"json", false}});
    if (args.wants_help()) {
        std::fputs(kInfoHelp, stdout);
        return 0;
    }
    args.expect_positional(1, "NAVMESH.nlnav");
    const std::string& path = args.positional()[0];
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
    std::printf("made with: %s\n", file.made_for_json.c_str());
    return 0;
}

}  // namespace nl::cli
