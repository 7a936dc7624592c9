/*
 * navlink/paths.h: Paths: found at once or queued, for the body that will walk them, and why one falls short.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_PATHS_H
#define NAVLINK_PATHS_H

#include "navlink/navmesh_file.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Paths: A* over a navmesh's polygons and links, filtered per request by what the agent's body can
 * do, then string-pulled into points that say how each segment is travelled (walk, jump, drop...).
 * Requests read an immutable snapshot of the navmesh and its links taken when they are made: editing
 * links meanwhile never blocks nor disturbs them (docs/pathfinding.md).
 * ------------------------------------------------------------------------------------------- */

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
    nl_agent_capabilities capabilities;
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
    float carrier_position[3]; /**< The point in its navmesh's own space: where it stays on a navmesh
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
 *  (the result is written, the points are not), OUT_OF_MEMORY. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] def  The request.
 *  @param[out] out_result  Receives the result.
 *  @param[out,opt] out_points  Receives the points, or NULL to count only.
 *  @param[in] capacity  Points `out_points` has room for.
 *  @param[out] out_count  Receives the number of points. */
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
 *  Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] def  The request.
 *  @param[out] out_shortfall  Receives why its path falls short. */
NL_API nl_status nl_path_explain(nl_world* world, const nl_path_request_def* def, nl_path_shortfall* out_shortfall);

/** Queues a path request and returns at once with its ticket in `*out_ticket`. The request reads the
 *  navmesh and links as they are now. `def` is borrowed and copied. Path workers plan it (or
 *  nl_path_process when path_worker_count is 0); poll the ticket or receive the callback, read the
 *  result, then release the ticket. Every accepted request finishes exactly once.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh), INVALID_ARGUMENT (as nl_path_find),
 *  OUT_OF_MEMORY; on failure no ticket is made and the callback is never called. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] def  The request.
 *  @param[out] out_ticket  Receives its ticket. */
NL_API nl_status nl_path_request(nl_world* world, const nl_path_request_def* def, nl_path_ticket* out_ticket);

/** Writes the request's outcome (NL_PATH_PENDING while it runs) to `*out_outcome`.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (null, released or foreign ticket) or
 *  INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] ticket  The request.
 *  @param[out] out_outcome  Receives its outcome. */
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
 *  Thread-safe: any number of threads can wait, for the same ticket or others.
 *  @param[in] world  The world.
 *  @param[in] ticket  The request.
 *  @param[in] timeout_ms  How long to wait at most, or NL_PATH_WAIT_FOREVER.
 *  @param[out] out_outcome  Receives its outcome. */
NL_API nl_status nl_path_wait(nl_world* world, nl_path_ticket ticket, uint32_t timeout_ms, nl_path_outcome* out_outcome);

/** Copies a finished request's result and points, as nl_path_find. Can be called any number of times
 *  until the ticket is released. Returns SUCCESS (with PARTIAL_RESULT for NL_PATH_PARTIAL),
 *  NL_STATUS_IN_PROGRESS (not finished; nothing written), or a failure with INVALID_HANDLE,
 *  INVALID_ARGUMENT or BUFFER_TOO_SMALL (result written, points not). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] ticket  The request.
 *  @param[out] out_result  Receives the result.
 *  @param[out,opt] out_points  Receives the points, or NULL to count only.
 *  @param[in] capacity  Points `out_points` has room for.
 *  @param[out] out_count  Receives the number of points. */
NL_API nl_status nl_path_get_result(const nl_world* world, nl_path_ticket ticket, nl_path_result* out_result,
                                    nl_path_point* out_points, uint32_t capacity, uint32_t* out_count);

/** Asks a request to stop. A request not started yet finishes at once as NL_PATH_CANCELLED (its
 *  callback runs on this thread); a running one stops at its next check (every 64 polygons the
 *  search expands) unless it finishes first; a finished one is unchanged.
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] ticket  The request to stop. */
NL_API nl_status nl_path_cancel(nl_world* world, nl_path_ticket ticket);

/** Frees a request's result; the ticket becomes invalid at once. Releasing an unfinished request
 *  cancels it; its callback still runs once (on this thread if it had not started). Returns SUCCESS
 *  or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] ticket  The ticket to release. */
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
 *  Returns SUCCESS or INVALID_ARGUMENT (NaN milliseconds, `size` too small). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in,opt] budget  How much to do, or NULL for no limits.
 *  @param[out,opt] out_processed  Receives how many requests finished here, or NULL. */
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
 *  too small). Thread-safe: each finished request is taken by one call only.
 *  @param[in] world  The world.
 *  @param[out,opt] out_finished  Receives the finished requests, or NULL to take none.
 *  @param[in] capacity  Entries `out_finished` has room for.
 *  @param[out] out_count  Receives how many were written.
 *  @param[out,opt] out_remaining  Receives how many still wait, or NULL. */
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

/** Fills `*out_stats` (caller-owned, `size` set). Returns SUCCESS or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[out] out_stats  Receives the counters. */
NL_API nl_status nl_path_get_queue_stats(const nl_world* world, nl_path_queue_stats* out_stats);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_PATHS_H */
