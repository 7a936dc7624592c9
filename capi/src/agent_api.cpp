// nl_agent_* and nl_world_step: agents over the core's (sdk/agents).
#include <cstddef>

#include "entry_guard.h"
#include "first_sizes.h"
#include "field_copy.h"
#include "mapping.h"
#include "host_input.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;
using nl::capi::copy_point;
using nl::capi::to_id;

namespace {

static_assert(uint32_t(nl::AgentState::Failed) == NL_AGENT_FAILED &&
                  uint32_t(nl::AgentState::Waiting) == NL_AGENT_WAITING,
              "core and header disagree on agent states");
static_assert(uint32_t(nl::AgentReason::Crowd) == NL_AGENT_REASON_CROWD &&
                  uint32_t(nl::AgentReason::TileUnloaded) == NL_AGENT_REASON_TILE_UNLOADED,
              "core and header disagree on agent reasons");
static_assert(uint32_t(nl::AgentEventKind::Waiting) == NL_AGENT_EVENT_WAITING, "core and header disagree on events");

nl_trajectory_kind trajectory_kind(nl::MotionKind kind) {
    switch (kind) {
        case nl::MotionKind::Arc: return NL_TRAJECTORY_ARC;
        case nl::MotionKind::Fall: return NL_TRAJECTORY_FALL;
        case nl::MotionKind::Line: break;
    }
    return NL_TRAJECTORY_LINE;
}

nl::AgentCapabilities to_core(const nl_agent_capabilities& c) {
    nl::AgentCapabilities out;
    NL_COPY_FIELDS(NL_AGENT_CAPABILITIES_FIELDS, out, c);
    return out;
}

nl::AgentDef agent_from_def(const nl_agent_def& given) {
    const nl_agent_def def =
        nl::capi::read_growable(given, nl_default_agent_def(), nl::capi::kFirstSize<nl_agent_def>, "def");
    nl::AgentDef out;
    out.navmesh = to_handle(def.navmesh);
    out.capabilities = to_core(def.capabilities);
    out.height = def.height;
    out.max_speed = def.max_speed;
    out.max_acceleration = def.max_acceleration;
    out.gravity = def.gravity;
    out.takeoff_speed = def.takeoff_speed;
    out.position = nl::capi::read_position(def.position, "position");
    out.user_data = def.user_data;
    out.avoidance = def.avoidance != 0;
    out.give_up_seconds = def.give_up_seconds;
    return out;
}

nl_agent_info to_c(const nl::AgentInfo& a) {
    nl_agent_info c{};
    c.size = sizeof c;
    c.state = static_cast<nl_agent_state>(a.state);
    c.id = to_id<nl_agent_id>(a.id);
    copy_point(c.position, a.position);
    copy_point(c.velocity, a.velocity);
    c.polygon = a.polygon;
    c.reason = static_cast<nl_agent_reason>(a.reason);
    c.link = to_id<nl_link_id>(a.link);
    c.link_progress = a.link_progress;
    copy_point(c.destination, a.destination);
    c.has_destination = a.has_destination ? 1 : 0;
    c.corners_ahead = a.corners_ahead;
    c.navmesh = to_id<nl_navmesh_id>(a.navmesh);
    c.carrier = to_id<nl_mesh_id>(a.carrier);
    copy_point(c.carrier_position, a.carrier_position);
    c.user_data = a.user_data;
    return c;
}

}  // namespace

extern "C" {

NL_API nl_agent_def nl_default_agent_def(void) {
    const nl::AgentDef core;
    nl_agent_def def{};
    def.size = sizeof def;
    def.capabilities = nl_default_agent_capabilities();
    def.height = core.height;
    def.max_speed = core.max_speed;
    def.max_acceleration = core.max_acceleration;
    def.gravity = core.gravity;
    def.takeoff_speed = core.takeoff_speed;
    def.avoidance = 1;
    def.give_up_seconds = core.give_up_seconds;
    return def;
}

NL_API nl_status nl_agent_add(nl_world* world, const nl_agent_def* def, nl_agent_id* out_id) {
    return guarded("nl_agent_add", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        require(out_id, "out_id");
        const nl::AgentDef core = nl::naming_fields("def->", [&] { return agent_from_def(*def); });
        *out_id = to_id<nl_agent_id>(nl::naming_fields("def->", [&] { return w.add_agent(core); }));
    });
}

NL_API nl_status nl_agent_remove(nl_world* world, nl_agent_id agent) {
    return guarded("nl_agent_remove", world, [&] { deref(world).agents().remove(to_handle(agent)); });
}

NL_API int32_t nl_agent_is_valid(const nl_world* world, nl_agent_id agent) {
    int32_t valid = 0;
    guarded("nl_agent_is_valid", world, [&] { valid = deref(world).agents().contains(to_handle(agent)) ? 1 : 0; });
    return valid;
}

NL_API nl_status nl_agent_set_destination(nl_world* world, nl_agent_id agent, const float* point) {
    return guarded("nl_agent_set_destination", world, [&] {
        nl::World& w = deref(world);
        w.agents().info(to_handle(agent));  // a stale id first, before the point
        require(point, "point");
        const nl::Vec3 p = nl::capi::read_position(point, "point");
        w.agents().set_destination(w.navmeshes(), to_handle(agent), p, "point");
    });
}

NL_API nl_status nl_agent_stop(nl_world* world, nl_agent_id agent) {
    return guarded("nl_agent_stop", world, [&] { deref(world).agents().stop(to_handle(agent)); });
}

NL_API nl_status nl_agent_teleport(nl_world* world, nl_agent_id agent, const float* point) {
    return guarded("nl_agent_teleport", world, [&] {
        nl::World& w = deref(world);
        w.agents().info(to_handle(agent));
        require(point, "point");
        w.agents().teleport(w.navmeshes(), to_handle(agent), nl::capi::read_position(point, "point"), "point");
    });
}

NL_API nl_status nl_agent_set_capabilities(nl_world* world, nl_agent_id agent,
                                           const nl_agent_capabilities* capabilities) {
    return guarded("nl_agent_set_capabilities", world, [&] {
        nl::World& w = deref(world);
        w.agents().info(to_handle(agent));
        require(capabilities, "capabilities");
        nl::naming_fields("", [&] { w.agents().set_capabilities(to_handle(agent), to_core(*capabilities)); });
    });
}

NL_API nl_status nl_agent_set_speed(nl_world* world, nl_agent_id agent, float max_speed, float max_acceleration) {
    return guarded("nl_agent_set_speed", world, [&] {
        nl::World& w = deref(world);
        w.agents().info(to_handle(agent));  // a stale id first, before the figures (as the other setters)
        w.agents().set_speed(to_handle(agent), max_speed, max_acceleration);
    });
}

NL_API nl_status nl_world_step(nl_world* world, float dt) {
    return guarded("nl_world_step", world, [&] { deref(world).step(dt); });
}

NL_API nl_status nl_agent_get_info(const nl_world* world, nl_agent_id agent, nl_agent_info* out_info) {
    return guarded("nl_agent_get_info", world, [&] {
        const nl::AgentInfo info = deref(world).agents().info(to_handle(agent));
        require(out_info, "out_info");
        nl::capi::write_growable(out_info, to_c(info), nl::capi::kFirstSize<nl_agent_info>, "out_info");
    });
}

NL_API nl_status nl_world_get_agents(const nl_world* world, nl_agent_info* out_infos, uint32_t capacity,
                                     uint32_t* out_count) {
    return guarded("nl_world_get_agents", world, [&] {
        const std::vector<nl::AgentInfo> infos = deref(world).agents().infos();
        nl::capi::list_growable_into(infos, out_infos, capacity, out_count, nl::capi::kFirstSize<nl_agent_info>,
                                     "out_infos", [](const nl::AgentInfo& a) { return to_c(a); });
    });
}

NL_API nl_status nl_agent_get_corners(const nl_world* world, nl_agent_id agent, nl_path_point* out_points,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_agent_get_corners", world, [&] {
        const std::vector<nl::PathPoint> corners = deref(world).agents().corners(to_handle(agent));
        nl::capi::list_growable_into(corners, out_points, capacity, out_count, nl::capi::kFirstSize<nl_path_point>,
                                     "out_points", [](const nl::PathPoint& p) { return nl::capi::to_c(p); });
    });
}

NL_API nl_status nl_agent_get_trajectory(const nl_world* world, nl_agent_id agent,
                                         nl_agent_trajectory* out_trajectory) {
    return guarded("nl_agent_get_trajectory", world, [&] {
        const nl::Agents::Flight flight = deref(world).agents().flight(to_handle(agent));
        require(out_trajectory, "out_trajectory");
        nl::capi::check_growable_output(out_trajectory, nl::capi::kFirstSize<nl_agent_trajectory>, "out_trajectory");
        nl_agent_trajectory t{};
        t.size = sizeof t;
        t.kind = NL_TRAJECTORY_NONE;
        if (!flight.motion) {  // on the ground: an answer, not an error (hosts ask every frame)
            nl::capi::write_growable(out_trajectory, t, nl::capi::kFirstSize<nl_agent_trajectory>, "out_trajectory");
            return;
        }
        const std::optional<nl::LinkMotion>& motion = flight.motion;
        t.kind = trajectory_kind(motion->kind());
        t.link = to_id<nl_link_id>(flight.link);
        // Flown in its navmesh's space: on a moving carrier, shown where the carrier is now.
        const nl::CarrierPose& pose = flight.pose;
        copy_point(t.from, pose.world_point(motion->from()));
        copy_point(t.to, pose.world_point(motion->to()));
        copy_point(t.apex, pose.world_point(motion->apex()));
        const auto& fall = motion->fall_points();
        for (int k = 0; k < 4; ++k)
            copy_point(t.points[k], pose.world_point(motion->kind() == nl::MotionKind::Fall
                                                         ? fall[k]
                                                         : (k < 2 ? motion->from() : motion->to())));
        t.duration = motion->duration();
        t.elapsed = flight.elapsed;
        nl::capi::write_growable(out_trajectory, t, nl::capi::kFirstSize<nl_agent_trajectory>, "out_trajectory");
    });
}

NL_API nl_status nl_world_get_agent_events(const nl_world* world, nl_agent_event* out_events, uint32_t capacity,
                                           uint32_t* out_count) {
    return guarded("nl_world_get_agent_events", world, [&] {
        const std::vector<nl::AgentEvent> events = deref(world).agents().events();
        nl::capi::list_growable_into(events, out_events, capacity, out_count, nl::capi::kFirstSize<nl_agent_event>,
                                     "out_events", [](const nl::AgentEvent& e) {
                                         nl_agent_event c{};
                                         c.size = sizeof c;
                                         c.kind = static_cast<nl_agent_event_kind>(e.kind);
                                         c.agent = to_id<nl_agent_id>(e.agent);
                                         c.link = to_id<nl_link_id>(e.link);
                                         c.reason = static_cast<nl_agent_reason>(e.reason);
                                         c.user_data = e.user_data;
                                         return c;
                                     });
    });
}

}  // extern "C"
