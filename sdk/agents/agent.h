// Agents in the core's terms: what a host asks of one (AgentDef), what it reads back (AgentInfo),
// and what happened in a step (AgentEvent).
#pragma once

#include <cstdint>

#include "level/geometry.h"
#include "path/path_query.h"
#include "util/handle.h"

namespace nl {

enum class AgentState : uint32_t {
    Idle = 0,        // no destination
    Walking = 1,     // following its path on the ground
    Jumping = 2,     // in the air on a jump's arc
    Falling = 3,     // on a drop: out past the rim, across, down
    Traversing = 4,  // on another kind of link (manual, a plugin's): a straight line
    Waiting = 5,     // for its path to be planned, or for a link's landing to clear
    Arrived = 6,     // at its destination
    Failed = 7,      // cannot go on; AgentInfo::reason says why
};

// Why an agent planned again, or failed.
enum class AgentReason : uint32_t {
    None = 0,
    DestinationSet = 1,  // a new destination
    LinkGone = 2,        // a link of its path was removed, disabled, moved, or is beyond its body now
    WorldChanged = 3,    // its navmesh changed under it
    OffPath = 4,         // pushed too far off its path
    NoPath = 5,          // the destination cannot be reached (it went as near as it could)
    NavMeshRemoved = 6,  // its navmesh was removed
    CapabilitiesChanged = 7,
    Crowd = 8,         // other bodies are in its way: waiting for room, or given up (give_up_seconds)
    TileUnloaded = 9,  // the tile it stands on was removed: it waits until it is back
};

enum class AgentEventKind : uint32_t {
    PathReady = 1,
    LinkStarted = 2,
    LinkFinished = 3,
    Arrived = 4,
    Failed = 5,
    Replanned = 6,
    Waiting = 7,  // it stopped for room (reason Crowd: stuck among other bodies, or giving way), or for
                  // its tile (reason TileUnloaded)
};

struct AgentDef {
    Handle navmesh;
    AgentCapabilities capabilities;
    float height = 2.0f;
    float max_speed = 3.5f;         // m/s on the ground
    float max_acceleration = 8.0f;  // m/s^2
    float gravity = 9.81f;          // m/s^2: a jump's and a fall's timing
    float takeoff_speed = 0.0f;     // m/s; > 0: a jump's timing from this speed instead of gravity
    Vec3 position = Vec3::Zero();
    uint64_t user_data = 0;
    bool avoidance = true;  // steer around other agents and walls
    // Seconds without getting kGiveUpProgress nearer its destination, held up by bodies heading the
    // other way, after which it gives its destination up (Failed, Crowd); 0: never.
    float give_up_seconds = 0.0f;
};

struct AgentEvent {
    AgentEventKind kind;
    Handle agent;
    Handle link;  // LinkStarted, LinkFinished: the link; else null
    AgentReason reason = AgentReason::None;
    uint64_t user_data = 0;
};

struct AgentInfo {
    Handle id;
    AgentState state = AgentState::Idle;
    AgentReason reason = AgentReason::None;  // of a failure, or of the last plan
    Vec3 position = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    uint32_t polygon = 0xffffffffu;
    Handle link;                 // the link being taken (Jumping, Falling, Traversing) or waited for
    float link_progress = 0.0f;  // 0..1 of the way along it
    Vec3 destination = Vec3::Zero();
    bool has_destination = false;
    uint32_t corners_ahead = 0;
    uint64_t user_data = 0;
    Handle navmesh;                        // it stands on now
    Handle carrier;                        // the movable mesh that navmesh rides; null for none
    Vec3 carrier_position = Vec3::Zero();  // position in that mesh's space
};

}  // namespace nl
