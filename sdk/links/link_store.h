// The links of a world, each belonging to one navmesh. Manual links live beside generated ones and
// survive regeneration. Readers take an immutable snapshot of a navmesh's links; every edit
// publishes a new one, so a reader never blocks an edit nor sees half of one.
#pragma once

#include <memory>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "links/link.h"
#include "util/handle.h"
#include "util/shared_mutex.h"

namespace nl {

struct StoredLink {
    Handle id;
    Link link;
};

// The links of one navmesh at one moment, in the order they were added.
using LinkSnapshot = std::vector<StoredLink>;

class LinkStore {
public:
    explicit LinkStore(uint32_t handle_tag) : links_(handle_tag) {}

    Handle add(Handle navmesh, const Link& link);
    // Replaces a link's fields; its navmesh and whether it was generated stay.
    void update(Handle id, const Link& link);
    void remove(Handle id);
    // Throws InvalidHandle for an unknown id.
    std::pair<Handle, Link> get(Handle id) const;
    bool contains(Handle id) const;

    // Replaces the navmesh's generated links with `generated`; manual links stay. Returns the ids.
    std::vector<Handle> replace_generated(Handle navmesh, const std::vector<Link>& generated);
    // Replaces every link of the navmesh (loading a saved set).
    std::vector<Handle> replace_all(Handle navmesh, const std::vector<Link>& links);
    uint32_t remove_generated(Handle navmesh);
    void remove_navmesh(Handle navmesh);

    std::shared_ptr<const LinkSnapshot> snapshot(Handle navmesh) const;

private:
    struct Entry {
        Handle navmesh;
        Link link;
    };
    static uint64_t key(Handle h) { return (uint64_t(h.index1) << 32) | h.generation; }
    // Marks the navmesh's snapshot out of date; called under the exclusive lock after every edit.
    // The next snapshot() builds it: a run of edits with no reader between them costs one copy of
    // the list, not one per edit (20,000 single adds copied 200 million links).
    void publish(Handle navmesh);
    void erase_where(Handle navmesh, bool generated_only);

    mutable SharedMutex mutex_;
    SlotMap<Entry> links_;
    std::unordered_map<uint64_t, std::vector<Handle>> by_navmesh_;
    // Per navmesh with links: its last snapshot, or null while an edit since has not been read.
    mutable std::unordered_map<uint64_t, std::shared_ptr<const LinkSnapshot>> snapshots_;
    // Navmeshes removed from the world: a generation that finishes after the removal must not store links
    // for them.
    RemovedHandles removed_;
    void require_live(Handle navmesh) const;
};

}  // namespace nl
