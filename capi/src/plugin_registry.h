// The plugins of a world: built-in ones registered at creation, others loaded from shared libraries.
// Plugins are never unloaded before the world, so a plugin found once stays valid.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "navlink/plugin.h"
#include "util/handle.h"
#include "util/shared_mutex.h"

struct nl_world;

namespace nl::capi {

struct Plugin {
    nl_plugin_info info{};
    std::string name, version, description;  // copied: the world hands these out as its own
    void* library = nullptr;                 // dlopen handle, null for built-in plugins
    bool builtin = false;
};

class PluginRegistry {
public:
    PluginRegistry(nl_world& world, uint32_t handle_tag);
    ~PluginRegistry();
    PluginRegistry(const PluginRegistry&) = delete;
    PluginRegistry& operator=(const PluginRegistry&) = delete;

    // Negotiates with the entry function and registers what it provides. Throws (VersionMismatch,
    // InvalidArgument for a bad or duplicate description); `library` is then left to the caller.
    Handle add(nl_plugin_entry_fn* entry, void* library, bool builtin, const std::string& origin);
    // Loads a shared library and adds the plugin it exports.
    Handle load(const std::string& path);

    const Plugin& get(Handle h) const;
    const Plugin* find_navmesh_builder(const std::string& name) const;
    std::vector<const Plugin*> link_kinds() const;  // in registration order
    std::vector<Handle> handles() const;
    const nl_plugin_host& host() const { return host_; }

private:
    nl_plugin_host host_{};
    mutable SharedMutex mutex_;
    SlotMap<std::unique_ptr<Plugin>> plugins_;
    std::vector<Handle> order_;  // registration order: built-in first
};

// Registers the plugins compiled into the library (the Recast navmesh builder).
void register_builtin_plugins(PluginRegistry& registry);

// The reason a plugin gave through host->set_error during the current call on this thread (empty if
// none); taking it clears it.
std::string take_plugin_error();

}  // namespace nl::capi
