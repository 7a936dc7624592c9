#include "agents/crowd.h"

#include <algorithm>
#include <cmath>

namespace nl {
namespace {

// A body this near a take-off (in body widths of its own and the widest other) is queueing for it.
constexpr float kQueueWidths = 2.0f;

struct TakeoffClaim {
    Handle link;
    bool reversed;
    float distance;
    uint32_t agent;
};

void choose_first_at_takeoffs(const std::vector<const Agent*>& agents, CrowdSnapshot& crowd) {
    std::vector<TakeoffClaim> claims;
    for (uint32_t i = 0; i < agents.size(); ++i) {
        const Agent& a = *agents[i];
        // One waiting at the take-off holds it too: the next in the queue makes way for it.
        if (a.motion || (a.state != AgentState::Walking && !a.at_takeoff) || a.next >= a.path.size()) continue;
        const PathPoint& takeoff = a.path[a.next];
        if (takeoff.segment == kSegmentWalk) continue;
        const float distance = std::hypot(a.position.x() - takeoff.position.x(), a.position.z() - takeoff.position.z());
        if (distance > kQueueWidths * (a.def.capabilities.radius + crowd.max_radius)) continue;
        auto same = std::find_if(claims.begin(), claims.end(), [&](const TakeoffClaim& c) {
            return c.link == takeoff.link && c.reversed == takeoff.reversed;
        });
        if (same == claims.end())
            claims.push_back({takeoff.link, takeoff.reversed, distance, i});
        else if (distance < same->distance)  // agents come in index order: a tie keeps the lower
            *same = {takeoff.link, takeoff.reversed, distance, i};
    }
    crowd.first_at_takeoff.assign(agents.size(), 0);
    for (const TakeoffClaim& c : claims) crowd.first_at_takeoff[c.agent] = 1;
}

// How many bodies share each body's destination (CrowdSnapshot::sharing_goal).
void count_shared_goals(const std::vector<const Agent*>& agents, CrowdSnapshot& crowd) {
    const size_t n = agents.size();
    crowd.goals.resize(n);
    crowd.sharing_goal.assign(n, 0);
    std::vector<uint8_t> has_goal(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const Agent& a = *agents[i];
        has_goal[i] = a.has_destination && a.destination_navmesh == a.def.navmesh && !a.motion;
        crowd.goals[i] = a.destination;
    }
    NeighbourGrid grid;
    grid.build(crowd.goals, has_goal, std::max(crowd.max_radius * 2.0f, 0.5f));
    for (size_t i = 0; i < n; ++i) {
        if (!has_goal[i]) continue;
        uint32_t count = 0;
        grid.visit(crowd.goals[i], crowd.radii[i] + crowd.max_radius, [&](uint32_t j) {
            const Vec3 d = crowd.goals[j] - crowd.goals[i];
            count += std::hypot(d.x(), d.z()) < crowd.radii[i] + crowd.radii[j];
        });
        crowd.sharing_goal[i] = static_cast<uint16_t>(std::min<uint32_t>(count, UINT16_MAX));
    }
}

}  // namespace

bool on_its_way(const Agent& a) {
    return !a.motion && !a.at_takeoff && !a.path.empty() && (a.state == AgentState::Walking || a.giving_way > 0.0f);
}

Vec3 way_ahead(const Agent& a) {
    const Vec3& to = a.path[a.next].position;
    const Vec3& from = a.next > 0 ? a.path[a.next - 1].position : a.position;
    return Vec3(to.x() - from.x(), 0.0f, to.z() - from.z());
}

void snapshot_crowd(const std::vector<const Agent*>& agents, CrowdSnapshot& crowd) {
    const size_t n = agents.size();
    crowd.positions.resize(n);
    crowd.velocities.resize(n);
    crowd.radii.resize(n);
    crowd.grounded.resize(n);
    crowd.arrived.resize(n);
    crowd.makes_room.resize(n);
    crowd.ways.resize(n);
    crowd.max_radius = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        const Agent& a = *agents[i];
        crowd.positions[i] = a.position;
        crowd.velocities[i] = a.velocity;
        crowd.radii[i] = a.def.capabilities.radius;
        // Every body standing on the navmesh is avoided, one that does not steer itself included; one
        // whose navmesh was removed stands nowhere.
        crowd.grounded[i] = !a.motion && !(a.state == AgentState::Failed && a.reason == AgentReason::NavMeshRemoved);
        crowd.arrived[i] = a.state == AgentState::Arrived;
        crowd.makes_room[i] = crowd.arrived[i] || a.giving_way > 0.0f;
        crowd.ways[i] = on_its_way(a) ? way_ahead(a) : Vec3(Vec3::Zero());
        if (!crowd.grounded[i]) continue;
        crowd.max_radius = std::max(crowd.max_radius, crowd.radii[i]);
    }
    // Cells three radii wide, as DetourCrowd's proximity grid: a body's contacts lie in the 2 x 2 cells
    // around it, and the nearest neighbours of a body in a crowd within the next ring (a cell as wide
    // as the avoidance range, 12 radii, held hundreds of bodies each in a dense crowd).
    crowd.grid.build(crowd.positions, crowd.grounded, std::max(crowd.max_radius * 3.0f, 0.5f));
    choose_first_at_takeoffs(agents, crowd);
    count_shared_goals(agents, crowd);
}

}  // namespace nl
