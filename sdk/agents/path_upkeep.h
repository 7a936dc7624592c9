// Whether an agent's path still holds when its navmesh's links change: the links it has yet to take
// must still exist, be enabled, lie where they lay (not parked off a removed tile) and be within its
// body. An agent whose path holds keeps it (new links serve from its next plan); one whose path lost
// a link plans again. Likewise when tiles change: a path whose tiles stayed as they were is kept.
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include "agents/agent_state.h"
#include "path/path_graph.h"

namespace nl {

// The links of the link snapshots a step looks at, by handle; built once per snapshot per step.
class LinkLookup {
public:
    const Link* find(const PathGraph& graph, Handle link);

private:
    std::vector<std::pair<const LinkSnapshot*, std::unordered_map<uint64_t, const Link*>>> snapshots_;
};

// What became of an agent's path in the moment `now` of its navmesh.
struct PathUpkeep {
    enum Verdict { Holds, LinkGone, NavMeshChanged } verdict = Holds;
    Handle link;  // LinkGone: the first link of the path that no longer serves
};

// `carried_over`: its path was carried over to `now`'s navmesh (carry_path_over), so another navmesh
// under the handle does not end it.
PathUpkeep check_path(const Agent& agent, const PathGraph& now, LinkLookup& links, bool carried_over = false);

// When its navmesh's tiles changed under its handle: whether the rest of its path (from where it stands
// through its remaining points) lies on tiles whose polygons are the same in `before` (the navmesh it
// was planned on) and `now` (NavMesh::tile_fingerprint; each stretch's x-z bounds taken whole). Then
// its remaining points are placed on `now` (their polygons) and true: it keeps its path, whose links
// check_path (carried_over) checks next. False leaves the agent as it was: it plans again.
bool carry_path_over(Agent& agent, const NavMesh& before, const NavMesh& now);

}  // namespace nl
