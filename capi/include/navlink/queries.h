/*
 * navlink/queries.h: Queries on a navmesh for one body: reachability, islands, navmesh raycasts, moves along the
 * surface, random points.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_QUERIES_H
#define NAVLINK_QUERIES_H

#include "navlink/paths.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Queries on a navmesh for one body: where it can get to (reachability), how far it walks in a
 * straight line (raycast), sliding a point along the surface, random points (docs/queries.md).
 * ------------------------------------------------------------------------------------------- */

/** The body a query is for, as a path request gives it: its capabilities (the links it can take,
 *  the room a wider body needs) and its area costs (an area of cost NL_AREA_EXCLUDED is kept out
 *  of; other costs do not matter to these queries). Get one from nl_default_query_filter(). */
typedef struct nl_query_filter {
    uint32_t size;                /**< sizeof(nl_query_filter). */
    nl_agent_capabilities capabilities;
    const float* area_costs;      /**< Optional, borrowed during the call: as nl_path_request_def. */
    uint32_t area_cost_count;     /**< At most 256. */
    uint32_t reserved;
} nl_query_filter;

/** A default walker (nl_default_agent_capabilities) that keeps out of no area. Thread-safe. */
NL_API nl_query_filter nl_default_query_filter(void);

/** An island with no number: a polygon in an area the filter excludes. */
#define NL_NO_ISLAND 0xffffffffu

/** For each of `count` pairs, whether the filter's body can get from polygon from_polygons[i] to
 *  polygon to_polygons[i] of the navmesh by walking and by the links it can take, exactly as a path
 *  request for it would find (1) or not (0), into out_reachable[i]. A polygon reaches itself; one in
 *  an excluded area is reached from nowhere else, but a body standing in one walks out of it.
 *  The answers come from the navmesh's reachability map for the body's class (the links it can
 *  take, the portals its width closes, its excluded areas): built on the first query for a class (linear in polygons
 *  and links, plus a closure of up to 8 MiB over the islands links join), kept until the navmesh or
 *  its links change (or until 64 other bodies, or 256 MiB of other maps, were asked for since),
 *  shared by bodies of the same class; each answer then takes constant time, without a search. When
 *  links join more than 8192 islands there is no closure and each answer walks the island graph.
 *  Links to another navmesh are not followed (a map is per navmesh, as a path search is). A path
 *  request with accept_partial 0 uses the body's map when one is built, to return NL_PATH_NO_PATH at
 *  once; a request never builds one first, but one whose search found its goal out of reach leaves it
 *  built.
 *  [in] filter: borrowed; NULL for nl_default_query_filter(). [in] from_polygons, to_polygons:
 *  borrowed, `count` each. [out] out_reachable: caller-owned, `count` bytes. count == 0 succeeds.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh), INVALID_ARGUMENT (a null pointer, a
 *  polygon out of range: its index named, a filter as nl_path_request_def refuses, size too small),
 *  OUT_OF_MEMORY. Thread-safe: any number of queries at once, a map built once.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] filter  The body, or NULL for the default walker.
 *  @param[in] from_polygons  The pairs' start polygons, `count` of them.
 *  @param[in] to_polygons  The pairs' goal polygons, `count` of them.
 *  @param[in] count  The number of pairs.
 *  @param[out] out_reachable  Receives 1 or 0 per pair. */
NL_API nl_status nl_navmesh_can_reach(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                      const uint32_t* from_polygons, const uint32_t* to_polygons, uint32_t count,
                                      uint8_t* out_reachable);

/** Every polygon the filter's body can reach from `from_polygon` (itself included), ascending, into
 *  `out_polygons` (caller-owned, `capacity` entries; NULL with capacity 0 to learn the count;
 *  `*out_count` receives it). Returns SUCCESS, BUFFER_TOO_SMALL (nothing written but the count), or
 *  a failure as nl_navmesh_can_reach. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] filter  The body, or NULL for the default walker.
 *  @param[in] from_polygon  The polygon to start from.
 *  @param[out,opt] out_polygons  Receives the polygons, or NULL to count only.
 *  @param[in] capacity  Entries `out_polygons` has room for.
 *  @param[out] out_count  Receives the number of polygons reached. */
NL_API nl_status nl_navmesh_get_reachable_polygons(const nl_world* world, nl_navmesh_id navmesh,
                                                   const nl_query_filter* filter, uint32_t from_polygon,
                                                   uint32_t* out_polygons, uint32_t capacity, uint32_t* out_count);

/** The island of every polygon for the filter's body, into `out_islands` (caller-owned, one per
 *  polygon, `capacity` entries; NULL with capacity 0 to learn the count; `*out_count` receives the
 *  polygon count): polygons of one island reach each other; from one island the body may reach
 *  another over one-way links (ask nl_navmesh_can_reach). Islands are numbered 0 up in order of
 *  their lowest polygon; NL_NO_ISLAND for polygons in excluded areas. `out_island_count` (optional)
 *  receives the number of islands (also with BUFFER_TOO_SMALL). For drawing, and for a host's own
 *  bookkeeping per body.
 *  Returns SUCCESS, BUFFER_TOO_SMALL, or a failure as nl_navmesh_can_reach. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] filter  The body, or NULL for the default walker.
 *  @param[out,opt] out_islands  Receives each polygon's island, or NULL to count only.
 *  @param[in] capacity  Entries `out_islands` has room for.
 *  @param[out] out_count  Receives the number of polygons.
 *  @param[out,opt] out_island_count  Receives the number of islands, or NULL. */
NL_API nl_status nl_navmesh_get_islands(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                        uint32_t* out_islands, uint32_t capacity, uint32_t* out_count,
                                        uint32_t* out_island_count);

/** One straight walk for nl_navmesh_raycast. */
typedef struct nl_navmesh_ray {
    float start[3];          /**< Over start_polygon (within 1 mm, seen from above). */
    uint32_t start_polygon;  /**< The polygon under start, from nl_navmesh_find_nearest. */
    float end[3];            /**< Anywhere: the walk heads for it, seen from above. */
} nl_navmesh_ray;

/** How far a straight walk along a navmesh went (nl_navmesh_raycast). An array element that may
 *  grow: set `size` of the first element of the output array (nl_navmesh_raycast_hit_init). */
typedef struct nl_navmesh_raycast_hit {
    uint32_t size;           /**< sizeof(nl_navmesh_raycast_hit) as the host knows it; written back. */
    uint8_t hit;             /**< 1 if a wall (the navmesh's outline, or an excluded area) stopped
                                  the walk before `end`; 0 if it arrived. */
    uint8_t reserved[3];
    float t;                 /**< The fraction of start -> end walked (seen from above): 1 if it
                                  arrived. */
    float point[3];          /**< Where it stopped (or `end`), at the navmesh surface's height. */
    float wall_normal[3];    /**< The wall's normal, horizontal and pointing back the way the walk
                                  came from (into the last polygon); zero if it arrived (and for a
                                  walk cut short after crossing more polygons than the navmesh has,
                                  which a navmesh with overlapping polygons alone could make). */
    uint32_t end_polygon;    /**< The polygon holding `point`. */
    uint32_t polygon_count;  /**< Polygons crossed, the start polygon first and end_polygon last
                                  (all of them, also when out_polygons had room for fewer). */
} nl_navmesh_raycast_hit;

NL_DEFINE_OUTPUT_INIT(nl_navmesh_raycast_hit, nl_navmesh_raycast_hit_init)

/** Walks each of `count` rays in a straight line (seen from above) from its start toward its end
 *  along the navmesh surface, as Detour's raycast: how far a body can walk before a wall stops it,
 *  the wall, and the polygons crossed; for line-of-sight checks, charges, corner cutting. The
 *  navmesh's outline and polygons in areas the filter excludes are walls; the navmesh is taken as
 *  built for its agent (a body wider than that is not kept further from walls here; links are not
 *  taken). Batched, as nl_navmesh_find_nearest: the navmesh is looked up once, and large batches run
 *  over the world's workers; the answers do not depend on the thread count.
 *  [in] filter: borrowed, NULL for nl_default_query_filter(). [in] rays: borrowed, `count`.
 *  [out] out_hits: caller-owned, `count` entries, out_hits[0].size set. [out] out_polygons: optional
 *  (NULL with polygons_per_ray 0), caller-owned, count * polygons_per_ray entries: ray i's crossed
 *  polygons from out_polygons[i * polygons_per_ray], at most polygons_per_ray of them (its
 *  polygon_count says how many it crossed). count == 0 succeeds.
 *  A ray's polygon slots past those it crossed are left as they were.
 *  Returns SUCCESS, or a failure with nothing written: INVALID_HANDLE, INVALID_ARGUMENT (a null
 *  pointer, a ray's point not finite or beyond NL_COORDINATE_LIMIT, its start_polygon out of range or
 *  its start not over it: the ray's index named, a filter as nl_navmesh_can_reach refuses,
 *  out_hits[0].size unset); OUT_OF_MEMORY (some rays' hits may be written). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] filter  The body, or NULL for the default walker.
 *  @param[in] rays  The walks, `count` of them.
 *  @param[in] count  The number of walks.
 *  @param[out] out_hits  Receives how far each walk went.
 *  @param[out,opt] out_polygons  Receives the polygons each walk crossed, or NULL.
 *  @param[in] polygons_per_ray  Entries of `out_polygons` per walk. */
NL_API nl_status nl_navmesh_raycast(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                    const nl_navmesh_ray* rays, uint32_t count, nl_navmesh_raycast_hit* out_hits,
                                    uint32_t* out_polygons, uint32_t polygons_per_ray);

/** Slides a point from `start` (over `start_polygon`) towards `target` along the navmesh, as
 *  Detour's moveAlongSurface: the result is `target` when a polygon reached from the start through
 *  portals within the circle through start and target holds it, else the point nearest to `target`
 *  on the walls of those polygons, so a host that steers its own bodies can keep one on the navmesh
 *  each frame. Meant for a frame's step: a long move can round a corner a straight walk could not
 *  (nl_navmesh_raycast says whether the straight way is clear). Walls are as
 *  nl_navmesh_raycast's. [in] filter: borrowed, NULL for nl_default_query_filter(). [in] start,
 *  target: 3 floats each; start must lie over start_polygon (within 1 mm, seen from above).
 *  [out] out_point: its point (at the surface height), polygon and distance to `target` (found is 1).
 *  [out] out_polygons: caller-owned, `capacity` entries, or NULL with capacity 0: the polygons
 *  visited on the way from the start polygon to the result's; `*out_count` (optional) receives how
 *  many it visited, also when fewer fit. Returns SUCCESS, BUFFER_TOO_SMALL (the point is written and
 *  the first `capacity` polygons), or a failure with INVALID_HANDLE, INVALID_ARGUMENT (null pointer, a point
 *  not finite or beyond NL_COORDINATE_LIMIT, start_polygon out of range or start not over it, a
 *  filter as nl_navmesh_can_reach refuses). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] filter  The body, or NULL for the default walker.
 *  @param[in] start_polygon  The polygon under `start`.
 *  @param[in] start  Where the move starts, 3 floats.
 *  @param[in] target  Where it heads, 3 floats.
 *  @param[out] out_point  Receives where it ends.
 *  @param[out,opt] out_polygons  Receives the polygons visited, or NULL.
 *  @param[in] capacity  Entries `out_polygons` has room for.
 *  @param[out,opt] out_count  Receives how many polygons it visited, or NULL. */
NL_API nl_status nl_navmesh_move_along_surface(const nl_world* world, nl_navmesh_id navmesh,
                                               const nl_query_filter* filter, uint32_t start_polygon,
                                               const float* start, const float* target, nl_nav_point* out_point,
                                               uint32_t* out_polygons, uint32_t capacity, uint32_t* out_count);

/** Which random points nl_navmesh_random_points draws. Get one from nl_default_random_points_def(). */
typedef struct nl_random_points_def {
    uint32_t size;                 /**< sizeof(nl_random_points_def). */
    const nl_query_filter* filter; /**< Optional, borrowed: points stay out of its excluded areas. */
    float centre[3];               /**< With radius > 0: points within `radius` of it, seen from above. */
    float radius;                  /**< 0 (default): anywhere on the navmesh. */
    uint32_t reachable_from;       /**< A polygon, or NL_NO_POLYGON (default): only points the
                                        filter's body can reach from it (nl_navmesh_can_reach). */
    uint32_t reserved;
    uint64_t seed;                 /**< The same seed, navmesh and def give the same points on every
                                        run and thread count (NavLink's own generator and clipping,
                                        not the C library's random numbers or cos). */
} nl_random_points_def;

/** Whole navmesh, no filter, seed 1. Thread-safe; never fails. */
NL_API nl_random_points_def nl_default_random_points_def(void);

/** Draws `count` points uniformly by surface area over the navmesh polygons `def` allows (within the
 *  radius of the centre: uniform over the part of the navmesh inside that circle, seen from above,
 *  weighted by the surface's slope) into `out_points` (caller-owned, `count` entries): each with its
 *  polygon, at the surface height, found = 1, distance 0. `*out_found` receives how many were
 *  drawn: `count`, or 0 when no allowed polygon lies in the circle (the rest are left found = 0), or
 *  fewer when the allowed part inside the circle is so thin that 64 tries per point met it too
 *  seldom. Returns SUCCESS, or a failure with INVALID_HANDLE, INVALID_ARGUMENT (null pointer, a
 *  centre or radius not finite or out of range, radius < 0, reachable_from out of range, a filter
 *  as nl_navmesh_can_reach refuses, size too small). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in] def  Which points to draw.
 *  @param[out] out_points  Receives the points, `count` of them.
 *  @param[in] count  The number of points to draw.
 *  @param[out] out_found  Receives how many were drawn. */
NL_API nl_status nl_navmesh_random_points(const nl_world* world, nl_navmesh_id navmesh,
                                          const nl_random_points_def* def, nl_nav_point* out_points, uint32_t count,
                                          uint32_t* out_found);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_QUERIES_H */
