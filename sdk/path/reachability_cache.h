// The reachability maps of one path graph, built when first asked for and kept as long as the graph
// (an edit to the navmesh or its links makes a new graph, so a map is never asked for past what it
// describes; a thread that was handed one by ready() keeps it until it asks about another graph).
//
// Thread-safety: any number of threads may ask at once. A map is built once per class of body: the
// first thread to ask builds it outside the lock while the others asking for the same class wait for
// it and those asking for other classes go on.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <vector>

#include "path/path_query.h"

namespace nl {

class PathGraph;
class ReachabilityMap;

class ReachabilityCache {
public:
    // The map for a body (capabilities and area costs, as a path request gives them) on `graph`, the
    // graph that owns this cache. Throws what building throws (out of memory); a later call tries
    // again.
    std::shared_ptr<const ReachabilityMap> get(const PathGraph& graph, const AgentCapabilities& agent,
                                               const std::vector<float>& area_costs);
    // The map for a body when one is built and ready; null otherwise (never builds, never waits).
    // The pointer stays valid until this thread's next call of ready() on any cache: the thread keeps
    // the last map it was given (alive, even past this cache, until it asks about another), so that
    // asking again for the same body on the same graph takes no lock, as every path request does.
    const ReachabilityMap* ready(const AgentCapabilities& agent, const std::vector<float>& area_costs) const;
    // Maps built and kept (for tests and statistics).
    size_t map_count() const;

    // Bodies remembered; beyond it, or beyond kMaxBytes of maps, the least recently asked for is
    // forgotten (its map stays while another body of the same class holds it, or a caller does).
    static constexpr size_t kMaxBodies = 64;
    static constexpr size_t kMaxBytes = size_t(256) << 20;

private:
    using MapFuture = std::shared_future<std::shared_ptr<const ReachabilityMap>>;
    struct Class;
    struct BodyEntry {
        AgentCapabilities capabilities;
        std::array<uint64_t, 4> excluded_areas;
        std::shared_ptr<Class> map_class;
        uint64_t last_used;
    };

    // Adds a body (once), forgetting the least recently used beyond kMaxBodies and the classes no
    // body holds any more; mutex_ held.
    void remember(const BodyEntry& body);
    // Drops a class whose build failed, and the bodies that point at it.
    void forget(const std::shared_ptr<Class>& map_class);

    const uint64_t id_ = next_id();  // names this cache in a thread's last answer from ready()
    static uint64_t next_id();
    mutable std::mutex mutex_;
    std::atomic<bool> remembered_{false};  // a body was ever remembered: ready() may find a map
    std::vector<BodyEntry> bodies_;
    std::vector<std::shared_ptr<Class>> classes_;
    uint64_t clock_ = 0;
};

}  // namespace nl
