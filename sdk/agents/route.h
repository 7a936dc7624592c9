// Routes that leave an agent's navmesh: over cross links (Link::crosses) from one navmesh to another,
// a ledge onto a moving platform and off it again. A route is searched over the cross links (a
// Dijkstra whose edges are walks planned inside one navmesh), and the agent is given its first leg:
// the walk to the first cross link's take-off. It plans the next leg when it lands.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "navmesh/carrier_pose.h"
#include "path/path_graph.h"
#include "path/path_query.h"
#include "util/handle.h"

namespace nl {

// The navmeshes as a step sees them: each one's graph and pose, read once (so every route of the
// step is planned on the same moment, whatever the thread count).
struct StepNavMesh {
    Handle navmesh;
    std::shared_ptr<const PathGraph> graph;  // null: removed
    CarrierPose pose;
};

class StepNavMeshes {
public:
    // Every navmesh of `all` (handles and graphs), with its pose now.
    void add(Handle navmesh, std::shared_ptr<const PathGraph> graph);
    const StepNavMesh* find(Handle navmesh) const;
    const std::vector<StepNavMesh>& all() const { return navmeshes_; }
    // Whether a cross link of `navmesh` holds at this moment (cross_link_holds).
    bool holds(Handle navmesh, const Link& link) const;

private:
    std::vector<StepNavMesh> navmeshes_;
};

struct RouteQuery {
    Handle from_navmesh;
    Vec3 from = Vec3::Zero();  // in from_navmesh's space
    Handle to_navmesh;
    Vec3 goal = Vec3::Zero();  // in to_navmesh's space
    AgentCapabilities capabilities;
    // Also over cross links that do not hold now: the agent will wait at the take-off (a ferry).
    bool through_waiting = false;
};

// Plans the route's first leg into `out` (in from_navmesh's space; its last point the take-off of the
// first cross link, marked with the link) and returns true, or returns false when no route reaches
// the goal. Thread-safe over a `navmeshes` nobody changes meanwhile.
bool plan_route(const StepNavMeshes& navmeshes, const RouteQuery& query, PathResult& out);

}  // namespace nl
