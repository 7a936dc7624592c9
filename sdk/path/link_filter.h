// Whether an agent's body can take a link in a given direction: the per-request filter that
// replaces switching links off for everybody while one agent plans.
#pragma once

#include "links/link.h"
#include "path/path_query.h"

namespace nl {

// What a link asks that the body does not have, the first in this order.
enum class LinkLimit : uint32_t {
    None = 0,
    JumpDistance = 1,
    JumpHeight = 2,
    DropHeight = 3,
    Width = 4,
    Abilities = 5
};

// The first limit and its figures: what the link needs and what the body has (metres; the body's
// diameter against the link's clearance for Width), or the ability bits the body lacks.
struct LinkShortfall {
    LinkLimit limit = LinkLimit::None;
    float needed = 0.0f, has = 0.0f;
    uint64_t missing_abilities = 0;
};

inline LinkShortfall what_stops(const Link& link, bool reversed, const AgentCapabilities& agent) {
    const LinkRequirements& r = link.requirements;
    const float rise = reversed ? r.drop : r.rise;
    const float drop = reversed ? r.rise : r.drop;
    // Walking off a ledge carries the body forward as it falls: a drop taken downward is no jump.
    const bool stepping_off = link.kind == LinkKind::Drop && !reversed;
    if (!stepping_off && r.gap > agent.max_jump_distance)
        return {LinkLimit::JumpDistance, r.gap, agent.max_jump_distance};
    if (rise > agent.max_jump_height) return {LinkLimit::JumpHeight, rise, agent.max_jump_height};
    if (drop > agent.max_drop_height) return {LinkLimit::DropHeight, drop, agent.max_drop_height};
    // A clearance of 0 was never measured (a manual link): the host vouches for it.
    if (r.clearance_width > 0.0f && r.clearance_width < 2.0f * agent.radius)
        return {LinkLimit::Width, 2.0f * agent.radius, r.clearance_width};
    if ((r.abilities & ~agent.abilities) != 0)
        return {LinkLimit::Abilities, 0.0f, 0.0f, r.abilities & ~agent.abilities};
    return {};
}

inline bool can_take(const Link& link, bool reversed, const AgentCapabilities& agent) {
    return what_stops(link, reversed, agent).limit == LinkLimit::None;
}

}  // namespace nl
