#include "plugin_adapter.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>

#include "entry_guard.h"
#include "level/level_hash.h"
#include "host_input.h"
#include "mapping.h"
#include "navmesh/tile_join.h"

namespace nl::capi {
namespace {

// One C plugin as the core's interfaces.
class CPlugin final : public Plugin, public NavMeshBuilder, public LinkKindProvider {
public:
    CPlugin(World& world, std::unique_ptr<platform::DynamicLibrary> library, bool builtin)
        : world_(world), library_(std::move(library)), host_(make_plugin_host(this)) {
        info_.size = sizeof(nl_plugin_info);
        description_.builtin = builtin;
    }
    ~CPlugin() override {
        if (started_ && info_.destroy) info_.destroy(info_.state);
    }
    CPlugin(const CPlugin&) = delete;
    CPlugin& operator=(const CPlugin&) = delete;

    void start(nl_plugin_entry_fn* entry, const std::string& origin);

    World& world() noexcept { return world_; }

    const PluginDescription& description() const noexcept override { return description_; }
    NavMeshBuilder* navmesh_builder() noexcept override {
        return (info_.kinds & NL_PLUGIN_NAVMESH_BUILDER) ? this : nullptr;
    }
    LinkKindProvider* link_kind() noexcept override { return (info_.kinds & NL_PLUGIN_LINK_KIND) ? this : nullptr; }

    BuiltNavMesh build(World& world, const NavMeshBuildRequest& request) override;
    uint32_t kind() const noexcept override { return info_.link_kind.kind; }
    const std::string& kind_name() const noexcept override { return kind_name_; }
    void propose(World& world, Handle navmesh, const std::string& settings_json,
                 FunctionRef<void(Link)> accept) override;

private:
    void check_description(const std::string& origin) const;

    World& world_;
    std::unique_ptr<platform::DynamicLibrary> library_;  // unloaded after the plugin's destroy
    nl_plugin_host host_;
    nl_plugin_info info_{};
    bool started_ = false;
    PluginDescription description_;
    std::string kind_name_;
};

void CPlugin::check_description(const std::string& origin) const {
    if (!info_.name || !*info_.name) fail(ErrorCode::InvalidArgument, "plugin ", origin, " has no name");
    if ((info_.kinds & NL_PLUGIN_NAVMESH_BUILDER) && !info_.navmesh_builder.build)
        fail(ErrorCode::InvalidArgument, "plugin '", info_.name,
             "' says it builds navmeshes but gives no build function");
    if ((info_.kinds & NL_PLUGIN_LINK_KIND) &&
        (!info_.link_kind.generate || !info_.link_kind.kind_name || info_.link_kind.kind < NL_LINK_FIRST_PLUGIN_KIND))
        fail(ErrorCode::InvalidArgument, "plugin '", info_.name,
             "' says it provides a link kind but its kind is below NL_LINK_FIRST_PLUGIN_KIND or has no name or "
             "generate function");
    if (info_.kinds & ~(NL_PLUGIN_NAVMESH_BUILDER | NL_PLUGIN_LINK_KIND))
        fail(ErrorCode::InvalidArgument, "plugin '", info_.name, "' has unknown kinds 0x", std::hex, info_.kinds);
}

void CPlugin::start(nl_plugin_entry_fn* entry, const std::string& origin) {
    take_plugin_error();
    const nl_status status = entry(NL_PLUGIN_ABI_VERSION, &host_, &info_);
    const std::string reason = take_plugin_error();
    if (NL_FAILED(status)) {
        if (status & NL_STATUS_VERSION_MISMATCH)
            fail(ErrorCode::VersionMismatch, "plugin ", origin,
                 " speaks no plugin ABI version <= ", NL_PLUGIN_ABI_VERSION, reason.empty() ? "" : ": ", reason);
        throw Error(to_error_code(status) == ErrorCode::OutOfMemory ? ErrorCode::OutOfMemory : ErrorCode::Internal,
                    concat("plugin ", origin, " refused to start (", nl_status_string(status), ")",
                           reason.empty() ? "" : ": ", reason));
    }
    started_ = true;  // from here on its destroy function is owed
    if (info_.abi_version == 0 || info_.abi_version > NL_PLUGIN_ABI_VERSION)
        fail(ErrorCode::VersionMismatch, "plugin ", origin, " answered ABI version ", info_.abi_version,
             "; this library speaks 1..", NL_PLUGIN_ABI_VERSION);
    check_description(origin);
    description_.name = info_.name;
    description_.version = info_.version ? info_.version : "";
    description_.description = info_.description ? info_.description : "";
    description_.abi_version = info_.abi_version;
    if (info_.kinds & NL_PLUGIN_LINK_KIND) kind_name_ = info_.link_kind.kind_name;
}

// What a builder hands back through the sink: the navmesh, validated and built (the builder is told
// when it was refused), or its tiles, kept to be joined when it returns; or why it was refused.
struct BuildSink {
    int calls = 0;
    std::shared_ptr<const NavMesh> navmesh;
    TileInputs tiles;
    std::exception_ptr error;

    static nl_status receive(void* context, const nl_navmesh_def* def) {
        auto& self = *static_cast<BuildSink*>(context);
        ++self.calls;
        try {
            require(def, "navmesh");
            NavMeshInput input = naming_fields("def->", [&] { return navmesh_input_from_def(*def); });
            if (input.tiles.grid.tiled()) {
                if (self.navmesh) fail(ErrorCode::InvalidArgument, "a tile was handed over after a solo navmesh");
                self.tiles.push_back(std::make_shared<const NavMeshInput>(std::move(input)));
                return NL_STATUS_SUCCESS;
            }
            if (self.calls > 1) {
                take_plugin_error();
                return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
            }
            self.navmesh = naming_fields("def->", [&] { return build_navmesh(input); });
            return NL_STATUS_SUCCESS;
        } catch (const Error& e) {
            self.error = std::current_exception();
            return NL_STATUS_FAILURE | to_status(e.code());
        } catch (const std::bad_alloc&) {
            self.error = std::current_exception();
            return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
        } catch (...) {
            self.error = std::current_exception();
            return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
        }
    }

    // The tiles joined into one navmesh (tile_join.h); the tiles kept in row order.
    void join_tiles_handed() {
        navmesh = build_navmesh(join_tiles(tiles));
        sort_in_row_order(tiles);
    }
};

// The build this thread runs (builders call back on the thread that called them).
struct RunningBuild;
thread_local RunningBuild* running_build = nullptr;

struct RunningBuild {
    RunningBuild(const CPlugin& builder, const NavMeshBuildRequest& request)
        : builder(builder), request(request), outer(running_build) {
        running_build = this;
    }
    ~RunningBuild() { running_build = outer; }
    RunningBuild(const RunningBuild&) = delete;
    RunningBuild& operator=(const RunningBuild&) = delete;

    const CPlugin& builder;
    const NavMeshBuildRequest& request;
    std::string settings_used;             // what the builder recorded (host->record_build_settings)
    std::optional<BuildTriangles> handed;  // the level as the builder was shown it, unless the request had it
    struct ColumnsRead {
        Columns columns;
        BuildTriangles triangles;
        Aabb bounds;
    };
    std::optional<ColumnsRead> columns_read;  // the last columns the builder read of it
    RunningBuild* outer;
};

BuiltNavMesh CPlugin::build(World&, const NavMeshBuildRequest& request) {
    RunningBuild running(*this, request);
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.carrier = to_id<nl_mesh_id>(request.carrier);
    def.builder = description_.name.c_str();
    def.agent_type = to_c(request.agent_type);
    def.settings = request.builder_settings;
    def.settings_json = request.settings_json;
    def.settings_json_length = request.settings_json_length;
    if (request.only_tiles.asked()) {
        def.tile_origin_x = request.only_tiles.grid.origin_x;
        def.tile_origin_z = request.only_tiles.grid.origin_z;
        def.tile_width = request.only_tiles.grid.tile_width;
        def.first_tile = nl_tile_coord{request.only_tiles.first.x, request.only_tiles.first.z};
        def.tile_columns = request.only_tiles.columns;
        def.tile_rows = request.only_tiles.rows;
    }
    BuildSink sink;
    take_plugin_error();
    const nl_status status = info_.navmesh_builder.build(info_.state, &host_, &def, &BuildSink::receive, &sink);
    const std::string reason = take_plugin_error();
    const std::string& name = description_.name;
    if (sink.error) {
        // The builder's output, not the caller's arguments, was wrong.
        try {
            std::rethrow_exception(sink.error);
        } catch (const Error& e) {
            if (e.code() == ErrorCode::OutOfMemory) throw;
            fail(ErrorCode::Internal, "builder '", name, "' made a navmesh that was refused: ", e.what());
        }
    }
    if (sink.calls > 1 && sink.tiles.empty())
        fail(ErrorCode::Internal, "builder '", name, "' handed over ", sink.calls, " navmeshes, not one");
    if (NL_FAILED(status))
        throw Error(to_error_code(status),
                    concat("builder '", name, "': ", reason.empty() ? nl_status_string(status) : reason));
    if (request.only_tiles.asked()) {
        // Some tiles, maybe none: the world puts them in the navmesh.
        if (sink.navmesh) fail(ErrorCode::Internal, "builder '", name, "' handed over a solo navmesh for tiles");
        sort_in_row_order(sink.tiles);
        return {nullptr, std::move(running.settings_used), 0, std::move(sink.tiles)};
    }
    if (sink.calls == 0) fail(ErrorCode::Internal, "builder '", name, "' succeeded without handing over a navmesh");
    if (!sink.tiles.empty()) {
        try {
            sink.join_tiles_handed();
        } catch (const Error& e) {
            if (e.code() == ErrorCode::OutOfMemory) throw;
            fail(ErrorCode::Internal, "builder '", name, "' made tiles that were refused: ", e.what());
        }
    }
    const uint64_t built_from = request.level ? request.level_hash : running.handed ? level_hash(*running.handed) : 0;
    return {std::move(sink.navmesh), std::move(running.settings_used), built_from, std::move(sink.tiles)};
}

// What a link-kind plugin hands back through the sink: each link read and given to `accept`, whose
// refusal the plugin is told of.
struct LinkSink {
    FunctionRef<void(Link)> accept;
    bool out_of_memory = false;

    static nl_status receive(void* context, const nl_link_def* def) {
        auto& self = *static_cast<LinkSink*>(context);
        try {
            require(def, "link");
            self.accept(naming_fields("def->", [&] { return link_from_def(*def); }));
            return NL_STATUS_SUCCESS;
        } catch (const std::bad_alloc&) {
            self.out_of_memory = true;
            return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
        } catch (const Error& e) {
            if (e.code() == ErrorCode::OutOfMemory) self.out_of_memory = true;
            return NL_STATUS_FAILURE | to_status(e.code());
        } catch (...) {
            return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
        }
    }
};

void CPlugin::propose(World&, Handle navmesh, const std::string& settings_json, FunctionRef<void(Link)> accept) {
    LinkSink sink{accept};
    take_plugin_error();
    const nl_status status = info_.link_kind.generate(info_.state, &host_, to_id<nl_navmesh_id>(navmesh),
                                                      settings_json.empty() ? nullptr : settings_json.c_str(),
                                                      settings_json.size(), &LinkSink::receive, &sink);
    const std::string reason = take_plugin_error();
    if (sink.out_of_memory) throw std::bad_alloc();
    if (NL_FAILED(status))
        throw Error(to_error_code(status), concat("link-kind plugin '", description_.name,
                                                  "': ", reason.empty() ? nl_status_string(status) : reason));
}

}  // namespace

void with_level_triangles(void* context, FunctionRef<void(const BuildTriangles&)> use) {
    const Level& level = world_of_plugin(context).level();
    if (running_build) {
        const NavMeshBuildRequest& request = running_build->request;
        if (request.level) return use(*request.level);
        std::optional<BuildTriangles>& handed = running_build->handed;
        if (!handed) handed = level.triangles_to_build(request.carrier);
        use(*handed);
        return;
    }
    BuildTriangles all;
    all.mesh = level.world_triangles();
    all.areas.assign(all.mesh.triangles.size(), 0);
    use(all);
}

void with_build_triangles_in_columns(void* context, const Columns& columns,
                                     FunctionRef<void(const BuildTriangles&, const Aabb& bounds)> use) {
    if (!running_build || &running_build->builder != context)
        fail(ErrorCode::InvalidArgument,
             "get_build_triangles_in_columns was called outside a navmesh build of this plugin on this thread");
    auto& read = running_build->columns_read;
    if (!read || !(read->columns == columns)) {
        Aabb bounds;
        BuildTriangles triangles = world_of_plugin(context).level().triangles_to_build_in_columns(
            running_build->request.carrier, columns, bounds);
        read = RunningBuild::ColumnsRead{columns, std::move(triangles), bounds};
    }
    use(read->triangles, read->bounds);
}

bool report_build_progress(void* context, float fraction, const char* stage) {
    if (!running_build || &running_build->builder != context)
        fail(ErrorCode::InvalidArgument,
             "report_build_progress was called outside a navmesh build of this plugin on this thread");
    const auto& progress = running_build->request.progress;
    return !progress || progress(fraction, stage);
}

void record_build_settings(void* context, std::string_view settings_json) {
    if (!running_build || &running_build->builder != context)
        fail(ErrorCode::InvalidArgument,
             "record_build_settings was called outside a navmesh build of this plugin on this thread");
    running_build->settings_used.assign(settings_json);
}

void run_build_tasks(void* context, uint32_t count, FunctionRef<void(uint32_t index)> task) {
    if (!running_build || &running_build->builder != context)
        fail(ErrorCode::InvalidArgument, "run_tasks was called outside a navmesh build of this plugin on this thread");
    world_of_plugin(context).tasks().parallel_for(count, 1, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) task(i);
    });
}

World& world_of_plugin(void* context) { return static_cast<CPlugin*>(context)->world(); }
const std::string& name_of_plugin(void* context) { return static_cast<CPlugin*>(context)->description().name; }

Handle add_c_plugin(World& world, nl_plugin_entry_fn* entry, std::unique_ptr<platform::DynamicLibrary> library,
                    bool builtin, const std::string& origin) {
    auto plugin = std::make_unique<CPlugin>(world, std::move(library), builtin);
    plugin->start(entry, origin);
    return world.plugins().add(std::move(plugin));
}

Handle load_c_plugin(World& world, const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(ErrorCode::NotFound, "no plugin library at '", path, "'");
    auto library = std::make_unique<platform::DynamicLibrary>(path);
    void* symbol = library->function(NL_PLUGIN_ENTRY_SYMBOL);
    if (!symbol) fail(ErrorCode::NotFound, "'", path, "' exports no ", NL_PLUGIN_ENTRY_SYMBOL, " function");
    nl_plugin_entry_fn* entry;
    static_assert(sizeof(entry) == sizeof(symbol), "function and object pointers differ in size");
    std::memcpy(&entry, &symbol, sizeof entry);  // POSIX guarantees the conversion; C++ needs a copy
    return add_c_plugin(world, entry, std::move(library), false, "'" + path + "'");
}

}  // namespace nl::capi
