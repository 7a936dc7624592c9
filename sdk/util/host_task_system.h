// A TaskSystem that runs NavLink's parallel loops on a host's task system (a game engine's job system)
// instead of TBB, through two functions the host supplies, as Box2D's enqueueTask / finishTask:
// `enqueue` hands the host one parallel loop (a HostTask over `count` items, in ranges of at least
// `min_range`) and returns the host's handle of it; `finish` waits for that handle. The C layer adapts
// nl_world_def's task callbacks to this (capi/src/world_api.cpp).
//
// What it keeps of task_system.h's contract:
//  - Every body runs inside a TaskScope, on whichever thread the host gives it. The calling thread is
//    inside a TaskScope too while it is in `enqueue` and `finish`: whatever host work it runs
//    meanwhile counts as inside a task, so a lock-taking NavLink call from there is refused
//    (TaskSystem::inside_task) instead of waiting on a lock its own thread holds.
//  - An exception from a body reaches the caller of parallel_for: the first one is kept, the ranges
//    the host runs after it skip their bodies (as TBB cancels), and it is rethrown once `finish` has
//    returned, never before (bodies refer to the caller's stack).
//  - execute and execute_exclusive run fn on the calling thread. They hold no place in any queue, so
//    they never wait behind bodies; Embree's BVH builds inside them still use Embree's own TBB
//    threads (its default arena: up to one per hardware thread), which no host scheduler replaces.
//
// What it checks of the host: each range within [0, count) and not empty, each worker index below
// worker_count, and every item run before `finish` returns (or before `enqueue` returns null). A host
// that breaks one fails the parallel_for with ErrorCode::Internal naming what it did; a range out of
// bounds is not run.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "util/task_system.h"

namespace nl {

// One parallel loop handed to the host. The host calls run() over disjoint ranges that cover
// [0, count) once, on any threads, in any order, possibly at the same time.
class HostTask {
public:
    // Runs the loop's body over [begin, end) for host worker `worker` (< worker_count; NavLink's
    // bodies do not depend on it). Never throws: a body's exception, or a bad range, is kept for the
    // caller of parallel_for.
    virtual void run(uint32_t begin, uint32_t end, uint32_t worker) noexcept = 0;

protected:
    ~HostTask() = default;
};

struct HostScheduler {
    // The host's workers: worker indices are below it, and it is thread_count() (>= 1).
    int worker_count = 1;
    // Starts `task` over `count` items in ranges of at least `min_range` (but for the last); returns
    // the host's handle, passed to `finish` once, or null when every range already ran (the host ran
    // them inline). May be called from inside a range of another task (nested work).
    std::function<void*(HostTask& task, uint32_t count, uint32_t min_range)> enqueue;
    // Returns once every range of the task behind `handle` has run. It may run ranges itself (of this
    // task or others of NavLink's), but must not wait for anything the calling thread holds. Must not
    // throw (an exception from it ends the program: bodies could still be running).
    std::function<void(void* handle)> finish;
};

// Throws InvalidArgument naming `enqueue`, `finish` or `worker_count` when one is missing or below 1.
std::unique_ptr<TaskSystem> make_host_task_system(HostScheduler scheduler);

}  // namespace nl
