// Bodies pushed apart after a step's move, so that they never sink into each other: overlaps are
// resolved by moving positions, as DetourCrowd's collision pass does, but over every body standing on
// the navmesh (arrived and waiting ones make room too), through the surface (walls hold), and in
// parallel with the same result for any thread count (each round reads the positions of the last).
#pragma once

#include <cstdint>
#include <vector>

#include "agents/agent_state.h"
#include "navmesh/navmesh.h"
#include "util/task_system.h"

namespace nl {

// One body of a space (the bodies on the ground that share the world, or one moving surface).
struct OverlapBody {
    Agent* agent;
    const NavMesh* navmesh;  // the agent's
    // How readily it gives way: of an overlap between two bodies, each moves its share of their sum
    // (a standing body makes room for a walker: kStandingGives to 1; 0 holds its place).
    float give = 1.0f;
};
constexpr float kStandingGives = 4.0f;

// Pushes apart the bodies of one space whose discs (x-z) overlap: kRounds rounds, each moving every
// body by its share of each overlap it is in (OverlapBody::give), over the surface. A
// walker's velocity takes the push (over the step's `dt` seconds).
void resolve_overlaps(const std::vector<OverlapBody>& bodies, float dt, TaskSystem& tasks);

}  // namespace nl
