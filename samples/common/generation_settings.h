// Settings of a generation, read from one JSON file: the link generator's settings (the keys
// nl_link_settings_from_json knows: docs/link-generation.md), plus two optional objects passed on as
// they are, "recast" (the navmesh builder's settings, navlink/recast.h) and "plugins" (link-kind
// plugins' settings, keyed by kind name):
//
//   {"max_jump_gap": 6, "drop_angles": [0], "recast": {"cell_size": 0.2}}
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

struct GenerationSettings {
    nl_link_settings links = nl_default_link_settings();
    std::string recast_json;   // empty: the builder's defaults
    std::string plugins_json;  // empty: none; links.plugin_settings_json points here

    GenerationSettings() = default;
    GenerationSettings(const GenerationSettings& other) { *this = other; }
    GenerationSettings& operator=(const GenerationSettings& other);  // keeps the pointer on its own copy
};

// Parses a settings JSON object; `source` names the file in errors. Throws SampleError with the
// library's message (which names the key) for a bad link setting.
GenerationSettings parse_generation_settings(const std::string& text, const std::string& source);

GenerationSettings read_generation_settings_file(const std::string& path);

// The builder's settings object `recast_json` (empty: the defaults) with "tile_size" set to
// `tile_size` cells: the navmesh built in tiles of that side (navlink/recast.h).
std::string with_tile_size(const std::string& recast_json, uint32_t tile_size);

}  // namespace nl::samples
