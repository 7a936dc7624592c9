// The link store's snapshots: a reader's snapshot never changes, every edit is seen by the next
// reader, and a navmesh's links keep the order they were added in.
#include <doctest/doctest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "links/link_store.h"

namespace {

nl::Link link_with(uint64_t user_data) {
    nl::Link l;
    l.user_data = user_data;
    return l;
}

std::vector<uint64_t> user_data_of(const nl::LinkSnapshot& snapshot) {
    std::vector<uint64_t> out;
    for (const nl::StoredLink& s : snapshot) out.push_back(s.link.user_data);
    return out;
}

}  // namespace

TEST_CASE("link store: a snapshot stays as it was taken; the next one sees every edit since") {
    nl::LinkStore store(0);
    const nl::Handle navmesh{1, 1};
    CHECK(store.snapshot(navmesh)->empty());

    std::vector<nl::Handle> ids;
    for (uint64_t i = 0; i < 3; ++i) ids.push_back(store.add(navmesh, link_with(i)));
    const auto three = store.snapshot(navmesh);
    CHECK(store.snapshot(navmesh) == three);  // no edit between: the same snapshot, shared
    store.add(navmesh, link_with(3));
    store.update(ids[0], link_with(10));
    store.remove(ids[1]);
    CHECK(user_data_of(*three) == std::vector<uint64_t>{0, 1, 2});
    const auto edited = store.snapshot(navmesh);
    CHECK(user_data_of(*edited) == std::vector<uint64_t>{10, 2, 3});
    CHECK(edited->front().id == ids[0]);

    store.replace_all(navmesh, {link_with(7)});
    CHECK(user_data_of(*store.snapshot(navmesh)) == std::vector<uint64_t>{7});
    CHECK(user_data_of(*edited) == std::vector<uint64_t>{10, 2, 3});
    store.remove_navmesh(navmesh);
    CHECK(store.snapshot(navmesh)->empty());
}

TEST_CASE("link store: readers racing one writer see the links in order, each snapshot whole") {
    nl::LinkStore store(0);
    const nl::Handle navmesh{1, 1};
    constexpr uint64_t kLinks = 3000;
    std::atomic<bool> done{false};
    std::atomic<int> broken{0};
    std::vector<std::thread> readers;
    for (int r = 0; r < 3; ++r) {
        readers.emplace_back([&] {
            size_t last = 0;
            while (!done) {
                const auto snapshot = store.snapshot(navmesh);
                bool ok = snapshot->size() >= last;  // edits only add here: never fewer than before
                for (size_t i = 0; i < snapshot->size(); ++i) ok = ok && (*snapshot)[i].link.user_data == i;
                broken += !ok;
                last = snapshot->size();
            }
        });
    }
    for (uint64_t i = 0; i < kLinks; ++i) store.add(navmesh, link_with(i));
    done = true;
    for (std::thread& t : readers) t.join();
    CHECK(broken == 0);
    CHECK(store.snapshot(navmesh)->size() == kLinks);
}
