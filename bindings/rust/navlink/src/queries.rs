//! Queries on a navmesh for one body (navlink.h's section of that name): whether it can get somewhere
//! (reachability), how far it walks in a straight line (raycast), sliding a point along the surface, and
//! random points. Polygons come from `find_nearest`.
use crate::error::{check, Error, Result};
use crate::list::two_call;
use crate::types::{AgentCapabilities, NavPoint, NavmeshId, NavmeshRaycastHit};
use crate::world::World;
use navlink_sys as sys;
use std::ptr;

/// Polygons fetched in one go by `raycast` and `move_along_surface` when a walk crosses no more; longer
/// walks take a second call.
const FIRST_WALK_CAPACITY: usize = 32;

/// The body a query is for (`nl_query_filter`), as a [`PathQuery`](crate::PathQuery) describes it: its
/// capabilities (the links it can take, the room a wider body needs) and its area costs (an area of cost
/// `AREA_EXCLUDED`, 0, is kept out of; other costs do not matter to these queries). `Default` is
/// `nl_default_query_filter()`: a default walker that keeps out of no area.
#[derive(Clone, Debug, PartialEq)]
pub struct QueryFilter {
    pub agent: AgentCapabilities,
    /// Cost per metre in area i (at most 256); empty: no area is excluded.
    pub area_costs: Vec<f32>,
}

impl Default for QueryFilter {
    fn default() -> Self {
        let c = unsafe { sys::nl_default_query_filter() };
        QueryFilter { agent: c.agent, area_costs: Vec::new() }
    }
}

impl QueryFilter {
    /// The body of `agent`, excluding no area.
    pub fn new(agent: AgentCapabilities) -> Self {
        QueryFilter { agent, area_costs: Vec::new() }
    }

    /// The same body with these area costs.
    pub fn with_area_costs(self, area_costs: &[f32]) -> Self {
        QueryFilter { area_costs: area_costs.to_vec(), ..self }
    }

    /// The C struct; borrows `self.area_costs`.
    fn to_c(&self) -> sys::nl_query_filter {
        let mut c = unsafe { sys::nl_default_query_filter() };
        c.agent = self.agent;
        c.area_costs = if self.area_costs.is_empty() { ptr::null() } else { self.area_costs.as_ptr() };
        c.area_cost_count = self.area_costs.len() as u32;
        c
    }
}

/// Which random points `random_points` draws (`nl_random_points_def`). `Default` is
/// `nl_default_random_points_def()`: anywhere on the navmesh, no filter, seed 1.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomPointsOptions {
    /// Points stay out of its excluded areas; with `reachable_from`, the body whose reach counts (`None`:
    /// `QueryFilter::default()`).
    pub filter: Option<QueryFilter>,
    /// With `radius` > 0: points within `radius` of it, seen from above.
    pub centre: [f32; 3],
    /// 0: anywhere on the navmesh.
    pub radius: f32,
    /// Only points the filter's body can reach from this polygon (`None`: any).
    pub reachable_from: Option<u32>,
    /// The same seed, navmesh and options give the same points on every platform and thread count.
    pub seed: u64,
}

impl Default for RandomPointsOptions {
    fn default() -> Self {
        let c = unsafe { sys::nl_default_random_points_def() };
        RandomPointsOptions {
            filter: None,
            centre: c.centre,
            radius: c.radius,
            reachable_from: if c.reachable_from == sys::NL_NO_POLYGON { None } else { Some(c.reachable_from) },
            seed: c.seed,
        }
    }
}

fn buffer_too_small(status: u32) -> bool {
    sys::nl_failed(status) && status & sys::NL_STATUS_BUFFER_TOO_SMALL != 0
}

impl World {
    /// For each pair `(from[i], to[i])` of polygons, whether the filter's body can get from the one to the
    /// other by walking and by the links it can take, exactly as a path request for it would find. Each
    /// answer takes constant time (the navmesh's reachability map for the body's class, built on the first
    /// query). `from` and `to` must have the same length.
    pub fn can_reach(&self, navmesh: NavmeshId, filter: &QueryFilter, from: &[u32], to: &[u32]) -> Result<Vec<bool>> {
        if from.len() != to.len() {
            return Err(Error::binding(
                sys::NL_STATUS_INVALID_ARGUMENT,
                format!("can_reach: {} from-polygons but {} to-polygons", from.len(), to.len()),
            ));
        }
        let c = filter.to_c();
        let mut answers = vec![0u8; from.len()];
        check(unsafe {
            sys::nl_navmesh_can_reach(
                self.raw(),
                navmesh,
                &c,
                from.as_ptr(),
                to.as_ptr(),
                from.len() as u32,
                answers.as_mut_ptr(),
            )
        })?;
        Ok(answers.into_iter().map(|a| a != 0).collect())
    }

    /// Every polygon the filter's body can reach from `from_polygon` (itself included), ascending.
    pub fn reachable_polygons(&self, navmesh: NavmeshId, filter: &QueryFilter, from_polygon: u32) -> Result<Vec<u32>> {
        let c = filter.to_c();
        two_call(|buffer, capacity, count| unsafe {
            sys::nl_navmesh_get_reachable_polygons(self.raw(), navmesh, &c, from_polygon, buffer, capacity, count)
        })
    }

    /// The island of every polygon for the filter's body (one per polygon) and the number of islands.
    /// Polygons of one island reach each other; one-way links may lead from one island to another (ask
    /// `can_reach`). Islands are numbered from 0 in order of their lowest polygon; `NO_ISLAND` for polygons
    /// in excluded areas.
    pub fn islands(&self, navmesh: NavmeshId, filter: &QueryFilter) -> Result<(Vec<u32>, u32)> {
        let c = filter.to_c();
        let mut island_count = 0u32;
        let islands = two_call(|buffer, capacity, count| unsafe {
            sys::nl_navmesh_get_islands(self.raw(), navmesh, &c, buffer, capacity, count, &mut island_count)
        })?;
        Ok((islands, island_count))
    }

    /// Walks in a straight line (seen from above) from `start`, over `start_polygon`, towards `end` along
    /// the navmesh surface, as Detour's raycast: how far a body walks before a wall (the navmesh's outline,
    /// or an area the filter excludes) stops it, and the polygons crossed (the start polygon first, the
    /// hit's `end_polygon` last).
    pub fn raycast(
        &self,
        navmesh: NavmeshId,
        filter: &QueryFilter,
        start_polygon: u32,
        start: [f32; 3],
        end: [f32; 3],
    ) -> Result<(NavmeshRaycastHit, Vec<u32>)> {
        let c = filter.to_c();
        let mut polygons = vec![0u32; FIRST_WALK_CAPACITY];
        loop {
            let mut hit = sys::nl_navmesh_raycast_hit_init();
            let mut count = 0u32;
            let status = unsafe {
                sys::nl_navmesh_raycast(
                    self.raw(),
                    navmesh,
                    &c,
                    start_polygon,
                    start.as_ptr(),
                    end.as_ptr(),
                    &mut hit,
                    polygons.as_mut_ptr(),
                    polygons.len() as u32,
                    &mut count,
                )
            };
            if buffer_too_small(status) && hit.polygon_count as usize > polygons.len() {
                // The hit says how many: walk again with room for them.
                polygons = vec![0u32; hit.polygon_count as usize];
                continue;
            }
            check(status)?;
            polygons.truncate(count as usize);
            return Ok((hit.into(), polygons));
        }
    }

    /// Slides a point from `start` (over `start_polygon`) towards `target` along the navmesh, as Detour's
    /// moveAlongSurface: `target` when the straight way there stays on the navmesh, else the point of the
    /// walls met nearest to it. The point is at the surface height with its polygon, `found`, and its
    /// `distance` short of `target`; the polygons are those visited from the start's to the result's.
    pub fn move_along_surface(
        &self,
        navmesh: NavmeshId,
        filter: &QueryFilter,
        start_polygon: u32,
        start: [f32; 3],
        target: [f32; 3],
    ) -> Result<(NavPoint, Vec<u32>)> {
        let c = filter.to_c();
        let mut visited = vec![0u32; FIRST_WALK_CAPACITY];
        loop {
            let mut moved = sys::nl_nav_point::default();
            let mut count = 0u32;
            let status = unsafe {
                sys::nl_navmesh_move_along_surface(
                    self.raw(),
                    navmesh,
                    &c,
                    start_polygon,
                    start.as_ptr(),
                    target.as_ptr(),
                    &mut moved,
                    visited.as_mut_ptr(),
                    visited.len() as u32,
                    &mut count,
                )
            };
            if buffer_too_small(status) {
                // The call does not say how many it visited, only that they did not fit; a slide visits each
                // polygon at most once, so the navmesh's polygon count is room enough.
                let polygons = self.navmesh_info(navmesh)?.polygon_count as usize;
                visited = vec![0u32; polygons.max(2 * visited.len())];
                continue;
            }
            check(status)?;
            visited.truncate(count as usize);
            return Ok((moved.into(), visited));
        }
    }

    /// Draws up to `count` random points uniformly by surface area over the navmesh polygons `options`
    /// allows: `count` of them, none when no allowed polygon lies in the circle, or fewer when the allowed
    /// part inside it is too thin. Each has its polygon, the surface height, `found`, distance 0.
    pub fn random_points(&self, navmesh: NavmeshId, count: u32, options: &RandomPointsOptions) -> Result<Vec<NavPoint>> {
        let filter = options.filter.as_ref().map(QueryFilter::to_c);
        let mut def = unsafe { sys::nl_default_random_points_def() };
        def.filter = filter.as_ref().map_or(ptr::null(), |f| f as *const sys::nl_query_filter);
        def.centre = options.centre;
        def.radius = options.radius;
        def.reachable_from = options.reachable_from.unwrap_or(sys::NL_NO_POLYGON);
        def.seed = options.seed;
        let mut points = vec![sys::nl_nav_point::default(); count as usize];
        let mut found = 0u32;
        check(unsafe { sys::nl_navmesh_random_points(self.raw(), navmesh, &def, points.as_mut_ptr(), count, &mut found) })?;
        points.truncate(found as usize);
        Ok(points.into_iter().map(NavPoint::from).collect())
    }
}

/// A walker of radius 0.6 that keeps out of no area: `QueryFilter::default()`.
pub fn default_query_filter() -> QueryFilter {
    QueryFilter::default()
}
