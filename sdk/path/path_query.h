// What a path request asks and what it gets back, in the core's terms (capi/ maps them to nl_*).
#pragma once

#include <cstdint>
#include <vector>

#include "level/geometry.h"
#include "util/handle.h"

namespace nl {

// What an agent's body can do; links that ask for more are not used (link_filter.h).
struct AgentCapabilities {
    float max_jump_distance = 0.0f;
    float max_jump_height = 0.0f;
    float max_drop_height = 0.0f;
    float radius = 0.6f;
    uint64_t abilities = 0;
};

struct PathQuery {
    Vec3 start = Vec3::Zero();
    Vec3 goal = Vec3::Zero();
    Vec3 search_half_extents = Vec3(2.0f, 4.0f, 2.0f);
    AgentCapabilities capabilities;
    std::vector<float> area_costs;  // per area id; missing ids cost 1, 0 keeps the agent out
    float link_cost = 0.0f;         // added to every link taken
    uint32_t max_nodes = 0;         // 0: no limit
    bool accept_partial = true;

    float area_cost(uint8_t area) const { return area < area_costs.size() ? area_costs[area] : 1.0f; }
};

enum class PathOutcome : uint32_t {
    Pending = 0,
    Complete = 1,
    Partial = 2,
    NoPath = 3,
    StartOffNavMesh = 4,
    GoalOffNavMesh = 5,
    Cancelled = 6,
    Failed = 7,
};

// How the agent goes on from a path point: walking, or the kind of the link it takes.
constexpr uint32_t kSegmentWalk = 0;

struct PathPoint {
    Vec3 position = Vec3::Zero();          // in the world (as the request's ends are)
    Vec3 carrier_position = Vec3::Zero();  // in the navmesh's own space: where it stays on a moving surface
    uint32_t polygon = 0xffffffffu;
    uint32_t segment = kSegmentWalk;
    Handle link;  // null for walking
    Vec3 apex = Vec3::Zero();
    bool reversed = false;
};

struct PathResult {
    PathOutcome outcome = PathOutcome::Pending;
    uint32_t failure = 0;  // ErrorCode of a Failed request
    std::vector<PathPoint> points;
    uint32_t links_used = 0;
    uint32_t nodes_visited = 0;
    bool out_of_nodes = false;
    float length = 0.0f;
    float cost = 0.0f;
    Vec3 start = Vec3::Zero();
    Vec3 goal = Vec3::Zero();
};

}  // namespace nl
