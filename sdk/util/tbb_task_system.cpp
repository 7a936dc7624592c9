#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "util/task_system.h"

namespace nl {
namespace {

class TbbTaskSystem final : public TaskSystem {
public:
    explicit TbbTaskSystem(int threads) : threads_(std::max(1, threads)), arena_(threads_) {}

    int thread_count() const noexcept override { return threads_; }

    void parallel_for(uint32_t count, uint32_t grain,
                      FunctionRef<void(uint32_t, uint32_t)> body) override {
        if (count == 0) return;
        grain = std::max<uint32_t>(1, grain);
        if (threads_ == 1 || count <= grain) {
            body(0, count);
            return;
        }
        arena_.execute([&] {
            tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, grain),
                              [&](const tbb::blocked_range<uint32_t>& r) { body(r.begin(), r.end()); });
        });
    }

    void execute(FunctionRef<void()> fn) override {
        arena_.execute([&] { fn(); });
    }

private:
    int threads_;
    tbb::task_arena arena_;
};

}  // namespace

std::unique_ptr<TaskSystem> make_tbb_task_system(int threads) {
    return std::make_unique<TbbTaskSystem>(threads);
}

}  // namespace nl
