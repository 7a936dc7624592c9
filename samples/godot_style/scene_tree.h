// The scene tree and its main loop, as Godot's SceneTree: it owns the root node and the navigation
// server, and runs frames: physics_process(delta) down the tree (platforms move), the server's sync
// point (the agents move and their events reach their nodes), then process(delta) down the tree.
#pragma once

#include <functional>
#include <memory>

#include "navigation_server.h"
#include "node.h"

namespace nl::godot_style {

class SceneTree {
public:
    // `workers`: the navigation world's threads (NavigationServer); the scene plays the same on any.
    explicit SceneTree(int32_t workers = 1) : navigation_(workers) {}
    ~SceneTree();

    // Makes `root` the tree's root: it and its subtree enter the tree (ready() runs).
    Node* set_root(std::unique_ptr<Node> root);
    Node* root() const { return root_.get(); }
    NavigationServer& navigation() { return navigation_; }

    void run_frame(double delta);
    // Frames of `delta` until `done()` or `max_seconds` of scene time; returns the scene time.
    double run_until(const std::function<bool()>& done, double delta, double max_seconds);
    double time() const { return time_; }

private:
    // Destroyed in reverse: the nodes first (agents and links leave the world), then the server.
    NavigationServer navigation_;
    std::unique_ptr<Node> root_;
    double time_ = 0.0;
};

}  // namespace nl::godot_style
