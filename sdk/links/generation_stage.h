// What the stages of one link generation pass share (take-off probing, jumps, drops; the pass itself is
// LinkGeneration's): the pass's inputs, the rays and sweeps every stage casts through, and the rules
// for reusing what the old cache holds. Internal to sdk/links.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "links/clearance.h"
#include "links/link_generation.h"
#include "links/rim_search.h"
#include "navmesh/walk_graph.h"

namespace nl::generation {

constexpr float kDegrees = 3.14159265358979f / 180.0f;
constexpr float kProbeLift = 0.5f;   // probes start this far above the navmesh: clear of the floor,
                                     // and below any ceiling (the navmesh has agent height above it)
constexpr float kFloorReach = 2.0f;  // a link end's floor is looked for this far below kProbeLift
constexpr float kPastRim = 0.2f;     // a drop's fall starts this far past the rim
constexpr float kPad = 1e-3f;        // bounds are padded: a surface exactly on them still counts

inline uint64_t pair_key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

inline Aabb bounds_of(std::initializer_list<Vec3> points) {
    Aabb box;
    for (const Vec3& p : points) box.grow(p);
    return box;
}

inline void grow(Aabb& box, const Aabb& other) {
    box.grow(other.min);
    box.grow(other.max);
}

// Whether what was cast within `a` may see a change inside `box` (none: a full generation, everything).
inline bool touches(const Aabb& a, const Aabb* box) {
    if (!box) return true;
    return (a.min.array() - kPad <= box->max.array()).all() && (a.max.array() + kPad >= box->min.array()).all();
}

// Reports progress; throws Cancelled when the host says stop.
void check_progress(const GenerationProgress& progress, float fraction, const char* stage);

// One generation or update: what it reads, the old cache it may reuse, the report it fills.
struct PassInputs {
    PassInputs(const NavMesh& navmesh, const EdgeSampling& sampling, const LinkSettings& settings,
               GenerationMethod method, const LinkGeneration::Cache& old, const Aabb* box, const Level& level,
               TaskSystem& tasks, LinkGenerationReport& report, GenerationProgress progress);

    const NavMesh& navmesh;
    const std::vector<EdgeSample>& samples;
    const LinkSettings& settings;
    GenerationMethod method;
    const LinkGeneration::Cache& old;
    const Aabb* box;  // null: a full generation
    const Level& level;
    TaskSystem& tasks;
    LinkGenerationReport& report;
    GenerationProgress progress;
    Body body;
    WalkGraph walk;
    RimProbing rim_probing;
};

// A stage's view of the pass, and what every stage casts through (counted in the report).
class GenerationStage {
public:
    explicit GenerationStage(PassInputs& in);

protected:
    // Reports progress; throws Cancelled when the host says stop.
    void step(float fraction, const char* stage);
    std::vector<RayHit> cast(const std::vector<Ray>& rays);
    std::vector<uint8_t> blocked(const std::vector<Segment>& segments);
    // The floor under a take-off point: its sample's x and z, the height of the level found under it.
    Vec3 floor_point(const LinkGeneration::Cache& c, uint32_t i) const;
    // Sweeps each path with the agent's body and bodies 1.5 and 2 times as wide (clearance.h).
    std::vector<LinkGeneration::Sweep> sweep(const std::vector<PathPoints>& paths);
    // Sweeps the jump arcs between each pair of ends (from the first to the second).
    std::vector<LinkGeneration::Sweep> sweep_arcs(const std::vector<std::pair<Vec3, Vec3>>& ends);
    // Point location through the navmesh's polygon grid, or over every polygon (brute force).
    NavPoint locate(const Vec3& point, const Vec3& half_extents) const;

    const NavMesh& mesh_;
    const std::vector<EdgeSample>& samples_;
    const LinkSettings& settings_;
    GenerationMethod method_;
    const LinkGeneration::Cache& old_;
    const Aabb* box_;
    const Level& level_;
    TaskSystem& tasks_;
    LinkGenerationReport& report_;
    GenerationProgress progress_;
    const Body& body_;
    const WalkGraph& walk_;
    const RimProbing& rim_probing_;
};

// The stages, in the order a pass runs them (each fills its part of `next`, reusing the old cache's
// where the box cannot have changed it).
void probe_takeoffs(PassInputs& in, LinkGeneration::Cache& next);  // takeoff_probing.cpp
void find_jumps(PassInputs& in, LinkGeneration::Cache& next);      // jump_finding.cpp
void find_drops(PassInputs& in, LinkGeneration::Cache& next);      // drop_finding.cpp
// Selection (no rays, over the whole cache): the kept jumps in take-off order, the kept drops in key order.
std::vector<Link> straightest_jumps(PassInputs& in, const LinkGeneration::Cache& c);      // jump_finding.cpp
std::vector<Link> one_drop_per_way_down(PassInputs& in, const LinkGeneration::Cache& c);  // drop_finding.cpp

}  // namespace nl::generation
