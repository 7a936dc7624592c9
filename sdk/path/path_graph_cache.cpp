#include "path/path_graph_cache.h"

namespace nl {

std::shared_ptr<const PathGraph> PathGraphCache::get(Handle navmesh_id, std::shared_ptr<const NavMesh> navmesh,
                                                     std::shared_ptr<const LinkSnapshot> links) {
    auto current = [&](const std::shared_ptr<const PathGraph>& graph) {
        // A navmesh without links gets a fresh empty snapshot every time: empty equals empty.
        return graph && graph->navmesh_ptr() == navmesh &&
               (graph->links_ptr() == links || (graph->links_ptr()->empty() && (!links || links->empty())));
    };
    {
        std::lock_guard lock(mutex_);
        auto found = graphs_.find(key(navmesh_id));
        if (found != graphs_.end() && current(found->second)) return found->second;
    }
    // Built outside the lock: requests on other navmeshes, or on this one's cached graph, go on.
    auto graph = std::make_shared<const PathGraph>(std::move(navmesh), std::move(links));
    std::lock_guard lock(mutex_);
    graphs_[key(navmesh_id)] = graph;
    return graph;
}

void PathGraphCache::forget(Handle navmesh_id) {
    std::lock_guard lock(mutex_);
    graphs_.erase(key(navmesh_id));
}

}  // namespace nl
