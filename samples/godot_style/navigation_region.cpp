#include "navigation_region.h"

#include "navmesh_setup.h"
#include "sample_error.h"
#include "scene_tree.h"

namespace nl::godot_style {

NavigationRegion::NavigationRegion(std::string name, levelgen::GeneratedLevel level, nl_agent_type body,
                                   nl_link_settings links)
    : Node(std::move(name)), generated_(std::move(level)), body_(body), link_settings_(links) {}

void NavigationRegion::ready() {
    nl_world* world = tree()->navigation().world();
    level_ = samples::add_generated_level(world, generated_, name());
    navmesh_ = samples::build_navmesh(world, body_, "");
    report_.size = sizeof report_;
    samples::check(nl_navmesh_generate_links(world, navmesh_, &link_settings_, nullptr, nullptr, &report_),
                   name() + ": baking links");
}

}  // namespace nl::godot_style
