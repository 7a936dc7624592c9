#include <chrono>
#include <cstddef>
#include <exception>

#include "entry_guard.h"
#include "host_input.h"
#include "navlink/plugin.h"
#include "navlink/recast.h"
#include "recast_builder.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;

namespace {

constexpr size_t kBuildDefFirstSize = offsetof(nl_navmesh_build_def, settings_json_length) + sizeof(size_t);
constexpr size_t kDescriptionFirstSize = offsetof(nl_plugin_description, description) + sizeof(const char*);

using nl::capi::to_handle;
using nl::capi::to_id;

// What a builder hands back through the sink: the navmesh, validated and built but not yet added
// (only a builder that then succeeds gets it added), or why it was refused.
struct BuildSink {
    nl_world* world = nullptr;
    int calls = 0;
    std::shared_ptr<const nl::NavMesh> navmesh;
    std::exception_ptr error;

    static nl_status receive(void* context, const nl_navmesh_def* def) {
        auto& self = *static_cast<BuildSink*>(context);
        if (++self.calls > 1) {
            nl::capi::take_plugin_error();
            return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
        }
        try {
            require(def, "navmesh");
            self.navmesh = nl::capi::navmesh_from_def(*self.world, *def, "nl_navmesh_build");
            return NL_STATUS_SUCCESS;
        } catch (const nl::Error& e) {
            self.error = std::current_exception();
            return NL_STATUS_FAILURE | nl::capi::to_status(e.code());
        } catch (...) {
            self.error = std::current_exception();
            return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
        }
    }
};

std::string loaded_builders(const nl::capi::PluginRegistry& plugins) {
    std::string names;
    for (nl::Handle h : plugins.handles()) {
        const nl::capi::Plugin& p = plugins.get(h);
        if (p.info.kinds & NL_PLUGIN_NAVMESH_BUILDER) names += (names.empty() ? "'" : ", '") + p.name + "'";
    }
    return names.empty() ? "none" : names;
}

}  // namespace

namespace nl::capi {

void register_builtin_plugins(PluginRegistry& registry) {
    registry.add(nl::recast::plugin_entry, nullptr, true, "recast (built in)");
}

}  // namespace nl::capi

extern "C" {

NL_API nl_recast_settings nl_default_recast_settings(void) { return nl::recast::default_settings(); }

NL_API nl_navmesh_build_def nl_default_navmesh_build_def(void) {
    nl_navmesh_build_def def{};
    def.size = sizeof(nl_navmesh_build_def);
    def.builder = "recast";
    def.agent = nl_default_agent_type();
    return def;
}

NL_API nl_status nl_navmesh_build(nl_world* world, const nl_navmesh_build_def* def, nl_navmesh_id* out_id) {
    return guarded("nl_navmesh_build", world, [&] {
        nl_world& w = deref(world);
        require(def, "def");
        require(out_id, "out_id");
        const nl_navmesh_build_def settings =
            nl::capi::read_growable(*def, nl_default_navmesh_build_def(), kBuildDefFirstSize, "def");
        const std::string name = settings.builder ? settings.builder : "recast";
        const nl::capi::Plugin* builder = w.plugins->find_navmesh_builder(name);
        if (!builder)
            fail(ErrorCode::NotFound, "no navmesh builder named '", name, "' (loaded: ", loaded_builders(*w.plugins), ")");

        const auto start = std::chrono::steady_clock::now();
        BuildSink sink;
        sink.world = &w;
        nl::capi::take_plugin_error();
        const nl_status status = builder->info.navmesh_builder.build(builder->info.state, &w.plugins->host(), &settings,
                                                                    &BuildSink::receive, &sink);
        const std::string reason = nl::capi::take_plugin_error();
        if (sink.error) {
            // The builder's output, not the caller's arguments, was wrong.
            try {
                std::rethrow_exception(sink.error);
            } catch (const nl::Error& e) {
                if (e.code() == ErrorCode::OutOfMemory) throw;
                fail(ErrorCode::Internal, "builder '", name, "' made a navmesh that was refused: ", e.what());
            }
        }
        if (sink.calls > 1) fail(ErrorCode::Internal, "builder '", name, "' handed over ", sink.calls, " navmeshes, not one");
        if (NL_FAILED(status)) {
            throw nl::Error(nl::capi::to_error_code(status),
                            nl::concat("builder '", name, "': ", reason.empty() ? nl_status_string(status) : reason));
        }
        if (sink.calls == 0) fail(ErrorCode::Internal, "builder '", name, "' succeeded without handing over a navmesh");
        *out_id = to_id<nl_navmesh_id>(w.navmeshes->add(std::move(sink.navmesh)));
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        nl::capi::log(&w, NL_LOG_INFO, NL_STATUS_SUCCESS, nl::concat("nl_navmesh_build: '", name, "' built a navmesh in ", ms, " ms"));
    });
}

NL_API nl_status nl_plugin_load(nl_world* world, const char* path, nl_plugin_id* out_id) {
    return guarded("nl_plugin_load", world, [&] {
        nl_world& w = deref(world);
        require(path, "path");
        require(out_id, "out_id");
        *out_id = to_id<nl_plugin_id>(w.plugins->load(path));
    });
}

NL_API nl_status nl_plugin_register(nl_world* world, nl_plugin_entry_fn* entry, nl_plugin_id* out_id) {
    return guarded("nl_plugin_register", world, [&] {
        nl_world& w = deref(world);
        require(reinterpret_cast<const void*>(entry), "entry");
        require(out_id, "out_id");
        *out_id = to_id<nl_plugin_id>(w.plugins->add(entry, nullptr, false, "registered by the host"));
    });
}

NL_API nl_status nl_plugin_get_description(const nl_world* world, nl_plugin_id plugin,
                                           nl_plugin_description* out_description) {
    return guarded("nl_plugin_get_description", world, [&] {
        const nl::capi::Plugin& p = deref(world).plugins->get(to_handle(plugin));
        require(out_description, "out_description");
        nl_plugin_description d{};
        d.size = sizeof d;
        d.abi_version = p.info.abi_version;
        d.kinds = p.info.kinds;
        d.builtin = p.builtin ? 1u : 0u;
        d.name = p.name.c_str();
        d.version = p.version.c_str();
        d.description = p.description.c_str();
        nl::capi::write_growable(out_description, d, kDescriptionFirstSize, "out_description");
    });
}

NL_API nl_status nl_world_get_plugins(const nl_world* world, nl_plugin_id* out_ids, uint32_t capacity,
                                      uint32_t* out_count) {
    return guarded("nl_world_get_plugins", world, [&] {
        nl::capi::list_into(deref(world).plugins->handles(), out_ids, capacity, out_count, "out_ids", to_id<nl_plugin_id>);
    });
}

}  // extern "C"
