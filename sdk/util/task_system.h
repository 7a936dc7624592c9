// The one interface all parallel work goes through. The default runs on TBB (Embree brings it);
// a host may later supply its own scheduler behind the same interface.
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
    // in parallel; returns when all are done. An exception from a body is rethrown here.
    virtual void parallel_for(uint32_t count, uint32_t grain,
                              FunctionRef<void(uint32_t begin, uint32_t end)> body) = 0;

    // Runs fn inside the task system's thread limit, so that parallelism inside libraries called by
    // fn (Embree's BVH builds) uses at most thread_count() threads.
    virtual void execute(FunctionRef<void()> fn) = 0;
};

// threads < 1 means one thread (the caller).
std::unique_ptr<TaskSystem> make_tbb_task_system(int threads);

}  // namespace nl
