#include "scene_tree.h"

namespace nl::godot_style {

SceneTree::~SceneTree() {
    if (root_) root_->leave_tree();
    root_.reset();
}

Node* SceneTree::set_root(std::unique_ptr<Node> root) {
    root_ = std::move(root);
    root_->enter_tree(this);
    return root_.get();
}

void SceneTree::run_frame(double delta) {
    // As Godot's physics frame: the host's bodies move first, then the navigation server's sync point
    // moves the agents over them.
    if (root_) root_->physics_process_tree(delta);
    navigation_.sync(delta);
    if (root_) root_->process_tree(delta);
    time_ += delta;
}

double SceneTree::run_until(const std::function<bool()>& done, double delta, double max_seconds) {
    const double end = time_ + max_seconds;
    while (!done() && time_ < end) run_frame(delta);
    return time_;
}

}  // namespace nl::godot_style
