#include "platforms_scene.h"

#include <cctype>

namespace nl::godot_style {
namespace {

// "shuttle" -> "Shuttle", as Godot names nodes.
std::string node_name(std::string name) {
    if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    return name;
}

}  // namespace

PlatformsScene build_platforms_scene(uint32_t seed, int32_t workers) {
    PlatformsScene scene;
    scene.tree = std::make_unique<SceneTree>(workers);
    scene.level = samples::generate_platforms_level(seed);
    const samples::AgentProfile& first = scene.level.passengers.front().profile;

    // Children enter the tree in order: the region's navmesh and links are there before the
    // platforms' gangways join them, and both before the agents plan.
    auto root = std::make_unique<Node>("Main");
    scene.region = root->add_child(
        std::make_unique<NavigationRegion>("Level", scene.level.level, first.body, nl_default_link_settings()));
    for (const samples::PlatformLayout& layout : scene.level.platforms)
        scene.platforms.push_back(
            root->add_child(std::make_unique<MovingPlatform>(node_name(layout.name), *scene.region, layout)));
    for (const samples::Passenger& passenger : scene.level.passengers) {
        auto agent = std::make_unique<NavigationAgent>(passenger.profile.name, *scene.region, passenger.profile,
                                                       passenger.start);
        agent->set_target_position(passenger.destination);
        scene.agents.push_back(root->add_child(std::move(agent)));
    }
    scene.tree->set_root(std::move(root));
    return scene;
}

}  // namespace nl::godot_style
