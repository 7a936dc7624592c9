// Whether a flight the generator did not prove is clear: a jump onto a moving surface is aimed where
// the landing will be, off the arc that was swept when the link was made, so it is swept again, the
// agent's body along it tested exactly against the level (links/clearance.h, Level::bodies_clear)
// as the level will be when the body passes: each moving mesh placed where its motion carries it
// by then (agents/mesh_motion.h), the static level where it stands.
#pragma once

#include <vector>

#include "agents/mesh_motion.h"
#include "level/level.h"
#include "motion/link_motion.h"

namespace nl {

// Whether a body of `radius` and `height` flying `flight` (world space, from now) touches nothing in
// the level, leaving out the ends as the generator does (take-off and landing touch the floor).
// `moving`: the movable meshes and their motions. A flight `on_proven_arc` (the one the link was
// swept along) that no moving mesh comes near is clear without a sweep. Called with no lock of the
// level held, never from inside a task body.
bool flight_is_clear(const LinkMotion& flight, float radius, float height, const Level& level,
                     const std::vector<MeshMotion>& moving, bool on_proven_arc);

}  // namespace nl
