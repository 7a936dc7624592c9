// The demo's cast, shared by `navlink demo`, the viewer and the Godot-style harness: three agents
// with the same body and different abilities, and link settings that generate every traversal the
// most able of them can take.
#pragma once

#include <navlink/navlink.h>

#include <vector>

#include "agent_profile.h"

namespace nl::samples {

// A walker (no jumps, no drops), a short jumper (3.8 m across, 1 m up, no drops) and a long jumper
// who may drop (6 m across, 1.5 m up, drops of 4 m), in that order. All have Recast's default body.
std::vector<AgentProfile> demo_agents();

// Default settings, but links up to 6.5 m long: the long jumper's 6 m jumps, measured between
// navmesh edges, need them (the default 4 m suits Recast's default agent jumping 2.5 m gaps).
nl_link_settings demo_link_settings();

}  // namespace nl::samples
