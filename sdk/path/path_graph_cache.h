// The newest PathGraph of each navmesh. A request asks for the graph of the navmesh and links as
// they are now; the graph is built again only when the navmesh or its link snapshot changed, so a
// stream of requests between two edits shares one.
#pragma once

#include <memory>
#include <mutex>
#include <unordered_map>

#include "path/path_graph.h"
#include "util/handle.h"

namespace nl {

class PathGraphCache {
public:
    std::shared_ptr<const PathGraph> get(Handle navmesh_id, std::shared_ptr<const NavMesh> navmesh,
                                         std::shared_ptr<const LinkSnapshot> links);
    // Drops a removed navmesh's graph (requests holding it keep their copy).
    void forget(Handle navmesh_id);

private:
    static uint64_t key(Handle h) { return (uint64_t(h.index1) << 32) | h.generation; }

    std::mutex mutex_;
    std::unordered_map<uint64_t, std::shared_ptr<const PathGraph>> graphs_;
};

}  // namespace nl
