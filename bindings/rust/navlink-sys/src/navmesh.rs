//! navlink.h: "Navmeshes" and "Building navmeshes".
use crate::level::nl_mesh_id;
use crate::output_init;
use crate::status::nl_status;
use crate::world::nl_world;
use std::os::raw::{c_char, c_void};

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_navmesh_id {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_navmesh_id, "NavmeshId");

pub const NL_MAX_POLYGON_VERTICES: usize = 16;
pub const NL_NO_POLYGON: u32 = 0xffff_ffff;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_agent_type {
    pub radius: f32,
    pub height: f32,
    pub max_climb: f32,
    pub max_slope: f32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_navmesh_def {
    pub size: u32,
    pub vertices: *const f32,
    pub vertex_count: u32,
    pub vertex_stride: u32,
    pub indices: *const u32,
    pub polygon_vertex_counts: *const u8,
    pub polygon_count: u32,
    pub areas: *const u8,
    pub weld_tolerance: f32,
    pub agent: nl_agent_type,
    pub detail_vertices: *const f32,
    pub detail_vertex_count: u32,
    pub detail_triangles: *const u32,
    pub detail_triangle_count: u32,
    pub detail_triangle_starts: *const u32,
    /// A movable mesh (`NL_MESH_MOVABLE`) the navmesh rides, or the null id. With one, every coordinate
    /// above is in that mesh's own space and `nl_mesh_set_transform` moves the navmesh. Added in 0.3.
    pub surface: nl_mesh_id,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_navmesh_info {
    pub size: u32,
    pub vertex_count: u32,
    pub polygon_count: u32,
    pub portal_count: u32,
    pub boundary_edge_count: u32,
    pub welded_vertex_count: u32,
    pub flipped_polygon_count: u32,
    pub dropped_polygon_count: u32,
    pub non_manifold_edge_count: u32,
    pub agent: nl_agent_type,
    /// In the world; for a navmesh that rides a moving mesh, a box that holds it where the mesh is now.
    pub bounds_min: [f32; 3],
    pub bounds_max: [f32; 3],
    /// The movable mesh it rides; the null id for none. Added in 0.3.
    pub surface: nl_mesh_id,
    /// Meshes `nl_navmesh_build` built it on that look wound clockwise: turned over, they would hold much
    /// more floor for its agent than as given (the build also logs a warning naming them and
    /// `NL_MESH_CLOCKWISE`). 0 for a navmesh added from polygons or loaded from a file. Added in 0.3.
    pub turned_over_mesh_count: u32,
    /// `NL_BUILD_WARNING_*` bits: what `nl_navmesh_build` found wrong with its level (each also said in a
    /// warning in the log). 0 for a navmesh added from polygons or loaded from a file. Added in 0.3.
    pub build_warnings: u32,
}

// `nl_navmesh_info::build_warnings`: a build succeeded on a level that looks given wrong.
/// Meshes look wound clockwise (`turned_over_mesh_count`).
pub const NL_BUILD_WARNING_CLOCKWISE: u32 = 0x1;
/// Meshes that did not say their units (`nl_mesh_def::metres_per_unit` 0) look given in other units than
/// metres: walls more than 25 agents tall, or the whole level narrower than two.
pub const NL_BUILD_WARNING_UNITS: u32 = 0x2;
/// Meshes that did not say their up axis would hold more than 1.5 times the floor for the agent with z up.
pub const NL_BUILD_WARNING_Z_UP: u32 = 0x4;

pub fn nl_navmesh_info_init() -> nl_navmesh_info {
    unsafe { output_init() }
}
default_is_init!(nl_navmesh_info, nl_navmesh_info_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_nav_polygon {
    pub size: u32,
    pub vertex_count: u32,
    pub vertices: [u32; NL_MAX_POLYGON_VERTICES],
    pub neighbours: [u32; NL_MAX_POLYGON_VERTICES],
    pub area: u32,
    pub normal: [f32; 3],
    pub centre: [f32; 3],
}

pub fn nl_nav_polygon_init() -> nl_nav_polygon {
    unsafe { output_init() }
}
default_is_init!(nl_nav_polygon, nl_nav_polygon_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_boundary_edge {
    pub start: [f32; 3],
    pub end: [f32; 3],
    pub outward: [f32; 3],
    pub normal: [f32; 3],
    pub polygon: u32,
    pub edge: u32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_nav_point {
    pub point: [f32; 3],
    pub distance: f32,
    pub polygon: u32,
    pub found: u8,
    /// Why `found` is 0: 1 when the navmesh's nearest point lies beyond the search box; `point` and
    /// `distance` then give that point (`polygon` stays `NL_NO_POLYGON`). 0 when found. Added in 0.3.
    pub beyond_box: u8,
    pub reserved: [u8; 2],
}

/// `nl_progress_fn*` (a navmesh build, a link generation): `fraction` done (0..1, never going back) and the
/// stage's name; return 0 to cancel the call. Called on the thread that made the call.
pub type nl_progress_fn = Option<unsafe extern "C" fn(user: *mut c_void, fraction: f32, stage: *const c_char) -> i32>;

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_navmesh_build_def {
    pub size: u32,
    pub builder: *const c_char,
    pub agent: nl_agent_type,
    pub settings: *const c_void,
    pub settings_json: *const c_char,
    pub settings_json_length: usize,
    /// A movable mesh to build on (alone, in its own space; the navmesh rides it), or the null id: every
    /// static mesh. Added in 0.3.
    pub surface: nl_mesh_id,
    /// Told of the build's progress from its start; returning 0 cancels it (CANCELLED, nothing added).
    /// Added in 0.3.
    pub progress: nl_progress_fn,
    /// Passed back to `progress`; not dereferenced.
    pub progress_user: *mut c_void,
}

extern "C" {
    pub fn nl_default_agent_type() -> nl_agent_type;
    pub fn nl_default_navmesh_def() -> nl_navmesh_def;
    pub fn nl_navmesh_add(world: *mut nl_world, def: *const nl_navmesh_def, out_id: *mut nl_navmesh_id) -> nl_status;
    pub fn nl_navmesh_remove(world: *mut nl_world, navmesh: nl_navmesh_id) -> nl_status;
    pub fn nl_navmesh_is_valid(world: *const nl_world, navmesh: nl_navmesh_id) -> i32;
    pub fn nl_navmesh_get_info(world: *const nl_world, navmesh: nl_navmesh_id, out_info: *mut nl_navmesh_info)
        -> nl_status;
    pub fn nl_navmesh_get_vertices(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        out_xyz: *mut f32,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_navmesh_get_polygon(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        polygon: u32,
        out_polygon: *mut nl_nav_polygon,
    ) -> nl_status;
    pub fn nl_navmesh_get_boundary_edges(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        out_edges: *mut nl_boundary_edge,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_navmesh_find_nearest(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        points: *const f32,
        count: u32,
        half_extents: *const f32,
        out: *mut nl_nav_point,
    ) -> nl_status;
    pub fn nl_world_get_navmeshes(
        world: *const nl_world,
        out_ids: *mut nl_navmesh_id,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_default_navmesh_build_def() -> nl_navmesh_build_def;
    pub fn nl_navmesh_build(world: *mut nl_world, def: *const nl_navmesh_build_def, out_id: *mut nl_navmesh_id)
        -> nl_status;
}
