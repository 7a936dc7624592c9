//! What a navmesh build takes from the level (tests/abi/navmesh_build_tests.c's winding, mesh_roles,
//! mesh_areas and build_progress, with their geometry): the winding of a mesh's triangles, obstacles and
//! meshes left out of builds, each mesh's area in the polygons built over it, a mesh's units; and a build's
//! progress and cancel.
mod common;

use common::*;
use navlink::{
    default_agent_type, status, BuildWarnings, ErrorKind, MeshFlags, MeshId, MeshOptions, NavPolygon, NavmeshBuild, NavmeshId,
    Ray, UpAxis, World, MESH_MAX_AREA,
};

/// A horizontal quad's triangles: counter-clockwise seen from above (its front faces up), and the same
/// triangles wound the other way.
const FRONT_UP: [u32; 6] = [0, 1, 2, 0, 2, 3];
const FRONT_DOWN: [u32; 6] = [0, 2, 1, 0, 3, 2];

/// A horizontal quad, x in [x0, x1], z in [z0, z1] at height y.
fn add_quad(world: &World, [x0, z0, x1, z1]: [f32; 4], y: f32, winding: &[u32; 6], options: &MeshOptions) -> navlink::Result<MeshId> {
    let corners = [x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0];
    world.add_mesh(&corners, winding, options)
}

fn flagged(flags: MeshFlags) -> MeshOptions {
    MeshOptions { flags, ..Default::default() }
}

fn build(world: &World) -> NavmeshId {
    world.build_navmesh(&NavmeshBuild::new(default_agent_type())).expect("a navmesh")
}

/// The polygon within (0.4, 0.3, 0.4) of the point, if any.
fn polygon_at(world: &World, navmesh: NavmeshId, point: [f32; 3]) -> Option<NavPolygon> {
    let hit = world.find_nearest(navmesh, &[point], [0.4, 0.3, 0.4]).unwrap()[0];
    hit.found.then(|| world.polygon(navmesh, hit.polygon).unwrap())
}

fn walkable_at(world: &World, navmesh: NavmeshId, point: [f32; 3]) -> bool {
    polygon_at(world, navmesh, point).is_some()
}

#[test]
fn a_clockwise_floor_builds_only_with_the_clockwise_flag() {
    let world = World::new().unwrap();
    // Wound clockwise (fronts down): nothing to walk on, and the message names the flag to set.
    let floor = add_quad(&world, [-10.0, -10.0, 10.0, 10.0], 0.0, &FRONT_DOWN, &MeshOptions::default()).unwrap();
    let unflagged = world.build_navmesh(&NavmeshBuild::new(default_agent_type()));
    assert_fails(unflagged, status::NOT_FOUND, "NL_MESH_CLOCKWISE");
    world.remove_mesh(floor).unwrap();

    let floor = add_quad(&world, [-10.0, -10.0, 10.0, 10.0], 0.0, &FRONT_DOWN, &flagged(MeshFlags::CLOCKWISE)).unwrap();
    assert_eq!(world.mesh_info(floor).unwrap().flags, MeshFlags::CLOCKWISE, "the mesh keeps its flag");
    assert!(walkable_at(&world, build(&world), [0.0, 0.0, 0.0]), "the same floor flagged clockwise is walked on");
}

#[test]
fn an_obstacle_crate_is_not_walked_on_and_a_left_out_slab_is_not_built() {
    let world = World::new().unwrap();
    add_quad(&world, [-10.0, -10.0, 10.0, 10.0], 0.0, &FRONT_UP, &MeshOptions::default()).unwrap();
    // A 4 x 4 x 1 m crate, x and z in [3, 7]: its top is walkable as any floor, unless it is an obstacle.
    let crate_box = add_box(&world, [3.0, 0.0, 3.0], [7.0, 1.0, 7.0]);
    assert!(walkable_at(&world, build(&world), [5.0, 1.0, 5.0]), "an ordinary crate's top is walkable");
    world.remove_mesh(crate_box).unwrap();
    let crate_box = add_box_with(&world, [3.0, 0.0, 3.0], [7.0, 1.0, 7.0], &flagged(MeshFlags::OBSTACLE));
    assert!(world.mesh_info(crate_box).unwrap().flags.contains(MeshFlags::OBSTACLE));
    let navmesh = build(&world);
    assert!(!walkable_at(&world, navmesh, [5.0, 1.0, 5.0]), "an obstacle crate's top is not walked on");
    assert!(!walkable_at(&world, navmesh, [5.0, 0.0, 5.0]), "the floor under the obstacle is blocked");
    assert!(walkable_at(&world, navmesh, [-5.0, 0.0, 5.0]), "the floor beside it is walkable");

    // A slab 1 m over the floor leaves no headroom; left out of builds it leaves the floor, and rays meet it.
    let slab_corners = [-8.0, -8.0, -2.0, -2.0];
    let slab = add_quad(&world, slab_corners, 1.0, &FRONT_DOWN, &MeshOptions::default()).unwrap();
    assert!(!walkable_at(&world, build(&world), [-5.0, 0.0, -5.0]), "no headroom under the slab");
    world.remove_mesh(slab).unwrap();
    let slab = add_quad(&world, slab_corners, 1.0, &FRONT_DOWN, &flagged(MeshFlags::NOT_IN_NAVMESH)).unwrap();
    assert!(walkable_at(&world, build(&world), [-5.0, 0.0, -5.0]), "a slab left out of builds leaves the floor walkable");
    let hit = world.cast_rays(&[Ray { origin: [-5.0, 5.0, -5.0], direction: [0.0, -1.0, 0.0], max_distance: 10.0 }]).unwrap()[0];
    assert!(hit.hit && hit.mesh == slab && (hit.point[1] - 1.0).abs() < 1e-4, "a ray meets the left-out slab: {:?}", hit);

    let both = add_quad(&world, [0.0, 0.0, 1.0, 1.0], 0.0, &FRONT_UP, &flagged(MeshFlags::OBSTACLE | MeshFlags::NOT_IN_NAVMESH));
    assert_eq!(both.expect_err("obstacle and left out").kind(), ErrorKind::InvalidArgument);
}

#[test]
fn a_mesh_area_is_carried_into_the_built_polygons() {
    let world = World::new().unwrap();
    add_quad(&world, [-10.0, -10.0, 0.0, 10.0], 0.0, &FRONT_UP, &MeshOptions::default()).unwrap();
    let east = add_quad(&world, [0.0, -10.0, 10.0, 10.0], 0.0, &FRONT_UP, &MeshOptions { area: 5, ..Default::default() }).unwrap();
    assert_eq!(world.mesh_info(east).unwrap().area, 5, "the mesh info reports the area");
    let navmesh = build(&world);
    assert_eq!(polygon_at(&world, navmesh, [5.0, 0.0, 0.0]).map(|p| p.area), Some(5), "the polygon over the east mesh");
    assert_eq!(polygon_at(&world, navmesh, [-5.0, 0.0, 0.0]).map(|p| p.area), Some(0), "the polygon over the west mesh");

    let too_high = MeshOptions { area: MESH_MAX_AREA + 1, ..Default::default() };
    assert_fails(add_quad(&world, [0.0, 0.0, 1.0, 1.0], 0.0, &FRONT_UP, &too_high), status::INVALID_ARGUMENT, "area");
}

#[test]
fn a_level_in_centimetres_is_registered_in_metres() {
    // The 10 x 10 m box, 1 m thick, as an exporter in centimetres writes it.
    let (lo, hi) = ([-500.0, -100.0, -500.0], [500.0, 0.0, 500.0]);
    let (world, logged) = world_keeping_log();
    let centimetres = MeshOptions { metres_per_unit: 0.01, up_axis: UpAxis::Y, ..Default::default() };
    let mesh = add_box_with(&world, lo, hi, &centimetres);
    let info = world.mesh_info(mesh).unwrap();
    assert_eq!((info.metres_per_unit, info.up_axis), (0.01, UpAxis::Y), "the mesh info reports its frame");
    let near = |a: [f32; 3], b: [f32; 3]| a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-4);
    assert!(near(info.bounds_min, [-5.0, -1.0, -5.0]) && near(info.bounds_max, [5.0, 0.0, 5.0]), "the bounds in metres: {:?}", info);
    assert_eq!(world.navmesh_info(build(&world)).unwrap().build_warnings, BuildWarnings::NONE);
    world.remove_mesh(mesh).unwrap();

    // Not said, its walls are 100 m tall for a body of 2 m. Coarse cells: read as metres it is 1 km wide.
    add_box(&world, lo, hi);
    let coarse = NavmeshBuild { settings_json: Some("{\"cell_size\": 2.0, \"cell_height\": 0.5}"), ..NavmeshBuild::new(default_agent_type()) };
    let navmesh = world.build_navmesh(&coarse).unwrap();
    assert_eq!(world.navmesh_info(navmesh).unwrap().build_warnings, BuildWarnings::UNITS);
    let logged = logged.lock().unwrap();
    assert!(logged.iter().any(|m| m.contains("metres_per_unit")), "the log's warning names the option: {:?}", logged);
}

#[test]
fn a_build_reports_progress_and_can_be_cancelled() {
    let world = World::new().unwrap();
    add_box(&world, [-10.0, 0.0, -10.0], [10.0, 1.0, 10.0]);
    let caller = std::thread::current().id();
    let mut fractions = Vec::new();
    let mut stages = Vec::new();
    let mut other_thread = 0;
    let mut progress = |fraction: f32, stage: &str| {
        fractions.push(fraction);
        stages.push(stage.to_string());
        other_thread += (std::thread::current().id() != caller) as i32;
        true
    };
    world.build_navmesh_with_progress(&NavmeshBuild::new(default_agent_type()), &mut progress).unwrap();
    assert!(fractions.len() >= 2, "{} progress calls", fractions.len());
    assert!(fractions.windows(2).all(|pair| pair[1] >= pair[0]), "progress never goes back: {:?}", fractions);
    assert_eq!((fractions[0], *fractions.last().unwrap()), (0.0, 1.0), "from 0 to 1: {:?}", fractions);
    assert!(stages.iter().any(|s| s == "rasterising the level"), "{:?}", stages);
    assert_eq!(other_thread, 0, "progress runs on the calling thread");

    // Cancelled while rasterising: CANCELLED, no navmesh added, and nothing reported after the cancel.
    let (mut cancelled, mut calls_after_cancel) = (false, 0);
    let mut cancel = |_: f32, stage: &str| {
        if cancelled {
            calls_after_cancel += 1;
            return false;
        }
        cancelled = stage == "rasterising the level";
        !cancelled
    };
    let error = world.build_navmesh_with_progress(&NavmeshBuild::new(default_agent_type()), &mut cancel).unwrap_err();
    assert_eq!(error.kind(), ErrorKind::Cancelled, "{}", error);
    assert!(cancelled && calls_after_cancel == 0, "the build stopped at its cancel ({} calls after)", calls_after_cancel);
    assert_eq!(world.navmeshes().unwrap().len(), 1, "a cancelled build adds no navmesh");

    // A panic in the closure cancels the build and comes back to the caller.
    let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let _ = world.build_navmesh_with_progress(&NavmeshBuild::new(default_agent_type()), &mut |_, _| panic!("progress panics"));
    }));
    assert!(panicked.is_err(), "the closure's panic comes back to the caller");
    assert_eq!(world.navmeshes().unwrap().len(), 1, "and the build added nothing");
}
