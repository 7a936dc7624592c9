// navlink-viewer: a level, its navmesh, links and the demo agents' paths, in a window when there is
// a display (click to set the destination), or as a scripted sequence of PNG frames when there is
// none (SDL_VIDEODRIVER=dummy, no DISPLAY) or --headless is given.
#include <SDL2/SDL.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "arguments.h"
#include "generation_settings.h"
#include "headless_script.h"
#include "interactive_viewer.h"
#include "platforms_script.h"
#include "sample_error.h"
#include "viewer_session.h"

namespace {

const char* const kHelp =
    "usage: navlink-viewer [LEVEL.obj] [--links LINKS.json] [--seed N] [--oblique] [--headless]\n"
    "                      [--frames DIR] [--platforms] [--from X,Y,Z --to X,Y,Z] [--settings GEN.json]\n"
    "                      [--tile-size N] [--stream-tiles R] [--agent 1|2|3]\n"
    "\n"
    "Shows a level (default: the generated default level), its navmesh, its links (generated with the\n"
    "demo's settings unless --links) and the paths of the demo's agents (walker, short jumper, long\n"
    "jumper) from a start to a destination you click.\n"
    "With --platforms: the default level with moving platforms beside it (a shuttle across a chasm, a\n"
    "turning disc, a lift to an upper floor), which move by their timetables, and four agents riding\n"
    "them, each to its own destination.\n"
    "--from and --to place the start and the destination (else the level's own, or the middle).\n"
    "--settings: the link generator's settings and the navmesh builder's (\"recast\"), as navlink generate\n"
    "reads them; --tile-size N builds the navmesh in tiles of N cells (16..4096), drawn with their borders.\n"
    "--stream-tiles R: of a tiled navmesh, only the tiles within R metres of the chosen agent stay loaded\n"
    "(key T toggles it): tiles going out of range are saved and removed, those coming in added back, and\n"
    "the agent is sent along its way over every tile. --agent N chooses one agent (1 walker, 2 short\n"
    "jumper, 3 long jumper; default: all three) to send and follow.\n"
    "Without a display (or with --headless) it renders a scripted sequence of frames into DIR (default\n"
    "'.') as frame_NN.png instead; with --to or --stream-tiles, the agents' trip to the destination only.\n"
    "Exit status: with --to or --stream-tiles, 0 when every agent sent arrived and 1 when one did not;\n"
    "without, 1 when the script failed (a click that picked another place, an agent with a complete path\n"
    "that did not arrive); 2 on an error.\n"
    "\n"
    "keys:\n";

bool display_available() {
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return false;
    const char* driver = SDL_GetCurrentVideoDriver();
    return driver && std::strcmp(driver, "dummy") != 0 && std::strcmp(driver, "offscreen") != 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const nl::samples::Arguments args("navlink-viewer", "navlink-viewer", argc, argv, 1,
                                          {{"links", true},
                                           {"seed", true},
                                           {"oblique", false},
                                           {"headless", false},
                                           {"frames", true},
                                           {"platforms", false},
                                           {"from", true},
                                           {"to", true},
                                           {"settings", true},
                                           {"tile-size", true},
                                           {"stream-tiles", true},
                                           {"agent", true}});
        if (args.wants_help()) {
            std::printf("%s%s", kHelp, nl::picture::kViewerKeys);
            return 0;
        }
        if (args.positional().size() > 1)
            throw nl::samples::SampleError("unexpected argument '" + args.positional()[1] +
                                           "' (see navlink-viewer --help)");
        nl::picture::ViewerOptions options;
        if (!args.positional().empty()) options.level_path = args.positional()[0];
        options.links_path = args.value("links");
        options.seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
        options.platforms = args.has("platforms");
        if (options.platforms && options.level_path)
            throw nl::samples::SampleError(
                "--platforms stand beside the generated default level: give no LEVEL.obj "
                "(see navlink-viewer --help)");
        if (const auto settings = args.value("settings"))
            options.settings = nl::samples::read_generation_settings_file(*settings);
        if (args.has("tile-size"))
            options.settings.recast_json = nl::samples::with_tile_size(
                options.settings.recast_json, static_cast<uint32_t>(args.whole_number("tile-size", 16, 4096, 0)));
        if (args.has("agent")) {
            if (options.platforms)
                throw nl::samples::SampleError("--platforms send each passenger to its own destination: no --agent");
            options.agent = static_cast<size_t>(args.whole_number("agent", 1, 3, 1) - 1);
        }
        const bool stream = args.has("stream-tiles");
        if (stream) {
            const std::string text = *args.value("stream-tiles");
            char* end = nullptr;
            options.stream_radius = std::strtof(text.c_str(), &end);
            if (*end != '\0' || !std::isfinite(options.stream_radius) || options.stream_radius < 1.0f ||
                options.stream_radius > 100000.0f)
                throw nl::samples::SampleError("--stream-tiles must be a radius in metres from 1 to 100000 (got '" +
                                               text + "')");
            if (options.platforms) throw nl::samples::SampleError("--platforms: no --stream-tiles");
        }
        nl::picture::ViewSettings view;
        view.oblique = args.has("oblique");

        if (options.platforms && (args.has("from") || args.has("to")))
            throw nl::samples::SampleError("--platforms send each passenger to its own destination: no --from or --to");
        nl::picture::ViewerSession session(options);
        nl::picture::ViewerSession::Point point{};
        // Every agent (a session starts with all selected), as a trip the host asked for: one that
        // cannot start or go there is an error.
        if (const auto from = args.value("from")) {
            nl::samples::parse_point(*from, "--from", point.data());
            if (!session.set_start(point))
                throw nl::samples::SampleError("--from " + *from + ": not every agent can stand there (above)");
        }
        if (const auto to = args.value("to")) {
            nl::samples::parse_point(*to, "--to", point.data());
            if (!session.set_destination(point))
                throw nl::samples::SampleError("--to " + *to + ": not every agent can go there (above)");
        }
        if (stream && !session.set_streaming(true))
            throw nl::samples::SampleError(
                "--stream-tiles streams the tiles of a tiled navmesh: give --tile-size N (or \"tile_size\" in "
                "--settings' \"recast\")");
        const bool headless = args.has("headless") || !display_available();
        const std::string frames = args.value("frames").value_or(".");
        const int status = !headless                  ? nl::picture::run_interactive_viewer(session, view)
                           : options.platforms        ? nl::picture::run_platforms_script(session, view, frames)
                           : args.has("to") || stream ? nl::picture::run_headless_trip(session, view, frames)
                                                      : nl::picture::run_headless_script(session, view, frames);
        SDL_Quit();
        return status;
    } catch (const nl::samples::SampleError& e) {
        std::fprintf(stderr, "navlink-viewer: %s\n", e.what());
        return 2;
    }
}
