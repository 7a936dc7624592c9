// navlink level: the generated default level as an OBJ file.
#include <cstdio>

#include "arguments.h"
#include "commands.h"
#include "help_text.h"
#include "level_generator.h"
#include "output_paths.h"
#include "text_file.h"

namespace nl::cli {

int run_level(int argc, char** argv) {
    const samples::Arguments args("navlink level", "level", argc, argv, 2, {{"out", true}, {"seed", true}});
    if (args.wants_help()) {
        std::fputs(kLevelHelp, stdout);
        return 0;
    }
    args.expect_positional(0, "");
    const std::string out = args.required("out");
    samples::check_writable_file(out);
    const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
    const levelgen::GeneratedLevel level = levelgen::generate_default_level(seed);
    samples::write_text_file(out, level.to_obj());
    std::printf("wrote %s: generated default level (seed %u), %u triangles\n", out.c_str(), seed,
                level.triangle_count());
    for (const levelgen::Marker& m : level.markers)
        std::printf("  %s: %.2f,%.2f,%.2f\n", m.name.c_str(), m.position[0], m.position[1], m.position[2]);
    return 0;
}

}  // namespace nl::cli
