// Puts a link made outside the generator (by the host, a plugin or a links file) on its navmesh:
// both ends must be near it, and each end remembers the polygon under it.
#pragma once

#include <string>

#include "links/link.h"
#include "navmesh/navmesh.h"
#include "navmesh/carrier_pose.h"

namespace nl {

// How far a link's end may be from its navmesh.
constexpr float kLinkEndReach = 1.0f;

// Sets the link's start and end polygons to those nearest its ends. Throws InvalidArgument about the
// field "start" or "end" (fail_field) when an end is not within kLinkEndReach of the navmesh.
void place_link(const NavMesh& navmesh, Link& link);

// As place_link, for a link read back from a file that names its polygons: a named polygon that still
// holds its end (seen from above, within the reach in height) is kept, so a file saved from another
// build of the navmesh keeps the polygons it can; the others are located again.
void place_saved_link(const NavMesh& navmesh, Link& link);

// As place_link for a link from `from` to another navmesh `to`: the start on `from`, the end on `to`.
void place_cross_link(const NavMesh& from, const NavMesh& to, Link& link);

// Whether a cross link holds with its navmeshes placed at `from` (its start's) and `to` (its end's):
// its end, seen from the start's navmesh, is within its tolerance of where it was placed.
bool cross_link_holds(const Link& link, const CarrierPose& from, const CarrierPose& to);

// The link with its points (ends, apex) carried by `pose` to the world, or from the world to the
// surface: a link on a navmesh that rides a moving mesh is kept in the mesh's space. What it asks of
// a body (rise, drop, length) stays: the surface's up is taken as the world's.
Link link_in_world(Link link, const CarrierPose& pose);
Link link_in_carrier_space(Link link, const CarrierPose& pose);
// For a link whose end lies on another navmesh (a cross link): start and apex by `from`, end by `to`.
Link link_in_world(Link link, const CarrierPose& from, const CarrierPose& to);

}  // namespace nl
