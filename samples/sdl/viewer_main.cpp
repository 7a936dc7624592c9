// navlink-viewer: a level, its navmesh, links and the demo agents' paths, in a window when there is
// a display (click to set the destination), or as a scripted sequence of PNG frames when there is
// none (SDL_VIDEODRIVER=dummy, no DISPLAY) or --headless is given.
#include <SDL2/SDL.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "arguments.h"
#include "headless_script.h"
#include "interactive_viewer.h"
#include "platforms_script.h"
#include "sample_error.h"
#include "viewer_session.h"

namespace {

const char* const kHelp =
    "usage: navlink-viewer [LEVEL.obj] [--links LINKS.json] [--seed N] [--oblique] [--headless]\n"
    "                      [--frames DIR] [--platforms] [--from X,Y,Z --to X,Y,Z]\n"
    "\n"
    "Shows a level (default: the generated default level), its navmesh, its links (generated with the\n"
    "demo's settings unless --links) and the paths of the demo's agents (walker, short jumper, long\n"
    "jumper) from a start to a destination you click.\n"
    "With --platforms: the default level with moving platforms beside it (a shuttle across a chasm, a\n"
    "turning disc, a lift to an upper floor), which move by their timetables, and four agents riding\n"
    "them, each to its own destination.\n"
    "--from and --to place the start and the destination (else the level's own, or the middle).\n"
    "Without a display (or with --headless) it renders a scripted sequence of frames into DIR (default\n"
    "'.') as frame_NN.png instead; with --to, the agents' trip there only.\n"
    "Exit status: with --to, 0 when every agent arrived and 1 when one did not; without, 1 when the\n"
    "script failed (a click that picked another place, an agent with a complete path that did not\n"
    "arrive); 2 on an error.\n"
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
                                           {"to", true}});
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
        const bool headless = args.has("headless") || !display_available();
        const std::string frames = args.value("frames").value_or(".");
        const int status = !headless           ? nl::picture::run_interactive_viewer(session, view)
                           : options.platforms ? nl::picture::run_platforms_script(session, view, frames)
                           : args.has("to")    ? nl::picture::run_headless_trip(session, view, frames)
                                               : nl::picture::run_headless_script(session, view, frames);
        SDL_Quit();
        return status;
    } catch (const nl::samples::SampleError& e) {
        std::fprintf(stderr, "navlink-viewer: %s\n", e.what());
        return 2;
    }
}
