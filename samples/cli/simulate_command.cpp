// navlink simulate: the demo's three bodies as agents (nl_agent_*) on the default level, or agents
// on the host's own level between --from and --to, stepped until each has arrived; prints when and
// where, and draws the tracks they really took. With --platforms, passengers ride the moving
// platforms beside the level instead.
#include <cstdio>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "arguments.h"
#include "commands.h"
#include "demo_setup.h"
#include "help_text.h"
#include "generation_settings.h"
#include "level_frame_options.h"
#include "level_generator.h"
#include "link_files.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "output_paths.h"
#include "palette.h"
#include "picture_export.h"
#include "sample_error.h"
#include "simulate_scenes.h"
#include "simulation.h"

namespace nl::cli {

namespace {

// The agents of `profiles` leave `start` for `goal` on `level`, stepped as `options` say; prints their
// run and writes simulate.png. Returns 0 when every agent arrived, 1 when one did not.
int play(NavigableLevel& level, const nl_link_generation_report& report,
         const std::vector<samples::AgentProfile>& profiles, const float start[3], const float goal[3],
         const SimulateOptions& options, const std::string& picture_title) {
    std::printf("NavLink simulate: %s, %u jumps and %u drops\n", level.level().name.c_str(), report.jump_links,
                report.drop_links);
    std::printf("  %zu agent%s leave (%.1f, %.1f, %.1f) for (%.1f, %.1f, %.1f), stepped every %.1f ms\n\n",
                profiles.size(), profiles.size() == 1 ? "" : "s", start[0], start[1], start[2], goal[0], goal[1],
                goal[2], options.dt * 1000.0);

    Simulation simulation(level.world());
    for (const samples::AgentProfile& profile : profiles) simulation.add_agent(profile, level.navmesh(), start, goal);
    simulation.run(options.dt, options.seconds);
    simulation.print_table();

    PictureRequest request;
    request.path = options.out_dir + "/simulate.png";
    request.oblique = options.oblique;
    request.title = picture_title;
    write_picture(level.level(), samples::read_navmesh_contents(level.world(), level.navmesh()), simulation.tracks(),
                  request,
                  {{"start", {start[0], start[1], start[2]}, picture::palette::kText},
                   {"goal", {goal[0], goal[1], goal[2]}, picture::palette::kText}});
    std::printf("\nwrote %s\n", request.path.c_str());
    if (!simulation.all_arrived()) std::printf("not every agent arrived\n");
    return simulation.all_arrived() ? 0 : 1;
}

}  // namespace

int simulate_default_level(const SimulateOptions& options) {
    const levelgen::GeneratedLevel generated = levelgen::generate_default_level(options.seed);
    const std::vector<samples::AgentProfile> profiles = samples::demo_agents();
    const std::string seed = std::to_string(options.seed);
    NavigableLevel level(generated, "generated default level (seed " + seed + ")", profiles[0].body, "");
    const nl_link_generation_report report = level.generate_links(nl_default_link_settings());
    return play(level, report, profiles, generated.marker("start")->position, generated.marker("goal")->position,
                options, "navlink simulate: the tracks three agents took (seed " + seed + ")");
}

int simulate_level(const samples::Arguments& args, const SimulateOptions& options) {
    float from[3], to[3];
    samples::parse_point(args.required("from"), "--from", from);
    samples::parse_point(args.required("to"), "--to", to);
    // One agent of --agent's body and capabilities, or the demo's three (a walker, a short jumper, a
    // long jumper) on the navmesh built for the first one's body.
    const std::vector<samples::AgentProfile> profiles =
        args.has("agent") ? std::vector<samples::AgentProfile>{samples::read_agent_file(*args.value("agent"))}
                          : samples::demo_agents();
    const samples::GenerationSettings settings = args.has("settings")
                                                     ? samples::read_generation_settings_file(*args.value("settings"))
                                                     : samples::GenerationSettings();
    NavigableLevel level(args.positional()[0], std::nullopt, profiles[0].body, settings.recast_json, true, std::nullopt,
                         level_frame(args));
    nl_link_generation_report report = nl_link_generation_report_init();
    if (const auto links = args.value("links"))
        load_links_option(args, level.world(), level.navmesh(), *links);
    else
        report = level.generate_links(settings.links);
    if (args.has("links")) {
        const samples::NavmeshContents contents = samples::read_navmesh_contents(level.world(), level.navmesh());
        for (const nl_link& link : contents.links) {
            report.jump_links += link.kind == NL_LINK_JUMP;
            report.drop_links += link.kind == NL_LINK_DROP;
        }
    }
    return play(level, report, profiles, from, to, options, "navlink simulate: " + args.positional()[0]);
}

int run_simulate(int argc, char** argv) {
    const samples::Arguments args("navlink simulate", "simulate", argc, argv, 2,
                                  with_level_frame_options({{"seed", true},
                                                            {"out-dir", true},
                                                            {"oblique", false},
                                                            {"hz", true},
                                                            {"seconds", true},
                                                            {"platforms", false},
                                                            {"from", true},
                                                            {"to", true},
                                                            {"agent", true},
                                                            {"links", true},
                                                            {"settings", true},
                                                            {"any-body", false}}));
    if (args.wants_help()) {
        std::fputs(kSimulateHelp, stdout);
        return 0;
    }
    const bool own_level = !args.positional().empty();
    if (own_level) {
        args.expect_positional(1, "LEVEL.obj");
        for (const char* generated_only : {"seed", "platforms"})
            if (args.has(generated_only))
                throw samples::SampleError(std::string("--") + generated_only +
                                           " is for the generated default level, not " + args.positional()[0]);
    } else {
        for (const char* level_only :
             {"from", "to", "agent", "links", "settings", "clockwise", "units", "up", "any-body"})
            if (args.has(level_only)) throw samples::SampleError(std::string("--") + level_only + " needs LEVEL.obj");
    }
    SimulateOptions options;
    options.seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
    options.out_dir = args.value("out-dir").value_or(".");
    samples::prepare_output_folder(options.out_dir);
    samples::check_writable_file(options.out_dir + (args.has("platforms") ? "/platforms.png" : "/simulate.png"));
    options.dt = 1.0 / static_cast<double>(args.whole_number("hz", 2, 1000, 60));
    options.seconds = static_cast<double>(args.whole_number("seconds", 1, 3600, 120));
    options.oblique = args.has("oblique");
    if (own_level) return simulate_level(args, options);
    return args.has("platforms") ? simulate_platforms(options) : simulate_default_level(options);
}

}  // namespace nl::cli
