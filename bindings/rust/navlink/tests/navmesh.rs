//! Navmeshes built by Recast and handed over by the host; point location; a navmesh that rides a moving mesh,
//! a cross link onto it, and cross links generated between it and a ledge.
mod common;

use common::*;
use navlink::{
    default_agent_type, default_link_def, default_link_settings, default_recast_settings, describe_navmesh_file, status, AgentReason,
    AgentType, BuildWarnings, ErrorKind, Link, LinkDef, LinkDefExt, LinkExt, LinkSettings, MeshFlags, MeshId, MeshOptions, NavmeshBuild,
    NavmeshId, NavmeshInput, NavmeshLoadOptions, NavmeshTile, PathOutcome, PathQuery, RecastSettings, TileCoord, World, NO_POLYGON,
};

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
    assert!((info.agent_type.radius - 0.6).abs() < 1e-6);
    assert_eq!(info.turned_over_mesh_count, 0, "the level's fronts are wound counter-clockwise");
    assert_eq!(info.build_warnings, BuildWarnings::NONE, "the level is in metres with y up");
    // Three islands: the platforms (top y = 0) and the pit floor 20 m down, walkable but unreachable.
    assert!(info.bounds_min[0] >= -12.0 && info.bounds_max[0] <= 12.0 && info.bounds_max[1] < 0.5);
    assert!(info.bounds_min[1] > -20.1 && info.bounds_min[1] < -19.5, "{:?}", info.bounds_min);

    assert_eq!(world.navmesh_vertices(navmesh).unwrap().len() as u32, info.vertex_count);
    let edges = world.boundary_edges(navmesh).unwrap();
    assert_eq!(edges.len() as u32, info.boundary_edge_count);
    assert!(edges.iter().all(|e| ((e.outward[0].powi(2) + e.outward[2].powi(2)).sqrt() - 1.0).abs() < 1e-3));

    let found = world.find_nearest(navmesh, &[[-6.0, 3.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 30.0]], [2.0, 4.0, 2.0]).unwrap();
    assert!(found[0].found && (found[0].point[0] + 6.0).abs() < 1e-3 && found[0].point[1] < 0.5, "{:?}", found[0]);
    assert!(found[1].found && found[1].point[0].abs() >= 1.5, "over the gap, a rim: {:?}", found[1]);
    assert!(!found[2].found && found[2].polygon == NO_POLYGON);

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

/// A 40 x 1 x 12 m floor (top y = 0) built in tiles of 32 cells (9.6 m): the tiles listed are the info's, in row
/// order; the tile under (20, 0, 3) removed leaves a hole and is gone from the list, removed again it is not
/// found; built again from the level in a box around its centre it is back (tile_size 64 refused, nothing
/// changed); removed once more, a hand-made quad added as that tile (the floor eroded 0.6 m within the tile's
/// square) fills the hole and joins its neighbours.
#[test]
fn tiles_out_and_in_again() {
    let world = World::new().unwrap();
    add_box(&world, [0.0, -1.0, 0.0], [40.0, 0.0, 12.0]);
    let defaults = default_recast_settings();
    assert_eq!((defaults.tile_size, defaults.tile_border), (0, 0), "solo by default");
    let recast = RecastSettings { tile_size: 32, ..defaults };
    let navmesh = world.build_navmesh(&NavmeshBuild { recast: Some(recast), ..NavmeshBuild::new(default_agent_type()) }).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    let tiles = world.tiles(navmesh).unwrap();
    assert!(tiles.len() > 1, "{:?}", tiles);
    assert_eq!(tiles.len() as u32, info.tile_count);
    let mut row_order = tiles.clone();
    row_order.sort_by_key(|t| (t.z, t.x));
    assert_eq!(tiles, row_order, "row order: z, then x");
    assert!((info.tile_width - 32.0 * recast.cell_size).abs() < 1e-4, "{}", info.tile_width);
    let (width, origin) = (info.tile_width, info.tile_origin);
    let middle = [20.0, 0.0, 3.0];
    let tile = TileCoord { x: ((middle[0] - origin[0]) / width).floor() as i32, z: ((middle[2] - origin[1]) / width).floor() as i32 };
    assert!(tiles.contains(&tile), "{:?} in {:?}", tile, tiles);
    let on_navmesh = |point: [f32; 3]| world.find_nearest(navmesh, &[point], [0.4, 0.3, 0.4]).unwrap()[0].found;
    let end_to_end = || world.find_path(&PathQuery::new(navmesh, [2.0, 0.0, 3.0], [38.0, 0.0, 3.0], walker())).unwrap().outcome();
    assert!(on_navmesh(middle));
    assert_eq!(end_to_end(), PathOutcome::Complete);

    world.remove_tile(navmesh, tile).unwrap();
    let after = world.tiles(navmesh).unwrap();
    assert_eq!(after.len(), tiles.len() - 1);
    assert_eq!(after, tiles.iter().copied().filter(|t| *t != tile).collect::<Vec<_>>());
    assert_eq!(world.navmesh_info(navmesh).unwrap().tile_count as usize, after.len());
    assert!(!on_navmesh(middle), "a hole where the tile was");
    let twice = world.remove_tile(navmesh, tile);
    assert_eq!(twice.as_ref().map_err(|e| e.kind()), Err(ErrorKind::NotFound));
    assert_fails(twice, status::NOT_FOUND, "no tile");
    assert_eq!(world.tiles(navmesh).unwrap(), after, "a refused removal changes nothing");

    // The tile built again from the level, with the same settings, in a small box around its centre.
    let centre = [origin[0] + (tile.x as f32 + 0.5) * width, 0.0, origin[1] + (tile.z as f32 + 0.5) * width];
    let (box_min, box_max) = ([centre[0] - 0.5, -1.0, centre[2] - 0.5], [centre[0] + 0.5, 1.0, centre[2] + 0.5]);
    let same = NavmeshBuild { recast: Some(recast), ..NavmeshBuild::new(default_agent_type()) };
    world.build_tiles(navmesh, &same, box_min, box_max).unwrap();
    assert_eq!(world.tiles(navmesh).unwrap(), tiles, "the built tile is back in its place");
    assert_eq!(world.navmesh_info(navmesh).unwrap().tile_count as usize, tiles.len());
    assert!(on_navmesh(middle), "the built tile fills the hole");
    assert_eq!(end_to_end(), PathOutcome::Complete, "the built tile joins its neighbours");
    // Settings making tiles of another width (64 cells) are refused, and change nothing.
    let rebuilt = (world.navmesh_info(navmesh).unwrap().polygon_count, world.navmesh_vertices(navmesh).unwrap());
    let wider = NavmeshBuild { recast: Some(RecastSettings { tile_size: 64, ..defaults }), ..same };
    let refused = world.build_tiles(navmesh, &wider, box_min, box_max);
    assert_eq!(refused.as_ref().map_err(|e| e.kind()), Err(ErrorKind::InvalidArgument));
    assert_fails(refused, status::INVALID_ARGUMENT, "makes tiles of");
    assert_eq!(world.tiles(navmesh).unwrap(), tiles, "a refused build changes no tile");
    assert_eq!(world.navmesh_info(navmesh).unwrap().tile_count as usize, tiles.len());
    assert_eq!((world.navmesh_info(navmesh).unwrap().polygon_count, world.navmesh_vertices(navmesh).unwrap()), rebuilt);
    assert_eq!(end_to_end(), PathOutcome::Complete);
    world.remove_tile(navmesh, tile).unwrap();
    assert_eq!(world.tiles(navmesh).unwrap(), after);

    // The host's tile: one quad on the navmesh's grid.
    let (x0, z0) = ((origin[0] + tile.x as f32 * width).max(0.6), (origin[1] + tile.z as f32 * width).max(0.6));
    let (x1, z1) = ((origin[0] + (tile.x + 1) as f32 * width).min(39.4), (origin[1] + (tile.z + 1) as f32 * width).min(11.4));
    let corners = [x0, 0.0, z0, x0, 0.0, z1, x1, 0.0, z1, x1, 0.0, z0];
    let place = NavmeshTile::on_grid_of(&info, tile);
    assert_eq!(place, NavmeshTile { coord: tile, width, origin });
    let hand_made = NavmeshInput { tile: Some(place), ..quad(&corners) };
    world.add_tile(navmesh, &hand_made).unwrap();
    assert_eq!(world.tiles(navmesh).unwrap(), tiles);
    assert_eq!(world.navmesh_info(navmesh).unwrap().tile_count as usize, tiles.len());
    assert!(on_navmesh(middle), "the hand-made tile fills the hole");
    assert_eq!(end_to_end(), PathOutcome::Complete, "the tile joins its neighbours");
    assert_fails(world.add_tile(navmesh, &hand_made), status::INVALID_ARGUMENT, "loaded already");
    let elsewhere = NavmeshTile { coord: TileCoord { x: 99, z: 0 }, width: 2.0 * width, origin };
    let on_another_grid = NavmeshInput { tile: Some(elsewhere), ..quad(&corners) };
    assert_fails(world.add_tile(navmesh, &on_another_grid), status::INVALID_ARGUMENT, "another grid");
    assert_fails(world.add_tile(navmesh, &quad(&corners)), status::INVALID_ARGUMENT, "not a tile");
    // A solo navmesh has no tiles and takes none.
    let solo = world.add_navmesh(&quad(&[-5.0, 0.0, -5.0, -5.0, 0.0, 5.0, 5.0, 0.0, 5.0, 5.0, 0.0, -5.0])).unwrap();
    assert_eq!((world.tiles(solo).unwrap(), world.navmesh_info(solo).unwrap().tile_count), (vec![], 0));
    assert_fails(world.remove_tile(solo, TileCoord { x: 0, z: 0 }), status::INVALID_ARGUMENT, "not tiled");
    assert_eq!(AgentReason::from_raw(navlink::sys::NL_AGENT_REASON_TILE_UNLOADED), AgentReason::TileUnloaded);
    assert_eq!(AgentReason::TileUnloaded.to_raw(), 9);
}

/// The gap level built in tiles of 32 cells (9.6 m), its links generated (the jumps start on one tile and land on
/// another): every tile saved as a tile's file and described (a tile, its place, the world's content hash for it);
/// the first tile's bytes loaded in a second world with the same level and the others added make the same tiles
/// and links; one tile once through a file; a tile added twice refused.
#[test]
fn tiles_saved_and_loaded_as_tiles_files() {
    let world = World::new().unwrap();
    add_gap_level(&world);
    let recast = RecastSettings { tile_size: 32, ..default_recast_settings() };
    let navmesh = world.build_navmesh(&NavmeshBuild { recast: Some(recast), ..NavmeshBuild::new(default_agent_type()) }).unwrap();
    world.generate_links(navmesh, None, None, None).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    let tiles = world.tiles(navmesh).unwrap();
    let link_count = world.links(navmesh).unwrap().len();
    assert!(tiles.len() > 1 && link_count > 0, "{} tiles, {} links", tiles.len(), link_count);

    let files: Vec<Vec<u8>> = tiles.iter().map(|&tile| world.save_tile(navmesh, tile).unwrap()).collect();
    let mut tile_links = 0;
    for (&tile, file) in tiles.iter().zip(&files) {
        let (described, _) = describe_navmesh_file(file).unwrap();
        assert!(described.is_tile && described.tile == tile, "{:?}: {:?}", tile, described);
        let hash = world.tile_hash(navmesh, tile).unwrap();
        assert!(hash != 0 && described.content_hash == hash, "{:?}: {:#x}, the world's {:#x}", tile, described.content_hash, hash);
        assert_eq!((described.tile_width, [described.tile_origin_x, described.tile_origin_z]), (info.tile_width, info.tile_origin));
        assert_eq!(described.file_size, file.len() as u64);
        tile_links += described.link_count as usize;
    }
    assert_eq!(tile_links, link_count, "each generated link in the file of the tile it starts on");
    let (whole, _) = describe_navmesh_file(&world.save_navmesh(navmesh).unwrap()).unwrap();
    assert!(!whole.is_tile && whole.content_hash == 0, "a whole navmesh's file is no tile's: {:?}", whole);

    let other = World::new().unwrap();
    add_gap_level(&other);
    let loaded = other.load_navmesh(&files[0], &NavmeshLoadOptions::default()).unwrap();
    assert_eq!(other.tiles(loaded).unwrap(), vec![tiles[0]], "the first tile's file makes a navmesh of that tile");
    for file in &files[1..] {
        other.add_tile_bytes(loaded, file).unwrap();
    }
    assert_eq!(other.tiles(loaded).unwrap(), tiles);
    assert_eq!(other.links(loaded).unwrap().len(), link_count);
    assert_eq!(other.navmesh_info(loaded).unwrap().polygon_count, info.polygon_count);

    // Once through a file: the tile with the most links, saved to a file, removed and added back from it.
    let most = (0..tiles.len()).max_by_key(|&k| describe_navmesh_file(&files[k]).unwrap().0.link_count).unwrap();
    let dir = TempDir::new("tile-files");
    let path = dir.0.join("tile.nlnav");
    world.save_tile_file(navmesh, tiles[most], &path).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), files[most]);
    other.remove_tile(loaded, tiles[most]).unwrap();
    assert_eq!(other.tiles(loaded).unwrap().len(), tiles.len() - 1);
    other.add_tile_file(loaded, &path).unwrap();
    assert_eq!(other.tiles(loaded).unwrap(), tiles);
    assert_eq!(other.links(loaded).unwrap().len(), link_count, "its links back with it");

    let twice = other.add_tile_bytes(loaded, &files[most]);
    assert_eq!(twice.as_ref().map_err(|e| e.kind()), Err(ErrorKind::InvalidArgument));
    assert_fails(twice, status::INVALID_ARGUMENT, "loaded already");
    assert_eq!((other.tiles(loaded).unwrap(), other.links(loaded).unwrap().len()), (tiles, link_count), "nothing changed");
}

/// The moving surface: an 8 x 4 m movable box (top y = 0 in its own space) carrying a 7.2 x 3.2 m navmesh
/// quad, then moved 10 m along x and turned 90 degrees about y: its x axis goes to the world's -z, its z
/// axis to x.
const RAFT_QUAD: [f32; 12] = [-3.6, 0.0, -1.6, -3.6, 0.0, 1.6, 3.6, 0.0, 1.6, 3.6, 0.0, -1.6];
const RAFT_MOVED: [f32; 16] = [0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 10.0, 0.0, 0.0, 1.0];
const RAFT_SCALED: [f32; 16] = [2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 10.0, 0.0, 0.0, 1.0];

// Within a millimetre: navmeshes keep coordinates on a grid of 1/1024 m.
fn assert_near(got: [f32; 3], want: [f32; 3], what: &str) {
    assert!(got.iter().zip(want.iter()).all(|(g, w)| (g - w).abs() < 1e-3), "{}: {:?}, expected {:?}", what, got, want);
}

#[test]
fn navmesh_on_a_moving_surface() {
    let world = World::new().unwrap();
    let movable = MeshOptions { flags: MeshFlags::MOVABLE, ..Default::default() };
    let raft = add_box_with(&world, [-4.0, -1.0, -2.0], [4.0, 0.0, 2.0], &movable);
    let input = NavmeshInput { polygon_vertex_counts: Some(&[4]), carrier: Some(raft), ..NavmeshInput::triangles(&RAFT_QUAD, &[0, 1, 2, 3]) };
    let navmesh = world.add_navmesh(&input).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    assert_eq!((info.carrier, info.polygon_count), (raft, 1));
    let (on_raft, old_place) = ([10.0, 0.5, 3.0], [0.0, 0.5, 0.0]);
    let found = world.find_nearest(navmesh, &[old_place, on_raft], [0.5, 2.0, 0.5]).unwrap();
    assert_eq!((found[0].found, found[1].found), (true, false), "before the move: at the origin");

    world.set_mesh_transform(raft, &RAFT_MOVED).unwrap();
    let info = world.navmesh_info(navmesh).unwrap();
    assert_eq!(info.carrier, raft);
    assert!(
        info.bounds_min[0] <= 8.4 + 1e-3 && info.bounds_max[0] >= 11.6 - 1e-3 && info.bounds_min[2] <= -3.6 + 1e-3
            && info.bounds_max[2] >= 3.6 - 1e-3,
        "{:?} {:?}",
        info.bounds_min,
        info.bounds_max
    );
    // (10, 3) is on the quad only if it was turned (its z half-width is 1.6 before).
    let found = world.find_nearest(navmesh, &[old_place, on_raft], [0.5, 2.0, 0.5]).unwrap();
    assert!(!found[0].found, "nothing left at the old place");
    assert!(found[1].found);
    assert_near(found[1].point, [10.0, 0.0, 3.0], "the navmesh point on the moved raft");

    // Along the raft: the world's +z to -z is the mesh's -x to +x.
    let path = world.find_path(&PathQuery::new(navmesh, [10.0, 0.0, 3.0], [10.0, 0.0, -3.0], walker())).unwrap();
    assert_eq!(path.outcome(), PathOutcome::Complete);
    assert!((path.summary.length - 6.0).abs() < 1e-4, "{} m", path.summary.length);
    let (first, last) = (path.points[0], *path.points.last().unwrap());
    assert_near(first.position, [10.0, 0.0, 3.0], "first position (world)");
    assert_near(first.carrier_position, [-3.0, 0.0, 0.0], "first carrier_position (the mesh's space)");
    assert_near(last.position, [10.0, 0.0, -3.0], "last position (world)");
    assert_near(last.carrier_position, [3.0, 0.0, 0.0], "last carrier_position (the mesh's space)");

    // Only rigid moves for a mesh that carries a navmesh, and it cannot go while the navmesh rides it.
    assert_fails(world.set_mesh_transform(raft, &RAFT_SCALED), status::INVALID_ARGUMENT, "nl_mesh_set_transform");
    assert_eq!(world.mesh_info(raft).unwrap().transform, RAFT_MOVED, "a refused move moves nothing");
    assert_fails(world.remove_mesh(raft), status::INVALID_ARGUMENT, "nl_mesh_remove");

    // Recast on the raft alone, in its space, riding it; without a carrier a build sees static meshes only.
    let built = world.build_navmesh(&NavmeshBuild { carrier: Some(raft), ..NavmeshBuild::new(default_agent_type()) }).unwrap();
    assert_eq!(world.navmesh_info(built).unwrap().carrier, raft);
    let found = world.find_nearest(built, &[on_raft, old_place], [0.5, 2.0, 0.5]).unwrap();
    assert_eq!((found[0].found, found[1].found), (true, false));
    assert_fails(world.build_navmesh(&NavmeshBuild::new(default_agent_type())), status::NOT_FOUND, "no triangles");
    world.remove_navmesh(built).unwrap();
    world.remove_navmesh(navmesh).unwrap();
    world.remove_mesh(raft).unwrap();

    // A navmesh on no carrier reports the null id, and its path points' carrier_position is position.
    let floor = [-5.0, 0.0, -5.0, 5.0, 0.0, -5.0, 5.0, 0.0, 5.0, -5.0, 0.0, 5.0];
    let ground = world.add_navmesh(&NavmeshInput::triangles(&floor, &[0, 2, 1, 0, 3, 2])).unwrap();
    assert_eq!(world.navmesh_info(ground).unwrap().carrier, MeshId::default());
    let stroll = world.find_path(&PathQuery::new(ground, [-4.0, 0.0, -4.0], [4.0, 0.0, 4.0], walker())).unwrap();
    assert!(stroll.points.iter().all(|q| q.carrier_position == q.position), "{:?}", stroll.points);
}

/// A cross link onto a moving surface: a static 6 x 4 m ledge navmesh (x in [-6, 0], z in [-2, 2], y = 0) and,
/// 1 m past its edge, a 4 x 4 m movable box (x in [1, 5]; its own space is the world's until it moves) carrying
/// a 3.6 x 3.6 m navmesh quad. The link goes from the ledge's edge onto the box; the box then moves 2 m away
/// along x and back.
const LEDGE_QUAD: [f32; 12] = [-6.0, 0.0, -2.0, -6.0, 0.0, 2.0, 0.0, 0.0, 2.0, 0.0, 0.0, -2.0];
const DECK_QUAD: [f32; 12] = [1.2, 0.0, -1.8, 1.2, 0.0, 1.8, 4.8, 0.0, 1.8, 4.8, 0.0, -1.8];
const DECK_HOME: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
const DECK_AWAY: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 2.0, 0.0, 0.0, 1.0];
const CROSS_START: [f32; 3] = [-0.4, 0.0, 0.0];
const CROSS_END: [f32; 3] = [1.6, 0.0, 0.0];
const CROSS_END_AWAY: [f32; 3] = [3.6, 0.0, 0.0];

/// A one-quad navmesh.
fn quad(vertices: &[f32]) -> NavmeshInput<'_> {
    NavmeshInput { polygon_vertex_counts: Some(&[4]), ..NavmeshInput::triangles(vertices, &[0, 1, 2, 3]) }
}

#[test]
fn cross_link_onto_a_moving_surface() {
    let world = World::new().unwrap();
    let ledge = world.add_navmesh(&quad(&LEDGE_QUAD)).unwrap();
    let movable = MeshOptions { flags: MeshFlags::MOVABLE, ..Default::default() };
    let deck_box = add_box_with(&world, [1.0, -1.0, -2.0], [5.0, 0.0, 2.0], &movable);
    let deck = world.add_navmesh(&NavmeshInput { carrier: Some(deck_box), ..quad(&DECK_QUAD) }).unwrap();
    let defaults = default_link_def();
    assert_eq!(defaults.landing(), None, "a link within one navmesh by default");
    assert_eq!(defaults.tolerance, 0.25);
    // In the world, the box beside the ledge.
    let def = LinkDef { start: CROSS_START, end: CROSS_END, ..defaults }.with_landing(Some(deck));
    assert_eq!((def.landing(), def.landing_navmesh), (Some(deck), deck));
    let cross = world.add_link(ledge, &def).unwrap();
    let link = world.link(cross).unwrap();
    assert_eq!((link.navmesh, link.landing(), link.landing_navmesh), (ledge, Some(deck), deck));
    assert_eq!((link.holds, link.bidirectional), (true, false));
    assert_eq!(link.tolerance, 0.25);
    assert_ne!(link.end_polygon, NO_POLYGON, "the end is on a polygon of the deck");
    assert_near(link.start, CROSS_START, "start");
    assert_near(link.end, CROSS_END, "end");

    world.set_mesh_transform(deck_box, &DECK_AWAY).unwrap();
    let link = world.link(cross).unwrap();
    assert!(!link.holds, "the box moved 2 m away: past the link's tolerance");
    assert_near(link.start, CROSS_START, "the start stays on the ledge");
    assert_near(link.end, CROSS_END_AWAY, "the end moved with the box");
    let listed = world.links(ledge).unwrap();
    assert_eq!(listed.iter().map(|l| (l.id, l.landing(), l.holds)).collect::<Vec<_>>(), vec![(cross, Some(deck), false)]);
    assert_near(listed[0].end, CROSS_END_AWAY, "the listed end");

    world.set_mesh_transform(deck_box, &DECK_HOME).unwrap();
    let link = world.link(cross).unwrap();
    assert!(link.holds, "the box is back");
    assert_near(link.end, CROSS_END, "the end is back");

    // A link within one navmesh: no landing navmesh, always holds, tolerance 0.
    let within = LinkDef { start: [-5.0, 0.0, 0.0], end: [-1.0, 0.0, 0.0], ..default_link_def() };
    let plain = world.link(world.add_link(ledge, &within).unwrap()).unwrap();
    assert_eq!((plain.landing(), plain.landing_navmesh, plain.holds, plain.tolerance), (None, NavmeshId::default(), true, 0.0));

    // Cross links are one-way, lead to another live navmesh, and links files do not hold them.
    assert_fails(world.add_link(ledge, &LinkDef { bidirectional: true, ..def }), status::INVALID_ARGUMENT, "bidirectional");
    assert_fails(world.add_link(ledge, &def.with_landing(Some(ledge))), status::INVALID_ARGUMENT, "landing_navmesh");
    let gone = world.add_navmesh(&quad(&DECK_QUAD)).unwrap();
    world.remove_navmesh(gone).unwrap();
    assert_fails(world.add_link(ledge, &def.with_landing(Some(gone))), status::INVALID_HANDLE, "landing_navmesh");
    assert_fails(world.add_link(ledge, &LinkDef { tolerance: -1.0, ..def }), status::INVALID_ARGUMENT, "tolerance");
    assert_eq!(world.links(ledge).unwrap().len(), 2, "nothing refused was added");
    assert_fails(world.save_links_json(ledge), status::INVALID_ARGUMENT, "cross link");
}

/// Generated cross links (tests/core/world/surface_tests.cpp's ferry): a static 6 x 6 m ledge (box x in [0, 6], z in
/// [0, 6], top y = 0) whose navmesh is its top eroded 0.3 m, and a 4 x 4 m movable box (top y = 0 in its own
/// space, centred on its origin) carrying its top eroded 0.3 m as a navmesh, placed 1 m off the ledge's edge
/// (centre x = 9, z = 3), then 3 m off (x = 11). Both navmeshes for radius 0.3; jumps up to 2 m across.
const LEDGE_TOP: [f32; 12] = [0.3, 0.0, 0.3, 0.3, 0.0, 5.7, 5.7, 0.0, 5.7, 5.7, 0.0, 0.3];
const PLATFORM_TOP: [f32; 12] = [-1.7, 0.0, -1.7, -1.7, 0.0, 1.7, 1.7, 0.0, 1.7, 1.7, 0.0, -1.7];

/// The platform's transform: its centre at (x, 0, 3) (column-major).
fn platform_at(x: f32) -> [f32; 16] {
    [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, x, 0.0, 3.0, 1.0]
}

#[test]
fn cross_links_generated_for_where_a_platform_stands() {
    let world = World::new().unwrap();
    add_box(&world, [0.0, -1.0, 0.0], [6.0, 0.0, 6.0]);
    let at_9 = MeshOptions { flags: MeshFlags::MOVABLE, transform: Some(platform_at(9.0)), ..Default::default() };
    let platform = add_box_with(&world, [-2.0, -0.5, -2.0], [2.0, 0.0, 2.0], &at_9);
    let agent_type = AgentType { radius: 0.3, ..default_agent_type() };
    let ledge = world.add_navmesh(&NavmeshInput { agent_type, ..quad(&LEDGE_TOP) }).unwrap();
    let deck = world.add_navmesh(&NavmeshInput { agent_type, carrier: Some(platform), ..quad(&PLATFORM_TOP) }).unwrap();
    let settings = LinkSettings { max_jump_gap: 2.0, ..default_link_settings() };
    let crossing = |navmesh: NavmeshId, landing: NavmeshId| -> Vec<Link> {
        world.links(navmesh).unwrap().into_iter().filter(|l| l.landing() == Some(landing)).collect()
    };
    let ids = |links: &[Link]| links.iter().map(|l| l.id).collect::<Vec<_>>();

    let mut last_fraction = -1.0;
    let mut progress = |fraction: f32, _stage: &str| {
        last_fraction = fraction;
        true
    };
    let report = world.generate_cross_links(ledge, deck, 0.25, Some(&settings), Some(&mut progress)).unwrap();
    assert_eq!(last_fraction, 1.0, "progress reported to the end");
    let (onto, off) = (crossing(ledge, deck), crossing(deck, ledge));
    assert!(report.jump_links > 0, "{:?}", report);
    assert!(!onto.is_empty(), "links from the ledge onto the platform");
    assert!(!off.is_empty(), "links from the platform onto the ledge");
    assert_eq!((report.jump_links + report.drop_links) as usize, onto.len() + off.len(), "the report counts them");
    let all = world.links(ledge).unwrap().len() + world.links(deck).unwrap().len();
    assert_eq!(all, onto.len() + off.len(), "no links within either navmesh");
    for l in onto.iter().chain(&off) {
        assert_eq!((l.generated, l.holds, l.bidirectional, l.tolerance), (true, true, false, 0.25), "{:?}", l);
        assert_ne!(l.end_polygon, NO_POLYGON);
    }
    // In the world: from the ledge's rim (x 5.7) to the platform's (x 7.3), and back.
    for l in &onto {
        assert!(l.start[0] > 5.5 && l.start[0] < 6.0 && l.end[0] > 7.0 && l.end[0] < 7.5, "{:?} {:?}", l.start, l.end);
    }
    for l in &off {
        assert!(l.start[0] > 7.0 && l.start[0] < 7.5 && l.end[0] > 5.5 && l.end[0] < 6.0, "{:?} {:?}", l.start, l.end);
    }

    // 3 m off the ledge: nothing holds; beyond a 2 m jump nothing is found, and the links made 1 m off stay.
    world.set_mesh_transform(platform, &platform_at(11.0)).unwrap();
    assert!(crossing(ledge, deck).iter().chain(&crossing(deck, ledge)).all(|l| !l.holds), "none holds 3 m off");
    let report = world.generate_cross_links(ledge, deck, 0.25, Some(&settings), None).unwrap();
    assert_eq!((report.jump_links, report.drop_links), (0, 0));
    assert_eq!(ids(&crossing(ledge, deck)), ids(&onto), "kept for when it is back");
    assert_eq!(ids(&crossing(deck, ledge)), ids(&off));

    // Back 1 m off: they hold again, and generating there again replaces them (not doubled).
    world.set_mesh_transform(platform, &platform_at(9.0)).unwrap();
    assert!(crossing(ledge, deck).iter().chain(&crossing(deck, ledge)).all(|l| l.holds));
    world.generate_cross_links(ledge, deck, 0.25, Some(&settings), None).unwrap();
    assert_eq!((crossing(ledge, deck).len(), crossing(deck, ledge).len()), (onto.len(), off.len()));

    // Refused: the same navmesh twice, a bad tolerance, another body, a stale navmesh; a cancel changes nothing.
    assert_fails(
        world.generate_cross_links(ledge, ledge, 0.25, Some(&settings), None),
        status::INVALID_ARGUMENT,
        "nl_navmesh_generate_cross_links",
    );
    assert_fails(world.generate_cross_links(ledge, deck, -1.0, Some(&settings), None), status::INVALID_ARGUMENT, "tolerance");
    let wide = world.add_navmesh(&quad(&PLATFORM_TOP)).unwrap(); // the default radius, 0.6
    assert_fails(world.generate_cross_links(ledge, wide, 0.25, Some(&settings), None), status::INVALID_ARGUMENT, "bodies");
    world.remove_navmesh(wide).unwrap();
    assert_fails(world.generate_cross_links(ledge, wide, 0.25, Some(&settings), None), status::INVALID_HANDLE, "second");
    let before = ids(&world.links(ledge).unwrap());
    assert_fails(
        world.generate_cross_links(ledge, deck, 0.25, Some(&settings), Some(&mut |_, _| false)),
        status::CANCELLED,
        "",
    );
    assert_eq!(ids(&world.links(ledge).unwrap()), before);
}
