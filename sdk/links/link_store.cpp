#include "links/link_store.h"

#include <algorithm>

namespace nl {

void LinkStore::require_live(Handle navmesh) const {
    if (removed_.contains(navmesh)) fail_stale("navmesh", navmesh);
}

Handle LinkStore::add(Handle navmesh, const Link& link) {
    std::unique_lock lock(mutex_);
    require_live(navmesh);
    auto& ids = by_navmesh_[key(navmesh)];
    // Allocate before inserting (a failure must leave no orphan), growing geometrically: reserving
    // one more each time copied the whole list on every add.
    if (ids.size() == ids.capacity()) ids.reserve(2 * ids.size() + 8);
    const Handle id = links_.insert(Entry{navmesh, link});
    ids.push_back(id);
    publish(navmesh);
    return id;
}

void LinkStore::update(Handle id, const Link& link) {
    std::unique_lock lock(mutex_);
    Entry* entry = links_.find(id);
    if (!entry) fail_stale("link", id);
    const bool generated = entry->link.generated;
    entry->link = link;
    entry->link.generated = generated;
    publish(entry->navmesh);
}

void LinkStore::remove(Handle id) {
    std::unique_lock lock(mutex_);
    Entry* entry = links_.find(id);
    if (!entry) fail_stale("link", id);
    const Handle navmesh = entry->navmesh;
    auto& ids = by_navmesh_[key(navmesh)];
    ids.erase(std::find(ids.begin(), ids.end(), id));
    links_.erase(id);
    publish(navmesh);
}

std::pair<Handle, Link> LinkStore::get(Handle id) const {
    std::shared_lock lock(mutex_);
    const Entry* entry = links_.find(id);
    if (!entry) fail_stale("link", id);
    return {entry->navmesh, entry->link};
}

bool LinkStore::contains(Handle id) const {
    std::shared_lock lock(mutex_);
    return links_.find(id) != nullptr;
}

void LinkStore::erase_where(Handle navmesh, bool generated_only) {
    auto& ids = by_navmesh_[key(navmesh)];
    std::vector<Handle> kept;
    kept.reserve(ids.size());  // nothing below may throw once links are being erased
    for (Handle id : ids) {
        if (generated_only && !links_.find(id)->link.generated) kept.push_back(id);
        else links_.erase(id);
    }
    ids = std::move(kept);
}

std::vector<Handle> LinkStore::replace_generated(Handle navmesh, const std::vector<Link>& generated) {
    std::unique_lock lock(mutex_);
    require_live(navmesh);
    erase_where(navmesh, true);
    std::vector<Handle> ids;
    ids.reserve(generated.size());
    auto& list = by_navmesh_[key(navmesh)];
    for (const Link& l : generated) {
        Link copy = l;
        copy.generated = true;
        ids.push_back(links_.insert(Entry{navmesh, copy}));
        list.push_back(ids.back());
    }
    publish(navmesh);
    return ids;
}

std::vector<Handle> LinkStore::replace_all(Handle navmesh, const std::vector<Link>& links) {
    std::unique_lock lock(mutex_);
    require_live(navmesh);
    erase_where(navmesh, false);
    std::vector<Handle> ids;
    auto& list = by_navmesh_[key(navmesh)];
    for (const Link& l : links) {
        ids.push_back(links_.insert(Entry{navmesh, l}));
        list.push_back(ids.back());
    }
    publish(navmesh);
    return ids;
}

uint32_t LinkStore::remove_generated(Handle navmesh) {
    std::unique_lock lock(mutex_);
    require_live(navmesh);
    const size_t before = by_navmesh_[key(navmesh)].size();
    erase_where(navmesh, true);
    publish(navmesh);
    return static_cast<uint32_t>(before - by_navmesh_[key(navmesh)].size());
}

void LinkStore::remove_navmesh(Handle navmesh) {
    std::unique_lock lock(mutex_);
    removed_.add(navmesh);  // first: it may throw, and then nothing has changed
    erase_where(navmesh, false);
    by_navmesh_.erase(key(navmesh));
    snapshots_.erase(key(navmesh));
}

void LinkStore::publish(Handle navmesh) { snapshots_[key(navmesh)].reset(); }

std::shared_ptr<const LinkSnapshot> LinkStore::snapshot(Handle navmesh) const {
    // Shared by every navmesh without links: path requests ask for it each time.
    static const auto empty = std::make_shared<const LinkSnapshot>();
    {
        std::shared_lock lock(mutex_);
        const auto it = snapshots_.find(key(navmesh));
        if (it == snapshots_.end()) return empty;
        if (it->second) return it->second;
    }
    // The first read since an edit builds the snapshot, under the exclusive lock: another reader may
    // have built it meanwhile.
    std::unique_lock lock(mutex_);
    const auto it = snapshots_.find(key(navmesh));
    if (it == snapshots_.end()) return empty;
    if (!it->second) {
        auto snapshot = std::make_shared<LinkSnapshot>();
        const auto ids = by_navmesh_.find(key(navmesh));
        if (ids != by_navmesh_.end()) {
            snapshot->reserve(ids->second.size());
            for (Handle id : ids->second) snapshot->push_back(StoredLink{id, links_.find(id)->link});
        }
        it->second = std::move(snapshot);
    }
    return it->second;
}

}  // namespace nl
