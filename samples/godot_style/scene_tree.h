// The scene tree and its main loop, as Godot's SceneTree: it owns the root node and the navigation
// server, runs frames (process(delta) down the tree), and runs calls deferred from other threads at
// the start of the next frame (Godot's call_deferred), which is how path results from NavLink's
// worker threads reach the nodes.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "navigation_server.h"
#include "node.h"

namespace nl::godot_style {

class SceneTree {
public:
    // `path_workers`: NavLink path worker threads (0: paths are planned at each frame's sync point,
    // deterministically; with workers, run_until paces frames in real time).
    explicit SceneTree(int32_t path_workers = 0);
    ~SceneTree();

    // Makes `root` the tree's root: it and its subtree enter the tree (ready() runs).
    Node* set_root(std::unique_ptr<Node> root);
    Node* root() const { return root_.get(); }
    NavigationServer& navigation() { return navigation_; }

    // Thread-safe: `call` runs on the tree's thread at the start of the next frame.
    void call_deferred(std::function<void()> call);

    // One frame: the navigation server's sync, the deferred calls, then process(delta) down the tree.
    void run_frame(double delta);
    // Frames of `delta` until `done()` or `max_seconds` of scene time; returns the scene time.
    double run_until(const std::function<bool()>& done, double delta, double max_seconds);
    double time() const { return time_; }

private:
    void flush_deferred();

    // Destroyed in reverse: the nodes first (agents release their requests, whose callbacks still
    // defer), then the server, then the deferred queue that may have received those callbacks.
    std::mutex deferred_mutex_;
    std::vector<std::function<void()>> deferred_;
    NavigationServer navigation_;
    std::unique_ptr<Node> root_;
    double time_ = 0.0;
};

}  // namespace nl::godot_style
