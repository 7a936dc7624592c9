//! navlink.h: "Baked navmesh files".
use crate::level::nl_mesh_id;
use crate::navmesh::{nl_agent_type, nl_navmesh_id};
use crate::output_init;
use crate::status::nl_status;
use crate::world::nl_world;
use std::os::raw::{c_char, c_void};

/// Refuse a file baked from other level geometry than the world holds now (see `nl_navmesh_load_def`).
pub const NL_NAVMESH_LOAD_SAME_LEVEL: u32 = 0x1;

/// How to load a navmesh file. Get one from `nl_default_navmesh_load_def()`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct nl_navmesh_load_def {
    pub size: u32,
    /// For a file whose navmesh rode a movable mesh (`nl_navmesh_file_info::rides_surface`): the movable
    /// mesh it rides now. The null id otherwise.
    pub surface: nl_mesh_id,
    /// `NL_NAVMESH_LOAD_SAME_LEVEL`: refuse a file baked from other level geometry. 0: load it whatever the level.
    pub flags: u32,
}

/// What a navmesh file holds and was made for (`nl_navmesh_file_describe`). Its `Default` is zeroed with
/// `size` set, as the caller must set it (the header defines no initialiser for it).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_navmesh_file_info {
    pub size: u32,
    /// The file's format version.
    pub version: u32,
    /// Bytes.
    pub file_size: u64,
    /// The body the navmesh was made for.
    pub agent: nl_agent_type,
    pub vertex_count: u32,
    pub polygon_count: u32,
    /// 0: no height detail.
    pub detail_triangle_count: u32,
    pub link_count: u32,
    /// Of `link_count`, made by link generation.
    pub generated_link_count: u32,
    /// 1: its coordinates are in the space of a movable mesh it rode.
    pub rides_surface: u32,
    /// Metres per step of its fixed-point coordinates (1/1024).
    pub quantum: f32,
    pub reserved: u32,
    /// Of the level triangles it was built from; 0: handed over by the host.
    pub level_hash: u64,
}

impl Default for nl_navmesh_file_info {
    /// Zeroed, with `size` set.
    fn default() -> Self {
        unsafe { output_init() }
    }
}

extern "C" {
    pub fn nl_navmesh_save(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        buffer: *mut c_void,
        capacity: usize,
        out_size: *mut usize,
    ) -> nl_status;
    pub fn nl_navmesh_save_file(world: *const nl_world, navmesh: nl_navmesh_id, path: *const c_char) -> nl_status;
    pub fn nl_default_navmesh_load_def() -> nl_navmesh_load_def;
    pub fn nl_navmesh_load(
        world: *mut nl_world,
        data: *const c_void,
        size: usize,
        def: *const nl_navmesh_load_def,
        out_id: *mut nl_navmesh_id,
    ) -> nl_status;
    pub fn nl_navmesh_load_file(
        world: *mut nl_world,
        path: *const c_char,
        def: *const nl_navmesh_load_def,
        out_id: *mut nl_navmesh_id,
    ) -> nl_status;
    pub fn nl_navmesh_file_describe(
        data: *const c_void,
        size: usize,
        out_info: *mut nl_navmesh_file_info,
        made_for_json: *mut c_char,
        capacity: usize,
        out_length: *mut usize,
    ) -> nl_status;
}
