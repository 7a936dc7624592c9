// navlink generate and navlink bake: navmesh, links, report (and a picture); generate writes the
// links as JSON, bake the navmesh and its links as a baked navmesh file.
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "arguments.h"
#include "generation_report_text.h"
#include "commands.h"
#include "generation_settings.h"
#include "help_text.h"
#include "island_colors.h"
#include "json_text.h"
#include "link_files.h"
#include "level_frame_options.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "navmesh_files.h"
#include "output_paths.h"
#include "picture_export.h"
#include "sample_error.h"
#include "text_file.h"
#include "tile_bake.h"

namespace nl::cli {

namespace {

enum class Output { LinksJson, NavMeshFile };

// --tile-size N (bake only): cells per tile side, 16..4096 as nl_recast_settings.tile_size.
std::optional<int> tile_size_option(const samples::Arguments& args, bool bake) {
    const auto given = args.value("tile-size");
    if (!given) return std::nullopt;
    if (!bake) throw samples::SampleError("--tile-size is for navlink bake (a folder of tiles)");
    char* end = nullptr;
    const long cells = std::strtol(given->c_str(), &end, 10);
    if (end == given->c_str() || *end != '\0' || cells < 16 || cells > 4096)
        throw samples::SampleError("--tile-size must be a whole number of cells from 16 to 4096 (got '" + *given +
                                   "')");
    return static_cast<int>(cells);
}

// The builder's settings JSON with its tile size set.
std::string with_tile_size(const std::string& recast_json, int cells) {
    nlohmann::json settings = recast_json.empty() ? nlohmann::json::object()
                                                  : samples::parse_json_text(recast_json, "the \"recast\" settings");
    settings["tile_size"] = cells;
    return settings.dump();
}

int generate(int argc, char** argv, Output output) {
    const bool bake = output == Output::NavMeshFile;
    const samples::Arguments args(bake ? "navlink bake" : "navlink generate", bake ? "bake" : "generate", argc, argv, 2,
                                  with_level_frame_options({{"out", true},
                                                            {"navmesh", true},
                                                            {"agent", true},
                                                            {"settings", true},
                                                            {"plugin", true},
                                                            {"png", true},
                                                            {"oblique", false},
                                                            {"link-numbers", false},
                                                            {"roofs", false},
                                                            {"tile-size", true}}));
    if (args.wants_help()) {
        std::fputs(bake ? kBakeHelp : kGenerateHelp, stdout);
        return 0;
    }
    args.expect_positional(1, "LEVEL.obj");
    const std::string out = args.required("out");
    const std::optional<int> tile_size = tile_size_option(args, bake);
    // Every output is checked before the work, so a bad --png fails before --out is written.
    if (!tile_size) samples::check_writable_file(out);
    if (const auto png = args.value("png")) samples::check_writable_file(*png);
    // Read every input before the slow work, so a bad file fails at once.
    const samples::AgentProfile agent =
        args.has("agent") ? samples::read_agent_file(*args.value("agent")) : samples::default_agent_profile();
    // Links are generated for a body and shared by every agent with it; what each agent can take is
    // chosen when its path is planned. A capability here would silently change nothing.
    if (!agent.first_capability_key.empty())
        throw samples::SampleError(*args.value("agent") + ": " + agent.first_capability_key +
                                   " is a capability: capabilities choose links when a path is planned (navlink path "
                                   "--agent); generate reads only the body (radius, height, max_climb, max_slope)");
    samples::GenerationSettings settings = args.has("settings")
                                               ? samples::read_generation_settings_file(*args.value("settings"))
                                               : samples::GenerationSettings();
    if (tile_size) settings.recast_json = with_tile_size(settings.recast_json, *tile_size);

    NavigableLevel level(args.positional()[0], args.value("navmesh"), agent.body, settings.recast_json, args.has("png"),
                         args.value("plugin"), level_frame(args));
    const nl_link_generation_report report = level.generate_links(settings.links);
    TileBakeWritten tiles;
    if (tile_size)
        tiles = write_tile_bake(level.world(), level.navmesh(), out);
    else if (bake)
        samples::save_navmesh_file(level.world(), level.navmesh(), out);
    else
        samples::write_text_file(out, samples::links_json(level.world(), level.navmesh()));

    const samples::NavmeshContents contents = samples::read_navmesh_contents(level.world(), level.navmesh());
    std::printf("level: %s (%u triangles)\n", level.level().name.c_str(), level.level().info.triangle_count);
    std::printf("navmesh: %zu polygons, %zu boundary edges (%s)\n", contents.polygons.size(),
                contents.boundary_edges.size(),
                args.has("navmesh") ? args.value("navmesh")->c_str() : "built by recast");
    print_generation_report(stdout, report, contents.links, level.times());
    if (tile_size)
        std::printf("wrote %s: %zu tiles written (%llu bytes), %zu kept (the same content hash), %zu stale removed\n",
                    out.c_str(), tiles.written, static_cast<unsigned long long>(tiles.bytes), tiles.kept,
                    tiles.removed);
    else
        std::printf("wrote %s\n", out.c_str());
    if (const auto png = args.value("png")) {
        PictureRequest request;
        request.path = *png;
        request.oblique = args.has("oblique");
        request.link_numbers = args.has("link-numbers");
        request.roofs = args.has("roofs");
        // Islands for the body navlink path plans for without --agent: one that takes every link the
        // default settings generate.
        const samples::AgentProfile body = samples::default_agent_profile();
        request.islands = picture::read_islands(level.world(), level.navmesh(), body.capabilities, "default body");
        request.title = std::string(bake ? "navlink bake " : "navlink generate ") + level.level().name;
        const std::string counted = write_picture(level.level(), contents, {}, request);
        std::printf("wrote %s (%s)\n", png->c_str(), counted.c_str());
    }
    return 0;
}

}  // namespace

int run_generate(int argc, char** argv) { return generate(argc, argv, Output::LinksJson); }
int run_bake(int argc, char** argv) { return generate(argc, argv, Output::NavMeshFile); }

}  // namespace nl::cli
