#include "level_triangles.h"

#include <climits>
#include <cstddef>
#include <cmath>

#include "build_failure.h"
#include "host_table.h"

namespace nl::recast {
namespace {

// The level may grow between the counting call and the copying call (another thread adds a mesh);
// then the copy is BUFFER_TOO_SMALL and is tried again with the new counts, a few times.
constexpr int kAttempts = 8;

void check(const LevelTriangles& level) {
    const size_t vertex_count = level.vertices.size() / 3;
    for (size_t i = 0; i < level.vertices.size(); ++i) {
        if (!std::isfinite(level.vertices[i]))
            fail(NL_STATUS_INVALID_ARGUMENT, "level vertex ", i / 3, " has a coordinate that is not finite");
    }
    if (level.whole_bounds)
        for (float v : *level.whole_bounds)
            if (!std::isfinite(v))
                fail(NL_STATUS_INTERNAL_ERROR, "get_build_triangles_in_columns gave bounds that are not finite");
    for (size_t i = 0; i < level.indices.size(); ++i) {
        if (level.indices[i] >= vertex_count)
            fail(NL_STATUS_INTERNAL_ERROR, "get_level_triangles gave index ", level.indices[i], " of triangle ", i / 3,
                 " but only ", vertex_count, " vertices");
    }
}

}  // namespace

LevelTriangles fetch_level_triangles(const nl_plugin_host& host, const std::optional<std::array<double, 4>>& columns) {
    const bool in_columns = columns && NL_RECAST_HOST_OFFERS(host, get_build_triangles_in_columns);
    const bool with_areas = NL_RECAST_HOST_OFFERS(host, get_build_triangles);
    if (!with_areas && !NL_RECAST_HOST_OFFERS(host, get_level_triangles))
        fail(NL_STATUS_INVALID_ARGUMENT, "the host offers no get_level_triangles");
    const char* const query = in_columns   ? "get_build_triangles_in_columns"
                              : with_areas ? "get_build_triangles"
                                           : "get_level_triangles";
    LevelTriangles level;
    if (in_columns) level.whole_bounds.emplace();
    auto copy = [&](uint32_t vertex_capacity, uint32_t* vertex_count, uint32_t triangle_capacity,
                    uint32_t* triangle_count) {
        float* const vertices = vertex_capacity ? level.vertices.data() : nullptr;
        uint32_t* const indices = triangle_capacity ? level.indices.data() : nullptr;
        if (in_columns)
            return host.get_build_triangles_in_columns(host.context, columns->data(), vertices, vertex_capacity,
                                                       vertex_count, indices,
                                                       triangle_capacity ? level.areas.data() : nullptr,
                                                       triangle_capacity, triangle_count, level.whole_bounds->data());
        if (with_areas)
            return host.get_build_triangles(host.context, vertices, vertex_capacity, vertex_count, indices,
                                            triangle_capacity ? level.areas.data() : nullptr, triangle_capacity,
                                            triangle_count);
        return host.get_level_triangles(host.context, vertices, vertex_capacity, vertex_count, indices,
                                        triangle_capacity, triangle_count);
    };

    uint32_t vertex_count = 0;
    uint32_t triangle_count = 0;
    nl_status status = copy(0, &vertex_count, 0, &triangle_count);
    uint32_t vertex_capacity = 0;
    uint32_t triangle_capacity = 0;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        if (NL_FAILED(status) && !(status & NL_STATUS_BUFFER_TOO_SMALL))
            fail(status & NL_STATUS_DETAIL_MASK, query, " failed (status 0x", std::hex, status, ")");
        if (vertex_count > INT_MAX / 3 || triangle_count > INT_MAX / 3)
            fail(NL_STATUS_INVALID_ARGUMENT, "the level has ", vertex_count, " vertices and ", triangle_count,
                 " triangles; Recast takes at most ", INT_MAX / 3, " of each");
        if (attempt > 0 && NL_SUCCEEDED(status)) {
            if (vertex_count > vertex_capacity || triangle_count > triangle_capacity)
                fail(NL_STATUS_INTERNAL_ERROR, query, " succeeded with counts beyond the capacities");
            level.vertices.resize(size_t{vertex_count} * 3);
            level.indices.resize(size_t{triangle_count} * 3);
            level.areas.resize(triangle_count);
            check(level);
            return level;
        }
        if (triangle_count == 0 && NL_SUCCEEDED(status)) return level;  // an empty level
        level.vertices.assign(size_t{vertex_count} * 3, 0.0f);
        level.indices.assign(size_t{triangle_count} * 3, 0u);
        level.areas.assign(triangle_count, 0);  // what an older host's triangles all are
        vertex_capacity = vertex_count;
        triangle_capacity = triangle_count;
        status = copy(vertex_capacity, &vertex_count, triangle_capacity, &triangle_count);
    }
    fail(NL_STATUS_INTERNAL_ERROR, "the level kept changing while its triangles were copied (", kAttempts,
         " attempts)");
}

}  // namespace nl::recast
