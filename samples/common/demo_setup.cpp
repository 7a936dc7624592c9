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
    return {agent("walker", 0.0f, 0.0f, 0.0f), agent("short jumper", 3.8f, 1.0f, 0.0f),
            agent("long jumper", 6.0f, 1.5f, 4.0f)};
}

nl_link_settings demo_link_settings() {
    nl_link_settings settings = nl_default_link_settings();
    settings.max_link_distance = 6.5f;
    return settings;
}

}  // namespace nl::samples
