//! navlink.h: "Plugins", and the plugin side of the ABI (navlink/plugin.h).
use crate::level::{nl_ray, nl_ray_hit, nl_segment};
use crate::links::{nl_link_def, nl_link_kind};
use crate::navmesh::{nl_boundary_edge, nl_nav_point, nl_navmesh_build_def, nl_navmesh_def, nl_navmesh_id, nl_navmesh_info};
use crate::output_init;
use crate::status::nl_status;
use crate::world::{nl_log_level, nl_world};
use std::os::raw::{c_char, c_void};

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_plugin_id {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_plugin_id, "PluginId");

pub const NL_PLUGIN_NAVMESH_BUILDER: u32 = 0x1;
pub const NL_PLUGIN_LINK_KIND: u32 = 0x2;

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct nl_plugin_description {
    pub size: u32,
    pub abi_version: u32,
    pub kinds: u32,
    pub builtin: u32,
    pub name: *const c_char,
    pub version: *const c_char,
    pub description: *const c_char,
}

pub fn nl_plugin_description_init() -> nl_plugin_description {
    unsafe { output_init() }
}
default_is_init!(nl_plugin_description, nl_plugin_description_init);

pub const NL_PLUGIN_ABI_VERSION: u32 = 1;
/// `NL_PLUGIN_ENTRY_SYMBOL`, NUL-terminated.
pub const NL_PLUGIN_ENTRY_SYMBOL: &[u8] = b"nl_plugin_entry\0";

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_plugin_host {
    pub size: u32,
    pub abi_version: u32,
    pub context: *mut c_void,
    pub log: Option<unsafe extern "C" fn(context: *mut c_void, level: nl_log_level, message: *const c_char)>,
    pub set_error: Option<unsafe extern "C" fn(context: *mut c_void, message: *const c_char)>,
    pub get_level_triangles: Option<
        unsafe extern "C" fn(
            context: *mut c_void,
            vertices: *mut f32,
            vertex_capacity: u32,
            out_vertex_count: *mut u32,
            indices: *mut u32,
            triangle_capacity: u32,
            out_triangle_count: *mut u32,
        ) -> nl_status,
    >,
    pub navmesh_get_boundary_edges: Option<
        unsafe extern "C" fn(
            context: *mut c_void,
            navmesh: nl_navmesh_id,
            out_edges: *mut nl_boundary_edge,
            capacity: u32,
            out_count: *mut u32,
        ) -> nl_status,
    >,
    pub navmesh_get_info:
        Option<unsafe extern "C" fn(context: *mut c_void, navmesh: nl_navmesh_id, out_info: *mut nl_navmesh_info) -> nl_status>,
    pub navmesh_find_nearest: Option<
        unsafe extern "C" fn(
            context: *mut c_void,
            navmesh: nl_navmesh_id,
            points: *const f32,
            count: u32,
            half_extents: *const f32,
            out: *mut nl_nav_point,
        ) -> nl_status,
    >,
    pub cast_rays: Option<
        unsafe extern "C" fn(context: *mut c_void, rays: *const nl_ray, count: u32, out_hits: *mut nl_ray_hit) -> nl_status,
    >,
    pub segments_blocked: Option<
        unsafe extern "C" fn(
            context: *mut c_void,
            segments: *const nl_segment,
            count: u32,
            out_blocked: *mut u8,
        ) -> nl_status,
    >,
    /// Present when `size` covers it (added in 0.3).
    pub record_build_settings:
        Option<unsafe extern "C" fn(context: *mut c_void, settings_json: *const c_char, length: usize) -> nl_status>,
    /// As `get_level_triangles`, with each triangle's area (`NL_BUILD_AREA_OBSTACLE` for an obstacle's).
    /// Present when `size` covers it (added in 0.3).
    pub get_build_triangles: Option<
        unsafe extern "C" fn(
            context: *mut c_void,
            vertices: *mut f32,
            vertex_capacity: u32,
            out_vertex_count: *mut u32,
            indices: *mut u32,
            areas: *mut u8,
            triangle_capacity: u32,
            out_triangle_count: *mut u32,
        ) -> nl_status,
    >,
    /// CANCELLED when the build's caller asked to stop. Present when `size` covers it (added in 0.3).
    pub report_build_progress:
        Option<unsafe extern "C" fn(context: *mut c_void, fraction: f32, stage: *const c_char) -> nl_status>,
}

/// The area `get_build_triangles` gives an obstacle's triangles.
pub const NL_BUILD_AREA_OBSTACLE: u32 = 255;

/// `nl_navmesh_sink_fn*`.
pub type nl_navmesh_sink_fn =
    Option<unsafe extern "C" fn(sink_context: *mut c_void, navmesh: *const nl_navmesh_def) -> nl_status>;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct nl_navmesh_builder {
    pub build: Option<
        unsafe extern "C" fn(
            plugin_state: *mut c_void,
            host: *const nl_plugin_host,
            def: *const nl_navmesh_build_def,
            sink: nl_navmesh_sink_fn,
            sink_context: *mut c_void,
        ) -> nl_status,
    >,
}

/// `nl_link_sink_fn*`.
pub type nl_link_sink_fn = Option<unsafe extern "C" fn(sink_context: *mut c_void, link: *const nl_link_def) -> nl_status>;

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_link_kind_provider {
    pub kind: nl_link_kind,
    pub kind_name: *const c_char,
    pub generate: Option<
        unsafe extern "C" fn(
            plugin_state: *mut c_void,
            host: *const nl_plugin_host,
            navmesh: nl_navmesh_id,
            settings_json: *const c_char,
            settings_json_length: usize,
            sink: nl_link_sink_fn,
            sink_context: *mut c_void,
        ) -> nl_status,
    >,
}

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_plugin_info {
    pub size: u32,
    pub abi_version: u32,
    pub name: *const c_char,
    pub version: *const c_char,
    pub description: *const c_char,
    pub kinds: u32,
    pub state: *mut c_void,
    pub destroy: Option<unsafe extern "C" fn(state: *mut c_void)>,
    pub navmesh_builder: nl_navmesh_builder,
    pub link_kind: nl_link_kind_provider,
}

/// `nl_plugin_entry_fn*`.
pub type nl_plugin_entry_fn = Option<
    unsafe extern "C" fn(host_abi_version: u32, host: *const nl_plugin_host, out_info: *mut nl_plugin_info) -> nl_status,
>;

extern "C" {
    pub fn nl_plugin_load(world: *mut nl_world, path: *const c_char, out_id: *mut nl_plugin_id) -> nl_status;
    pub fn nl_plugin_get_description(
        world: *const nl_world,
        plugin: nl_plugin_id,
        out_description: *mut nl_plugin_description,
    ) -> nl_status;
    pub fn nl_world_get_plugins(
        world: *const nl_world,
        out_ids: *mut nl_plugin_id,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    /// navlink/plugin.h.
    pub fn nl_plugin_register(world: *mut nl_world, entry: nl_plugin_entry_fn, out_id: *mut nl_plugin_id) -> nl_status;
}
