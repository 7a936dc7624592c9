// Where the ground under a navmesh edge falls away along a heading: the rim a body leaves from.
//
// A rim is not a line along its edge: a bevel that widens, a stepped or notched lip, a corner the
// heading passes all put it at a different distance for each heading. So a rim is searched for along
// the heading the body takes (straight out for a take-off point, turned for a drop probe, towards the
// other end for a jump), never derived from another heading's.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "level/level.h"

namespace nl {

class TaskSystem;

// One search: from a point on (or over) an edge, out along a horizontal unit heading.
struct RimQuery {
    Vec3 from;       // x and z of the start; its height is ignored (ground_y is the floor's)
    Vec3 heading;    // horizontal, unit length
    float ground_y;  // the floor's height under `from`
    float reach;     // how far out to look (> 0)
    // A static triangle known to be under `from` (Level::static_triangles of the floor ray's hit), if
    // any: probes that cross it well inside are on ground without a ray. Only for Indexed generations.
    std::optional<std::array<Vec3, 3>> floor;
};

// How the ground is told from air: a probe from `lift` above the start's floor down `step_reach`
// finds ground (a step down the body can walk still counts as ground).
struct RimProbing {
    float lift;
    float step_reach;
    bool floor_shortcut;  // use RimQuery::floor and the triangles probes hit (Indexed generations)
};

// Probes step out every kStep (clamped at the reach), then the last step is halved kHalvings times.
struct RimSearch {
    static constexpr float kStep = 0.25f;
    static constexpr int kHalvings = 4;  // found to kStep / 16, about 1.6 cm
};

// For each query, how far out along its heading the ground falls away: the outer end of the last
// interval halved (known to be past the ground, so a gap measured to it never reads wider than it
// is), or -1 when there is ground all the way to the reach. `rays_cast` is increased by the probes
// cast. Deterministic for any thread count.
std::vector<float> find_rims(const Level& level, TaskSystem& tasks, std::vector<RimQuery> queries,
                             const RimProbing& probing, uint64_t& rays_cast);

// Everything a query's probes can touch (its start to its reach, the probes' tops and bottoms), so a
// cache knows when a change in the level may move the rim.
Aabb rim_search_bounds(const RimQuery& query, const RimProbing& probing);

}  // namespace nl
