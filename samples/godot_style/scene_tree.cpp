#include "scene_tree.h"

#include <chrono>
#include <thread>

namespace nl::godot_style {

SceneTree::SceneTree(int32_t path_workers) : navigation_(*this, path_workers) {}

SceneTree::~SceneTree() {
    // Nodes leave the tree (agents release their path requests) while the server still exists;
    // results that arrive meanwhile are dropped with the deferred queue.
    if (root_) root_->leave_tree();
    root_.reset();
}

Node* SceneTree::set_root(std::unique_ptr<Node> root) {
    root_ = std::move(root);
    root_->enter_tree(this);
    return root_.get();
}

void SceneTree::call_deferred(std::function<void()> call) {
    std::lock_guard<std::mutex> lock(deferred_mutex_);
    deferred_.push_back(std::move(call));
}

void SceneTree::flush_deferred() {
    std::vector<std::function<void()>> calls;
    {
        std::lock_guard<std::mutex> lock(deferred_mutex_);
        calls.swap(deferred_);
    }
    for (auto& call : calls) call();
}

void SceneTree::run_frame(double delta) {
    navigation_.sync();
    flush_deferred();
    if (root_) root_->process_tree(delta);
    time_ += delta;
}

double SceneTree::run_until(const std::function<bool()>& done, double delta, double max_seconds) {
    const double end = time_ + max_seconds;
    // With background planning, a frame must take its time, or the scene would outrun the workers.
    const bool real_time = navigation_.has_path_workers();
    auto next = std::chrono::steady_clock::now();
    while (!done() && time_ < end) {
        run_frame(delta);
        if (!real_time) continue;
        next += std::chrono::microseconds(static_cast<long>(delta * 1e6));
        std::this_thread::sleep_until(next);
    }
    return time_;
}

}  // namespace nl::godot_style
