// The DetourCrowd agent the crowd benchmarks pit NavLink against: RecastDemo's crowd tool flags
// (anticipate turns, optimise visibility and topology, obstacle avoidance with dtCrowd::init's default
// parameters), collision query range 12 radii, path optimisation range 30 radii, and NavLink's
// default speed and acceleration (nl_default_agent_def) with the level's body.
#pragma once

#include <DetourCrowd.h>
#include <navlink/navlink.h>

#include "recast_detour.h"

namespace nl::bench {

inline dtCrowdAgentParams detour_crowd_agent(const RecastLevel& level) {
    dtCrowdAgentParams params{};
    params.radius = level.agent.radius;
    params.height = level.agent.height;
    const nl_agent_def defaults = nl_default_agent_def();
    params.maxAcceleration = defaults.max_acceleration;
    params.maxSpeed = defaults.max_speed;
    params.collisionQueryRange = params.radius * 12.0f;
    params.pathOptimizationRange = params.radius * 30.0f;
    params.separationWeight = 2.0f;  // unused: separation is off, as in RecastDemo's default
    params.updateFlags =
        DT_CROWD_ANTICIPATE_TURNS | DT_CROWD_OPTIMIZE_VIS | DT_CROWD_OPTIMIZE_TOPO | DT_CROWD_OBSTACLE_AVOIDANCE;
    params.obstacleAvoidanceType = 0;
    params.queryFilterType = 0;
    return params;
}

}  // namespace nl::bench
