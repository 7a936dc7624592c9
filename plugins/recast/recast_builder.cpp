#include "recast_builder.h"

#include <cstddef>
#include <exception>
#include <new>

#include "build_failure.h"
#include "host_log_context.h"
#include "level_triangles.h"
#include "navmesh_export.h"
#include "recast_settings.h"
#include "solo_mesh.h"
#include "tiled_mesh.h"

namespace nl::recast {
namespace {

#define NL_RECAST_STRINGIFY2(x) #x
#define NL_RECAST_STRINGIFY(x) NL_RECAST_STRINGIFY2(x)
// The plugin ships with the library, so it carries the library's version.
constexpr const char kVersion[] = NL_RECAST_STRINGIFY(NL_VERSION_MAJOR) "." NL_RECAST_STRINGIFY(
    NL_VERSION_MINOR) "." NL_RECAST_STRINGIFY(NL_VERSION_PATCH);
#undef NL_RECAST_STRINGIFY
#undef NL_RECAST_STRINGIFY2

constexpr const char kName[] = "recast";
constexpr const char kDescription[] =
    "Builds a navmesh from the level with Recast (solo mesh or tiles, as RecastDemo), settings nl_recast_settings or "
    "JSON";

// The sink refused a tile: its status ends the build, with the reason the host already holds.
struct SinkRefused {
    nl_status status;
};

nl_status report(const nl_plugin_host& host, nl_status status, const char* message) noexcept {
    host_set_error(host, message);
    return status;
}

nl_status build(void* /*plugin_state*/, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                nl_navmesh_sink_fn* sink, void* sink_context) noexcept {
    if (!host) return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    try {
        if (!def) fail(NL_STATUS_INVALID_ARGUMENT, "def is NULL");
        if (!sink) fail(NL_STATUS_INVALID_ARGUMENT, "sink is NULL");
        if (def->size < offsetof(nl_navmesh_build_def, settings_json_length) + sizeof def->settings_json_length)
            fail(NL_STATUS_INVALID_ARGUMENT, "def->size is ", def->size, ", smaller than an nl_navmesh_build_def");
        validate_agent(def->agent_type);
        const nl_recast_settings settings = resolve_settings(*def);
        const BuildProgress progress(*host);
        progress.report(0.0f, "reading the level");
        const LevelTriangles level = fetch_level_triangles(*host, columns_to_read(settings, *def));

        HostLogContext context(*host);
        const nl_status recorded = host_record_build_settings(*host, settings_to_json(settings));
        if (NL_FAILED(recorded))
            fail(recorded & ~NL_STATUS_FAILURE, "the host refused the record of the settings used");
        if (asks_for_tiles(*def) && settings.tile_size == 0)
            fail(NL_STATUS_INVALID_ARGUMENT, "tiles of ", def->tile_width,
                 " m were asked for, but the settings' tile_size is 0 (one solo mesh): build with the settings the "
                 "navmesh was built with");
        if (settings.tile_size > 0) {
            // The sink reports its own failures; the first one is the build's.
            build_tiled_mesh(context, *host, level, settings, *def, progress, [&](const NavMeshExport& tile) {
                const nl_navmesh_def tile_def = tile.def(def->agent_type);
                const nl_status handed = sink(sink_context, &tile_def);
                if (NL_FAILED(handed)) throw SinkRefused{handed};
            });
            return NL_STATUS_SUCCESS;
        }
        const RecastPolygons mesh = build_solo_mesh(context, level, settings, def->agent_type, progress);
        progress.report(0.98f, "handing over the navmesh");
        const NavMeshExport navmesh(*mesh.polygons, *mesh.detail);
        const nl_navmesh_def navmesh_def = navmesh.def(def->agent_type);
        // The sink reports its own failures; its status is the build's.
        return sink(sink_context, &navmesh_def);
    } catch (const SinkRefused& refused) {
        return refused.status;
    } catch (const BuildFailure& e) {
        return report(*host, e.status(), e.what());
    } catch (const std::bad_alloc&) {
        return report(*host, NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY, "out of memory while building the navmesh");
    } catch (const std::exception& e) {
        return report(*host, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, e.what());
    } catch (...) {
        return report(*host, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, "unknown exception in the recast builder");
    }
}

}  // namespace

nl_recast_settings default_settings() noexcept {
    nl_recast_settings s{};
    s.size = sizeof s;
    s.cell_size = 0.3f;
    s.cell_height = 0.2f;
    s.region_min_size = 8.0f;
    s.region_merge_size = 20.0f;
    s.edge_max_length = 12.0f;
    s.edge_max_error = 1.3f;
    s.vertices_per_polygon = 6;
    s.detail_sample_distance = 6.0f;
    s.detail_sample_max_error = 1.0f;
    s.partition = NL_RECAST_PARTITION_WATERSHED;
    s.filter_low_hanging_obstacles = 1;
    s.filter_ledge_spans = 1;
    s.filter_walkable_low_height_spans = 1;
    s.reserved = 0;
    s.tile_size = 0;
    s.tile_border = 0;
    return s;
}

nl_status plugin_entry(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) noexcept {
    if (host_abi_version < 1) {
        if (host) {
            host_set_error(*host, "recast: the host speaks plugin ABI version 0; this plugin speaks 1 and later");
        }
        return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
    }
    if (!out_info || out_info->size < sizeof(nl_plugin_info)) {
        if (host) host_set_error(*host, "recast: out_info is NULL or smaller than an nl_plugin_info");
        return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    }
    out_info->abi_version = host_abi_version < NL_PLUGIN_ABI_VERSION ? host_abi_version : NL_PLUGIN_ABI_VERSION;
    out_info->name = kName;
    out_info->version = kVersion;
    out_info->description = kDescription;
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER;
    out_info->state = nullptr;  // stateless: builds share nothing
    out_info->destroy = nullptr;
    out_info->navmesh_builder.build = &build;
    return NL_STATUS_SUCCESS;
}

}  // namespace nl::recast

extern "C" {

// Declared in navlink/recast.h: part of the library's ABI, defined with the builder it describes.
NL_API nl_recast_settings nl_default_recast_settings(void) { return nl::recast::default_settings(); }

}  // extern "C"
