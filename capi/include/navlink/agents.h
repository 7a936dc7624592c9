/*
 * navlink/agents.h: Agents: bodies that walk their navmesh, take the links their body can, and keep out of each
 * other's way.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_AGENTS_H
#define NAVLINK_AGENTS_H

#include "navlink/queries.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Agents: bodies that walk their navmesh, take the links their body can, and keep out of each
 * other's way. nl_world_step moves every agent; the host reads their states and the step's events
 * in bulk (docs/agents.md).
 * ------------------------------------------------------------------------------------------- */

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
#define NL_AGENT_REASON_WORLD_CHANGED 3u       /**< Its navmesh changed under it: tiles were added or removed
                                                    (nl_navmesh_add_tile, nl_navmesh_remove_tile), or a tile
                                                    it waited for is back. One on a moving surface moves
                                                    whole, its agents with it (nothing to replan). */
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
#define NL_AGENT_REASON_TILE_UNLOADED 9u       /**< The tile it stands on was removed (nl_navmesh_remove_tile):
                                                    it waits where it stood (the WAITING event; nl_agent_info
                                                    reads WAITING with this reason) until a tile holds it
                                                    again, then plans again (REPLANNED, WORLD_CHANGED).
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
 *  the message says how far the nearest navmesh point is). Thread-safe (waits for a step running).
 *  @param[in] world  The world.
 *  @param[in] def  The agent to add.
 *  @param[out] out_id  Receives its id. */
NL_API nl_status nl_agent_add(nl_world* world, const nl_agent_def* def, nl_agent_id* out_id);

/** Removes an agent. Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent to remove. */
NL_API nl_status nl_agent_remove(nl_world* world, nl_agent_id agent);

/** Nonzero if `agent` is an agent of `world`. Thread-safe; from a task callback during nl_world_step
 *  it cannot look (the step holds the agents) and answers 0 ("Callbacks" at the top).
 *  @param[in] world  The world.
 *  @param[in] agent  The id to check. */
NL_API int32_t nl_agent_is_valid(const nl_world* world, nl_agent_id agent);

/** Sends the agent to `point` (3 floats, borrowed), located at once on its navmesh, or else on a
 *  navmesh that cross links join to it (nl_link_def.landing_navmesh: a platform, a ledge across a
 *  chasm): on none of them is NOT_FOUND and the destination is not kept. A destination on a navmesh
 *  that rides a moving mesh is kept in the mesh's space: it moves with the mesh, and the agent
 *  arrives where it is at arrival (docs/moving-surfaces.md). The path is planned in a coming nl_world_step (an agent
 *  in the air lands first). Returns SUCCESS, or INVALID_HANDLE (also for an agent whose navmesh was
 *  removed), INVALID_ARGUMENT, NOT_FOUND. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[in] point  The destination, 3 floats. */
NL_API nl_status nl_agent_set_destination(nl_world* world, nl_agent_id agent, const float* point);

/** Forgets the destination: the agent stops and stands (NL_AGENT_IDLE); one in the air lands first;
 *  one whose navmesh was removed stays NL_AGENT_FAILED. Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent to stop. */
NL_API nl_status nl_agent_stop(nl_world* world, nl_agent_id agent);

/** Puts the agent at the navmesh point of `point`, standing, keeping its destination (it plans again
 *  from there). Returns SUCCESS, or INVALID_HANDLE (also for an agent whose navmesh was removed),
 *  INVALID_ARGUMENT (also while it is taking a link), NOT_FOUND. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[in] point  Where to put it, 3 floats. */
NL_API nl_status nl_agent_teleport(nl_world* world, nl_agent_id agent, const float* point);

/** Changes what the agent's body can do (copied); it plans again. Returns SUCCESS, or INVALID_HANDLE,
 *  INVALID_ARGUMENT (a negative or non-finite figure). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[in] capabilities  What its body can do now. */
NL_API nl_status nl_agent_set_capabilities(nl_world* world, nl_agent_id agent, const nl_agent_capabilities* capabilities);

/** Changes the agent's walking speed and acceleration (each finite and > 0). Returns SUCCESS, or
 *  INVALID_HANDLE, INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[in] max_speed  Walking speed, m/s.
 *  @param[in] max_acceleration  Acceleration, m/s^2. */
NL_API nl_status nl_agent_set_speed(nl_world* world, nl_agent_id agent, float max_speed, float max_acceleration);

/** Advances every agent by `dt` seconds (finite, >= 0; 0 does nothing), in parallel on the world's
 *  task system, with the same result bit for bit whatever the thread count: plans the paths asked
 *  for (at most agent_paths_per_step: agents standing without a path first, then the oldest), steers and moves every agent on the ground,
 *  flies those on links, and checks each link just before take-off. An agent's trouble (no path,
 *  its navmesh removed) is its failure and event, not the call's.
 *  Returns SUCCESS, or INVALID_ARGUMENT (dt NaN, infinite or negative: nothing changes), OUT_OF_MEMORY,
 *  INTERNAL_ERROR (called from a task callback of a step: refused, see "Callbacks" at the top).
 *  Thread-safe: other agent calls wait for it; an agent call from one of its task callbacks is refused.
 *  @param[in] world  The world.
 *  @param[in] dt  Seconds to advance. */
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
    nl_mesh_id carrier;       /**< The movable mesh that navmesh rides, its carrier (the agent rides it
                                   too), or the null id; also the null id while it flies a cross link
                                   (in the world, on no carrier). Added in 0.3. */
    float carrier_position[3]; /**< `position` in the carrier's own space (equal to `position` on no
                                    carrier, and in the air over a cross link): to parent the body to
                                    the platform in the host's scene. Added in 0.3. */
    uint32_t reserved2;
} nl_agent_info;

NL_DEFINE_OUTPUT_INIT(nl_agent_info, nl_agent_info_init)

/** Fills `*out_info` (caller-owned, `size` set). Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT.
 *  Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[out] out_info  Receives its state. */
NL_API nl_status nl_agent_get_info(const nl_world* world, nl_agent_id agent, nl_agent_info* out_info);

/** Every agent's state, in bulk, in a stable order until an agent is removed (two-call pattern as
 *  nl_world_get_meshes; out_infos[0].size set when out_infos is not NULL). Thread-safe.
 *  @param[in] world  The world.
 *  @param[out,opt] out_infos  Receives each agent's state, or NULL to count only.
 *  @param[in] capacity  Entries `out_infos` has room for.
 *  @param[out] out_count  Receives the number of agents. */
NL_API nl_status nl_world_get_agents(const nl_world* world, nl_agent_info* out_infos, uint32_t capacity,
                                     uint32_t* out_count);

/** Where the agent is, then the path points it has yet to reach, the next first (two-call pattern;
 *  out_points[0].size set): where it walks, and at which point it takes which link. The first point
 *  is its position now and how it goes on from there (NL_SEGMENT_WALK, or the link it is flying, with
 *  that link's apex), so a straight walk to the goal is two points; corners_ahead + 1 points in all
 *  (since 0.3; before, the stretch being walked was missing). None when it has no path or has
 *  arrived. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[out,opt] out_points  Receives the points, or NULL to count only.
 *  @param[in] capacity  Points `out_points` has room for.
 *  @param[out] out_count  Receives the number of points. */
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
 *  or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] agent  The agent.
 *  @param[out] out_trajectory  Receives the trajectory. */
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
                                              on; or for its tile (reason TILE_UNLOADED). Said once per
                                              wait. Added in 0.3. */

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
 *  Thread-safe.
 *  @param[in] world  The world.
 *  @param[out,opt] out_events  Receives the events, or NULL to count only.
 *  @param[in] capacity  Entries `out_events` has room for.
 *  @param[out] out_count  Receives the number of events. */
NL_API nl_status nl_world_get_agent_events(const nl_world* world, nl_agent_event* out_events, uint32_t capacity,
                                           uint32_t* out_count);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_AGENTS_H */
