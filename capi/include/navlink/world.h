/*
 * navlink/world.h: The world: the root object that owns everything, its log and its host task system.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_WORLD_H
#define NAVLINK_WORLD_H

#include "navlink/base.h"

#ifdef __cplusplus
extern "C" {
#endif

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
 *  Thread-safe.
 *  @param[in,opt] def  How to create the world, or NULL for the defaults.
 *  @param[out] out_world  Receives the new world. */
NL_API nl_status nl_world_create(const nl_world_def* def, nl_world** out_world);

/** Destroys a world and everything it owns; every id from it becomes invalid. NULL is ignored.
 *  Queued path requests first finish as NL_PATH_CANCELLED (their callbacks run, on this thread, and
 *  may still use the world's path functions); running ones are asked to stop and waited for.
 *  Must not run at the same time as any other call on this world.
 *  @param[in,opt] world  The world to destroy, or NULL. */
NL_API void nl_world_destroy(nl_world* world);

/** The number of threads the world uses for batch work (1 when everything runs on the caller; with
 *  task callbacks, the host's worker_count). Returns 0 for a null world. Thread-safe.
 *  @param[in] world  The world. */
NL_API int32_t nl_world_get_worker_count(const nl_world* world);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_WORLD_H */
