//! A world whose batch work runs on the host's task system (`World::with_host_tasks`): an inline host
//! written here gives the same rays and links as NavLink's own threads, and is really called.
mod common;

use common::*;
use navlink::{default_agent_type, status, sys, HostTasks, Link, NavmeshBuild, Ray, World, WorldOptions};
use std::os::raw::c_void;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Runs every range at once, in pieces of `min_range`, and returns null (nothing to finish).
/// What the host counts: enqueues and finishes.
#[derive(Default)]
struct Calls {
    enqueues: AtomicUsize,
    finishes: AtomicUsize,
}

unsafe extern "C" fn enqueue_inline(
    user: *mut c_void,
    task: sys::nl_task_fn,
    task_context: *mut c_void,
    item_count: u32,
    min_range: u32,
) -> *mut c_void {
    let calls = &*(user as *const Calls);
    calls.enqueues.fetch_add(1, Ordering::SeqCst);
    let task = task.expect("a task");
    let mut begin = 0;
    while begin < item_count {
        let end = item_count.min(begin + min_range.max(1));
        task(task_context, begin, end, 0);
        begin = end;
    }
    std::ptr::null_mut()
}

/// Never called: every handle is null. (No panic here: it would unwind into C.)
unsafe extern "C" fn finish_counted(user: *mut c_void, _host_task: *mut c_void) {
    (*(user as *const Calls)).finishes.fetch_add(1, Ordering::SeqCst);
}

fn grid_rays() -> Vec<Ray> {
    let mut rays = Vec::new();
    for x in 0..60 {
        for z in 0..40 {
            rays.push(Ray { origin: [-13.0 + 0.45 * x as f32, 5.0, -6.0 + 0.3 * z as f32], direction: [0.0, -1.0, 0.0], max_distance: 100.0 });
        }
    }
    rays
}

/// A link without its ids (they carry the world's tag), as bit patterns.
fn shape(l: &Link) -> Vec<u32> {
    let mut v = vec![l.kind.to_raw()];
    v.extend(l.start.iter().chain(l.end.iter()).chain(l.apex.iter()).map(|f| f.to_bits()));
    v.extend([l.requirements.gap, l.requirements.rise, l.requirements.drop, l.requirements.length].iter().map(|f| f.to_bits()));
    v
}

fn run(world: &World) -> (Vec<(bool, u32)>, Vec<Vec<u32>>) {
    add_gap_level(world);
    let hits = world.cast_rays(&grid_rays()).unwrap().iter().map(|h| (h.hit, h.distance.to_bits())).collect();
    let navmesh = world.build_navmesh(&NavmeshBuild::new(default_agent_type())).unwrap();
    world.generate_links(navmesh, None, None, None).unwrap();
    (hits, world.links(navmesh).unwrap().iter().map(shape).collect())
}

#[test]
fn host_tasks_give_the_same_results_as_navlink_threads() {
    let reference = run(&World::with_options(WorldOptions { worker_count: 2, path_worker_count: 0, ..Default::default() }).unwrap());
    assert!(!reference.1.is_empty(), "the gap level has jumps");

    let calls = Calls::default();
    let tasks = HostTasks { enqueue: enqueue_inline, finish: finish_counted, user: &calls as *const Calls as *mut c_void };
    let options = WorldOptions { worker_count: 1, path_worker_count: 0, ..Default::default() };
    let world = unsafe { World::with_host_tasks(options, tasks) }.unwrap();
    assert_eq!(world.worker_count(), 1);
    assert_eq!(run(&world), reference);
    drop(world);
    assert!(calls.enqueues.load(Ordering::SeqCst) > 0, "the host's enqueue was never called");
    assert_eq!(calls.finishes.load(Ordering::SeqCst), 0, "a null handle was finished");
}

#[test]
fn host_tasks_need_a_worker_count() {
    let calls = Calls::default();
    let tasks = HostTasks { enqueue: enqueue_inline, finish: finish_counted, user: &calls as *const Calls as *mut c_void };
    let refused = unsafe { World::with_host_tasks(WorldOptions::default(), tasks) }; // NL_WORKERS_AUTO
    assert_fails(refused.map(drop), status::INVALID_ARGUMENT, "worker_count");
}
