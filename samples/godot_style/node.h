// A node of the scene tree, as Godot's Node: a name, a parent, owned children, and the callbacks the
// tree drives: ready() when the node enters the tree (children first, as in Godot), and each frame
// physics_process(delta) before the navigation server's sync point and process(delta) after it
// (parents first).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace nl::godot_style {

class SceneTree;

class Node {
public:
    explicit Node(std::string name) : name_(std::move(name)) {}
    virtual ~Node() = default;
    Node(const Node&) = delete;
    Node& operator=(const Node&) = delete;

    // Adds a child and returns it; if this node is in a tree, the child (and its subtree) enters it.
    template <typename T>
    T* add_child(std::unique_ptr<T> child) {
        T* raw = child.get();
        attach(std::move(child));
        return raw;
    }
    // Removes and destroys a child (its exit_tree runs first).
    void remove_child(Node* child);

    const std::string& name() const { return name_; }
    Node* parent() const { return parent_; }
    SceneTree* tree() const { return tree_; }
    const std::vector<std::unique_ptr<Node>>& children() const { return children_; }
    // The first ancestor of type T, or nullptr (Godot's get_parent() chain, typed).
    template <typename T>
    T* find_ancestor() const {
        for (Node* n = parent_; n; n = n->parent_)
            if (auto* t = dynamic_cast<T*>(n)) return t;
        return nullptr;
    }

protected:
    virtual void ready() {}
    // Where bodies the host moves (platforms) are moved, so that agents move with them at the sync point.
    virtual void physics_process(double /*delta*/) {}
    virtual void process(double /*delta*/) {}
    virtual void exit_tree() {}

private:
    friend class SceneTree;
    void attach(std::unique_ptr<Node> child);
    void enter_tree(SceneTree* tree);
    void leave_tree();
    void physics_process_tree(double delta);
    void process_tree(double delta);

    std::string name_;
    Node* parent_ = nullptr;
    SceneTree* tree_ = nullptr;
    std::vector<std::unique_ptr<Node>> children_;
};

}  // namespace nl::godot_style
