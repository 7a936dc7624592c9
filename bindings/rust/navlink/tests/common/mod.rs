//! Levels and agents shared by the tests: the same scenario as the C# and Python tests.
#![allow(dead_code)] // each test binary uses a part

use navlink::{
    default_agent_capabilities, default_agent_type, status, AgentCapabilities, Error, MeshId, MeshOptions, NavmeshId, NavmeshInput,
    World, WorldOptions,
};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

const BOX_INDICES: [u32; 36] = [
    0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6,
];

/// A box from (x0, y0, z0) to (x1, y1, z1): corner k takes x from bit 0, y from bit 1, z from bit 2.
pub fn add_box(world: &World, lo: [f32; 3], hi: [f32; 3]) -> MeshId {
    add_box_with(world, lo, hi, &MeshOptions::default())
}

/// `add_box` with flags, a transform or user data.
pub fn add_box_with(world: &World, lo: [f32; 3], hi: [f32; 3], options: &MeshOptions) -> MeshId {
    let mut v = [0f32; 24];
    for k in 0..8 {
        v[3 * k] = if k & 1 != 0 { hi[0] } else { lo[0] };
        v[3 * k + 1] = if k & 2 != 0 { hi[1] } else { lo[1] };
        v[3 * k + 2] = if k & 4 != 0 { hi[2] } else { lo[2] };
    }
    world.add_mesh(&v, &BOX_INDICES, options).expect("a box")
}

/// "gap": two 10 x 10 m platforms (top y = 0, 1 m thick), x in [-11, -1] and [1, 11], z in [-5, 5], 2 m
/// apart over a pit whose floor (y = -20) is beyond any drop. Recast's navmesh stops 0.6-0.9 m short of
/// each rim, so a jump across is 3.2-3.8 m: only an agent that jumps gets across.
pub fn add_gap_level(world: &World) {
    add_box(world, [-11.0, -1.0, -5.0], [-1.0, 0.0, 5.0]);
    add_box(world, [1.0, -1.0, -5.0], [11.0, 0.0, 5.0]);
    add_box(world, [-12.0, -21.0, -6.0], [12.0, -20.0, 6.0]);
}

/// "bridge" (tests/abi/agents_tests.c's level): two 4 x 10 m platforms (tops at y = 0) 2 m apart along x,
/// x in [0, 4] and [6, 10], z in [0, 10], joined by a bridge at z 8-10; the host's navmesh is their tops
/// set in 0.3 m from every rim (five convex polygons, for radius 0.3), its links generated. A walker goes
/// round by the bridge; a jumper jumps the gap.
pub fn add_bridge_level(world: &World) -> NavmeshId {
    add_box(world, [0.0, -1.0, 0.0], [4.0, 0.0, 10.0]);
    add_box(world, [6.0, -1.0, 0.0], [10.0, 0.0, 10.0]);
    add_box(world, [4.0, -1.0, 8.0], [6.0, 0.0, 10.0]);
    let polygons: [&[[f32; 2]]; 5] = [
        &[[0.3, 0.3], [0.3, 8.0], [3.7, 8.0], [3.7, 0.3]],
        &[[0.3, 8.0], [0.3, 9.7], [4.0, 9.7], [4.0, 8.0], [3.7, 8.0]],
        &[[4.0, 8.0], [4.0, 9.7], [6.0, 9.7], [6.0, 8.0]],
        &[[6.0, 8.0], [6.0, 9.7], [9.7, 9.7], [9.7, 8.0], [6.3, 8.0]],
        &[[6.3, 0.3], [6.3, 8.0], [9.7, 8.0], [9.7, 0.3]],
    ];
    let vertices: Vec<f32> = polygons.iter().flat_map(|p| p.iter()).flat_map(|&[x, z]| [x, 0.0, z]).collect();
    let indices: Vec<u32> = (0..vertices.len() as u32 / 3).collect();
    let counts: Vec<u8> = polygons.iter().map(|p| p.len() as u8).collect();
    let input = NavmeshInput {
        polygon_vertex_counts: Some(&counts),
        agent_type: navlink::AgentType { radius: 0.3, ..default_agent_type() },
        ..NavmeshInput::triangles(&vertices, &indices)
    };
    let navmesh = world.add_navmesh(&input).expect("the bridge navmesh");
    world.generate_links(navmesh, None, None, None).expect("its links");
    navmesh
}

pub const WEST: [f32; 3] = [-6.0, 0.0, 0.0];
pub const EAST: [f32; 3] = [6.0, 0.0, 0.0];

/// The default body: no jumps, no drops.
pub fn walker() -> AgentCapabilities {
    default_agent_capabilities()
}

/// Jumps 4.5 m across and 1.5 m up, drops 5 m.
pub fn jumper() -> AgentCapabilities {
    AgentCapabilities { max_jump_distance: 4.5, max_jump_height: 1.5, max_drop_height: 5.0, ..default_agent_capabilities() }
}

pub fn horizontal_distance(a: [f32; 3], b: [f32; 3]) -> f32 {
    ((a[0] - b[0]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The shared levels folder: NAVLINK_LEVELS_DIR, else ../shared/levels beside the source tree.
pub fn levels_dir() -> PathBuf {
    std::env::var_os("NAVLINK_LEVELS_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../../shared/levels"))
}

/// Fan triangles of an OBJ file's faces (n corners: n - 2), counted without the library.
pub fn count_obj_triangles(path: &std::path::Path) -> usize {
    let text = std::fs::read_to_string(path).expect("read the OBJ file");
    text.lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|w| w.first() == Some(&"f"))
        .map(|w| w.len() - 3)
        .sum()
}

/// The error must carry `bit` and a message containing `part`.
pub fn assert_fails<T: std::fmt::Debug>(result: Result<T, Error>, bit: u32, part: &str) {
    let error = result.expect_err("expected a failure");
    assert!(error.has(status::FAILURE) && error.has(bit), "status {:#x} lacks {:#x}: {}", error.status(), bit, error);
    assert!(error.message().contains(part), "message '{}' lacks '{}'", error.message(), part);
}

/// A temporary folder, removed on drop.
pub struct TempDir(pub PathBuf);

impl TempDir {
    /// `name`: unique among the tests of one test binary (they run at once).
    pub fn new(name: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("navlink-rust-{}-{}", name, std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A world whose log callback keeps every message it is given, and those messages.
pub fn world_keeping_log() -> (World, Arc<Mutex<Vec<String>>>) {
    let logged = Arc::new(Mutex::new(Vec::<String>::new()));
    let sink = Arc::clone(&logged);
    let world = World::with_options(WorldOptions {
        log: Some(Box::new(move |_level, _status, message: &str| sink.lock().unwrap().push(message.to_string()))),
        ..Default::default()
    })
    .unwrap();
    (world, logged)
}
