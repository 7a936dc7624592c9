#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "util/task_system.h"
#include "util/tsan.h"

namespace nl {
namespace {

class TbbTaskSystem final : public TaskSystem {
public:
    explicit TbbTaskSystem(int threads)
        : threads_(std::max(1, threads)), work_arena_(threads_), build_arena_(threads_), exclusive_arena_(threads_) {}

    int thread_count() const noexcept override { return threads_; }

    void parallel_for(uint32_t count, uint32_t grain, FunctionRef<void(uint32_t, uint32_t)> body) override {
        if (count == 0) return;
        grain = std::max<uint32_t>(1, grain);
        if (threads_ == 1 || count <= grain) {
            TaskScope scope;
            body(0, count);
            return;
        }
        char started = 0, finished = 0;  // ThreadSanitizer's view of what TBB guarantees
        tsan_release(&started);
        work_arena_.execute([&] {
            tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, grain),
                              [&](const tbb::blocked_range<uint32_t>& r) {
                                  tsan_acquire(&started);
                                  {
                                      TaskScope scope;
                                      body(r.begin(), r.end());
                                  }
                                  tsan_release(&finished);
                              });
        });
        tsan_acquire(&finished);
    }

    // Arenas of their own: a build must not queue for a slot that a long parallel_for holds, and a
    // commit made under the level's exclusive lock not even behind another build (every query waits
    // for it meanwhile).
    void execute(FunctionRef<void()> fn) override { run_in(build_arena_, fn); }
    void execute_exclusive(FunctionRef<void()> fn) override { run_in(exclusive_arena_, fn); }

private:
    static void run_in(tbb::task_arena& arena, FunctionRef<void()> fn) {
        char started = 0, finished = 0;  // fn may run on another thread (TBB hands it over)
        tsan_release(&started);
        arena.execute([&] {
            tsan_acquire(&started);
            fn();
            tsan_release(&finished);
        });
        tsan_acquire(&finished);
    }

    int threads_;
    tbb::task_arena work_arena_;
    tbb::task_arena build_arena_;
    tbb::task_arena exclusive_arena_;
};

}  // namespace

std::unique_ptr<TaskSystem> make_tbb_task_system(int threads) { return std::make_unique<TbbTaskSystem>(threads); }

}  // namespace nl
