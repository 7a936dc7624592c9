// The demo's cast, shared by `navlink demo`, the viewer and the Godot-style harness: three agents
// with the same body and different abilities. The default link settings generate every traversal
// the most able of them can take (gaps up to 4 m, rim to rim).
#pragma once

#include <navlink/navlink.h>

#include <vector>

#include "agent_profile.h"

namespace nl::samples {

// A walker (no jumps, no drops), a short jumper (gaps of 2 m, 1 m up, no drops) and a long jumper
// who may drop (gaps of 3.5 m, 1.5 m up, drops of 4 m), in that order. All have Recast's default body.
std::vector<AgentProfile> demo_agents();

}  // namespace nl::samples
