//! Path requests on the gap level for two bodies: a walker (no jumps) cannot cross the gap, a jumper must
//! jump it. Planned now, queued with worker threads and closures, and queued with no workers
//! (process_paths, polling, cancelling).
mod common;

use common::*;
use navlink::{
    default_agent_type, status, FinishedPath, LinkLimit, NavmeshBuild, NavmeshId, PathBudget, PathOutcome, PathQuery,
    PathResult, PathShortfallReason, World, WorldOptions,
};
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Duration;

fn gap_level_with_links(world: &World) -> NavmeshId {
    add_gap_level(world);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    world.generate_links(navmesh, None, None, None).unwrap();
    navmesh
}

/// Across the gap in one jump: walk to the west rim, jump (a generated jump link, apex above), walk on.
fn check_jumper_across(world: &World, r: &PathResult) {
    assert_eq!(r.outcome(), PathOutcome::Complete);
    let p = &r.points;
    let jumps: Vec<usize> = (0..p.len()).filter(|&i| p[i].segment != navlink::LinkKind::Walk).collect();
    assert!(jumps.len() == 1 && p[jumps[0]].segment == navlink::LinkKind::Jump && r.summary.links_used == 1, "{:?}", p);
    let j = jumps[0];
    assert!(j + 1 < p.len() && p[j].position[0] < -1.0 && p[j + 1].position[0] > 1.0, "west rim to east rim");
    let link = world.link(p[j].link).unwrap();
    assert!(link.kind == navlink::LinkKind::Jump && link.generated);
    assert!(p[j].apex[1] > p[j].position[1].max(p[j + 1].position[1]), "apex above both ends");
    assert!(p.last().unwrap().segment == navlink::LinkKind::Walk && p[0].link == Default::default());
    assert!(horizontal_distance(p[0].position, WEST) < 0.01 && horizontal_distance(p.last().unwrap().position, EAST) < 0.01);
    assert!(r.summary.length >= 12.0 && r.summary.length < 13.0, "{} m", r.summary.length);
}

/// No link for a walker: the path leads to the reachable point nearest the goal, the west rim.
fn check_walker_stops_at_gap(r: &PathResult) {
    assert_eq!(r.outcome(), PathOutcome::Partial);
    assert!(r.summary.links_used == 0 && r.points.iter().all(|q| q.segment == navlink::LinkKind::Walk && q.link == Default::default()));
    assert!(r.points.len() >= 2 && r.points.iter().all(|q| q.position[0] < -1.0), "stays on the west platform");
    assert!(r.points.last().unwrap().position[0] > -2.1, "ends at the west rim");
}

#[test]
fn walker_and_jumper_planned_now() {
    let world = World::new().unwrap();
    let navmesh = gap_level_with_links(&world);
    check_jumper_across(&world, &world.find_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap());
    check_walker_stops_at_gap(&world.find_path(&PathQuery::new(navmesh, WEST, EAST, walker())).unwrap());

    let no_partial = PathQuery { accept_partial: false, ..PathQuery::new(navmesh, WEST, EAST, walker()) };
    let none = world.find_path(&no_partial).unwrap();
    assert!(none.outcome() == PathOutcome::NoPath && none.points.is_empty());

    // A jumper whose jump is shorter than the gap is filtered out of every link.
    let short = navlink::AgentCapabilities { max_jump_distance: 1.8, ..jumper() };
    let too_short = world.find_path(&PathQuery::new(navmesh, WEST, EAST, short)).unwrap();
    assert!(too_short.outcome() == PathOutcome::Partial && too_short.summary.links_used == 0);

    let stroll = world.find_path(&PathQuery::new(navmesh, [-9.0, 0.0, -3.0], [-3.0, 0.0, 3.0], walker())).unwrap();
    assert!(stroll.outcome() == PathOutcome::Complete && stroll.summary.links_used == 0 && stroll.points.len() >= 2);
    assert!(stroll.points.iter().all(|q| q.segment == navlink::LinkKind::Walk));
    assert!(stroll.summary.length >= 8.48 && stroll.summary.length < 8.6, "{} m", stroll.summary.length);

    let off_start = world.find_path(&PathQuery::new(navmesh, [0.0, -10.0, 30.0], EAST, jumper())).unwrap();
    assert_eq!(off_start.outcome(), PathOutcome::StartOffNavmesh);
    let off_goal = world.find_path(&PathQuery::new(navmesh, WEST, [0.0, -10.0, 30.0], jumper())).unwrap();
    assert_eq!(off_goal.outcome(), PathOutcome::GoalOffNavmesh);
}

#[test]
fn why_a_path_falls_short() {
    let world = World::new().unwrap();
    // A platform 4.2 m above a floor, no stairs, no links: its top is an island of the navmesh.
    add_box(&world, [-10.0, -1.0, -10.0], [20.0, 0.0, 10.0]);
    add_box(&world, [0.0, 0.0, -3.0], [6.0, 4.2, 3.0]);
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    let down = PathQuery { accept_partial: true, ..PathQuery::new(navmesh, [3.0, 4.2, 0.0], [15.0, 0.0, 0.0], walker()) };
    let stuck = world.explain_path(&down).unwrap();
    assert_eq!(stuck.reason, PathShortfallReason::NoLinks, "{:?}", stuck);
    assert!(stuck.limit == LinkLimit::None && stuck.link == Default::default(), "{:?}", stuck);
    assert!(stuck.text.contains("the navmesh has no links"), "{:?}", stuck.text);
    let stroll = world.explain_path(&PathQuery::new(navmesh, [15.0, 0.0, 0.0], [18.0, 0.0, 0.0], walker())).unwrap();
    assert_eq!(stroll.reason, PathShortfallReason::None, "{:?}", stroll);
    assert_eq!(stroll.text, "");
}

#[test]
fn queued_with_path_workers_and_closures() {
    let world = World::new().unwrap();
    let navmesh = gap_level_with_links(&world);
    let (sender, finished) = mpsc::channel();
    let (walker_done, jumper_done) = (sender.clone(), sender);
    let walker_ticket = world
        .request_path_with(&PathQuery::new(navmesh, WEST, EAST, walker()), move |t, o| walker_done.send(("walker", t, o)).unwrap())
        .unwrap()
        .into_ticket();
    let jumper_ticket = world
        .request_path_with(&PathQuery::new(navmesh, WEST, EAST, jumper()), move |t, o| jumper_done.send(("jumper", t, o)).unwrap())
        .unwrap()
        .into_ticket();
    assert_ne!(walker_ticket, jumper_ticket);
    let mut calls = Vec::new();
    for _ in 0..2 {
        calls.push(finished.recv_timeout(Duration::from_secs(20)).expect("a callback"));
    }
    calls.sort_by_key(|c| c.0);
    assert_eq!(calls, vec![("jumper", jumper_ticket, PathOutcome::Complete), ("walker", walker_ticket, PathOutcome::Partial)]);
    assert!(finished.recv_timeout(Duration::from_millis(50)).is_err(), "each closure ran once (and was dropped)");
    assert_eq!(world.poll_path(walker_ticket).unwrap(), PathOutcome::Partial);

    check_walker_stops_at_gap(&world.path_result(walker_ticket).unwrap().expect("finished"));
    let jumped = world.path_result(jumper_ticket).unwrap().expect("finished");
    check_jumper_across(&world, &jumped);
    let direct = world.find_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap();
    assert_eq!(direct.points, jumped.points, "queued and direct planning agree");

    world.release_path(walker_ticket).unwrap();
    world.release_path(jumper_ticket).unwrap();
    assert_fails(world.poll_path(walker_ticket), status::INVALID_HANDLE, "nl_path_poll");
    assert_fails(world.release_path(jumper_ticket), status::INVALID_HANDLE, "nl_path_release");
    assert_eq!(world.path_queue_stats().unwrap().unreleased, 0);
}

#[test]
fn queued_and_run_by_the_host() {
    let world = World::with_options(WorldOptions { path_worker_count: 0, ..Default::default() }).unwrap();
    let navmesh = gap_level_with_links(&world);
    let jumper_ticket = world.request_path(&PathQuery::new(navmesh, WEST, EAST, jumper())).unwrap().into_ticket();
    let seen = Arc::new(Mutex::new(None));
    let record = Arc::clone(&seen);
    let doomed = world
        .request_path_with(&PathQuery::new(navmesh, WEST, EAST, walker()), move |_, o| {
            *record.lock().unwrap() = Some((o, std::thread::current().id()))
        })
        .unwrap()
        .into_ticket();
    let stats = world.path_queue_stats().unwrap();
    assert!(stats.workers == 0 && stats.queued == 2 && stats.submitted == 2, "{:?}", stats);
    assert_eq!(world.poll_path(jumper_ticket).unwrap(), PathOutcome::Pending);
    assert_eq!(world.path_result(jumper_ticket).unwrap(), None, "no result while pending (IN_PROGRESS)");

    world.cancel_path(doomed).unwrap();
    assert_eq!(*seen.lock().unwrap(), Some((PathOutcome::Cancelled, std::thread::current().id())),
               "a queued request cancels at once, its closure on the cancelling thread");
    assert_fails(world.process_paths(PathBudget::milliseconds(f64::NAN)), status::INVALID_ARGUMENT, "nl_path_process");
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 1);
    check_jumper_across(&world, &world.path_result(jumper_ticket).unwrap().expect("planned by the host"));
    let stats = world.path_queue_stats().unwrap();
    assert!(stats.finished == 2 && stats.unreleased == 2 && stats.queued == 0, "{:?}", stats);

    // A request still queued when the world goes: its closure reports it cancelled, once.
    let (sender, last) = mpsc::channel();
    world.request_path_with(&PathQuery::new(navmesh, WEST, EAST, jumper()), move |_, o| sender.send(o).unwrap()).unwrap().into_ticket();
    drop(world);
    assert_eq!(last.try_recv(), Ok(PathOutcome::Cancelled));
    assert!(last.try_recv().is_err());
}

#[test]
fn budgets_and_finished_requests_taken_by_the_host() {
    let world = World::with_options(WorldOptions { path_worker_count: 0, ..Default::default() }).unwrap();
    let navmesh = gap_level_with_links(&world);
    let jumper_query = PathQuery::new(navmesh, WEST, EAST, jumper());
    let walker_query = PathQuery::new(navmesh, WEST, EAST, walker());
    assert_eq!(world.take_finished_paths().unwrap(), vec![], "nothing finished yet");
    let default = PathBudget::default();
    assert!(default == PathBudget::unlimited() && default.max_requests == 0 && default.max_milliseconds == 0.0 && default.max_search_nodes == 0);

    // Budgets: a request is never split, so each limit lets one request through.
    let a = world.request_path(&jumper_query).unwrap().into_ticket();
    let b = world.request_path(&walker_query).unwrap().into_ticket();
    assert_eq!(world.process_paths(PathBudget::requests(1)).unwrap(), 1);
    assert!(world.poll_path(a).unwrap() == PathOutcome::Complete && world.poll_path(b).unwrap() == PathOutcome::Pending);
    let c = world.request_path(&jumper_query).unwrap().into_ticket();
    let d = world.request_path(&walker_query).unwrap().into_ticket();
    let e = world.request_path(&jumper_query).unwrap().into_ticket();
    assert_eq!(world.process_paths(PathBudget::search_nodes(1)).unwrap(), 1, "the request that crosses the limit");
    assert!(world.poll_path(b).unwrap() == PathOutcome::Partial && world.poll_path(c).unwrap() == PathOutcome::Pending);
    assert_eq!(world.process_paths(PathBudget { max_search_nodes: 1, ..Default::default() }).unwrap(), 1);
    assert_eq!(world.poll_path(d).unwrap(), PathOutcome::Pending);
    assert_eq!(world.process_paths(PathBudget::milliseconds(1e-6)).unwrap(), 1, "a budget of 1 ns: one request");
    assert_eq!(world.poll_path(e).unwrap(), PathOutcome::Pending);
    assert_eq!(world.process_paths(PathBudget::unlimited()).unwrap(), 1, "no limits: the rest");

    // Each finished request once, oldest first, with its outcome.
    let finished = |ticket, outcome| FinishedPath { ticket, outcome };
    assert_eq!(world.take_finished_paths().unwrap(), vec![
        finished(a, PathOutcome::Complete),
        finished(b, PathOutcome::Partial),
        finished(c, PathOutcome::Complete),
        finished(d, PathOutcome::Partial),
        finished(e, PathOutcome::Complete),
    ]);
    assert_eq!(world.take_finished_paths().unwrap(), vec![], "each is taken once");

    // Released tickets are not reported, finished or cancelled; cancelled ones are.
    let (sender, calls) = mpsc::channel();
    let released = world.request_path_with(&jumper_query, move |_, o| sender.send(o).unwrap()).unwrap().into_ticket();
    let cancelled = world.request_path(&walker_query).unwrap().into_ticket();
    let kept = world.request_path(&jumper_query).unwrap().into_ticket();
    let released_later = world.request_path(&walker_query).unwrap().into_ticket();
    world.release_path(released).unwrap();
    world.cancel_path(cancelled).unwrap();
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 2);
    assert_eq!(calls.try_iter().collect::<Vec<_>>(), vec![PathOutcome::Cancelled], "the released request called back once");
    world.release_path(released_later).unwrap();
    assert_eq!(world.take_finished_paths().unwrap(), vec![finished(cancelled, PathOutcome::Cancelled), finished(kept, PathOutcome::Complete)]);

    // More than the binding takes in one call (16) come back in one Vec, in order.
    let many: Vec<_> = (0..40).map(|i| world.request_path(if i % 2 == 0 { &jumper_query } else { &walker_query }).unwrap().into_ticket()).collect();
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 40);
    let expected: Vec<_> = many
        .iter()
        .enumerate()
        .map(|(i, &t)| finished(t, if i % 2 == 0 { PathOutcome::Complete } else { PathOutcome::Partial }))
        .collect();
    assert_eq!(world.take_finished_paths().unwrap(), expected);

    // The raw call: the library reads the element size from out_finished[0].size; a refusal loses nothing.
    let raw = world.request_path(&jumper_query).unwrap().into_ticket();
    world.process_paths(PathBudget::default()).unwrap();
    unsafe {
        let mut buffer: [navlink::sys::nl_path_finished; 2] = std::mem::zeroed();
        let (mut count, mut remaining) = (99, 99);
        let s = navlink::sys::nl_path_take_finished(world.as_ptr(), buffer.as_mut_ptr(), 2, &mut count, &mut remaining);
        assert!(navlink::sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0, "an element size left at 0");
        buffer[0] = navlink::sys::nl_path_finished_init();
        let s = navlink::sys::nl_path_take_finished(world.as_ptr(), buffer.as_mut_ptr(), 2, &mut count, &mut remaining);
        assert!(s == status::SUCCESS && count == 1 && remaining == 0 && buffer[0].ticket == raw);
        assert_eq!(buffer[0].outcome, navlink::sys::NL_PATH_COMPLETE);
        // A budget whose size is too small is refused by name.
        let mut small = navlink::sys::nl_default_path_budget();
        small.size = 8;
        let s = navlink::sys::nl_path_process(world.as_ptr(), &small, std::ptr::null_mut());
        assert!(navlink::sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0);
        let message = std::ffi::CStr::from_ptr(navlink::sys::nl_get_last_error_message()).to_str().unwrap();
        assert!(message.contains("budget"), "{}", message);
    }
}

#[test]
fn a_panicking_path_closure_is_contained() {
    let world = World::with_options(WorldOptions { path_worker_count: 0, ..Default::default() }).unwrap();
    let navmesh = gap_level_with_links(&world);
    let ticket = world.request_path_with(&PathQuery::new(navmesh, WEST, EAST, jumper()), |_, _| panic!("closure panics")).unwrap().into_ticket();
    assert_eq!(world.process_paths(PathBudget::default()).unwrap(), 1);
    assert_eq!(world.poll_path(ticket).unwrap(), PathOutcome::Complete, "the request finished normally");
}

#[test]
fn invalid_requests() {
    let world = World::with_options(WorldOptions { path_worker_count: 0, ..Default::default() }).unwrap();
    let navmesh = gap_level_with_links(&world);
    let calls = Arc::new(Mutex::new(0));
    let counter = Arc::clone(&calls);
    let null_navmesh = PathQuery::new(Default::default(), WEST, EAST, walker());
    assert_fails(world.request_path_with(&null_navmesh, move |_, _| *counter.lock().unwrap() += 1), status::INVALID_HANDLE, "nl_path_request");
    let negative = PathQuery::new(navmesh, WEST, EAST, navlink::AgentCapabilities { max_jump_distance: -1.0, ..jumper() });
    assert_fails(world.request_path(&negative), status::INVALID_ARGUMENT, "max_jump_distance");
    assert_fails(world.find_path(&PathQuery::new(navmesh, [f32::NAN, 0.0, 0.0], EAST, walker())), status::INVALID_ARGUMENT, "start");
    world.process_paths(PathBudget::default()).unwrap();
    assert!(*calls.lock().unwrap() == 0 && world.path_queue_stats().unwrap().submitted == 0, "refused requests never call back");
    assert_eq!(Arc::strong_count(&calls), 1, "and their closures were freed");
    assert_fails(world.cancel_path(Default::default()), status::INVALID_HANDLE, "nl_path_cancel");
    unsafe {
        let s = navlink::sys::nl_path_get_queue_stats(world.as_ptr(), std::ptr::null_mut());
        assert!(navlink::sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0);
    }
}
