// A hand-placed link, as Godot's NavigationLink3D: a ladder, a door, a teleporter between two points
// of a region's navmesh. It exists in the navmesh while the node is in the tree.
#pragma once

#include <navlink/navlink.h>

#include "node.h"

namespace nl::godot_style {

class NavigationRegion;

class NavigationLink : public Node {
public:
    // `def` as for nl_link_add (kind, ends, bidirectionality, requirements...).
    NavigationLink(std::string name, NavigationRegion& region, const nl_link_def& def);

    nl_link_id id() const { return id_; }

protected:
    void ready() override;
    void exit_tree() override;

private:
    NavigationRegion& region_;
    nl_link_def def_;
    nl_link_id id_{};
};

}  // namespace nl::godot_style
