#include "agents/giving_way.h"

#include <algorithm>
#include <cmath>

namespace nl {
namespace {

constexpr float kGivingWaySeconds = 1.5f;  // it stands aside this long, then walks on
// Of its radius: two stuck walkers this near each other's surface are in each other's way. Touching is
// not needed: two heading for one corner from either side stood 0.6 m apart for good, the velocity
// obstacles holding each short of it (0.5 radii let that be, in the corridors crossing at 90 degrees).
constexpr float kContactSlack = 1.5f;
constexpr float kStraightInto = 0.9f;  // cosine: a body this near straight ahead is in the way

// Walking on the ground toward a point (not standing at a take-off, not in the air).
bool walking(const Agent& a) { return a.state == AgentState::Walking && !a.at_takeoff && !a.motion && !a.path.empty(); }

// What a host reads as waiting for room: stuck while walking, or standing aside.
bool waits_for_room(const Agent& a) {
    return (walking(a) && a.blocked_time >= kStuckSeconds) || (a.giving_way > 0.0f && a.state == AgentState::Waiting);
}

// How far it still has to go along its path (x-z to the next point, then the path's legs).
float remaining_way(const Agent& a) {
    const Vec3& next = a.path[a.next].position;
    float way = std::hypot(a.position.x() - next.x(), a.position.z() - next.z());
    for (size_t k = a.next; k + 1 < a.path.size(); ++k) way += (a.path[k + 1].position - a.path[k].position).norm();
    return way;
}

// Says when a body starts waiting for room, and gives up the destination of one that has got no
// kGiveUpProgress nearer it for its give_up_seconds held up by bodies heading the other way, walking
// or giving way on the ground.
void keep_patience(Agent& a, float dt) {
    const bool waits = waits_for_room(a);
    if (waits && !a.waiting_for_room) a.emit(AgentEventKind::Waiting, AgentReason::Crowd);
    a.waiting_for_room = waits;
    const bool counting = !a.path.empty() && !a.motion && !a.wants_path &&
                          (a.state == AgentState::Walking || (a.state == AgentState::Waiting && a.giving_way > 0.0f));
    if (!counting || a.at_takeoff) {
        // At a take-off or in the air it got somewhere; waiting for its path, it did not walk.
        if (a.at_takeoff || a.motion) forget_patience(a);
        return;
    }
    const float remaining = remaining_way(a);
    if (remaining < a.best_remaining - kGiveUpProgress || a.best_remaining == std::numeric_limits<float>::infinity()) {
        a.best_remaining = remaining;
        a.no_progress_time = 0.0f;
        a.held_by_counterflow = false;
        return;
    }
    if (a.held_by_counterflow) a.no_progress_time += dt;
    if (a.def.give_up_seconds <= 0.0f || a.no_progress_time < a.def.give_up_seconds) return;
    a.giving_way = 0.0f;
    a.waiting_for_room = false;
    forget_progress(a);
    forget_patience(a);
    a.fail(AgentReason::Crowd);
}

}  // namespace

void decide_giving_way(std::vector<Agent>& agents, const std::vector<uint32_t>& space_of,
                       const std::vector<uint32_t>& index_in_space, const std::vector<CrowdSnapshot>& crowds,
                       float dt) {
    const size_t n = agents.size();
    std::vector<std::vector<uint32_t>> members(crowds.size());
    for (size_t s = 0; s < crowds.size(); ++s) members[s].resize(crowds[s].positions.size());
    for (uint32_t i = 0; i < n; ++i) members[space_of[i]][index_in_space[i]] = i;

    for (Agent& a : agents) {
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
    std::vector<uint8_t> gives(n, 0), stuck(n, 0), against_counterflow(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
        const Agent& a = agents[i];
        if (a.blocked_time < kStuckSeconds || a.giving_way > 0.0f) continue;
        stuck[i] = 1;
        const CrowdSnapshot& crowd = crowds[space_of[i]];
        const uint32_t self = index_in_space[i];
        const float radius = a.def.capabilities.radius;
        const float slack = kContactSlack * radius;
        const Vec3& target = a.path[a.next].position;
        const Vec3 heading(target.x() - a.position.x(), 0.0f, target.z() - a.position.z());
        crowd.grid.visit(crowd.positions[self], radius + crowd.max_radius + slack, [&](uint32_t k) {
            const uint32_t j = members[space_of[i]][k];
            if (j == i) return;
            const Agent& b = agents[j];
            const Vec3 d(crowd.positions[k].x() - crowd.positions[self].x(), 0.0f,
                         crowd.positions[k].z() - crowd.positions[self].z());
            if (d.norm() >= radius + b.def.capabilities.radius + slack) return;
            if (std::fabs(crowd.positions[k].y() - crowd.positions[self].y()) > std::max(a.def.height, b.def.height))
                return;
            // On its way (not standing where it arrived), along a leg that runs against ours.
            if (on_its_way(b)) against_counterflow[i] |= way_ahead(b).dot(way_ahead(a)) < 0.0f;
            if (gives[i]) return;
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
        Agent& a = agents[i];
        a.giving_way = kGivingWaySeconds;
        a.blocked_time = 0.0f;
        a.state = AgentState::Waiting;
    }
    for (uint32_t i = 0; i < n; ++i) {
        Agent& a = agents[i];
        // Giving way, it keeps what held it up when it stepped aside.
        if (stuck[i]) a.held_by_counterflow = against_counterflow[i];
        keep_patience(a, dt);
    }
}

}  // namespace nl
