//! navlink/recast.h: the built-in Recast builder's settings.

pub const NL_RECAST_PARTITION_WATERSHED: u32 = 0;
pub const NL_RECAST_PARTITION_MONOTONE: u32 = 1;
pub const NL_RECAST_PARTITION_LAYERS: u32 = 2;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_recast_settings {
    pub size: u32,
    pub cell_size: f32,
    pub cell_height: f32,
    pub region_min_size: f32,
    pub region_merge_size: f32,
    pub edge_max_length: f32,
    pub edge_max_error: f32,
    pub vertices_per_polygon: u32,
    pub detail_sample_distance: f32,
    pub detail_sample_max_error: f32,
    pub partition: u32,
    pub filter_low_hanging_obstacles: u8,
    pub filter_ledge_spans: u8,
    pub filter_walkable_low_height_spans: u8,
    pub reserved: u8,
}

extern "C" {
    pub fn nl_default_recast_settings() -> nl_recast_settings;
}
