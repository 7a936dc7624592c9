// The agents of a world: bodies that follow their paths, take links along the trajectories the
// generator proved clear, and keep out of each other's way. One step moves every agent by dt.
//
// A step runs in phases (agents_step.cpp), so that its result is the same bit for bit whatever the
// thread count:
//   1. check_against_world (serial): each agent checks its navmesh and links against the world as it
//      is now, and asks for a new path when they changed under it;
//   2. plan_asked_paths: the paths asked for, at most max_paths_per_step of them (agents standing
//      without a path first, then the oldest request), planned in parallel on the world's task
//      system, each on the navmesh and links as they are now;
//   3. move (parallel): each agent steers, avoids its neighbours and the walls (positions as they
//      were at the start of the phase), moves over the surface, or flies its link;
//   4. separate (parallel): bodies on the ground that overlap are pushed apart over the surface;
//   5. land_cross_flights (serial): bodies landed over a cross link go onto the landing navmesh;
//   6. take_off (serial, in agent order): agents at a link's take-off check that the link is still
//      there, enabled and within their body, and that its landing is clear, then take off or plan
//      again.
// Each agent writes only its own state in a parallel phase; events are gathered in agent order.
//
// Positions: a host gives and reads them in the world. Inside, each agent is kept in its navmesh's
// own space (agent_state.h), so an agent on a navmesh that rides a moving mesh moves with it; bodies
// avoid the bodies that share their space (on the same moving mesh, or all that ride nothing).
//
// Thread-safety: every method may be called from any thread; step() holds the agents' lock for its
// whole run, so calls on agents wait for it, and it must not be called from inside a task body. Lock
// order: the agents' lock, then the navmesh registry's.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "agents/agent.h"
#include "agents/mesh_motion.h"
#include "agents/route.h"
#include "level/level.h"
#include "motion/link_motion.h"
#include "path/path_graph.h"
#include "util/handle.h"
#include "os/shared_mutex.h"
#include "util/task_system.h"
#include "registry/navmesh_registry.h"

namespace nl {

struct Agent;

struct AgentsSettings {
    uint32_t max_paths_per_step = 32;  // paths planned in one step at most; the rest wait their turn
};

class Agents {
public:
    Agents(uint32_t handle_tag, AgentsSettings settings);
    ~Agents();
    Agents(const Agents&) = delete;
    Agents& operator=(const Agents&) = delete;

    // Throws InvalidHandle (navmesh), InvalidArgument about a field (fail_field: "position", "max_speed"...),
    // NotFound when the position is not on the navmesh (the message says how far the nearest is).
    Handle add(const NavMeshRegistry& navmeshes, const AgentDef& def);
    void remove(Handle agent);
    bool contains(Handle agent) const;

    // Located at once on the agent's navmesh, or else on a navmesh it reaches over cross links (a
    // moving platform, a ledge across a chasm), and kept in that navmesh's space (on a moving
    // surface it moves with it). NotFound when it is on none of them: the destination is not kept.
    // The agent plans a path to it in a coming step.
    // `field` names the point in a failure (the caller's name for it). An agent whose navmesh was
    // removed is refused (InvalidHandle, saying so), as by teleport().
    void set_destination(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& destination,
                         const char* field = "destination");
    // Forgets the destination and stands still (Idle). An agent in the air lands first; one whose
    // navmesh was removed stays Failed.
    void stop(Handle agent);
    // Puts the agent at a navmesh point (NotFound off it), still, keeping its destination (it plans
    // again from there). Refused (InvalidArgument) while it is taking a link.
    void teleport(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& position, const char* field = "position");
    void set_capabilities(Handle agent, const AgentCapabilities& capabilities);
    void set_speed(Handle agent, float max_speed, float max_acceleration);

    // Advances every agent by dt seconds (>= 0, finite). Throws nothing for an agent's trouble: the
    // agent fails, with its event.
    // A flight over a cross link aimed off the arc its link was proven on is swept again against
    // `level` at take-off (flight_check.h), the level's lock taken after the agents'.
    void step(float dt, const NavMeshRegistry& navmeshes, const Level& level, TaskSystem& tasks);

    AgentInfo info(Handle agent) const;
    std::vector<AgentInfo> infos() const;  // every agent, in a stable order (until one is removed)
    // Where the agent is (how it goes on from there: walking, or the link it flies), then the path
    // points it has yet to reach, the next first; empty with no path, or once it has arrived.
    std::vector<PathPoint> corners(Handle agent) const;
    // The link the agent is taking, read at one moment: its motion (empty on the ground), the link,
    // and the seconds since take-off.
    struct Flight {
        std::optional<LinkMotion> motion;  // in the navmesh's space: `pose` places it in the world
        Handle link;
        float elapsed = 0.0f;
        CarrierPose pose;
    };
    Flight flight(Handle agent) const;
    // The last step's events, in agent order.
    std::vector<AgentEvent> events() const;
    uint32_t count() const;

private:
    // The phases of step() (agents_step.cpp), in order, and what they share.
    struct Step;
    void check_against_world(Step& s);
    bool stand_on_navmesh_now(Agent& a, const PathGraph& now);
    void plan_asked_paths(Step& s);
    void move(Step& s);
    void separate(Step& s);
    void land_cross_flights(Step& s);
    void take_off(Step& s);

    Agent& find(Handle agent);
    const Agent& find(Handle agent) const;
    // The agent's navmesh, its pose now and the agent's radius; InvalidHandle for a stale agent, or
    // one whose navmesh is gone.
    std::shared_ptr<const NavMesh> navmesh_of(const NavMeshRegistry& navmeshes, Handle agent, float& radius,
                                              CarrierPose& pose) const;
    // Locates a world point on the navmesh placed at `pose`: the point found is in the navmesh's space.
    uint32_t locate(const NavMesh& navmesh, const CarrierPose& pose, const Vec3& point, float radius, const char* field,
                    Vec3& on_navmesh) const;
    // Locates a world point on a navmesh that cross links join to `own` (found: its navmesh, frame
    // and the point in its space).
    bool locate_across(const NavMeshRegistry& navmeshes, Handle own, const Vec3& point, float radius, Vec3& on_navmesh,
                       Handle& navmesh, std::shared_ptr<const CarrierFrame>& frame) const;

    // Take-off over a cross link that holds: the body flies in world space to where the landing
    // point will be when it lands (the landing surface's motion over the last step carried on).
    // Returns false, changing nothing, when that flight would meet the level (it waits and tries again).
    bool take_off_across(Agent& a, const Link& link, Handle id, const BodyMotion& body, const StepNavMeshes& table,
                         const Level& level);
    // A body landed over a cross link goes onto `navmesh` (`graph`, null if removed): the link's
    // landing navmesh, or the one a ray down found under it.
    void land_across(Agent& a, Handle navmesh, const std::shared_ptr<const PathGraph>& graph,
                     const StepNavMeshes& table);
    // How the level's movable meshes moved over the last step: a jump onto a moving surface aims
    // where its landing will be, and its flight is checked against where they will be.
    MeshMotions motions_;

    mutable SharedMutex mutex_{"the agents"};
    AgentsSettings settings_;
    SlotMap<uint32_t> ids_;      // agent handle -> index in agents_
    std::vector<Agent> agents_;  // dense, in a stable order between removals
    std::vector<AgentEvent> events_;
    uint64_t next_path_order_ = 0;
};

}  // namespace nl
