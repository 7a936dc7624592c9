// A generation of one navmesh's links that remembers what every ray looked at, so that after the level
// changes inside a box only the probes and sweeps whose bounds touch that box are cast again.
//
// Stages: samples (navmesh only) -> take-off probes -> jump candidates (geometry-free constraints,
// recomputed every time: cheap) with their arc sweeps -> drop probes with their fall sweeps ->
// selection and merge (no rays, over everything cached). Because the last two steps always run over
// the whole cache, an update gives exactly the links a full generation would.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "links/edge_samples.h"
#include "links/generate_links.h"

namespace nl {

class LinkGeneration {
public:
    LinkGeneration(std::shared_ptr<const NavMesh> navmesh, const LinkSettings& settings, GenerationMethod method);

    // Casts everything.
    std::vector<Link> run(const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                          GenerationProgress progress);
    // Casts again what geometry inside `box` can have changed. Throws (Cancelled, ...) leaving the
    // generation as it was.
    std::vector<Link> update(const Aabb& box, const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                             GenerationProgress progress);

    enum class TakeoffRejection : uint8_t {
        None,
        Wall,   // something solid between the edge and the rim, at chest height
        NoRim,  // ground within a step below all the way to falloff_distance
    };
    struct TakeoffState {
        bool valid = false;
        TakeoffRejection rejected = TakeoffRejection::None;
        float ground_y = 0.0f;  // the floor under the sample
        float rim = 0.0f;       // how far out along the sample's outward direction the ground falls away
        Aabb bounds;            // everything its probes touched
    };
    struct Sweep {
        bool swept = false;  // the rest is known (a drop probe is swept only if it may be kept)
        bool clear = false;
        float width = 0.0f;  // widest body found clear (2, 3 or 4 agent radii)
        Aabb bounds;         // the widest sweep's reach
    };
    struct JumpCandidate {
        uint32_t a = 0, b = 0;  // take-off samples
        Link link;              // its requirements.gap measured along the line between the ends
        Sweep sweep;
        Aabb rim_bounds;         // the searches for the rims along that line
        bool gap_within = true;  // the gap measured is max_jump_gap or narrower (kept, unswept, if not: an
                                 // update reuses the measurement)
    };
    struct DropProbe {
        uint64_t key = 0;  // (sample, angle)
        uint8_t outcome =
            0;  // 0: landed, 1: no landing (or no rim along the heading), 2: too shallow (walked), 3: too deep
        float rim = -1.0f;  // how far out along the probe's heading the ground falls away (-1: not within reach)
        Aabb bounds;  // the rim search along the heading, the probe ray and the ray to the floor under the landing
        Link link;
        std::array<Vec3, 4> fall;  // out over the rim, across, down (when landed)
        Sweep sweep;
        Sweep back;  // the jump back up, for a drop no deeper than max_jump_up
    };
    struct Cache {
        std::vector<TakeoffState> takeoffs;                 // by sample
        std::unordered_map<uint64_t, JumpCandidate> jumps;  // by (a, b)
        std::vector<DropProbe> drops;                       // by key, ascending
    };

private:
    std::vector<Link> generate(const Aabb* box, const Level& level, TaskSystem& tasks, LinkGenerationReport& report,
                               GenerationProgress progress);

    std::shared_ptr<const NavMesh> navmesh_;
    LinkSettings settings_;
    GenerationMethod method_;
    EdgeSampling sampling_;
    Cache cache_;
    bool generated_ = false;
    std::mutex mutex_;  // one generation or update at a time
};

}  // namespace nl
