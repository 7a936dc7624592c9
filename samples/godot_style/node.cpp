#include "node.h"

#include <algorithm>

namespace nl::godot_style {

void Node::attach(std::unique_ptr<Node> child) {
    child->parent_ = this;
    Node* raw = child.get();
    children_.push_back(std::move(child));
    if (tree_) raw->enter_tree(tree_);
}

void Node::remove_child(Node* child) {
    const auto it =
        std::find_if(children_.begin(), children_.end(), [child](const auto& c) { return c.get() == child; });
    if (it == children_.end()) return;
    if (tree_) child->leave_tree();
    children_.erase(it);
}

void Node::enter_tree(SceneTree* tree) {
    tree_ = tree;
    for (auto& c : children_) c->enter_tree(tree);
    ready();  // children are ready before their parent, as in Godot
}

void Node::leave_tree() {
    for (auto& c : children_) c->leave_tree();
    exit_tree();
    tree_ = nullptr;
}

void Node::physics_process_tree(double delta) {
    physics_process(delta);
    for (size_t i = 0; i < children_.size(); ++i) children_[i]->physics_process_tree(delta);
}

void Node::process_tree(double delta) {
    process(delta);
    // By index: a node may add children while processing.
    for (size_t i = 0; i < children_.size(); ++i) children_[i]->process_tree(delta);
}

}  // namespace nl::godot_style
