// The harness's moving-platforms scene: the ground of the platforms level as a navigation region,
// the shuttle, the disc and the lift as MovingPlatform nodes, and their four passengers as
// NavigationAgents, each sent to its own target: across the chasm, onto the disc, past it, and up
// to the upper floor.
#pragma once

#include <memory>
#include <vector>

#include "moving_platform.h"
#include "navigation_agent.h"
#include "navigation_region.h"
#include "platforms_level.h"
#include "scene_tree.h"

namespace nl::godot_style {

struct PlatformsScene {
    std::unique_ptr<SceneTree> tree;
    samples::PlatformsLevel level;  // where everything is and goes (the nodes hold their own copies)
    NavigationRegion* region = nullptr;
    std::vector<MovingPlatform*> platforms;  // shuttle, disc, lift
    std::vector<NavigationAgent*> agents;    // ferry rider, disc rider, disc crosser, lift rider
};

// Builds the scene and puts it in a tree: the region bakes its navmesh and links, then the platforms
// register and place their gangways, then the agents ask for their paths. `workers` as for
// SceneTree. Throws SampleError.
PlatformsScene build_platforms_scene(uint32_t seed, int32_t workers = 1);

}  // namespace nl::godot_style
