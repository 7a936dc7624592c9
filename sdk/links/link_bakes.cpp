#include "links/link_bakes.h"

namespace nl {

std::shared_ptr<std::mutex> LinkBakes::serializer(Handle navmesh) {
    std::lock_guard lock(mutex_);
    // A removed navmesh keeps no entry (its bake will not be kept either).
    if (removed_.contains(navmesh)) return std::make_shared<std::mutex>();
    auto& m = serializers_[key(navmesh)];
    if (!m) m = std::make_shared<std::mutex>();
    return m;
}

void LinkBakes::store(Handle navmesh, Entry entry, FunctionRef<void()> links) {
    std::lock_guard lock(mutex_);
    links();
    if (removed_.contains(navmesh)) return;
    bakes_[key(navmesh)] = std::move(entry);
}

bool LinkBakes::store_if_current(Handle navmesh, const LinkBake* bake, FunctionRef<void()> links) {
    std::lock_guard lock(mutex_);
    const auto it = bakes_.find(key(navmesh));
    if (it == bakes_.end() || it->second.bake.get() != bake) return false;
    links();
    return true;
}

LinkBakes::Entry LinkBakes::get(Handle navmesh) const {
    std::lock_guard lock(mutex_);
    const auto it = bakes_.find(key(navmesh));
    return it == bakes_.end() ? Entry{} : it->second;
}

void LinkBakes::forget(Handle navmesh, FunctionRef<void()> links) {
    std::lock_guard lock(mutex_);
    links();
    bakes_.erase(key(navmesh));
}

void LinkBakes::remove(Handle navmesh) {
    std::lock_guard lock(mutex_);
    removed_.add(navmesh);  // first: it may throw, and then nothing has changed
    bakes_.erase(key(navmesh));
    serializers_.erase(key(navmesh));
}

}  // namespace nl
