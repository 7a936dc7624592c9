//! navlink.h: "Agents".
use crate::level::nl_mesh_id;
use crate::links::nl_link_id;
use crate::navmesh::nl_navmesh_id;
use crate::output_init;
use crate::paths::{nl_agent_capabilities, nl_path_point};
use crate::status::nl_status;
use crate::world::nl_world;

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_agent_id {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_agent_id, "AgentId");

pub type nl_agent_state = u32;
pub const NL_AGENT_IDLE: nl_agent_state = 0;
pub const NL_AGENT_WALKING: nl_agent_state = 1;
pub const NL_AGENT_JUMPING: nl_agent_state = 2;
pub const NL_AGENT_FALLING: nl_agent_state = 3;
pub const NL_AGENT_TRAVERSING: nl_agent_state = 4;
pub const NL_AGENT_WAITING: nl_agent_state = 5;
pub const NL_AGENT_ARRIVED: nl_agent_state = 6;
pub const NL_AGENT_FAILED: nl_agent_state = 7;

pub type nl_agent_reason = u32;
pub const NL_AGENT_REASON_NONE: nl_agent_reason = 0;
pub const NL_AGENT_REASON_DESTINATION_SET: nl_agent_reason = 1;
pub const NL_AGENT_REASON_LINK_GONE: nl_agent_reason = 2;
pub const NL_AGENT_REASON_WORLD_CHANGED: nl_agent_reason = 3;
pub const NL_AGENT_REASON_OFF_PATH: nl_agent_reason = 4;
pub const NL_AGENT_REASON_NO_PATH: nl_agent_reason = 5;
pub const NL_AGENT_REASON_NAVMESH_REMOVED: nl_agent_reason = 6;
pub const NL_AGENT_REASON_CAPABILITIES_CHANGED: nl_agent_reason = 7;
/// Other bodies are in its way: it waits for room (the WAITING event; `nl_agent_info` reads WAITING with
/// this reason meanwhile), or it gave its destination up after `nl_agent_def.give_up_seconds` (FAILED).
/// Added in 0.3.
pub const NL_AGENT_REASON_CROWD: nl_agent_reason = 8;

/// How to add an agent. Get one from `nl_default_agent_def()`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_agent_def {
    pub size: u32,
    pub navmesh: nl_navmesh_id,
    pub height: f32,
    pub capabilities: nl_agent_capabilities,
    pub max_speed: f32,
    pub max_acceleration: f32,
    pub gravity: f32,
    pub takeoff_speed: f32,
    pub position: [f32; 3],
    pub avoidance: u8,
    pub reserved: [u8; 3],
    pub user_data: u64,
    /// 0 (default): never. Held up this long by bodies heading the other way (walking or giving way on
    /// the ground) without getting 1 m nearer its destination along its path, it gives the destination
    /// up: FAILED, reason `NL_AGENT_REASON_CROWD`. A queue, all one way, never counts. Added in 0.3.
    pub give_up_seconds: f32,
    pub reserved2: u32,
}

/// An agent's state. An array element that may grow: the library lays out an output array with the
/// first element's `size`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_agent_info {
    pub size: u32,
    pub state: nl_agent_state,
    pub id: nl_agent_id,
    pub position: [f32; 3],
    pub velocity: [f32; 3],
    pub polygon: u32,
    pub reason: nl_agent_reason,
    pub link: nl_link_id,
    pub link_progress: f32,
    /// In the world, where it is now (on a moving surface it moves with the surface).
    pub destination: [f32; 3],
    pub has_destination: u8,
    pub reserved: [u8; 3],
    pub corners_ahead: u32,
    pub user_data: u64,
    /// The navmesh it stands on now (it changes when the agent takes a cross link; while in the air, the
    /// one it took off from). Added in 0.3.
    pub navmesh: nl_navmesh_id,
    /// The movable mesh that navmesh rides (the agent rides it too), or the null id. Added in 0.3.
    pub surface: nl_mesh_id,
    /// `position` in that mesh's own space (equal to `position` on no surface, and in the air over a
    /// cross link). Added in 0.3.
    pub surface_position: [f32; 3],
    pub reserved2: u32,
}

pub fn nl_agent_info_init() -> nl_agent_info {
    unsafe { output_init() }
}
default_is_init!(nl_agent_info, nl_agent_info_init);

pub type nl_trajectory_kind = u32;
pub const NL_TRAJECTORY_NONE: nl_trajectory_kind = 0;
pub const NL_TRAJECTORY_ARC: nl_trajectory_kind = 1;
pub const NL_TRAJECTORY_FALL: nl_trajectory_kind = 2;
pub const NL_TRAJECTORY_LINE: nl_trajectory_kind = 3;

/// How a link is being taken: the trajectory the generator checked, with its timing.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_agent_trajectory {
    pub size: u32,
    pub kind: nl_trajectory_kind,
    pub link: nl_link_id,
    pub from: [f32; 3],
    pub to: [f32; 3],
    pub apex: [f32; 3],
    /// For `NL_TRAJECTORY_FALL`; else from, from, to, to.
    pub points: [[f32; 3]; 4],
    pub duration: f32,
    pub elapsed: f32,
}

pub fn nl_agent_trajectory_init() -> nl_agent_trajectory {
    unsafe { output_init() }
}
default_is_init!(nl_agent_trajectory, nl_agent_trajectory_init);

pub type nl_agent_event_kind = u32;
pub const NL_AGENT_EVENT_PATH_READY: nl_agent_event_kind = 1;
pub const NL_AGENT_EVENT_LINK_STARTED: nl_agent_event_kind = 2;
pub const NL_AGENT_EVENT_LINK_FINISHED: nl_agent_event_kind = 3;
pub const NL_AGENT_EVENT_ARRIVED: nl_agent_event_kind = 4;
pub const NL_AGENT_EVENT_FAILED: nl_agent_event_kind = 5;
pub const NL_AGENT_EVENT_REPLANNED: nl_agent_event_kind = 6;
/// It stopped for room (reason `NL_AGENT_REASON_CROWD`): stuck among other bodies for 0.75 s, or giving
/// way to one; its `nl_agent_info` reads WAITING, reason CROWD, until it walks on. Said once per wait.
/// Added in 0.3.
pub const NL_AGENT_EVENT_WAITING: nl_agent_event_kind = 7;

/// What happened to an agent in the last step. An array element that may grow.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct nl_agent_event {
    pub size: u32,
    pub kind: nl_agent_event_kind,
    pub agent: nl_agent_id,
    pub link: nl_link_id,
    pub reason: nl_agent_reason,
    pub reserved: u32,
    pub user_data: u64,
}

pub fn nl_agent_event_init() -> nl_agent_event {
    unsafe { output_init() }
}
default_is_init!(nl_agent_event, nl_agent_event_init);

extern "C" {
    pub fn nl_default_agent_def() -> nl_agent_def;
    pub fn nl_agent_add(world: *mut nl_world, def: *const nl_agent_def, out_id: *mut nl_agent_id) -> nl_status;
    pub fn nl_agent_remove(world: *mut nl_world, agent: nl_agent_id) -> nl_status;
    pub fn nl_agent_is_valid(world: *const nl_world, agent: nl_agent_id) -> i32;
    pub fn nl_agent_set_destination(world: *mut nl_world, agent: nl_agent_id, point: *const f32) -> nl_status;
    pub fn nl_agent_stop(world: *mut nl_world, agent: nl_agent_id) -> nl_status;
    pub fn nl_agent_teleport(world: *mut nl_world, agent: nl_agent_id, point: *const f32) -> nl_status;
    pub fn nl_agent_set_capabilities(
        world: *mut nl_world,
        agent: nl_agent_id,
        capabilities: *const nl_agent_capabilities,
    ) -> nl_status;
    pub fn nl_agent_set_speed(world: *mut nl_world, agent: nl_agent_id, max_speed: f32, max_acceleration: f32)
        -> nl_status;
    pub fn nl_world_step(world: *mut nl_world, dt: f32) -> nl_status;
    pub fn nl_agent_get_info(world: *const nl_world, agent: nl_agent_id, out_info: *mut nl_agent_info) -> nl_status;
    pub fn nl_world_get_agents(
        world: *const nl_world,
        out_infos: *mut nl_agent_info,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_agent_get_corners(
        world: *const nl_world,
        agent: nl_agent_id,
        out_points: *mut nl_path_point,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_agent_get_trajectory(
        world: *const nl_world,
        agent: nl_agent_id,
        out_trajectory: *mut nl_agent_trajectory,
    ) -> nl_status;
    pub fn nl_world_get_agent_events(
        world: *const nl_world,
        out_events: *mut nl_agent_event,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
}
