//! Path requests: planned now (`find_path`) or queued with tickets (`request_path`...).
use crate::callbacks::{self, PathBox};
use crate::error::{check, Result};
use crate::types::{AgentCapabilities, NavmeshId, PathPoint, PathQueueStats, PathTicket};
use crate::world::World;
use navlink_sys as sys;
use std::os::raw::c_void;
use std::ptr;

/// How a request ended (`nl_path_outcome`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathOutcome {
    Pending,
    Complete,
    Partial,
    NoPath,
    StartOffNavmesh,
    GoalOffNavmesh,
    Cancelled,
    Failed,
    /// A value a newer library may add.
    Other(u32),
}

impl PathOutcome {
    pub fn from_raw(raw: u32) -> PathOutcome {
        match raw {
            sys::NL_PATH_PENDING => PathOutcome::Pending,
            sys::NL_PATH_COMPLETE => PathOutcome::Complete,
            sys::NL_PATH_PARTIAL => PathOutcome::Partial,
            sys::NL_PATH_NO_PATH => PathOutcome::NoPath,
            sys::NL_PATH_START_OFF_NAVMESH => PathOutcome::StartOffNavmesh,
            sys::NL_PATH_GOAL_OFF_NAVMESH => PathOutcome::GoalOffNavmesh,
            sys::NL_PATH_CANCELLED => PathOutcome::Cancelled,
            sys::NL_PATH_FAILED => PathOutcome::Failed,
            other => PathOutcome::Other(other),
        }
    }
}

/// A walker: radius 0.6, no jumps, no drops.
pub fn default_agent_capabilities() -> AgentCapabilities {
    unsafe { sys::nl_default_agent_capabilities() }
}

/// One path request, with the header's defaults (`nl_default_path_request_def`).
#[derive(Clone, Debug)]
pub struct PathQuery {
    pub navmesh: NavmeshId,
    pub start: [f32; 3],
    pub goal: [f32; 3],
    pub search_half_extents: [f32; 3],
    pub agent: AgentCapabilities,
    /// Cost per metre in area i; empty: every area costs 1.
    pub area_costs: Vec<f32>,
    pub link_cost: f32,
    pub max_nodes: u32,
    pub accept_partial: bool,
}

impl PathQuery {
    pub fn new(navmesh: NavmeshId, start: [f32; 3], goal: [f32; 3], agent: AgentCapabilities) -> PathQuery {
        let def = unsafe { sys::nl_default_path_request_def() };
        PathQuery {
            navmesh,
            start,
            goal,
            search_half_extents: def.search_half_extents,
            agent,
            area_costs: Vec::new(),
            link_cost: def.link_cost,
            max_nodes: def.max_nodes,
            accept_partial: def.accept_partial != 0,
        }
    }

    /// The C def; borrows `self.area_costs`.
    fn def(&self) -> sys::nl_path_request_def {
        let mut def = unsafe { sys::nl_default_path_request_def() };
        def.navmesh = self.navmesh;
        def.start = self.start;
        def.goal = self.goal;
        def.search_half_extents = self.search_half_extents;
        def.agent = self.agent;
        def.area_costs = if self.area_costs.is_empty() { ptr::null() } else { self.area_costs.as_ptr() };
        def.area_cost_count = self.area_costs.len() as u32;
        def.link_cost = self.link_cost;
        def.max_nodes = self.max_nodes;
        def.accept_partial = self.accept_partial as u8;
        def
    }
}

/// What a finished request found.
#[derive(Clone, Debug, PartialEq)]
pub struct PathResult {
    pub info: sys::nl_path_result,
    pub points: Vec<PathPoint>,
}

impl PathResult {
    pub fn outcome(&self) -> PathOutcome {
        PathOutcome::from_raw(self.info.outcome)
    }
}

/// How much `process_paths` may do in one call (`nl_path_budget`). `Default`: no limits. A request is
/// never split: the budget is checked between requests, so a call that finds the queue non-empty plans
/// at least one, and the request that crosses a limit finishes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathBudget {
    /// Requests planned at most; 0: no limit.
    pub max_requests: u32,
    /// Time spent at most; <= 0: no limit.
    pub max_milliseconds: f64,
    /// Polygons the searches may visit in all (their `nodes_visited` added up); 0: no limit. Bounds a
    /// frame by work, whatever the clock does.
    pub max_search_nodes: u64,
}

impl Default for PathBudget {
    /// No limits (`nl_default_path_budget`).
    fn default() -> Self {
        let c = unsafe { sys::nl_default_path_budget() };
        PathBudget { max_requests: c.max_requests, max_milliseconds: c.max_milliseconds, max_search_nodes: c.max_search_nodes }
    }
}

impl PathBudget {
    /// No limits: plan until the queue is empty.
    pub fn unlimited() -> Self {
        Self::default()
    }

    /// At most `max_requests` requests.
    pub fn requests(max_requests: u32) -> Self {
        PathBudget { max_requests, ..Self::default() }
    }

    /// Until `max_milliseconds` have passed (checked between requests).
    pub fn milliseconds(max_milliseconds: f64) -> Self {
        PathBudget { max_milliseconds, ..Self::default() }
    }

    /// Until the searches have visited `max_search_nodes` polygons (checked between requests).
    pub fn search_nodes(max_search_nodes: u64) -> Self {
        PathBudget { max_search_nodes, ..Self::default() }
    }

    fn to_c(self) -> sys::nl_path_budget {
        let mut c = unsafe { sys::nl_default_path_budget() };
        c.max_requests = self.max_requests;
        c.max_milliseconds = self.max_milliseconds;
        c.max_search_nodes = self.max_search_nodes;
        c
    }
}

/// A request that finished, as `take_finished_paths` reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FinishedPath {
    pub ticket: PathTicket,
    pub outcome: PathOutcome,
}

fn empty_result() -> sys::nl_path_result {
    sys::nl_path_result_init()
}

fn buffer_too_small(status: u32) -> bool {
    sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0
}

// Points fetched in one go by find_path when the path has no more; longer ones take a second call.
const FIRST_POINT_CAPACITY: usize = 64;
// Finished requests taken per call at first by take_finished_paths; more calls take the rest.
const FINISHED_CHUNK: usize = 16;

impl World {
    /// Plans a path now, on this thread (for tools and tests; games queue requests).
    pub fn find_path(&self, query: &PathQuery) -> Result<PathResult> {
        let def = query.def();
        // PathPoint::default() sets the size the library lays the points out with.
        let mut points = vec![PathPoint::default(); FIRST_POINT_CAPACITY];
        loop {
            let mut info = empty_result();
            let mut count = 0;
            let status = unsafe {
                sys::nl_path_find(self.raw(), &def, &mut info, points.as_mut_ptr(), points.len() as u32, &mut count)
            };
            if buffer_too_small(status) {
                // More points than room: this thread kept the plan, the second call copies it.
                points = vec![PathPoint::default(); count as usize];
                continue;
            }
            check(status)?;
            points.truncate(count as usize);
            return Ok(PathResult { info, points });
        }
    }

    /// Queues a request; poll its ticket, read the result, release it.
    pub fn request_path(&self, query: &PathQuery) -> Result<PathTicket> {
        self.submit(query, None)
    }

    /// Queues a request; `on_finished` runs exactly once when it finishes, on a NavLink path worker, in
    /// `process_paths`, in `cancel_path` or when the world is dropped. A panic in it is caught and reported.
    pub fn request_path_with<F>(&self, query: &PathQuery, on_finished: F) -> Result<PathTicket>
    where
        F: FnOnce(PathTicket, PathOutcome) + Send + 'static,
    {
        self.submit(query, Some(Box::new(on_finished)))
    }

    fn submit(&self, query: &PathQuery, on_finished: Option<PathBox>) -> Result<PathTicket> {
        let mut def = query.def();
        let user = on_finished.map(|f| Box::into_raw(Box::new(f)));
        if let Some(user) = user {
            def.callback = Some(callbacks::path_finished);
            def.user = user as *mut c_void;
        }
        let mut ticket = PathTicket::default();
        let status = unsafe { sys::nl_path_request(self.raw(), &def, &mut ticket) };
        if sys::nl_failed(status) {
            let error = check(status).unwrap_err();
            if let Some(user) = user {
                // A refused request never calls back: the closure is ours to free.
                drop(unsafe { Box::from_raw(user) });
            }
            return Err(error);
        }
        Ok(ticket)
    }

    /// The request's outcome (`Pending` while it runs).
    pub fn poll_path(&self, ticket: PathTicket) -> Result<PathOutcome> {
        let mut outcome = 0;
        check(unsafe { sys::nl_path_poll(self.raw(), ticket, &mut outcome) })?;
        Ok(PathOutcome::from_raw(outcome))
    }

    /// The finished request's result, or `None` while it is pending.
    pub fn path_result(&self, ticket: PathTicket) -> Result<Option<PathResult>> {
        loop {
            let mut info = empty_result();
            let mut count = 0;
            let status = unsafe { sys::nl_path_get_result(self.raw(), ticket, &mut info, ptr::null_mut(), 0, &mut count) };
            if status & sys::NL_STATUS_IN_PROGRESS != 0 {
                return Ok(None);
            }
            if !buffer_too_small(status) {
                check(status)?;
            }
            let mut points = vec![PathPoint::default(); count as usize];
            let status =
                unsafe { sys::nl_path_get_result(self.raw(), ticket, &mut info, points.as_mut_ptr(), count, &mut count) };
            if buffer_too_small(status) {
                continue;
            }
            check(status)?;
            points.truncate(count as usize);
            return Ok(Some(PathResult { info, points }));
        }
    }

    /// Asks a request to stop (a queued one finishes at once as `Cancelled`).
    pub fn cancel_path(&self, ticket: PathTicket) -> Result<()> {
        check(unsafe { sys::nl_path_cancel(self.raw(), ticket) }).map(drop)
    }

    /// Frees the request's result; the ticket becomes invalid (an unfinished request is cancelled).
    pub fn release_path(&self, ticket: PathTicket) -> Result<()> {
        check(unsafe { sys::nl_path_release(self.raw(), ticket) }).map(drop)
    }

    /// Plans queued requests on this thread until the queue is empty or the budget is spent; returns how
    /// many finished here. How a world with `path_worker_count` 0 runs its queue, e.g.
    /// `world.process_paths(PathBudget::milliseconds(2.0))` each frame.
    pub fn process_paths(&self, budget: PathBudget) -> Result<u32> {
        let budget = budget.to_c();
        let mut processed = 0;
        check(unsafe { sys::nl_path_process(self.raw(), &budget, &mut processed) })?;
        Ok(processed)
    }

    /// The requests that finished since the last call, oldest first, each reported once: the way to
    /// learn of finished requests on your own thread without a closure (closures still run too).
    /// Requests whose ticket was released are not reported.
    pub fn take_finished_paths(&self) -> Result<Vec<FinishedPath>> {
        let mut taken = Vec::new();
        // nl_path_finished::default() sets the size the library lays the array out with.
        let mut buffer = vec![sys::nl_path_finished::default(); FINISHED_CHUNK];
        loop {
            let (mut count, mut remaining) = (0u32, 0u32);
            check(unsafe {
                sys::nl_path_take_finished(self.raw(), buffer.as_mut_ptr(), buffer.len() as u32, &mut count, &mut remaining)
            })?;
            taken.extend(buffer[..count as usize].iter().map(|f| FinishedPath {
                ticket: f.ticket,
                outcome: PathOutcome::from_raw(f.outcome),
            }));
            if remaining == 0 {
                return Ok(taken);
            }
            if remaining as usize > buffer.len() {
                buffer = vec![sys::nl_path_finished::default(); remaining as usize];
            }
        }
    }

    pub fn path_queue_stats(&self) -> Result<PathQueueStats> {
        let mut stats = PathQueueStats::default(); // size set
        check(unsafe { sys::nl_path_get_queue_stats(self.raw(), &mut stats) })?;
        Ok(stats)
    }
}
