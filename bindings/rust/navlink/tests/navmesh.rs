//! Navmeshes built by Recast and handed over by the host; point location.
mod common;

use common::*;
use navlink::{default_agent_type, default_recast_settings, status, NavmeshBuild, NavmeshInput, World, NO_POLYGON};

#[test]
fn navmesh_from_the_level() {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let mut recast = default_recast_settings();
    assert!((recast.cell_size - 0.3).abs() < 1e-6);
    recast.cell_size = 0.2;
    let build = NavmeshBuild { recast: Some(recast), settings_json: Some("{\"edge_max_length\": 6}"), ..NavmeshBuild::new(default_agent_type()) };
    let navmesh = world.build_navmesh(&build).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    assert!(info.polygon_count >= 2 && info.boundary_edge_count >= 8, "{:?}", info);
    assert!((info.agent.radius - 0.6).abs() < 1e-6);
    // Three islands: the platforms (top y = 0) and the pit floor 20 m down, walkable but unreachable.
    assert!(info.bounds_min[0] >= -12.0 && info.bounds_max[0] <= 12.0 && info.bounds_max[1] < 0.5);
    assert!(info.bounds_min[1] > -20.1 && info.bounds_min[1] < -19.5, "{:?}", info.bounds_min);

    assert_eq!(world.navmesh_vertices(navmesh).unwrap().len() as u32, info.vertex_count);
    let edges = world.boundary_edges(navmesh).unwrap();
    assert_eq!(edges.len() as u32, info.boundary_edge_count);
    assert!(edges.iter().all(|e| ((e.outward[0].powi(2) + e.outward[2].powi(2)).sqrt() - 1.0).abs() < 1e-3));

    let found = world.find_nearest(navmesh, &[[-6.0, 3.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 30.0]], [2.0, 4.0, 2.0]).unwrap();
    assert!(found[0].found == 1 && (found[0].point[0] + 6.0).abs() < 1e-3 && found[0].point[1] < 0.5, "{:?}", found[0]);
    assert!(found[1].found == 1 && found[1].point[0].abs() >= 1.5, "over the gap, a rim: {:?}", found[1]);
    assert!(found[2].found == 0 && found[2].polygon == NO_POLYGON);

    assert_eq!(world.navmeshes().unwrap(), vec![navmesh]);

    // The settings struct reaches the builder: 3 corners per polygon turn the platforms' quads into triangles.
    let triangles = NavmeshBuild {
        recast: Some(navlink::RecastSettings { vertices_per_polygon: 3, ..default_recast_settings() }),
        ..NavmeshBuild::new(default_agent_type())
    };
    let triangulated = world.build_navmesh(&triangles).unwrap();
    let polygons = world.navmesh_info(triangulated).unwrap().polygon_count;
    assert!((0..polygons).all(|i| world.polygon(triangulated, i).unwrap().vertex_count == 3));
    assert!((0..info.polygon_count).any(|i| world.polygon(navmesh, i).unwrap().vertex_count > 3));
    world.remove_navmesh(triangulated).unwrap();
    let bad_json = NavmeshBuild { settings_json: Some("{oops"), ..NavmeshBuild::new(default_agent_type()) };
    assert_fails(world.build_navmesh(&bad_json), status::PARSE_ERROR, "settings");
    let unknown = NavmeshBuild { builder: Some("nope"), ..NavmeshBuild::new(default_agent_type()) };
    assert_fails(world.build_navmesh(&unknown), status::NOT_FOUND, "nope");
    world.remove_navmesh(navmesh).unwrap();
    assert!(!world.is_navmesh_valid(navmesh));
    assert_fails(world.navmesh_info(navmesh), status::INVALID_HANDLE, "nl_navmesh_get_info");

    let empty = World::new().unwrap();
    assert_fails(empty.build_navmesh(&NavmeshBuild::new(default_agent_type())), status::NOT_FOUND, "walkable");
}

#[test]
fn navmesh_from_the_host() {
    // Two 1 x 1 m squares as four triangles with their own vertices (Unity's triangulation).
    let vertices = [
        0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, //
        1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0, 1.0, 1.0, 0.0, 0.0, 2.0, 0.0, 1.0, 2.0, 0.0, 0.0,
    ];
    let mut indices: Vec<u32> = (0..12).collect();
    let areas = [0u8, 0, 5, 5];
    let world = World::new().unwrap();
    let navmesh = world.add_navmesh(&NavmeshInput { areas: Some(&areas), ..NavmeshInput::triangles(&vertices, &indices) }).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    assert_eq!(
        (info.vertex_count, info.welded_vertex_count, info.portal_count, info.boundary_edge_count),
        (6, 6, 3, 6)
    );
    let polygon = world.polygon(navmesh, 2).unwrap();
    let linked = polygon.neighbours[..polygon.vertex_count as usize].iter().filter(|&&n| n != NO_POLYGON).count();
    assert!(polygon.vertex_count == 3 && polygon.area == 5 && linked >= 1 && polygon.neighbours[15] == NO_POLYGON);
    assert_fails(world.polygon(navmesh, 99), status::INVALID_ARGUMENT, "polygon");
    indices[2] = 40;
    assert_fails(world.add_navmesh(&NavmeshInput::triangles(&vertices, &indices)), status::INVALID_ARGUMENT, "indices");
}
