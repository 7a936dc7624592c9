#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "util/handle.h"
#include "util/task_system.h"

TEST_CASE("slot map: stale handles are recognised after their slot is reused") {
    nl::SlotMap<int> map;
    const nl::Handle a = map.insert(1);
    const nl::Handle b = map.insert(2);
    CHECK(*map.find(a) == 1);
    CHECK(map.erase(a));
    CHECK_FALSE(map.erase(a));
    CHECK(map.find(a) == nullptr);
    const nl::Handle c = map.insert(3);  // reuses a's slot
    CHECK(c.index1 == a.index1);
    CHECK(c.generation != a.generation);
    CHECK(map.find(a) == nullptr);
    CHECK(*map.find(c) == 3);
    CHECK(*map.find(b) == 2);
    CHECK(map.find(nl::Handle{}) == nullptr);
    CHECK(map.find(nl::Handle{99, 1}) == nullptr);
    CHECK(map.size() == 2);
}

TEST_CASE("task system: parallel_for covers every index exactly once, for 1 and 2 threads") {
    for (int threads : {1, 2}) {
        auto tasks = nl::make_tbb_task_system(threads);
        CHECK(tasks->thread_count() == threads);
        for (uint32_t count : {0u, 1u, 7u, 1000u, 100003u}) {
            std::vector<std::atomic<int>> seen(count);
            tasks->parallel_for(count, 64, [&](uint32_t begin, uint32_t end) {
                for (uint32_t i = begin; i < end; ++i) seen[i].fetch_add(1);
            });
            int wrong = 0;
            for (auto& s : seen) wrong += s.load() != 1;
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("task system: an exception in a body reaches the caller") {
    auto tasks = nl::make_tbb_task_system(2);
    CHECK_THROWS_AS(tasks->parallel_for(10000, 16,
                                        [](uint32_t begin, uint32_t) {
                                            if (begin > 5000) throw std::runtime_error("body failed");
                                        }),
                    std::runtime_error);
}

TEST_CASE("slot map: handles from a map with another tag are refused") {
    nl::SlotMap<int> mine(1), theirs(2);
    const nl::Handle a = mine.insert(1);
    const nl::Handle b = theirs.insert(2);
    CHECK(a.index1 == b.index1);
    CHECK(mine.find(b) == nullptr);
    CHECK(theirs.find(a) == nullptr);
    CHECK_FALSE(mine.erase(b));
    CHECK(mine.size() == 1);
}
