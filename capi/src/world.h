// What an nl_world is behind the opaque pointer.
#pragma once

#include <memory>

#include "level/level.h"
#include "links/link_bakes.h"
#include "links/link_store.h"
#include "navlink/navlink.h"
#include "navmesh/navmesh_registry.h"
#include "path/path_graph_cache.h"
#include "path/path_queue.h"
#include "plugin_registry.h"
#include "util/handle_tag.h"
#include "util/task_system.h"

// Members are destroyed in reverse order: the path queue goes first (its workers stop, requests still
// queued finish as cancelled), then plugins (their destroy functions may still use the world), the
// task system last.
struct nl_world {
    nl_world_def def;
    nl::HandleTag handle_tag = nl::HandleTag::acquire();  // released last, after every id it tagged
    std::unique_ptr<nl::TaskSystem> tasks;
    std::unique_ptr<nl::Level> level;
    std::unique_ptr<nl::NavMeshRegistry> navmeshes;
    std::unique_ptr<nl::LinkStore> links;
    std::unique_ptr<nl::LinkBakes> generations;  // each navmesh's last generation, for nl_navmesh_update_links_in_box
    std::unique_ptr<nl::capi::PluginRegistry> plugins;
    std::unique_ptr<nl::PathGraphCache> path_graphs;
    std::unique_ptr<nl::PathQueue> paths;
};

namespace nl::capi {

// Throws InvalidArgument for a null world.
inline nl_world& deref(nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world;
}
inline const nl_world& deref(const nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world;
}

}  // namespace nl::capi
