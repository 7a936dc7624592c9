// One agent's whole state, as the step works on it (sdk/agents internals).
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "agents/agent.h"
#include "motion/link_motion.h"
#include "navmesh/carrier_pose.h"
#include "path/path_graph.h"
#include "path/path_query.h"

namespace nl {

// Every point and vector of a body is in its navmesh's own space: on a navmesh that rides a moving
// mesh the body rides with it (no drift: its world position is the mesh's pose applied to it, never
// integrated), and its destination and path stay where they were set on the surface.
struct Agent {
    AgentDef def;
    std::shared_ptr<const CarrierFrame> frame;  // its navmesh's; null on a navmesh that rides nothing
    AgentState state = AgentState::Idle;
    AgentReason reason = AgentReason::None;
    Handle id;
    Vec3 position = Vec3::Zero();
    uint32_t polygon = 0;
    Vec3 velocity = Vec3::Zero();

    bool has_destination = false;
    Vec3 destination = Vec3::Zero();  // in its navmesh's space (the one it was located on)
    Handle destination_navmesh;       // the agent's own, or one it reaches over cross links
    std::shared_ptr<const CarrierFrame> destination_frame;

    // The path it follows, the snapshot it was planned on, and the next point to reach.
    std::shared_ptr<const PathGraph> graph;
    std::vector<PathPoint> path;
    uint32_t next = 0;
    bool partial = false;

    // A path asked for, waiting its turn (oldest first).
    bool wants_path = false;
    AgentReason plan_reason = AgentReason::None;
    uint64_t path_order = 0;

    // A link being taken, or waited for at its take-off.
    std::optional<LinkMotion> motion;
    float motion_time = 0.0f;
    // A flight over a cross link, in world space, to this navmesh (frame null meanwhile); it moves
    // onto it when it lands.
    Handle landing_navmesh;
    Handle link;
    uint32_t landing_polygon = 0;
    // The navmesh `polygon` and `landing_polygon` index: its navmesh's tiles may change under its
    // handle (World::add_tile), and the indices with them.
    std::shared_ptr<const NavMesh> stands_on;
    // It stood on a tile that was removed: it waits (TileUnloaded) until a tile holds it again.
    bool awaiting_tile = false;
    bool at_takeoff = false;
    bool off_path = false;  // pushed too far off its path in the last move
    // Giving way (docs/agents.md, "Passing in narrow places"): how long it has walked without
    // getting anywhere, and how long it still stands aside (WAITING) for another to pass.
    float blocked_time = 0.0f;
    float giving_way = 0.0f;
    uint32_t progress_next = UINT32_MAX;  // the path point its progress is measured toward
    float progress_best = 0.0f;           // the nearest it came to it (x-z)
    bool waiting_for_room = false;        // a host reads WAITING (stuck or giving way): said once
    // Giving up (AgentDef::give_up_seconds): the shortest way left it has had along its path, how
    // long it has been held up since it last got kGiveUpProgress shorter, and whether what holds it
    // up is a body heading the other way (a queue, all one way, is waited out however long).
    float best_remaining = std::numeric_limits<float>::infinity();
    float no_progress_time = 0.0f;
    bool held_by_counterflow = false;

    // How far the feet were off the navmesh surface on landing (a link ends on the level's floor,
    // which a Recast detail surface can stand a cell or two above), eased out over the first metre.
    float landing_offset = 0.0f;
    float walked_since_landing = 0.0f;
    void put_on_surface(const Vec3& point) {
        position = point;
        landing_offset = 0.0f;
    }

    std::vector<AgentEvent> step_events;  // this step's, gathered in agent order at its end

    void emit(AgentEventKind kind, AgentReason why = AgentReason::None, Handle on_link = Handle{}) {
        step_events.push_back(AgentEvent{kind, id, on_link, why, def.user_data});
    }
    // Asks for a path to its destination (planned in a coming step, oldest request first).
    void ask_path(AgentReason why, uint64_t& order) {
        if (!has_destination) return;
        if (!wants_path) path_order = order++;
        wants_path = true;
        plan_reason = why;
    }
    void fail(AgentReason why) {
        state = AgentState::Failed;
        reason = why;
        velocity = Vec3::Zero();
        wants_path = false;
        at_takeoff = false;
        path.clear();
        emit(AgentEventKind::Failed, why);
    }
};

}  // namespace nl
