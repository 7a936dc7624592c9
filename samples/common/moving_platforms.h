// The platforms of a PlatformsLevel in a world, through the C ABI: each one a movable mesh
// (NL_MESH_MOVABLE) with a navmesh the Recast builder makes on it (in its own space, so it rides the
// mesh), and its gangways: cross links between it and the ground, each added while the platform
// stands where the gangway was placed. The host moves them (nl_mesh_set_transform) by their
// timetables; NavLink carries their navmeshes, links and riders along.
#pragma once

#include <navlink/navlink.h>

#include <optional>
#include <vector>

#include "platforms_level.h"

namespace nl::samples {

struct MovingPlatform {
    const PlatformLayout* layout = nullptr;  // borrowed: the PlatformsLevel outlives the platform
    nl_mesh_id mesh{};
    nl_navmesh_id navmesh{};
    std::vector<nl_link_id> gangways;  // layout->gangways', in the same order
};

// Registers the platform on `ground` (the static navmesh its gangways lead from and to) for agents
// with `body`, and leaves it where its timetable has it at `time`. Throws SampleError naming the
// platform.
MovingPlatform add_moving_platform(nl_world* world, nl_navmesh_id ground, const PlatformLayout& layout,
                                   const nl_agent_type& body, double time);
std::vector<MovingPlatform> add_moving_platforms(nl_world* world, nl_navmesh_id ground,
                                                 const std::vector<PlatformLayout>& layouts, const nl_agent_type& body,
                                                 double time);

// Puts the platform where its timetable has it at `time`. Throws SampleError.
void move_platform(nl_world* world, const MovingPlatform& platform, double time);
void move_platforms(nl_world* world, const std::vector<MovingPlatform>& platforms, double time);

// Takes the platform out of the world: its gangways, its navmesh, then its mesh (which cannot go
// while a navmesh rides it). Never throws: what is already gone is skipped.
void remove_moving_platform(nl_world* world, const MovingPlatform& platform);

// What a link is to the platforms: a gangway of one of them, or nothing.
struct GangwayLink {
    const MovingPlatform* platform;
    const Gangway* gangway;
};
std::optional<GangwayLink> find_gangway(const std::vector<MovingPlatform>& platforms, nl_link_id link);

bool same_link(nl_link_id a, nl_link_id b);

}  // namespace nl::samples
