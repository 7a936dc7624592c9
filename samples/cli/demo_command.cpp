// navlink demo: the default level, its links, and one route planned for three different bodies.
#include <cstdio>

#include "arguments.h"
#include "commands.h"
#include "demo_setup.h"
#include "help_text.h"
#include "island_colors.h"
#include "level_generator.h"
#include "link_files.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "output_paths.h"
#include "palette.h"
#include "path_plan.h"
#include "picture_export.h"
#include "route_text.h"
#include "sample_error.h"
#include "text_file.h"

namespace nl::cli {

int run_demo(int argc, char** argv) {
    const samples::Arguments args(
        "navlink demo", "demo", argc, argv, 2,
        {{"seed", true}, {"out-dir", true}, {"oblique", false}, {"link-numbers", false}, {"roofs", false}});
    if (args.wants_help()) {
        std::fputs(kDemoHelp, stdout);
        return 0;
    }
    args.expect_positional(0, "");
    const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
    const std::string dir = args.value("out-dir").value_or(".");
    samples::prepare_output_folder(dir);
    const std::string links_path = dir + "/demo.links.json";
    const std::string png_path = dir + "/demo.png";
    samples::check_writable_file(links_path);
    samples::check_writable_file(png_path);

    const levelgen::GeneratedLevel generated = levelgen::generate_default_level(seed);
    const std::vector<samples::AgentProfile> agents = samples::demo_agents();
    NavigableLevel level(generated, "generated default level (seed " + std::to_string(seed) + ")", agents[0].body, "");
    const nl_link_settings settings = nl_default_link_settings();
    const nl_link_generation_report report = level.generate_links(settings);
    const samples::NavmeshContents contents = samples::read_navmesh_contents(level.world(), level.navmesh());

    const float* start = generated.marker("start")->position;
    const float* goal = generated.marker("goal")->position;
    std::printf("NavLink demo: %s, %u triangles\n", level.level().name.c_str(), level.level().info.triangle_count);
    std::printf("  navmesh: %zu polygons, built by recast in %.0f ms\n", contents.polygons.size(),
                level.times().navmesh_ms);
    std::printf("  links:   %u jumps and %u drops (gaps up to %.1f m), generated in %.0f ms\n", report.jump_links,
                report.drop_links, settings.max_jump_gap, report.milliseconds_total);
    std::printf("  route:   from (%.1f, %.1f, %.1f) on the first platform to (%.1f, %.1f, %.1f) on the last\n\n",
                start[0], start[1], start[2], goal[0], goal[1], goal[2]);

    std::printf("%-13s %7s %7s %7s | %-9s %7s  %-16s %s\n", "agent", "across", "up", "down", "outcome", "length",
                "links", "route (metres)");
    std::vector<picture::PathLayer> layers;
    bool all_complete = true;
    for (size_t i = 0; i < agents.size(); ++i) {
        const samples::AgentProfile& a = agents[i];
        const samples::PlannedPath path =
            samples::find_path(level.world(), level.navmesh(), start, goal, a.capabilities);
        const std::string links = samples::describe_links(samples::count_links(path));
        std::printf("%-13s %5.1f m %5.1f m %5.1f m | %-9s %5.1f m  %-16s %s\n", a.name.c_str(),
                    a.capabilities.max_jump_distance, a.capabilities.max_jump_height, a.capabilities.max_drop_height,
                    samples::outcome_name(path.result.outcome), path.result.length, links.c_str(),
                    route_text(path).c_str());
        char label[96];
        std::snprintf(label, sizeof label, "%s: %.1f m, %s", a.name.c_str(), path.result.length, links.c_str());
        layers.push_back({label, picture::palette::agent(i), path.points});
        all_complete = all_complete && path.result.outcome == NL_PATH_COMPLETE;
    }

    samples::write_text_file(links_path, samples::links_json(level.world(), level.navmesh()));
    PictureRequest request;
    request.path = png_path;
    request.oblique = args.has("oblique");
    request.link_numbers = args.has("link-numbers");
    request.roofs = args.has("roofs");
    request.islands = picture::read_islands(level.world(), level.navmesh(), agents[0].capabilities, agents[0].name);
    request.title = "navlink demo: one route, three bodies (seed " + std::to_string(seed) + ")";
    const std::string counted = write_picture(level.level(), contents, layers, request,
                                              {{"start", {start[0], start[1], start[2]}, picture::palette::kText},
                                               {"goal", {goal[0], goal[1], goal[2]}, picture::palette::kText}});
    std::printf("\nwrote %s and %s (%s)\n", links_path.c_str(), png_path.c_str(), counted.c_str());
    return all_complete ? 0 : 1;
}

}  // namespace nl::cli
