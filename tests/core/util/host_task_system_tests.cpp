// The task system over a host's scheduler (util/host_task_system.h), driven by small schedulers written
// here: a thread pool whose finish helps, an inline one, and broken ones that break the contract.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "util/error.h"
#include "util/host_task_system.h"

namespace {

thread_local uint32_t t_worker = 0;  // the pool's threads are 1..threads; any other thread is 0

// A host job system: enqueue splits the range into chunks its threads take; finish helps with the
// chunks of its own task, then waits for the rest.
class Pool {
public:
    explicit Pool(uint32_t threads) : workers_(threads + 1) {
        for (uint32_t i = 1; i <= threads; ++i) threads_.emplace_back([this, i] { loop(i); });
    }
    ~Pool() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        work_.notify_all();
        for (auto& t : threads_) t.join();
    }

    nl::HostScheduler scheduler() {
        nl::HostScheduler s;
        s.worker_count = static_cast<int>(workers_);
        s.enqueue = [this](nl::HostTask& task, uint32_t count, uint32_t min_range) {
            return enqueue(task, count, min_range);
        };
        s.finish = [this](void* handle) { finish(static_cast<Job*>(handle)); };
        return s;
    }

    std::atomic<int> enqueues{0}, finishes{0}, on_pool_threads{0};
    std::atomic<uint32_t> max_min_range{0};

private:
    struct Job {
        nl::HostTask* task;
        uint32_t count, chunk, next = 0, chunks, done = 0;
    };

    void* enqueue(nl::HostTask& task, uint32_t count, uint32_t min_range) {
        ++enqueues;
        max_min_range = std::max(max_min_range.load(), min_range);
        const uint32_t chunk = std::max(min_range, (count + 4 * workers_ - 1) / (4 * workers_));
        auto* job = new Job{&task, count, chunk, 0, (count + chunk - 1) / chunk};
        {
            std::lock_guard lock(mutex_);
            jobs_.push_back(job);
        }
        work_.notify_all();
        return job;
    }

    // Claims the next chunk of `job` (any job when null); false when there is none.
    bool run_one(std::unique_lock<std::mutex>& lock, Job* only) {
        Job* job = nullptr;
        for (Job* j : jobs_)
            if ((!only || j == only) && j->next < j->count) {
                job = j;
                break;
            }
        if (!job) return false;
        const uint32_t begin = job->next, end = std::min(job->count, begin + job->chunk);
        job->next = end;
        lock.unlock();
        if (t_worker != 0) ++on_pool_threads;
        job->task->run(begin, end, t_worker);
        lock.lock();
        if (++job->done == job->chunks) done_.notify_all();
        return true;
    }

    void finish(Job* job) {
        ++finishes;
        std::unique_lock lock(mutex_);
        while (run_one(lock, job)) {}
        done_.wait(lock, [&] { return job->done == job->chunks; });
        jobs_.erase(std::find(jobs_.begin(), jobs_.end(), job));
        delete job;
    }

    void loop(uint32_t index) {
        t_worker = index;
        std::unique_lock lock(mutex_);
        for (;;) {
            if (run_one(lock, nullptr)) continue;
            if (stop_) return;
            work_.wait(lock);
        }
    }

    const uint32_t workers_;
    std::mutex mutex_;
    std::condition_variable work_, done_;
    std::deque<Job*> jobs_;
    bool stop_ = false;
    std::vector<std::thread> threads_;
};

// Runs every range at once on the calling thread, in ranges of min_range, and returns null.
nl::HostScheduler inline_scheduler(std::atomic<int>& enqueues, std::atomic<int>& finishes) {
    nl::HostScheduler s;
    s.worker_count = 1;
    s.enqueue = [&enqueues](nl::HostTask& task, uint32_t count, uint32_t min_range) -> void* {
        ++enqueues;
        for (uint32_t begin = 0; begin < count; begin += min_range)
            task.run(begin, std::min(count, begin + min_range), 0);
        return nullptr;
    };
    s.finish = [&finishes](void*) { ++finishes; };
    return s;
}

// A scheduler that runs what `ranges` says for a task of any size, on worker `worker`, inline.
nl::HostScheduler broken_scheduler(std::vector<std::pair<uint32_t, int64_t>> ranges, uint32_t worker) {
    nl::HostScheduler s;
    s.worker_count = 2;
    s.enqueue = [ranges, worker](nl::HostTask& task, uint32_t count, uint32_t) -> void* {
        for (auto [begin, end_from_count] : ranges)
            task.run(begin, static_cast<uint32_t>(count + end_from_count), worker);
        return nullptr;
    };
    s.finish = [](void*) {};
    return s;
}

// parallel_for over `count` with `grain`; every index must be visited exactly once, inside a task.
void expect_each_index_once(nl::TaskSystem& tasks, uint32_t count, uint32_t grain) {
    std::vector<std::atomic<int>> visits(count);
    std::atomic<int> outside{0};
    tasks.parallel_for(count, grain, [&](uint32_t begin, uint32_t end) {
        if (!nl::TaskSystem::inside_task()) ++outside;
        for (uint32_t i = begin; i < end; ++i) ++visits[i];
    });
    int wrong = 0;
    for (auto& v : visits) wrong += v.load() != 1;
    CHECK_MESSAGE(wrong == 0, wrong << " of " << count << " indices not visited exactly once (grain " << grain << ")");
    CHECK(outside == 0);
    CHECK_FALSE(nl::TaskSystem::inside_task());
}

}  // namespace

TEST_CASE("host task system: parallel_for covers every index exactly once, on the host's threads") {
    Pool pool(2);
    auto tasks = nl::make_host_task_system(pool.scheduler());
    CHECK(tasks->thread_count() == 3);
    for (uint32_t count : {1u, 2u, 63u, 64u, 65u, 1000u, 100003u})
        for (uint32_t grain : {0u, 1u, 7u, 64u, 512u}) expect_each_index_once(*tasks, count, grain);
    CHECK(pool.enqueues > 0);
    CHECK(pool.finishes == pool.enqueues);  // the pool never returns null
    // The work really goes to the pool's threads: the caller, helping in finish, waits (up to 10 s) in
    // its range until a pool thread has run one.
    tasks->parallel_for(64, 1, [&](uint32_t, uint32_t) {
        if (t_worker == 0)
            for (int wait = 0; wait < 10000 && pool.on_pool_threads == 0; ++wait)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
    CHECK(pool.on_pool_threads > 0);
}

TEST_CASE("host task system: a loop of one range runs on the caller, without the host") {
    Pool pool(1);
    auto tasks = nl::make_host_task_system(pool.scheduler());
    const auto caller = std::this_thread::get_id();
    bool on_caller = false, inside = false;
    tasks->parallel_for(100, 100, [&](uint32_t begin, uint32_t end) {
        on_caller = std::this_thread::get_id() == caller && begin == 0 && end == 100;
        inside = nl::TaskSystem::inside_task();
    });
    CHECK(on_caller);
    CHECK(inside);
    CHECK(pool.enqueues == 0);
    tasks->parallel_for(0, 1, [&](uint32_t, uint32_t) { FAIL("a body for no items"); });
    CHECK(pool.enqueues == 0);
    tasks->parallel_for(101, 100, [&](uint32_t, uint32_t) {});
    CHECK(pool.enqueues == 1);
    CHECK(pool.max_min_range == 100);  // the grain is the minimum range the host is asked for
}

TEST_CASE("host task system: an exception in a body reaches the caller after the task finished") {
    Pool pool(2);
    auto tasks = nl::make_host_task_system(pool.scheduler());
    std::atomic<int> running{0};
    try {
        tasks->parallel_for(10000, 16, [&](uint32_t begin, uint32_t) {
            ++running;
            std::this_thread::yield();
            --running;
            if (begin >= 5000) nl::fail(nl::ErrorCode::NotFound, "no item ", begin);
        });
        FAIL("nothing was thrown");
    } catch (const nl::Error& e) {
        CHECK(e.code() == nl::ErrorCode::NotFound);  // the body's own exception, not a wrapper
        CHECK(std::string(e.what()).rfind("no item ", 0) == 0);
    }
    CHECK(running == 0);  // no body outlives the call
    CHECK(pool.finishes == pool.enqueues);
    // The task system is still usable afterwards.
    expect_each_index_once(*tasks, 5000, 10);
    // Any exception type, also from the inline path.
    CHECK_THROWS_AS(tasks->parallel_for(10, 100, [](uint32_t, uint32_t) { throw std::out_of_range("x"); }),
                    std::out_of_range);
}

TEST_CASE("host task system: a body may run parallel_for again (nested), on the host's threads") {
    Pool pool(2);
    auto tasks = nl::make_host_task_system(pool.scheduler());
    constexpr uint32_t kOuter = 16, kInner = 2000;
    std::vector<std::atomic<int>> visits(kOuter * kInner);
    std::atomic<int> nested_on_pool{0}, outside{0};
    tasks->parallel_for(kOuter, 1, [&](uint32_t begin, uint32_t end) {
        // The caller waits (up to 10 s) until a pool thread has taken an outer range, so that nested
        // loops really start on the pool's threads however fast the caller would be alone.
        if (t_worker == 0)
            for (int wait = 0; wait < 10000 && nested_on_pool == 0; ++wait)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        for (uint32_t o = begin; o < end; ++o) {
            if (t_worker != 0) ++nested_on_pool;  // this enqueue and finish run on a pool thread
            tasks->parallel_for(kInner, 50, [&](uint32_t b, uint32_t e) {
                if (!nl::TaskSystem::inside_task()) ++outside;
                for (uint32_t i = b; i < e; ++i) ++visits[o * kInner + i];
            });
        }
    });
    int wrong = 0;
    for (auto& v : visits) wrong += v.load() != 1;
    CHECK(wrong == 0);
    CHECK(outside == 0);
    CHECK(pool.enqueues == 1 + static_cast<int>(kOuter));
    CHECK(pool.finishes == pool.enqueues);
    CHECK(nested_on_pool > 0);
}

TEST_CASE("host task system: an inline host (enqueue runs everything and returns null) is never asked to finish") {
    std::atomic<int> enqueues{0}, finishes{0};
    auto tasks = nl::make_host_task_system(inline_scheduler(enqueues, finishes));
    for (uint32_t count : {2u, 100u, 4097u}) expect_each_index_once(*tasks, count, 1);
    CHECK(enqueues == 3);
    CHECK(finishes == 0);
}

TEST_CASE("host task system: the calling thread counts as inside a task while it waits for the host") {
    // Host work run by the waiting thread must not take NavLink's locks (the level refuses them
    // inside a task): the thread holds some of them across the wait.
    bool inside_enqueue = false, inside_finish = false;
    nl::HostScheduler s;
    s.worker_count = 1;
    s.enqueue = [&](nl::HostTask& task, uint32_t count, uint32_t) -> void* {
        inside_enqueue = nl::TaskSystem::inside_task();
        task.run(0, count, 0);
        return &task;
    };
    s.finish = [&](void*) { inside_finish = nl::TaskSystem::inside_task(); };
    auto tasks = nl::make_host_task_system(std::move(s));
    tasks->parallel_for(10, 1, [](uint32_t, uint32_t) {});
    CHECK(inside_enqueue);
    CHECK(inside_finish);
    CHECK_FALSE(nl::TaskSystem::inside_task());
}

TEST_CASE("host task system: execute and execute_exclusive run on the calling thread") {
    Pool pool(1);
    auto tasks = nl::make_host_task_system(pool.scheduler());
    const auto caller = std::this_thread::get_id();
    int ran = 0;
    tasks->execute([&] { ran += std::this_thread::get_id() == caller; });
    tasks->execute_exclusive([&] { ran += std::this_thread::get_id() == caller; });
    CHECK(ran == 2);
    CHECK(pool.enqueues == 0);
}

TEST_CASE("host task system: a host that breaks the contract fails the call, naming what it did") {
    const auto fails_with = [](nl::HostScheduler s, const char* needle) {
        auto tasks = nl::make_host_task_system(std::move(s));
        std::atomic<uint32_t> largest_end{0};
        try {
            tasks->parallel_for(100, 10, [&](uint32_t, uint32_t end) {
                uint32_t seen = largest_end;
                while (end > seen && !largest_end.compare_exchange_weak(seen, end)) {}
            });
            FAIL("the broken host was not noticed (", needle, ")");
        } catch (const nl::Error& e) {
            CHECK(e.code() == nl::ErrorCode::Internal);
            CHECK_MESSAGE(std::string(e.what()).find(needle) != std::string::npos, e.what());
        }
        CHECK(largest_end <= 100);  // a range past the end is never run
    };
    fails_with(broken_scheduler({{0, 0}, {0, 0}}, 0), "ran 200 items of a task of 100");           // twice
    fails_with(broken_scheduler({{0, -1}}, 0), "ran 99 items of a task of 100");                   // one left out
    fails_with(broken_scheduler({{0, 1}}, 0), "ran items [0, 101) on worker 0 of a task of 100");  // past the end
    fails_with(broken_scheduler({{50, -50}, {0, 0}}, 0), "ran items [50, 50)");                    // an empty range
    fails_with(broken_scheduler({{0, 0}}, 2), "on worker 2 of a task of 100 items with 2 workers");
}

TEST_CASE("host task system: both functions and at least one worker are required") {
    std::atomic<int> enqueues{0}, finishes{0};
    nl::HostScheduler no_enqueue = inline_scheduler(enqueues, finishes);
    no_enqueue.enqueue = nullptr;
    CHECK_THROWS_WITH_AS(nl::make_host_task_system(no_enqueue), doctest::Contains("enqueue"), nl::Error);
    nl::HostScheduler no_finish = inline_scheduler(enqueues, finishes);
    no_finish.finish = nullptr;
    CHECK_THROWS_WITH_AS(nl::make_host_task_system(no_finish), doctest::Contains("finish"), nl::Error);
    nl::HostScheduler no_workers = inline_scheduler(enqueues, finishes);
    no_workers.worker_count = 0;
    CHECK_THROWS_WITH_AS(nl::make_host_task_system(no_workers), doctest::Contains("worker_count"), nl::Error);
}
