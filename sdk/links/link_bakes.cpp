#include "links/link_bakes.h"

namespace nl {

namespace {

thread_local bool holding_turn = false;

}  // namespace

LinkBakes::Turn::Turn(std::shared_ptr<std::mutex> mutex) : mutex_(std::move(mutex)) {
    mutex_->lock();
    holding_turn = true;
}

LinkBakes::Turn::~Turn() {
    holding_turn = false;
    mutex_->unlock();
}

LinkBakes::Turn LinkBakes::take_turn(Handle navmesh) {
    if (holding_turn)
        fail(ErrorCode::InvalidArgument, "links cannot be generated or updated from inside another generation or update "
                                         "(its progress callback or a plugin): it could wait for itself");
    std::shared_ptr<std::mutex> m;
    {
        std::lock_guard lock(mutex_);
        // A removed navmesh keeps no entry (its generation will not be kept either).
        if (removed_.contains(navmesh)) {
            m = std::make_shared<std::mutex>();
        } else {
            auto& shared = serializers_[key(navmesh)];
            if (!shared) shared = std::make_shared<std::mutex>();
            m = shared;
        }
    }
    return Turn(std::move(m));
}

void LinkBakes::store(Handle navmesh, Entry entry, FunctionRef<void()> links) {
    std::lock_guard lock(mutex_);
    links();
    if (removed_.contains(navmesh)) return;
    bakes_[key(navmesh)] = std::move(entry);
}

bool LinkBakes::store_if_current(Handle navmesh, const LinkGeneration* generation, FunctionRef<void()> links) {
    std::lock_guard lock(mutex_);
    const auto it = bakes_.find(key(navmesh));
    if (it == bakes_.end() || it->second.generation.get() != generation) return false;
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
