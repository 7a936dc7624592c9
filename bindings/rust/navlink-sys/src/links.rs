//! navlink.h: "Links".
use crate::navmesh::{nl_navmesh_id, nl_progress_fn};
use crate::output_init;
use crate::status::nl_status;
use crate::world::nl_world;
use std::os::raw::{c_char, c_void};

#[repr(C)]
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct nl_link_id {
    pub index1: u32,
    pub generation: u32,
}
id_debug!(nl_link_id, "LinkId");

pub type nl_link_kind = u32;
pub const NL_LINK_JUMP: nl_link_kind = 1;
pub const NL_LINK_DROP: nl_link_kind = 2;
pub const NL_LINK_MANUAL: nl_link_kind = 3;
pub const NL_LINK_FIRST_PLUGIN_KIND: nl_link_kind = 256;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_link_requirements {
    pub gap: f32,
    pub rise: f32,
    pub drop: f32,
    pub clearance_width: f32,
    pub abilities: u64,
    pub length: f32,
    pub reserved: u32,
}

/// An array element that may grow: the library lays out an output array with the first element's `size`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_link {
    pub size: u32,
    pub kind: nl_link_kind,
    pub id: nl_link_id,
    pub navmesh: nl_navmesh_id,
    pub start: [f32; 3],
    pub end: [f32; 3],
    pub apex: [f32; 3],
    pub bidirectional: u8,
    pub generated: u8,
    pub enabled: u8,
    pub reserved: u8,
    pub cost_modifier: f32,
    pub start_polygon: u32,
    pub end_polygon: u32,
    pub reserved2: u32,
    pub user_data: u64,
    pub requirements: nl_link_requirements,
    /// For a link to another navmesh (a cross link), the navmesh its end is on (`end_polygon` is one of
    /// its polygons); the null id for a link within `navmesh`. Added in 0.3.
    pub landing_navmesh: nl_navmesh_id,
    /// A cross link's: how far its end may move, seen from its start, before it stops holding; 0 for
    /// other links.
    pub tolerance: f32,
    /// 1 if the link can be taken as the navmeshes stand now: always for a link within one navmesh; for a
    /// cross link, while its end is within `tolerance` of where it was, seen from its start.
    pub holds: u8,
    pub reserved3: [u8; 3],
}

pub fn nl_link_init() -> nl_link {
    unsafe { output_init() }
}
default_is_init!(nl_link, nl_link_init);

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_link_def {
    pub size: u32,
    pub kind: nl_link_kind,
    pub start: [f32; 3],
    pub end: [f32; 3],
    pub bidirectional: u8,
    pub enabled: u8,
    /// 0 (default): `requirements`' gap, length, rise and drop are measured from the ends; 1: all of
    /// `requirements` as given.
    pub requirements_as_given: u8,
    pub reserved: u8,
    pub cost_modifier: f32,
    pub user_data: u64,
    pub requirements: nl_link_requirements,
    /// The null id (default): both ends on the link's navmesh. Another navmesh: a cross link from the
    /// link's navmesh to that one, `end` on it. Both ends are given in the world as the navmeshes stand
    /// now; the link holds while the end, seen from the start, stays within `tolerance` of where it is
    /// now. Cross links are one-way and are not saved in links files. Added in 0.3.
    pub landing_navmesh: nl_navmesh_id,
    /// Of a cross link, metres; 0.25 by default; >= 0.
    pub tolerance: f32,
    pub reserved2: u32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_link_settings {
    pub size: u32,
    pub min_edge_length: f32,
    pub min_group_size: u32,
    pub max_group_size: u32,
    pub sample_spacing: f32,
    pub falloff_distance: f32,
    pub max_jump_gap: f32,
    pub min_link_distance: f32,
    pub short_link_distance: f32,
    pub max_jump_up: f32,
    pub jump_arc_height: f32,
    pub strict_forward_angle: f32,
    pub permissive_forward_angle: f32,
    pub strict_incline_angle: f32,
    pub permissive_incline_angle: f32,
    pub max_drop_distance: f32,
    pub drop_angles: [f32; 16],
    pub drop_angle_count: u32,
    pub drop_steepness: f32,
    pub merge_distance: f32,
    pub clearance_margin: f32,
    pub arc_segments: u32,
    pub plugin_settings_json: *const c_char,
    pub plugin_settings_json_length: usize,
    pub walk_factor: f32,
    pub walk_distance: f32,
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_link_generation_report {
    pub size: u32,
    pub edges: u32,
    pub groups: u32,
    pub samples: u32,
    pub takeoff_points: u32,
    pub jump_candidates: u32,
    pub drop_candidates: u32,
    pub jump_links: u32,
    pub drop_links: u32,
    pub plugin_links: u32,
    pub rejected_wall: u32,
    pub rejected_not_ledge: u32,
    pub rejected_distance: u32,
    pub rejected_rise: u32,
    pub rejected_angle: u32,
    pub rejected_no_landing: u32,
    pub rejected_clearance: u32,
    pub rejected_duplicate: u32,
    pub rays_cast: u64,
    pub milliseconds_edges: f64,
    pub milliseconds_takeoff: f64,
    pub milliseconds_jumps: f64,
    pub milliseconds_drops: f64,
    pub milliseconds_merge: f64,
    pub milliseconds_total: f64,
    pub box_queries: u64,
    pub body_tests: u64,
    pub rejected_walkable: u32,
    pub rejected_too_shallow: u32,
    pub rejected_too_deep: u32,
    pub reserved: u32,
}

pub fn nl_link_generation_report_init() -> nl_link_generation_report {
    unsafe { output_init() }
}
default_is_init!(nl_link_generation_report, nl_link_generation_report_init);

/// Load links generated for another body than the navmesh's (see `nl_navmesh_load_links_json`).
pub const NL_LINKS_LOAD_ANY_BODY: u32 = 0x1;

extern "C" {
    pub fn nl_default_link_def() -> nl_link_def;
    pub fn nl_link_add(
        world: *mut nl_world,
        navmesh: nl_navmesh_id,
        def: *const nl_link_def,
        out_id: *mut nl_link_id,
    ) -> nl_status;
    pub fn nl_link_update(world: *mut nl_world, link: nl_link_id, def: *const nl_link_def) -> nl_status;
    pub fn nl_link_remove(world: *mut nl_world, link: nl_link_id) -> nl_status;
    pub fn nl_link_is_valid(world: *const nl_world, link: nl_link_id) -> i32;
    pub fn nl_link_get(world: *const nl_world, link: nl_link_id, out_link: *mut nl_link) -> nl_status;
    pub fn nl_navmesh_get_links(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        out_links: *mut nl_link,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_navmesh_remove_generated_links(world: *mut nl_world, navmesh: nl_navmesh_id, out_removed: *mut u32)
        -> nl_status;
    pub fn nl_default_link_settings() -> nl_link_settings;
    pub fn nl_link_settings_from_json(json: *const c_char, length: usize, settings: *mut nl_link_settings)
        -> nl_status;
    pub fn nl_navmesh_generate_links(
        world: *mut nl_world,
        navmesh: nl_navmesh_id,
        settings: *const nl_link_settings,
        progress: nl_progress_fn,
        user: *mut c_void,
        out_report: *mut nl_link_generation_report,
    ) -> nl_status;
    pub fn nl_navmesh_generate_cross_links(
        world: *mut nl_world,
        first: nl_navmesh_id,
        second: nl_navmesh_id,
        tolerance: f32,
        settings: *const nl_link_settings,
        progress: nl_progress_fn,
        user: *mut c_void,
        out_report: *mut nl_link_generation_report,
    ) -> nl_status;
    pub fn nl_navmesh_update_links_in_box(
        world: *mut nl_world,
        navmesh: nl_navmesh_id,
        box_min: *const f32,
        box_max: *const f32,
        progress: nl_progress_fn,
        user: *mut c_void,
        out_report: *mut nl_link_generation_report,
    ) -> nl_status;
    pub fn nl_navmesh_save_links_json(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        buffer: *mut c_char,
        capacity: usize,
        out_length: *mut usize,
    ) -> nl_status;
    pub fn nl_navmesh_load_links_json(
        world: *mut nl_world,
        navmesh: nl_navmesh_id,
        json: *const c_char,
        length: usize,
        flags: u32,
        out_count: *mut u32,
    ) -> nl_status;
}
