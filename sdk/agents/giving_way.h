// Who gives way in a narrow place (docs/agents.md, "Passing in narrow places"): walkers that press
// against each other without getting anywhere would stand so for ever (two at a door's mouth, each
// in the other's way). When walkers in contact have both been stuck a while, one of them stands aside
// (WAITING, making room: others push it out of their way) for a moment while the other goes on.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "agents/agent_state.h"
#include "agents/crowd.h"

namespace nl {

// A walker that has got no nearer its next path point by kProgressStep for kStuckSeconds is stuck:
// a host reads it as WAITING (for room), and in contact with another stuck walker one gives way.
// (0.5 s made open crowds give way too often: a tenth fewer arrivals on undulating at 10% cover.)
constexpr float kProgressStep = 0.1f;
constexpr float kStuckSeconds = 0.75f;

// Forgets how far the agent has come toward its next path point, and that it was stuck: when it was
// moved otherwise than by its walk (it gave way, got a new path, was sent or put elsewhere).
inline void forget_progress(Agent& a) {
    a.blocked_time = 0.0f;
    a.progress_next = UINT32_MAX;
}

// A body that gives its destination up has made no kGiveUpProgress toward it for its
// give_up_seconds while held up by others (docs/agents.md, "When the crowd does not let it through").
constexpr float kGiveUpProgress = 1.0f;

// Starts its count toward giving up afresh: its way ahead changed (a new destination or path, a
// teleport), or it made progress otherwise than by walking (it reached a link).
inline void forget_patience(Agent& a) {
    a.best_remaining = std::numeric_limits<float>::infinity();
    a.no_progress_time = 0.0f;
    a.held_by_counterflow = false;
}

// Ends its giving way, if it was, and forgets its progress and patience (a new destination, a stop,
// a teleport).
inline void stop_giving_way(Agent& a) {
    a.giving_way = 0.0f;
    a.waiting_for_room = false;
    forget_progress(a);
    forget_patience(a);
}

// After a step's move: counts how long each walker has been stuck and picks those that give way;
// ends the turns of those whose time is up; says when one starts waiting for room (Waiting, Crowd)
// and fails one that has waited past its give_up_seconds (Failed, Crowd). `crowds[space_of[i]]` holds
// agent i at index_in_space[i] (positions as the move began). Serial, in agent order: the same for any thread count.
void decide_giving_way(std::vector<Agent>& agents, const std::vector<uint32_t>& space_of,
                       const std::vector<uint32_t>& index_in_space, const std::vector<CrowdSnapshot>& crowds, float dt);

}  // namespace nl
