#include "moving_platform.h"

#include "navigation_region.h"
#include "scene_tree.h"

namespace nl::godot_style {

MovingPlatform::MovingPlatform(std::string name, NavigationRegion& ground, samples::PlatformLayout layout)
    : Node(std::move(name)), ground_(ground), layout_(std::move(layout)) {}

void MovingPlatform::ready() {
    platform_ = samples::add_moving_platform(tree()->navigation().world(), ground_.navmesh(), layout_, ground_.body(),
                                             tree()->time());
}

void MovingPlatform::physics_process(double delta) {
    // The sync point that follows moves the agents to the end of this frame: the platform is there.
    samples::move_platform(tree()->navigation().world(), platform_, tree()->time() + delta);
}

void MovingPlatform::exit_tree() {
    samples::remove_moving_platform(tree()->navigation().world(), platform_);
    platform_ = samples::MovingPlatform{};
}

}  // namespace nl::godot_style
