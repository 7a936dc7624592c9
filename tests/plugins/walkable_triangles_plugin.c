/*
 * A navmesh-builder plugin loaded at run time by the plugin tests, written in C against
 * capi/include/navlink/plugin.h only. Builder "walkable-triangles": every level triangle no steeper
 * than the agent's max slope becomes a navmesh triangle. Compiled several times with one of:
 *   TEST_PLUGIN_OK          the working plugin
 *   TEST_PLUGIN_NO_ENTRY    exports no nl_plugin_entry
 *   TEST_PLUGIN_TOO_NEW     needs a host ABI version this library does not have
 *   TEST_PLUGIN_BAD_ANSWER  answers a version higher than the host offered
 */
#include <navlink/plugin.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define EXPORT __attribute__((visibility("default")))
#else
#define EXPORT
#endif

static nl_status build(void* state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                       nl_navmesh_sink_fn* sink, void* sink_context) {
    uint32_t vertex_count = 0, triangle_count = 0, kept = 0, t;
    float* vertices;
    uint32_t* indices;
    nl_status status;
    const float min_up = cosf(def->agent_type.max_slope * 3.14159265f / 180.0f);
    (void)state;

    status = host->get_level_triangles(host->context, NULL, 0, &vertex_count, NULL, 0, &triangle_count);
    if (NL_FAILED(status)) return status;
    if (triangle_count == 0) {
        host->set_error(host->context, "the level has no triangles");
        return NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
    }
    vertices = (float*)malloc(sizeof(float) * 3 * vertex_count);
    indices = (uint32_t*)malloc(sizeof(uint32_t) * 3 * triangle_count);
    if (!vertices || !indices) {
        free(vertices);
        free(indices);
        return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
    }
    status = host->get_level_triangles(host->context, vertices, vertex_count, &vertex_count, indices, triangle_count,
                                       &triangle_count);
    if (NL_SUCCEEDED(status)) {
        for (t = 0; t < triangle_count; ++t) {
            const float* a = vertices + 3 * indices[3 * t];
            const float* b = vertices + 3 * indices[3 * t + 1];
            const float* c = vertices + 3 * indices[3 * t + 2];
            const float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            const float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            const float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                e1[0] * e2[1] - e1[1] * e2[0]};
            const float length = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (length > 0.0f && n[1] / length >= min_up) {
                memmove(indices + 3 * kept, indices + 3 * t, 3 * sizeof(uint32_t));
                ++kept;
            }
        }
        if (kept == 0) {
            host->set_error(host->context, "no triangle is flat enough to walk on");
            status = NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
        } else {
            /* Filled by hand, not with nl_default_navmesh_def(): a plugin needs no symbol of the library. */
            nl_navmesh_def navmesh;
            memset(&navmesh, 0, sizeof navmesh);
            navmesh.size = (uint32_t)sizeof navmesh;
            navmesh.weld_tolerance = 0.001f;
            navmesh.vertices = vertices;
            navmesh.vertex_count = vertex_count;
            navmesh.indices = indices;
            navmesh.polygon_count = kept;
            navmesh.agent_type = def->agent_type;
            status = sink(sink_context, &navmesh);
        }
    }
    free(vertices);
    free(indices);
    return status;
}

#if !defined(TEST_PLUGIN_NO_ENTRY)
EXPORT nl_status nl_plugin_entry(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    (void)host;
#if defined(TEST_PLUGIN_TOO_NEW)
    if (host_abi_version < 99u) return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
#endif
    if (host_abi_version < 1u) return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
#if defined(TEST_PLUGIN_BAD_ANSWER)
    out_info->abi_version = host_abi_version + 1u;
#else
    out_info->abi_version = 1u;
#endif
    out_info->name = "walkable-triangles";
    out_info->version = "1.0";
    out_info->description = "every level triangle flat enough to walk on";
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER;
    out_info->navmesh_builder.build = build;
    return NL_STATUS_SUCCESS;
}
#else
/* Something to export, so the library is otherwise a normal one. */
EXPORT nl_navmesh_builder not_a_plugin(void) {
    nl_navmesh_builder b;
    b.build = build;
    return b;
}
#endif
