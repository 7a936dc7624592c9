#include "core_world.h"

#include <cstddef>
#include <cstring>
#include <string>
#include <utility>

#include "cell_map.h"
#include "generated_mesh.h"
#include "io/link_json.h"
#include "io/obj_reader.h"
#include "navmesh/tile_join.h"
#include "navlink/plugin.h"
#include "recast_builder.h"
#include "util/error.h"

namespace nl::test {
namespace {

// The core error code of a plugin ABI status's detail bit (the reverse of the C layer's mapping, for
// the codes a builder returns).
ErrorCode code_of(nl_status status) {
    if (status & NL_STATUS_INVALID_ARGUMENT) return ErrorCode::InvalidArgument;
    if (status & NL_STATUS_NOT_FOUND) return ErrorCode::NotFound;
    if (status & NL_STATUS_OUT_OF_MEMORY) return ErrorCode::OutOfMemory;
    if (status & NL_STATUS_PARSE_ERROR) return ErrorCode::Parse;
    if (status & NL_STATUS_VERSION_MISMATCH) return ErrorCode::VersionMismatch;
    if (status & NL_STATUS_CANCELLED) return ErrorCode::Cancelled;
    return ErrorCode::Internal;
}

// The navmesh a builder hands over, as core input: the arrays of an nl_navmesh_def copied as
// nl_navmesh_add reads them (capi/src/navmesh_api.cpp, navmesh_input_from_def). The builder's output
// is trusted here: the core's build_navmesh still checks it.
NavMeshInput input_of(const nl_navmesh_def& def) {
    NavMeshInput in;
    const size_t step = def.vertex_stride == 0 ? 3 * sizeof(float) : def.vertex_stride;
    const auto* bytes = reinterpret_cast<const unsigned char*>(def.vertices);
    for (uint32_t i = 0; i < def.vertex_count; ++i) {
        float xyz[3];
        std::memcpy(xyz, bytes + i * step, sizeof xyz);
        in.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    size_t index_count = size_t(def.polygon_count) * 3;
    if (def.polygon_vertex_counts) {
        in.polygon_sizes.assign(def.polygon_vertex_counts, def.polygon_vertex_counts + def.polygon_count);
        index_count = 0;
        for (uint8_t n : in.polygon_sizes) index_count += n;
    }
    in.indices.assign(def.indices, def.indices + index_count);
    if (def.areas) in.areas.assign(def.areas, def.areas + def.polygon_count);
    in.weld_tolerance = def.weld_tolerance;
    in.agent_type =
        AgentType{def.agent_type.radius, def.agent_type.height, def.agent_type.max_climb, def.agent_type.max_slope};
    if (def.tile_width > 0.0f) {
        in.tiles.grid = TileGrid{def.tile_origin_x, def.tile_origin_z, def.tile_width};
        in.tiles.tiles.push_back(TileCoord{def.tile_x, def.tile_z});
    }
    if (def.detail_triangle_starts) {
        in.detail_starts.assign(def.detail_triangle_starts, def.detail_triangle_starts + def.polygon_count + 1);
        for (uint32_t i = 0; i < def.detail_vertex_count; ++i)
            in.detail_vertices.emplace_back(def.detail_vertices[3 * i], def.detail_vertices[3 * i + 1],
                                            def.detail_vertices[3 * i + 2]);
        in.detail_indices.assign(def.detail_triangles, def.detail_triangles + size_t(def.detail_triangle_count) * 3);
    }
    return in;
}

// The Recast plugin behind the core's builder interface: its entry function and build function, a
// host table over the world's level (the level's world-space triangles, as the C layer's table gives
// them), and a sink that builds the core navmesh.
class RecastBuilder final : public Plugin, public NavMeshBuilder {
public:
    RecastBuilder() {
        const nl_plugin_host host = table(nullptr);
        info_.size = sizeof info_;
        if (NL_FAILED(recast::plugin_entry(NL_PLUGIN_ABI_VERSION, &host, &info_)))
            fail(ErrorCode::Internal, "the recast plugin refused to start");
        description_ = PluginDescription{info_.name, info_.version, info_.description, info_.abi_version, true};
    }
    const PluginDescription& description() const noexcept override { return description_; }
    NavMeshBuilder* navmesh_builder() noexcept override { return this; }

    BuiltNavMesh build(World& world, const NavMeshBuildRequest& request) override {
        Call call{&world, {}, nullptr, {}, {}, {}};
        const nl_plugin_host host = table(&call);
        nl_navmesh_build_def def{};
        def.size = sizeof def;
        def.builder = description_.name.c_str();
        def.agent_type = nl_agent_type{request.agent_type.radius, request.agent_type.height,
                                       request.agent_type.max_climb, request.agent_type.max_slope};
        def.settings = request.builder_settings;
        def.settings_json = request.settings_json;
        def.settings_json_length = request.settings_json_length;
        const auto& only = request.only_tiles;
        if (only.asked()) {
            def.tile_origin_x = only.grid.origin_x;
            def.tile_origin_z = only.grid.origin_z;
            def.tile_width = only.grid.tile_width;
            def.first_tile = nl_tile_coord{only.first.x, only.first.z};
            def.tile_columns = only.columns;
            def.tile_rows = only.rows;
        }
        const nl_status status = info_.navmesh_builder.build(info_.state, &host, &def, &Call::receive, &call);
        if (call.error) std::rethrow_exception(call.error);
        if (NL_FAILED(status)) fail(code_of(status), call.reason);
        if (only.asked()) return {nullptr, std::move(call.settings_used), 0, std::move(call.tiles)};
        if (!call.tiles.empty()) call.navmesh = build_navmesh(join_tiles(call.tiles));
        return {std::move(call.navmesh), std::move(call.settings_used), 0, std::move(call.tiles)};
    }

private:
    struct Call {
        World* world;
        std::string reason;  // the plugin's set_error
        std::shared_ptr<const NavMesh> navmesh;
        std::exception_ptr error;
        std::string settings_used;

        TileInputs tiles;  // a tiled build's (row order: the builder hands them so), joined when it returns

        static nl_status receive(void* context, const nl_navmesh_def* def) {
            auto& self = *static_cast<Call*>(context);
            try {
                if (def->tile_width > 0.0f) {
                    self.tiles.push_back(std::make_shared<const NavMeshInput>(input_of(*def)));
                    return NL_STATUS_SUCCESS;
                }
                self.navmesh = build_navmesh(input_of(*def));
                return NL_STATUS_SUCCESS;
            } catch (...) {
                self.error = std::current_exception();
                return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
            }
        }
    };

    static nl_plugin_host table(Call* call) {
        nl_plugin_host h{};
        h.size = sizeof h;
        h.abi_version = NL_PLUGIN_ABI_VERSION;
        h.context = call;
        h.set_error = [](void* context, const char* message) {
            if (context) static_cast<Call*>(context)->reason = message ? message : "";
        };
        h.get_level_triangles = &level_triangles;
        h.record_build_settings = [](void* context, const char* json, size_t length) {
            static_cast<Call*>(context)->settings_used.assign(json, length);
            return NL_STATUS_SUCCESS;
        };
        // As the C layer's: the tasks on the world's task system.
        h.run_tasks = [](void* context, uint32_t count, nl_plugin_task_fn* task, void* user) {
            static_cast<Call*>(context)->world->tasks().parallel_for(count, 1, [&](uint32_t begin, uint32_t end) {
                for (uint32_t i = begin; i < end; ++i) task(user, i);
            });
            return NL_STATUS_SUCCESS;
        };
        return h;
    }

    // As the C layer's host table (capi/src/plugin_host.cpp): counts always, both buffers or none.
    static nl_status level_triangles(void* context, float* vertices, uint32_t vertex_capacity,
                                     uint32_t* out_vertex_count, uint32_t* indices, uint32_t triangle_capacity,
                                     uint32_t* out_triangle_count) {
        const TriangleMesh level = static_cast<Call*>(context)->world->level().world_triangles();
        if (out_vertex_count) *out_vertex_count = static_cast<uint32_t>(level.vertices.size());
        if (out_triangle_count) *out_triangle_count = static_cast<uint32_t>(level.triangles.size());
        if (vertex_capacity == 0 && triangle_capacity == 0) return NL_STATUS_SUCCESS;
        if (!vertices || !indices || level.vertices.size() > vertex_capacity ||
            level.triangles.size() > triangle_capacity)
            return NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
        for (size_t i = 0; i < level.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) vertices[3 * i + k] = level.vertices[i][k];
        for (size_t t = 0; t < level.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) indices[3 * t + k] = level.triangles[t][k];
        return NL_STATUS_SUCCESS;
    }

    nl_plugin_info info_{};
    PluginDescription description_;
};

}  // namespace

std::unique_ptr<World> make_world(int workers, unsigned path_workers) {
    WorldSettings settings;
    settings.worker_count = workers;
    settings.path_worker_count = path_workers;
    return std::make_unique<World>(std::move(settings));
}

Handle add_level(World& world, const levelgen::GeneratedLevel& level, uint32_t flags, const Transform& transform) {
    return world.level().add_mesh(to_triangle_mesh(level), transform, flags, 0);
}

Handle add_obj_file(World& world, const std::filesystem::path& path) {
    return world.level().add_mesh(read_obj_file(path.string()), Transform::Identity(), 0, 0);
}

void add_recast_builder(World& world) {
    if (!world.plugins().find_navmesh_builder("recast")) world.plugins().add(std::make_unique<RecastBuilder>());
}

Handle build_recast_navmesh(World& world, const AgentType& agent, const std::string& settings_json) {
    add_recast_builder(world);
    NavMeshBuildRequest request;
    request.builder = "recast";
    request.agent_type = agent;
    if (!settings_json.empty()) {
        request.settings_json = settings_json.c_str();
        request.settings_json_length = settings_json.size();
    }
    return world.build_navmesh(request);
}

RecastWorld recast_world(const levelgen::GeneratedLevel& level, int workers) {
    RecastWorld out;
    out.world = make_world(workers);
    add_level(*out.world, level);
    out.navmesh = build_recast_navmesh(*out.world);
    out.mesh = out.world->navmeshes().navmesh(out.navmesh);
    return out;
}

std::vector<StoredLink> links_of(const World& world, Handle navmesh) {
    const auto snapshot = world.navmeshes().links(navmesh);
    return std::vector<StoredLink>(snapshot->begin(), snapshot->end());
}

std::string save_links_json(const World& world, Handle navmesh) {
    std::vector<Link> links;
    for (const StoredLink& s : links_of(world, navmesh)) links.push_back(s.link);
    return links_to_json(links);
}

size_t load_links_json(World& world, Handle navmesh, const std::string& json) {
    std::vector<Link> links = links_from_json(json);
    const size_t count = links.size();
    world.load_links(navmesh, std::move(links));
    return count;
}

NavMeshInput cell_navmesh(const std::vector<std::string>& rows, float agent_radius) {
    const CellMap map(rows);
    NavMeshInput in;
    for (size_t i = 0; i + 2 < map.vertices.size(); i += 3)
        in.vertices.emplace_back(map.vertices[i], map.vertices[i + 1], map.vertices[i + 2]);
    in.indices = map.indices;
    in.polygon_sizes = map.counts;
    in.areas = map.areas;
    in.agent_type.radius = agent_radius;
    return in;
}

bool same_navmesh(const NavMesh& a, const NavMesh& b) {
    if (a.vertex_count() != b.vertex_count() || a.polygon_count() != b.polygon_count()) return false;
    for (uint32_t v = 0; v < a.vertex_count(); ++v)
        if (a.vertex(v) != b.vertex(v)) return false;
    for (uint32_t p = 0; p < a.polygon_count(); ++p)
        for (uint32_t k = 0; k < a.corner_count(p); ++k)
            if (a.corner(p, k) != b.corner(p, k) || a.neighbour(p, k) != b.neighbour(p, k)) return false;
    return a.tiles().tiles == b.tiles().tiles;
}

}  // namespace nl::test
