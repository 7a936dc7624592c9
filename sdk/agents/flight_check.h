// Whether a flight the generator did not prove is clear: a jump onto a moving surface is aimed where
// the landing will be, off the arc that was swept when the link was made, so it is swept again, the
// agent's body along it tested exactly against the level (links/clearance.h, Level::bodies_clear).
#pragma once

#include "level/level.h"
#include "motion/link_motion.h"

namespace nl {

// Whether a body of `radius` and `height` flying `flight` (world space) touches nothing in the level
// as it stands now, leaving out the ends as the generator does (take-off and landing touch the
// floor). Called with no lock of the level held, never from inside a task body.
bool flight_is_clear(const LinkMotion& flight, float radius, float height, const Level& level);

}  // namespace nl
