#include "demo_scene.h"

#include "demo_setup.h"
#include "sample_error.h"

namespace nl::godot_style {
namespace {

Vec3 marker(const levelgen::GeneratedLevel& level, const char* name) {
    const levelgen::Marker* m = level.marker(name);
    if (!m) throw samples::SampleError(std::string("the level has no '") + name + "' marker");
    return {m->position[0], m->position[1], m->position[2]};
}

}  // namespace

samples::AgentProfile climber_profile() {
    samples::AgentProfile climber = samples::demo_agents()[0];
    climber.name = "climber";
    climber.capabilities.max_jump_height = 0.5f;
    climber.capabilities.abilities = kClimbAbility;
    return climber;
}

nl_link_def ladder_def(const levelgen::GeneratedLevel& level) {
    nl_link_def def = nl_default_link_def();
    def.kind = NL_LINK_MANUAL;
    const Vec3 bottom = marker(level, "ladder_bottom"), top = marker(level, "ladder_top");
    for (int k = 0; k < 3; ++k) {
        def.start[k] = bottom[k];
        def.end[k] = top[k];
    }
    def.bidirectional = 0;
    // Measured from its ends it would be a 2 m jump up; a ladder asks for the ability, and the step
    // onto its first rung.
    def.requirements_as_given = 1;
    def.requirements.rise = 0.3f;
    def.requirements.abilities = kClimbAbility;
    return def;
}

DemoScene build_demo_scene(uint32_t seed, int32_t workers) {
    DemoScene scene;
    scene.tree = std::make_unique<SceneTree>(workers);
    const levelgen::GeneratedLevel level = levelgen::generate_default_level(seed);
    const Vec3 start = marker(level, "start");
    scene.target = marker(level, "goal");
    std::vector<samples::AgentProfile> profiles = samples::demo_agents();
    profiles.push_back(climber_profile());

    auto root = std::make_unique<Node>("Main");
    scene.region = root->add_child(
        std::make_unique<NavigationRegion>("Level", level, profiles[0].body, nl_default_link_settings()));
    scene.ladder = root->add_child(std::make_unique<NavigationLink>("Ladder", *scene.region, ladder_def(level)));
    for (const samples::AgentProfile& profile : profiles) {
        auto agent = std::make_unique<NavigationAgent>(profile.name, *scene.region, profile, start);
        agent->set_target_position(scene.target);
        scene.agents.push_back(root->add_child(std::move(agent)));
    }
    scene.tree->set_root(std::move(root));  // ready(): generate, add the ladder and the agents
    return scene;
}

}  // namespace nl::godot_style
