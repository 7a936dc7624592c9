#include "util/host_task_system.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <utility>

#include "util/error.h"

namespace nl {
namespace {

class HostTaskSystem final : public TaskSystem {
public:
    explicit HostTaskSystem(HostScheduler scheduler) : scheduler_(std::move(scheduler)) {}

    int thread_count() const noexcept override { return scheduler_.worker_count; }

    void parallel_for(uint32_t count, uint32_t grain, FunctionRef<void(uint32_t, uint32_t)> body) override {
        if (count == 0) return;
        grain = std::max<uint32_t>(1, grain);
        if (count <= grain) {  // one range: nothing to share out, so no round trip through the host
            TaskScope scope;
            body(0, count);
            return;
        }
        Task task(body, count, static_cast<uint32_t>(scheduler_.worker_count));
        {
            // Host work this thread runs while it waits counts as inside a task (see the header).
            TaskScope scope;
            void* const handle = scheduler_.enqueue(task, count, grain);
            if (handle) finish(handle);
        }
        task.check();
    }

    void execute(FunctionRef<void()> fn) override { fn(); }
    void execute_exclusive(FunctionRef<void()> fn) override { fn(); }

private:
    class Task final : public HostTask {
    public:
        Task(FunctionRef<void(uint32_t, uint32_t)> body, uint32_t count, uint32_t workers)
            : body_(body), count_(count), workers_(workers) {}

        void run(uint32_t begin, uint32_t end, uint32_t worker) noexcept override {
            if (begin >= end || end > count_ || worker >= workers_) {
                note_host_error(begin, end, worker);
                return;
            }
            ran_.fetch_add(end - begin, std::memory_order_relaxed);
            if (failed_.load(std::memory_order_relaxed)) return;  // a body threw: skip the rest
            try {
                TaskScope scope;
                body_(begin, end);
            } catch (...) {
                std::lock_guard lock(mutex_);
                if (!exception_) exception_ = std::current_exception();
                failed_.store(true, std::memory_order_relaxed);
            }
        }

        // After the host said the task is done: what went wrong, first the host's part.
        void check() {
            std::lock_guard lock(mutex_);
            if (host_error_)
                fail(ErrorCode::Internal, "the host's task system ran items [", bad_begin_, ", ", bad_end_,
                     ") on worker ", bad_worker_, " of a task of ", count_, " items with ", workers_,
                     " workers (each range must lie in [0, item count) and each worker index be below worker_count)");
            if (exception_) std::rethrow_exception(exception_);
            const uint64_t ran = ran_.load(std::memory_order_relaxed);
            if (ran != count_)
                fail(ErrorCode::Internal, "the host's task system ran ", ran, " items of a task of ", count_,
                     " before saying it was done (each item must run exactly once before the finish callback returns, "
                     "or the enqueue callback returns NULL)");
        }

    private:
        void note_host_error(uint32_t begin, uint32_t end, uint32_t worker) noexcept {
            std::lock_guard lock(mutex_);
            failed_.store(true, std::memory_order_relaxed);
            if (host_error_) return;
            host_error_ = true;
            bad_begin_ = begin;
            bad_end_ = end;
            bad_worker_ = worker;
        }

        FunctionRef<void(uint32_t, uint32_t)> body_;
        const uint32_t count_;
        const uint32_t workers_;
        std::atomic<uint64_t> ran_{0};
        std::atomic<bool> failed_{false};
        std::mutex mutex_;  // guards what follows
        std::exception_ptr exception_;
        bool host_error_ = false;
        uint32_t bad_begin_ = 0, bad_end_ = 0, bad_worker_ = 0;
    };

    // noexcept: a finish that throws leaves bodies that may still use this stack frame; stop here.
    void finish(void* handle) noexcept { scheduler_.finish(handle); }

    HostScheduler scheduler_;
};

}  // namespace

std::unique_ptr<TaskSystem> make_host_task_system(HostScheduler scheduler) {
    if (!scheduler.enqueue) fail_field(ErrorCode::InvalidArgument, "enqueue is not set (set both enqueue and finish)");
    if (!scheduler.finish) fail_field(ErrorCode::InvalidArgument, "finish is not set (set both enqueue and finish)");
    if (scheduler.worker_count < 1)
        fail_field(ErrorCode::InvalidArgument, "worker_count is ", scheduler.worker_count, " (at least 1)");
    return std::make_unique<HostTaskSystem>(std::move(scheduler));
}

}  // namespace nl
