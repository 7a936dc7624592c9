// Crowd scenarios with known answers, on host navmeshes drawn from rectangles (already eroded by the
// body's radius, as a host's navmesh is): agents sent to one point from several sides, counterflow
// through a door, a corridor. The same scenarios serve the core's crowd tests and the crowd bench.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "level/geometry.h"
#include "navmesh/navmesh_builder.h"

namespace nl::test {

struct CrowdAgent {
    Vec3 start = Vec3::Zero();
    Vec3 goal = Vec3::Zero();
};

struct CrowdScenario {
    std::string name;
    NavMeshInput navmesh;  // y = 0, eroded by `radius`
    // The same place as level geometry (boxes: a floor 1 m thick, its top at y = 0, and walls 2.5 m
    // high), for a navmesh built by Recast (the crowd bench, beside DetourCrowd).
    std::vector<std::pair<Vec3, Vec3>> boxes;
    float radius = 0.6f;
    float max_speed = 3.5f;         // m/s, nl_default_agent_def's
    float max_acceleration = 8.0f;  // m/s^2
    std::vector<CrowdAgent> agents;
    float seconds = 60.0f;  // everyone arrives within this
};

// An open floor `half` metres each way from the origin.
NavMeshInput open_floor(float half, float radius);
// Two rooms `half` metres deep each way along x, joined at x = 0 by a door `door` metres wide (before
// erosion) through a wall `wall` metres thick.
NavMeshInput rooms_with_door(float half, float door, float wall, float radius);

// `count` agents on a circle of `distance` metres, evenly spaced, all sent to its centre (2 agents:
// head-on; `quarter` puts the second at 90 degrees instead).
CrowdScenario one_point(int count, float distance, bool quarter = false);
// `per_side` agents on each side of a door, each sent to the other side (`both_ways` false: only the
// first side goes), bodies of `radius` (rows spaced to fit them).
CrowdScenario door_counterflow(int per_side, float door, bool both_ways = true, float radius = 0.6f);
// A corridor `width` metres wide and 30 m long, `per_end` agents at each end sent to the other end
// (`crossing`: a second corridor across its middle at 90 degrees, its agents crossing too).
CrowdScenario corridor(int per_end, float width, bool crossing);

// What a run of a scenario measured.
struct CrowdOutcome {
    int arrived = 0;  // agents that reached ARRIVED at least once
    int never_arrived = 0;
    int stuck = 0;              // agents that went 5 s WALKING without getting 0.1 m nearer their goal
    float all_arrived_at = -1;  // seconds, -1 if not all did
    float deepest_overlap = 0;  // metres, over every pair of bodies on the ground, every step
    float mean_overlap = 0;     // metres, over the overlapping pairs
};

}  // namespace nl::test
