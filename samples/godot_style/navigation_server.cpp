#include "navigation_server.h"

#include <memory>

#include "sample_error.h"
#include "scene_tree.h"

namespace nl::godot_style {
namespace {

// What a request's callback needs; owned by the request until its callback (exactly once) runs.
struct PendingQuery {
    SceneTree* tree;
    NavigationServer::PathDone done;
};

}  // namespace

nl_path_ticket NavigationServer::query_path(const nl_path_request_def& def, PathDone done) {
    // The callback owns the context: NavLink calls it exactly once for an accepted request, possibly
    // on a worker before nl_path_request returns. A refused request never calls it.
    auto* pending = new PendingQuery{&tree_, std::move(done)};
    nl_path_request_def request = def;
    request.callback = on_path_finished;
    request.user = pending;
    nl_path_ticket ticket{};
    const nl_status status = nl_path_request(world_.get(), &request, &ticket);
    if (NL_FAILED(status)) {
        delete pending;
        samples::check(status, "requesting a path");
    }
    return ticket;
}

bool NavigationServer::has_path_workers() const {
    nl_path_queue_stats stats{};
    stats.size = sizeof stats;
    samples::check(nl_path_get_queue_stats(world_.get(), &stats), "reading the path queue");
    return stats.workers > 0;
}

void NavigationServer::sync() {
    if (!has_path_workers()) samples::check(nl_path_process(world_.get(), nullptr, nullptr), "planning paths");
}

void NavigationServer::on_path_finished(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    // A NavLink path worker (or the thread that cancelled): hand over to the tree's thread.
    std::unique_ptr<PendingQuery> pending(static_cast<PendingQuery*>(user));
    pending->tree->call_deferred([done = std::move(pending->done), ticket, outcome] { done(ticket, outcome); });
}

}  // namespace nl::godot_style
