#include "path/reachability_cache.h"

#include <algorithm>
#include <chrono>

#include "path/reachability.h"

namespace nl {

struct ReachabilityCache::Class {
    ReachabilityClass key;
    MapFuture map;
};

namespace {

bool same_body(const AgentCapabilities& a, const AgentCapabilities& b) {
    return a.max_jump_distance == b.max_jump_distance && a.max_jump_height == b.max_jump_height &&
           a.max_drop_height == b.max_drop_height && a.radius == b.radius && a.abilities == b.abilities;
}

}  // namespace

std::shared_ptr<const ReachabilityMap> ReachabilityCache::get(const PathGraph& graph, const AgentCapabilities& agent,
                                                              const std::vector<float>& area_costs) {
    const std::array<uint64_t, 4> excluded = ReachabilityClass::excluded_areas_of(area_costs);
    auto known = [&]() -> std::shared_ptr<Class> {
        for (BodyEntry& body : bodies_) {
            if (body.excluded_areas == excluded && same_body(body.capabilities, agent)) {
                body.last_used = ++clock_;
                return body.map_class;
            }
        }
        return nullptr;
    };
    std::shared_ptr<Class> map_class;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        map_class = known();
    }
    if (map_class) return map_class->map.get();

    // A new body: which links it can take is a pass over the links, done outside the lock.
    ReachabilityClass key = ReachabilityClass::of(graph, agent, area_costs);
    std::promise<std::shared_ptr<const ReachabilityMap>> promise;
    bool build = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        map_class = known();  // another thread may have added it meanwhile
        if (!map_class) {
            for (const std::shared_ptr<Class>& c : classes_) {
                if (c->key == key) map_class = c;
            }
            const bool new_class = !map_class;
            if (new_class) map_class = std::make_shared<Class>(Class{std::move(key), promise.get_future().share()});
            remember(BodyEntry{agent, excluded, map_class, ++clock_});
            if (new_class) {
                classes_.push_back(map_class);  // after remember(), which may throw: no class without its builder
                build = true;
            }
        }
    }
    if (build) {
        try {
            promise.set_value(std::make_shared<const ReachabilityMap>(graph, map_class->key));
        } catch (...) {
            promise.set_exception(std::current_exception());
            forget(map_class);
            throw;
        }
    }
    return map_class->map.get();
}

uint64_t ReachabilityCache::next_id() {
    static std::atomic<uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

const ReachabilityMap* ReachabilityCache::ready(const AgentCapabilities& agent,
                                                const std::vector<float>& area_costs) const {
    // This thread's last answer: a map never changes for its graph, and the thread holds it (until
    // it asks about another graph).
    struct LastAnswer {
        uint64_t cache = 0;
        AgentCapabilities capabilities;
        std::array<uint64_t, 4> excluded{};
        std::shared_ptr<const ReachabilityMap> map;
    };
    thread_local LastAnswer last;
    if (last.cache != id_ && last.map) last = LastAnswer{};
    // Most graphs never build a map (every request finds its goal): no lock for them.
    if (!remembered_.load(std::memory_order_acquire)) return nullptr;
    const std::array<uint64_t, 4> excluded = ReachabilityClass::excluded_areas_of(area_costs);
    if (last.cache == id_ && last.excluded == excluded && same_body(last.capabilities, agent)) return last.map.get();
    std::lock_guard<std::mutex> lock(mutex_);
    for (const BodyEntry& body : bodies_) {
        if (body.excluded_areas != excluded || !same_body(body.capabilities, agent)) continue;
        const MapFuture& map = body.map_class->map;
        if (map.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return nullptr;
        try {
            last.map = map.get();
        } catch (...) {
            return nullptr;  // a build that failed: the next get() tries again
        }
        last.cache = id_, last.capabilities = agent, last.excluded = excluded;
        return last.map.get();
    }
    return nullptr;
}

void ReachabilityCache::remember(const BodyEntry& body) {
    auto forget_oldest = [&] {
        const auto oldest =
            std::min_element(bodies_.begin(), bodies_.end(),
                             [](const BodyEntry& a, const BodyEntry& b) { return a.last_used < b.last_used; });
        bodies_.erase(oldest);
        classes_.erase(std::remove_if(classes_.begin(), classes_.end(),
                                      [](const std::shared_ptr<Class>& c) { return c.use_count() == 1; }),
                       classes_.end());
    };
    if (bodies_.size() >= kMaxBodies) forget_oldest();
    // The maps built so far (those still building count when done): a navmesh of a million polygons
    // makes maps of several megabytes each.
    auto bytes = [&] {
        size_t total = 0;
        for (const std::shared_ptr<Class>& c : classes_) {
            if (c->map.wait_for(std::chrono::seconds(0)) != std::future_status::ready) continue;
            try {
                total += c->map.get()->memory_bytes();
            } catch (...) {}
        }
        return total;
    };
    while (!bodies_.empty() && bytes() > kMaxBytes) forget_oldest();
    bodies_.push_back(body);
    remembered_.store(true, std::memory_order_release);
}

void ReachabilityCache::forget(const std::shared_ptr<Class>& map_class) {
    std::lock_guard<std::mutex> lock(mutex_);
    bodies_.erase(
        std::remove_if(bodies_.begin(), bodies_.end(), [&](const BodyEntry& b) { return b.map_class == map_class; }),
        bodies_.end());
    classes_.erase(std::remove(classes_.begin(), classes_.end(), map_class), classes_.end());
}

size_t ReachabilityCache::map_count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return classes_.size();
}

}  // namespace nl
