/*
 * navlink/level.h: Level geometry: the meshes a world queries with rays, and the ray queries.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_LEVEL_H
#define NAVLINK_LEVEL_H

#include "navlink/world.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Level geometry: collision meshes the world queries with rays (held in an Embree scene).
 * ------------------------------------------------------------------------------------------- */

/** Mesh flags.
 *
 *  Winding: a triangle's front is the side from which its corners run counter-clockwise (the right-
 *  hand rule: the front is along (b - a) x (c - a)); navmesh builders walk on fronts that face up
 *  (the Recast builder: within max_slope of +y). Vertices are read as given (x right-handed with
 *  y up, or any other frame: the rule is on the numbers). So:
 *  - OpenGL, glTF, Blender exports, Detour/Recast: counter-clockwise fronts, no flag.
 *  - Godot: clockwise fronts (ArrayMesh), right-handed y up: set NL_MESH_CLOCKWISE.
 *  - Unity: clockwise fronts in its left-handed frame. Passed as Unity has them (x, y, z unchanged),
 *    the numbers already follow the rule: no flag. A host that converts to a right-handed frame by
 *    negating one axis (z = -z) mirrors the winding too: set NL_MESH_CLOCKWISE, or swap two indices.
 *  A transform that mirrors (negative determinant) keeps each triangle's front as it is in the mesh's
 *  own space, as engines draw mirrored objects. When a navmesh build finds no walkable triangle but
 *  would find some with the triangles turned over, its message says so and names this flag. */
#define NL_MESH_MOVABLE 0x00000001u /**< The mesh will move: it is held as an Embree instance, so
                                         nl_mesh_set_transform costs a refit of the top level only.
                                         Without it a transform change re-uploads the vertices. */
#define NL_MESH_CLOCKWISE 0x00000002u      /**< Its fronts are wound clockwise: the triangles are turned
                                                over when registered (nl_mesh_info.flags keeps the flag). */
#define NL_MESH_OBSTACLE 0x00000004u       /**< In navmesh builds it only blocks: none of its triangles
                                                is walked on, whatever its slope (crates, props, walls
                                                the host does not want agents on top of). */
#define NL_MESH_NOT_IN_NAVMESH 0x00000008u /**< Left out of navmesh builds (triggers, foliage, debris):
                                                rays, link checks and agents' bodies still meet it.
                                                Not together with NL_MESH_OBSTACLE. */

/** The highest nl_mesh_def.area. The Recast builder carries areas 0..62 (Recast keeps 6 bits). */
#define NL_MESH_MAX_AREA 254u

/** Describes a triangle mesh to register. Get one from nl_default_mesh_def(). */
typedef struct nl_mesh_def {
    uint32_t size;                 /**< sizeof(nl_mesh_def); set by nl_default_mesh_def(). */
    const float* vertices;         /**< vertex_count positions, x y z floats each; borrowed. */
    uint32_t vertex_count;
    uint32_t vertex_stride;        /**< Bytes from one vertex to the next; 0 means 12 (packed). */
    const uint32_t* indices;       /**< triangle_count * 3 vertex indices; borrowed. */
    uint32_t triangle_count;
    uint32_t flags;                /**< NL_MESH_* flags. */
    const float* transform;        /**< Optional 4x4 affine matrix, 16 floats, column-major
                                        (translation in elements 12, 13, 14); NULL = identity. Borrowed. */
    uint64_t user_data;            /**< Returned by nl_mesh_get_info; never interpreted. */
    uint32_t area;                 /**< The area navmesh builds give the polygons over this mesh's
                                        walkable triangles (default 0), at most NL_MESH_MAX_AREA:
                                        what nl_path_request_def.area_costs prices. Where two
                                        meshes' floors meet within a cell, the higher area wins
                                        (Recast's rule). Added in 0.3. */
    uint32_t reserved;             /**< Must be 0. */
    float metres_per_unit;         /**< The length of one unit of `vertices` in metres: 0.01 for
                                        centimetres (Unreal's, many exporters'), 0.0254 for inches,
                                        1 for metres; 1e-6..1e6. 0 (the default) means metres, not
                                        said: a navmesh build then warns when the level's size
                                        against its agent's suggests other units
                                        (NL_BUILD_WARNING_UNITS); 1 says metres and silences it.
                                        The vertices are scaled when registered, before `transform`:
                                        the transform, as every other position and length in this
                                        API, is in metres. Added in 0.3. */
    uint32_t up_axis;              /**< NL_UP_AXIS_*: which axis of `vertices` points up. Vertices
                                        with z up (Blender's, Unreal's, 3ds Max's own frame) are
                                        turned to NavLink's y up when registered, before `transform`:
                                        (x, y, z) becomes (x, z, -y), a rotation, so fronts stay
                                        fronts. Added in 0.3. */
} nl_mesh_def;

/** nl_mesh_def.up_axis. NavLink's own frame is right-handed with y up. */
#define NL_UP_AXIS_NOT_SAID 0u /**< The default: y up, and a navmesh build warns when the level would
                                    hold much more floor with z up (NL_BUILD_WARNING_Z_UP). */
#define NL_UP_AXIS_Y 1u        /**< Y up, said: no such warning. */
#define NL_UP_AXIS_Z 2u        /**< Z up: turned to y up when registered. */

/** A def with no geometry, identity transform and no flags. Thread-safe; never fails. */
NL_API nl_mesh_def nl_default_mesh_def(void);

/** Registers a triangle mesh. Vertices, indices and transform are copied: the caller's arrays may be
 *  freed when the call returns. Triangles with repeated indices or (almost) zero area are skipped and
 *  counted (nl_mesh_info.degenerate_triangle_count); everything else about the input must be valid or
 *  nothing is registered. `*out_id` receives the id.
 *  Returns SUCCESS, or a failure with INVALID_ARGUMENT (null pointer, zero counts, a stride below 12,
 *  a coordinate not finite or beyond NL_COORDINATE_LIMIT before or after the transform, an index out
 *  of range, a non-affine or singular transform, unknown flags, NL_MESH_OBSTACLE with
 *  NL_MESH_NOT_IN_NAVMESH, an area above NL_MESH_MAX_AREA, reserved not 0, every triangle degenerate),
 *  OUT_OF_MEMORY or INTERNAL_ERROR.
 *  Thread-safe; waits for ray queries in flight on this world to finish.
 *  @param[in] world  The world.
 *  @param[in] def  The mesh to register.
 *  @param[out] out_id  Receives the mesh's id. */
NL_API nl_status nl_mesh_add(nl_world* world, const nl_mesh_def* def, nl_mesh_id* out_id);

/** Loads a Wavefront OBJ file (positions and faces; polygons are fan-triangulated; Y is up; other
 *  statements are ignored; a line ends at \n, \r\n or a lone \r) and registers it as one mesh. `path` is a borrowed NUL-terminated UTF-8
 *  path. `def` is optional (NULL = defaults): its flags, transform, user_data, area, metres_per_unit and up_axis apply; its vertex
 *  and index fields must be empty.
 *  The file is a regular file or a pipe (read until its writer closes it).
 *  Returns SUCCESS, or a failure with INVALID_ARGUMENT, NOT_FOUND (no such file), IO_ERROR (a
 *  directory, a device or a socket, no permission, a read error), PARSE_ERROR (malformed: a number that is not a finite
 *  float, a face index that is 0, past the last vertex (or vt, vn) or not an integer, no faces; the
 *  line is named), OUT_OF_MEMORY or INTERNAL_ERROR.
 *  Thread-safe, as nl_mesh_add.
 *  @param[in] world  The world.
 *  @param[in] path  The OBJ file.
 *  @param[in,opt] def  Flags, transform and the like, or NULL for the defaults.
 *  @param[out] out_id  Receives the mesh's id. */
NL_API nl_status nl_mesh_add_obj_file(nl_world* world, const char* path, const nl_mesh_def* def,
                                      nl_mesh_id* out_id);

/** As nl_mesh_add_obj_file, from `length` bytes of OBJ text in memory (borrowed, not necessarily
 *  NUL-terminated).
 *  @param[in] world  The world.
 *  @param[in] data  The OBJ text, `length` bytes.
 *  @param[in] length  The bytes of `data`.
 *  @param[in,opt] def  Flags, transform and the like, or NULL for the defaults.
 *  @param[out] out_id  Receives the mesh's id. */
NL_API nl_status nl_mesh_add_obj_memory(nl_world* world, const char* data, size_t length,
                                        const nl_mesh_def* def, nl_mesh_id* out_id);

/** Removes a mesh. Returns SUCCESS, or INVALID_HANDLE for a null, stale or another world's id, or
 *  INVALID_ARGUMENT for a mesh a navmesh rides (remove the navmesh first).
 *  Thread-safe; waits for ray queries in flight on this world to finish.
 *  @param[in] world  The world.
 *  @param[in] mesh  The mesh to remove. */
NL_API nl_status nl_mesh_remove(nl_world* world, nl_mesh_id mesh);

/** Moves a mesh: `transform` (16 floats, column-major, affine, invertible; borrowed) replaces the
 *  mesh's transform. Cheap for NL_MESH_MOVABLE meshes; otherwise the vertices are re-uploaded.
 *  The navmeshes that ride the mesh (nl_navmesh_def.carrier) move with it when this returns: no
 *  rebuild and no new snapshot; their point location, paths and link ends answer in the world where
 *  the mesh is now, and agents on them ride along (docs/moving-surfaces.md). Such a mesh takes only
 *  rotations and translations.
 *  Returns SUCCESS, or INVALID_HANDLE, or INVALID_ARGUMENT (null, non-finite, non-affine, singular;
 *  not rigid for a mesh a navmesh rides; nothing moves).
 *  Thread-safe: meant to be called from the host's physics or game thread while path workers plan
 *  and nl_world_step runs elsewhere. A path planned meanwhile uses one pose throughout (the one of
 *  the moment its search starts); an agent step reads each carrier's pose when it reads the agent.
 *  The mesh's own transform (nl_mesh_get_info, ray queries) changes a moment before its navmeshes'
 *  pose: another thread may read the new transform and agents placed at the old pose. To place a
 *  body on the platform, use nl_agent_info.carrier_position with the transform the host set.
 *  Waits for ray queries in flight on this world to finish.
 *  @param[in] world  The world.
 *  @param[in] mesh  The mesh to move.
 *  @param[in] transform  Its new transform, 16 floats. */
NL_API nl_status nl_mesh_set_transform(nl_world* world, nl_mesh_id mesh, const float* transform);

/** Nonzero if `mesh` refers to a mesh registered in `world` and not removed. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] mesh  The id to check. */
NL_API int32_t nl_mesh_is_valid(const nl_world* world, nl_mesh_id mesh);

/** What a registered mesh holds. */
typedef struct nl_mesh_info {
    uint32_t size;                      /**< Set by the caller to sizeof(nl_mesh_info). */
    uint32_t vertex_count;
    uint32_t triangle_count;            /**< Triangles kept (degenerate ones excluded). */
    uint32_t degenerate_triangle_count; /**< Triangles skipped as degenerate. */
    uint32_t flags;
    float transform[16];                /**< Column-major. */
    float bounds_min[3];                /**< World-space bounds under the current transform. */
    float bounds_max[3];
    uint64_t user_data;
    uint32_t area;                      /**< As given in nl_mesh_def (0.3). */
    uint32_t reserved;
    float metres_per_unit;              /**< As given in nl_mesh_def (0 = not said) (0.3). */
    uint32_t up_axis;                   /**< As given in nl_mesh_def, NL_UP_AXIS_* (0.3). */
} nl_mesh_info;

NL_DEFINE_OUTPUT_INIT(nl_mesh_info, nl_mesh_info_init)

/** Fills `*out_info` (caller-owned; set its `size` field to sizeof(nl_mesh_info) first: the library
 *  writes that many bytes at most). Returns SUCCESS, INVALID_HANDLE (null, stale or another world's
 *  id) or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] mesh  The mesh.
 *  @param[out] out_info  Receives what it holds. */
NL_API nl_status nl_mesh_get_info(const nl_world* world, nl_mesh_id mesh, nl_mesh_info* out_info);

/** Lists the ids of all registered meshes (the two-call pattern of every list): with out_ids NULL,
 *  only `*out_count` is written (the number of meshes) and the call succeeds; with a buffer
 *  (caller-owned, `capacity` entries) the ids are copied, or, if they do not fit, the call fails with
 *  BUFFER_TOO_SMALL, copies nothing and still writes `*out_count`. INVALID_ARGUMENT for a null
 *  world or out_count. Thread-safe.
 *  @param[in] world  The world.
 *  @param[out,opt] out_ids  Receives the ids, or NULL to count only.
 *  @param[in] capacity  Entries `out_ids` has room for.
 *  @param[out] out_count  Receives the number of meshes. */
NL_API nl_status nl_world_get_meshes(const nl_world* world, nl_mesh_id* out_ids, uint32_t capacity,
                                     uint32_t* out_count);

/* ---------------------------------------------------------------------------------------------
 * Ray queries, in batches, parallel over the world's workers.
 * ------------------------------------------------------------------------------------------- */

/** A ray from `origin` along `direction` (any nonzero length; normalised internally), up to
 *  `max_distance` metres (> 0; INFINITY allowed). */
typedef struct nl_ray {
    float origin[3];
    float direction[3];
    float max_distance;
} nl_ray;

/** The closest hit of a ray. An array element that may grow: set out_hits[0].size (nl_ray_hit_init). */
typedef struct nl_ray_hit {
    uint32_t size;       /**< sizeof(nl_ray_hit) as the host knows it; written back. */
    float distance;      /**< Metres from the origin along the normalised direction. */
    float point[3];      /**< World-space hit point. */
    float normal[3];     /**< Unit geometric normal in world space, by the triangle's winding
                              (counter-clockwise = front); not flipped toward the ray. */
    nl_mesh_id mesh;     /**< The mesh hit. */
    uint32_t triangle;   /**< Index of the triangle in the mesh's input (before degenerate ones
                              were skipped). */
    uint8_t hit;         /**< 1 if the ray hit something; else 0 and the other fields are zero. */
    uint8_t reserved[3];
} nl_ray_hit;

NL_DEFINE_OUTPUT_INIT(nl_ray_hit, nl_ray_hit_init)

/** Casts `count` rays and writes the closest hit of each to `out_hits` (caller-owned, `count`
 *  entries of the size set in out_hits[0].size). `rays` is borrowed. count == 0 succeeds and writes
 *  nothing. A ray that starts on a surface
 *  hits it at distance 0: start probes slightly off the surface they leave.
 *  Returns SUCCESS, or INVALID_ARGUMENT (null pointer; a ray with an origin not finite or beyond
 *  NL_COORDINATE_LIMIT, a zero or non-finite direction, or max_distance <= 0 or NaN: its index is
 *  named, nothing is written).
 *  Thread-safe: many threads may query at once; mesh edits wait for queries in flight.
 *  @param[in] world  The world.
 *  @param[in] rays  The rays, `count` of them.
 *  @param[in] count  The number of rays.
 *  @param[out] out_hits  Receives each ray's closest hit. */
NL_API nl_status nl_world_cast_rays(nl_world* world, const nl_ray* rays, uint32_t count,
                                    nl_ray_hit* out_hits);

/** A straight segment between two points. */
typedef struct nl_segment {
    float from[3];
    float to[3];
} nl_segment;

/** Tests `count` segments for any geometry between their ends (occlusion) and writes 1 (blocked)
 *  or 0 (clear) per segment to `out_blocked` (caller-owned, `count` bytes). Ends are included: a
 *  segment that starts or ends exactly on a surface is blocked, so pull the ends back by a small
 *  margin to ignore the floor a test stands on. A zero-length segment is clear. `segments` is borrowed.
 *  Returns SUCCESS, or INVALID_ARGUMENT (null pointer, a coordinate not finite or beyond
 *  NL_COORDINATE_LIMIT: its index is named).
 *  Thread-safe, as nl_world_cast_rays.
 *  @param[in] world  The world.
 *  @param[in] segments  The segments, `count` of them.
 *  @param[in] count  The number of segments.
 *  @param[out] out_blocked  Receives 1 or 0 per segment. */
NL_API nl_status nl_world_segments_blocked(nl_world* world, const nl_segment* segments,
                                           uint32_t count, uint8_t* out_blocked);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_LEVEL_H */
