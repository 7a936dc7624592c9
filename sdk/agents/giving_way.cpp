#include "agents/giving_way.h"

#include <algorithm>
#include <cmath>

namespace nl {
namespace {

constexpr float kGivingWaySeconds = 1.5f;  // it stands aside this long, then walks on
constexpr float kContactSlack = 0.5f;   // of its radius: this near another body counts as contact
constexpr float kStraightInto = 0.9f;   // cosine: a body this near straight ahead is in the way

// Walking on the ground toward a point (not standing at a take-off, not in the air).
bool walking(const AgentBody& a) { return a.state == AgentState::Walking && !a.at_takeoff && !a.motion && !a.path.empty(); }

}  // namespace

void decide_giving_way(std::vector<AgentBody>& agents, const std::vector<uint32_t>& space_of,
                       const std::vector<uint32_t>& index_in_space, const std::vector<CrowdSnapshot>& crowds, float dt) {
    const size_t n = agents.size();
    std::vector<std::vector<uint32_t>> members(crowds.size());
    for (size_t s = 0; s < crowds.size(); ++s) members[s].resize(crowds[s].positions.size());
    for (uint32_t i = 0; i < n; ++i) members[space_of[i]][index_in_space[i]] = i;

    for (AgentBody& a : agents) {
        if (a.giving_way > 0.0f) {
            a.giving_way -= dt;
            if (a.giving_way > 0.0f) continue;
            a.giving_way = 0.0f;
            forget_progress(a);  // it stepped back: its best so far is not a mark to beat
            if (a.state == AgentState::Waiting && !a.wants_path && !a.path.empty()) a.state = AgentState::Walking;
            continue;
        }
        if (!walking(a)) {
            forget_progress(a);
            continue;
        }
        const Vec3& target = a.path[a.next].position;
        const float distance = std::hypot(a.position.x() - target.x(), a.position.z() - target.z());
        if (a.next != a.progress_next || distance < a.progress_best - kProgressStep) {
            a.progress_next = a.next;
            a.progress_best = distance;
            a.blocked_time = 0.0f;
        } else {
            a.blocked_time += dt;
        }
    }
    // Of two stuck walkers in contact, the one stuck longer goes on (the lower index on a tie); the
    // other gives way, and so do the stuck walkers pressing into one that gives way (a queue behind
    // it would hold it in the other's path). Decided from the state above for all at once, then
    // applied: a queue gives way one body further each step.
    std::vector<uint8_t> gives(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
        const AgentBody& a = agents[i];
        if (a.blocked_time < kStuckSeconds || a.giving_way > 0.0f) continue;
        const CrowdSnapshot& crowd = crowds[space_of[i]];
        const uint32_t self = index_in_space[i];
        const float radius = a.def.capabilities.radius;
        const float slack = kContactSlack * radius;
        const Vec3& target = a.path[a.next].position;
        const Vec3 heading(target.x() - a.position.x(), 0.0f, target.z() - a.position.z());
        crowd.grid.visit(crowd.positions[self], radius + crowd.max_radius + slack, [&](uint32_t k) {
            const uint32_t j = members[space_of[i]][k];
            if (gives[i] || j == i) return;
            const AgentBody& b = agents[j];
            const Vec3 d(crowd.positions[k].x() - crowd.positions[self].x(), 0.0f, crowd.positions[k].z() - crowd.positions[self].z());
            if (d.norm() >= radius + b.def.capabilities.radius + slack) return;
            if (std::fabs(crowd.positions[k].y() - crowd.positions[self].y()) > std::max(a.def.height, b.def.height)) return;
            if (b.giving_way > 0.0f) {
                // Pressing straight into one that stands aside (it is in the way ahead, not beside).
                gives[i] = heading.dot(d) > kStraightInto * heading.norm() * d.norm();
                return;
            }
            if (b.blocked_time < kStuckSeconds) return;
            gives[i] = b.blocked_time > a.blocked_time || (b.blocked_time == a.blocked_time && j < i);
        });
    }
    for (uint32_t i = 0; i < n; ++i) {
        if (!gives[i]) continue;
        AgentBody& a = agents[i];
        a.giving_way = kGivingWaySeconds;
        a.blocked_time = 0.0f;
        a.state = AgentState::Waiting;
    }
}

}  // namespace nl
