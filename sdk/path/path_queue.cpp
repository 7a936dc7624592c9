#include "path/path_queue.h"

#include <algorithm>
#include <chrono>
#include <new>

#include "path/path_planner.h"
#include "util/error.h"

namespace nl {
namespace {

PathResult failed(ErrorCode code) {
    PathResult result;
    result.outcome = PathOutcome::Failed;
    result.failure = static_cast<uint32_t>(code);
    return result;
}

// Set while this thread runs a path callback.
thread_local bool in_path_callback = false;

struct InPathCallback {
    InPathCallback() : outer(in_path_callback) { in_path_callback = true; }
    ~InPathCallback() { in_path_callback = outer; }
    bool outer;
};

PathResult cancelled() {
    PathResult result;
    result.outcome = PathOutcome::Cancelled;
    return result;
}

}  // namespace

PathQueue::PathQueue(uint32_t handle_tag, unsigned workers) : tickets_(handle_tag, HandleKind::PathTicket) {
    try {
        for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { work(); });
    } catch (...) {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (std::thread& worker : workers_) worker.join();
        throw;
    }
}

void PathQueue::shutdown() {
    {
        std::lock_guard lock(mutex_);
        if (stopping_) return;
        stopping_ = true;
        tickets_.for_each([](Handle, const Ticket& t) {
            if (t.running) t.job->cancel.store(true, std::memory_order_relaxed);
        });
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
    std::unique_lock lock(mutex_);
    while (!queue_.empty()) {
        const Handle h = queue_.front();
        queue_.pop_front();
        Ticket* ticket = tickets_.find(h);
        if (!ticket || ticket->running || ticket->result.outcome != PathOutcome::Pending) continue;
        --queued_;
        finish(lock, h, cancelled());
    }
}

PathQueue::~PathQueue() { shutdown(); }

Handle PathQueue::submit(std::shared_ptr<const PathGraph> graph, PathQuery query, PathCallback callback, void* user) {
    auto job = std::make_shared<Job>();
    job->graph = std::move(graph);
    job->query = std::move(query);
    job->callback = std::move(callback);
    Handle h;
    {
        std::lock_guard lock(mutex_);
        // A callback answering the shutdown's cancellations with new requests would never end it.
        if (stopping_) fail(ErrorCode::Cancelled, "the world is being destroyed");
        h = tickets_.insert(Ticket{std::move(job), PathResult{}, false, false, user});
        try {
            queue_.push_back(h);
        } catch (...) {
            tickets_.erase(h);  // not accepted: no ticket, no callback
            throw;
        }
        ++queued_;
        ++submitted_;
    }
    wake_.notify_one();
    return h;
}

PathQueue::Ticket& PathQueue::find(Handle ticket) {
    Ticket* found = tickets_.find(ticket);
    if (!found || found->released) fail_stale("path ticket", ticket);
    return *found;
}

const PathQueue::Ticket& PathQueue::find(Handle ticket) const { return const_cast<PathQueue*>(this)->find(ticket); }

PathOutcome PathQueue::poll(Handle ticket) const {
    std::lock_guard lock(mutex_);
    return find(ticket).result.outcome;
}

bool PathQueue::read(Handle ticket, FunctionRef<void(const PathResult&)> read) const {
    std::lock_guard lock(mutex_);
    const Ticket& t = find(ticket);
    if (t.result.outcome == PathOutcome::Pending) return false;
    read(t.result);
    return true;
}

void PathQueue::cancel(Handle ticket) {
    std::unique_lock lock(mutex_);
    Ticket& t = find(ticket);
    if (t.result.outcome != PathOutcome::Pending) return;
    if (t.running) {
        t.job->cancel.store(true, std::memory_order_relaxed);
        return;
    }
    --queued_;
    finish(lock, ticket, cancelled());
    drop_finished_entries();
}

void PathQueue::release(Handle ticket) {
    std::unique_lock lock(mutex_);
    Ticket& t = find(ticket);
    if (t.result.outcome != PathOutcome::Pending) {
        tickets_.erase(ticket);
        if (finished_list_.size() > 2 * size_t(tickets_.size()) + 64) {
            finished_list_.erase(std::remove_if(finished_list_.begin(), finished_list_.end(),
                                                [&](Handle h) { return tickets_.find(h) == nullptr; }),
                                 finished_list_.end());
        }
        return;
    }
    t.released = true;  // the ticket goes when the request finishes
    if (t.running) {
        t.job->cancel.store(true, std::memory_order_relaxed);
        ++released_running_;
        return;
    }
    --queued_;
    finish(lock, ticket, cancelled());
    drop_finished_entries();
}

void PathQueue::drop_finished_entries() noexcept {
    if (queue_.size() <= 2 * size_t(queued_) + 64) return;
    queue_.erase(std::remove_if(queue_.begin(), queue_.end(),
                                [&](Handle h) {
                                    const Ticket* t = tickets_.find(h);
                                    return !t || t->running || t->result.outcome != PathOutcome::Pending;
                                }),
                 queue_.end());
}

void PathQueue::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stopping_ || queued_ > 0; });
        if (stopping_) return;
        uint64_t nodes = 0;
        run_next(lock, nodes);
    }
}

bool PathQueue::run_next(std::unique_lock<std::mutex>& lock, uint64_t& nodes_visited) {
    while (!queue_.empty()) {
        const Handle h = queue_.front();
        queue_.pop_front();
        Ticket* ticket = tickets_.find(h);
        if (!ticket || ticket->running || ticket->result.outcome != PathOutcome::Pending) continue;
        ticket->running = true;
        --queued_;
        ++running_;
        const std::shared_ptr<Job> job = ticket->job;
        lock.unlock();
        PathResult result;
        try {
            plan_path(*job->graph, job->query, &job->cancel, result);
        } catch (const std::bad_alloc&) {
            result = failed(ErrorCode::OutOfMemory);
        } catch (const Error& e) {
            result = failed(e.code());
        } catch (...) {
            result = failed(ErrorCode::Internal);
        }
        nodes_visited += result.nodes_visited;
        lock.lock();
        --running_;
        finish(lock, h, std::move(result));
        return true;
    }
    return false;
}

void PathQueue::finish(std::unique_lock<std::mutex>& lock, Handle h, PathResult result) {
    Ticket& ticket = *tickets_.find(h);  // unfinished tickets are never erased
    const PathOutcome outcome = result.outcome;
    const PathCallback callback = std::move(ticket.job->callback);
    ticket.result = std::move(result);
    ticket.job.reset();  // lets go of the snapshot now, not at release
    if (ticket.released) {
        if (ticket.running) --released_running_;
        tickets_.erase(h);
    } else {
        ticket.running = false;
        try {
            finished_list_.push_back(h);
        } catch (...) {
            // Out of memory: the request still finishes (poll and the callback say so); only
            // take_finished will not list it.
        }
    }
    request_finished_.notify_all();
    if (callback) {
        lock.unlock();
        {
            const InPathCallback marked;
            callback(h, outcome);
        }
        lock.lock();
    }
    ++finished_;  // after the callback: a host that waits for `finished` may free what it reads
}

PathOutcome PathQueue::wait(Handle ticket, std::chrono::steady_clock::duration timeout) {
    using Clock = std::chrono::steady_clock;
    if (in_path_callback)
        fail(ErrorCode::InvalidArgument,
             "a path callback cannot wait for a path: it runs on a thread that finishes them");
    const Clock::time_point now = Clock::now();
    const bool forever = timeout >= Clock::time_point::max() - now;
    const Clock::time_point deadline = forever ? Clock::time_point::max() : now + timeout;
    std::unique_lock lock(mutex_);
    for (;;) {
        const Ticket& t = find(ticket);
        if (t.result.outcome != PathOutcome::Pending) return t.result.outcome;
        if (!forever && Clock::now() >= deadline) return PathOutcome::Pending;
        uint64_t nodes = 0;
        if (workers_.empty() && !t.running && run_next(lock, nodes)) continue;
        if (forever)
            request_finished_.wait(lock);
        else
            request_finished_.wait_until(lock, deadline);
    }
}

uint32_t PathQueue::process(const ProcessBudget& budget) {
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    uint64_t nodes = 0;
    auto spent = [&] {
        return (budget.max_milliseconds > 0.0 &&
                std::chrono::duration<double, std::milli>(Clock::now() - begin).count() >= budget.max_milliseconds) ||
               (budget.max_search_nodes > 0 && nodes >= budget.max_search_nodes);
    };
    std::unique_lock lock(mutex_);
    uint32_t done = 0;
    // The budget is checked between requests: each call plans at least one.
    while ((budget.max_requests == 0 || done < budget.max_requests) && (done == 0 || !spent()) && run_next(lock, nodes))
        ++done;
    return done;
}

uint32_t PathQueue::take_finished(uint32_t capacity, std::vector<FinishedRequest>& out) {
    std::lock_guard lock(mutex_);
    out.clear();
    out.reserve(std::min<size_t>(capacity, finished_list_.size()));
    while (out.size() < capacity && !finished_list_.empty()) {
        const Handle h = finished_list_.front();
        finished_list_.pop_front();
        const Ticket* t = tickets_.find(h);
        if (!t || t->released) continue;
        out.push_back(FinishedRequest{h, t->result.outcome, t->user});
    }
    uint32_t remaining = 0;
    for (Handle h : finished_list_) {
        const Ticket* t = tickets_.find(h);
        if (t && !t->released) ++remaining;
    }
    return remaining;
}

PathQueueStats PathQueue::stats() const {
    std::lock_guard lock(mutex_);
    PathQueueStats s;
    s.workers = static_cast<uint32_t>(workers_.size());
    s.queued = queued_;
    s.running = running_;
    s.unreleased = tickets_.size() - released_running_;
    s.submitted = submitted_;
    s.finished = finished_;
    return s;
}

}  // namespace nl
