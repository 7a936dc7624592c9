#include "world/plugin_registry.h"

#include <mutex>
#include <shared_mutex>

namespace nl {

PluginRegistry::~PluginRegistry() {
    for (auto it = order_.rbegin(); it != order_.rend(); ++it) plugins_.find(*it)->reset();
}

Handle PluginRegistry::add(std::unique_ptr<Plugin> plugin) {
    std::unique_lock lock(mutex_);
    const PluginDescription& described = plugin->description();
    const LinkKindProvider* kind = plugin->link_kind();
    for (Handle h : order_) {
        Plugin& other = **plugins_.find(h);
        if (other.description().name == described.name)
            fail(ErrorCode::InvalidArgument, "a plugin named '", described.name, "' is already loaded");
        if (kind && other.link_kind() && other.link_kind()->kind() == kind->kind())
            fail(ErrorCode::InvalidArgument, "plugin '", described.name, "' claims link kind ", kind->kind(),
                 ", which plugin '", other.description().name, "' has");
    }
    order_.reserve(order_.size() + 1);  // nothing may throw once the plugin is in
    const Handle h = plugins_.insert(std::move(plugin));
    order_.push_back(h);
    return h;
}

Plugin& PluginRegistry::get(Handle plugin) const {
    std::shared_lock lock(mutex_);
    const auto* found = plugins_.find(plugin);
    if (!found) fail_stale("plugin", plugin);
    return **found;
}

NavMeshBuilder* PluginRegistry::find_navmesh_builder(const std::string& name) const {
    std::shared_lock lock(mutex_);
    for (Handle h : order_) {
        Plugin& p = **plugins_.find(h);
        if (p.description().name == name && p.navmesh_builder()) return p.navmesh_builder();
    }
    return nullptr;
}

std::vector<std::string> PluginRegistry::navmesh_builder_names() const {
    std::shared_lock lock(mutex_);
    std::vector<std::string> names;
    for (Handle h : order_) {
        Plugin& p = **plugins_.find(h);
        if (p.navmesh_builder()) names.push_back(p.description().name);
    }
    return names;
}

std::vector<Plugin*> PluginRegistry::link_kind_plugins() const {
    std::shared_lock lock(mutex_);
    std::vector<Plugin*> out;
    for (Handle h : order_) {
        Plugin* p = plugins_.find(h)->get();
        if (p->link_kind()) out.push_back(p);
    }
    return out;
}

std::string listed_names(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "'" : ", '") + name + "'";
    return out.empty() ? "none" : out;
}

std::vector<Handle> PluginRegistry::handles() const {
    std::shared_lock lock(mutex_);
    return order_;
}

}  // namespace nl
