// Link generation for one navmesh against the level's geometry:
//   edges -> samples -> take-off points -> jump candidates (spatial grid) and drop probes
//   -> constraints -> the agent's body swept exactly along each arc and fall -> merge.
// Deterministic: the same navmesh, level and settings give the same links in the same order,
// whatever the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "level/level.h"
#include "links/link.h"
#include "links/link_settings.h"
#include "navmesh/navmesh.h"
#include "util/function_ref.h"
#include "util/task_system.h"

namespace nl {

// Answers a level designer's "why is there no link here?": what each stage saw and refused.
struct LinkGenerationReport {
    uint32_t edges = 0;            // boundary edges of the navmesh
    uint32_t groups = 0;           // groups of short edges
    uint32_t samples = 0;          // take-off samples on edges
    uint32_t takeoff_points = 0;   // samples that really hang over a drop or gap
    uint32_t jump_candidates = 0;  // edge pairs within reach, tested further
    uint32_t drop_candidates = 0;  // landings found below take-off points, tested further
    uint32_t jump_links = 0;
    uint32_t drop_links = 0;
    uint32_t plugin_links = 0;  // filled by the caller that runs link-kind plugins
    // Rejections, by reason.
    uint32_t rejected_wall = 0;         // something solid between the edge and the rim
    uint32_t rejected_not_ledge = 0;    // walkable ground a step below the take-off point
    uint32_t rejected_distance = 0;     // a jump's gap too wide or too narrow
    uint32_t rejected_rise = 0;         // a jump higher than max_jump_up
    uint32_t rejected_angle = 0;        // not facing the other edge, or too steep
    uint32_t rejected_no_landing = 0;   // no navmesh where the agent would land
    uint32_t rejected_clearance = 0;    // the agent's body would touch geometry on the way
    uint32_t rejected_duplicate = 0;    // the same traversal as a link already kept
    uint32_t rejected_walkable = 0;     // a jump whose ends are about as near on foot
    uint32_t rejected_too_shallow = 0;  // a drop no deeper than max_climb, floor to floor (walked)
    uint32_t rejected_too_deep = 0;     // a drop deeper than max_drop_distance, floor to floor
    uint64_t rays_cast = 0;             // rays and occlusion segments sent to Embree
    uint64_t box_queries = 0;           // boxes whose triangles the level gathered for the exact body tests
    uint64_t body_tests = 0;            // sweep pieces tested exactly against the triangles near them
    double milliseconds_edges = 0, milliseconds_takeoff = 0, milliseconds_jumps = 0, milliseconds_drops = 0,
           milliseconds_merge = 0, milliseconds_total = 0;
};

// How a generation finds its work; both give the same links, bit for bit.
//   Indexed:    spatial indexes everywhere: jump candidates from a grid of take-off points, points
//               located through the navmesh's polygon grid, near-duplicates found through a grid of
//               link ends, and a straight run of sweep pieces whose box no triangle touches is clear
//               after one gathering of the triangles near it (Level::bodies_clear by groups).
//   BruteForce: none of them: every pair of take-off points, every polygon, every kept link, every
//               piece of every sweep tested exactly (the level's rays and the triangles near a piece
//               still come from Embree). The reference the tests and navlink-bench-links compare the
//               generator with.
enum class GenerationMethod { Indexed, BruteForce };

// Called between and within stages with the fraction done (0..1) and the stage's name; returning
// false cancels the generation (generate_links then throws Cancelled).
using GenerationProgress = FunctionRef<bool(float fraction, const char* stage)>;

std::vector<Link> generate_links(const NavMesh& navmesh, const Level& level, TaskSystem& tasks,
                                 const LinkSettings& settings, GenerationMethod method, LinkGenerationReport& report,
                                 GenerationProgress progress);

}  // namespace nl
