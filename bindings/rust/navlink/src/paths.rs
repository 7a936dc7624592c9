//! Path requests: planned now (`find_path`) or queued (`request_path`), each queued one a
//! [`PathRequest`] to poll, wait for or await, released when dropped.
use crate::callbacks::{self, PathBox, PathCallback};
use crate::error::{check, Error, Result};
use crate::kinds::{LinkLimit, PathOutcome, PathShortfallReason};
use crate::types::{AgentCapabilities, LinkId, NavmeshId, PathPoint, PathQueueStats, PathSummary, PathTicket};
use crate::world::World;
use navlink_sys as sys;
use std::future::Future;
use std::os::raw::c_void;
use std::pin::Pin;
use std::ptr;
use std::sync::{Arc, Mutex, MutexGuard};
use std::task::{Context, Poll, Waker};
use std::time::Duration;

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
    pub capabilities: AgentCapabilities,
    /// Cost per metre in area i; empty: every area costs 1.
    pub area_costs: Vec<f32>,
    pub link_cost: f32,
    pub max_nodes: u32,
    pub accept_partial: bool,
}

impl PathQuery {
    pub fn new(navmesh: NavmeshId, start: [f32; 3], goal: [f32; 3], capabilities: AgentCapabilities) -> PathQuery {
        let def = unsafe { sys::nl_default_path_request_def() };
        PathQuery {
            navmesh,
            start,
            goal,
            search_half_extents: def.search_half_extents,
            capabilities,
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
        def.capabilities = self.capabilities;
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
    pub summary: PathSummary,
    pub points: Vec<PathPoint>,
}

impl PathResult {
    pub fn outcome(&self) -> PathOutcome {
        self.summary.outcome
    }

    fn from_c(summary: sys::nl_path_result, points: Vec<sys::nl_path_point>) -> PathResult {
        PathResult { summary: summary.into(), points: points.into_iter().map(PathPoint::from).collect() }
    }
}

/// Why a request's path falls short of its goal (`World::explain_path`, `nl_path_shortfall`).
#[derive(Clone, Debug, PartialEq)]
pub struct PathShortfall {
    /// `None` when the path reaches the goal or an end is off the navmesh.
    pub reason: PathShortfallReason,
    /// For `LinkBeyondBody`: what the link asks that the body lacks.
    pub limit: LinkLimit,
    /// `LinkBeyondBody`: what the link needs, metres (for `LinkLimit::Width` the body's diameter);
    /// `BodyTooWide`: the body's radius.
    pub needed: f32,
    /// `LinkBeyondBody`: what the body can, metres (for `LinkLimit::Width` the link's clearance);
    /// `BodyTooWide`: the navmesh's radius.
    pub has: f32,
    /// The link would be taken from its end to its start.
    pub reversed: bool,
    /// `LinkLimit::Abilities`: the bits the body lacks.
    pub missing_abilities: u64,
    /// `LinkBeyondBody`: the link (of the request's navmesh, or a cross link of another); the null id otherwise.
    pub link: LinkId,
    /// Where the body would take the link, in the world.
    pub link_start: [f32; 3],
    /// The same as a sentence naming the field to change, e.g. "a drop at (12, 4, 3) would get there: it
    /// needs a drop of 4.2 m, and the body drops 4 m (max_drop_height)"; empty for `None`.
    pub text: String,
}

impl From<sys::nl_path_shortfall> for PathShortfall {
    fn from(c: sys::nl_path_shortfall) -> PathShortfall {
        // A NUL-terminated UTF-8 sentence in a char[256].
        let bytes: Vec<u8> = c.text.iter().take_while(|&&b| b != 0).map(|&b| b as u8).collect();
        PathShortfall {
            reason: PathShortfallReason::from_raw(c.reason),
            limit: LinkLimit::from_raw(c.limit),
            needed: c.needed,
            has: c.has,
            reversed: c.reversed != 0,
            missing_abilities: c.missing_abilities,
            link: c.link,
            link_start: c.link_start,
            text: String::from_utf8_lossy(&bytes).into_owned(),
        }
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
        // nl_path_point::default() sets the size the library lays the points out with.
        let mut points = vec![sys::nl_path_point::default(); FIRST_POINT_CAPACITY];
        loop {
            let mut info = empty_result();
            let mut count = 0;
            let status = unsafe {
                sys::nl_path_find(self.raw(), &def, &mut info, points.as_mut_ptr(), points.len() as u32, &mut count)
            };
            if buffer_too_small(status) {
                // More points than room: this thread kept the plan, the second call copies it.
                points = vec![sys::nl_path_point::default(); count as usize];
                continue;
            }
            check(status)?;
            points.truncate(count as usize);
            return Ok(PathResult::from_c(info, points));
        }
    }

    /// Why the query's path falls short of its goal (`nl_path_explain`): plans it as `find_path` does and,
    /// for a `Partial` or `NoPath` outcome, plans again with one limit lifted at a time (the body's width,
    /// the excluded areas, the links the body cannot take) and names the first that gets there;
    /// `PathShortfallReason::None` when the path reaches the goal or an end is off the navmesh. Up to five
    /// searches on this thread: for tools, logs and debugging.
    pub fn explain_path(&self, query: &PathQuery) -> Result<PathShortfall> {
        let def = query.def();
        let mut shortfall = sys::nl_path_shortfall_init();
        check(unsafe { sys::nl_path_explain(self.raw(), &def, &mut shortfall) })?;
        Ok(PathShortfall::from(shortfall))
    }

    /// Queues a request: poll, wait for or await the [`PathRequest`]; dropping it releases the ticket.
    pub fn request_path(&self, query: &PathQuery) -> Result<PathRequest<'_>> {
        self.submit(query, None)
    }

    /// Queues a request; `on_finished` runs exactly once when it finishes, on a NavLink path worker, in
    /// `process_paths` or a wait, in `cancel_path`, or when the request is dropped unfinished (which
    /// cancels it). A panic in it is caught and reported.
    pub fn request_path_with<F>(&self, query: &PathQuery, on_finished: F) -> Result<PathRequest<'_>>
    where
        F: FnOnce(PathTicket, PathOutcome) + Send + 'static,
    {
        self.submit(query, Some(Box::new(on_finished)))
    }

    fn submit(&self, query: &PathQuery, on_finished: Option<PathBox>) -> Result<PathRequest<'_>> {
        let mut def = query.def();
        // Every request calls back, to fill the slot its future reads: the callback may run before
        // nl_path_request returns, so the slot exists first.
        let finished = Arc::new(Mutex::new(FinishedSlot::default()));
        let user = Box::into_raw(Box::new(PathCallback { finished: finished.clone(), on_finished }));
        def.callback = Some(callbacks::path_finished);
        def.user = user as *mut c_void;
        let mut ticket = PathTicket::default();
        let status = unsafe { sys::nl_path_request(self.raw(), &def, &mut ticket) };
        if sys::nl_failed(status) {
            let error = check(status).unwrap_err();
            // A refused request never calls back: the callback's box is ours to free.
            drop(unsafe { Box::from_raw(user) });
            return Err(error);
        }
        Ok(PathRequest { world: self, ticket, finished, released: false })
    }

    /// Blocks until the request has finished or `timeout` has passed (`None`: as long as it takes);
    /// `Pending` on a timeout. `Some(Duration::ZERO)` only looks. With `path_worker_count` 0 this thread
    /// plans queued requests itself, oldest first, until this one has finished, checking the time between
    /// requests (a request is never split, so a wait can overrun its timeout by one request).
    /// `INVALID_ARGUMENT` from inside a path closure (it would wait for itself), `INVALID_HANDLE` for a
    /// released ticket.
    pub fn wait_path(&self, ticket: PathTicket, timeout: Option<Duration>) -> Result<PathOutcome> {
        let mut outcome = sys::NL_PATH_PENDING;
        check(unsafe { sys::nl_path_wait(self.raw(), ticket, wait_milliseconds(timeout), &mut outcome) })?;
        Ok(PathOutcome::from_raw(outcome))
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
            let mut points = vec![sys::nl_path_point::default(); count as usize];
            let status =
                unsafe { sys::nl_path_get_result(self.raw(), ticket, &mut info, points.as_mut_ptr(), count, &mut count) };
            if buffer_too_small(status) {
                continue;
            }
            check(status)?;
            points.truncate(count as usize);
            return Ok(Some(PathResult::from_c(info, points)));
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
        let mut stats = sys::nl_path_queue_stats_init();
        check(unsafe { sys::nl_path_get_queue_stats(self.raw(), &mut stats) })?;
        Ok(stats.into())
    }
}

/// `nl_path_wait`'s milliseconds: rounded up, so a short wait still waits; `NL_PATH_WAIT_FOREVER` for
/// `None` only (a very long timeout stops just short of it).
fn wait_milliseconds(timeout: Option<Duration>) -> u32 {
    match timeout {
        None => sys::NL_PATH_WAIT_FOREVER,
        Some(timeout) => {
            let rounded_up = (timeout.as_nanos() + 999_999) / 1_000_000;
            rounded_up.min(u128::from(sys::NL_PATH_WAIT_FOREVER - 1)) as u32
        }
    }
}

/// What a request's callback leaves for its [`PathRequest`]'s future: the outcome, and the waker of the
/// task that polled before it came.
#[derive(Default)]
pub(crate) struct FinishedSlot {
    outcome: Option<PathOutcome>,
    waker: Option<Waker>,
}

/// Called by the request's callback (any thread): records the outcome and wakes the polling task.
pub(crate) fn fill_finished_slot(slot: &Mutex<FinishedSlot>, outcome: PathOutcome) {
    let waker = {
        let mut slot = lock(slot);
        slot.outcome = Some(outcome);
        slot.waker.take()
    };
    // Woken outside the lock: the task may be polled on this very thread, inside wake.
    if let Some(waker) = waker {
        waker.wake();
    }
}

/// Nothing panics while holding the slot's lock, so a poisoned one still holds consistent data.
fn lock(slot: &Mutex<FinishedSlot>) -> MutexGuard<'_, FinishedSlot> {
    slot.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// A queued path request. It borrows its world, so it cannot outlive it; dropping it releases the
/// ticket (cancelling the request if unfinished). Wait for it with [`wait`](PathRequest::wait), or
/// `.await` it: as a `Future` it resolves to the request's result once a path worker, `process_paths`
/// or a wait on another thread has finished it (with `path_worker_count` 0 and nobody calling
/// `process_paths`, it never does). Any executor will do; the crate depends on none.
pub struct PathRequest<'w> {
    world: &'w World,
    ticket: PathTicket,
    finished: Arc<Mutex<FinishedSlot>>,
    /// Released already (or handed over by `into_ticket`): `Drop` leaves the ticket alone.
    released: bool,
}

impl<'w> PathRequest<'w> {
    /// The raw ticket, as `take_finished_paths` and the request's closure report it.
    pub fn ticket(&self) -> PathTicket {
        self.ticket
    }

    /// The outcome now (`Pending` while it runs).
    pub fn poll_outcome(&self) -> Result<PathOutcome> {
        self.world.poll_path(self.ticket)
    }

    /// `World::wait_path` for this request.
    pub fn wait(&self, timeout: Option<Duration>) -> Result<PathOutcome> {
        self.world.wait_path(self.ticket, timeout)
    }

    /// The result, or `None` while it is pending.
    pub fn result(&self) -> Result<Option<PathResult>> {
        self.world.path_result(self.ticket)
    }

    /// Asks the request to stop (a queued one finishes at once as `Cancelled`).
    pub fn cancel(&self) -> Result<()> {
        self.world.cancel_path(self.ticket)
    }

    /// Releases the ticket now, with the library's answer (dropping releases too, ignoring it).
    pub fn release(mut self) -> Result<()> {
        self.released = true;
        self.world.release_path(self.ticket)
    }

    /// Gives up ownership of the ticket: it stays valid until `World::release_path`.
    pub fn into_ticket(mut self) -> PathTicket {
        self.released = true;
        self.ticket
    }
}

impl std::fmt::Debug for PathRequest<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PathRequest").field("ticket", &self.ticket).field("released", &self.released).finish()
    }
}

impl Future for PathRequest<'_> {
    type Output = Result<PathResult>;

    fn poll(self: Pin<&mut Self>, context: &mut Context<'_>) -> Poll<Result<PathResult>> {
        {
            let mut slot = lock(&self.finished);
            if slot.outcome.is_none() {
                if !slot.waker.as_ref().map_or(false, |w| w.will_wake(context.waker())) {
                    slot.waker = Some(context.waker().clone());
                }
                return Poll::Pending;
            }
        }
        Poll::Ready(self.result().and_then(|result| {
            result.ok_or_else(|| Error::binding(sys::NL_STATUS_INTERNAL_ERROR, "a finished path request has no result".into()))
        }))
    }
}

impl Drop for PathRequest<'_> {
    fn drop(&mut self) {
        if !self.released {
            // A ticket released through World::release_path already is refused here; nothing to undo.
            let _ = self.world.release_path(self.ticket);
        }
    }
}
