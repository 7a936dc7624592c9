// The navigation server of the scene, as Godot's NavigationServer3D: the one place that talks to
// NavLink. It owns the nl_world; regions, links and agents register through it.
//
// Like Godot's server it has a sync point per frame, before the nodes process: there every agent
// moves (nl_world_step, in parallel on the world's threads, the same on any thread count) and each
// agent node is handed its events of that step, on the tree's thread.
#pragma once

#include <navlink/navlink.h>

#include <unordered_map>

#include "world.h"

namespace nl::godot_style {

class NavigationAgent;

class NavigationServer {
public:
    // `workers`: the world's threads (NL_WORKERS_AUTO or a count; 0 or 1: the tree's thread only).
    // Agents plan their paths within the step: the world runs no path threads.
    explicit NavigationServer(int32_t workers) : world_(0, workers) {}

    nl_world* world() const { return world_.get(); }

    // Adds the agent `def` describes for `node`, which then receives the agent's events. Throws
    // SampleError if refused.
    nl_agent_id add_agent(nl_agent_def def, NavigationAgent& node);
    void remove_agent(nl_agent_id agent);

    // The frame's sync point: moves every agent by `delta` seconds and hands out the step's events.
    void sync(double delta);

private:
    samples::World world_;
    std::unordered_map<uint64_t, NavigationAgent*> nodes_;  // by the agent's user_data
    uint64_t next_key_ = 1;
};

}  // namespace nl::godot_style
