//! The world: the root object that owns everything.
use crate::callbacks::{self, LogBox};
use crate::error::{check, Error, Result};
use crate::types::Version;
use navlink_sys as sys;
use std::os::raw::c_void;
use std::ptr::NonNull;

/// Receives every failure of a call on the world (and, by `log_level`, warnings...): level, status,
/// message. Called on the failing thread, which may be a NavLink worker, hence `Send + Sync`; it must not
/// call into the same world (navlink.h).
pub type LogFn = dyn Fn(u32, u32, &str) + Send + Sync;

/// How to create a world (`nl_world_def`).
pub struct WorldOptions {
    /// Threads for batch work, the caller included; `WORKERS_AUTO`: one per hardware thread.
    pub worker_count: i32,
    /// Threads planning queued path requests; 0: the host runs the queue with `World::process_paths`.
    pub path_worker_count: i32,
    pub log_level: u32,
    pub log: Option<Box<LogFn>>,
    /// Agents' paths planned in one `World::step` at most (at least 1): when many agents ask at once,
    /// the rest wait their turn (`agent_state::WAITING`), oldest first, so a step's cost stays bounded.
    pub agent_paths_per_step: u32,
}

impl Default for WorldOptions {
    fn default() -> Self {
        let def = unsafe { sys::nl_default_world_def() };
        WorldOptions {
            worker_count: def.worker_count,
            path_worker_count: def.path_worker_count,
            log_level: def.log_level,
            log: None,
            agent_paths_per_step: def.agent_paths_per_step,
        }
    }
}

/// A host task system (`nl_world_def.task_enqueue_fn`, `task_finish_fn`, `task_user`): NavLink's batch
/// work (ray and segment batches, point location, link generation) runs on the host's threads instead of
/// TBB's, with identical results. `WorldOptions::worker_count` is then the number of the host's workers
/// (1 to `NL_MAX_WORKERS`; the worker indices NavLink may be given lie below it). The callbacks'
/// contract is navlink.h's (`nl_task_fn`, `nl_task_enqueue_fn`, `nl_task_finish_fn`); see
/// `World::with_host_tasks`.
#[derive(Clone, Copy, Debug)]
pub struct HostTasks {
    /// Starts `task(task_context, begin, end, worker)` over ranges covering `[0, item_count)`; returns
    /// the host's handle, or null when every range already ran.
    pub enqueue: unsafe extern "C" fn(
        user: *mut c_void,
        task: sys::nl_task_fn,
        task_context: *mut c_void,
        item_count: u32,
        min_range: u32,
    ) -> *mut c_void,
    /// Returns once every range of the task behind `host_task` has run (helping rather than sleeping).
    pub finish: unsafe extern "C" fn(user: *mut c_void, host_task: *mut c_void),
    /// Passed back to both as `user`.
    pub user: *mut c_void,
}

// `World::with_host_tasks`'s contract already requires the callbacks and `user` to be usable from any
// thread, so the options that carry them may be built on one thread and used on another.
unsafe impl Send for HostTasks {}
unsafe impl Sync for HostTasks {}

/// A NavLink world. Its methods may be called from several threads at once (navlink.h); dropping it
/// destroys the world, finishing queued path requests as cancelled (their callbacks run then).
pub struct World {
    raw: NonNull<sys::nl_world>,
    // The log callback's closure; dropped after the world (fields drop after `Drop::drop`).
    _log: Option<Box<LogBox>>,
}

// navlink.h: "all functions that take a world are safe to call from several threads at once on the same
// world; nl_world_destroy must not race with any other call on it". Drop takes the world by value, after
// every borrow has ended, so no call can race with it.
unsafe impl Send for World {}
unsafe impl Sync for World {}

impl World {
    /// A world with every default.
    pub fn new() -> Result<World> {
        World::with_options(WorldOptions::default())
    }

    pub fn with_options(options: WorldOptions) -> Result<World> {
        World::create(options, None)
    }

    /// A world whose batch work runs on the host's task system.
    ///
    /// # Safety
    /// `tasks.enqueue` and `tasks.finish` must keep navlink.h's contract: every range of a task run
    /// exactly once, and all of them returned before `finish` returns (or before `enqueue` returns
    /// null), whatever thread they run on; `finish` must not run work that calls into NavLink while
    /// it waits. Both, and whatever `tasks.user` points to, must stay valid and usable from any
    /// thread until the world is dropped.
    pub unsafe fn with_host_tasks(options: WorldOptions, tasks: HostTasks) -> Result<World> {
        World::create(options, Some(tasks))
    }

    fn create(options: WorldOptions, tasks: Option<HostTasks>) -> Result<World> {
        let mut def = unsafe { sys::nl_default_world_def() };
        def.worker_count = options.worker_count;
        def.path_worker_count = options.path_worker_count;
        def.log_level = options.log_level;
        def.agent_paths_per_step = options.agent_paths_per_step;
        if let Some(tasks) = tasks {
            def.task_enqueue_fn = Some(tasks.enqueue);
            def.task_finish_fn = Some(tasks.finish);
            def.task_user = tasks.user;
        }
        let log: Option<Box<LogBox>> = options.log.map(Box::new);
        if let Some(handler) = &log {
            def.log_fn = Some(callbacks::log);
            def.log_user = &**handler as *const LogBox as *mut c_void;
        }
        let mut raw = std::ptr::null_mut();
        check(unsafe { sys::nl_world_create(&def, &mut raw) })?;
        let raw = NonNull::new(raw).ok_or_else(|| Error::binding(sys::NL_STATUS_INTERNAL_ERROR, "null world".into()))?;
        Ok(World { raw, _log: log })
    }

    /// The loaded library's version.
    pub fn library_version() -> Version {
        unsafe { sys::nl_get_version() }
    }

    /// Threads used for batch work (1 when everything runs on the caller).
    pub fn worker_count(&self) -> i32 {
        unsafe { sys::nl_world_get_worker_count(self.raw()) }
    }

    /// The `nl_world*`, for navlink-sys calls; valid while `self` lives. Do not destroy it.
    pub fn as_ptr(&self) -> *mut sys::nl_world {
        self.raw.as_ptr()
    }

    pub(crate) fn raw(&self) -> *mut sys::nl_world {
        self.raw.as_ptr()
    }
}

impl Drop for World {
    fn drop(&mut self) {
        unsafe { sys::nl_world_destroy(self.raw.as_ptr()) }
    }
}
