// The navigation server of the scene, as Godot's NavigationServer3D: the one place that talks to
// NavLink. It owns the nl_world; regions, links and agents register through it, and path queries
// answer through a callback deferred to the scene tree's thread.
//
// Like Godot's server it has a sync point per frame. With no path worker threads (the default) the
// queued requests are planned there, on the tree's thread (nl_path_process), so a scene runs the
// same way every time and as fast as the machine allows. With worker threads, requests are planned
// in the background and answered whenever they finish, which only makes sense in real time.
#pragma once

#include <navlink/navlink.h>

#include <functional>

#include "world.h"

namespace nl::godot_style {

class SceneTree;

class NavigationServer {
public:
    using PathDone = std::function<void(nl_path_ticket, nl_path_outcome)>;

    NavigationServer(SceneTree& tree, int32_t path_workers) : tree_(tree), world_(path_workers) {}

    nl_world* world() const { return world_.get(); }
    bool has_path_workers() const;
    // The frame's sync point: plans the queued requests when there are no workers.
    void sync();

    // Queues a path request (nl_path_request). `done` runs once on the tree's thread, at the start
    // of the frame after the request finished (any outcome). Throws SampleError if refused.
    nl_path_ticket query_path(const nl_path_request_def& def, PathDone done);

private:
    static void on_path_finished(void* user, nl_path_ticket ticket, nl_path_outcome outcome);

    SceneTree& tree_;
    samples::World world_;
};

}  // namespace nl::godot_style
