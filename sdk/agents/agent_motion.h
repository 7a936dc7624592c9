// What one agent does in a step's parallel phase: follow its path on the ground (steer to the next
// point, avoid neighbours, move over the surface, stop at a link's take-off) or fly the link
// it took. Reads the step's snapshot of everybody's position, writes only its own state.
#pragma once

#include <cstdint>

#include "agents/agent_state.h"
#include "agents/crowd.h"
#include "navmesh/navmesh.h"
#include "navmesh/surface_walk.h"

namespace nl {

// Moves agent `self` (its index in the snapshot) by dt on `navmesh` (its own). May mark it off its
// path or at a take-off (the serial phase acts on those); never changes another agent.
void move_agent(Agent& agent, uint32_t self, float dt, const NavMesh& navmesh, const CrowdSnapshot& crowd);

// A body moved over the surface from `from` (on `polygon`) toward `to` by something other than its
// walk (a push, a step back): its feet keep their height over the surface (eased near a take-off or a
// landing), as move_along_surface otherwise puts them on it.
SurfaceMove move_keeping_height(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to);

}  // namespace nl
