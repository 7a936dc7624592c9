//! navlink.h: "Queries on a navmesh for one body": reachability, the navmesh raycast and slide, random points.
use crate::navmesh::{nl_nav_point, nl_navmesh_id};
use crate::output_init;
use crate::paths::nl_agent_capabilities;
use crate::status::nl_status;
use crate::world::nl_world;

/// The body a query is for, as a path request gives it (`area_costs` borrowed during the call; an area of
/// cost `NL_AREA_EXCLUDED` is kept out of). Get one from `nl_default_query_filter()`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_query_filter {
    pub size: u32,
    pub agent: nl_agent_capabilities,
    pub area_costs: *const f32,
    /// At most 256.
    pub area_cost_count: u32,
    pub reserved: u32,
}

/// An island with no number: a polygon in an area the filter excludes.
pub const NL_NO_ISLAND: u32 = 0xffff_ffff;

/// One straight walk for `nl_navmesh_raycast`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct nl_navmesh_ray {
    /// Over `start_polygon` (within 1 mm, seen from above).
    pub start: [f32; 3],
    /// The polygon under `start`, from `nl_navmesh_find_nearest`.
    pub start_polygon: u32,
    /// Anywhere: the walk heads for it, seen from above.
    pub end: [f32; 3],
}

/// How far a straight walk along a navmesh went (`nl_navmesh_raycast`). An array element that may grow:
/// set `size` of the first element of the output array (`nl_navmesh_raycast_hit_init`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct nl_navmesh_raycast_hit {
    pub size: u32,
    /// 1 if a wall (the navmesh's outline, or an excluded area) stopped the walk before `end`; 0 if it arrived.
    pub hit: u8,
    pub reserved: [u8; 3],
    /// The fraction of start -> end walked (seen from above): 1 if it arrived.
    pub t: f32,
    /// Where it stopped (or `end`), at the navmesh surface's height.
    pub point: [f32; 3],
    /// The wall's normal, horizontal and pointing back the way the walk came from; zero if it arrived.
    pub wall_normal: [f32; 3],
    /// The polygon holding `point`.
    pub end_polygon: u32,
    /// Polygons crossed, the start polygon first and `end_polygon` last (all of them, also when
    /// `out_polygons` had room for fewer).
    pub polygon_count: u32,
}

pub fn nl_navmesh_raycast_hit_init() -> nl_navmesh_raycast_hit {
    unsafe { output_init() }
}
default_is_init!(nl_navmesh_raycast_hit, nl_navmesh_raycast_hit_init);

/// Which random points `nl_navmesh_random_points` draws. Get one from `nl_default_random_points_def()`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct nl_random_points_def {
    pub size: u32,
    /// Optional, borrowed: points stay out of its excluded areas.
    pub filter: *const nl_query_filter,
    /// With `radius` > 0: points within `radius` of it, seen from above.
    pub centre: [f32; 3],
    /// 0 (default): anywhere on the navmesh.
    pub radius: f32,
    /// A polygon, or `NL_NO_POLYGON` (default): only points the filter's body can reach from it.
    pub reachable_from: u32,
    pub reserved: u32,
    /// The same seed, navmesh and def give the same points on every run and thread count.
    pub seed: u64,
}

extern "C" {
    pub fn nl_default_query_filter() -> nl_query_filter;
    pub fn nl_navmesh_can_reach(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        filter: *const nl_query_filter,
        from_polygons: *const u32,
        to_polygons: *const u32,
        count: u32,
        out_reachable: *mut u8,
    ) -> nl_status;
    pub fn nl_navmesh_get_reachable_polygons(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        filter: *const nl_query_filter,
        from_polygon: u32,
        out_polygons: *mut u32,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_navmesh_get_islands(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        filter: *const nl_query_filter,
        out_islands: *mut u32,
        capacity: u32,
        out_count: *mut u32,
        out_island_count: *mut u32,
    ) -> nl_status;
    /// `rays`: `count`; `out_hits`: `count`, `out_hits[0].size` set. `out_polygons`: null with
    /// `polygons_per_ray` 0, or `count * polygons_per_ray`: ray i's crossed polygons from
    /// `out_polygons[i * polygons_per_ray]`, at most `polygons_per_ray` of them (its hit's `polygon_count`
    /// is how many it crossed). A refused batch writes nothing.
    pub fn nl_navmesh_raycast(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        filter: *const nl_query_filter,
        rays: *const nl_navmesh_ray,
        count: u32,
        out_hits: *mut nl_navmesh_raycast_hit,
        out_polygons: *mut u32,
        polygons_per_ray: u32,
    ) -> nl_status;
    /// `*out_count` (optional) receives how many polygons it visited, also when fewer fit
    /// (`BUFFER_TOO_SMALL`: the point and the first `capacity` polygons are written).
    pub fn nl_navmesh_move_along_surface(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        filter: *const nl_query_filter,
        start_polygon: u32,
        start: *const f32,
        target: *const f32,
        out_point: *mut nl_nav_point,
        out_polygons: *mut u32,
        capacity: u32,
        out_count: *mut u32,
    ) -> nl_status;
    pub fn nl_default_random_points_def() -> nl_random_points_def;
    pub fn nl_navmesh_random_points(
        world: *const nl_world,
        navmesh: nl_navmesh_id,
        def: *const nl_random_points_def,
        out_points: *mut nl_nav_point,
        count: u32,
        out_found: *mut u32,
    ) -> nl_status;
}
