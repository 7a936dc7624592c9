// The navmeshes of a world. Each is immutable and shared: a reader takes its own reference, so a
// navmesh removed while a query runs on it lives until that query ends.
#pragma once

#include <memory>
#include <mutex>
#include <shared_mutex>
#include <vector>

#include "navmesh/navmesh.h"
#include "util/error.h"
#include "util/handle.h"
#include "util/shared_mutex.h"

namespace nl {

class NavMeshRegistry {
public:
    explicit NavMeshRegistry(uint32_t handle_tag) : navmeshes_(handle_tag) {}

    Handle add(std::shared_ptr<const NavMesh> navmesh) {
        std::unique_lock lock(mutex_);
        return navmeshes_.insert(std::move(navmesh));
    }

    void remove(Handle h) {
        std::unique_lock lock(mutex_);
        if (!navmeshes_.erase(h)) fail_stale("navmesh", h);
    }

    // Throws InvalidHandle for a null, stale or foreign handle.
    std::shared_ptr<const NavMesh> get(Handle h) const {
        std::shared_lock lock(mutex_);
        const auto* found = navmeshes_.find(h);
        if (!found) fail_stale("navmesh", h);
        return *found;
    }

    bool contains(Handle h) const {
        std::shared_lock lock(mutex_);
        return navmeshes_.find(h) != nullptr;
    }

    std::vector<Handle> handles() const {
        std::shared_lock lock(mutex_);
        std::vector<Handle> out;
        navmeshes_.for_each([&](Handle h, const auto&) { out.push_back(h); });
        return out;
    }

private:
    mutable SharedMutex mutex_;
    SlotMap<std::shared_ptr<const NavMesh>> navmeshes_;
};

}  // namespace nl
