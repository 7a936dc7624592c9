#include "plugin_registry.h"

#include <dlfcn.h>

#include <filesystem>

#include "entry_guard.h"
#include "world.h"

namespace nl::capi {
namespace {

thread_local std::string plugin_error;

nl_world& world_of(void* context) { return *static_cast<nl_world*>(context); }

void host_log(void* context, nl_log_level level, const char* message) {
    log(&world_of(context), level, NL_STATUS_SUCCESS, message ? message : "");
}

void host_set_error(void* context, const char* message) {
    (void)context;
    try {
        plugin_error = message ? message : "";
    } catch (...) {
    }
}

nl_status host_get_level_triangles(void* context, float* vertices, uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                   uint32_t* indices, uint32_t triangle_capacity, uint32_t* out_triangle_count) {
    try {
        const TriangleMesh level = world_of(context).level->world_triangles();
        if (out_vertex_count) *out_vertex_count = static_cast<uint32_t>(level.vertices.size());
        if (out_triangle_count) *out_triangle_count = static_cast<uint32_t>(level.triangles.size());
        if (vertex_capacity == 0 && triangle_capacity == 0) return NL_STATUS_SUCCESS;
        if (!vertices || !indices || level.vertices.size() > vertex_capacity || level.triangles.size() > triangle_capacity)
            return NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
        for (size_t i = 0; i < level.vertices.size(); ++i) Eigen::Map<Vec3>(vertices + 3 * i) = level.vertices[i];
        for (size_t t = 0; t < level.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) indices[3 * t + k] = level.triangles[t][k];
        return NL_STATUS_SUCCESS;
    } catch (const std::bad_alloc&) {
        return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
    } catch (...) {
        return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
    }
}

nl_status host_boundary_edges(void* context, nl_navmesh_id navmesh, nl_boundary_edge* out, uint32_t capacity,
                               uint32_t* count) {
    return nl_navmesh_get_boundary_edges(&world_of(context), navmesh, out, capacity, count);
}
nl_status host_navmesh_info(void* context, nl_navmesh_id navmesh, nl_navmesh_info* out) {
    return nl_navmesh_get_info(&world_of(context), navmesh, out);
}
nl_status host_find_nearest(void* context, nl_navmesh_id navmesh, const float* points, uint32_t count,
                            const float* half_extents, nl_nav_point* out) {
    return nl_navmesh_find_nearest(&world_of(context), navmesh, points, count, half_extents, out);
}
nl_status host_cast_rays(void* context, const nl_ray* rays, uint32_t count, nl_ray_hit* hits) {
    return nl_world_cast_rays(&world_of(context), rays, count, hits);
}
nl_status host_segments_blocked(void* context, const nl_segment* segments, uint32_t count, uint8_t* blocked) {
    return nl_world_segments_blocked(&world_of(context), segments, count, blocked);
}

void check_description(const nl_plugin_info& info, const std::string& origin) {
    if (!info.name || !*info.name) fail(ErrorCode::InvalidArgument, "plugin ", origin, " has no name");
    if ((info.kinds & NL_PLUGIN_NAVMESH_BUILDER) && !info.navmesh_builder.build)
        fail(ErrorCode::InvalidArgument, "plugin '", info.name, "' says it builds navmeshes but gives no build function");
    if ((info.kinds & NL_PLUGIN_LINK_KIND) &&
        (!info.link_kind.generate || !info.link_kind.kind_name || info.link_kind.kind < NL_LINK_FIRST_PLUGIN_KIND))
        fail(ErrorCode::InvalidArgument, "plugin '", info.name,
             "' says it provides a link kind but its kind is below NL_LINK_FIRST_PLUGIN_KIND or has no name or generate function");
    if (info.kinds & ~(NL_PLUGIN_NAVMESH_BUILDER | NL_PLUGIN_LINK_KIND | NL_PLUGIN_PATH_MODIFIER))
        fail(ErrorCode::InvalidArgument, "plugin '", info.name, "' has unknown kinds 0x", std::hex, info.kinds);
}

}  // namespace

std::string take_plugin_error() {
    std::string message;
    message.swap(plugin_error);
    return message;
}

PluginRegistry::PluginRegistry(nl_world& world, uint32_t handle_tag) : plugins_(handle_tag) {
    host_.size = sizeof(nl_plugin_host);
    host_.abi_version = NL_PLUGIN_ABI_VERSION;
    host_.context = &world;
    host_.log = host_log;
    host_.set_error = host_set_error;
    host_.get_level_triangles = host_get_level_triangles;
    host_.navmesh_get_boundary_edges = host_boundary_edges;
    host_.navmesh_get_info = host_navmesh_info;
    host_.navmesh_find_nearest = host_find_nearest;
    host_.cast_rays = host_cast_rays;
    host_.segments_blocked = host_segments_blocked;
}

PluginRegistry::~PluginRegistry() {
    // Last registered first: a plugin may rely on one loaded before it.
    for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
        Plugin& p = **plugins_.find(*it);
        if (p.info.destroy) p.info.destroy(p.info.state);
        if (p.library) dlclose(p.library);
    }
}

Handle PluginRegistry::add(nl_plugin_entry_fn* entry, void* library, bool builtin, const std::string& origin) {
    auto plugin = std::make_unique<Plugin>();
    plugin->info.size = sizeof(nl_plugin_info);
    take_plugin_error();
    const nl_status status = entry(NL_PLUGIN_ABI_VERSION, &host_, &plugin->info);
    const std::string reason = take_plugin_error();
    if (NL_FAILED(status)) {
        if (status & NL_STATUS_VERSION_MISMATCH)
            fail(ErrorCode::VersionMismatch, "plugin ", origin, " speaks no plugin ABI version <= ", NL_PLUGIN_ABI_VERSION,
                 reason.empty() ? "" : ": ", reason);
        throw Error(to_error_code(status) == ErrorCode::OutOfMemory ? ErrorCode::OutOfMemory : ErrorCode::Internal,
                    concat("plugin ", origin, " refused to start (", nl_status_string(status), ")",
                           reason.empty() ? "" : ": ", reason));
    }
    const nl_plugin_info& info = plugin->info;
    auto release = [&] {
        if (info.destroy) info.destroy(info.state);
    };
    try {
        if (info.abi_version == 0 || info.abi_version > NL_PLUGIN_ABI_VERSION)
            fail(ErrorCode::VersionMismatch, "plugin ", origin, " answered ABI version ", info.abi_version,
                 "; this library speaks 1..", NL_PLUGIN_ABI_VERSION);
        check_description(info, origin);
        plugin->name = info.name;
        plugin->version = info.version ? info.version : "";
        plugin->description = info.description ? info.description : "";
        plugin->library = library;
        plugin->builtin = builtin;

        std::unique_lock lock(mutex_);
        for (Handle h : order_) {
            const Plugin& other = **plugins_.find(h);
            if (other.name == plugin->name)
                fail(ErrorCode::InvalidArgument, "a plugin named '", plugin->name, "' is already loaded");
            if ((info.kinds & NL_PLUGIN_LINK_KIND) && (other.info.kinds & NL_PLUGIN_LINK_KIND) &&
                other.info.link_kind.kind == info.link_kind.kind)
                fail(ErrorCode::InvalidArgument, "plugin '", plugin->name, "' claims link kind ", info.link_kind.kind,
                     ", which plugin '", other.name, "' has");
        }
        const Handle h = plugins_.insert(std::move(plugin));
        order_.push_back(h);
        return h;
    } catch (...) {
        release();
        throw;
    }
}

Handle PluginRegistry::load(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(ErrorCode::NotFound, "no plugin library at '", path, "'");
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        fail(ErrorCode::Io, "cannot load '", path, "': ", why ? why : "unknown loader error");
    }
    try {
        void* symbol = dlsym(library, NL_PLUGIN_ENTRY_SYMBOL);
        if (!symbol) fail(ErrorCode::NotFound, "'", path, "' exports no ", NL_PLUGIN_ENTRY_SYMBOL, " function");
        nl_plugin_entry_fn* entry;
        static_assert(sizeof(entry) == sizeof(symbol), "function and object pointers differ in size");
        std::memcpy(&entry, &symbol, sizeof entry);  // POSIX guarantees the conversion; C++ needs a copy
        return add(entry, library, false, "'" + path + "'");
    } catch (...) {
        dlclose(library);
        throw;
    }
}

const Plugin& PluginRegistry::get(Handle h) const {
    std::shared_lock lock(mutex_);
    const auto* found = plugins_.find(h);
    if (!found) fail_stale("plugin", h);
    return **found;
}

const Plugin* PluginRegistry::find_navmesh_builder(const std::string& name) const {
    std::shared_lock lock(mutex_);
    for (Handle h : order_) {
        const Plugin& p = **plugins_.find(h);
        if (p.name == name && (p.info.kinds & NL_PLUGIN_NAVMESH_BUILDER)) return &p;
    }
    return nullptr;
}

std::vector<const Plugin*> PluginRegistry::link_kinds() const {
    std::shared_lock lock(mutex_);
    std::vector<const Plugin*> out;
    for (Handle h : order_) {
        const Plugin& p = **plugins_.find(h);
        if (p.info.kinds & NL_PLUGIN_LINK_KIND) out.push_back(&p);
    }
    return out;
}

std::vector<Handle> PluginRegistry::handles() const {
    std::shared_lock lock(mutex_);
    return order_;
}

}  // namespace nl::capi
