// The builder's inputs made safe to use: the agent type checked, and the settings resolved from the
// defaults, the optional nl_recast_settings struct and the optional JSON object, each value checked.
// Every function throws BuildFailure naming the bad field.
#pragma once

#include <string>

#include "navlink/navlink.h"
#include "navlink/recast.h"

namespace nl::recast {

// INVALID_ARGUMENT unless radius >= 0, height > 0, max_climb >= 0 and 0 <= max_slope < 90, all finite.
void validate_agent(const nl_agent_type& agent);

// Defaults, then def.settings (an nl_recast_settings of at least the first version's size; fields past
// its size keep their defaults), then def.settings_json. INVALID_ARGUMENT for an unknown key, a value
// of the wrong type or out of range (the field named), PARSE_ERROR for malformed JSON (with the
// parser's position).
nl_recast_settings resolve_settings(const nl_navmesh_build_def& def);

// Every setting as a JSON object that resolve_settings reads back to the same settings (the partition
// by name, the filters as booleans).
std::string settings_to_json(const nl_recast_settings& settings);

}  // namespace nl::recast
