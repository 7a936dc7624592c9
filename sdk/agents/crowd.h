// Everybody as they were when a step's parallel phase began: what each agent's move reads of the
// others (positions, velocities, who stands arrived, a grid to find neighbours), and who goes first
// at a take-off that several bodies head for.
#pragma once

#include <cstdint>
#include <vector>

#include "agents/agent_state.h"
#include "agents/neighbours.h"

namespace nl {

struct CrowdSnapshot {
    std::vector<Vec3> positions;
    std::vector<Vec3> velocities;
    std::vector<float> radii;
    std::vector<uint8_t> grounded;  // on the ground, with avoidance on: others steer around it
    std::vector<uint8_t> arrived;   // standing at its destination
    // Standing aside: arrived, or giving way to another. Walkers do not steer around these; they
    // walk on and push them aside (overlaps.h), so a crowd that has arrived never walls a way off.
    std::vector<uint8_t> makes_room;
    // The leg of its path it walks, walking or giving way (on_its_way): zero for any other body.
    std::vector<Vec3> ways;
    // Its destination (in the space's coordinates) and how many bodies, itself included, are sent to
    // one so near it that they cannot all stand there (their discs at the two destinations overlap):
    // 0 for a body without a destination in this space.
    std::vector<Vec3> goals;
    std::vector<uint16_t> sharing_goal;
    // The nearest of the bodies close to one take-off (the lower index on a tie): it walks straight
    // onto the take-off point, the others make way, so that no two block each other there.
    std::vector<uint8_t> first_at_takeoff;
    NeighbourGrid grid;
    float max_radius = 0.0f;  // the widest body on the ground
};

// Walking its path on the ground, or standing aside for a moment to let another pass.
bool on_its_way(const Agent& a);

// The direction of the leg of its path a body on its way walks (x-z): from the point before the next
// to the next, whatever way the crowd has pushed it (past a corner, its heading to the next point
// turns back); on the first leg, from where it stands.
Vec3 way_ahead(const Agent& a);

// Fills `crowd` (in place: its grid refers to its positions) from the agents as they are: the bodies
// that share one space (the world, or one moving surface), in agent order; crowd index k is members[k].
void snapshot_crowd(const std::vector<const Agent*>& members, CrowdSnapshot& crowd);

}  // namespace nl
