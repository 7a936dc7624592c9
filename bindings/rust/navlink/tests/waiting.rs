//! Paths you can wait for (issue 18): `PathRequest::wait` with and without path workers, a timeout that
//! only looks, requests awaited as futures by a small executor written here (no runtime dependency),
//! tickets released on drop; and the safe API's kinds: `ErrorKind`, the enums, `Send` settings.
mod common;

use common::*;
use navlink::{
    default_agent_type, AgentEventKind, AgentReason, AgentState, ErrorKind, LinkKind, NavmeshBuild, NavmeshId, PathBudget, PathOutcome,
    PathQuery, PathRequest, PathResult, TrajectoryKind, World, WorldOptions,
};
use std::future::Future;
use std::pin::Pin;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::sync::Arc;
use std::task::{Context, Poll, Wake, Waker};
use std::thread::{self, Thread};
use std::time::Duration;

fn gap_level_with_links(world: &World) -> NavmeshId {
    add_gap_level(world);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    world.generate_links(navmesh, None, None, None).unwrap();
    navmesh
}

fn host_run_world() -> World {
    World::with_options(WorldOptions { path_worker_count: 0, ..Default::default() }).unwrap()
}

/// Wakes by unparking the thread that polls, and counts the wakes.
struct ThreadWaker {
    thread: Thread,
    wakes: AtomicUsize,
}

impl Wake for ThreadWaker {
    fn wake(self: Arc<Self>) {
        self.wake_by_ref();
    }

    fn wake_by_ref(self: &Arc<Self>) {
        self.wakes.fetch_add(1, Ordering::SeqCst);
        self.thread.unpark();
    }
}

/// Polls every future until all are ready, parking in between: a waker that is never called leaves
/// this thread parked, and the test's timeout fails it. Returns the outputs in order and the wakes seen.
fn block_on_all<F: Future + Unpin>(mut futures: Vec<F>) -> (Vec<F::Output>, usize) {
    let waker_state = Arc::new(ThreadWaker { thread: thread::current(), wakes: AtomicUsize::new(0) });
    let waker = Waker::from(waker_state.clone());
    let mut context = Context::from_waker(&waker);
    let mut outputs: Vec<Option<F::Output>> = futures.iter().map(|_| None).collect();
    while outputs.iter().any(Option::is_none) {
        for (future, output) in futures.iter_mut().zip(outputs.iter_mut()) {
            if output.is_none() {
                if let Poll::Ready(value) = Pin::new(future).poll(&mut context) {
                    *output = Some(value);
                }
            }
        }
        if outputs.iter().any(Option::is_none) {
            thread::park_timeout(Duration::from_secs(20));
        }
    }
    (outputs.into_iter().map(Option::unwrap).collect(), waker_state.wakes.load(Ordering::SeqCst))
}

fn assert_crosses_with_one_jump(result: &PathResult) {
    assert_eq!(result.outcome(), PathOutcome::Complete);
    assert_eq!(result.points.iter().filter(|p| p.segment == LinkKind::Jump).count(), 1, "{:?}", result.points);
    assert_eq!(result.summary.links_used, 1);
}

#[test]
fn wait_with_path_workers() {
    let world = World::new().unwrap();
    let navmesh = gap_level_with_links(&world);
    assert!(world.path_queue_stats().unwrap().workers > 0);
    let request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    assert_eq!(request.wait(None).unwrap(), PathOutcome::Complete);
    assert_eq!(request.poll_outcome().unwrap(), PathOutcome::Complete, "a wait returns once the request has finished");
    assert_crosses_with_one_jump(&request.result().unwrap().expect("finished"));
    let walker_request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, walker())).unwrap();
    assert_eq!(walker_request.wait(Some(Duration::from_secs(20))).unwrap(), PathOutcome::Partial);
}

#[test]
fn wait_without_path_workers_plans_on_the_waiting_thread() {
    let world = host_run_world();
    let navmesh = gap_level_with_links(&world);
    let (sender, planned_on) = mpsc::channel();
    let older = world.request_path(&PathQuery::new(navmesh, WEST, EAST, walker())).unwrap();
    let request = world
        .request_path_with(&PathQuery::new(navmesh, WEST, EAST, jumper()), move |_, outcome| {
            sender.send((outcome, thread::current().id())).unwrap()
        })
        .unwrap();
    assert_eq!(world.path_queue_stats().unwrap().queued, 2);
    assert_eq!(request.wait(None).unwrap(), PathOutcome::Complete);
    assert_eq!(planned_on.try_recv(), Ok((PathOutcome::Complete, thread::current().id())), "planned by the waiting thread");
    // Oldest first, as process_paths: the older request was planned on the way.
    assert_eq!(older.poll_outcome().unwrap(), PathOutcome::Partial);
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 0, "nothing left to plan");
    assert_crosses_with_one_jump(&request.result().unwrap().expect("finished"));
}

#[test]
fn a_zero_timeout_only_looks() {
    let world = host_run_world();
    let navmesh = gap_level_with_links(&world);
    let request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    assert_eq!(request.wait(Some(Duration::ZERO)).unwrap(), PathOutcome::Pending);
    let stats = world.path_queue_stats().unwrap();
    assert!(stats.queued == 1 && stats.finished == 0, "a zero timeout plans nothing: {:?}", stats);
    assert_eq!(request.result().unwrap(), None);
    world.process_paths(PathBudget::default()).unwrap();
    assert_eq!(request.wait(Some(Duration::ZERO)).unwrap(), PathOutcome::Complete);
}

#[test]
fn several_futures_polled_to_completion() {
    let world = World::new().unwrap();
    let navmesh = gap_level_with_links(&world);
    let requests: Vec<PathRequest<'_>> = (0..6)
        .map(|i| {
            let body = if i % 2 == 0 { jumper() } else { walker() };
            world.request_path(&PathQuery::new(navmesh, WEST, EAST, body)).unwrap()
        })
        .collect();
    let (results, _wakes) = block_on_all(requests);
    for (i, result) in results.into_iter().enumerate() {
        let result = result.unwrap();
        if i % 2 == 0 {
            assert_crosses_with_one_jump(&result);
        } else {
            assert_eq!(result.outcome(), PathOutcome::Partial);
        }
    }
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 0, "awaited requests are dropped, so released");
}

#[test]
fn a_future_pending_at_first_poll_is_woken_by_the_callback() {
    let world = host_run_world();
    let navmesh = gap_level_with_links(&world);
    let request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    // Nobody plans until the thread below does: the first poll must be Pending, and only the
    // callback's wake can end the park.
    thread::scope(|scope| {
        let planner = scope.spawn(|| {
            thread::sleep(Duration::from_millis(50));
            world.process_paths(PathBudget::default()).unwrap()
        });
        let (results, wakes) = block_on_all(vec![request]);
        assert_crosses_with_one_jump(results[0].as_ref().unwrap());
        assert!(wakes >= 1, "woken by the request's callback");
        assert_eq!(planner.join().unwrap(), 1);
    });
}

#[test]
fn a_cancelled_request_resolves_as_cancelled() {
    let world = host_run_world();
    let navmesh = gap_level_with_links(&world);
    let request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    request.cancel().unwrap();
    let (results, _) = block_on_all(vec![request]);
    assert_eq!(results[0].as_ref().unwrap().outcome(), PathOutcome::Cancelled);
}

#[test]
fn dropping_a_request_releases_its_ticket() {
    let world = host_run_world();
    let navmesh = gap_level_with_links(&world);
    let query = PathQuery::new(navmesh, WEST, EAST, jumper());
    let (first, second) = (world.request_path(&query).unwrap(), world.request_path(&query).unwrap());
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 2);
    let first_ticket = first.ticket();
    drop(first);
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 1);
    assert_eq!(world.poll_path(first_ticket).unwrap_err().kind(), ErrorKind::InvalidHandle, "the dropped ticket is gone");
    // Dropping an unfinished request cancels it: only the second is left to plan.
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 1);
    second.release().unwrap();
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 0);

    // into_ticket hands the ticket over: it stays until released by hand.
    let kept = world.request_path(&query).unwrap().into_ticket();
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 1);
    world.release_path(kept).unwrap();
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 0);
}

#[test]
fn error_kinds() {
    let world = Arc::new(host_run_world());
    let navmesh = gap_level_with_links(&world);
    let request = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    let ticket = request.ticket();
    request.release().unwrap();
    assert_eq!(world.wait_path(ticket, None).unwrap_err().kind(), ErrorKind::InvalidHandle);

    let nan_start = PathQuery::new(navmesh, [f32::NAN, 0.0, 0.0], EAST, walker());
    assert_eq!(world.request_path(&nan_start).unwrap_err().kind(), ErrorKind::InvalidArgument);
    assert_eq!(world.add_obj_file("/no/such/level.obj", &Default::default()).unwrap_err().kind(), ErrorKind::NotFound);
    assert_eq!(world.load_navmesh(b"not a navmesh file", &Default::default()).unwrap_err().kind(), ErrorKind::VersionMismatch);

    // Waiting from inside a path closure could wait for itself: refused.
    let (sender, waited) = mpsc::channel();
    let inside = Arc::clone(&world);
    let request = world
        .request_path_with(&PathQuery::new(navmesh, WEST, EAST, walker()), move |ticket, _| {
            sender.send(inside.wait_path(ticket, Some(Duration::ZERO)).map_err(|e| e.kind())).unwrap()
        })
        .unwrap();
    world.process_paths(PathBudget::default()).unwrap();
    assert_eq!(waited.try_recv(), Ok(Err(ErrorKind::InvalidArgument)));
    drop(request);
}

#[test]
fn enums_keep_values_they_do_not_know() {
    for raw in 0..=8 {
        assert_eq!(PathOutcome::from_raw(raw).to_raw(), raw);
        assert_eq!(AgentState::from_raw(raw).to_raw(), raw);
        assert_eq!(AgentReason::from_raw(raw).to_raw(), raw);
        assert_eq!(AgentEventKind::from_raw(raw).to_raw(), raw);
        assert_eq!(TrajectoryKind::from_raw(raw).to_raw(), raw);
        assert_eq!(navlink::PathShortfallReason::from_raw(raw).to_raw(), raw);
        assert_eq!(navlink::LinkLimit::from_raw(raw).to_raw(), raw);
    }
    assert_eq!(PathOutcome::from_raw(navlink::sys::NL_PATH_NO_PATH), PathOutcome::NoPath);
    assert_eq!(PathOutcome::from_raw(99), PathOutcome::Other(99));
    assert_eq!(LinkKind::from_raw(navlink::sys::NL_LINK_JUMP), LinkKind::Jump);
    let plugin_kind = LinkKind::from_raw(LinkKind::FIRST_PLUGIN_KIND + 2);
    assert!(plugin_kind.is_plugin() && !LinkKind::Drop.is_plugin() && plugin_kind.to_raw() == navlink::sys::NL_LINK_FIRST_PLUGIN_KIND + 2);
}

fn assert_send<T: Send>() {}

/// Compiles only if every settings, def and option type of the safe API is `Send` (a raw pointer inside
/// one makes it `!Send`): the test fails by not building.
#[test]
fn settings_and_defs_are_send() {
    assert_send::<navlink::WorldOptions>();
    assert_send::<navlink::HostTasks>();
    assert_send::<navlink::MeshOptions>();
    assert_send::<navlink::NavmeshBuild<'static>>();
    assert_send::<navlink::NavmeshInput<'static>>();
    assert_send::<navlink::RecastSettings>();
    assert_send::<navlink::RecastPartition>();
    assert_send::<navlink::AgentType>();
    assert_send::<navlink::LinkSettings>();
    assert_send::<navlink::LinkDef>();
    assert_send::<navlink::LinkRequirements>();
    assert_send::<navlink::LinkKind>();
    assert_send::<navlink::LinksLoadOptions>();
    assert_send::<navlink::NavmeshLoadOptions>();
    assert_send::<navlink::PathQuery>();
    assert_send::<navlink::QueryFilter>();
    assert_send::<navlink::RandomPointsOptions>();
    assert_send::<navlink::PathBudget>();
    assert_send::<navlink::AgentDef>();
    assert_send::<navlink::AgentCapabilities>();
    assert_send::<PathRequest<'static>>();
    assert_send::<navlink::Error>();
    // What the safe API hands back, to move to another thread with its results.
    assert_send::<navlink::Link>();
    assert_send::<navlink::MeshInfo>();
    assert_send::<navlink::RayHit>();
    assert_send::<navlink::NavmeshInfo>();
    assert_send::<navlink::NavPolygon>();
    assert_send::<navlink::NavPoint>();
    assert_send::<navlink::NavmeshRaycastHit>();
    assert_send::<navlink::LinkGenerationReport>();
    assert_send::<navlink::NavmeshFileInfo>();
    assert_send::<navlink::PathShortfall>();
}
