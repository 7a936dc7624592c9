//! navlink.h: "Paths".
use crate::links::nl_link_id;
use crate::navmesh::nl_navmesh_id;
use crate::output_init;
use crate::status::nl_status;
use crate::world::nl_world;
use std::os::raw::{c_char, c_void};

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_path_ticket {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_path_ticket, "PathTicket");

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_agent_capabilities {
    pub max_jump_distance: f32,
    pub max_jump_height: f32,
    pub max_drop_height: f32,
    pub radius: f32,
    pub abilities: u64,
}

pub const NL_AREA_EXCLUDED: f32 = 0.0;

pub type nl_path_outcome = u32;
pub const NL_PATH_PENDING: nl_path_outcome = 0;
pub const NL_PATH_COMPLETE: nl_path_outcome = 1;
pub const NL_PATH_PARTIAL: nl_path_outcome = 2;
pub const NL_PATH_NO_PATH: nl_path_outcome = 3;
pub const NL_PATH_START_OFF_NAVMESH: nl_path_outcome = 4;
pub const NL_PATH_GOAL_OFF_NAVMESH: nl_path_outcome = 5;
pub const NL_PATH_CANCELLED: nl_path_outcome = 6;
pub const NL_PATH_FAILED: nl_path_outcome = 7;

/// `nl_path_wait`'s timeout that never ends.
pub const NL_PATH_WAIT_FOREVER: u32 = 0xffff_ffff;

/// `nl_path_callback*`: called exactly once per accepted request, from the thread that finished it.
pub type nl_path_callback =
    Option<unsafe extern "C" fn(user: *mut c_void, ticket: nl_path_ticket, outcome: nl_path_outcome)>;

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_path_request_def {
    pub size: u32,
    pub navmesh: nl_navmesh_id,
    pub start: [f32; 3],
    pub goal: [f32; 3],
    pub search_half_extents: [f32; 3],
    pub agent: nl_agent_capabilities,
    pub area_costs: *const f32,
    pub area_cost_count: u32,
    pub link_cost: f32,
    pub max_nodes: u32,
    pub accept_partial: u8,
    pub reserved: [u8; 3],
    pub callback: nl_path_callback,
    pub user: *mut c_void,
}

pub type nl_segment_kind = u32;
pub const NL_SEGMENT_WALK: nl_segment_kind = 0;

/// An array element that may grow: the library lays out an output array with the first element's `size`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_path_point {
    pub size: u32,
    pub position: [f32; 3],
    pub polygon: u32,
    pub segment: nl_segment_kind,
    pub link: nl_link_id,
    pub apex: [f32; 3],
    pub reversed: u8,
    pub reserved: [u8; 3],
    /// The point in its navmesh's own space (`position` and `apex` are in the world, at the surface's pose
    /// when the path was planned); equal to `position` on a navmesh that rides nothing. Added in 0.3.
    pub surface_position: [f32; 3],
}

pub fn nl_path_point_init() -> nl_path_point {
    unsafe { output_init() }
}
default_is_init!(nl_path_point, nl_path_point_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_path_result {
    pub size: u32,
    pub outcome: nl_path_outcome,
    pub status: nl_status,
    pub point_count: u32,
    pub links_used: u32,
    pub nodes_visited: u32,
    pub out_of_nodes: u8,
    pub reserved: [u8; 3],
    pub length: f32,
    pub cost: f32,
    pub start: [f32; 3],
    pub goal: [f32; 3],
}

pub fn nl_path_result_init() -> nl_path_result {
    unsafe { output_init() }
}
default_is_init!(nl_path_result, nl_path_result_init);

/// Why a path falls short of its goal: `nl_path_shortfall::reason`.
pub const NL_PATH_SHORTFALL_NONE: u32 = 0;
pub const NL_PATH_SHORTFALL_OUT_OF_NODES: u32 = 1;
pub const NL_PATH_SHORTFALL_BODY_TOO_WIDE: u32 = 2;
pub const NL_PATH_SHORTFALL_AREAS_EXCLUDED: u32 = 3;
pub const NL_PATH_SHORTFALL_LINK_BEYOND_BODY: u32 = 4;
pub const NL_PATH_SHORTFALL_NO_LINKS: u32 = 5;
pub const NL_PATH_SHORTFALL_NOT_CONNECTED: u32 = 6;

/// What a link asks that the body lacks: `nl_path_shortfall::limit`.
pub const NL_LINK_LIMIT_NONE: u32 = 0;
pub const NL_LINK_LIMIT_JUMP_DISTANCE: u32 = 1;
pub const NL_LINK_LIMIT_JUMP_HEIGHT: u32 = 2;
pub const NL_LINK_LIMIT_DROP_HEIGHT: u32 = 3;
pub const NL_LINK_LIMIT_WIDTH: u32 = 4;
pub const NL_LINK_LIMIT_ABILITIES: u32 = 5;

/// Why a request's path falls short of its goal (`nl_path_explain`). `text` is a NUL-terminated UTF-8
/// sentence ("" for `NL_PATH_SHORTFALL_NONE`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_path_shortfall {
    pub size: u32,
    pub reason: u32,
    pub limit: u32,
    pub needed: f32,
    pub has: f32,
    pub reversed: u32,
    pub missing_abilities: u64,
    pub link: nl_link_id,
    pub link_start: [f32; 3],
    pub text: [c_char; 256],
}

pub fn nl_path_shortfall_init() -> nl_path_shortfall {
    unsafe { output_init() }
}
default_is_init!(nl_path_shortfall, nl_path_shortfall_init);

/// How much `nl_path_process` may do in one call. Get one from `nl_default_path_budget()`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_path_budget {
    pub size: u32,
    pub max_requests: u32,
    pub max_milliseconds: f64,
    pub max_search_nodes: u64,
}

/// A request that finished, as `nl_path_take_finished` reports it. An array element that may grow.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct nl_path_finished {
    pub size: u32,
    pub outcome: nl_path_outcome,
    pub ticket: nl_path_ticket,
    pub user: *mut c_void,
}

pub fn nl_path_finished_init() -> nl_path_finished {
    unsafe { output_init() }
}
default_is_init!(nl_path_finished, nl_path_finished_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct nl_path_queue_stats {
    pub size: u32,
    pub workers: u32,
    pub queued: u32,
    pub running: u32,
    pub unreleased: u32,
    pub reserved: u32,
    pub submitted: u64,
    pub finished: u64,
}

pub fn nl_path_queue_stats_init() -> nl_path_queue_stats {
    unsafe { output_init() }
}
default_is_init!(nl_path_queue_stats, nl_path_queue_stats_init);

extern "C" {
    pub fn nl_default_agent_capabilities() -> nl_agent_capabilities;
    pub fn nl_default_path_request_def() -> nl_path_request_def;
    pub fn nl_path_find(
        world: *mut nl_world,
        def: *const nl_path_request_def,
        out_result: *mut nl_path_result,
        out_points: *mut nl_path_point,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    /// Plans the request as `nl_path_find` does and, for a PARTIAL or NO_PATH outcome, says why (up to five
    /// searches on the calling thread); `NL_PATH_SHORTFALL_NONE` otherwise.
    pub fn nl_path_explain(
        world: *mut nl_world,
        def: *const nl_path_request_def,
        out_shortfall: *mut nl_path_shortfall,
    ) -> nl_status;
    pub fn nl_path_request(world: *mut nl_world, def: *const nl_path_request_def, out_ticket: *mut nl_path_ticket)
        -> nl_status;
    pub fn nl_path_poll(world: *const nl_world, ticket: nl_path_ticket, out_outcome: *mut nl_path_outcome)
        -> nl_status;
    /// Blocks until the request finished (SUCCESS) or `timeout_ms` passed (IN_PROGRESS, outcome PENDING);
    /// with path_worker_count 0 the waiting thread plans queued requests itself. INVALID_ARGUMENT from
    /// inside a path callback.
    pub fn nl_path_wait(
        world: *mut nl_world,
        ticket: nl_path_ticket,
        timeout_ms: u32,
        out_outcome: *mut nl_path_outcome,
    ) -> nl_status;
    pub fn nl_path_get_result(
        world: *const nl_world,
        ticket: nl_path_ticket,
        out_result: *mut nl_path_result,
        out_points: *mut nl_path_point,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_path_cancel(world: *mut nl_world, ticket: nl_path_ticket) -> nl_status;
    pub fn nl_path_release(world: *mut nl_world, ticket: nl_path_ticket) -> nl_status;
    pub fn nl_default_path_budget() -> nl_path_budget;
    pub fn nl_path_process(world: *mut nl_world, budget: *const nl_path_budget, out_processed: *mut u32) -> nl_status;
    pub fn nl_path_take_finished(
        world: *mut nl_world,
        out_finished: *mut nl_path_finished,
        capacity: u32,
        out_count: *mut u32,
        out_remaining: *mut u32,
    ) -> nl_status;
    pub fn nl_path_get_queue_stats(world: *const nl_world, out_stats: *mut nl_path_queue_stats) -> nl_status;
}
