// A level ready for links and paths: a world holding the level geometry and one navmesh for an
// agent's body, built by Recast or handed over from an OBJ file. Shared by generate, path and demo.
#pragma once

#include <navlink/navlink.h>

#include <optional>
#include <string>

#include "agent_profile.h"
#include "generation_report_text.h"
#include "level.h"
#include "level_generator.h"
#include "world.h"

namespace nl::cli {

class NavigableLevel {
public:
    // Loads the plugin library `plugin_path` (if given) and LEVEL.obj given as `frame` says (and its
    // triangles too when `for_drawing`); builds the navmesh for `body` with `recast_json` settings
    // unless `navmesh_path` is given, and names on stderr the option that would answer each of the
    // build's warnings (a level wound clockwise, in other units, with z up). Throws SampleError.
    NavigableLevel(const std::string& level_path, const std::optional<std::string>& navmesh_path,
                   const nl_agent_type& body, const std::string& recast_json, bool for_drawing,
                   const std::optional<std::string>& plugin_path = std::nullopt, const samples::LevelFrame& frame = {});
    // Registers a generated level and builds its navmesh.
    NavigableLevel(const levelgen::GeneratedLevel& generated, const std::string& name, const nl_agent_type& body,
                   const std::string& recast_json);

    nl_world* world() const { return world_.get(); }
    nl_navmesh_id navmesh() const { return navmesh_; }
    const samples::Level& level() const { return level_; }
    GenerationTimes& times() { return times_; }

    // Generates links with `settings` (a progress bar when stdout is a terminal). Throws SampleError.
    nl_link_generation_report generate_links(const nl_link_settings& settings);

private:
    samples::World world_;
    samples::Level level_;
    nl_navmesh_id navmesh_{};
    GenerationTimes times_;
};

}  // namespace nl::cli
