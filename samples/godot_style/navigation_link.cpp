#include "navigation_link.h"

#include "navigation_region.h"
#include "sample_error.h"
#include "scene_tree.h"

namespace nl::godot_style {

NavigationLink::NavigationLink(std::string name, NavigationRegion& region, const nl_link_def& def)
    : Node(std::move(name)), region_(region), def_(def) {}

void NavigationLink::ready() {
    samples::check(nl_link_add(tree()->navigation().world(), region_.navmesh(), &def_, &id_),
                   name() + ": adding the link");
}

void NavigationLink::exit_tree() {
    // Agents whose paths take it plan again in the next step, before they reach it.
    nl_link_remove(tree()->navigation().world(), id_);
    id_ = nl_link_id{};
}

}  // namespace nl::godot_style
