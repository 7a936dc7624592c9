// Provenance: what a navmesh and its links were made for and with, kept beside them in the world and saved with
// them, so that a baked file says what it was baked for (navlink info, nl_navmesh_load).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "util/handle.h"

namespace nl {

// What a navmesh's links were generated with, as JSON texts (empty: nothing recorded).
struct LinkProvenance {
    std::string settings;  // the link generation settings (link_settings_to_json)
    // Each link-kind plugin that ran: {"KIND": {"plugin": name, "version": v, "settings": {...}}}.
    std::string plugins;
};

struct NavMeshProvenance {
    std::string builder;  // the builder plugin's name; empty: polygons handed over by the host
    // The settings it built with, as a JSON object: complete when the builder said what it used
    // (the Recast builder does), else as it was given; empty: neither.
    std::string builder_settings;
    uint64_t level_hash = 0;  // of the triangles it was built from (level_hash.h); 0: not built from the level
    LinkProvenance links;     // of its generated links
    // The meshes it was built on that looked wound clockwise (level/winding_check.h): the build's
    // warning. Not kept in navmesh files.
    std::vector<Handle> turned_over_meshes;
    // What the build warned of about its level: BuildWarning bits. Not kept in navmesh files.
    uint32_t warnings = 0;
};

// A navmesh build's warnings about the level it was given (the log says each in words).
enum BuildWarning : uint32_t {
    kWarnedClockwise = 1u << 0,  // meshes look wound clockwise (turned_over_meshes)
    kWarnedUnits = 1u << 1,      // the level's size against the agent's suggests other units than metres
    kWarnedZUp = 1u << 2,        // the level would hold much more floor with z up
};

}  // namespace nl
