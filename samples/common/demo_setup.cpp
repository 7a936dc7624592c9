#include "demo_setup.h"

namespace nl::samples {
namespace {

AgentProfile agent(const char* name, float jump_distance, float jump_height, float drop_height) {
    AgentProfile profile = default_agent_profile();
    profile.name = name;
    profile.capabilities.max_jump_distance = jump_distance;
    profile.capabilities.max_jump_height = jump_height;
    profile.capabilities.max_drop_height = drop_height;
    return profile;
}

}  // namespace

std::vector<AgentProfile> demo_agents() {
    return {agent("walker", 0.0f, 0.0f, 0.0f), agent("short jumper", 2.0f, 1.0f, 0.0f),
            agent("long jumper", 3.5f, 1.5f, 4.0f)};
}

}  // namespace nl::samples
