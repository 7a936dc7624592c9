// The agents of a world as the samples read them: every agent's state and the last step's events in
// bulk (the two-call pattern), an agent's corners ahead, an agent definition from a profile, and the
// names of states, reasons and events for printing.
#pragma once

#include <navlink/navlink.h>

#include <vector>

#include "agent_profile.h"

namespace nl::samples {

// The definition of an agent with `profile`'s body and capabilities standing at `position` of
// `navmesh`, at the default speeds.
nl_agent_def agent_def(const AgentProfile& profile, nl_navmesh_id navmesh, const float position[3]);

// Throw SampleError if the call fails.
std::vector<nl_agent_info> read_agents(const nl_world* world);
std::vector<nl_agent_event> read_agent_events(const nl_world* world);
nl_agent_info read_agent(const nl_world* world, nl_agent_id agent);
std::vector<nl_path_point> read_corners(const nl_world* world, nl_agent_id agent);

bool same_agent(nl_agent_id a, nl_agent_id b);
// Jumping, falling or traversing: taking a link.
bool in_the_air(nl_agent_state state);

// "walking", "jumping", ...; "link gone", "no path", ...; "path ready", "link started", ...
const char* agent_state_name(nl_agent_state state);
const char* agent_reason_name(nl_agent_reason reason);
const char* agent_event_name(nl_agent_event_kind kind);

}  // namespace nl::samples
