// The function table a plugin is given: the world's queries, called directly on the core. A failing
// query returns its status to the plugin and is logged at debug level under the plugin's name; it
// never records the host thread's last status nor logs as an error of a call the host never made.
#include <algorithm>
#include <new>

#include "entry_guard.h"
#include "plugin_adapter.h"
#include "queries.h"

namespace nl::capi {
namespace {

static_assert(NL_BUILD_AREA_OBSTACLE == kObstacleArea, "plugin header and core disagree on the obstacle area");

thread_local std::string plugin_error;

// Runs a query for a plugin: its status, never an exception.
template <typename Call>
nl_status for_plugin(void* context, const char* query, Call&& call) noexcept {
    try {
        call();
        return NL_STATUS_SUCCESS;
    } catch (const Error& e) {
        try {
            world_of_plugin(context).logger().log(
                LogLevel::Debug, concat("plugin '", name_of_plugin(context), "': ", query, ": ", e.what()));
        } catch (...) {}
        return NL_STATUS_FAILURE | to_status(e.code());
    } catch (const std::bad_alloc&) {
        return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
    } catch (...) {
        return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
    }
}

void host_log(void* context, nl_log_level level, const char* message) {
    if (level > NL_LOG_DEBUG) level = NL_LOG_DEBUG;
    try {
        world_of_plugin(context).logger().log(static_cast<LogLevel>(level), message ? message : "");
    } catch (...) {}
}

void host_set_error(void*, const char* message) {
    try {
        plugin_error = message ? message : "";
    } catch (...) {}
}

// Copies `level` out in the two-call pattern into the plugin's buffers; `areas` may be null
// (get_level_triangles). BUFFER_TOO_SMALL when they are short.
nl_status copy_out(const BuildTriangles& level, float* vertices, uint32_t vertex_capacity, uint32_t* out_vertex_count,
                   uint32_t* indices, uint8_t* areas, bool areas_asked, uint32_t triangle_capacity,
                   uint32_t* out_triangle_count) {
    const TriangleMesh& mesh = level.mesh;
    if (out_vertex_count) *out_vertex_count = static_cast<uint32_t>(mesh.vertices.size());
    if (out_triangle_count) *out_triangle_count = static_cast<uint32_t>(mesh.triangles.size());
    if (vertex_capacity == 0 && triangle_capacity == 0) return NL_STATUS_SUCCESS;
    if (!vertices || !indices || (areas_asked && !areas) || mesh.vertices.size() > vertex_capacity ||
        mesh.triangles.size() > triangle_capacity)
        return NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
    for (size_t i = 0; i < mesh.vertices.size(); ++i) Eigen::Map<Vec3>(vertices + 3 * i) = mesh.vertices[i];
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
    if (areas_asked) std::copy(level.areas.begin(), level.areas.end(), areas);
    return NL_STATUS_SUCCESS;
}

// The two-call copy of what a build is for; `areas` may be null (get_level_triangles).
nl_status copy_build_triangles(void* context, const char* query, float* vertices, uint32_t vertex_capacity,
                               uint32_t* out_vertex_count, uint32_t* indices, uint8_t* areas, bool areas_asked,
                               uint32_t triangle_capacity, uint32_t* out_triangle_count) {
    nl_status copied = NL_STATUS_SUCCESS;
    const nl_status ran = for_plugin(context, query, [&] {
        with_level_triangles(context, [&](const BuildTriangles& level) {
            copied = copy_out(level, vertices, vertex_capacity, out_vertex_count, indices, areas, areas_asked,
                              triangle_capacity, out_triangle_count);
        });
    });
    return NL_FAILED(ran) ? ran : copied;
}

nl_status host_get_level_triangles(void* context, float* vertices, uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                   uint32_t* indices, uint32_t triangle_capacity, uint32_t* out_triangle_count) {
    return copy_build_triangles(context, "get_level_triangles", vertices, vertex_capacity, out_vertex_count, indices,
                                nullptr, false, triangle_capacity, out_triangle_count);
}

nl_status host_get_build_triangles(void* context, float* vertices, uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                   uint32_t* indices, uint8_t* areas, uint32_t triangle_capacity,
                                   uint32_t* out_triangle_count) {
    return copy_build_triangles(context, "get_build_triangles", vertices, vertex_capacity, out_vertex_count, indices,
                                areas, true, triangle_capacity, out_triangle_count);
}

nl_status host_get_build_triangles_in_columns(void* context, const double* columns, float* vertices,
                                              uint32_t vertex_capacity, uint32_t* out_vertex_count, uint32_t* indices,
                                              uint8_t* areas, uint32_t triangle_capacity, uint32_t* out_triangle_count,
                                              float* out_bounds) {
    nl_status copied = NL_STATUS_SUCCESS;
    const nl_status ran = for_plugin(context, "get_build_triangles_in_columns", [&] {
        if (!columns) fail(ErrorCode::InvalidArgument, "columns is NULL");
        const Columns asked{columns[0], columns[1], columns[2], columns[3]};
        with_build_triangles_in_columns(context, asked, [&](const BuildTriangles& level, const Aabb& bounds) {
            if (out_bounds) {
                const bool none = bounds.empty();
                for (int axis = 0; axis < 3; ++axis) {
                    out_bounds[axis] = none ? 0.0f : bounds.min[axis];
                    out_bounds[3 + axis] = none ? 0.0f : bounds.max[axis];
                }
            }
            copied = copy_out(level, vertices, vertex_capacity, out_vertex_count, indices, areas, true,
                              triangle_capacity, out_triangle_count);
        });
    });
    return NL_FAILED(ran) ? ran : copied;
}

nl_status host_report_build_progress(void* context, float fraction, const char* stage) {
    bool go_on = true;
    const nl_status ran =
        for_plugin(context, "report_build_progress", [&] { go_on = report_build_progress(context, fraction, stage); });
    if (NL_FAILED(ran)) return ran;
    return go_on ? NL_STATUS_SUCCESS : NL_STATUS_FAILURE | NL_STATUS_CANCELLED;
}

nl_status host_record_build_settings(void* context, const char* settings_json, size_t length) {
    return for_plugin(context, "record_build_settings", [&] {
        if (!settings_json) fail(ErrorCode::InvalidArgument, "settings_json is NULL");
        record_build_settings(context, std::string_view(settings_json, length));
    });
}

nl_status host_run_tasks(void* context, uint32_t count, nl_plugin_task_fn* task, void* user) {
    return for_plugin(context, "run_tasks", [&] {
        if (!task) fail(ErrorCode::InvalidArgument, "task is NULL");
        run_build_tasks(context, count, [&](uint32_t index) { task(user, index); });
    });
}

nl_status host_boundary_edges(void* context, nl_navmesh_id navmesh, nl_boundary_edge* out, uint32_t capacity,
                              uint32_t* count) {
    return for_plugin(context, "navmesh_get_boundary_edges",
                      [&] { navmesh_get_boundary_edges(world_of_plugin(context), navmesh, out, capacity, count); });
}

nl_status host_navmesh_info(void* context, nl_navmesh_id navmesh, nl_navmesh_info* out) {
    return for_plugin(context, "navmesh_get_info", [&] { navmesh_get_info(world_of_plugin(context), navmesh, out); });
}

nl_status host_find_nearest(void* context, nl_navmesh_id navmesh, const float* points, uint32_t count,
                            const float* half_extents, nl_nav_point* out) {
    return for_plugin(context, "navmesh_find_nearest", [&] {
        navmesh_find_nearest(world_of_plugin(context), navmesh, points, count, half_extents, out);
    });
}

nl_status host_cast_rays(void* context, const nl_ray* rays, uint32_t count, nl_ray_hit* hits) {
    return for_plugin(context, "cast_rays", [&] { cast_rays(world_of_plugin(context), rays, count, hits); });
}

nl_status host_segments_blocked(void* context, const nl_segment* segments, uint32_t count, uint8_t* blocked) {
    return for_plugin(context, "segments_blocked",
                      [&] { segments_blocked(world_of_plugin(context), segments, count, blocked); });
}

}  // namespace

std::string take_plugin_error() {
    std::string message;
    message.swap(plugin_error);
    return message;
}

nl_plugin_host make_plugin_host(void* context) {
    nl_plugin_host host{};
    host.size = sizeof(nl_plugin_host);
    host.abi_version = NL_PLUGIN_ABI_VERSION;
    host.context = context;
    host.log = host_log;
    host.set_error = host_set_error;
    host.get_level_triangles = host_get_level_triangles;
    host.navmesh_get_boundary_edges = host_boundary_edges;
    host.navmesh_get_info = host_navmesh_info;
    host.navmesh_find_nearest = host_find_nearest;
    host.cast_rays = host_cast_rays;
    host.segments_blocked = host_segments_blocked;
    host.record_build_settings = host_record_build_settings;
    host.get_build_triangles = host_get_build_triangles;
    host.report_build_progress = host_report_build_progress;
    host.run_tasks = host_run_tasks;
    host.get_build_triangles_in_columns = host_get_build_triangles_in_columns;
    return host;
}

}  // namespace nl::capi
