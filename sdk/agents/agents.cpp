#include "agents/agents.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <shared_mutex>

#include "agents/agent_motion.h"
#include "agents/agent_state.h"
#include "agents/flight_check.h"
#include "agents/giving_way.h"
#include "agents/path_upkeep.h"
#include "agents/route.h"
#include "links/link_placement.h"
#include "path/link_filter.h"
#include "path/path_planner.h"

namespace nl {
namespace {

void check_positive(float value, const char* field) {
    if (!(value > 0.0f) || !std::isfinite(value))
        fail_field(ErrorCode::InvalidArgument, field, " is ", value, " (must be finite and > 0)");
}
void check_amount(float value, const char* field) {
    if (!(value >= 0.0f) || !std::isfinite(value))
        fail_field(ErrorCode::InvalidArgument, field, " is ", value, " (must be finite and >= 0)");
}
void check_capabilities(const AgentCapabilities& c) {
    check_amount(c.max_jump_distance, "capabilities.max_jump_distance");
    check_amount(c.max_jump_height, "capabilities.max_jump_height");
    check_amount(c.max_drop_height, "capabilities.max_drop_height");
    check_amount(c.radius, "capabilities.radius");
}
void check_point(const Vec3& p, const char* field) {
    if (!within_coordinate_limit(p))
        fail_field(ErrorCode::InvalidArgument, field, " is not finite or beyond the coordinate limit");
}

}  // namespace

Agents::Agents(uint32_t handle_tag, AgentsSettings settings)
    : settings_(settings), ids_(handle_tag, HandleKind::Agent) {}
Agents::~Agents() = default;

Agent& Agents::find(Handle agent) {
    uint32_t* index = ids_.find(agent);
    if (!index) fail_stale("agent", agent);
    return agents_[*index];
}
const Agent& Agents::find(Handle agent) const { return const_cast<Agents*>(this)->find(agent); }

uint32_t Agents::locate(const NavMesh& navmesh, const CarrierPose& pose, const Vec3& world_point, float radius,
                        const char* field, Vec3& on_navmesh) const {
    // Over the navmesh, or within the body's radius of its edge (half a metre at least), and within
    // 2 m above or below it; farther is refused, saying how far the nearest navmesh is.
    const float across = std::max(0.5f, radius);
    const Vec3 point = pose.carrier_point(world_point);
    const NavPoint near = navmesh.find_nearest(point, pose.carrier_extents(Vec3(across, 2.0f, across)));
    if (near.found) {
        on_navmesh = near.point;
        return near.polygon;
    }
    const NavPoint far = navmesh.find_nearest(point, Vec3(25.0f, 25.0f, 25.0f));
    if (far.found)
        fail_field(ErrorCode::NotFound, field, " is not on the navmesh: the nearest navmesh point is ", far.distance,
                   " m away (within ", across, " m across and 2 m up or down is on it)");
    fail_field(ErrorCode::NotFound, field, " is not on the navmesh (nothing within 25 m)");
}

std::shared_ptr<const NavMesh> Agents::navmesh_of(const NavMeshRegistry& navmeshes, Handle agent, float& radius,
                                                  CarrierPose& pose) const {
    Handle navmesh;
    {
        std::shared_lock lock(mutex_);
        const Agent& a = find(agent);
        navmesh = a.def.navmesh;
        radius = a.def.capabilities.radius;
        pose = pose_of(a.frame);
    }
    try {
        return navmeshes.navmesh(navmesh);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        fail(ErrorCode::InvalidHandle, "the agent's navmesh {", navmesh.index1, ", ", navmesh.revision,
             "} was removed: the agent cannot go anywhere (it fails at the next step; remove it)");
    }
}

bool Agents::locate_across(const NavMeshRegistry& navmeshes, Handle own, const Vec3& point, float radius,
                           Vec3& on_navmesh, Handle& navmesh, std::shared_ptr<const CarrierFrame>& frame) const {
    // The navmeshes cross links join to the agent's, nearest hop first (either way: a platform the
    // agent can ride away from its own navmesh and back).
    std::vector<std::pair<Handle, Handle>> joins;
    for (Handle h : navmeshes.handles()) {
        try {
            const auto links = navmeshes.links(h);  // held: an edit on another thread may publish the next
            for (const StoredLink& s : *links)
                if (s.link.crosses()) joins.emplace_back(h, s.link.landing_navmesh);
        } catch (const Error& e) {
            if (e.code() != ErrorCode::InvalidHandle) throw;  // removed meanwhile
        }
    }
    std::vector<Handle> seen{own};
    for (size_t next = 0; next < seen.size(); ++next) {
        for (const auto& [a, b] : joins) {
            const Handle other = a == seen[next] ? b : b == seen[next] ? a : Handle{};
            if (other == Handle{} || std::find(seen.begin(), seen.end(), other) != seen.end()) continue;
            seen.push_back(other);
            try {
                const std::shared_ptr<const NavMesh> mesh = navmeshes.navmesh(other);
                std::shared_ptr<const CarrierFrame> other_frame = navmeshes.frame(other);
                locate(*mesh, pose_of(other_frame), point, radius, "point", on_navmesh);
                navmesh = other;
                frame = std::move(other_frame);
                return true;
            } catch (const Error& e) {
                if (e.code() != ErrorCode::NotFound && e.code() != ErrorCode::InvalidHandle) throw;
            }
        }
    }
    return false;
}

Handle Agents::add(const NavMeshRegistry& navmeshes, const AgentDef& def) {
    check_capabilities(def.capabilities);
    check_positive(def.height, "height");
    check_positive(def.max_speed, "max_speed");
    check_positive(def.max_acceleration, "max_acceleration");
    check_positive(def.gravity, "gravity");
    check_amount(def.takeoff_speed, "takeoff_speed");
    check_amount(def.give_up_seconds, "give_up_seconds");
    check_point(def.position, "position");
    const std::shared_ptr<const NavMesh> navmesh = navmeshes.navmesh(def.navmesh);
    Agent body;
    body.def = def;
    body.frame = navmeshes.frame(def.navmesh);
    body.polygon =
        locate(*navmesh, pose_of(body.frame), def.position, def.capabilities.radius, "position", body.position);
    body.stands_on = navmesh;
    std::unique_lock lock(mutex_);
    // Nothing may throw once the id is taken. Grown geometrically: adding n agents one by one
    // copies O(n) bodies in all, not O(n^2).
    if (agents_.size() == agents_.capacity()) agents_.reserve(std::max<size_t>(16, 2 * agents_.capacity()));
    const Handle id = ids_.insert(static_cast<uint32_t>(agents_.size()));
    body.id = id;
    agents_.push_back(std::move(body));
    return id;
}

void Agents::remove(Handle agent) {
    std::unique_lock lock(mutex_);
    uint32_t* slot = ids_.find(agent);
    if (!slot) fail_stale("agent", agent);
    const uint32_t at = *slot;
    ids_.erase(agent);
    if (at + 1 != agents_.size()) {
        agents_[at] = std::move(agents_.back());
        *ids_.find(agents_[at].id) = at;
    }
    agents_.pop_back();
}

bool Agents::contains(Handle agent) const {
    std::shared_lock lock(mutex_);
    return ids_.find(agent) != nullptr;
}

void Agents::set_destination(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& destination,
                             const char* field) {
    check_point(destination, field);
    float radius;
    CarrierPose pose;
    const std::shared_ptr<const NavMesh> mesh = navmesh_of(navmeshes, agent, radius, pose);
    Handle own;
    {
        std::shared_lock lock(mutex_);
        own = find(agent).def.navmesh;
    }
    Vec3 on_navmesh;
    Handle there = own;
    std::shared_ptr<const CarrierFrame> there_frame = navmeshes.frame(own);
    // Located on the surface now, and kept there: it moves with the surface until the agent arrives.
    try {
        locate(*mesh, pose, destination, radius, field, on_navmesh);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::NotFound) throw;
        if (!locate_across(navmeshes, own, destination, radius, on_navmesh, there, there_frame)) throw;
    }
    std::unique_lock lock(mutex_);
    Agent& a = find(agent);
    stop_giving_way(a);  // sent, stopped or put elsewhere: whatever held it up is behind it
    a.has_destination = true;
    a.destination = on_navmesh;
    a.destination_navmesh = there;
    a.destination_frame = std::move(there_frame);
    if (!a.motion) {
        // The old path leads elsewhere: walking on along it while the new one waits its turn would end
        // in an arrival (or failure) at the old destination.
        a.path.clear();
        a.at_takeoff = false;
        a.link = Handle{};
        a.state = AgentState::Waiting;
    }
    a.reason = AgentReason::None;
    a.ask_path(AgentReason::DestinationSet, next_path_order_);
}

void Agents::stop(Handle agent) {
    std::unique_lock lock(mutex_);
    Agent& a = find(agent);
    stop_giving_way(a);  // sent, stopped or put elsewhere: whatever held it up is behind it
    a.has_destination = false;
    a.wants_path = false;
    a.at_takeoff = false;
    a.path.clear();
    a.graph.reset();
    if (!a.motion) a.link = Handle{};
    // One whose navmesh was removed stays failed: it has nowhere to stand (and would fail again,
    // with a second event, at the next step).
    const bool stranded = a.state == AgentState::Failed && a.reason == AgentReason::NavMeshRemoved;
    if (!a.motion && !stranded) {
        a.state = AgentState::Idle;
        a.velocity = Vec3::Zero();
    }
}

void Agents::teleport(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& position, const char* field) {
    check_point(position, field);
    float radius;
    CarrierPose pose;
    const std::shared_ptr<const NavMesh> mesh = navmesh_of(navmeshes, agent, radius, pose);
    Vec3 on_navmesh;
    const uint32_t polygon = locate(*mesh, pose, position, radius, field, on_navmesh);
    std::unique_lock lock(mutex_);
    Agent& a = find(agent);
    if (a.motion) fail(ErrorCode::InvalidArgument, "the agent is taking a link (teleport it after it lands)");
    stop_giving_way(a);  // sent, stopped or put elsewhere: whatever held it up is behind it
    a.put_on_surface(on_navmesh);
    a.polygon = polygon;
    a.stands_on = mesh;
    a.awaiting_tile = false;
    a.velocity = Vec3::Zero();
    a.at_takeoff = false;
    a.link = Handle{};
    a.path.clear();
    if (a.has_destination && a.state != AgentState::Failed) {
        a.state = AgentState::Waiting;
        a.ask_path(AgentReason::OffPath, next_path_order_);
    }
}

void Agents::set_capabilities(Handle agent, const AgentCapabilities& capabilities) {
    check_capabilities(capabilities);
    std::unique_lock lock(mutex_);
    Agent& a = find(agent);
    a.def.capabilities = capabilities;
    // A body that could not reach its destination may now (one whose navmesh was removed may not).
    const bool stranded = a.state == AgentState::Failed && a.reason == AgentReason::NavMeshRemoved;
    if (a.has_destination && a.state != AgentState::Arrived && !stranded) {
        if (a.state == AgentState::Failed) a.state = AgentState::Waiting;
        a.ask_path(AgentReason::CapabilitiesChanged, next_path_order_);
    }
}

void Agents::set_speed(Handle agent, float max_speed, float max_acceleration) {
    check_positive(max_speed, "max_speed");
    check_positive(max_acceleration, "max_acceleration");
    std::unique_lock lock(mutex_);
    Agent& a = find(agent);
    a.def.max_speed = max_speed;
    a.def.max_acceleration = max_acceleration;
}

uint32_t Agents::count() const {
    std::shared_lock lock(mutex_);
    return static_cast<uint32_t>(agents_.size());
}

namespace {

// The path points the agent has yet to reach: in the air `next` is still the take-off point (it
// moves on at the landing); arrived (perhaps beside its goal, among others), none.
size_t points_ahead(const Agent& a) {
    if (a.next >= a.path.size() || a.state == AgentState::Arrived) return 0;
    return a.path.size() - a.next - (a.motion ? 1 : 0);
}

// What a host reads, in the world: on a moving surface, at the carrier's pose of this moment (the
// velocity is the body's own, turned with the surface, without the surface's motion).
AgentInfo info_of(const Agent& a) {
    const CarrierPose pose = pose_of(a.frame);
    AgentInfo info;
    info.id = a.id;
    // Walking without getting anywhere (pressed in a crowd, queueing at a door): waiting for room.
    info.state = a.waiting_for_room ? AgentState::Waiting : a.state;
    info.reason = a.waiting_for_room ? AgentReason::Crowd : a.reason;
    // On a tile that was removed, whatever the host asked since (a new destination waits for it too).
    if (a.awaiting_tile && a.state != AgentState::Failed) {
        info.state = AgentState::Waiting;
        info.reason = AgentReason::TileUnloaded;
    }
    info.position = pose.world_point(a.position);
    info.velocity = pose.world_vector(a.velocity);
    info.polygon = a.polygon;
    info.link = a.link;
    info.link_progress = a.motion ? std::clamp(a.motion_time / a.motion->duration(), 0.0f, 1.0f) : 0.0f;
    info.destination = pose_of(a.destination_frame).world_point(a.destination);
    info.has_destination = a.has_destination;
    info.corners_ahead = static_cast<uint32_t>(points_ahead(a));
    info.user_data = a.def.user_data;
    info.navmesh = a.def.navmesh;
    info.carrier = a.frame ? a.frame->mesh() : Handle{};
    info.carrier_position = a.position;
    return info;
}

}  // namespace

AgentInfo Agents::info(Handle agent) const {
    std::shared_lock lock(mutex_);
    return info_of(find(agent));
}

std::vector<AgentInfo> Agents::infos() const {
    std::shared_lock lock(mutex_);
    std::vector<AgentInfo> out;
    out.reserve(agents_.size());
    for (const Agent& a : agents_) out.push_back(info_of(a));
    return out;
}

std::vector<PathPoint> Agents::corners(Handle agent) const {
    std::shared_lock lock(mutex_);
    const Agent& a = find(agent);
    const size_t ahead = points_ahead(a);
    if (ahead == 0) return {};
    // Where it is now, going on as it does: flying the link it took off on (the point `next` still
    // names), or walking. Without it a straight walk to the goal would be one point.
    PathPoint here;
    if (a.motion)
        here = a.path[a.next];
    else
        here.apex = a.position;
    here.carrier_position = a.position;
    here.polygon = a.polygon;
    std::vector<PathPoint> out;
    out.reserve(ahead + 1);
    out.push_back(here);
    out.insert(out.end(), a.path.end() - static_cast<std::ptrdiff_t>(ahead), a.path.end());
    const CarrierPose pose = pose_of(a.frame);
    for (PathPoint& p : out) {
        p.position = pose.world_point(p.carrier_position);
        p.apex = pose.world_point(p.apex);
    }
    return out;
}

Agents::Flight Agents::flight(Handle agent) const {
    std::shared_lock lock(mutex_);
    const Agent& a = find(agent);
    if (!a.motion) return {};
    return Flight{a.motion, a.link, a.motion_time, pose_of(a.frame)};
}

std::vector<AgentEvent> Agents::events() const {
    std::shared_lock lock(mutex_);
    return events_;
}

}  // namespace nl
