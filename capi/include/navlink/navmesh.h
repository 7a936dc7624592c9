/*
 * navlink/navmesh.h: Navmeshes: walkable polygons for one agent type, added by the host or built from the level.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_NAVMESH_H
#define NAVLINK_NAVMESH_H

#include "navlink/level.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Navmeshes: walkable polygons for one agent type. A world holds several (one per agent type),
 * handed over by the host (its engine's navmesh) or built from the level by a builder plugin.
 * A navmesh never changes once added: replace it by adding a new one and removing the old.
 * ------------------------------------------------------------------------------------------- */

/** Most corners a navmesh polygon may have. */
#define NL_MAX_POLYGON_VERTICES 16

/** No polygon: a boundary edge's neighbour, a point that found no polygon. */
#define NL_NO_POLYGON 0xffffffffu

/** The body a navmesh is made for. */
typedef struct nl_agent_type {
    float radius;    /**< Metres the navmesh keeps from walls (0.6 by default). */
    float height;    /**< Headroom needed, metres (2.0). */
    float max_climb; /**< Highest step walked up without a link, metres (0.9). */
    float max_slope; /**< Steepest walkable slope, degrees (45). Recast also refuses a step
                          between neighbouring cells higher than max_climb, so a slope can be
                          unwalkable below max_slope when its cells rise faster than that. */
} nl_agent_type;

/** Recast's usual agent: radius 0.6, height 2.0, climb 0.9, slope 45. Thread-safe; never fails. */
NL_API nl_agent_type nl_default_agent_type(void);

/** A navmesh handed over by the host. Get one from nl_default_navmesh_def(). */
typedef struct nl_navmesh_def {
    uint32_t size;                        /**< sizeof(nl_navmesh_def); set by nl_default_navmesh_def(). */
    const float* vertices;                /**< x y z per vertex, world space; borrowed. */
    uint32_t vertex_count;
    uint32_t vertex_stride;               /**< Bytes between vertices; 0 means 12. */
    const uint32_t* indices;              /**< Polygon corners, polygon after polygon; borrowed. */
    const uint8_t* polygon_vertex_counts; /**< Corners of each polygon (3..NL_MAX_POLYGON_VERTICES);
                                               NULL means every polygon is a triangle. Borrowed. */
    uint32_t polygon_count;
    const uint8_t* areas;                 /**< Optional area id per polygon; NULL means area 0. Borrowed. */
    float weld_tolerance;                 /**< Vertices closer than this (metres, 0..1) become one, so
                                               polygons that only touch (Unity repeats vertices per
                                               triangle) are connected, and a vertex this near an
                                               edge of another polygon's outline, between its ends,
                                               becomes a corner of it (a T-junction, as at tile
                                               borders: the polygons then connect). Default 0.001
                                               (at least the 1/1024 m grid's rounding is allowed);
                                               0 welds exact duplicates only and joins nothing. */
    nl_agent_type agent_type;             /**< The agent type this navmesh was made for. */
    /* Optional height detail, as Recast's detail mesh: triangles over each polygon that follow the
       surface more closely than the polygon does, used for point location. All NULL/0 means the
       polygons are the surface. (Recast's, like Detour's, sit up to two cell heights above the
       floor: voxel tops are rounded up.) */
    const float* detail_vertices;         /**< x y z per detail vertex; borrowed. */
    uint32_t detail_vertex_count;
    const uint32_t* detail_triangles;     /**< 3 indices into detail_vertices per triangle; borrowed. */
    uint32_t detail_triangle_count;
    const uint32_t* detail_triangle_starts; /**< polygon_count + 1 offsets: polygon p's detail triangles
                                                 are [starts[p], starts[p + 1]); starts[polygon_count]
                                                 must equal detail_triangle_count. Borrowed. As Detour
                                                 keeps it, a detail vertex over one of its polygon's
                                                 corners (the same x and z) is that corner, at the
                                                 corner's height; a polygon may have at most 239 detail
                                                 vertices besides its corners, and 512 detail triangles. */
    nl_mesh_id carrier;                   /**< The navmesh's carrier: a movable mesh (NL_MESH_MOVABLE)
                                               it rides, or the null id. With one, every coordinate above
                                               is in that mesh's own space, and the navmesh follows
                                               the mesh: nl_mesh_set_transform moves it (no rebuild).
                                               Added in 0.3. */
    /* A tile of a tiled navmesh (tile_width > 0): one square of a grid on the x-z plane, tile
       (tile_x, tile_z) spanning x in [tile_origin_x + tile_x * tile_width, ... + tile_width] and z
       alike. A builder hands a tiled navmesh tile by tile (nl_navmesh_builder.build); the host joins
       them along the lines between tiles: corners two tiles share on a line (the same x and z) become
       one within the agent's max_climb in height, and the edges there are joined as T-junctions. Added
       in 0.3. */
    float tile_width;                     /**< Metres; 0 (default): not a tile. */
    float tile_origin_x;                  /**< x of tile (0, 0)'s lower corner. */
    float tile_origin_z;                  /**< z of tile (0, 0)'s lower corner. */
    int32_t tile_x;                       /**< The tile's column. */
    int32_t tile_z;                       /**< The tile's row. */
} nl_navmesh_def;

/** A def with no geometry, weld tolerance 0.001 and the default agent type. Thread-safe. */
NL_API nl_navmesh_def nl_default_navmesh_def(void);

/** Adds a navmesh from the host's polygons; everything is copied. The polygons are cleaned up as a
 *  host's navmesh usually needs: coincident vertices are welded (weld_tolerance); polygons wound
 *  clockwise seen from above are turned over so that every normal points up; polygons that welding
 *  collapses or that have no area are dropped; edges that meet others at T-junctions get their corners;
 *  an edge shared by three or more polygons connects none of them. nl_navmesh_get_info counts each
 *  repair. Adjacency (portals) and boundary edges are built.
 *  Returns SUCCESS, or a failure with INVALID_ARGUMENT (null pointer, zero counts, a coordinate not
 *  finite or beyond NL_COORDINATE_LIMIT, an index out of range, a polygon with fewer than 3 or more
 *  than NL_MAX_POLYGON_VERTICES corners, a polygon not convex seen from above (navmesh polygons are
 *  2.5D: convex in x-z, heights free, as Recast's), a negative or NaN
 *  tolerance or agent field, bad detail data, every polygon degenerate: the item is named and nothing
 *  is added), OUT_OF_MEMORY. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] def  The polygons to add.
 *  @param[out] out_id  Receives the navmesh's id. */
NL_API nl_status nl_navmesh_add(nl_world* world, const nl_navmesh_def* def, nl_navmesh_id* out_id);

/** Removes a navmesh and its links, and the cross links of other navmeshes that land on it.
 *  Queries already running on it finish on their own copy.
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh to remove. */
NL_API nl_status nl_navmesh_remove(nl_world* world, nl_navmesh_id navmesh);

/** Nonzero if `navmesh` is a navmesh of `world`. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The id to check. */
NL_API int32_t nl_navmesh_is_valid(const nl_world* world, nl_navmesh_id navmesh);

/** Sizes of a navmesh and what was repaired when it was added. */
typedef struct nl_navmesh_info {
    uint32_t size;                     /**< Set by the caller to sizeof(nl_navmesh_info). */
    uint32_t vertex_count;             /**< After welding. */
    uint32_t polygon_count;            /**< Polygons kept. */
    uint32_t portal_count;             /**< Edges shared by exactly two polygons. */
    uint32_t boundary_edge_count;      /**< Edges owned by exactly one polygon. */
    uint32_t welded_vertex_count;      /**< Input vertices merged into another. */
    uint32_t flipped_polygon_count;    /**< Polygons turned over to face up. */
    uint32_t dropped_polygon_count;    /**< Degenerate polygons dropped. */
    uint32_t non_manifold_edge_count;  /**< Edges shared by three or more polygons (connect none). */
    nl_agent_type agent_type;
    float bounds_min[3];               /**< In the world; for a navmesh that rides a moving mesh, a
                                            box that holds it where the mesh is now. */
    float bounds_max[3];
    nl_mesh_id carrier;                /**< The movable mesh it rides; the null id for none. Added in 0.3. */
    uint32_t turned_over_mesh_count;   /**< Meshes nl_navmesh_build built it on that look wound
                                            clockwise: turned over, they would hold much more floor
                                            for its agent than as given (the build also logs a
                                            warning naming them and NL_MESH_CLOCKWISE; see
                                            nl_mesh_def's winding rule). 0 for a navmesh added from
                                            polygons or loaded from a file. Added in 0.3. */
    uint32_t build_warnings;           /**< NL_BUILD_WARNING_* bits: what nl_navmesh_build found wrong
                                            with its level (each also said in a warning in the log).
                                            0 for a navmesh added from polygons or loaded from a
                                            file. Added in 0.3. */
    uint32_t t_junction_corner_count;  /**< Corners inserted where a polygon's edge met the edges of
                                            others at T-junctions (a tile border, Unity's exported
                                            triangulation), so that they connect: each vertex within
                                            weld_tolerance of another polygon's outline edge, strictly
                                            between its ends, joins that edge. Added in 0.3. */
    uint32_t unjoined_t_junction_count; /**< Such edges left as walls: their polygon would have had
                                             more than NL_MAX_POLYGON_VERTICES corners. Added in 0.3. */
    uint32_t tile_count;               /**< Tiles it was joined from (nl_navmesh_def.tile_width); 0 for a
                                            solo navmesh. Added in 0.3. */
    float tile_width;                  /**< Their side, metres; 0 for a solo navmesh. Added in 0.3. */
    float tile_origin[2];              /**< x and z of tile (0, 0)'s lower corner. Added in 0.3. */
} nl_navmesh_info;

/** nl_navmesh_info.build_warnings: a build succeeded on a level that looks given wrong. */
#define NL_BUILD_WARNING_CLOCKWISE 0x1u /**< Meshes look wound clockwise (turned_over_mesh_count). */
#define NL_BUILD_WARNING_UNITS 0x2u     /**< Meshes that did not say their units (nl_mesh_def.
                                             metres_per_unit 0) look given in other units than
                                             metres: walls more than 25 agents tall, or the whole
                                             level narrower than two. */
#define NL_BUILD_WARNING_Z_UP 0x4u      /**< Meshes that did not say their up axis would hold more
                                             than 1.5 times the floor for the agent with z up. */

NL_DEFINE_OUTPUT_INIT(nl_navmesh_info, nl_navmesh_info_init)

/** Fills `*out_info` (caller-owned; set its `size` first). Returns SUCCESS, INVALID_HANDLE or
 *  INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out] out_info  Receives its sizes and repairs. */
NL_API nl_status nl_navmesh_get_info(const nl_world* world, nl_navmesh_id navmesh, nl_navmesh_info* out_info);

/** Copies the navmesh's vertices (x y z each, after welding) into `out_xyz` (caller-owned, room for
 *  `capacity` vertices, i.e. 3 * capacity floats), with the two-call pattern of nl_world_get_meshes.
 *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL, INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] out_xyz  Receives x y z per vertex, or NULL to count only.
 *  @param[in] capacity  Vertices `out_xyz` has room for.
 *  @param[out] out_count  Receives the number of vertices. */
NL_API nl_status nl_navmesh_get_vertices(const nl_world* world, nl_navmesh_id navmesh, float* out_xyz,
                                         uint32_t capacity, uint32_t* out_count);

/** One polygon: corners counter-clockwise seen from above, and the neighbour across each edge. May
 *  grow: set `size` (nl_nav_polygon_init). */
typedef struct nl_nav_polygon {
    uint32_t size;                                /**< sizeof(nl_nav_polygon) as the host knows it. */
    uint32_t vertex_count;
    uint32_t vertices[NL_MAX_POLYGON_VERTICES];   /**< Indices into the navmesh's vertices. */
    uint32_t neighbours[NL_MAX_POLYGON_VERTICES]; /**< Polygon across edge i (corner i to i + 1), or
                                                       NL_NO_POLYGON for a boundary or non-manifold edge. */
    uint32_t area;
    float normal[3];                              /**< Unit, pointing up. */
    float centre[3];                              /**< Average of the corners. */
} nl_nav_polygon;

NL_DEFINE_OUTPUT_INIT(nl_nav_polygon, nl_nav_polygon_init)

/** Fills `*out_polygon` (caller-owned, `size` set) with polygon `polygon` (0 .. polygon_count - 1). Polygons keep
 *  the order they were given in, less the dropped ones; a polygon's corners start at its first given
 *  corner (reversed when it was turned over). Entries past vertex_count are 0 (vertices) and
 *  NL_NO_POLYGON (neighbours). Returns SUCCESS, INVALID_HANDLE, or INVALID_ARGUMENT (null pointer,
 *  polygon out of range). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in] polygon  The polygon's index.
 *  @param[out] out_polygon  Receives the polygon. */
NL_API nl_status nl_navmesh_get_polygon(const nl_world* world, nl_navmesh_id navmesh, uint32_t polygon,
                                        nl_nav_polygon* out_polygon);

/** An edge of the navmesh's outline: owned by exactly one polygon. Jump and drop links start here. */
typedef struct nl_boundary_edge {
    float start[3];   /**< Corners in the polygon's counter-clockwise order. */
    float end[3];
    float outward[3]; /**< Unit, in the polygon's plane, perpendicular to the edge, away from the polygon. */
    float normal[3];  /**< The polygon's unit surface normal. */
    uint32_t polygon;
    uint32_t edge;    /**< The polygon's edge index: from corner `edge` to corner `edge + 1`. */
} nl_boundary_edge;

/** Copies the boundary edges into `out_edges` (caller-owned, `capacity` entries), with the two-call
 *  pattern of nl_world_get_meshes. Returns SUCCESS, or a failure with BUFFER_TOO_SMALL, INVALID_HANDLE
 *  or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] out_edges  Receives the edges, or NULL to count only.
 *  @param[in] capacity  Entries `out_edges` has room for.
 *  @param[out] out_count  Receives the number of boundary edges. */
NL_API nl_status nl_navmesh_get_boundary_edges(const nl_world* world, nl_navmesh_id navmesh,
                                               nl_boundary_edge* out_edges, uint32_t capacity,
                                               uint32_t* out_count);

/** Where a point lies on a navmesh. */
typedef struct nl_nav_point {
    float point[3];   /**< The navmesh point for the query: straight below or above it when it is
                           over a polygon (at the surface's detail height when given), else the
                           nearest point of a polygon's outline. */
    float distance;   /**< From the query point to `point`, metres. */
    uint32_t polygon; /**< The polygon holding `point`, or NL_NO_POLYGON when none was in the box. */
    uint8_t found;    /**< 1 if a polygon was found within the search box, else 0. */
    uint8_t beyond_box; /**< Why found is 0: 1 when the navmesh's nearest point lies beyond the search
                             box; `point` and `distance` then give that point (polygon stays
                             NL_NO_POLYGON), so a host can say how far off the query was or widen
                             its box. 0 when found. Added in 0.3. */
    uint8_t reserved[2];
} nl_nav_point;

/** For each of `count` points (x y z each in `points`, borrowed), finds its navmesh point among the
 *  polygons that overlap the box `point +- half_extents` (3 floats, each > 0) and writes it to `out`
 *  (caller-owned, `count` entries). As Detour's findNearestPoly, a polygon straight below or above
 *  the point within the navmesh agent's max_climb wins (an agent standing there is on that floor,
 *  even when the rim of a ledge beside it is nearer); otherwise the closest point wins. Ties go to
 *  the lower polygon index, so the answer never depends on thread count. count == 0 succeeds.
 *  Returns SUCCESS (points not found have found = 0, beyond_box = 1 and the navmesh's nearest point
 *  beyond the box: a miss costs a second search, from the navmesh's bounds out to that point, up to
 *  the whole navmesh), or a failure with INVALID_HANDLE or
 *  INVALID_ARGUMENT (null pointer, a point not finite or beyond NL_COORDINATE_LIMIT: its index is
 *  named; half_extents not positive and finite). Thread-safe; parallel over the world's workers.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in] points  x y z per point, `count` points.
 *  @param[in] count  The number of points.
 *  @param[in] half_extents  The search box's half size, 3 floats.
 *  @param[out] out  Receives each point's navmesh point. */
NL_API nl_status nl_navmesh_find_nearest(const nl_world* world, nl_navmesh_id navmesh, const float* points,
                                         uint32_t count, const float* half_extents, nl_nav_point* out);

/** Lists the world's navmeshes into `out_ids` (two-call pattern as nl_world_get_meshes).
 *  @param[in] world  The world.
 *  @param[out,opt] out_ids  Receives the ids, or NULL to count only.
 *  @param[in] capacity  Entries `out_ids` has room for.
 *  @param[out] out_count  Receives the number of navmeshes. */
NL_API nl_status nl_world_get_navmeshes(const nl_world* world, nl_navmesh_id* out_ids, uint32_t capacity,
                                        uint32_t* out_count);

/* ---------------------------------------------------------------------------------------------
 * Building navmeshes from the level with a navmesh-builder plugin (the Recast builder is built in).
 * ------------------------------------------------------------------------------------------- */

/** Progress of a long call (a navmesh build, a link generation): `fraction` done (0..1, never going
 *  back) and the stage's name (borrowed for the call). Return 0 to cancel the call; it then fails
 *  with CANCELLED and changes nothing. Called on the thread that made the call. */
typedef int32_t nl_progress_fn(void* user, float fraction, const char* stage);

/** A tile's place in its grid: tile (x, z) spans x in [origin_x + x * tile_width, + tile_width] and z
 *  alike (nl_navmesh_info.tile_origin, tile_width). Added in 0.3. */
typedef struct nl_tile_coord {
    int32_t x;
    int32_t z;
} nl_tile_coord;

/** How to build a navmesh. Get one from nl_default_navmesh_build_def(). */
typedef struct nl_navmesh_build_def {
    uint32_t size;              /**< sizeof(nl_navmesh_build_def). */
    const char* builder;        /**< Name of a navmesh-builder plugin, NUL-terminated; NULL = "recast". */
    nl_agent_type agent_type;   /**< The agent type to build for. */
    const void* settings;       /**< Optional builder-specific settings struct starting with
                                     `uint32_t size` (nl_recast_settings for "recast"); borrowed. */
    const char* settings_json;  /**< Optional settings as a JSON object (UTF-8, `settings_json_length`
                                     bytes), applied over `settings` or the defaults; borrowed. NULL
                                     means none (length must then be 0); an empty string is not a
                                     JSON object (PARSE_ERROR). */
    size_t settings_json_length;
    nl_mesh_id carrier;         /**< A movable mesh to build on, or the null id. With one, the builder
                                     sees that mesh alone, in its own space, and the navmesh rides it
                                     (as nl_navmesh_def.carrier). Without one, it sees every static
                                     mesh (movable meshes are left out: a navmesh over one would stay
                                     behind when it moves). Added in 0.3. */
    nl_progress_fn* progress;   /**< Optional: told of the build's progress from its start (the
                                     builder reports its stages; Recast's rasterisation in steps),
                                     and can cancel it. Added in 0.3. */
    void* progress_user;        /**< Passed back to `progress`; not dereferenced. */
    /* Which tiles: set by nl_navmesh_build_tiles for the builder (a host leaves them 0 for
       nl_navmesh_build, which builds every tile of a tiled build, and nl_navmesh_build_tiles refuse
       any other value with INVALID_ARGUMENT). With tile_columns and tile_rows > 0,
       a builder builds only the tiles (x, z), first_tile.x <= x < first_tile.x + tile_columns and z
       alike with tile_rows, of the grid of tile_width from (tile_origin_x, tile_origin_z), hands over
       those that have polygons (none is a success), and fails with INVALID_ARGUMENT when its settings
       make tiles of another width. Added in 0.3. */
    float tile_origin_x;
    float tile_origin_z;
    float tile_width;
    nl_tile_coord first_tile;
    uint32_t tile_columns;
    uint32_t tile_rows;
} nl_navmesh_build_def;

/** Builder "recast", default agent type, default settings. Thread-safe; never fails. */
NL_API nl_navmesh_build_def nl_default_navmesh_build_def(void);

/** Builds a navmesh from every static mesh registered in the world (under their current transforms;
 *  or, with def->carrier, from that movable mesh in its own space) but those flagged
 *  NL_MESH_NOT_IN_NAVMESH, walking on none of an NL_MESH_OBSTACLE mesh's triangles and giving each
 *  mesh's polygons its area, and adds it as nl_navmesh_add would. A mesh that looks wound clockwise
 *  (turned over, it would hold more than twice the floor for the agent) does not fail the build: it
 *  is named in a warning in the log and counted in nl_navmesh_info.turned_over_mesh_count (docs/c-api.md,
 *  "Winding"). Returns SUCCESS, or a failure with
 *  NOT_FOUND (no builder of that name,
 *  or no walkable surface in the level), CANCELLED (def->progress returned 0: nothing is added),
 *  INVALID_ARGUMENT (bad agent or settings, the field named;
 *  settings JSON nested deeper than 64 levels; for "recast", a level with more walkable cells than
 *  Recast indexes at that cell_size, which is named), PARSE_ERROR (malformed settings JSON),
 *  OUT_OF_MEMORY, INTERNAL_ERROR (the builder failed).
 *  A builder's output that nl_navmesh_add would refuse is INTERNAL_ERROR (a builder bug), with
 *  the reason; nothing is added unless the builder succeeds.
 *  Thread-safe; long-running (a flat 650k-triangle level: about 0.2 s; it grows with the walkable
 *  area and the cell size more than with the triangles): give def->progress to show it and cancel.
 *  @param[in] world  The world.
 *  @param[in] def  How to build it.
 *  @param[out] out_id  Receives the navmesh's id. */
NL_API nl_status nl_navmesh_build(nl_world* world, const nl_navmesh_build_def* def, nl_navmesh_id* out_id);

/* Tiles. A tiled navmesh (built with nl_recast_settings.tile_size, or added from a tile: an
   nl_navmesh_def with tile_width > 0) is joined from square tiles of one grid; tiles come and go at run
   time, each change one step for everything else: path requests already running finish on the navmesh
   they started on; an agent standing on a removed tile waits (NL_AGENT_EVENT_WAITING, reason
   NL_AGENT_REASON_TILE_UNLOADED) until a tile holds it again, and every agent whose path touches a
   changed tile plans again (REPLANNED, reason WORLD_CHANGED; the others keep their paths); a link with an end on a removed tile is out of
   every path until the tile is back. Tiles join the same whatever the order they come in. A change
   joins every loaded tile again (its cost grows with the navmesh, not the tile: docs/tiles.md); on a
   navmesh paths were asked for, it also builds the new navmesh's path graph before returning, so the
   next nl_path_request does not.
   Links across tiles: a tile owns the generated links that start on its polygons, wherever they end
   (any tile within link reach, not only a neighbour). Once links were generated on a tiled navmesh
   (nl_navmesh_generate_links), a tile added or built has its links, and those of the tiles within link
   reach of it, generated again over the tiles loaded then, and no others; a tile removed takes its
   own generated links with it; a tile from a tile's file (nl_navmesh_add_tile_bytes) brings its
   links. So a link exists exactly while the tiles of both its ends are loaded, whatever the order they
   came in (docs/tiles.md, "Links across tiles"). Added in 0.3. */

/** Adds a tile to a tiled navmesh: `def` is a tile (tile_width > 0) of the navmesh's grid, made for its
 *  agent type, with def->carrier the navmesh's carrier (the null id for one that rides none); its
 *  polygons are copied. The navmesh is joined again with it (nl_navmesh_def's tile fields say how).
 *  Returns SUCCESS, or a failure with INVALID_ARGUMENT (its polygons or agent type, as nl_navmesh_add;
 *  a navmesh that is not tiled; a def that is not a tile, or on another grid, or for another agent
 *  type, or with another carrier; a tile already loaded at its place: remove it first; nothing
 *  changed), INVALID_HANDLE (the navmesh; def->carrier), OUT_OF_MEMORY. Thread-safe; waits for a link generation of the navmesh running meanwhile. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] def  The tile. */
NL_API nl_status nl_navmesh_add_tile(nl_world* world, nl_navmesh_id navmesh, const nl_navmesh_def* def);

/** Removes the tile at `tile` from a tiled navmesh, with the generated links it owns. Returns SUCCESS, or a failure with NOT_FOUND (no
 *  tile loaded there: removed twice), INVALID_ARGUMENT (a navmesh that is not tiled; its last tile:
 *  remove the navmesh instead), INVALID_HANDLE, OUT_OF_MEMORY; nothing changed on a failure.
 *  Thread-safe; waits for a link generation of the navmesh running meanwhile. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] tile  The tile to remove. */
NL_API nl_status nl_navmesh_remove_tile(nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile);

/** Builds the tiles of a tiled navmesh's grid whose squares overlap the box [box_min, box_max] seen
 *  from above, from the level as it is now, with the builder and settings of `def` (whose tiles must
 *  have the navmesh's width: the same tile_size and cell_size as it was built with), and puts them in
 *  the navmesh as one step (as nl_navmesh_add_tile): a tile loaded there is replaced, one that comes out
 *  with no walkable surface is removed, the others are added. What a streaming host calls for the tiles
 *  around a player, and an editor after changing the level there. def->agent_type must be the navmesh's;
 *  def->carrier is ignored (the navmesh's own is built on) and the tile fields must be 0 (the navmesh's
 *  grid is used). Returns SUCCESS, or a
 *  failure with INVALID_ARGUMENT (a navmesh that is not tiled; a box not finite or with min > max, or
 *  of more than 2^22 tiles; another agent type; settings making another tile width; no tile would be
 *  left; def's tile fields not 0), INVALID_HANDLE, CANCELLED (from def->progress), the builder's failures,
 *  OUT_OF_MEMORY;
 *  nothing changed on a failure. Thread-safe; waits for a link generation of the navmesh running
 *  meanwhile. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] def  The builder, its settings and the agent type.
 *  @param[in] box_min  The box's lower corner, x y z (y is not used, but must be finite and within
 *                      NL_COORDINATE_LIMIT as x and z).
 *  @param[in] box_max  The box's upper corner. */
NL_API nl_status nl_navmesh_build_tiles(nl_world* world, nl_navmesh_id navmesh, const nl_navmesh_build_def* def,
                                        const float* box_min, const float* box_max);

/** Copies the coordinates of the loaded tiles, in row order (z, then x), into `out_tiles`
 *  (caller-owned, `capacity` entries), with the two-call pattern of nl_world_get_meshes; a solo navmesh
 *  has none. Returns SUCCESS, or a failure with BUFFER_TOO_SMALL, INVALID_HANDLE or INVALID_ARGUMENT.
 *  Thread-safe. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] out_tiles  Receives the tiles, or NULL to count only.
 *  @param[in] capacity  Entries `out_tiles` has room for.
 *  @param[out] out_count  Receives the number of tiles. */
NL_API nl_status nl_navmesh_get_tiles(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord* out_tiles,
                                      uint32_t capacity, uint32_t* out_count);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_NAVMESH_H */
