// navlink simulate: the demo's three bodies as agents (nl_agent_*) on the default level, stepped
// until each has arrived; prints when and where, and draws the tracks they really took. With
// --platforms, passengers ride the moving platforms beside the level instead.
#include <cstdio>
#include <string>
#include <vector>

#include "arguments.h"
#include "commands.h"
#include "demo_setup.h"
#include "help_text.h"
#include "level_generator.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "output_paths.h"
#include "palette.h"
#include "picture_export.h"
#include "simulate_scenes.h"
#include "simulation.h"

namespace nl::cli {

int simulate_default_level(const SimulateOptions& options) {
    const levelgen::GeneratedLevel generated = levelgen::generate_default_level(options.seed);
    const std::vector<samples::AgentProfile> profiles = samples::demo_agents();
    const std::string seed = std::to_string(options.seed);
    NavigableLevel level(generated, "generated default level (seed " + seed + ")", profiles[0].body, "");
    const nl_link_generation_report report = level.generate_links(nl_default_link_settings());

    const float* start = generated.marker("start")->position;
    const float* goal = generated.marker("goal")->position;
    std::printf("NavLink simulate: %s, %u jumps and %u drops generated\n", level.level().name.c_str(),
                report.jump_links, report.drop_links);
    std::printf("  three agents leave (%.1f, %.1f, %.1f) for (%.1f, %.1f, %.1f), stepped every %.1f ms\n\n",
                start[0], start[1], start[2], goal[0], goal[1], goal[2], options.dt * 1000.0);

    Simulation simulation(level.world());
    for (const samples::AgentProfile& profile : profiles) simulation.add_agent(profile, level.navmesh(), start, goal);
    simulation.run(options.dt, options.seconds);
    simulation.print_table();

    PictureRequest request;
    request.path = options.out_dir + "/simulate.png";
    request.oblique = options.oblique;
    request.title = "navlink simulate: the tracks three agents took (seed " + seed + ")";
    write_picture(level.level(), samples::read_navmesh_contents(level.world(), level.navmesh()), simulation.tracks(),
                  request,
                  {{"start", {start[0], start[1], start[2]}, picture::palette::kText},
                   {"goal", {goal[0], goal[1], goal[2]}, picture::palette::kText}});
    std::printf("\nwrote %s\n", request.path.c_str());
    return simulation.all_arrived() ? 0 : 1;
}

int run_simulate(int argc, char** argv) {
    const samples::Arguments args("navlink simulate", "simulate", argc, argv, 2,
                                  {{"seed", true}, {"out-dir", true}, {"oblique", false}, {"hz", true},
                                   {"seconds", true}, {"platforms", false}});
    if (args.wants_help()) {
        std::fputs(kSimulateHelp, stdout);
        return 0;
    }
    args.expect_positional(0, "");
    SimulateOptions options;
    options.seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
    options.out_dir = args.value("out-dir").value_or(".");
    samples::prepare_output_folder(options.out_dir);
    samples::check_writable_file(options.out_dir + (args.has("platforms") ? "/platforms.png" : "/simulate.png"));
    options.dt = 1.0 / static_cast<double>(args.whole_number("hz", 2, 1000, 60));
    options.seconds = static_cast<double>(args.whole_number("seconds", 1, 3600, 120));
    options.oblique = args.has("oblique");
    return args.has("platforms") ? simulate_platforms(options) : simulate_default_level(options);
}

}  // namespace nl::cli
