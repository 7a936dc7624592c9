#include "level_frame_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "link_files.h"
#include "sample_error.h"

namespace nl::cli {
namespace {

struct NamedUnit {
    const char* name;
    float metres;
};
constexpr NamedUnit kUnits[] = {{"m", 1.0f},     {"cm", 0.01f},   {"mm", 0.001f},
                                {"km", 1000.0f}, {"in", 0.0254f}, {"ft", 0.3048f}};

float metres_per_unit(const std::string& text) {
    for (const NamedUnit& unit : kUnits)
        if (text == unit.name) return unit.metres;
    char* end = nullptr;
    const float number = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(number) || !(number > 0.0f))
        throw samples::SampleError(
            "--units must be m, cm, mm, km, in, ft or the metres in one unit of LEVEL (0.01 for "
            "centimetres), got '" +
            text + "'");
    return number;
}

}  // namespace

std::vector<samples::OptionSpec> with_level_frame_options(std::vector<samples::OptionSpec> options) {
    options.push_back({"clockwise", false});
    options.push_back({"units", true});
    options.push_back({"up", true});
    return options;
}

samples::LevelFrame level_frame(const samples::Arguments& args) {
    samples::LevelFrame frame;
    if (args.has("clockwise")) frame.flags |= NL_MESH_CLOCKWISE;
    if (const auto units = args.value("units")) frame.metres_per_unit = metres_per_unit(*units);
    if (const auto up = args.value("up")) {
        if (*up == "y")
            frame.up_axis = NL_UP_AXIS_Y;
        else if (*up == "z")
            frame.up_axis = NL_UP_AXIS_Z;
        else
            throw samples::SampleError("--up must be y or z, got '" + *up + "'");
    }
    return frame;
}

uint32_t load_links_option(const samples::Arguments& args, nl_world* world, nl_navmesh_id navmesh,
                           const std::string& path) {
    try {
        return samples::load_links_file(world, navmesh, path, args.has("any-body") ? NL_LINKS_LOAD_ANY_BODY : 0u);
    } catch (const samples::SampleError& e) {
        if (std::string(e.what()).find("NL_LINKS_LOAD_ANY_BODY") == std::string::npos) throw;
        throw samples::SampleError(std::string(e.what()) + " (navlink: --any-body)");
    }
}

void hint_level_frame(const nl_navmesh_info& info, const std::string& level_path) {
    const char* level = level_path.c_str();
    if (info.turned_over_mesh_count > 0)
        std::fprintf(stderr, "hint: if %s was exported with clockwise fronts (Godot's convention), pass --clockwise\n",
                     level);
    if (info.build_warnings & NL_BUILD_WARNING_Z_UP)
        std::fprintf(
            stderr,
            "hint: if %s was exported with z up (Blender's, 3ds Max's own frame), pass --up z (--up y says y is up)\n",
            level);
    if (info.build_warnings & NL_BUILD_WARNING_UNITS)
        std::fprintf(
            stderr,
            "hint: if %s is not in metres, pass --units (cm, mm, in, ft, km or the metres in one unit; --units m "
            "says metres)\n",
            level);
}

}  // namespace nl::cli
