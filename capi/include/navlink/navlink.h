/*
 * NavLink: engine-agnostic navigation with generated jump and drop links.
 *
 * The one C header a host includes. It compiles as C11 and as C++; every type is blittable
 * (fixed-width integers, floats, pointers), so C#, Rust and Python bind it as is.
 *
 * Conventions (docs/c-api.md explains them with examples):
 * - Functions return an nl_status. On failure they write nothing to their outputs (except the count
 *   of a list that did not fit), change no state, and leave a message naming the failing argument
 *   in the calling thread's last error
 *   (nl_get_last_error_message) and, if the world has one, pass it to the world's log callback.
 * - Objects are referred to by ids passed by value: {index1, generation}; the all-zero id is null.
 *   An id whose object was removed is stale: using it returns NL_STATUS_INVALID_HANDLE, never crashes,
 *   and never reaches another object: a slot is retired before its generation could repeat, and no
 *   two live worlds tag their ids alike (docs/c-api.md, "Ids").
 * - Input pointers are borrowed for the duration of the call and copied where NavLink keeps the
 *   data; output pointers are caller-owned buffers. Each function says which.
 * - Unless a function says otherwise, all functions that take a world are safe to call from several
 *   threads at once on the same world; nl_world_destroy must not race with any other call on it.
 * - Callbacks (task, progress, log, plugin) run while the call that made them holds some of the
 *   world's locks, on the calling thread. A callback may call NavLink, except for what would take
 *   again a lock its caller holds: such a call fails at once with NL_STATUS_INTERNAL_ERROR and a
 *   message naming the lock (never waits for itself, never breaks the lock); a call from another
 *   thread waits for the lock as any call does, so a callback must not wait for such a thread. So,
 *   from a task callback during nl_world_step: no nl_agent_* function, nl_world_step or
 *   nl_world_get_agent*; from any task callback no level query or edit (nl_world_cast_rays,
 *   nl_mesh_*...: refused from every task); from a generation's progress callback or a link-kind
 *   plugin no other generation or update (INVALID_ARGUMENT, nl_navmesh_generate_links). Path
 *   requests, link edits and reads of navmeshes and links are meant to be called from callbacks.
 * - Structs that may grow start with `uint32_t size`. Inputs: fill them from the nl_default_*_def()
 *   functions, which set it, then change the fields you need; a library newer than the header a
 *   host was built with reads only the `size` bytes the host has and gives later fields their
 *   defaults. Outputs, single or in arrays: set `size` with the nl_*_init() functions below (inline,
 *   no library call: plugins use them too); the library writes only the `size` bytes the host has.
 *   An output array of such elements (nl_link, nl_path_point, nl_ray_hit...) is laid out with the
 *   host's element size, read from its FIRST element's `size`: set at least that one (the library
 *   writes every element's `size` back), e.g. `links[0] = nl_link_init();` (also after malloc: an
 *   unset `size` is garbage). A `size` smaller than the element's first release, over 4096 or not
 *   a multiple of the element's alignment is INVALID_ARGUMENT.
 * - Coordinates are metres; every position passed in must be finite and within
 *   +-NL_COORDINATE_LIMIT, or the call fails with NL_STATUS_INVALID_ARGUMENT.
 */
#ifndef NAVLINK_NAVLINK_H
#define NAVLINK_NAVLINK_H

#include <stddef.h>
#include <stdint.h>

#include "navlink/export.h"
#include "navlink/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Version
 * ------------------------------------------------------------------------------------------- */

/** Semantic version of the library. */
typedef struct nl_version {
    int32_t major;
    int32_t minor;
    int32_t patch;
} nl_version;

/** The version of the loaded library; equals NL_VERSION_MAJOR/MINOR/PATCH of the header it was
 *  built with. A host compares it with its own header's macros to detect a mismatched library.
 *  Thread-safe; never fails. */
NL_API nl_version nl_get_version(void);

/* ---------------------------------------------------------------------------------------------
 * Status
 *
 * A status has a kind part (success, failure, in progress) in the top bits and detail bits below,
 * as Detour's dtStatus: a success may carry NL_STATUS_PARTIAL_RESULT, a failure carries the reason.
 * ------------------------------------------------------------------------------------------- */

typedef uint32_t nl_status;

#define NL_STATUS_FAILURE 0x80000000u     /**< The call failed; the detail bits say why. */
#define NL_STATUS_SUCCESS 0x40000000u     /**< The call succeeded. */
#define NL_STATUS_IN_PROGRESS 0x20000000u /**< Work was accepted and is not finished yet. */
#define NL_STATUS_DETAIL_MASK 0x0fffffffu

#define NL_STATUS_INVALID_ARGUMENT 0x00000001u /**< An argument is null, out of range or not finite. */
#define NL_STATUS_INVALID_HANDLE 0x00000002u   /**< An id is null, stale, or from another world. */
#define NL_STATUS_BUFFER_TOO_SMALL 0x00000004u /**< An output buffer is too small; the count says how many were needed. */
#define NL_STATUS_OUT_OF_MEMORY 0x00000008u    /**< An allocation failed; nothing was changed. */
#define NL_STATUS_CANCELLED 0x00000010u        /**< The work was cancelled by the host. */
#define NL_STATUS_PARTIAL_RESULT 0x00000020u   /**< Success with a result that is not complete. */
#define NL_STATUS_NOT_FOUND 0x00000040u        /**< The thing asked for does not exist (a file, a point on a mesh). */
#define NL_STATUS_INTERNAL_ERROR 0x00000080u   /**< A bug or a failure inside a dependency; please report it. */
#define NL_STATUS_IO_ERROR 0x00000100u         /**< A file could not be read or written. */
#define NL_STATUS_PARSE_ERROR 0x00000200u      /**< A file or string is malformed (OBJ, JSON). */
#define NL_STATUS_VERSION_MISMATCH 0x00000400u /**< A plugin or file version is not supported. */

/** Nonzero if the status is a success (possibly with detail bits such as PARTIAL_RESULT). */
#define NL_SUCCEEDED(status) (((status) & NL_STATUS_SUCCESS) != 0u)
/** Nonzero if the status is a failure. */
#define NL_FAILED(status) (((status) & NL_STATUS_FAILURE) != 0u)

/** A short static English description of a status, e.g. "failure: invalid argument".
 *  The string is owned by the library and lives as long as it is loaded. Thread-safe. */
NL_API const char* nl_status_string(nl_status status);

/** The status returned by the most recent nl_* call on the calling thread that returns a status or
 *  takes a world (nl_status_string, nl_get_version, the nl_default_* functions and these two do not
 *  touch the record). Thread-safe; the record is per thread. */
NL_API nl_status nl_get_last_status(void);

/** The message of the most recent nl_* call on the calling thread: empty if it succeeded, else one
 *  line naming the function and the failing argument, e.g.
 *  "nl_mesh_add: def->indices[7] = 120 is out of range (vertex_count = 64)".
 *  Borrowed: valid until the next nl_* call on this thread. Never null. Thread-safe. */
NL_API const char* nl_get_last_error_message(void);

/** Zero-initialises a struct in C and C++ alike (the nl_*_init() functions use it). */
#ifdef __cplusplus
#define NL_ZERO_INIT {}
#else
#define NL_ZERO_INIT {0}
#endif

/** Defines `static inline T name(void)`: a zeroed T with `size` set, for output structs. */
#define NL_DEFINE_OUTPUT_INIT(T, name)          \
    static inline T name(void) {               \
        T value = NL_ZERO_INIT;                 \
        value.size = (uint32_t)sizeof(T);       \
        return value;                           \
    }

/** Largest coordinate magnitude accepted anywhere, in metres. Far beyond any playable space (float
 *  precision is coarser than a metre past 1e7); it keeps every computation inside float range. */
#define NL_COORDINATE_LIMIT 1.0e9f

/* ---------------------------------------------------------------------------------------------
 * World: the root object. It owns everything; no globals.
 * ------------------------------------------------------------------------------------------- */

typedef struct nl_world nl_world;

/** Log levels passed to the log callback. */
typedef uint32_t nl_log_level;
#define NL_LOG_ERROR 0u
#define NL_LOG_WARNING 1u
#define NL_LOG_INFO 2u
#define NL_LOG_DEBUG 3u

/** A log callback. `message` is borrowed for the duration of the call. It is called on the thread
 *  that made the failing call, which may be any host thread or a NavLink worker: it must be
 *  thread-safe and must not call back into the same world. */
typedef void nl_log_fn(void* user, nl_log_level level, nl_status status, const char* message);

/** Pass as worker_count to use one worker per hardware thread. */
#define NL_WORKERS_AUTO (-1)

/** Largest worker_count and path_worker_count a world accepts (far more threads than any machine
 *  runs NavLink on; a larger count is a bug in the host, refused before any thread starts). */
#define NL_MAX_WORKERS 1024

/** A host task system (optional; nl_world_def.task_enqueue_fn): NavLink's batch work, a parallel
 *  loop over items, run on the host's threads instead of NavLink's (TBB's), as Box2D's
 *  b2WorldDef.enqueueTask / finishTask. docs/c-api.md, "A host task system", has an example.
 *
 *  A task: runs items [begin, end) of the loop NavLink enqueued with `task_context` (pass back the
 *  pointer the enqueue callback received). The host calls it on disjoint ranges that cover
 *  [0, item_count) exactly once, begin < end, in any grouping and order, on any of its threads, at
 *  the same time or not. `worker_index` names the host worker calling it: below the world's
 *  worker_count, and used by one thread at a time (NavLink's own tasks do not depend on it yet).
 *  It returns when the range is done and never fails towards the host: a failure inside it is kept
 *  for the NavLink call that enqueued the task. It may call the enqueue callback again, on its own
 *  thread (nested parallel work). NavLink checks the host: a range out of bounds (not run) or a
 *  worker index >= worker_count, or items not run by the time the task is finished, fail the
 *  NavLink call with INTERNAL_ERROR naming what the host did. */
typedef void nl_task_fn(void* task_context, uint32_t begin, uint32_t end, uint32_t worker_index);

/** Enqueue callback: starts `task` over `item_count` items on the host's task system, split into
 *  ranges of at least `min_range` items (a suggestion to keep the overhead low: one range may be
 *  shorter where fewer remain). Returns the host's handle of the task, which NavLink passes to the
 *  finish callback exactly once, or NULL when the host ran every range before returning (inline; no
 *  finish call follows). `user` is nl_world_def.task_user. Called by the thread that called into
 *  NavLink, or by a host worker inside a task of NavLink's, possibly from several threads at once;
 *  item_count > min_range >= 1 (a loop of one range runs on the calling thread, without the host).
 *  It must not fail: if the host cannot queue, it runs the ranges itself and returns NULL. */
typedef void* nl_task_enqueue_fn(void* user, nl_task_fn* task, void* task_context, uint32_t item_count,
                                 uint32_t min_range);

/** Finish callback: returns once every range of the task behind `host_task` (an enqueue callback's
 *  result) has returned; called once per non-NULL handle, on the thread that enqueued it. It should
 *  help run the task's ranges rather than only sleep: it may be called on a host worker (NavLink
 *  called from a host job, or nested work), and a pool whose workers all sleep in it never finishes.
 *  NavLink may hold locks of the world while it waits (a ray batch holds the level's shared lock):
 *  it must not wait for anything that needs them, so meanwhile the thread must not run host work
 *  that calls into NavLink (ranges of NavLink's tasks are fine). NavLink marks the thread for that
 *  time: a level query or edit made from there fails with INTERNAL_ERROR instead of waiting on a
 *  lock the thread holds, and so does an agent call while nl_world_step waits ("Callbacks" at the
 *  top). It must return on the thread that called it (NavLink's locks belong to their thread: a
 *  fiber scheduler must not move the waiting job to another thread). */
typedef void nl_task_finish_fn(void* user, void* host_task);

/** How to create a world. Get one from nl_default_world_def(). */
typedef struct nl_world_def {
    uint32_t size;           /**< sizeof(nl_world_def); set by nl_default_world_def(). */
    int32_t worker_count;    /**< Threads NavLink may use for batch work, the calling thread
                                  included, at most NL_MAX_WORKERS. NL_WORKERS_AUTO (default): one
                                  per hardware thread; 0 or 1: everything runs on the calling thread.
                                  With task callbacks: the number of the host's workers, 1 to
                                  NL_MAX_WORKERS (worker indices lie below it; NavLink starts no
                                  thread for it). */
    nl_log_fn* log_fn;       /**< Optional. Receives every error (and, by log_level, more). */
    void* log_user;          /**< Passed back to log_fn as `user`; borrowed, never dereferenced. */
    nl_log_level log_level;  /**< Most verbose level passed to log_fn. Default NL_LOG_WARNING: errors,
                                  and warnings such as repaired input (skipped degenerate triangles). */
    uint32_t reserved;       /**< Ignored. (It fills what was padding in the first version, so that
                                  fields added later lie past the size hosts of that version pass.) */
    int32_t path_worker_count; /**< Threads that plan queued path requests (nl_path_request), apart
                                    from batch work, at most NL_MAX_WORKERS. NL_WORKERS_AUTO
                                    (default): one per hardware thread; 0: no threads, the host runs
                                    the queue with nl_path_process (a game loop with a frame budget). */
    /* The task callbacks came after 0.1.0: a host built against an older header passes a smaller
       size and gets these defaults. */
    nl_task_enqueue_fn* task_enqueue_fn; /**< Optional (default NULL: NavLink's batch work runs on TBB
                                              with worker_count threads). With task_finish_fn, runs
                                              every parallel loop of batch work (ray and segment
                                              batches, point location, link generation) on the
                                              host's task system: set both or neither. Results are
                                              identical bit for bit whatever the host's scheduling
                                              and worker_count. Embree's BVH builds (the first query
                                              after a mesh edit) still use Embree's own TBB threads,
                                              and path workers are NavLink's threads
                                              (path_worker_count 0 for none). */
    nl_task_finish_fn* task_finish_fn;   /**< Optional; waits for an enqueued task (see the type). */
    void* task_user;                     /**< Passed back to both callbacks as `user`; borrowed, never
                                              dereferenced. The callbacks and what task_user points to
                                              must stay valid until nl_world_destroy returns. */
    uint32_t agent_paths_per_step;       /**< Agents' paths planned in one nl_world_step at most
                                              (default 32): when many agents ask at once, the rest wait
                                              their turn, agents standing without a path first (they
                                              are NL_AGENT_WAITING), then the oldest request (those walk
                                              on meanwhile), so a step's cost stays bounded. At least 1. */
    uint32_t reserved2;                  /**< 0. */
} nl_world_def;

/** A def with every field at its default. Thread-safe; never fails. */
NL_API nl_world_def nl_default_world_def(void);

/** Creates a world. `def` is borrowed (NULL means all defaults); `*out_world` receives the new world,
 *  owned by the caller until nl_world_destroy.
 *  Returns NL_STATUS_SUCCESS, or a failure with INVALID_ARGUMENT (null out_world, size of def too
 *  small or ending inside the task callbacks, worker_count or path_worker_count < -1 or >
 *  NL_MAX_WORKERS, one task callback without the other, worker_count < 1 with task callbacks),
 *  OUT_OF_MEMORY (also when about 1,000 worlds exist at once: each world's Embree device takes one
 *  of the process's 1,024 thread-local keys) or INTERNAL_ERROR (the system refused a thread).
 *  Thread-safe. */
NL_API nl_status nl_world_create(const nl_world_def* def, nl_world** out_world);

/** Destroys a world and everything it owns; every id from it becomes invalid. NULL is ignored.
 *  Queued path requests first finish as NL_PATH_CANCELLED (their callbacks run, on this thread, and
 *  may still use the world's path functions); running ones are asked to stop and waited for.
 *  Must not run at the same time as any other call on this world. */
NL_API void nl_world_destroy(nl_world* world);

/** The number of threads the world uses for batch work (1 when everything runs on the caller; with
 *  task callbacks, the host's worker_count). Returns 0 for a null world. Thread-safe. */
NL_API int32_t nl_world_get_worker_count(const nl_world* world);

/* ---------------------------------------------------------------------------------------------
 * Level geometry: collision meshes the world queries with rays (held in an Embree scene).
 * ------------------------------------------------------------------------------------------- */

/** A registered mesh. Zero-initialised is the null id. */
typedef struct nl_mesh_id {
    uint32_t index1;     /**< Slot index + 1; 0 means null. */
    uint32_t generation; /**< Changes each time the slot is reused; never repeats. */
} nl_mesh_id;

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
 *  Thread-safe; waits for ray queries in flight on this world to finish. */
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
 *  Thread-safe, as nl_mesh_add. */
NL_API nl_status nl_mesh_add_obj_file(nl_world* world, const char* path, const nl_mesh_def* def,
                                      nl_mesh_id* out_id);

/** As nl_mesh_add_obj_file, from `length` bytes of OBJ text in memory (borrowed, not necessarily
 *  NUL-terminated). */
NL_API nl_status nl_mesh_add_obj_memory(nl_world* world, const char* data, size_t length,
                                        const nl_mesh_def* def, nl_mesh_id* out_id);

/** Removes a mesh. Returns SUCCESS, or INVALID_HANDLE for a null, stale or another world's id, or
 *  INVALID_ARGUMENT for a mesh a navmesh rides (remove the navmesh first).
 *  Thread-safe; waits for ray queries in flight on this world to finish. */
NL_API nl_status nl_mesh_remove(nl_world* world, nl_mesh_id mesh);

/** Moves a mesh: `transform` (16 floats, column-major, affine, invertible; borrowed) replaces the
 *  mesh's transform. Cheap for NL_MESH_MOVABLE meshes; otherwise the vertices are re-uploaded.
 *  The navmeshes that ride the mesh (nl_navmesh_def.surface) move with it when this returns: no
 *  rebuild and no new snapshot; their point location, paths and link ends answer in the world where
 *  the mesh is now, and agents on them ride along (docs/moving-surfaces.md). Such a mesh takes only
 *  rotations and translations.
 *  Returns SUCCESS, or INVALID_HANDLE, or INVALID_ARGUMENT (null, non-finite, non-affine, singular;
 *  not rigid for a mesh a navmesh rides; nothing moves).
 *  Thread-safe: meant to be called from the host's physics or game thread while path workers plan
 *  and nl_world_step runs elsewhere. A path planned meanwhile uses one pose throughout (the one of
 *  the moment its search starts); an agent step reads each surface's pose when it reads the agent.
 *  The mesh's own transform (nl_mesh_get_info, ray queries) changes a moment before its navmeshes'
 *  pose: another thread may read the new transform and agents placed at the old pose. To place a
 *  body on the platform, use nl_agent_info.surface_position with the transform the host set.
 *  Waits for ray queries in flight on this world to finish. */
NL_API nl_status nl_mesh_set_transform(nl_world* world, nl_mesh_id mesh, const float* transform);

/** Nonzero if `mesh` refers to a mesh registered in `world` and not removed. Thread-safe. */
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
 *  id) or INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_mesh_get_info(const nl_world* world, nl_mesh_id mesh, nl_mesh_info* out_info);

/** Lists the ids of all registered meshes (the two-call pattern of every list): with out_ids NULL,
 *  only `*out_count` is written (the number of meshes) and the call succeeds; with a buffer
 *  (caller-owned, `capacity` entries) the ids are copied, or, if they do not fit, the call fails with
 *  BUFFER_TOO_SMALL, copies nothing and still writes `*out_count`. INVALID_ARGUMENT for a null
 *  world or out_count. Thread-safe. */
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
 *  Thread-safe: many threads may query at once; mesh edits wait for queries in flight. */
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
 *  Thread-safe, as nl_world_cast_rays. */
NL_API nl_status nl_world_segments_blocked(nl_world* world, const nl_segment* segments,
                                           uint32_t count, uint8_t* out_blocked);

/* ---------------------------------------------------------------------------------------------
 * Navmeshes: walkable polygons for one agent type. A world holds several (one per agent type),
 * handed over by the host (its engine's navmesh) or built from the level by a builder plugin.
 * A navmesh never changes once added: replace it by adding a new one and removing the old.
 * ------------------------------------------------------------------------------------------- */

/** A navmesh in a world. Zero-initialised is the null id. */
typedef struct nl_navmesh_id {
    uint32_t index1;
    uint32_t generation;
} nl_navmesh_id;

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
                                               triangle) are connected. Default 0.001; 0 welds exact
                                               duplicates only. */
    nl_agent_type agent;                  /**< The agent type this navmesh was made for. */
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
    nl_mesh_id surface;                   /**< A movable mesh (NL_MESH_MOVABLE) the navmesh rides, or the
                                               null id. With one, every coordinate above is in that
                                               mesh's own space, and the navmesh follows the mesh:
                                               nl_mesh_set_transform moves it (no rebuild). Added in 0.3. */
} nl_navmesh_def;

/** A def with no geometry, weld tolerance 0.001 and the default agent type. Thread-safe. */
NL_API nl_navmesh_def nl_default_navmesh_def(void);

/** Adds a navmesh from the host's polygons; everything is copied. The polygons are cleaned up as a
 *  host's navmesh usually needs: coincident vertices are welded (weld_tolerance); polygons wound
 *  clockwise seen from above are turned over so that every normal points up; polygons that welding
 *  collapses or that have no area are dropped; an edge shared by three or more polygons connects none
 *  of them. nl_navmesh_get_info counts each repair. Adjacency (portals) and boundary edges are built.
 *  Returns SUCCESS, or a failure with INVALID_ARGUMENT (null pointer, zero counts, a coordinate not
 *  finite or beyond NL_COORDINATE_LIMIT, an index out of range, a polygon with fewer than 3 or more
 *  than NL_MAX_POLYGON_VERTICES corners, a polygon not convex seen from above (navmesh polygons are
 *  2.5D: convex in x-z, heights free, as Recast's), a negative or NaN
 *  tolerance or agent field, bad detail data, every polygon degenerate: the item is named and nothing
 *  is added), OUT_OF_MEMORY. Thread-safe. */
NL_API nl_status nl_navmesh_add(nl_world* world, const nl_navmesh_def* def, nl_navmesh_id* out_id);

/** Removes a navmesh and its links, and the cross links of other navmeshes that land on it.
 *  Queries already running on it finish on their own copy.
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_navmesh_remove(nl_world* world, nl_navmesh_id navmesh);

/** Nonzero if `navmesh` is a navmesh of `world`. Thread-safe. */
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
    nl_agent_type agent;
    float bounds_min[3];               /**< In the world; for a navmesh that rides a moving mesh, a
                                            box that holds it where the mesh is now. */
    float bounds_max[3];
    nl_mesh_id surface;                /**< The movable mesh it rides; the null id for none. Added in 0.3. */
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
 *  INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_navmesh_get_info(const nl_world* world, nl_navmesh_id navmesh, nl_navmesh_info* out_info);

/** Copies the navmesh's vertices (x y z each, after welding) into `out_xyz` (caller-owned, room for
 *  `capacity` vertices, i.e. 3 * capacity floats), with the two-call pattern of nl_world_get_meshes.
 *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL, INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe. */
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
 *  polygon out of range). Thread-safe. */
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
 *  or INVALID_ARGUMENT. Thread-safe. */
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
 *  named; half_extents not positive and finite). Thread-safe; parallel over the world's workers. */
NL_API nl_status nl_navmesh_find_nearest(const nl_world* world, nl_navmesh_id navmesh, const float* points,
                                         uint32_t count, const float* half_extents, nl_nav_point* out);

/** Lists the world's navmeshes into `out_ids` (two-call pattern as nl_world_get_meshes). */
NL_API nl_status nl_world_get_navmeshes(const nl_world* world, nl_navmesh_id* out_ids, uint32_t capacity,
                                        uint32_t* out_count);

/* ---------------------------------------------------------------------------------------------
 * Building navmeshes from the level with a navmesh-builder plugin (the Recast builder is built in).
 * ------------------------------------------------------------------------------------------- */

/** Progress of a long call (a navmesh build, a link generation): `fraction` done (0..1, never going
 *  back) and the stage's name (borrowed for the call). Return 0 to cancel the call; it then fails
 *  with CANCELLED and changes nothing. Called on the thread that made the call. */
typedef int32_t nl_progress_fn(void* user, float fraction, const char* stage);

/** How to build a navmesh. Get one from nl_default_navmesh_build_def(). */
typedef struct nl_navmesh_build_def {
    uint32_t size;              /**< sizeof(nl_navmesh_build_def). */
    const char* builder;        /**< Name of a navmesh-builder plugin, NUL-terminated; NULL = "recast". */
    nl_agent_type agent;        /**< The agent type to build for. */
    const void* settings;       /**< Optional builder-specific settings struct starting with
                                     `uint32_t size` (nl_recast_settings for "recast"); borrowed. */
    const char* settings_json;  /**< Optional settings as a JSON object (UTF-8, `settings_json_length`
                                     bytes), applied over `settings` or the defaults; borrowed. NULL
                                     means none (length must then be 0); an empty string is not a
                                     JSON object (PARSE_ERROR). */
    size_t settings_json_length;
    nl_mesh_id surface;         /**< A movable mesh to build on, or the null id. With one, the builder
                                     sees that mesh alone, in its own space, and the navmesh rides it
                                     (as nl_navmesh_def.surface). Without one, it sees every static
                                     mesh (movable meshes are left out: a navmesh over one would stay
                                     behind when it moves). Added in 0.3. */
    nl_progress_fn* progress;   /**< Optional: told of the build's progress from its start (the
                                     builder reports its stages; Recast's rasterisation in steps),
                                     and can cancel it. Added in 0.3. */
    void* progress_user;        /**< Passed back to `progress`; not dereferenced. */
} nl_navmesh_build_def;

/** Builder "recast", default agent type, default settings. Thread-safe; never fails. */
NL_API nl_navmesh_build_def nl_default_navmesh_build_def(void);

/** Builds a navmesh from every static mesh registered in the world (under their current transforms;
 *  or, with def->surface, from that movable mesh in its own space) but those flagged
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
 *  area and the cell size more than with the triangles): give def->progress to show it and cancel. */
NL_API nl_status nl_navmesh_build(nl_world* world, const nl_navmesh_build_def* def, nl_navmesh_id* out_id);

/* ---------------------------------------------------------------------------------------------
 * Links: jumps, drops and manual traversals, each belonging to a navmesh. Generated links are
 * replaced by each generation; manual links are never touched by it.
 * ------------------------------------------------------------------------------------------- */

/** A link in a world. Zero-initialised is the null id. */
typedef struct nl_link_id {
    uint32_t index1;
    uint32_t generation;
} nl_link_id;

/** The first link kind a plugin may use (nl_link_kind). */
#define NL_LINK_FIRST_PLUGIN_KIND 256u

/** Link kinds. Plugin kinds are numbered from NL_LINK_FIRST_PLUGIN_KIND. */
typedef uint32_t nl_link_kind;
#define NL_LINK_JUMP 1u   /**< Edge to edge across a gap, along a parabolic arc. */
#define NL_LINK_DROP 2u   /**< Off an edge down to the floor below. */
#define NL_LINK_MANUAL 3u /**< Placed by the host. */

/** What taking a link asks of an agent, going from its start to its end. Going the other way over
 *  a bidirectional link swaps rise and drop. */
typedef struct nl_link_requirements {
    float gap;             /**< Horizontal distance covered in the air, metres: rim to rim for a
                                generated jump, rim to landing for a generated drop; for other links
                                the ends' horizontal distance (their rims are not known).
                                nl_agent_capabilities.max_jump_distance is compared with it. */
    float rise;            /**< How far the end is above the start (0 if below), floor to floor for
                                generated links. */
    float drop;            /**< How far the end is below the start (0 if above), floor to floor for
                                generated links. */
    float clearance_width; /**< Widest body found clear along the link (0: not measured). */
    uint64_t abilities;    /**< Ability bits the agent must have (plugin kinds). */
    float length;          /**< Horizontal distance between the ends, metres. */
    uint32_t reserved;     /**< 0. */
} nl_link_requirements;

/** A link as the world holds it. An array element that may grow: set `size` of the first element of
 *  an output array (nl_link_init). */
typedef struct nl_link {
    uint32_t size;             /**< sizeof(nl_link) as the host knows it; written back. */
    nl_link_kind kind;
    nl_link_id id;
    nl_navmesh_id navmesh;
    float start[3];
    float end[3];
    float apex[3];             /**< Top of a jump's arc; for a generated drop, where its fall leaves
                                    the ground (0.2 m past the rim on the fall's heading, at the
                                    start's height); for other kinds the higher end. */
    uint8_t bidirectional;
    uint8_t generated;         /**< 1 if made by nl_navmesh_generate_links. */
    uint8_t enabled;
    uint8_t reserved;
    float cost_modifier;       /**< Multiplies the link's traversal cost (>= 0; 1 by default). */
    uint32_t start_polygon;    /**< Navmesh polygons under the ends (NL_NO_POLYGON if unknown). */
    uint32_t end_polygon;
    uint32_t reserved2;        /**< 0. (Keeps user_data 8-aligned with no hidden padding.) */
    uint64_t user_data;
    nl_link_requirements requirements;
    nl_navmesh_id landing_navmesh; /**< For a link to another navmesh (a cross link), the navmesh its
                                        end is on (end_polygon is one of its polygons); the null id
                                        for a link within `navmesh`. Added in 0.3. */
    float tolerance;           /**< A cross link's: how far its end may move, seen from its start,
                                    before it stops holding; 0 for other links. */
    uint8_t holds;             /**< 1 if the link can be taken as the navmeshes stand now: always for a
                                    link within one navmesh; for a cross link, while its end is within
                                    `tolerance` of where it was, seen from its start. */
    uint8_t reserved3[3];
} nl_link;

NL_DEFINE_OUTPUT_INIT(nl_link, nl_link_init)

/** A link to add, or the new state of one to update. Get one from nl_default_link_def(). */
typedef struct nl_link_def {
    uint32_t size;             /**< sizeof(nl_link_def). */
    nl_link_kind kind;         /**< NL_LINK_MANUAL by default. */
    float start[3];
    float end[3];
    uint8_t bidirectional;     /**< 0 by default. */
    uint8_t enabled;           /**< 1 by default. */
    uint8_t requirements_as_given; /**< 0 (default, and what a zeroed def says): requirements.gap,
                                        length, rise and drop are measured from the ends (gap =
                                        length: the rims are not known), and the values given for
                                        them are ignored; 1: all of `requirements` is taken as given
                                        (e.g. a link that asks only for an ability; a length of 0 is
                                        measured). clearance_width and abilities are always taken as
                                        given. */
    uint8_t reserved;
    float cost_modifier;       /**< 1 by default; >= 0. */
    uint64_t user_data;
    nl_link_requirements requirements;
    nl_navmesh_id landing_navmesh; /**< The null id (default): both ends on the link's navmesh. Another
                                        navmesh: a cross link from the link's navmesh to that one (a
                                        ledge to a moving platform, a platform to a ledge), `end` on it.
                                        Both ends are given in the world as the navmeshes stand now, and
                                        each is kept in its navmesh's space; the link holds while the
                                        end, seen from the start, stays within `tolerance` of where it
                                        is now (agents wait at its start until it does: a ferry). Cross
                                        links are one-way and are not saved in links files. Added in 0.3. */
    float tolerance;           /**< Of a cross link, metres; 0.25 by default; >= 0. */
    uint32_t reserved2;
} nl_link_def;

/** A manual link from (0,0,0) to (0,0,0), one-way, enabled, cost modifier 1, requirements measured
 *  from its ends (requirements_as_given 0). Thread-safe. */
NL_API nl_link_def nl_default_link_def(void);

/** Adds a link to a navmesh. Its ends must each lie within 1 m of the navmesh (they are kept as given;
 *  the polygons under them are recorded), or, with def->landing_navmesh, the start within 1 m of
 *  `navmesh` and the end within 1 m of the landing navmesh. Ends are given in the world; on a navmesh
 *  that rides a moving mesh they are kept in its space (nl_link_get reads them where it is now).
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh, landing_navmesh),
 *  INVALID_ARGUMENT (null pointer, a coordinate not finite or beyond the limit, an end off the navmesh,
 *  a negative cost modifier, requirement or tolerance, a two-way cross link, landing_navmesh equal to
 *  navmesh, size too small). Thread-safe. */
NL_API nl_status nl_link_add(nl_world* world, nl_navmesh_id navmesh, const nl_link_def* def, nl_link_id* out_id);

/** Replaces a link's fields with `def`'s (any link, generated ones too: to disable one, for instance).
 *  It stays on its navmesh and keeps whether it was generated; a generation replaces generated links,
 *  edited or not. Errors as nl_link_add, and INVALID_HANDLE for the link. Thread-safe. */
NL_API nl_status nl_link_update(nl_world* world, nl_link_id link, const nl_link_def* def);

/** Removes a link. Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_link_remove(nl_world* world, nl_link_id link);

/** Nonzero if `link` is a link of `world`. Thread-safe. */
NL_API int32_t nl_link_is_valid(const nl_world* world, nl_link_id link);

/** Fills `*out_link` (caller-owned, `size` set). Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT
 *  (null pointer, `size` too small). Thread-safe. */
NL_API nl_status nl_link_get(const nl_world* world, nl_link_id link, nl_link* out_link);

/** Lists a navmesh's links, in the order they were added (two-call pattern as nl_world_get_meshes;
 *  out_links[0].size set when out_links is not NULL).
 *  Thread-safe: the list is one consistent moment even while other threads edit. */
NL_API nl_status nl_navmesh_get_links(const nl_world* world, nl_navmesh_id navmesh, nl_link* out_links,
                                      uint32_t capacity, uint32_t* out_count);

/** Removes the navmesh's generated links; manual ones stay. `out_removed` (optional) receives how many
 *  went. The last generation is forgotten with them: nl_navmesh_update_links_in_box then returns
 *  NOT_FOUND until the next nl_navmesh_generate_links (an update never brings removed links back).
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_navmesh_remove_generated_links(nl_world* world, nl_navmesh_id navmesh, uint32_t* out_removed);

/** How links are generated (docs/link-generation.md explains each). Get one from
 *  nl_default_link_settings(); defaults work with Recast's default agent on the shared levels. */
typedef struct nl_link_settings {
    uint32_t size;                  /**< sizeof(nl_link_settings). */
    float min_edge_length;          /**< Shorter boundary edges are grouped with those they touch (0.4 m). */
    uint32_t min_group_size;        /**< Groups of fewer short edges are dropped (2). */
    uint32_t max_group_size;        /**< Longer chains of short edges are split (8). */
    float sample_spacing;           /**< Take-off samples along a long edge (1 m). */
    float falloff_distance;         /**< How far past an edge the ground must fall away (1.5 m). */
    float max_jump_gap;        /**< Widest gap a jump crosses, rim to rim (4 m). */
    float min_link_distance;        /**< Narrower gaps are walked, not jumped (0.3 m). */
    float short_link_distance;      /**< Shorter links use the permissive angles (2 m). */
    float max_jump_up;              /**< Highest rise of a jump, floor to floor; drops this low work
                                         both ways (1.5 m). */
    float jump_arc_height;          /**< Arc apex above the higher end (1 m). */
    float strict_forward_angle;     /**< Between a link and an edge's outward direction, degrees (35). */
    float permissive_forward_angle; /**< The same for short links (60). */
    float strict_incline_angle;     /**< Between a link and the take-off surface, degrees (45). */
    float permissive_incline_angle; /**< The same for short links (70). */
    float max_drop_distance;        /**< Deepest drop, floor to floor (5 m). */
    float drop_angles[16];          /**< Rotations of the outward direction probed for drops, degrees. */
    uint32_t drop_angle_count;      /**< Entries used in drop_angles (3: 0, -30, 30). */
    float drop_steepness;           /**< Landing probes fall this steeply, degrees below horizontal (60). */
    float merge_distance;           /**< Links with both ends this close are one (0.6 m). */
    float clearance_margin;         /**< Fraction of a path left out of the clearance test at each end (0.1). */
    uint32_t arc_segments;          /**< Pieces of a jump arc in the clearance test (12). */
    const char* plugin_settings_json;   /**< Optional JSON object of link-kind plugins' settings, one
                                             object per kind name: {"climb": {"max_height": 3}}
                                             (every value an object). Borrowed for the call; NULL =
                                             none (the length must then be 0). */
    size_t plugin_settings_json_length;
    float walk_factor;              /**< No jump whose ends are joined on foot by a walk of at most
                                         walk_factor x its length + walk_distance (1.5). */
    float walk_distance;            /**< (2 m). */
} nl_link_settings;

/** The defaults. Thread-safe; never fails. */
NL_API nl_link_settings nl_default_link_settings(void);

/** Applies a JSON object's keys (the field names above; drop_angles as an array) to `*settings`
 *  (caller-owned, in and out) and validates the result. On failure `*settings` is unchanged.
 *  Returns SUCCESS, or a failure with PARSE_ERROR (malformed JSON, with the position) or
 *  INVALID_ARGUMENT (an unknown key, a wrong type or value, nesting deeper than 64 levels: the key is
 *  named). Thread-safe. */
NL_API nl_status nl_link_settings_from_json(const char* json, size_t length, nl_link_settings* settings);

/** What a generation did: answers "why is there no link here?". */
typedef struct nl_link_generation_report {
    uint32_t size;               /**< Set by the caller to sizeof(nl_link_generation_report). */
    uint32_t edges;              /**< Boundary edges of the navmesh. */
    uint32_t groups;             /**< Groups of short edges. */
    uint32_t samples;            /**< Take-off samples on edges. */
    uint32_t takeoff_points;     /**< Samples that hang over a drop or gap. */
    uint32_t jump_candidates;    /**< Edge pairs that met the gap, rise, angle and walk limits. */
    uint32_t drop_candidates;    /**< Landings found below take-off points. */
    uint32_t jump_links;
    uint32_t drop_links;
    uint32_t plugin_links;         /**< Links of kinds from link-kind plugins. */
    uint32_t rejected_wall;        /**< Something solid between the edge and the rim. */
    uint32_t rejected_not_ledge;   /**< Walkable ground a step below the edge: no ledge there. */
    uint32_t rejected_distance;    /**< A jump's gap too wide or too narrow. */
    uint32_t rejected_rise;        /**< A jump higher than max_jump_up. */
    uint32_t rejected_angle;       /**< Not facing the other edge, or too steep. */
    uint32_t rejected_no_landing;  /**< No navmesh where the agent would land. */
    uint32_t rejected_clearance;   /**< The body would touch geometry on the way. */
    uint32_t rejected_duplicate;   /**< The same traversal as a link already kept. */
    uint64_t rays_cast;            /**< Rays and occlusion segments sent to Embree. */
    double milliseconds_edges;
    double milliseconds_takeoff;
    double milliseconds_jumps;
    double milliseconds_drops;
    double milliseconds_merge;
    double milliseconds_total;
    uint64_t box_queries;          /**< Boxes around straight runs of clearance sweeps asked whether
                                        any triangle touches them; an untouched one is clear without
                                        testing its pieces. Written when `size` covers it. */
    uint64_t body_tests;           /**< Pieces of clearance sweeps tested exactly against the
                                        triangles near them. The fields from here on are written
                                        when `size` covers them. */
    uint32_t rejected_walkable;    /**< Jumps whose ends are about as near on foot (walk_factor). */
    uint32_t rejected_too_shallow; /**< Drops no deeper than the agent's max_climb, floor to floor:
                                        a step, walked. */
    uint32_t rejected_too_deep;    /**< Drops deeper than max_drop_distance, floor to floor. */
    uint32_t reserved;
} nl_link_generation_report;

NL_DEFINE_OUTPUT_INIT(nl_link_generation_report, nl_link_generation_report_init)

/** Generates the navmesh's jump and drop links against the level geometry, and the links of every
 *  loaded link-kind plugin, and replaces its generated links with them; manual links are untouched.
 *  A plugin's refused link (a wrong kind, an end off the navmesh) fails the call with INTERNAL_ERROR
 *  and the plugin's name. `settings` is borrowed (NULL = defaults); `progress`
 *  is optional (`user` is passed back to it); `out_report` is optional (caller-owned, `size` set).
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (also when the navmesh was removed while the
 *  links were being generated: nothing is stored), INVALID_ARGUMENT (a setting, named; also a sample_spacing that
 *  would put more than 4,000,000 take-off samples on this navmesh's boundary; plugin_settings_json
 *  nested deeper than 64 levels, or with a value that is not an object, or naming a kind no loaded
 *  link-kind plugin provides: the key named, with the kinds loaded),
 *  PARSE_ERROR (malformed plugin_settings_json, found before any work), CANCELLED (progress
 *  returned 0: the navmesh's links are as they were), OUT_OF_MEMORY.
 *  Generations and updates of one navmesh run one after the other; other navmeshes' run at the same
 *  time. From inside a generation, update or cross-link generation (its progress callback, a
 *  link-kind plugin) links cannot be generated or updated, on any navmesh and of either kind
 *  (nl_navmesh_generate_links, nl_navmesh_update_links_in_box, nl_navmesh_generate_cross_links): such
 *  a call fails with INVALID_ARGUMENT (two threads each doing so for the other's navmesh would wait
 *  for each other forever).
 *  Thread-safe; parallel over the world's workers; the result does not depend on their number. */
NL_API nl_status nl_navmesh_generate_links(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                                           nl_progress_fn* progress, void* user, nl_link_generation_report* out_report);

/** Generates the jump and drop links between two navmeshes (a ledge and a platform; either may ride
 *  a moving mesh, nl_navmesh_def.surface) for where they stand now, both ways, as cross links
 *  (nl_link_def.landing_navmesh) that hold while the two stay placed so, within `tolerance` metres
 *  (0.25 is a good start). They replace the generated cross links between the two that hold now
 *  (made for this placement); those made for another placement (the platform's other stop) stay for
 *  when it is back, and each navmesh's own links stay. Only the polygons within a link's reach of
 *  the other navmesh are looked at, so a platform's links cost what its neighbourhood does: call it
 *  when a surface comes to rest, or when its links stop holding, as often as suits the host (nothing
 *  calls it for you). Links are proven against the level as it stands (the platform where it is).
 *  Both navmeshes must be made for the same agent radius and height. `settings`, `progress`, `user`
 *  and `out_report` as for nl_navmesh_generate_links (jump_links and drop_links count the cross
 *  links; link-kind plugins are not run: their links lie within one navmesh, though
 *  plugin_settings_json is checked as there). Returns SUCCESS, or a failure with INVALID_HANDLE (either
 *  navmesh), INVALID_ARGUMENT (the same navmesh twice, different bodies, a bad tolerance or setting,
 *  named; also when called from inside a generation, update or cross-link generation, as
 *  nl_navmesh_generate_links says), CANCELLED (nothing changed). Thread-safe; two calls for the same
 *  pair at once store one's result or the other's. */
NL_API nl_status nl_navmesh_generate_cross_links(nl_world* world, nl_navmesh_id first, nl_navmesh_id second, float tolerance,
                                                 const nl_link_settings* settings, nl_progress_fn* progress, void* user,
                                                 nl_link_generation_report* out_report);

/** Regenerates only what level geometry inside the box [box_min, box_max] (3 floats each, borrowed)
 *  can have changed since the navmesh's last generation: call it after meshes were added, removed or
 *  moved there; the box must hold every change (for a moved mesh, its bounds before and after).
 *  Probes and sweeps that touch the box are cast again, everything else is reused, and the result
 *  equals what nl_navmesh_generate_links with the same settings would give now. Link-kind plugins
 *  keep no cache: their links are generated again in full. The navmesh itself must be the same (a
 *  rebuilt navmesh is a new one: generate its links in full).
 *  Returns SUCCESS, or a failure with NOT_FOUND (never generated, or the generated links were removed or
 *  replaced by a JSON load since or meanwhile: nothing is stored), INVALID_HANDLE, INVALID_ARGUMENT
 *  (a null, non-finite or inverted box; also when called from inside a generation or update, as
 *  nl_navmesh_generate_links says), CANCELLED (nothing changed). Thread-safe. */
NL_API nl_status nl_navmesh_update_links_in_box(nl_world* world, nl_navmesh_id navmesh, const float* box_min,
                                                const float* box_max, nl_progress_fn* progress, void* user,
                                                nl_link_generation_report* out_report);

/** Writes the navmesh's links as JSON (schema "navlink-links" version 1, docs/link-generation.md)
 *  into `buffer` (caller-owned, `capacity` bytes, NUL-terminated on success), with what they were made
 *  for ("made_for": the navmesh's agent type, the settings of the generation that made its
 *  generated links, and the hash of the level a built navmesh came from, "level_hash"). `*out_length` always receives the length without the NUL; a NULL buffer only
 *  measures (two-call pattern). Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (capacity must
 *  exceed the length), INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_navmesh_save_links_json(const nl_world* world, nl_navmesh_id navmesh, char* buffer,
                                            size_t capacity, size_t* out_length);

/** Load links generated for another body than the navmesh's (see nl_navmesh_load_links_json). */
#define NL_LINKS_LOAD_ANY_BODY 0x1u

/** Replaces all of the navmesh's links with those in `json` (`length` bytes, borrowed); new ids are
 *  given. Each link is held to nl_link_add's rules: both ends within 1 m of the navmesh. A link
 *  without "requires" asks for what its ends measure; one with it for what it says (an absent key is
 *  0, an absent "length" the ends' horizontal distance). A file that says the body its links were
 *  generated for ("made_for".agent: radius and height) must say the navmesh's: links for another body
 *  are refused (INVALID_ARGUMENT, both bodies named), or, with NL_LINKS_LOAD_ANY_BODY in `flags`,
 *  loaded with a warning to the log callback. A file whose "level_hash" differs from the navmesh's
 *  was made for another level: a link end off the navmesh then fails saying so first, and links that
 *  all fit load with a warning. Files without "made_for" (written before 0.3) load as
 *  before. `out_count` (optional) receives how many were loaded. On failure nothing changes. On success
 *  the last generation is forgotten: nl_navmesh_update_links_in_box returns NOT_FOUND until the next
 *  nl_navmesh_generate_links.
 *  Returns SUCCESS, or a failure with PARSE_ERROR, VERSION_MISMATCH (another format or version),
 *  INVALID_ARGUMENT (a field missing or wrong, nesting deeper than 64 levels, an end off the navmesh,
 *  named by its path, e.g. "links[3].start"; links for another body; unknown flags), INVALID_HANDLE.
 *  Thread-safe. Changed in 0.3: `flags` was added. */
NL_API nl_status nl_navmesh_load_links_json(nl_world* world, nl_navmesh_id navmesh, const char* json, size_t length,
                                            uint32_t flags, uint32_t* out_count);

/* ---------------------------------------------------------------------------------------------
 * Baked navmesh files: a navmesh, its links and what they were made for in one compact, checked
 * binary file (docs/baking.md), saved in an editor or build step and loaded at run time with no
 * Recast build. Navmeshes keep their coordinates on a grid of 1/1024 m, so a file holds them exactly:
 * a loaded navmesh answers every query as the saved one did.
 * ------------------------------------------------------------------------------------------- */

/** Writes the navmesh, its links (generated and manual, in the order nl_navmesh_get_links lists them)
 *  and what they were made for (agent type, builder and its settings, the level's hash, the link
 *  generation settings) as a navmesh file into `buffer` (caller-owned, `capacity` bytes). `*out_size`
 *  always receives the file's size; a NULL buffer only measures (two-call pattern).
 *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (nothing written), INVALID_HANDLE,
 *  INVALID_ARGUMENT (out_size NULL; buffer NULL with a capacity; a navmesh with cross links: a file
 *  holds one navmesh's own links). Thread-safe. */
NL_API nl_status nl_navmesh_save(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity,
                                 size_t* out_size);

/** The same, written to the file at `path` (NUL-terminated, borrowed): whole or not at all (written
 *  beside it, then renamed over it). A symbolic link at `path` stays: the file it leads to (through
 *  any chain of links) is written. Returns SUCCESS, or a failure as nl_navmesh_save, or IO_ERROR
 *  (cannot write; the reason named; also a path that is, or leads to, a directory, a device, a socket
 *  or a pipe: left as it was). Thread-safe. */
NL_API nl_status nl_navmesh_save_file(const nl_world* world, nl_navmesh_id navmesh, const char* path);

/** Refuse a file baked from other level geometry than the world holds now (see nl_navmesh_load_def). */
#define NL_NAVMESH_LOAD_SAME_LEVEL 0x1u

/** How to load a navmesh file. Get one from nl_default_navmesh_load_def(). */
typedef struct nl_navmesh_load_def {
    uint32_t size;       /**< sizeof(nl_navmesh_load_def). */
    nl_mesh_id surface;  /**< For a file whose navmesh rode a movable mesh (nl_navmesh_file_info.rides_surface):
                              the movable mesh it rides now. The null id otherwise. */
    uint32_t flags;      /**< NL_NAVMESH_LOAD_SAME_LEVEL: compare the hash of the level it was baked from
                              with the world's (its static meshes, or the surface mesh in its own space)
                              and refuse a mismatch. 0: load it whatever the level. */
} nl_navmesh_load_def;

/** The null surface and no flags. Thread-safe; never fails. */
NL_API nl_navmesh_load_def nl_default_navmesh_load_def(void);

/** Adds the navmesh and its links held in a navmesh file (`data`, `size` bytes, borrowed), as
 *  nl_navmesh_add and nl_link_add would, with new ids (links in the file's order); what it was made
 *  for travels with it (nl_navmesh_save writes it again). `def` may be NULL (the defaults).
 *  Nothing in the world changes unless everything loads. Whatever the file says, the loader allocates
 *  no more than a fixed multiple of what its bytes inflate to (deflate's limit: 1032 times `size`).
 *  Returns SUCCESS, or a failure with VERSION_MISMATCH (not a NavLink navmesh file, or a newer format
 *  version), PARSE_ERROR (truncated or corrupted: the section and what is wrong named), INVALID_ARGUMENT
 *  (null data with a size, null out_id, bad def size or flags, a surface for a file that rode none or
 *  none for one that did, NL_NAVMESH_LOAD_SAME_LEVEL and the level differs, polygons or links that do
 *  not fit, named as "links[3].start"), INVALID_HANDLE (the surface), OUT_OF_MEMORY. Thread-safe. */
NL_API nl_status nl_navmesh_load(nl_world* world, const void* data, size_t size, const nl_navmesh_load_def* def,
                                 nl_navmesh_id* out_id);

/** The same, from the file at `path` (NUL-terminated, borrowed): a regular file or a pipe, read no
 *  further than its header says the file goes. Also NOT_FOUND (no such file), IO_ERROR (cannot read
 *  it; a directory, a device or a socket), PARSE_ERROR (a pipe that goes on past the file's end).
 *  Thread-safe. */
NL_API nl_status nl_navmesh_load_file(nl_world* world, const char* path, const nl_navmesh_load_def* def,
                                      nl_navmesh_id* out_id);

/** What a navmesh file holds and was made for (nl_navmesh_file_describe). */
typedef struct nl_navmesh_file_info {
    uint32_t size;                  /**< sizeof(nl_navmesh_file_info); set by the caller. */
    uint32_t version;               /**< The file's format version. */
    uint64_t file_size;             /**< Bytes. */
    nl_agent_type agent;            /**< The body the navmesh was made for. */
    uint32_t vertex_count;
    uint32_t polygon_count;
    uint32_t detail_triangle_count; /**< 0: no height detail. */
    uint32_t link_count;
    uint32_t generated_link_count;  /**< Of link_count, made by link generation. */
    uint32_t rides_surface;         /**< 1: its coordinates are in the space of a movable mesh it rode. */
    float quantum;                  /**< Metres per step of its fixed-point coordinates (1/1024). */
    uint32_t reserved;
    uint64_t level_hash;            /**< Of the level triangles it was built from; 0: handed over by the host. */
} nl_navmesh_file_info;

/** Reads a navmesh file (`data`, `size` bytes, borrowed) without loading it: fills `out_info`
 *  (optional) and writes what it was made for as a JSON object into `made_for_json` (optional,
 *  caller-owned, `capacity` bytes, NUL-terminated; `*out_length`, when given, always receives its
 *  length without the NUL; a NULL buffer only measures): {"builder": name or null, "builder_settings":
 *  object or null (complete when the builder recorded what it used, as "recast" does, else as
 *  given), "link_settings": object or null, "link_plugins": {kind name: {"plugin", "version",
 *  "settings"}} for each link-kind plugin that ran, or null, "level_hash": "16 hex digits",
 *  "writer": version}.
 *  Returns SUCCESS, or a failure as nl_navmesh_load reading the file (VERSION_MISMATCH, PARSE_ERROR),
 *  BUFFER_TOO_SMALL, INVALID_ARGUMENT (null data with a size; a buffer without out_length; bad info
 *  size). Thread-safe; needs no world (failures reach no log callback). */
NL_API nl_status nl_navmesh_file_describe(const void* data, size_t size, nl_navmesh_file_info* out_info,
                                          char* made_for_json, size_t capacity, size_t* out_length);

/* ---------------------------------------------------------------------------------------------
 * Paths: A* over a navmesh's polygons and links, filtered per request by what the agent's body can
 * do, then string-pulled into points that say how each segment is travelled (walk, jump, drop...).
 * Requests read an immutable snapshot of the navmesh and its links taken when they are made: editing
 * links meanwhile never blocks nor disturbs them (docs/pathfinding.md).
 * ------------------------------------------------------------------------------------------- */

/** A queued path request. Zero-initialised is the null ticket. */
typedef struct nl_path_ticket {
    uint32_t index1;
    uint32_t generation;
} nl_path_ticket;

/** What an agent's body can do. A link is usable only if the agent meets all of its requirements:
 *  gap <= max_jump_distance, rise <= max_jump_height, drop <= max_drop_height, clearance_width
 *  (when measured) >= 2 * radius, and every ability bit it asks for. Going the other way over a
 *  bidirectional link swaps rise and drop. A drop taken downward is a step off the edge, not a
 *  jump: its gap is not held against max_jump_distance. */
typedef struct nl_agent_capabilities {
    float max_jump_distance; /**< Widest horizontal gap jumped, metres (default 0: no jumps). */
    float max_jump_height;   /**< Highest rise jumped up, metres (default 0). */
    float max_drop_height;   /**< Deepest drop taken, metres (default 0: no drops). */
    float radius;            /**< Body radius, metres (default 0.6). Where it exceeds the radius the
                                  navmesh was built for (nl_agent_type.radius), the path keeps the
                                  difference away from the navmesh's outline, and portals that do not
                                  leave that room and 1 mm more are not crossed (an exact fit is
                                  refused the same way whatever the rounding). The room is measured along each portal:
                                  right for Recast's polygons, generous for long thin triangles laid
                                  across a corridor (a triangle soup), which can let a wider body by. */
    uint64_t abilities;      /**< Ability bits the agent has (default 0), for plugin link kinds. */
} nl_agent_capabilities;

/** A walker: radius 0.6, no jumps, no drops, no abilities. Thread-safe; never fails. */
NL_API nl_agent_capabilities nl_default_agent_capabilities(void);

/** Pass as an area cost to keep the agent out of that area. */
#define NL_AREA_EXCLUDED 0.0f

/** How a path request ended. */
typedef uint32_t nl_path_outcome;
#define NL_PATH_PENDING 0u            /**< Queued or being planned. */
#define NL_PATH_COMPLETE 1u           /**< The path reaches the goal. */
#define NL_PATH_PARTIAL 2u            /**< The goal is out of reach: the path is the shortest walk to
                                           the navmesh point nearest the goal that the body reaches.
                                           Or max_nodes ran out: the path leads towards the goal, as
                                           Detour's (to the point nearest the goal of the polygon whose
                                           entry the search found nearest to it). */
#define NL_PATH_NO_PATH 3u            /**< The goal is out of reach and accept_partial was 0. */
#define NL_PATH_START_OFF_NAVMESH 4u  /**< No polygon within search_half_extents of the start. */
#define NL_PATH_GOAL_OFF_NAVMESH 5u   /**< No polygon within search_half_extents of the goal. */
#define NL_PATH_CANCELLED 6u          /**< Cancelled or released before it finished, or the world was
                                           destroyed first. */
#define NL_PATH_FAILED 7u             /**< Could not run (out of memory, an internal error); the
                                           result's `status` says why. */

/** Called exactly once when a queued request finishes (nl_path_outcome says how), from the thread
 *  that finished it: a NavLink path worker, the thread in nl_path_process, the thread that cancelled
 *  or released a request that had not started, or the thread destroying the world. It can run before
 *  nl_path_request has returned the ticket. It may call nl_path_poll, nl_path_get_result and
 *  nl_path_release for `ticket` (unless the ticket was released: then it is already invalid), and
 *  submit new requests (refused with CANCELLED while the world is being destroyed); it must be quick
 *  (it holds up a worker), must not call nl_path_process, and must not destroy the world. nl_path_poll
 *  may report the outcome a moment before the callback runs: keep `user` alive until the callback has
 *  returned (nl_path_queue_stats.finished counts a request once its callback has returned). */
typedef void nl_path_callback(void* user, nl_path_ticket ticket, nl_path_outcome outcome);

/** One path request. Get one from nl_default_path_request_def(). */
typedef struct nl_path_request_def {
    uint32_t size;                 /**< sizeof(nl_path_request_def). */
    nl_navmesh_id navmesh;         /**< The agent type's navmesh. */
    float start[3];
    float goal[3];
    float search_half_extents[3];  /**< Start and goal snap to the navmesh within this box around them
                                        (default 2, 4, 2 m); each > 0. */
    nl_agent_capabilities agent;
    const float* area_costs;       /**< Optional, borrowed (copied): cost per metre walked in area i,
                                        for i < area_cost_count; other areas cost 1. Each finite and
                                        >= 0; NL_AREA_EXCLUDED (0) keeps the agent out. */
    uint32_t area_cost_count;      /**< At most 256. */
    float link_cost;               /**< Extra cost each time a link is taken, metres (default 0; >= 0).
                                        A link costs its length times its cost_modifier, plus this. */
    uint32_t max_nodes;            /**< Most polygons a search may visit; 0 (default): no limit. A
                                        goal found out of reach with no reachability map built yet
                                        takes two searches (pathfinding.md). */
    uint8_t accept_partial;        /**< 1 (default): when the goal cannot be reached, the path leads
                                        as near to it as the body can go (NL_PATH_PARTIAL);
                                        0: the outcome is NL_PATH_NO_PATH. */
    uint8_t reserved[3];
    nl_path_callback* callback;    /**< Optional, for nl_path_request only. */
    void* user;                    /**< Passed back to callback; borrowed, never dereferenced. */
} nl_path_request_def;

/** A request from (0,0,0) to (0,0,0) on the null navmesh for a default walker: set navmesh, start,
 *  goal and agent. Thread-safe; never fails. */
NL_API nl_path_request_def nl_default_path_request_def(void);

/** How the agent moves from one path point to the next: walking, or the kind of the link taken
 *  (NL_LINK_JUMP, NL_LINK_DROP, NL_LINK_MANUAL or a plugin kind). */
typedef uint32_t nl_segment_kind;
#define NL_SEGMENT_WALK 0u
#define NL_SEGMENT_JUMP 1u   /**< NL_LINK_JUMP. */
#define NL_SEGMENT_DROP 2u   /**< NL_LINK_DROP. */
#define NL_SEGMENT_MANUAL 3u /**< NL_LINK_MANUAL. */

/** One point of a path. An array element that may grow: set `size` of the first element of an
 *  output array (nl_path_point_init). */
typedef struct nl_path_point {
    uint32_t size;           /**< sizeof(nl_path_point) as the host knows it; written back. */
    float position[3];
    uint32_t polygon;        /**< Navmesh polygon at the point. */
    nl_segment_kind segment; /**< How the agent goes on from here to the next point (NL_SEGMENT_WALK
                                  at the last point of a path; an agent's corners, whose route leaves
                                  its navmesh, end at the take-off of a cross link, with that link).
                                  A drop climbed back up its bidirectional link is a jump:
                                  NL_LINK_JUMP, with `reversed` set. */
    nl_link_id link;         /**< The link of that segment; null for walking. */
    float apex[3];           /**< A jump's highest point, to prepare the jump; for other links the
                                  higher end; for walking the point itself. */
    uint8_t reversed;        /**< 1 if the link is taken from its end to its start. */
    uint8_t reserved[3];
    float surface_position[3]; /**< The point in its navmesh's own space: where it stays on a navmesh
                                    that rides a moving mesh (`position` and `apex` are in the world,
                                    at the mesh's pose when the path was planned). Equal to
                                    `position` on a navmesh that rides nothing. Added in 0.3. */
} nl_path_point;

NL_DEFINE_OUTPUT_INIT(nl_path_point, nl_path_point_init)

/** What a finished request found. */
typedef struct nl_path_result {
    uint32_t size;            /**< Set by the caller to sizeof(nl_path_result). */
    nl_path_outcome outcome;
    nl_status status;         /**< For NL_PATH_FAILED: why; NL_STATUS_SUCCESS otherwise. */
    uint32_t point_count;     /**< Points in the path (0 unless COMPLETE or PARTIAL). */
    uint32_t links_used;      /**< Link segments in the path. */
    uint32_t nodes_visited;   /**< Polygons the searches entered (both, when there were two). */
    uint8_t out_of_nodes;     /**< 1 if max_nodes stopped the search. */
    uint8_t reserved[3];
    float length;             /**< Metres walked: from point to point along the navmesh surface
                                   (through each portal crossed, at its height there), a link's
                                   straight chord. */
    float cost;               /**< What the path costs: its metres seen from above times the area
                                   cost of each polygon crossed, plus the links' costs. The least
                                   possible when the areas the body enters cost the same; else at
                                   most the dearest over the cheapest rate times it. */
    float start[3];           /**< The start snapped to the navmesh. */
    float goal[3];            /**< The goal snapped to the navmesh (where the path ends if COMPLETE). */
} nl_path_result;

NL_DEFINE_OUTPUT_INIT(nl_path_result, nl_path_result_init)

/** Plans a path now, on the calling thread, and writes the result to `*out_result` (caller-owned,
 *  `size` set) and its points to `out_points` (caller-owned, `capacity` entries, out_points[0].size
 *  set; may be NULL with capacity 0 to learn the count; `*out_count` receives the point count). For
 *  tools and tests; a game uses nl_path_request. `def` is borrowed; its callback is ignored.
 *  When the points did not fit (or were not asked for), the calling thread keeps the plan: the next
 *  nl_path_find on this thread with the same request, while the navmesh and its links are unchanged,
 *  copies it instead of planning again.
 *  Returns SUCCESS when the search ran, whatever it found (PARTIAL_RESULT is set for NL_PATH_PARTIAL;
 *  read the outcome), or a failure with INVALID_HANDLE (navmesh), INVALID_ARGUMENT (null pointer, a
 *  coordinate not finite, a negative capability or cost, size too small: named), BUFFER_TOO_SMALL
 *  (the result is written, the points are not), OUT_OF_MEMORY. Thread-safe. */
NL_API nl_status nl_path_find(nl_world* world, const nl_path_request_def* def, nl_path_result* out_result,
                              nl_path_point* out_points, uint32_t capacity, uint32_t* out_count);

/** Why a path falls short of its goal: nl_path_shortfall.reason. */
typedef uint32_t nl_path_shortfall_reason;
#define NL_PATH_SHORTFALL_NONE 0u             /**< It reaches the goal, or an end is off the navmesh
                                                   (the outcome says so). */
#define NL_PATH_SHORTFALL_OUT_OF_NODES 1u     /**< max_nodes stopped the search. */
#define NL_PATH_SHORTFALL_BODY_TOO_WIDE 2u    /**< A body of the navmesh's radius would get there:
                                                   passages on the way are too narrow for this one. */
#define NL_PATH_SHORTFALL_AREAS_EXCLUDED 3u   /**< Areas the request keeps the body out of stand in the way. */
#define NL_PATH_SHORTFALL_LINK_BEYOND_BODY 4u /**< A link would get there, and the body cannot take it
                                                   (`limit`, `needed`, `has`, `link`). */
#define NL_PATH_SHORTFALL_NO_LINKS 5u         /**< The goal is on another island of the navmesh, and the
                                                   navmesh has no links. */
#define NL_PATH_SHORTFALL_NOT_CONNECTED 6u    /**< No passage or link leads there, whatever the body. */

/** What a link asks that the body lacks: nl_path_shortfall.limit. */
typedef uint32_t nl_link_limit;
#define NL_LINK_LIMIT_NONE 0u
#define NL_LINK_LIMIT_JUMP_DISTANCE 1u /**< The gap, against max_jump_distance. */
#define NL_LINK_LIMIT_JUMP_HEIGHT 2u   /**< The rise, against max_jump_height. */
#define NL_LINK_LIMIT_DROP_HEIGHT 3u   /**< The drop, against max_drop_height. */
#define NL_LINK_LIMIT_WIDTH 4u         /**< The body's diameter, against the link's clearance. */
#define NL_LINK_LIMIT_ABILITIES 5u     /**< Ability bits the body lacks (missing_abilities). */

/** Why a request's path falls short of its goal (nl_path_explain). */
typedef struct nl_path_shortfall {
    uint32_t size;               /**< Set by the caller to sizeof(nl_path_shortfall). */
    nl_path_shortfall_reason reason; /**< NL_PATH_SHORTFALL_*. */
    nl_link_limit limit;         /**< NL_LINK_LIMIT_* for LINK_BEYOND_BODY. */
    float needed;                /**< LINK_BEYOND_BODY: what the link needs, metres (for WIDTH the
                                      body's diameter); BODY_TOO_WIDE: the body's radius. */
    float has;                   /**< LINK_BEYOND_BODY: what the body can, metres (for WIDTH the
                                      link's clearance); BODY_TOO_WIDE: the navmesh's radius. */
    uint32_t reversed;           /**< 1 if the link would be taken from its end to its start. */
    uint64_t missing_abilities;  /**< LIMIT_ABILITIES: the bits the body lacks. */
    nl_link_id link;             /**< LINK_BEYOND_BODY: the link (of the request's navmesh, or a cross
                                      link of another); the null id otherwise. */
    float link_start[3];         /**< Where the body would take it, in the world. */
    char text[256];              /**< The same as a sentence naming the field to change, NUL-
                                      terminated ("" for NONE), e.g. "a drop at (12, 4, 3) would get
                                      there: it needs a drop of 4.2 m, and the body drops 4 m
                                      (max_drop_height)". */
} nl_path_shortfall;

NL_DEFINE_OUTPUT_INIT(nl_path_shortfall, nl_path_shortfall_init)

/** Plans the request `def` (borrowed; its callback is ignored) as nl_path_find does and, when the path
 *  does not reach the goal (PARTIAL, NO_PATH), says why in `*out_shortfall` (caller-owned, `size`
 *  set): it plans again with one limit lifted at a time (the body's width down to the navmesh's
 *  radius, the excluded areas, what links the body can take; then all of them) and the first that
 *  reaches the goal is the reason; a link on that path the body cannot take is named with the
 *  capability it lacks and by how much (the cheapest way with every link allowed). For tools, logs
 *  and a host's debugging: up to five searches, on the calling thread.
 *  Returns SUCCESS (whatever the reason, NONE included), or a failure as nl_path_find's.
 *  Thread-safe. */
NL_API nl_status nl_path_explain(nl_world* world, const nl_path_request_def* def, nl_path_shortfall* out_shortfall);

/** Queues a path request and returns at once with its ticket in `*out_ticket`. The request reads the
 *  navmesh and links as they are now. `def` is borrowed and copied. Path workers plan it (or
 *  nl_path_process when path_worker_count is 0); poll the ticket or receive the callback, read the
 *  result, then release the ticket. Every accepted request finishes exactly once.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh), INVALID_ARGUMENT (as nl_path_find),
 *  OUT_OF_MEMORY; on failure no ticket is made and the callback is never called. Thread-safe. */
NL_API nl_status nl_path_request(nl_world* world, const nl_path_request_def* def, nl_path_ticket* out_ticket);

/** Writes the request's outcome (NL_PATH_PENDING while it runs) to `*out_outcome`.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (null, released or foreign ticket) or
 *  INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_path_poll(const nl_world* world, nl_path_ticket ticket, nl_path_outcome* out_outcome);

/** nl_path_wait's timeout that never ends. */
#define NL_PATH_WAIT_FOREVER 0xffffffffu

/** Blocks the calling thread until the request has finished or `timeout_ms` milliseconds have
 *  passed, and writes its outcome to `*out_outcome` (NL_PATH_PENDING on a timeout). A timeout of 0
 *  only looks, as nl_path_poll; NL_PATH_WAIT_FOREVER waits as long as it takes. With
 *  path_worker_count 0 nobody else plans requests, so the waiting thread plans queued ones itself
 *  (oldest first, as nl_path_process, their callbacks on this thread) until this one has finished,
 *  checking the time between requests: a request is never split, so a wait can overrun its timeout
 *  by the request being planned. The request's callback may still be running when the wait returns.
 *  Returns SUCCESS (finished), NL_STATUS_IN_PROGRESS (timed out; `*out_outcome` is NL_PATH_PENDING),
 *  or a failure with INVALID_HANDLE (null, released or foreign ticket, also one released by another
 *  thread during the wait) or INVALID_ARGUMENT (null out_outcome; called from a path callback, which
 *  runs on a thread that finishes requests and so could wait for itself).
 *  Thread-safe: any number of threads can wait, for the same ticket or others. */
NL_API nl_status nl_path_wait(nl_world* world, nl_path_ticket ticket, uint32_t timeout_ms, nl_path_outcome* out_outcome);

/** Copies a finished request's result and points, as nl_path_find. Can be called any number of times
 *  until the ticket is released. Returns SUCCESS (with PARTIAL_RESULT for NL_PATH_PARTIAL),
 *  NL_STATUS_IN_PROGRESS (not finished; nothing written), or a failure with INVALID_HANDLE,
 *  INVALID_ARGUMENT or BUFFER_TOO_SMALL (result written, points not). Thread-safe. */
NL_API nl_status nl_path_get_result(const nl_world* world, nl_path_ticket ticket, nl_path_result* out_result,
                                    nl_path_point* out_points, uint32_t capacity, uint32_t* out_count);

/** Asks a request to stop. A request not started yet finishes at once as NL_PATH_CANCELLED (its
 *  callback runs on this thread); a running one stops at its next check (every 64 polygons the
 *  search expands) unless it finishes first; a finished one is unchanged.
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_path_cancel(nl_world* world, nl_path_ticket ticket);

/** Frees a request's result; the ticket becomes invalid at once. Releasing an unfinished request
 *  cancels it; its callback still runs once (on this thread if it had not started). Returns SUCCESS
 *  or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_path_release(nl_world* world, nl_path_ticket ticket);

/** How much nl_path_process may do in one call. Get one from nl_default_path_budget() (no limits).
 *  A request is never split: the budget is checked between requests, so a call that finds the
 *  queue non-empty plans at least one, and the request that crosses a limit finishes. */
typedef struct nl_path_budget {
    uint32_t size;             /**< sizeof(nl_path_budget). */
    uint32_t max_requests;     /**< Requests planned at most; 0: no limit. */
    double max_milliseconds;   /**< Time spent at most; <= 0: no limit. */
    uint64_t max_search_nodes; /**< Search work at most: polygons the searches visited (their
                                    nl_path_result.nodes_visited added up); 0: no limit. A game
                                    bounds its frame by work this way, whatever the clock does. */
} nl_path_budget;

/** No limits. Thread-safe; never fails. */
NL_API nl_path_budget nl_default_path_budget(void);

/** Plans queued requests on the calling thread until the queue is empty or the budget (borrowed;
 *  NULL: no limits) is spent. The way a host with path_worker_count 0 runs the queue in its frame;
 *  with workers it helps them. `out_processed` (optional) receives how many requests finished here.
 *  Returns SUCCESS or INVALID_ARGUMENT (NaN milliseconds, `size` too small). Thread-safe. */
NL_API nl_status nl_path_process(nl_world* world, const nl_path_budget* budget, uint32_t* out_processed);

/** A request that finished, as nl_path_take_finished reports it. An array element that may grow: set
 *  `size` of the first element (nl_path_finished_init). */
typedef struct nl_path_finished {
    uint32_t size;           /**< sizeof(nl_path_finished) as the host knows it; written back. */
    nl_path_outcome outcome;
    nl_path_ticket ticket;
    void* user;              /**< The request's `user`, as given (not dereferenced). A host that frees
                                  `user` in the request's callback must not use this copy. */
} nl_path_finished;

NL_DEFINE_OUTPUT_INIT(nl_path_finished, nl_path_finished_init)

/** Takes the requests that finished since the last call, oldest first, on the host's own thread:
 *  the way to learn of finished requests without a callback (as Box2D's event arrays; callbacks still
 *  run as well). Writes up to `capacity` of them to `out_finished` (caller-owned, out_finished[0].size
 *  set when capacity > 0) and forgets those; `*out_count` receives how many were written and
 *  `*out_remaining` (optional) how many still wait for the next call. A request whose ticket was
 *  released is not reported (so what waits is bounded by the tickets not yet released).
 *  Returns SUCCESS, or INVALID_ARGUMENT (null out_count, NULL out_finished with capacity > 0, `size`
 *  too small). Thread-safe: each finished request is taken by one call only. */
NL_API nl_status nl_path_take_finished(nl_world* world, nl_path_finished* out_finished, uint32_t capacity,
                                       uint32_t* out_count, uint32_t* out_remaining);

/** Counters of a world's path queue. */
typedef struct nl_path_queue_stats {
    uint32_t size;         /**< Set by the caller to sizeof(nl_path_queue_stats). */
    uint32_t workers;      /**< Path worker threads. */
    uint32_t queued;       /**< Requests waiting. */
    uint32_t running;      /**< Requests being planned. */
    uint32_t unreleased;   /**< Tickets not released yet (finished or not). */
    uint32_t reserved;
    uint64_t submitted;    /**< Requests accepted since the world was created. */
    uint64_t finished;     /**< Requests finished (any outcome). */
} nl_path_queue_stats;

NL_DEFINE_OUTPUT_INIT(nl_path_queue_stats, nl_path_queue_stats_init)

/** Fills `*out_stats` (caller-owned, `size` set). Returns SUCCESS or INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_path_get_queue_stats(const nl_world* world, nl_path_queue_stats* out_stats);

/* ---------------------------------------------------------------------------------------------
 * Queries on a navmesh for one body: where it can get to (reachability), how far it walks in a
 * straight line (raycast), sliding a point along the surface, random points (docs/queries.md).
 * ------------------------------------------------------------------------------------------- */

/** The body a query is for, as a path request gives it: its capabilities (the links it can take,
 *  the room a wider body needs) and its area costs (an area of cost NL_AREA_EXCLUDED is kept out
 *  of; other costs do not matter to these queries). Get one from nl_default_query_filter(). */
typedef struct nl_query_filter {
    uint32_t size;                /**< sizeof(nl_query_filter). */
    nl_agent_capabilities agent;
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
 *  OUT_OF_MEMORY. Thread-safe: any number of queries at once, a map built once. */
NL_API nl_status nl_navmesh_can_reach(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                      const uint32_t* from_polygons, const uint32_t* to_polygons, uint32_t count,
                                      uint8_t* out_reachable);

/** Every polygon the filter's body can reach from `from_polygon` (itself included), ascending, into
 *  `out_polygons` (caller-owned, `capacity` entries; NULL with capacity 0 to learn the count;
 *  `*out_count` receives it). Returns SUCCESS, BUFFER_TOO_SMALL (nothing written but the count), or
 *  a failure as nl_navmesh_can_reach. Thread-safe. */
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
 *  Returns SUCCESS, BUFFER_TOO_SMALL, or a failure as nl_navmesh_can_reach. Thread-safe. */
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
 *  out_hits[0].size unset); OUT_OF_MEMORY (some rays' hits may be written). Thread-safe. */
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
 *  filter as nl_navmesh_can_reach refuses). Thread-safe. */
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
 *  as nl_navmesh_can_reach refuses, size too small). Thread-safe. */
NL_API nl_status nl_navmesh_random_points(const nl_world* world, nl_navmesh_id navmesh,
                                          const nl_random_points_def* def, nl_nav_point* out_points, uint32_t count,
                                          uint32_t* out_found);

/* ---------------------------------------------------------------------------------------------
 * Agents: bodies that walk their navmesh, take the links their body can, and keep out of each
 * other's way. nl_world_step moves every agent; the host reads their states and the step's events
 * in bulk (docs/agents.md).
 * ------------------------------------------------------------------------------------------- */

/** An agent in a world. Zero-initialised is the null id. */
typedef struct nl_agent_id {
    uint32_t index1;
    uint32_t generation;
} nl_agent_id;

/** What an agent is doing. */
typedef uint32_t nl_agent_state;
#define NL_AGENT_IDLE 0u        /**< No destination. */
#define NL_AGENT_WALKING 1u     /**< Following its path on the ground. */
#define NL_AGENT_JUMPING 2u     /**< In the air, on the arc the link generator checked. */
#define NL_AGENT_FALLING 3u     /**< On a drop: out past the rim, across, then falling straight down. */
#define NL_AGENT_TRAVERSING 4u  /**< On a manual or plugin link: a straight line at its walking speed. */
#define NL_AGENT_WAITING 5u     /**< For its path to be planned, for a link's landing to clear, or at a
                                     cross link's take-off for the link to hold (a ferry away). */
#define NL_AGENT_ARRIVED 6u     /**< At its destination (or as near as another body standing on it lets). */
#define NL_AGENT_FAILED 7u      /**< Cannot go on; nl_agent_info.reason says why. */

/** Why an agent planned again or failed (nl_agent_info.reason, nl_agent_event.reason). */
typedef uint32_t nl_agent_reason;
#define NL_AGENT_REASON_NONE 0u
#define NL_AGENT_REASON_DESTINATION_SET 1u     /**< A new destination. */
#define NL_AGENT_REASON_LINK_GONE 2u           /**< A link of its path was removed, disabled, moved, or is
                                                    beyond its body now: found at the first step after the
                                                    change or at the take-off, never in the air. An agent
                                                    whose path holds keeps it (new links serve its next plan). */
#define NL_AGENT_REASON_WORLD_CHANGED 3u       /**< Its navmesh changed under it. Not emitted today: a navmesh
                                                    never changes under its id, and one on a moving surface
                                                    moves whole, its agents with it (nothing to replan). */
#define NL_AGENT_REASON_OFF_PATH 4u            /**< Pushed too far off its path (REPLANNED), or teleported (the
                                                    next PATH_READY's reason). */
#define NL_AGENT_REASON_NO_PATH 5u             /**< The destination cannot be reached (it went as near as it could). */
#define NL_AGENT_REASON_NAVMESH_REMOVED 6u     /**< Its navmesh was removed. */
#define NL_AGENT_REASON_CAPABILITIES_CHANGED 7u
#define NL_AGENT_REASON_CROWD 8u               /**< Other bodies are in its way: it waits for room (the
                                                    WAITING event; nl_agent_info reads WAITING with this
                                                    reason meanwhile), or it gave its destination up after
                                                    nl_agent_def.give_up_seconds in counterflow (FAILED).
                                                    Added in 0.3. */

/** How to add an agent. Get one from nl_default_agent_def(). */
typedef struct nl_agent_def {
    uint32_t size;                      /**< sizeof(nl_agent_def). */
    nl_navmesh_id navmesh;              /**< The navmesh of its agent type. Where `position` stands on a
                                             movable mesh that a navmesh for the same body rides (found
                                             by a ray down), the agent goes on that one: it rides the
                                             platform it was put on (nl_agent_info.navmesh says so). */
    float height;                       /**< Body height, metres (default 2; > 0). */
    nl_agent_capabilities capabilities; /**< What its body can do (the links it takes) and its radius. */
    float max_speed;                    /**< Walking speed, m/s (default 3.5; > 0). It also walks a drop's
                                             way out and crosses manual and plugin links at this speed. */
    float max_acceleration;             /**< m/s^2 (default 8; > 0). */
    float gravity;                      /**< m/s^2 (default 9.81; > 0): how long a jump's arc and a fall take. */
    float takeoff_speed;                /**< m/s (default 0). > 0: a jump's time comes from this take-off
                                             speed instead of gravity (the arc stays the one checked). */
    float position[3];                  /**< Where it starts: on the navmesh (within its radius, half a metre
                                             at least, across and 2 m up or down), else NOT_FOUND. */
    uint8_t avoidance;                  /**< 1 (default): steers around other agents (docs/agents.md). */
    uint8_t reserved[3];
    uint64_t user_data;                 /**< The host's, handed back in infos and events. */
    float give_up_seconds;              /**< 0 (default): never. > 0: held up this long by bodies
                                             heading the other way (walking or giving way on the
                                             ground) without getting 1 m nearer its destination along
                                             its path, it gives the destination up: FAILED, reason
                                             NL_AGENT_REASON_CROWD, for a host that would rather send
                                             it elsewhere (docs/agents.md, "When the crowd does not
                                             let it through"). A queue, all one way, never counts.
                                             Added in 0.3. */
    uint32_t reserved2;
} nl_agent_def;

/** Default capabilities (a walker), height 2, speed 3.5, acceleration 8, gravity 9.81, avoidance
 *  on, never giving up, the null navmesh at (0,0,0): set navmesh and position. Thread-safe; never fails. */
NL_API nl_agent_def nl_default_agent_def(void);

/** Adds an agent, standing still (NL_AGENT_IDLE) at the navmesh point of def->position.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh), INVALID_ARGUMENT (null pointer, size
 *  too small, a field not finite or out of range: named), NOT_FOUND (position not on the navmesh:
 *  the message says how far the nearest navmesh point is). Thread-safe (waits for a step running). */
NL_API nl_status nl_agent_add(nl_world* world, const nl_agent_def* def, nl_agent_id* out_id);

/** Removes an agent. Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_agent_remove(nl_world* world, nl_agent_id agent);

/** Nonzero if `agent` is an agent of `world`. Thread-safe; from a task callback during nl_world_step
 *  it cannot look (the step holds the agents) and answers 0 ("Callbacks" at the top). */
NL_API int32_t nl_agent_is_valid(const nl_world* world, nl_agent_id agent);

/** Sends the agent to `point` (3 floats, borrowed), located at once on its navmesh, or else on a
 *  navmesh that cross links join to it (nl_link_def.landing_navmesh: a platform, a ledge across a
 *  chasm): on none of them is NOT_FOUND and the destination is not kept. A destination on a navmesh
 *  that rides a moving mesh is kept in the mesh's space: it moves with the mesh, and the agent
 *  arrives where it is at arrival (docs/moving-surfaces.md). The path is planned in a coming nl_world_step (an agent
 *  in the air lands first). Returns SUCCESS, or INVALID_HANDLE (also for an agent whose navmesh was
 *  removed), INVALID_ARGUMENT, NOT_FOUND. Thread-safe. */
NL_API nl_status nl_agent_set_destination(nl_world* world, nl_agent_id agent, const float* point);

/** Forgets the destination: the agent stops and stands (NL_AGENT_IDLE); one in the air lands first;
 *  one whose navmesh was removed stays NL_AGENT_FAILED. Returns SUCCESS or INVALID_HANDLE. Thread-safe. */
NL_API nl_status nl_agent_stop(nl_world* world, nl_agent_id agent);

/** Puts the agent at the navmesh point of `point`, standing, keeping its destination (it plans again
 *  from there). Returns SUCCESS, or INVALID_HANDLE (also for an agent whose navmesh was removed),
 *  INVALID_ARGUMENT (also while it is taking a link), NOT_FOUND. Thread-safe. */
NL_API nl_status nl_agent_teleport(nl_world* world, nl_agent_id agent, const float* point);

/** Changes what the agent's body can do (copied); it plans again. Returns SUCCESS, or INVALID_HANDLE,
 *  INVALID_ARGUMENT (a negative or non-finite figure). Thread-safe. */
NL_API nl_status nl_agent_set_capabilities(nl_world* world, nl_agent_id agent, const nl_agent_capabilities* capabilities);

/** Changes the agent's walking speed and acceleration (each finite and > 0). Returns SUCCESS, or
 *  INVALID_HANDLE, INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_agent_set_speed(nl_world* world, nl_agent_id agent, float max_speed, float max_acceleration);

/** Advances every agent by `dt` seconds (finite, >= 0; 0 does nothing), in parallel on the world's
 *  task system, with the same result bit for bit whatever the thread count: plans the paths asked
 *  for (at most agent_paths_per_step: agents standing without a path first, then the oldest), steers and moves every agent on the ground,
 *  flies those on links, and checks each link just before take-off. An agent's trouble (no path,
 *  its navmesh removed) is its failure and event, not the call's.
 *  Returns SUCCESS, or INVALID_ARGUMENT (dt NaN, infinite or negative: nothing changes), OUT_OF_MEMORY,
 *  INTERNAL_ERROR (called from a task callback of a step: refused, see "Callbacks" at the top).
 *  Thread-safe: other agent calls wait for it; an agent call from one of its task callbacks is refused. */
NL_API nl_status nl_world_step(nl_world* world, float dt);

/** An agent's state. An array element that may grow: set `size` of the first (nl_agent_info_init). */
typedef struct nl_agent_info {
    uint32_t size;            /**< sizeof(nl_agent_info) as the host knows it; written back. */
    nl_agent_state state;
    nl_agent_id id;
    float position[3];        /**< Feet, on the surface (in the air: on the link's trajectory). */
    float velocity[3];
    uint32_t polygon;         /**< The navmesh polygon it stands on (its take-off's while in the air). */
    nl_agent_reason reason;   /**< Why it failed, or why its current path was planned; CROWD while it
                                   waits for room. */
    nl_link_id link;          /**< The link it is taking, or waits to take; null otherwise. */
    float link_progress;      /**< 0..1 of the link's time. */
    float destination[3];     /**< Its destination, if has_destination: in the world, where it is now
                                   (on a moving surface it moves with the surface). */
    uint8_t has_destination;
    uint8_t reserved[3];
    uint32_t corners_ahead;   /**< Path points still to reach (nl_agent_get_corners gives them after
                                   where the agent is). */
    uint64_t user_data;
    nl_navmesh_id navmesh;    /**< The navmesh it stands on now (it changes when the agent takes a cross
                                   link; while in the air, the one it took off from). Added in 0.3. */
    nl_mesh_id surface;       /**< The movable mesh that navmesh rides (the agent rides it too), or the
                                   null id; also the null id while it flies a cross link (in the world,
                                   not on a surface). Added in 0.3. */
    float surface_position[3]; /**< `position` in that mesh's own space (equal to `position` on no
                                    surface, and in the air over a cross link): to parent the body to
                                    the platform in the host's scene. Added in 0.3. */
    uint32_t reserved2;
} nl_agent_info;

NL_DEFINE_OUTPUT_INIT(nl_agent_info, nl_agent_info_init)

/** Fills `*out_info` (caller-owned, `size` set). Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT.
 *  Thread-safe. */
NL_API nl_status nl_agent_get_info(const nl_world* world, nl_agent_id agent, nl_agent_info* out_info);

/** Every agent's state, in bulk, in a stable order until an agent is removed (two-call pattern as
 *  nl_world_get_meshes; out_infos[0].size set when out_infos is not NULL). Thread-safe. */
NL_API nl_status nl_world_get_agents(const nl_world* world, nl_agent_info* out_infos, uint32_t capacity,
                                     uint32_t* out_count);

/** Where the agent is, then the path points it has yet to reach, the next first (two-call pattern;
 *  out_points[0].size set): where it walks, and at which point it takes which link. The first point
 *  is its position now and how it goes on from there (NL_SEGMENT_WALK, or the link it is flying, with
 *  that link's apex), so a straight walk to the goal is two points; corners_ahead + 1 points in all
 *  (since 0.3; before, the stretch being walked was missing). None when it has no path or has
 *  arrived. Thread-safe. */
NL_API nl_status nl_agent_get_corners(const nl_world* world, nl_agent_id agent, nl_path_point* out_points,
                                      uint32_t capacity, uint32_t* out_count);

/** How a link is being taken: the trajectory the generator checked, with its timing, for a host that
 *  animates the body. */
typedef uint32_t nl_trajectory_kind;
#define NL_TRAJECTORY_NONE 0u  /**< On the ground: no link is being taken (the rest is zero). */
#define NL_TRAJECTORY_ARC 1u   /**< A jump: a parabola from `from` to `to` over `apex`. */
#define NL_TRAJECTORY_FALL 2u  /**< A drop: `points[0]` to `points[1]` (past the rim) and `points[2]`
                                    (above the landing) at the walking speed, then straight down to
                                    `points[3]` with gravity. */
#define NL_TRAJECTORY_LINE 3u  /**< Any other link: a straight line at the walking speed. */

typedef struct nl_agent_trajectory {
    uint32_t size;            /**< sizeof(nl_agent_trajectory) as the host knows it. */
    nl_trajectory_kind kind;
    nl_link_id link;
    float from[3];
    float to[3];
    float apex[3];
    float points[4][3];       /**< For NL_TRAJECTORY_FALL; else from, to repeated. */
    float duration;           /**< Seconds from take-off to landing. */
    float elapsed;            /**< Seconds since take-off. */
} nl_agent_trajectory;

NL_DEFINE_OUTPUT_INIT(nl_agent_trajectory, nl_agent_trajectory_init)

/** The trajectory of the link the agent is taking now, read at one moment (kind NL_TRAJECTORY_NONE
 *  while it is on the ground, also while it waits at a take-off), in the world: a link within a
 *  navmesh that rides a moving mesh is flown in the mesh's space and given where the mesh is now; a
 *  cross link is flown in the world, to where its landing was expected to be at landing time. Returns SUCCESS, INVALID_HANDLE
 *  or INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_agent_get_trajectory(const nl_world* world, nl_agent_id agent, nl_agent_trajectory* out_trajectory);

/** What happened to an agent in the last step. */
typedef uint32_t nl_agent_event_kind;
#define NL_AGENT_EVENT_PATH_READY 1u     /**< Its path was planned (reason: why it was asked for). */
#define NL_AGENT_EVENT_LINK_STARTED 2u   /**< It took off on `link`. */
#define NL_AGENT_EVENT_LINK_FINISHED 3u  /**< It landed at the end of `link`. */
#define NL_AGENT_EVENT_ARRIVED 4u
#define NL_AGENT_EVENT_FAILED 5u         /**< `reason` says why. */
#define NL_AGENT_EVENT_REPLANNED 6u      /**< It asked for a new path (`reason`; `link` for LINK_GONE). */
#define NL_AGENT_EVENT_WAITING 7u        /**< It stopped for room (reason NL_AGENT_REASON_CROWD): stuck
                                              among other bodies for 0.75 s, or giving way to one; its
                                              nl_agent_info reads WAITING, reason CROWD, until it walks
                                              on. Said once per wait. Added in 0.3. */

/** An array element that may grow: set `size` of the first (nl_agent_event_init). */
typedef struct nl_agent_event {
    uint32_t size;            /**< sizeof(nl_agent_event) as the host knows it; written back. */
    nl_agent_event_kind kind;
    nl_agent_id agent;
    nl_link_id link;
    nl_agent_reason reason;
    uint32_t reserved;
    uint64_t user_data;       /**< The agent's. */
} nl_agent_event;

NL_DEFINE_OUTPUT_INIT(nl_agent_event, nl_agent_event_init)

/** The events of the last nl_world_step, in agent order (two-call pattern; out_events[0].size set):
 *  the host drains them on its own thread, as Box2D's event arrays. They stay until the next step.
 *  Thread-safe. */
NL_API nl_status nl_world_get_agent_events(const nl_world* world, nl_agent_event* out_events, uint32_t capacity,
                                           uint32_t* out_count);

/* ---------------------------------------------------------------------------------------------
 * Plugins (plugins/include/navlink/plugin.h has the plugin side of the ABI).
 * ------------------------------------------------------------------------------------------- */

/** A plugin loaded in a world. Zero-initialised is the null id. */
typedef struct nl_plugin_id {
    uint32_t index1;
    uint32_t generation;
} nl_plugin_id;

/** Plugin kinds (bits of nl_plugin_description.kinds and nl_plugin_info.kinds). */
#define NL_PLUGIN_NAVMESH_BUILDER 0x1u
#define NL_PLUGIN_LINK_KIND 0x2u

/** Loads a plugin from a shared library (`path`, borrowed NUL-terminated UTF-8) into the world: finds
 *  its entry symbol, negotiates the ABI version and registers what it provides. The library stays
 *  loaded until the world is destroyed.
 *  Returns SUCCESS, or a failure with NOT_FOUND (no such file, or no entry symbol: the message says
 *  which), IO_ERROR (the file is not a loadable library; the loader's message is included),
 *  VERSION_MISMATCH (the plugin speaks no ABI version this library does), INVALID_ARGUMENT (a plugin
 *  with that name is already loaded, or the plugin described itself wrongly). Thread-safe. */
NL_API nl_status nl_plugin_load(nl_world* world, const char* path, nl_plugin_id* out_id);

/** What a loaded plugin is. Strings are owned by the world and live until it is destroyed. */
typedef struct nl_plugin_description {
    uint32_t size;          /**< Set by the caller to sizeof(nl_plugin_description). */
    uint32_t abi_version;   /**< The ABI version agreed with the plugin. */
    uint32_t kinds;         /**< NL_PLUGIN_* bits. */
    uint32_t builtin;       /**< 1 for plugins compiled into the library. */
    const char* name;
    const char* version;
    const char* description;
} nl_plugin_description;

NL_DEFINE_OUTPUT_INIT(nl_plugin_description, nl_plugin_description_init)

/** Describes a plugin. Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe. */
NL_API nl_status nl_plugin_get_description(const nl_world* world, nl_plugin_id plugin,
                                           nl_plugin_description* out_description);

/** Lists the world's plugins, built-in ones first (two-call pattern as nl_world_get_meshes). */
NL_API nl_status nl_world_get_plugins(const nl_world* world, nl_plugin_id* out_ids, uint32_t capacity,
                                      uint32_t* out_count);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_NAVLINK_H */
