// navlink path: plans one path over a level's navmesh and a links file, or over a baked navmesh file
// and its links, and prints it.
#include <cstdio>

#include "arguments.h"
#include "commands.h"
#include "generation_settings.h"
#include "help_text.h"
#include "island_colors.h"
#include "link_files.h"
#include "level_frame_options.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "navmesh_files.h"
#include "output_paths.h"
#include "palette.h"
#include "path_output.h"
#include "path_plan.h"
#include "picture_export.h"
#include "sample_error.h"
#include "tile_bake.h"

namespace nl::cli {

namespace {

// Prints the plan as text or JSON, with what was asked; the exit status: 0 when it arrives.
int report_path(nl_world* world, nl_navmesh_id navmesh, const samples::PlannedPath& path,
                const std::vector<nl_link>& links, const float from[3], const float to[3], const float search[3],
                const nl_agent_capabilities& agent, bool json) {
    const AskedPath asked = asked_path(world, navmesh, path, from, to, search, agent);
    if (json)
        std::fputs(path_json(path, links, asked).c_str(), stdout);
    else
        print_path_text(stdout, path, links, asked);
    return path.result.outcome == NL_PATH_COMPLETE ? 0 : 1;
}

}  // namespace

int run_path(int argc, char** argv) {
    const samples::Arguments args("navlink path", "path", argc, argv, 2,
                                  with_level_frame_options({{"links", true},
                                                            {"from", true},
                                                            {"to", true},
                                                            {"search", true},
                                                            {"agent", true},
                                                            {"navmesh", true},
                                                            {"settings", true},
                                                            {"json", false},
                                                            {"png", true},
                                                            {"oblique", false},
                                                            {"link-numbers", false},
                                                            {"roofs", false},
                                                            {"any-body", false}}));
    if (args.wants_help()) {
        std::fputs(kPathHelp, stdout);
        return 0;
    }
    args.expect_positional(1, "LEVEL.obj or NAVMESH.nlnav");
    const std::string& input = args.positional()[0];
    const bool tiles = is_tile_bake(input);
    const bool baked =
        tiles || samples::is_navmesh_file(input) ||
        (input.size() > 6 && input.compare(input.size() - 6, 6, ".nlnav") == 0);  // a damaged one: say why
    float from[3], to[3];
    samples::parse_point(args.required("from"), "--from", from);
    samples::parse_point(args.required("to"), "--to", to);
    const nl_path_request_def defaults = nl_default_path_request_def();
    float search[3] = {defaults.search_half_extents[0], defaults.search_half_extents[1],
                       defaults.search_half_extents[2]};
    if (const auto box = args.value("search")) {
        samples::parse_point(*box, "--search", search);
        if (!(search[0] > 0.0f && search[1] > 0.0f && search[2] > 0.0f))
            throw samples::SampleError("--search must be three half extents above 0, in metres (got '" + *box + "')");
    }
    const samples::AgentProfile agent =
        args.has("agent") ? samples::read_agent_file(*args.value("agent")) : samples::default_agent_profile();
    const samples::GenerationSettings settings = args.has("settings")
                                                     ? samples::read_generation_settings_file(*args.value("settings"))
                                                     : samples::GenerationSettings();

    if (baked) {
        // The navmesh and its links as baked: nothing is built, and there is no level to draw.
        for (const char* level_only :
             {"navmesh", "settings", "png", "oblique", "link-numbers", "roofs", "clockwise", "units", "up"})
            if (args.has(level_only))
                throw samples::SampleError(std::string("--") + level_only + " needs LEVEL.obj: " +
                                           args.positional()[0] + " is a baked navmesh file, planned over as it is");
        samples::World world;
        const nl_navmesh_id navmesh =
            tiles ? load_tile_bake(world.get(), input) : samples::load_navmesh_file(world.get(), args.positional()[0]);
        if (const auto links = args.value("links")) load_links_option(args, world.get(), navmesh, *links);
        const samples::PlannedPath path =
            samples::find_path(world.get(), navmesh, from, to, agent.capabilities, search);
        const samples::NavmeshContents contents = samples::read_navmesh_contents(world.get(), navmesh);
        return report_path(world.get(), navmesh, path, contents.links, from, to, search, agent.capabilities,
                           args.has("json"));
    }
    if (const auto png = args.value("png")) samples::check_writable_file(*png);
    NavigableLevel level(args.positional()[0], args.value("navmesh"), agent.body, settings.recast_json, args.has("png"),
                         std::nullopt, level_frame(args));
    // Without --links the navmesh is walked alone.
    if (const auto links = args.value("links")) load_links_option(args, level.world(), level.navmesh(), *links);
    const samples::PlannedPath path =
        samples::find_path(level.world(), level.navmesh(), from, to, agent.capabilities, search);
    const samples::NavmeshContents contents = samples::read_navmesh_contents(level.world(), level.navmesh());
    const int status = report_path(level.world(), level.navmesh(), path, contents.links, from, to, search,
                                   agent.capabilities, args.has("json"));

    if (const auto png = args.value("png")) {
        PictureRequest request;
        request.path = *png;
        request.oblique = args.has("oblique");
        request.link_numbers = args.has("link-numbers");
        request.roofs = args.has("roofs");
        request.islands = picture::read_islands(level.world(), level.navmesh(), agent.capabilities,
                                                args.has("agent") ? agent.name : "default body");
        request.title = "navlink path " + level.level().name;
        picture::PathLayer layer{agent.name + ": " + samples::outcome_name(path.result.outcome),
                                 picture::palette::agent(1), path.points};
        const std::string counted = write_picture(level.level(), contents, {layer}, request,
                                                  {{"from", {from[0], from[1], from[2]}, picture::palette::kText},
                                                   {"to", {to[0], to[1], to[2]}, picture::palette::kText}});
        if (!args.has("json")) std::printf("wrote %s (%s)\n", png->c_str(), counted.c_str());
    }
    return status;
}

}  // namespace nl::cli
