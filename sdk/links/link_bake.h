// A bake of one navmesh's links that remembers what every ray looked at, so that after the level
// changes inside a box only the probes and sweeps whose bounds touch that box are cast again.
//
// Stages: samples (navmesh only) -> take-off probes -> jump candidates (geometry-free constraints,
// recomputed every time: cheap) with their arc sweeps -> drop probes with their fall sweeps ->
// selection and merge (no rays, over everything cached). Because the last two steps always run over
// the whole cache, an update gives exactly the links a full bake would.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "links/edge_samples.h"
#include "links/link_generator.h"

namespace nl {

class LinkBake {
public:
    LinkBake(std::shared_ptr<const NavMesh> navmesh, const LinkSettings& settings, BakeMethod method);

    // Casts everything.
    std::vector<Link> run(const Level& level, TaskSystem& tasks, BakeReport& report, BakeProgress progress);
    // Casts again what geometry inside `box` can have changed. Throws (Cancelled, ...) leaving the
    // bake as it was.
    std::vector<Link> update(const Aabb& box, const Level& level, TaskSystem& tasks, BakeReport& report,
                             BakeProgress progress);

    struct TakeoffState {
        bool valid = false;
        uint8_t rejected = 0;  // 1: wall between the edge and the rim, 2: no rim (ground a step below)
        float ground_y = 0.0f;
        float rim = 0.0f;
        Aabb bounds;           // everything its probes touched
    };
    struct Sweep {
        bool clear = false;
        float width = 0.0f;    // widest body found clear (2, 3 or 4 agent radii)
        Aabb bounds;           // the widest sweep's reach
    };
    struct JumpCandidate {
        uint32_t a = 0, b = 0;  // take-off samples
        Link link;
        Sweep sweep;
    };
    struct DropProbe {
        uint64_t key = 0;       // (sample, angle)
        uint8_t outcome = 0;    // 0: landed, 1: no landing, 2: too shallow or too deep
        uint8_t fall_points = 0;
        Aabb bounds;            // the probe ray
        Link link;
        std::array<Vec3, 4> fall;  // out over the edge, across, down (when landed)
        Sweep sweep;
    };
    struct Cache {
        std::vector<TakeoffState> takeoffs;                 // by sample
        std::unordered_map<uint64_t, JumpCandidate> jumps;  // by (a, b)
        std::vector<DropProbe> drops;                       // by key, ascending
    };

private:
    std::vector<Link> bake(const Aabb* box, const Level& level, TaskSystem& tasks, BakeReport& report,
                           BakeProgress progress);

    std::shared_ptr<const NavMesh> navmesh_;
    LinkSettings settings_;
    BakeMethod method_;
    EdgeSampling sampling_;
    Cache cache_;
    bool baked_ = false;
    std::mutex mutex_;  // one bake or update at a time
};

// The last bake of each navmesh of a world, kept for updates, with the plugin settings it ran with.
class LinkBakes {
public:
    struct Entry {
        std::shared_ptr<LinkBake> bake;
        std::string plugin_settings_json;
    };

    // Generations and updates of one navmesh run one at a time, from reading its bake to storing its
    // links, so a later one never loses to an earlier one. Hold the returned mutex for that span.
    // (A progress callback must not start another on the same navmesh: it would wait for itself.)
    std::shared_ptr<std::mutex> serializer(Handle navmesh);

    // The links a bake made and the bake itself change together, so that an update never continues
    // a bake whose links were taken away. Each of these runs `links` (which changes the navmesh's
    // links in the link store) and the bookkeeping in one step; `links` must not call back in here.
    //
    // A generation's result: records `entry` (ignored for a removed navmesh: a generation that
    // finishes after the removal keeps nothing).
    void store(Handle navmesh, Entry entry, FunctionRef<void()> links);
    // An update's result: runs `links` only while `bake` is still the navmesh's bake, else returns
    // false and runs nothing.
    bool store_if_current(Handle navmesh, const LinkBake* bake, FunctionRef<void()> links);
    // The generated links removed or replaced by a load: there is no generation left to update.
    void forget(Handle navmesh, FunctionRef<void()> links);

    Entry get(Handle navmesh) const;  // empty if the navmesh was never baked, or its bake forgotten
    void remove(Handle navmesh);

private:
    static uint64_t key(Handle h) { return (uint64_t(h.index1) << 32) | h.generation; }
    mutable std::mutex mutex_;
    std::unordered_map<uint64_t, Entry> bakes_;
    std::unordered_map<uint64_t, std::shared_ptr<std::mutex>> serializers_;
    std::unordered_set<uint64_t> retired_;
};

}  // namespace nl
