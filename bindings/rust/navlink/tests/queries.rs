//! navlink.h's "Queries on a navmesh for one body" (tests/abi/queries_tests.c's cells): a navmesh of 1 m cells
//! in one row, "..#..#..": polygons 0-1 (x in [0, 2]), 2-3 (x in [3, 5]) and 4-5 (x in [6, 8]), z in [0, 1],
//! y = 0, for radius 0; a one-way manual link from cell 1's centre to cell 3's (2 m: its gap). A jumper (3 m)
//! takes it, a walker does not. And find_nearest's point beyond its box. The same checks as the C# and Python
//! tests.
use navlink::{
    default_agent_capabilities, default_agent_type, default_query_filter, sys, ErrorKind, LinkDef, NavmeshId, NavmeshInput,
    NavmeshRay, QueryFilter, RandomPointsOptions, World, AREA_EXCLUDED, NO_ISLAND, NO_POLYGON,
};

const START: [f32; 3] = [0.5, 0.0, 0.5];

/// The cells of one row ('.' a cell, '#' none) as a navmesh for radius 0.
fn add_cell_row(world: &World, row: &str) -> NavmeshId {
    let columns: Vec<f32> = row.chars().enumerate().filter(|&(_, c)| c == '.').map(|(i, _)| i as f32).collect();
    let vertices: Vec<f32> = columns.iter().flat_map(|&c| [c, 0.0, 0.0, c, 0.0, 1.0, c + 1.0, 0.0, 1.0, c + 1.0, 0.0, 0.0]).collect();
    let indices: Vec<u32> = (0..4 * columns.len() as u32).collect();
    let counts = vec![4u8; columns.len()];
    let input = NavmeshInput {
        polygon_vertex_counts: Some(&counts),
        agent_type: navlink::AgentType { radius: 0.0, ..default_agent_type() },
        ..NavmeshInput::triangles(&vertices, &indices)
    };
    world.add_navmesh(&input).expect("the cells")
}

/// The cell row with its one-way link from column 1 to column 3.
fn cells_with_link(world: &World) -> NavmeshId {
    let navmesh = add_cell_row(world, "..#..#..");
    world.add_link(navmesh, &LinkDef { start: [1.5, 0.0, 0.5], end: [3.5, 0.0, 0.5], ..LinkDef::default() }).unwrap();
    navmesh
}

fn body(jump: f32) -> QueryFilter {
    QueryFilter::new(navlink::AgentCapabilities { radius: 0.0, max_jump_distance: jump, ..default_agent_capabilities() })
}

fn near(a: [f32; 3], b: [f32; 3]) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-3)
}

#[test]
fn the_default_filter_is_the_headers() {
    let c = unsafe { sys::nl_default_query_filter() };
    assert_eq!(c.size as usize, std::mem::size_of::<sys::nl_query_filter>());
    assert_eq!(default_query_filter(), QueryFilter { capabilities: default_agent_capabilities(), area_costs: vec![] });
    assert_eq!(QueryFilter::default().capabilities, c.capabilities);
    let d = unsafe { sys::nl_default_random_points_def() };
    let options = RandomPointsOptions::default();
    assert_eq!((options.filter, options.radius, options.reachable_from, options.seed), (None, 0.0, None, 1));
    assert_eq!((d.reachable_from, d.seed, d.filter.is_null()), (NO_POLYGON, 1, true));
}

#[test]
fn reachability_one_way_across_a_link() {
    let world = World::new().unwrap();
    let navmesh = cells_with_link(&world);
    let (walker, jumper) = (body(0.0), body(3.0));
    assert_eq!(world.can_reach(navmesh, &walker, &[0], &[1]).unwrap(), vec![true], "a cell reaches its neighbour");
    assert_eq!(world.can_reach(navmesh, &QueryFilter::default(), &[0], &[1]).unwrap(), vec![false],
               "the default walker (radius 0.6) does not fit through a 1 m portal");
    assert_eq!(world.can_reach(navmesh, &walker, &[1], &[2]).unwrap(), vec![false], "a walker does not cross the gap");
    assert_eq!(world.can_reach(navmesh, &jumper, &[0, 3, 5], &[3, 0, 4]).unwrap(), vec![true, false, true],
               "the jumper takes the link; it does not lead back");
    assert_eq!(world.reachable_polygons(navmesh, &jumper, 1).unwrap(), vec![0, 1, 2, 3]);
    assert_eq!(world.reachable_polygons(navmesh, &walker, 1).unwrap(), vec![0, 1]);
    assert_eq!(world.islands(navmesh, &jumper).unwrap(), (vec![0, 0, 1, 1, 2, 2], 3));

    let keep_out = jumper.clone().with_area_costs(&[AREA_EXCLUDED]);
    assert_eq!(world.islands(navmesh, &keep_out).unwrap(), (vec![NO_ISLAND; 6], 0), "keeping out of area 0 leaves no island");
    assert_eq!(world.can_reach(navmesh, &keep_out, &[0, 0], &[1, 0]).unwrap(), vec![false, true],
               "an excluded polygon is reached from nowhere else, but reaches itself");

    let e = world.can_reach(navmesh, &jumper, &[0], &[6]).unwrap_err();
    assert!(e.kind() == ErrorKind::InvalidArgument && e.message().contains("to_polygons[0] is 6"), "{}", e);
    let e = world.can_reach(navmesh, &jumper, &[0, 1], &[2]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidArgument, "pairs of unequal lengths: {}", e);
}

#[test]
fn raycast_stops_at_a_missing_cell_and_a_slide_follows_the_wall() {
    let world = World::new().unwrap();
    let navmesh = cells_with_link(&world);
    let filter = QueryFilter::default();

    let (hit, crossed) = world.raycast(navmesh, &filter, 0, START, [4.5, 0.0, 0.5]).unwrap();
    assert!(hit.hit && (hit.t - 0.375).abs() < 1e-4, "a raycast into a missing cell stops at its wall: {:?}", hit);
    assert!(near(hit.point, [2.0, 0.0, 0.5]) && near(hit.wall_normal, [-1.0, 0.0, 0.0]), "{:?}", hit);
    assert_eq!((hit.end_polygon, hit.polygon_count, crossed), (1, 2, vec![0, 1]));
    let (hit, crossed) = world.raycast(navmesh, &filter, 0, START, [1.5, 0.0, 0.5]).unwrap();
    assert!(!hit.hit && hit.t == 1.0 && near(hit.point, [1.5, 0.0, 0.5]) && hit.wall_normal == [0.0; 3], "arrives: {:?}", hit);
    assert_eq!((hit.end_polygon, crossed), (1, vec![0, 1]));
    // The single ray is a batch of one: the library names it rays[0].
    let e = world.raycast(navmesh, &filter, 2, START, [1.0, 0.0, 1.0]).unwrap_err();
    assert!(
        e.kind() == ErrorKind::InvalidArgument && e.message().contains("rays[0].start is not over rays[0].start_polygon 2"),
        "{}",
        e
    );

    let (moved, visited) = world.move_along_surface(navmesh, &filter, 0, START, [2.5, 0.0, 0.5]).unwrap();
    assert!(moved.found && near(moved.point, [2.0, 0.0, 0.5]) && moved.polygon == 1, "slides to the wall: {:?}", moved);
    assert!((moved.distance - 0.5).abs() < 1e-3, "0.5 m short: {:?}", moved);
    assert!(visited.len() >= 2 && visited[0] == 0 && *visited.last().unwrap() == 1, "{:?}", visited);
    let (moved, _) = world.move_along_surface(navmesh, &body(0.0), 0, START, [1.5, 0.0, 0.5]).unwrap();
    assert!(near(moved.point, [1.5, 0.0, 0.5]) && moved.polygon == 1 && moved.distance == 0.0, "a clear slide arrives: {:?}", moved);
}

fn ray(start: [f32; 3], start_polygon: u32, end: [f32; 3]) -> NavmeshRay {
    NavmeshRay { start, start_polygon, end }
}

/// Each ray of a batch against the same ray alone, with and without polygons.
fn check_batch_against_single_calls(
    world: &World,
    navmesh: NavmeshId,
    filter: &QueryFilter,
    rays: &[NavmeshRay],
) -> Vec<(navlink::NavmeshRaycastHit, Vec<u32>)> {
    let walks = world.raycast_batch_with_polygons(navmesh, filter, rays).unwrap();
    let hits = world.raycast_batch(navmesh, filter, rays).unwrap();
    assert_eq!((walks.len(), hits.len()), (rays.len(), rays.len()), "one answer per ray");
    for (i, r) in rays.iter().enumerate() {
        let alone = world.raycast(navmesh, filter, r.start_polygon, r.start, r.end).unwrap();
        assert_eq!(walks[i], alone, "ray {} in a batch as alone", i);
        assert_eq!(hits[i], alone.0, "ray {} without polygons", i);
        assert_eq!(alone.0.polygon_count as usize, alone.1.len(), "ray {}: polygon_count counts the list", i);
    }
    walks
}

#[test]
fn a_batch_of_rays_answers_as_single_calls() {
    let world = World::new().unwrap();
    let navmesh = cells_with_link(&world);
    let rays = [
        ray(START, 0, [4.5, 0.0, 0.5]),             // into the missing cell
        ray(START, 0, [1.5, 0.0, 0.5]),             // arrives
        ray([3.5, 0.0, 0.5], 2, [0.5, 0.0, 0.5]),   // west into the gap
        ray([6.5, 0.0, 0.25], 4, [7.5, 0.0, 0.75]), // across the last island
        ray([1.5, 0.0, 0.5], 1, [1.5, 0.0, 3.0]),   // out through the side
    ];
    let walks = check_batch_against_single_calls(&world, navmesh, &body(3.0), &rays);
    assert!(walks[0].0.hit && near(walks[0].0.point, [2.0, 0.0, 0.5]) && walks[0].1 == vec![0, 1], "{:?}", walks[0]);
    assert!(!walks[1].0.hit, "{:?}", walks[1]);
    assert!(walks[2].0.hit && near(walks[2].0.point, [3.0, 0.0, 0.5]) && near(walks[2].0.wall_normal, [1.0, 0.0, 0.0]), "{:?}", walks[2]);
    assert_eq!(walks[2].1, vec![2]);
    assert!(!walks[3].0.hit && walks[3].0.end_polygon == 5 && walks[3].1 == vec![4, 5], "{:?}", walks[3]);
    assert!(walks[4].0.hit && near(walks[4].0.point, [1.5, 0.0, 1.0]) && near(walks[4].0.wall_normal, [0.0, 0.0, -1.0]), "{:?}", walks[4]);
    assert!(world.raycast_batch_with_polygons(navmesh, &body(3.0), &[]).unwrap().is_empty(), "an empty batch");
    assert!(world.raycast_batch(navmesh, &body(3.0), &[]).unwrap().is_empty(), "an empty batch");

    let mut refused = rays;
    refused[3].start_polygon = 2;
    let e = world.raycast_batch(navmesh, &body(3.0), &refused).unwrap_err();
    assert!(
        e.kind() == ErrorKind::InvalidArgument && e.message().contains("rays[3].start is not over rays[3].start_polygon 2"),
        "a batch with one ray off its polygon is refused, naming it: {}",
        e
    );

    // A raw batch the library refuses writes nothing: the hits keep what they held.
    let mut hits = [sys::nl_navmesh_raycast_hit_init(); 5];
    let mut polygons = [7u32; 5 * 4];
    let status = unsafe {
        let (hits, polygons) = (hits.as_mut_ptr(), polygons.as_mut_ptr());
        sys::nl_navmesh_raycast(world.as_ptr(), navmesh, std::ptr::null(), refused.as_ptr(), 5, hits, polygons, 4)
    };
    assert!(sys::nl_failed(status) && status & sys::NL_STATUS_INVALID_ARGUMENT != 0, "{:#x}", status);
    assert!(hits.iter().all(|h| *h == sys::nl_navmesh_raycast_hit_init()) && polygons.iter().all(|&p| p == 7), "nothing written");
    let status = unsafe {
        let (hits, polygons) = (hits.as_mut_ptr(), polygons.as_mut_ptr());
        sys::nl_navmesh_raycast(world.as_ptr(), navmesh, std::ptr::null(), rays.as_ptr(), 5, hits, polygons, 4)
    };
    assert_eq!(status, sys::NL_STATUS_SUCCESS);
    assert_eq!((hits[3].polygon_count, &polygons[12..14]), (2, &[4u32, 5][..]), "ray 3's polygons at 3 * 4");
}

#[test]
fn random_points_are_on_the_navmesh_and_repeat_with_their_seed() {
    let world = World::new().unwrap();
    let navmesh = cells_with_link(&world);
    let seven = RandomPointsOptions { seed: 7, ..Default::default() };
    let points = world.random_points(navmesh, 50, &seven).unwrap();
    let cell_x = [0.0, 1.0, 3.0, 4.0, 6.0, 7.0];
    assert_eq!(points.len(), 50);
    for p in &points {
        assert!(p.found && p.distance == 0.0 && p.point[1] == 0.0 && p.polygon < 6, "{:?}", p);
        let x = cell_x[p.polygon as usize];
        assert!(p.point[0] >= x && p.point[0] <= x + 1.0 && p.point[2] >= 0.0 && p.point[2] <= 1.0, "on its polygon: {:?}", p);
    }
    assert_eq!(world.random_points(navmesh, 50, &seven).unwrap(), points, "the same seed gives the same points");
    assert_ne!(world.random_points(navmesh, 50, &RandomPointsOptions { seed: 8, ..Default::default() }).unwrap(), points);

    let reachable = RandomPointsOptions { filter: Some(body(3.0)), reachable_from: Some(4), ..seven.clone() };
    let points = world.random_points(navmesh, 50, &reachable).unwrap();
    assert!(points.len() == 50 && points.iter().all(|p| p.polygon == 4 || p.polygon == 5), "the last island only");
    let circle = RandomPointsOptions { centre: START, radius: 0.5, ..Default::default() };
    let points = world.random_points(navmesh, 50, &circle).unwrap();
    assert!(points.len() == 50 && points.iter().all(|p| (p.point[0] - 0.5).hypot(p.point[2] - 0.5) <= 0.5 + 1e-4), "within 0.5 m");
    let keep_out = RandomPointsOptions { filter: Some(QueryFilter::default().with_area_costs(&[AREA_EXCLUDED])), ..Default::default() };
    assert!(world.random_points(navmesh, 10, &keep_out).unwrap().is_empty(), "none outside the excluded area");
}

#[test]
fn find_nearest_reports_the_point_beyond_its_box() {
    let world = World::new().unwrap();
    let navmesh = cells_with_link(&world);
    let found = world.find_nearest(navmesh, &[[12.0, 0.0, 0.5], START], [1.0, 1.0, 1.0]).unwrap();
    assert!(!found[0].found && found[0].beyond_box && found[0].polygon == NO_POLYGON, "{:?}", found[0]);
    assert!(near(found[0].point, [8.0, 0.0, 0.5]) && (found[0].distance - 4.0).abs() < 1e-3, "4 m off: {:?}", found[0]);
    assert!(found[1].found && !found[1].beyond_box && found[1].polygon == 0, "{:?}", found[1]);
}

#[test]
fn walks_longer_than_the_first_buffer() {
    // 40 cells in a row: a walk from the first to the last crosses 40 polygons, more than the binding's first
    // buffer holds, so it asks again.
    let world = World::new().unwrap();
    let row = add_cell_row(&world, &".".repeat(40));
    let all: Vec<u32> = (0..40).collect();
    let (hit, crossed) = world.raycast(row, &QueryFilter::default(), 0, START, [39.5, 0.0, 0.5]).unwrap();
    assert!(!hit.hit && hit.polygon_count == 40, "{:?}", hit);
    assert_eq!(crossed, all);
    let (moved, visited) = world.move_along_surface(row, &QueryFilter::default(), 0, START, [39.5, 0.0, 0.5]).unwrap();
    assert!(moved.polygon == 39 && near(moved.point, [39.5, 0.0, 0.5]), "{:?}", moved);
    assert_eq!(visited, all);

    // A batch of long and short walks: those that crossed more than 32 are walked again, together.
    let rays = [
        ray(START, 0, [39.5, 0.0, 0.5]),
        ray(START, 0, [1.5, 0.0, 0.5]),
        ray([39.5, 0.0, 0.5], 39, [2.5, 0.0, 0.5]),
        ray([10.5, 0.0, 0.5], 10, [45.0, 0.0, 0.5]),
        ray([20.5, 0.0, 0.5], 20, [20.5, 0.0, 0.5]),
    ];
    let walks = check_batch_against_single_calls(&world, row, &QueryFilter::default(), &rays);
    let counts: Vec<u32> = walks.iter().map(|w| w.0.polygon_count).collect();
    assert_eq!(counts, vec![40, 2, 38, 30, 1]);
    assert_eq!(walks[0].1, all);
    assert_eq!(walks[2].1, (2..40).rev().collect::<Vec<u32>>(), "backwards");
    assert!(walks[3].0.hit && near(walks[3].0.point, [40.0, 0.0, 0.5]), "out of the row's end: {:?}", walks[3].0);
    assert!(walks[4].0.t == 1.0 && walks[4].1 == vec![20], "a ray of no length: {:?}", walks[4]);
}
