//! navlink.h: "World".
use crate::status::nl_status;
use std::os::raw::{c_char, c_void};

/// Opaque root object.
#[repr(C)]
pub struct nl_world {
    _private: [u8; 0],
}

pub type nl_log_level = u32;
pub const NL_LOG_ERROR: nl_log_level = 0;
pub const NL_LOG_WARNING: nl_log_level = 1;
pub const NL_LOG_INFO: nl_log_level = 2;
pub const NL_LOG_DEBUG: nl_log_level = 3;

/// `nl_log_fn*`: called on the failing thread (any host thread or a NavLink worker).
pub type nl_log_fn =
    Option<unsafe extern "C" fn(user: *mut c_void, level: nl_log_level, status: nl_status, message: *const c_char)>;

pub const NL_WORKERS_AUTO: i32 = -1;
/// Largest `worker_count` and `path_worker_count` a world accepts.
pub const NL_MAX_WORKERS: i32 = 1024;

/// `nl_task_fn*`: runs items `[begin, end)` of a task NavLink enqueued, for host worker `worker_index`.
pub type nl_task_fn = Option<unsafe extern "C" fn(task_context: *mut c_void, begin: u32, end: u32, worker_index: u32)>;
/// `nl_task_enqueue_fn*`: starts a task on the host's task system; returns its handle, or null when it
/// already ran every range.
pub type nl_task_enqueue_fn = Option<
    unsafe extern "C" fn(
        user: *mut c_void,
        task: nl_task_fn,
        task_context: *mut c_void,
        item_count: u32,
        min_range: u32,
    ) -> *mut c_void,
>;
/// `nl_task_finish_fn*`: returns once every range of an enqueued task has run.
pub type nl_task_finish_fn = Option<unsafe extern "C" fn(user: *mut c_void, host_task: *mut c_void)>;

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_world_def {
    pub size: u32,
    pub worker_count: i32,
    pub log_fn: nl_log_fn,
    pub log_user: *mut c_void,
    pub log_level: nl_log_level,
    pub reserved: u32,
    pub path_worker_count: i32,
    pub task_enqueue_fn: nl_task_enqueue_fn,
    pub task_finish_fn: nl_task_finish_fn,
    pub task_user: *mut c_void,
    /// Agents' paths planned in one `nl_world_step` at most (default 32, at least 1).
    pub agent_paths_per_step: u32,
    pub reserved2: u32,
}

extern "C" {
    pub fn nl_default_world_def() -> nl_world_def;
    pub fn nl_world_create(def: *const nl_world_def, out_world: *mut *mut nl_world) -> nl_status;
    pub fn nl_world_destroy(world: *mut nl_world);
    pub fn nl_world_get_worker_count(world: *const nl_world) -> i32;
}
