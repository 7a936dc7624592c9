#include <chrono>
#include <cstddef>
#include <exception>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "mapping.h"
#include "navlink/plugin.h"
#include "plugin_adapter.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;

namespace {

using nl::capi::to_handle;
using nl::capi::to_id;

}  // namespace

namespace nl::capi {

NavMeshBuildRequest build_request_from_def(const nl_navmesh_build_def& given) {
    const nl_navmesh_build_def def =
        read_growable(given, nl_default_navmesh_build_def(), kFirstSize<nl_navmesh_build_def>, "def");
    if (def.tile_origin_x != 0.0f || def.tile_origin_z != 0.0f || def.tile_width != 0.0f || def.first_tile.x != 0 ||
        def.first_tile.z != 0 || def.tile_columns != 0 || def.tile_rows != 0)
        fail_field(ErrorCode::InvalidArgument,
                   "tile_origin_x, tile_origin_z, tile_width, first_tile, tile_columns and tile_rows are set by the "
                   "world for its builder: leave them 0 (nl_navmesh_build_tiles takes a box)");
    NavMeshBuildRequest request;
    request.builder = def.builder ? def.builder : "recast";
    request.agent_type = to_core(def.agent_type);
    request.builder_settings = def.settings;
    request.settings_json = def.settings_json;
    request.settings_json_length = def.settings_json_length;
    request.carrier = to_handle(def.carrier);
    if (def.progress) request.progress = progress_of(def.progress, def.progress_user);
    return request;
}

}  // namespace nl::capi

extern "C" {

NL_API nl_navmesh_build_def nl_default_navmesh_build_def(void) {
    nl_navmesh_build_def def{};
    def.size = sizeof(nl_navmesh_build_def);
    def.builder = "recast";
    def.agent_type = nl_default_agent_type();
    return def;
}

NL_API nl_status nl_navmesh_build(nl_world* world, const nl_navmesh_build_def* def, nl_navmesh_id* out_id) {
    return guarded("nl_navmesh_build", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        require(out_id, "out_id");
        const nl::NavMeshBuildRequest request =
            nl::naming_fields("def->", [&] { return nl::capi::build_request_from_def(*def); });
        const auto start = std::chrono::steady_clock::now();
        *out_id = to_id<nl_navmesh_id>(nl::naming_fields("def->", [&] { return w.build_navmesh(request); }));
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        w.logger().log(nl::LogLevel::Info,
                       nl::concat("nl_navmesh_build: '", request.builder, "' built a navmesh in ", ms, " ms"));
    });
}

NL_API nl_status nl_plugin_load(nl_world* world, const char* path, nl_plugin_id* out_id) {
    return guarded("nl_plugin_load", world, [&] {
        nl::World& w = deref(world);
        require(path, "path");
        require(out_id, "out_id");
        *out_id = to_id<nl_plugin_id>(nl::capi::load_c_plugin(w, path));
    });
}

NL_API nl_status nl_plugin_register(nl_world* world, nl_plugin_entry_fn* entry, nl_plugin_id* out_id) {
    return guarded("nl_plugin_register", world, [&] {
        nl::World& w = deref(world);
        require(reinterpret_cast<const void*>(entry), "entry");
        require(out_id, "out_id");
        *out_id = to_id<nl_plugin_id>(nl::capi::add_c_plugin(w, entry, nullptr, false, "registered by the host"));
    });
}

NL_API nl_status nl_plugin_get_description(const nl_world* world, nl_plugin_id plugin,
                                           nl_plugin_description* out_description) {
    return guarded("nl_plugin_get_description", world, [&] {
        nl::Plugin& p = deref(world).plugins().get(to_handle(plugin));
        require(out_description, "out_description");
        const nl::PluginDescription& described = p.description();
        nl_plugin_description d{};
        d.size = sizeof d;
        d.abi_version = described.abi_version;
        d.kinds = (p.navmesh_builder() ? NL_PLUGIN_NAVMESH_BUILDER : 0u) | (p.link_kind() ? NL_PLUGIN_LINK_KIND : 0u);
        d.builtin = described.builtin ? 1u : 0u;
        d.name = described.name.c_str();
        d.version = described.version.c_str();
        d.description = described.description.c_str();
        nl::capi::write_growable(out_description, d, nl::capi::kFirstSize<nl_plugin_description>, "out_description");
    });
}

NL_API nl_status nl_world_get_plugins(const nl_world* world, nl_plugin_id* out_ids, uint32_t capacity,
                                      uint32_t* out_count) {
    return guarded("nl_world_get_plugins", world, [&] {
        nl::capi::list_into(deref(world).plugins().handles(), out_ids, capacity, out_count, "out_ids",
                            to_id<nl_plugin_id>);
    });
}

}  // extern "C"
