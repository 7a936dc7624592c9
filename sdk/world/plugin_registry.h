// The plugins of a world, in the order they were added (built-in ones first). A plugin stays until
// the world goes, so a plugin found once stays valid; they are destroyed last added first (a plugin
// may rely on one added before it).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "util/handle.h"
#include "os/shared_mutex.h"
#include "world/plugin.h"

namespace nl {

class PluginRegistry {
public:
    explicit PluginRegistry(uint32_t handle_tag) : plugins_(handle_tag, HandleKind::Plugin) {}
    ~PluginRegistry();
    PluginRegistry(const PluginRegistry&) = delete;
    PluginRegistry& operator=(const PluginRegistry&) = delete;

    // Throws InvalidArgument for a name or link kind another plugin has (the plugin is destroyed).
    Handle add(std::unique_ptr<Plugin> plugin);

    // Throws InvalidHandle for an unknown handle.
    // Plugins are thread-safe by contract, so a const registry hands them out as they are.
    Plugin& get(Handle plugin) const;
    NavMeshBuilder* find_navmesh_builder(const std::string& name) const;
    std::vector<std::string> navmesh_builder_names() const;
    std::vector<Plugin*> link_kind_plugins() const;  // those with a link kind, in the order they were added
    std::vector<Handle> handles() const;

private:
    mutable SharedMutex mutex_{"the plugins"};
    SlotMap<std::unique_ptr<Plugin>> plugins_;
    std::vector<Handle> order_;
};

// Plugin names or kinds as a message lists what is loaded: 'a', 'b' ("none" for no name).
std::string listed_names(const std::vector<std::string>& names);

}  // namespace nl
