// A platform the host moves, as a Godot AnimatableBody3D with a NavigationRegion3D baked on it: a
// movable mesh, a navmesh built on it, and its gangways to the ground region (cross links, each
// added while the platform stands where it docks for it). Each physics frame, before the navigation
// server's sync point, it goes where its timetable has it at the end of the frame
// (nl_mesh_set_transform); NavLink carries its navmesh, gangways and riders along.
#pragma once

#include <navlink/navlink.h>

#include "moving_platforms.h"
#include "node.h"
#include "platforms_level.h"

namespace nl::godot_style {

class NavigationRegion;

class MovingPlatform : public Node {
public:
    // `ground` must enter the tree first: the gangways lead from and to its navmesh.
    MovingPlatform(std::string name, NavigationRegion& ground, samples::PlatformLayout layout);

    const samples::PlatformLayout& layout() const { return layout_; }
    // Its mesh, navmesh and gangways in the world (empty before it enters the tree).
    const samples::MovingPlatform& platform() const { return platform_; }

protected:
    void ready() override;
    void physics_process(double delta) override;
    void exit_tree() override;

private:
    NavigationRegion& ground_;
    samples::PlatformLayout layout_;
    samples::MovingPlatform platform_;
};

}  // namespace nl::godot_style
