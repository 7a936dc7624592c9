// The one interface all parallel work goes through. The default runs on TBB (Embree brings it);
// a host may supply its own scheduler behind the same interface (host_task_system.h).
//
// The contract that keeps every interleaving of NavLink's thread-safe calls free of deadlock:
//  - A parallel_for body never blocks on a lock (NavLink's bodies read what their caller prepared
//    and write disjoint outputs), so a parallel_for always finishes, whatever else is waiting.
//  - Lock-taking calls (the level's queries and edits) are made only by the thread that called into
//    NavLink, never from inside a body: the level's locks check it (inside_task()).
//  - execute_exclusive() is called while the level's exclusive lock is held (to commit the Embree
//    scene), so it must not wait for anything else: it runs in an arena only it enters, one caller
//    at a time (the lock's holder).
#pragma once

#include <cstdint>
#include <memory>

#include "util/function_ref.h"

namespace nl {

class TaskSystem {
public:
    virtual ~TaskSystem() = default;

    // Threads that may work at once, the calling thread included (>= 1).
    virtual int thread_count() const noexcept = 0;

    // Calls body(begin, end) on disjoint ranges covering [0, count), each about `grain` long, possibly
    // in parallel; returns when all are done. An exception from a body is rethrown here. Bodies run
    // inside a TaskScope; they may call parallel_for again, but must not block on a lock.
    virtual void parallel_for(uint32_t count, uint32_t grain, FunctionRef<void(uint32_t begin, uint32_t end)> body) = 0;

    // Runs fn inside the task system's thread limit, so that parallelism inside libraries called by
    // fn (Embree's BVH builds) uses at most thread_count() threads. fn may run on another thread than
    // the caller's (TBB hands it over when the arena is full): read thread-local state, such as
    // Embree's last error, inside fn. Never waits behind parallel_for bodies.
    virtual void execute(FunctionRef<void()> fn) = 0;
    // The same, for work done while holding a lock other callers wait for: it never queues behind
    // anything, because nothing but such work enters its arena, and only the lock's holder does.
    virtual void execute_exclusive(FunctionRef<void()> fn) = 0;

    // True while the calling thread runs a parallel_for body (of any task system).
    static bool inside_task() noexcept;

protected:
    // Marks the current thread as running a body for as long as it lives; implementations wrap
    // every body call in one.
    class TaskScope {
    public:
        TaskScope() noexcept;
        ~TaskScope();
        TaskScope(const TaskScope&) = delete;
        TaskScope& operator=(const TaskScope&) = delete;
    };
};

// threads < 1 means one thread (the caller).
std::unique_ptr<TaskSystem> make_tbb_task_system(int threads);

}  // namespace nl
