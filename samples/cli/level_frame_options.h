// The options that say how LEVEL.obj is given, shared by every command that reads one: --clockwise,
// --units and --up (nl_mesh_def's NL_MESH_CLOCKWISE, metres_per_unit and up_axis), and the hints
// that name them when a navmesh build warns of what they would fix.
#pragma once

#include <navlink/navlink.h>

#include <string>
#include <vector>

#include "arguments.h"
#include "level.h"

namespace nl::cli {

// `options` and the three above.
std::vector<samples::OptionSpec> with_level_frame_options(std::vector<samples::OptionSpec> options);

// What the options say; throws SampleError for a unit or axis it does not know.
samples::LevelFrame level_frame(const samples::Arguments& args);

// Loads LINKS.json into the navmesh, with NL_LINKS_LOAD_ANY_BODY when --any-body is given; a refusal
// of links for another body names --any-body. Throws SampleError.
uint32_t load_links_option(const samples::Arguments& args, nl_world* world, nl_navmesh_id navmesh,
                           const std::string& path);

// Says on stderr which option would answer each of the build's warnings (the library's own warning,
// printed before, names the C API's field).
void hint_level_frame(const nl_navmesh_info& info, const std::string& level_path);

}  // namespace nl::cli
