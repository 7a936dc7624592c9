// A navigation region, as Godot's NavigationRegion3D: a node that owns a level's geometry and its
// navmesh. When it enters the tree it registers the geometry with the navigation server, builds the
// navmesh for its agent body (the Recast builder) and generates the jump and drop links.
#pragma once

#include <navlink/navlink.h>

#include "level.h"
#include "level_generator.h"
#include "node.h"

namespace nl::godot_style {

class NavigationRegion : public Node {
public:
    NavigationRegion(std::string name, levelgen::GeneratedLevel level, nl_agent_type body, nl_link_settings links);

    nl_navmesh_id navmesh() const { return navmesh_; }
    const nl_agent_type& body() const { return body_; }
    const levelgen::GeneratedLevel& level() const { return generated_; }
    const nl_link_generation_report& generation_report() const { return report_; }

protected:
    void ready() override;

private:
    levelgen::GeneratedLevel generated_;
    nl_agent_type body_;
    nl_link_settings link_settings_;
    samples::Level level_;
    nl_navmesh_id navmesh_{};
    nl_link_generation_report report_{};
};

}  // namespace nl::godot_style
