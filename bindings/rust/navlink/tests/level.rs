//! The world, level geometry, ray and segment queries, OBJ loading, errors, threads.
mod common;

use common::*;
use navlink::{status, status_string, sys, MeshFlags, MeshOptions, Ray, Segment, World, WorldOptions};

const FLOOR: [f32; 12] = [-5.0, 0.0, -5.0, 5.0, 0.0, -5.0, 5.0, 0.0, 5.0, -5.0, 0.0, 5.0];
const QUAD: [u32; 6] = [0, 2, 1, 0, 3, 2];

fn down(x: f32, z: f32) -> Ray {
    Ray { origin: [x, 50.0, z], direction: [0.0, -1.0, 0.0], max_distance: 100.0 }
}

#[test]
fn version_and_statuses() {
    let v = World::library_version();
    assert_eq!((v.major, v.minor), (sys::NL_VERSION_MAJOR, sys::NL_VERSION_MINOR));
    assert!(status_string(status::FAILURE | status::INVALID_HANDLE).contains("invalid handle"));
}

#[test]
fn world_options() {
    let one = World::with_options(WorldOptions { worker_count: 1, path_worker_count: 0, ..Default::default() }).unwrap();
    assert_eq!(one.worker_count(), 1);
    let refused = World::with_options(WorldOptions { worker_count: -5, ..Default::default() });
    assert_fails(refused.map(drop), status::INVALID_ARGUMENT, "worker_count");
}

#[test]
fn meshes_and_rays() {
    let world = World::new().unwrap();
    let floor = world.add_mesh(&FLOOR, &QUAD, &MeshOptions { user_data: 42, ..Default::default() }).unwrap();
    assert!(world.is_mesh_valid(floor));
    let info = world.mesh_info(floor).unwrap();
    assert_eq!((info.triangle_count, info.vertex_count, info.user_data), (2, 4, 42));
    assert_eq!(info.bounds_max[0], 5.0);

    let hits = world
        .cast_rays(&[
            Ray { origin: [-2.0, 2.0, 1.0], direction: [0.0, -1.0, 0.0], max_distance: 100.0 },
            Ray { origin: [8.0, 2.0, 0.0], direction: [0.0, -1.0, 0.0], max_distance: 100.0 },
        ])
        .unwrap();
    assert!(hits[0].hit && hits[0].mesh == floor);
    assert!((hits[0].distance - 2.0).abs() < 1e-5 && (hits[0].normal[1] - 1.0).abs() < 1e-5);
    assert!(!hits[1].hit && hits[1].distance == 0.0);
    assert_eq!(hits[1], navlink::RayHit::default(), "a miss is all zero");

    // A movable 2 x 2 m tile 1 m up at x = 4, then lifted to 3.5 m.
    let tile = [-1.0, 0.0, -1.0, 1.0, 0.0, -1.0, 1.0, 0.0, 1.0, -1.0, 0.0, 1.0];
    let mut at = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 4.0, 1.0, 0.0, 1.0];
    let lift = world.add_mesh(&tile, &QUAD, &MeshOptions { flags: MeshFlags::MOVABLE, transform: Some(at), ..Default::default() }).unwrap();
    assert!((world.cast_rays(&[down(4.0, 0.0)]).unwrap()[0].point[1] - 1.0).abs() < 1e-4);
    at[13] = 3.5;
    world.set_mesh_transform(lift, &at).unwrap();
    assert!((world.cast_rays(&[down(4.0, 0.0)]).unwrap()[0].point[1] - 3.5).abs() < 1e-4);
    assert_eq!(world.meshes().unwrap().len(), 2);

    let blocked = world
        .segments_blocked(&[
            Segment { from: [4.0, 5.0, 0.0], to: [4.0, 2.0, 0.0] },
            Segment { from: [-4.0, 5.0, 0.0], to: [-4.0, 2.0, 0.0] },
        ])
        .unwrap();
    assert_eq!(blocked, vec![true, false]);

    // Stale ids are refused, never obeyed.
    world.remove_mesh(lift).unwrap();
    assert!(!world.is_mesh_valid(lift));
    assert_fails(world.remove_mesh(lift), status::INVALID_HANDLE, "nl_mesh_remove");
    assert_fails(world.set_mesh_transform(lift, &at), status::INVALID_HANDLE, "nl_mesh_set_transform");
    assert_fails(world.mesh_info(lift), status::INVALID_HANDLE, "nl_mesh_get_info");
}

#[test]
fn invalid_input_and_the_log_callback() {
    let (world, logged) = world_keeping_log();
    assert_fails(world.add_mesh(&FLOOR, &[0, 1, 7], &MeshOptions::default()), status::INVALID_ARGUMENT, "indices");
    {
        let logged = logged.lock().unwrap();
        assert!(logged.len() == 1 && logged[0].contains("indices"), "the log callback got the failure: {:?}", logged);
    }
    let zero = Ray { origin: [0.0, 1.0, 0.0], direction: [0.0; 3], max_distance: 1.0 };
    assert_fails(world.cast_rays(&[zero]), status::INVALID_ARGUMENT, "rays");
    assert_fails(world.add_obj_memory(b"v 0 0 0\nf 1 2 9\n", &MeshOptions::default()), status::PARSE_ERROR, ":2:");
    assert_fails(world.add_obj_file("/no/such/level.obj", &MeshOptions::default()), status::NOT_FOUND, "nl_mesh_add_obj_file");
    assert_fails(world.add_obj_file("nul\0byte.obj", &MeshOptions::default()), status::INVALID_ARGUMENT, "NUL");
    let floor = world.add_mesh(&FLOOR, &QUAD, &MeshOptions::default()).unwrap();
    assert_fails(world.set_mesh_transform(floor, &[0.0; 16]), status::INVALID_ARGUMENT, "transform");

    // Null pointers through navlink-sys: INVALID_ARGUMENT, the argument named.
    unsafe {
        let s = sys::nl_world_create(std::ptr::null(), std::ptr::null_mut());
        assert!(sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0);
        let s = sys::nl_world_get_meshes(world.as_ptr(), std::ptr::null_mut(), 0, std::ptr::null_mut());
        assert!(sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0);
        let message = std::ffi::CStr::from_ptr(sys::nl_get_last_error_message()).to_str().unwrap();
        assert!(message.contains("out_count"), "{}", message);
        assert_eq!(sys::nl_world_get_worker_count(std::ptr::null()), 0);
        assert!(sys::nl_failed(sys::nl_get_last_status()));
        let mut count = 0;
        assert_eq!(sys::nl_world_get_meshes(world.as_ptr(), std::ptr::null_mut(), 0, &mut count), status::SUCCESS);
        assert_eq!(*sys::nl_get_last_error_message(), 0, "a success clears the message");

        // Output arrays of growable elements: the library reads the element size from the first element,
        // which Default (nl_ray_hit_init) and the safe API set, and a raw caller must.
        let ray = down(0.0, 0.0);
        let mut hits: [sys::nl_ray_hit; 1] = std::mem::zeroed();
        let s = sys::nl_world_cast_rays(world.as_ptr(), &ray, 1, hits.as_mut_ptr());
        assert!(sys::nl_failed(s) && s & status::INVALID_ARGUMENT != 0);
        let message = std::ffi::CStr::from_ptr(sys::nl_get_last_error_message()).to_str().unwrap();
        assert!(message.contains("out_hits"), "{}", message);
        hits[0] = sys::nl_ray_hit_init();
        assert_eq!(sys::nl_world_cast_rays(world.as_ptr(), &ray, 1, hits.as_mut_ptr()), status::SUCCESS);
        assert!(hits[0].hit == 1 && hits[0].size as usize == std::mem::size_of::<sys::nl_ray_hit>());
    }
    // The safe API's RayHit has no size to set: the binding lays out the C array itself and copies the
    // hits into the caller's slice, leaving the elements past the rays as they were.
    let stale = navlink::RayHit { hit: true, distance: 7.0, ..Default::default() };
    let mut mine = [stale; 3];
    world.cast_rays_into(&[down(0.0, 0.0), down(9.0, 9.0)], &mut mine).unwrap();
    assert!(mine[0].hit && (mine[0].distance - 50.0).abs() < 1e-3 && mine[0].triangle < 2, "{:?}", mine[0]);
    assert_eq!(mine[1], navlink::RayHit::default(), "a miss overwrites the stale hit");
    assert_eq!(mine[2], stale, "past the rays: untouched");
    assert_fails(world.cast_rays_into(&[down(0.0, 0.0)], &mut []), status::INVALID_ARGUMENT, "fewer hits than rays");
}

#[test]
fn a_panicking_log_callback_is_contained() {
    let world = World::with_options(WorldOptions {
        log: Some(Box::new(|_, _, _: &str| panic!("the log callback panics"))),
        ..Default::default()
    })
    .unwrap();
    assert_fails(world.remove_mesh(Default::default()), status::INVALID_HANDLE, "nl_mesh_remove");
    assert!(world.add_mesh(&FLOOR, &QUAD, &MeshOptions::default()).is_ok(), "the world still works");
}

#[test]
fn queries_from_several_threads() {
    // World is Sync: navlink.h lets every world function run on several threads at once.
    let world = World::new().unwrap();
    world.add_mesh(&FLOOR, &QUAD, &MeshOptions::default()).unwrap();
    std::thread::scope(|s| {
        for t in 0..4 {
            let world = &world;
            s.spawn(move || {
                for i in 0..50 {
                    let x = -4.0 + (t * 50 + i) as f32 * 0.04;
                    let hit = world.cast_rays(&[down(x, 0.0)]).unwrap()[0];
                    assert!(hit.hit && (hit.distance - 50.0).abs() < 1e-3);
                }
            });
        }
    });
}

#[test]
fn dungeon_obj() {
    let path = levels_dir().join("dungeon.obj");
    let world = World::new().unwrap();
    let dungeon = world.add_obj_file(&path, &MeshOptions::default()).unwrap();
    let info = world.mesh_info(dungeon).unwrap();
    assert_eq!((info.triangle_count + info.degenerate_triangle_count) as usize, count_obj_triangles(&path));
    assert!(info.bounds_max[1] > info.bounds_min[1]);
}
