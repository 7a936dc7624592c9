#include <doctest/doctest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <vector>

#include "util/error.h"
#include "util/handle.h"
#include "util/handle_tag.h"
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
    CHECK(c.revision != a.revision);
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

TEST_CASE("slot map: a handle of another kind is refused, even in a slot of the same number and generation") {
    nl::SlotMap<int> navmeshes(5, nl::HandleKind::NavMesh), agents(5, nl::HandleKind::Agent);
    const nl::Handle navmesh = navmeshes.insert(1);
    const nl::Handle agent = agents.insert(2);
    CHECK((navmesh.index1 & nl::kHandleSlotMask) == (agent.index1 & nl::kHandleSlotMask));  // the same slot
    CHECK(navmesh.revision == agent.revision);
    CHECK(navmesh != agent);
    CHECK(agents.find(navmesh) == nullptr);
    CHECK_FALSE(agents.erase(navmesh));
    CHECK(*agents.find(agent) == 2);  // untouched
    CHECK(navmeshes.find(agent) == nullptr);
    CHECK(agents.handle_at(0) == agent);
    // Removed handles are kept by slot, whatever the kind bits.
    nl::RemovedHandles removed;
    removed.add(agent);
    CHECK(removed.contains(agent));
    CHECK(agents.erase(agent));
    const nl::Handle again = agents.insert(3);  // the slot again, its kind kept
    CHECK(again.index1 == agent.index1);
    CHECK_FALSE(removed.contains(again));
}

TEST_CASE("slot map: a slot whose generations are used up is retired, so no handle ever comes back to life") {
    nl::SlotMap<int> map(5);
    const nl::Handle first = map.insert(0);
    const nl::Handle neighbour = map.insert(-1);
    map.erase(first);
    nl::Handle last = first;
    uint32_t reuses = 0;
    for (;;) {
        const nl::Handle h = map.insert(1);
        if (h.index1 != first.index1) {
            // The slot is retired: the next value went elsewhere.
            CHECK(map.retired() == 1);
            CHECK(h.index1 != neighbour.index1);
            break;
        }
        ++reuses;
        CHECK(h.revision != first.revision);
        last = h;
        map.erase(h);
        REQUIRE(reuses <= nl::SlotMap<int>::kCounterMask);
    }
    CHECK(reuses == nl::SlotMap<int>::kCounterMask - 1);  // counters 2 .. mask after the first
    CHECK(map.find(first) == nullptr);
    CHECK(map.find(last) == nullptr);
    CHECK_FALSE(map.erase(first));
    CHECK(*map.find(neighbour) == -1);
    CHECK(map.size() == 2);
}

TEST_CASE("removed handles: one word per slot tells every removed generation from live ones") {
    nl::SlotMap<int> map(3);
    nl::RemovedHandles removed;
    const nl::Handle a = map.insert(1);
    CHECK_FALSE(removed.contains(a));
    map.erase(a);
    removed.add(a);
    CHECK(removed.contains(a));
    const nl::Handle b = map.insert(2);  // a's slot again
    REQUIRE(b.index1 == a.index1);
    CHECK_FALSE(removed.contains(b));
    CHECK_FALSE(removed.contains(nl::Handle{}));
    CHECK_FALSE(removed.contains(nl::Handle{1000, 1}));
    map.erase(b);
    removed.add(b);
    CHECK(removed.contains(a));
    CHECK(removed.contains(b));
}

TEST_CASE("handle tags: no two live holders share one; every tag can be held, then the next is refused") {
    std::vector<nl::HandleTag> held;
    std::set<uint32_t> values;
    for (;;) {
        try {
            held.push_back(nl::HandleTag::acquire());
        } catch (const nl::Error& e) {
            CHECK(e.code() == nl::ErrorCode::OutOfMemory);
            break;
        }
        CHECK(values.insert(held.back().value()).second);
        REQUIRE(held.size() <= nl::HandleTag::kCount);
    }
    CHECK(held.size() >= nl::HandleTag::kCount - 16);  // other tests' worlds may hold a few
    for (uint32_t v : values) CHECK((v >= 1 && v <= nl::HandleTag::kCount));
    const uint32_t freed = held.front().value();
    held.erase(held.begin());
    const nl::HandleTag again = nl::HandleTag::acquire();
    CHECK(again.value() == freed);  // the only free one
}
