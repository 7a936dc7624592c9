// An agent as the samples describe it: the body its navmesh is built for (nl_agent_type) and what
// that body can do on links (nl_agent_capabilities), read from a JSON file:
//
//   {"name": "long jumper", "radius": 0.6, "height": 2.0, "max_climb": 0.9, "max_slope": 45,
//    "max_jump_distance": 6, "max_jump_height": 1.5, "max_drop_height": 4, "abilities": 0}
//
// Every key is optional (defaults: default_agent_profile()); an unknown key, a wrong type or a value
// out of range is refused with the key named.
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

struct AgentProfile {
    std::string name;
    nl_agent_type body;                  // for the navmesh (radius, height, max_climb, max_slope)
    nl_agent_capabilities capabilities;  // for paths; capabilities.radius is body.radius
    std::string first_capability_key;    // the first capability key the file gave ("" if none)
};

// Recast's default body (radius 0.6, height 2, climb 0.9, slope 45) that takes every link the
// default link settings generate: jumps up to 4 m across and 1.5 m up, drops up to 5 m.
AgentProfile default_agent_profile();

// Parses an agent JSON object over default_agent_profile(). `source` names the file in errors.
// Throws SampleError("SOURCE: KEY must be ...") on any problem.
AgentProfile parse_agent_json(const std::string& text, const std::string& source);

// Reads and parses an agent file.
AgentProfile read_agent_file(const std::string& path);

}  // namespace nl::samples
