#include "navigation_server.h"

#include "world_agents.h"
#include "navigation_agent.h"
#include "sample_error.h"

namespace nl::godot_style {

nl_agent_id NavigationServer::add_agent(nl_agent_def def, NavigationAgent& node) {
    // The key, not the node's address, goes into NavLink: an event can never reach a freed node.
    def.user_data = next_key_++;
    nl_agent_id id{};
    samples::check(nl_agent_add(world_.get(), &def, &id), "adding agent " + node.name());
    nodes_[def.user_data] = &node;
    return id;
}

void NavigationServer::remove_agent(nl_agent_id agent) {
    nl_agent_info info = nl_agent_info_init();
    if (NL_FAILED(nl_agent_get_info(world_.get(), agent, &info))) return;
    nodes_.erase(info.user_data);
    nl_agent_remove(world_.get(), agent);
}

void NavigationServer::sync(double delta) {
    samples::check(nl_world_step(world_.get(), static_cast<float>(delta)), "moving the agents");
    for (const nl_agent_event& event : samples::read_agent_events(world_.get())) {
        const auto node = nodes_.find(event.user_data);
        if (node != nodes_.end()) node->second->on_navigation_event(event);
    }
}

}  // namespace nl::godot_style
