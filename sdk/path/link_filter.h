// Whether an agent's body can take a link in a given direction: the per-request filter that
// replaces switching links off for everybody while one agent plans.
#pragma once

#include "links/link.h"
#include "path/path_query.h"

namespace nl {

inline bool can_take(const Link& link, bool reversed, const AgentCapabilities& agent) {
    const LinkRequirements& r = link.requirements;
    const float rise = reversed ? r.drop : r.rise;
    const float drop = reversed ? r.rise : r.drop;
    // Walking off a ledge carries the body forward as it falls: a drop taken downward is no jump.
    const bool stepping_off = link.kind == LinkKind::Drop && !reversed;
    if (!stepping_off && r.gap > agent.max_jump_distance) return false;
    if (rise > agent.max_jump_height || drop > agent.max_drop_height) return false;
    // A clearance of 0 was never measured (a manual link): the host vouches for it.
    if (r.clearance_width > 0.0f && r.clearance_width < 2.0f * agent.radius) return false;
    return (r.abilities & ~agent.abilities) == 0;
}

}  // namespace nl
