//! Queries on a navmesh for one body (navlink.h's section of that name): whether it can get somewhere
//! (reachability), how far it walks in a straight line (raycast), sliding a point along the surface, and
//! random points. Polygons come from `find_nearest`.
use crate::error::{check, Error, Result};
use crate::list::two_call;
use crate::types::{AgentCapabilities, NavPoint, NavmeshId, NavmeshRay, NavmeshRaycastHit};
use crate::world::World;
use navlink_sys as sys;
use std::ptr;

/// Polygons fetched per walk in one go by the raycasts and `move_along_surface` when a walk crosses no more;
/// longer walks take a second call with room for them all.
const FIRST_WALK_CAPACITY: usize = 32;

/// The body a query is for (`nl_query_filter`), as a [`PathQuery`](crate::PathQuery) describes it: its
/// capabilities (the links it can take, the room a wider body needs) and its area costs (an area of cost
/// `AREA_EXCLUDED`, 0, is kept out of; other costs do not matter to these queries). `Default` is
/// `nl_default_query_filter()`: a default walker that keeps out of no area.
#[derive(Clone, Debug, PartialEq)]
pub struct QueryFilter {
    pub capabilities: AgentCapabilities,
    /// Cost per metre in area i (at most 256); empty: no area is excluded.
    pub area_costs: Vec<f32>,
}

impl Default for QueryFilter {
    fn default() -> Self {
        let c = unsafe { sys::nl_default_query_filter() };
        QueryFilter { capabilities: c.capabilities, area_costs: Vec::new() }
    }
}

impl QueryFilter {
    /// The body of `capabilities`, excluding no area.
    pub fn new(capabilities: AgentCapabilities) -> Self {
        QueryFilter { capabilities, area_costs: Vec::new() }
    }

    /// The same body with these area costs.
    pub fn with_area_costs(self, area_costs: &[f32]) -> Self {
        QueryFilter { area_costs: area_costs.to_vec(), ..self }
    }

    /// The C struct; borrows `self.area_costs`.
    fn to_c(&self) -> sys::nl_query_filter {
        let mut c = unsafe { sys::nl_default_query_filter() };
        c.capabilities = self.capabilities;
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
    /// The same seed, navmesh and options give the same points on every run and thread count.
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

    /// Walks each ray in a straight line (seen from above) from its `start`, over its `start_polygon`, towards
    /// its `end` along the navmesh surface, as Detour's raycast: how far a body walks before a wall (the
    /// navmesh's outline, or an area the filter excludes) stops it. One hit per ray (its `polygon_count`
    /// counts the polygons crossed); the navmesh is looked up once and large batches run over the world's
    /// workers. A ray the library refuses (its start not over its polygon...) fails the whole batch, naming
    /// its index.
    pub fn raycast_batch(&self, navmesh: NavmeshId, filter: &QueryFilter, rays: &[NavmeshRay]) -> Result<Vec<NavmeshRaycastHit>> {
        let hits = self.raycast_c(navmesh, &filter.to_c(), rays, &mut [], 0)?;
        Ok(hits.into_iter().map(NavmeshRaycastHit::from).collect())
    }

    /// `raycast_batch` with the polygons each ray crossed (its start polygon first, the hit's `end_polygon`
    /// last). Room for 32 per ray is asked first; the rays that crossed more are walked again, together,
    /// with room for the most any of them crossed.
    pub fn raycast_batch_with_polygons(
        &self,
        navmesh: NavmeshId,
        filter: &QueryFilter,
        rays: &[NavmeshRay],
    ) -> Result<Vec<(NavmeshRaycastHit, Vec<u32>)>> {
        let c = filter.to_c();
        let mut buffer = vec![0u32; rays.len() * FIRST_WALK_CAPACITY];
        let hits = self.raycast_c(navmesh, &c, rays, &mut buffer, FIRST_WALK_CAPACITY)?;
        let mut walks: Vec<(sys::nl_navmesh_raycast_hit, Vec<u32>)> = Vec::with_capacity(rays.len());
        let mut longer: Vec<usize> = Vec::new();
        for (i, hit) in hits.into_iter().enumerate() {
            let count = hit.polygon_count as usize;
            if count > FIRST_WALK_CAPACITY {
                longer.push(i);
                walks.push((hit, Vec::new()));
            } else {
                walks.push((hit, buffer[i * FIRST_WALK_CAPACITY..i * FIRST_WALK_CAPACITY + count].to_vec()));
            }
        }
        while !longer.is_empty() {
            // The hits say how many: walk those rays again with room for the most of them.
            let again: Vec<NavmeshRay> = longer.iter().map(|&i| rays[i]).collect();
            let room = longer.iter().map(|&i| walks[i].0.polygon_count as usize).max().unwrap_or(0);
            let mut buffer = vec![0u32; again.len() * room];
            let hits = self.raycast_c(navmesh, &c, &again, &mut buffer, room)?;
            let mut still = Vec::new();
            for (k, hit) in hits.into_iter().enumerate() {
                let (i, count) = (longer[k], hit.polygon_count as usize);
                walks[i].0 = hit;
                if count > room {
                    still.push(i); // cannot happen on a navmesh that never changes; asked again all the same
                } else {
                    walks[i].1 = buffer[k * room..k * room + count].to_vec();
                }
            }
            longer = still;
        }
        Ok(walks.into_iter().map(|(hit, polygons)| (hit.into(), polygons)).collect())
    }

    /// Walks in a straight line (seen from above) from `start`, over `start_polygon`, towards `end` along
    /// the navmesh surface, as Detour's raycast: how far a body walks before a wall (the navmesh's outline,
    /// or an area the filter excludes) stops it, and the polygons crossed (the start polygon first, the
    /// hit's `end_polygon` last). A batch of one ray (`raycast_batch_with_polygons`): room for 32 polygons,
    /// and a second walk with room for the hit's `polygon_count` when it crossed more.
    pub fn raycast(
        &self,
        navmesh: NavmeshId,
        filter: &QueryFilter,
        start_polygon: u32,
        start: [f32; 3],
        end: [f32; 3],
    ) -> Result<(NavmeshRaycastHit, Vec<u32>)> {
        let ray = NavmeshRay { start, start_polygon, end };
        let mut walks = self.raycast_batch_with_polygons(navmesh, filter, &[ray])?;
        Ok(walks.remove(0))
    }

    /// `nl_navmesh_raycast`: one hit per ray, ray i's first `per_ray` polygons in `polygons[i * per_ray..]`.
    fn raycast_c(
        &self,
        navmesh: NavmeshId,
        filter: &sys::nl_query_filter,
        rays: &[NavmeshRay],
        polygons: &mut [u32],
        per_ray: usize,
    ) -> Result<Vec<sys::nl_navmesh_raycast_hit>> {
        assert!(polygons.len() >= rays.len() * per_ray, "room for per_ray polygons per ray");
        let count = u32::try_from(rays.len())
            .map_err(|_| Error::binding(sys::NL_STATUS_INVALID_ARGUMENT, format!("raycast: {} rays", rays.len())))?;
        let per_ray = u32::try_from(per_ray)
            .map_err(|_| Error::binding(sys::NL_STATUS_INVALID_ARGUMENT, format!("raycast: room for {} polygons", per_ray)))?;
        // nl_navmesh_raycast_hit_init() sets the element size the library writes with.
        let mut hits = vec![sys::nl_navmesh_raycast_hit_init(); rays.len()];
        let out_polygons = if per_ray == 0 { ptr::null_mut() } else { polygons.as_mut_ptr() };
        check(unsafe {
            sys::nl_navmesh_raycast(self.raw(), navmesh, filter, rays.as_ptr(), count, hits.as_mut_ptr(), out_polygons, per_ray)
        })?;
        Ok(hits)
    }

    /// Slides a point from `start` (over `start_polygon`) towards `target` along the navmesh, as Detour's
    /// moveAlongSurface: `target` when the straight way there stays on the navmesh, else the point of the
    /// walls met nearest to it. The point is at the surface height with its polygon, `found`, and its
    /// `distance` short of `target`; the polygons are those visited from the start's to the result's (room
    /// for 32 first; when more were visited, the call says how many and is made again with that room).
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
            if buffer_too_small(status) && count as usize > visited.len() {
                // `count` is how many it visited: slide again with that room.
                visited = vec![0u32; count as usize];
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
