// The scripted scene of the harness: the generated default level as a navigation region, a ladder
// (a NavigationLink that only climbers may take), and four agents sent from the level's start to its
// goal: the demo's walker, short jumper and long jumper, and a climber (a walker with the climb
// ability).
#pragma once

#include <memory>
#include <vector>

#include "navigation_agent.h"
#include "navigation_link.h"
#include "navigation_region.h"
#include "scene_tree.h"

namespace nl::godot_style {

constexpr uint64_t kClimbAbility = 0x1;

struct DemoScene {
    std::unique_ptr<SceneTree> tree;
    NavigationRegion* region = nullptr;
    NavigationLink* ladder = nullptr;
    std::vector<NavigationAgent*> agents;  // walker, short jumper, long jumper, climber
    Vec3 target{};
};

// Builds the scene and puts it in a tree (regions generate, links register, agents ask for paths).
// `workers` as for SceneTree.
// Throws SampleError.
DemoScene build_demo_scene(uint32_t seed, int32_t workers = 1);

// The climber: a walker that can step up 0.5 m and climb ladders (kClimbAbility).
samples::AgentProfile climber_profile();

// The ladder: one-way up, from the level's "ladder_bottom" to its "ladder_top" marker, asking the
// climb ability and a 0.3 m step onto its first rung.
nl_link_def ladder_def(const levelgen::GeneratedLevel& level);

}  // namespace nl::godot_style
