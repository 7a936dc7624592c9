// The last generation of each navmesh of a world, kept so that nl_navmesh_update_links_in_box can continue
// it, and changed together with the generated links it made.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "links/link_generation.h"
#include "util/function_ref.h"
#include "util/handle.h"

namespace nl {

// Each navmesh's last generation, with the plugin settings it ran with.
class LinkBakes {
public:
    struct Entry {
        std::shared_ptr<LinkGeneration> generation;
        std::string plugin_settings_json;
    };

    // Generations and updates of one navmesh run one at a time, from reading its generation to storing its
    // links, so a later one never loses to an earlier one: hold a Turn for that span. A thread holds
    // one turn at a time: asking for a second (from a progress callback or a plugin of the generation it
    // runs) throws InvalidArgument instead of waiting, because two threads each waiting for the
    // other's navmesh from inside their callbacks would never wake.
    class Turn {
    public:
        explicit Turn(std::shared_ptr<std::mutex> mutex);
        ~Turn();
        Turn(const Turn&) = delete;
        Turn& operator=(const Turn&) = delete;

    private:
        std::shared_ptr<std::mutex> mutex_;
    };
    Turn take_turn(Handle navmesh);

    // The links a generation made and the generation itself change together, so that an update never continues
    // a generation whose links were taken away. Each of these runs `links` (which changes the navmesh's
    // links in the link store) and the bookkeeping in one step; `links` must not call back in here.
    //
    // A generation's result: records `entry` (ignored for a removed navmesh: a generation that
    // finishes after the removal keeps nothing).
    void store(Handle navmesh, Entry entry, FunctionRef<void()> links);
    // An update's result: runs `links` only while `generation` is still the navmesh's generation, else returns
    // false and runs nothing.
    bool store_if_current(Handle navmesh, const LinkGeneration* generation, FunctionRef<void()> links);
    // The generated links removed or replaced by a load: there is no generation left to update.
    void forget(Handle navmesh, FunctionRef<void()> links);

    Entry get(Handle navmesh) const;  // empty if the navmesh was never baked, or its generation forgotten
    void remove(Handle navmesh);

private:
    static uint64_t key(Handle h) { return (uint64_t(h.index1) << 32) | h.generation; }
    mutable std::mutex mutex_;
    std::unordered_map<uint64_t, Entry> bakes_;
    std::unordered_map<uint64_t, std::shared_ptr<std::mutex>> serializers_;
    RemovedHandles removed_;
};

}  // namespace nl
