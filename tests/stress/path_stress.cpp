// navlink-path-stress: the path queue under load. Several threads submit 100,000 requests (some
// cancelled or released at once) while another thread keeps adding, editing and removing links on
// the navmesh they plan on. Every request must finish exactly once, with an outcome its def allows,
// and its result must stay readable until released. Built and run under ThreadSanitizer by the test
// command. Exits 0 on success, 1 with the first failure described.
#include <navlink/navlink.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cell_navmesh.h"

namespace {

constexpr int kSubmitters = 4;
constexpr int kRequests = 100000;
constexpr int kSide = 24;  // the navmesh: kSide x kSide cells of 1 m, split into two halves by a gap

std::atomic<int> failures{0};

void fail(const std::string& what) {
    if (failures.fetch_add(1) < 10) std::fprintf(stderr, "navlink-path-stress: %s\n", what.c_str());
}

struct Slot {
    std::atomic<int> completions{0};
    std::atomic<uint32_t> outcome{NL_PATH_PENDING};
    nl_path_ticket ticket{};
    bool released_early = false;
};

void on_done(void* user, nl_path_ticket, nl_path_outcome outcome) {
    Slot& slot = *static_cast<Slot*>(user);
    slot.outcome.store(outcome, std::memory_order_relaxed);
    slot.completions.fetch_add(1, std::memory_order_release);
}

// kSide x kSide cells at y = 0; column kSide / 2 is a gap only links cross (when they exist and are
// enabled).
nl_navmesh_id add_navmesh(nl_world* world) {
    std::vector<std::string> rows(kSide, std::string(kSide, '.'));
    for (std::string& row : rows) row[kSide / 2] = '#';
    const nl::test::CellNavmesh cells(rows, 0.0f);
    nl_navmesh_id id{};
    if (nl_navmesh_add(world, &cells.def, &id) != NL_STATUS_SUCCESS)
        fail(std::string("nl_navmesh_add: ") + nl_get_last_error_message());
    return id;
}

// Adds, edits and removes jump links across the gap until told to stop.
void edit_links(nl_world* world, nl_navmesh_id navmesh, const std::atomic<bool>& stop, int& edits) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> row(2, kSide - 3);
    std::vector<nl_link_id> live;
    while (!stop.load()) {
        if (live.size() < 8 || rng() % 3 == 0) {
            nl_link_def def = nl_default_link_def();
            def.kind = NL_LINK_JUMP;
            const float z = float(row(rng)) + 0.5f;
            def.start[0] = kSide / 2 - 0.5f, def.start[2] = z;
            def.end[0] = kSide / 2 + 1.5f, def.end[2] = z;
            def.bidirectional = uint8_t(rng() % 2);
            nl_link_id id{};
            if (nl_link_add(world, navmesh, &def, &id) != NL_STATUS_SUCCESS)
                fail(std::string("nl_link_add: ") + nl_get_last_error_message());
            live.push_back(id);
        } else if (rng() % 2 == 0) {
            nl_link def = nl_link_init();
            nl_link_def update = nl_default_link_def();
            if (nl_link_get(world, live.back(), &def) != NL_STATUS_SUCCESS) fail("nl_link_get on a live link failed");
            for (int i = 0; i < 3; ++i) update.start[i] = def.start[i], update.end[i] = def.end[i];
            update.kind = NL_LINK_JUMP;
            update.enabled = uint8_t(rng() % 2);
            update.cost_modifier = 1.0f + float(rng() % 4);
            if (nl_link_update(world, live.back(), &update) != NL_STATUS_SUCCESS) fail("nl_link_update failed");
        } else {
            const size_t i = rng() % live.size();
            if (nl_link_remove(world, live[i]) != NL_STATUS_SUCCESS) fail("nl_link_remove failed");
            live.erase(live.begin() + long(i));
        }
        ++edits;
    }
}

void submit(nl_world* world, nl_navmesh_id navmesh, std::vector<Slot>& slots, int first, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coordinate(0.2f, kSide - 0.2f);
    for (int i = first; i < first + count; ++i) {
        Slot& slot = slots[i];
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = navmesh;
        def.start[0] = coordinate(rng), def.start[2] = coordinate(rng);
        def.goal[0] = coordinate(rng), def.goal[2] = coordinate(rng);
        def.capabilities.radius = 0.0f;
        def.capabilities.max_jump_distance = (i % 2) ? 3.0f : 0.0f;
        def.accept_partial = uint8_t(i % 3 != 0);
        def.callback = on_done;
        def.user = &slot;
        if (nl_path_request(world, &def, &slot.ticket) != NL_STATUS_SUCCESS) {
            fail(std::string("nl_path_request: ") + nl_get_last_error_message());
            slot.completions.store(1);  // never accepted: no callback will come
            continue;
        }
        if (i % 10 == 0) nl_path_cancel(world, slot.ticket);
        if (i % 7 == 0) {
            slot.released_early = true;
            if (nl_path_release(world, slot.ticket) != NL_STATUS_SUCCESS) fail("early nl_path_release failed");
        }
    }
}

}  // namespace

int main() {
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    def.path_worker_count = 2;
    nl_world* world = nullptr;
    if (nl_world_create(&def, &world) != NL_STATUS_SUCCESS) {
        std::fprintf(stderr, "navlink-path-stress: %s\n", nl_get_last_error_message());
        return 1;
    }
    const nl_navmesh_id navmesh = add_navmesh(world);
    std::vector<Slot> slots(kRequests);

    const auto begin = std::chrono::steady_clock::now();
    std::atomic<bool> stop_editing{false};
    int edits = 0;
    std::thread editor(edit_links, world, navmesh, std::cref(stop_editing), std::ref(edits));
    std::vector<std::thread> submitters;
    for (int t = 0; t < kSubmitters; ++t)
        submitters.emplace_back(submit, world, navmesh, std::ref(slots), t * (kRequests / kSubmitters),
                                kRequests / kSubmitters, unsigned(100 + t));
    for (std::thread& t : submitters) t.join();

    // Every request finishes: wait for the queue to drain (bounded, so a lost request fails the test).
    nl_path_queue_stats stats{};
    stats.size = sizeof stats;
    for (int waited_ms = 0;; waited_ms += 10) {
        nl_path_get_queue_stats(world, &stats);
        if (stats.finished >= stats.submitted && stats.queued == 0 && stats.running == 0) break;
        if (waited_ms > 600000) {
            fail("the queue did not drain in 10 minutes: " + std::to_string(stats.finished) + " of " +
                 std::to_string(stats.submitted) + " finished");
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    stop_editing = true;
    editor.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();

    if (stats.submitted != uint64_t(kRequests)) fail("submitted " + std::to_string(stats.submitted));
    int by_outcome[8] = {};
    std::vector<nl_path_point> points(512, nl_path_point_init());
    for (int i = 0; i < kRequests; ++i) {
        Slot& slot = slots[i];
        const int completions = slot.completions.load(std::memory_order_acquire);
        if (completions != 1)
            fail("request " + std::to_string(i) + " finished " + std::to_string(completions) + " times");
        const uint32_t outcome = slot.outcome.load();
        if (outcome > NL_PATH_FAILED) continue;
        ++by_outcome[outcome];
        const bool allowed = outcome == NL_PATH_COMPLETE || outcome == NL_PATH_CANCELLED ||
                             (outcome == NL_PATH_PARTIAL && i % 3 != 0) || (outcome == NL_PATH_NO_PATH && i % 3 == 0);
        if (!allowed) fail("request " + std::to_string(i) + " ended with outcome " + std::to_string(outcome));
        if ((slot.released_early || i % 10 == 0) && outcome != NL_PATH_CANCELLED && outcome != NL_PATH_COMPLETE &&
            outcome != NL_PATH_PARTIAL && outcome != NL_PATH_NO_PATH)
            fail("request " + std::to_string(i) + " cancelled early ended with outcome " + std::to_string(outcome));
        if (slot.released_early) {
            nl_path_outcome polled = 0;
            if (nl_path_poll(world, slot.ticket, &polled) != (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE))
                fail("a released ticket still answers");
            continue;
        }
        nl_path_result result{};
        result.size = sizeof result;
        uint32_t count = 0;
        const nl_status status =
            nl_path_get_result(world, slot.ticket, &result, points.data(), uint32_t(points.size()), &count);
        if (NL_FAILED(status) || result.outcome != outcome)
            fail("request " + std::to_string(i) + ": result disagrees with its callback");
        if (outcome == NL_PATH_COMPLETE &&
            (count < 2 || std::fabs(points[count - 1].position[0] - result.goal[0]) > 1e-4f))
            fail("request " + std::to_string(i) + ": a complete path that does not end at the goal");
        if (nl_path_release(world, slot.ticket) != NL_STATUS_SUCCESS) fail("nl_path_release failed");
    }
    nl_path_get_queue_stats(world, &stats);
    if (stats.unreleased != 0) fail(std::to_string(stats.unreleased) + " tickets left unreleased");
    nl_world_destroy(world);

    std::printf(
        "requests=%d seconds=%.2f link_edits=%d complete=%d partial=%d no_path=%d cancelled=%d failed=%d failures=%d\n",
        kRequests, seconds, edits, by_outcome[NL_PATH_COMPLETE], by_outcome[NL_PATH_PARTIAL],
        by_outcome[NL_PATH_NO_PATH], by_outcome[NL_PATH_CANCELLED], by_outcome[NL_PATH_FAILED], failures.load());
    return failures.load() == 0 ? 0 : 1;
}
