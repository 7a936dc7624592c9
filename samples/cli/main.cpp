// navlink: the command-line tool over the NavLink C ABI (generate links, plan paths, run the demo).
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include <navlink/navlink.h>
#include <navlink/version.h>

#include "commands.h"
#include "help_text.h"
#include "sample_error.h"

namespace {

// Errors are one line: a library or parser message with a line break in it is joined up.
std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(
            stderr,
            "navlink: missing command: demo, simulate, generate, bake, path, info or level (see navlink --help)\n");
        return 2;
    }
    if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        std::fputs(nl::cli::kMainHelp, stdout);
        return 0;
    }
    if (!std::strcmp(argv[1], "--version")) {
        // Both: a tool run against another libnavlink than it was built with shows it here.
        const nl_version library = nl_get_version();
        std::printf("navlink %d.%d.%d (libnavlink %d.%d.%d)\n", NL_VERSION_MAJOR, NL_VERSION_MINOR, NL_VERSION_PATCH,
                    static_cast<int>(library.major), static_cast<int>(library.minor), static_cast<int>(library.patch));
        return 0;
    }
    const std::string command = argv[1];
    try {
        if (command == "generate") return nl::cli::run_generate(argc, argv);
        if (command == "bake") return nl::cli::run_bake(argc, argv);
        if (command == "info") return nl::cli::run_info(argc, argv);
        if (command == "path") return nl::cli::run_path(argc, argv);
        if (command == "demo") return nl::cli::run_demo(argc, argv);
        if (command == "simulate") return nl::cli::run_simulate(argc, argv);
        if (command == "level") return nl::cli::run_level(argc, argv);
        throw nl::samples::SampleError("unknown command '" + command + "' (see navlink --help)");
    } catch (const nl::samples::SampleError& e) {
        std::fprintf(stderr, "navlink: %s\n", one_line(e.what()).c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "navlink: %s: %s\n", command.c_str(), one_line(e.what()).c_str());
        return 2;
    }
}
