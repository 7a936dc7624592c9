// Queued path requests: a ticket per request, worker threads (or the host's own calls) planning
// them, and a completion callback. Every accepted request finishes exactly once, whether it is
// planned, cancelled, released early or still queued when the queue is destroyed.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "path/path_graph.h"
#include "path/path_query.h"
#include "util/function_ref.h"
#include "util/handle.h"

namespace nl {

// Called once per request when it finishes, outside the queue's lock.
using PathCallback = std::function<void(Handle ticket, PathOutcome outcome)>;

// A finished request, as take_finished hands it over.
struct FinishedRequest {
    Handle ticket;
    PathOutcome outcome = PathOutcome::Pending;
    void* user = nullptr;
};

// How much process() may do in one call; 0 (or <= 0) means no limit. Checked between requests.
struct ProcessBudget {
    uint32_t max_requests = 0;
    double max_milliseconds = 0.0;
    uint64_t max_search_nodes = 0;
};

struct PathQueueStats {
    uint32_t workers = 0;
    uint32_t queued = 0;
    uint32_t running = 0;
    uint32_t unreleased = 0;
    uint64_t submitted = 0;
    uint64_t finished = 0;
};

class PathQueue {
public:
    // `workers` threads plan requests; with 0 only process() does.
    PathQueue(uint32_t handle_tag, unsigned workers);
    // Stops the workers after their current request (running ones are asked to stop); requests still
    // queued finish as Cancelled; later submissions are refused. Callbacks may still call the queue
    // while this runs. Idempotent; the destructor calls it.
    void shutdown();
    ~PathQueue();
    PathQueue(const PathQueue&) = delete;
    PathQueue& operator=(const PathQueue&) = delete;

    // Throws Cancelled once shut down. `user` is the host's, handed back by take_finished.
    Handle submit(std::shared_ptr<const PathGraph> graph, PathQuery query, PathCallback callback, void* user = nullptr);

    // Throw InvalidHandle for an unknown or released ticket.
    PathOutcome poll(Handle ticket) const;
    // Calls `read` with the result under the queue's lock and returns true, or returns false while
    // the request is pending.
    bool read(Handle ticket, FunctionRef<void(const PathResult&)> read) const;
    void cancel(Handle ticket);
    void release(Handle ticket);

    // Blocks until the request has finished or `timeout` has passed, and returns its outcome
    // (Pending on a timeout; a zero timeout polls). With no path workers, it plans queued requests
    // (oldest first, their callbacks on this thread) until this one has finished, checking the time
    // between requests. Throws InvalidHandle for an unknown or released ticket (also one released by
    // another thread meanwhile), and InvalidArgument from a path callback: it runs on a thread that
    // finishes requests, so it could wait for itself.
    PathOutcome wait(Handle ticket, std::chrono::steady_clock::duration timeout);

    // Plans queued requests on the calling thread within the budget (at least one when any is
    // queued); returns how many it finished.
    uint32_t process(const ProcessBudget& budget);

    // Moves up to `capacity` requests finished since the last call (oldest first, released ones left
    // out) into `out`; returns how many still wait.
    uint32_t take_finished(uint32_t capacity, std::vector<FinishedRequest>& out);

    PathQueueStats stats() const;

private:
    struct Job {
        std::shared_ptr<const PathGraph> graph;
        PathQuery query;
        PathCallback callback;
        std::atomic<bool> cancel{false};
    };
    struct Ticket {
        std::shared_ptr<Job> job;
        PathResult result;  // outcome Pending until finished
        bool running = false;
        bool released = false;
        void* user = nullptr;
    };

    void work();
    // Takes the next queued request and plans it; false if none was queued. Called with `lock` held;
    // returns with it held. Adds the polygons its search visited to `nodes_visited`.
    bool run_next(std::unique_lock<std::mutex>& lock, uint64_t& nodes_visited);
    // Records the outcome and calls the callback with the lock released.
    void finish(std::unique_lock<std::mutex>& lock, Handle ticket, PathResult result);
    // Cancelled and released requests leave their entries in queue_ until popped; with nothing
    // popping (no path workers, no process() calls) they would pile up: dropped once they are most of
    // it, so the queue stays within twice what is queued.
    void drop_finished_entries() noexcept;
    Ticket& find(Handle ticket);
    const Ticket& find(Handle ticket) const;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable request_finished_;  // notified each time a request finishes
    SlotMap<Ticket> tickets_;
    std::deque<Handle> queue_;  // may hold tickets cancelled or released since: skipped
    // Finished requests not taken yet; may hold released tickets (skipped, and dropped once they are
    // most of it, so it stays within about twice the tickets alive).
    std::deque<Handle> finished_list_;
    uint32_t queued_ = 0;
    uint32_t running_ = 0;
    uint64_t submitted_ = 0;
    uint64_t finished_ = 0;          // callbacks returned too
    uint32_t released_running_ = 0;  // released tickets kept until their request finishes
    bool stopping_ = false;
    std::vector<std::thread> workers_;
};

}  // namespace nl
