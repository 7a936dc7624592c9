//! navlink.h: "Level geometry" and "Ray queries".
use crate::output_init;
use crate::status::nl_status;
use crate::world::nl_world;
use std::os::raw::c_char;

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_mesh_id {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_mesh_id, "MeshId");

pub const NL_MESH_MOVABLE: u32 = 0x0000_0001;
/// Its fronts are wound clockwise: the triangles are turned over when registered.
pub const NL_MESH_CLOCKWISE: u32 = 0x0000_0002;
/// In navmesh builds it only blocks: none of its triangles is walked on.
pub const NL_MESH_OBSTACLE: u32 = 0x0000_0004;
/// Left out of navmesh builds; rays, link checks and agents still meet it. Not with `NL_MESH_OBSTACLE`.
pub const NL_MESH_NOT_IN_NAVMESH: u32 = 0x0000_0008;
/// The highest `nl_mesh_def::area`. The Recast builder carries areas 0..62.
pub const NL_MESH_MAX_AREA: u32 = 254;

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_mesh_def {
    pub size: u32,
    pub vertices: *const f32,
    pub vertex_count: u32,
    pub vertex_stride: u32,
    pub indices: *const u32,
    pub triangle_count: u32,
    pub flags: u32,
    pub transform: *const f32,
    pub user_data: u64,
    /// The area navmesh builds give the polygons over this mesh (0..=`NL_MESH_MAX_AREA`). Added in 0.3.
    pub area: u32,
    /// Must be 0.
    pub reserved: u32,
    /// The length of one unit of `vertices` in metres: 0.01 for centimetres (Unreal's, many exporters'),
    /// 0.0254 for inches, 1 for metres; 1e-6..1e6. 0 (the default) means metres, not said: a navmesh build
    /// then warns when the level's size against its agent's suggests other units (`NL_BUILD_WARNING_UNITS`);
    /// 1 says metres and silences it. The vertices are scaled when registered, before `transform`: the
    /// transform, as every other position and length in this API, is in metres. Added in 0.3.
    pub metres_per_unit: f32,
    /// `NL_UP_AXIS_*`: which axis of `vertices` points up. Vertices with z up (Blender's, Unreal's, 3ds Max's
    /// own frame) are turned to NavLink's y up when registered, before `transform`: (x, y, z) becomes
    /// (x, z, -y), a rotation, so fronts stay fronts. Added in 0.3.
    pub up_axis: u32,
}

// `nl_mesh_def::up_axis`. NavLink's own frame is right-handed with y up.
/// The default: y up, and a navmesh build warns when the level would hold much more floor with z up
/// (`NL_BUILD_WARNING_Z_UP`).
pub const NL_UP_AXIS_NOT_SAID: u32 = 0;
/// Y up, said: no such warning.
pub const NL_UP_AXIS_Y: u32 = 1;
/// Z up: turned to y up when registered.
pub const NL_UP_AXIS_Z: u32 = 2;

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_mesh_info {
    pub size: u32,
    pub vertex_count: u32,
    pub triangle_count: u32,
    pub degenerate_triangle_count: u32,
    pub flags: u32,
    pub transform: [f32; 16],
    pub bounds_min: [f32; 3],
    pub bounds_max: [f32; 3],
    pub user_data: u64,
    /// As given in `nl_mesh_def` (0.3).
    pub area: u32,
    pub reserved: u32,
    /// As given in `nl_mesh_def` (0 = not said) (0.3).
    pub metres_per_unit: f32,
    /// As given in `nl_mesh_def`, `NL_UP_AXIS_*` (0.3).
    pub up_axis: u32,
}

pub fn nl_mesh_info_init() -> nl_mesh_info {
    unsafe { output_init() }
}
default_is_init!(nl_mesh_info, nl_mesh_info_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_ray {
    pub origin: [f32; 3],
    pub direction: [f32; 3],
    pub max_distance: f32,
}

/// An array element that may grow: the library lays out an output array with the first element's `size`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_ray_hit {
    pub size: u32,
    pub distance: f32,
    pub point: [f32; 3],
    pub normal: [f32; 3],
    pub mesh: nl_mesh_id,
    pub triangle: u32,
    pub hit: u8,
    pub reserved: [u8; 3],
}

pub fn nl_ray_hit_init() -> nl_ray_hit {
    unsafe { output_init() }
}
default_is_init!(nl_ray_hit, nl_ray_hit_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_segment {
    pub from: [f32; 3],
    pub to: [f32; 3],
}

extern "C" {
    pub fn nl_default_mesh_def() -> nl_mesh_def;
    pub fn nl_mesh_add(world: *mut nl_world, def: *const nl_mesh_def, out_id: *mut nl_mesh_id) -> nl_status;
    pub fn nl_mesh_add_obj_file(
        world: *mut nl_world,
        path: *const c_char,
        def: *const nl_mesh_def,
        out_id: *mut nl_mesh_id,
    ) -> nl_status;
    pub fn nl_mesh_add_obj_memory(
        world: *mut nl_world,
        data: *const c_char,
        length: usize,
        def: *const nl_mesh_def,
        out_id: *mut nl_mesh_id,
    ) -> nl_status;
    pub fn nl_mesh_remove(world: *mut nl_world, mesh: nl_mesh_id) -> nl_status;
    pub fn nl_mesh_set_transform(world: *mut nl_world, mesh: nl_mesh_id, transform: *const f32) -> nl_status;
    pub fn nl_mesh_is_valid(world: *const nl_world, mesh: nl_mesh_id) -> i32;
    pub fn nl_mesh_get_info(world: *const nl_world, mesh: nl_mesh_id, out_info: *mut nl_mesh_info) -> nl_status;
    pub fn nl_world_get_meshes(
        world: *const nl_world,
        out_ids: *mut nl_mesh_id,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_world_cast_rays(world: *mut nl_world, rays: *const nl_ray, count: u32, out_hits: *mut nl_ray_hit)
        -> nl_status;
    pub fn nl_world_segments_blocked(
        world: *mut nl_world,
        segments: *const nl_segment,
        count: u32,
        out_blocked: *mut u8,
    ) -> nl_status;
}
