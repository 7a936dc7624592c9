// NavLink for C++: a thin, header-only C++17 layer over the C ABI of <navlink/navlink.h>.
//
// It uses the public C functions only (nothing of the library's C++ core), so it works with any
// libnavlink.so of the same ABI, and adds no symbol of its own to link. What it gives (docs/cpp.md):
// - navlink::World owns an nl_world* (move-only; destroyed with nl_world_destroy); get() is the raw
//   pointer for every C function this layer does not wrap.
// - Ids: navlink::MeshId, NavmeshId, LinkId, AgentId, PluginId, PathTicket ARE the C id structs (they
//   derive from them, add no field, and pass to nl_* functions as they are), with == and != and
//   `explicit operator bool` (not the null id).
// - navlink::Status wraps an nl_status; navlink::Error (a std::runtime_error) carries the status and
//   the library's message (nl_get_last_error_message); navlink::check() throws it on a failure, and
//   every World method throws it where the C function fails.
// - navlink::two_call() runs the capacity/count pattern of the C lists into a std::vector (docs/c-api.md,
//   "Variable-size outputs"), and World's list methods use it.
// Each wrapper keeps its C function's semantics (which it names): what is borrowed, copied, thread-safe
// and which statuses it returns; only a failure turns into an exception.
#ifndef NAVLINK_NAVLINK_HPP
#define NAVLINK_NAVLINK_HPP

#if !defined(__cplusplus) || (__cplusplus < 201703L && !(defined(_MSVC_LANG) && _MSVC_LANG >= 201703L))
#error "navlink/navlink.hpp needs C++17; from C (or older C++) include navlink/navlink.h"
#endif

#include <navlink/navlink.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace navlink {

// ---------------------------------------------------------------------------------------------
// Statuses and errors
// ---------------------------------------------------------------------------------------------

/// An nl_status: a kind (success, failure, in progress) and detail bits (docs/c-api.md, "Statuses").
class Status {
public:
    constexpr Status() noexcept = default;  ///< NL_STATUS_SUCCESS.
    constexpr explicit Status(nl_status value) noexcept : value_(value) {}

    constexpr nl_status value() const noexcept { return value_; }
    constexpr bool succeeded() const noexcept { return NL_SUCCEEDED(value_); }  ///< NL_SUCCEEDED.
    constexpr bool failed() const noexcept { return NL_FAILED(value_); }        ///< NL_FAILED.
    constexpr bool in_progress() const noexcept { return (value_ & NL_STATUS_IN_PROGRESS) != 0u; }
    /// A success with NL_STATUS_PARTIAL_RESULT (a partial path).
    constexpr bool partial() const noexcept { return succeeded() && (value_ & NL_STATUS_PARTIAL_RESULT) != 0u; }
    /// The detail bits (NL_STATUS_INVALID_ARGUMENT, ..._BUFFER_TOO_SMALL...): value() & NL_STATUS_DETAIL_MASK.
    constexpr uint32_t detail() const noexcept { return value_ & NL_STATUS_DETAIL_MASK; }
    /// True if any of `detail_bits` is set, e.g. has(NL_STATUS_INVALID_HANDLE).
    constexpr bool has(uint32_t detail_bits) const noexcept { return (detail() & detail_bits) != 0u; }
    /// nl_status_string: "failure: invalid argument".
    std::string to_string() const { return nl_status_string(value_); }

    friend constexpr bool operator==(Status a, Status b) noexcept { return a.value_ == b.value_; }
    friend constexpr bool operator!=(Status a, Status b) noexcept { return a.value_ != b.value_; }

private:
    nl_status value_ = NL_STATUS_SUCCESS;
};

/// A failed call: its status and the library's message for it (nl_get_last_error_message, copied).
/// what() is the message followed by the status string: "nl_mesh_add: def->vertices[1].y is not
/// finite (nan) (failure: invalid argument)".
class Error : public std::runtime_error {
public:
    Error(Status status, const std::string& message)
        : std::runtime_error(message.empty() ? status.to_string() : message + " (" + status.to_string() + ")"),
          status_(status),
          message_length_(message.size()) {}

    Status status() const noexcept { return status_; }
    /// The library's message alone (empty if it gave none).
    std::string message() const { return std::string(what(), message_length_); }

private:
    Status status_;
    std::size_t message_length_;  // what() starts with the message (copying an Error never throws)
};

/// Returns `status` as a Status, or throws navlink::Error with this thread's last error message if it
/// is a failure. Call it right after the nl_* call that returned `status` (the message is the
/// calling thread's, until its next nl_* call).
inline Status check(nl_status status) {
    if (NL_FAILED(status)) throw Error(Status(status), nl_get_last_error_message());
    return Status(status);
}

namespace detail {

// A count for the C ABI (uint32_t), or an INVALID_ARGUMENT Error naming what is too large.
inline uint32_t count32(std::size_t n, const char* what) {
    if (n > std::numeric_limits<uint32_t>::max())
        throw Error(Status(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT),
                    std::string("navlink: ") + what + " has more than 4294967295 items");
    return static_cast<uint32_t>(n);
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Ids
// ---------------------------------------------------------------------------------------------

/// A C id struct (nl_mesh_id...) with == and != (both fields) and `explicit operator bool` (not the
/// all-zero null id). It is the C struct: it converts from it implicitly, passes to nl_* functions as
/// is, and reads as `id.index1`, `id.revision`. Compare a raw C id with a wrapped one (`event.agent
/// == agent`), or wrap it first (`navlink::MeshId(hit.mesh)`). Validity in a world: World::is_valid.
template <typename C>
struct Id : C {
    constexpr Id() noexcept : C{} {}  ///< The null id.
    constexpr Id(const C& id) noexcept : C(id) {}  ///< From the C id (implicit).

    constexpr explicit operator bool() const noexcept { return this->index1 != 0u || this->revision != 0u; }
    constexpr const C& raw() const noexcept { return *this; }

    friend constexpr bool operator==(const Id& a, const Id& b) noexcept {
        return a.index1 == b.index1 && a.revision == b.revision;
    }
    friend constexpr bool operator!=(const Id& a, const Id& b) noexcept { return !(a == b); }
};

using MeshId = Id<nl_mesh_id>;
using NavmeshId = Id<nl_navmesh_id>;
using LinkId = Id<nl_link_id>;
using AgentId = Id<nl_agent_id>;
using PluginId = Id<nl_plugin_id>;
using PathTicket = Id<nl_path_ticket>;

// ---------------------------------------------------------------------------------------------
// The two-call pattern
// ---------------------------------------------------------------------------------------------

/// Runs a C list function's capacity/count pattern into a vector: `fn(T* buffer, uint32_t capacity,
/// uint32_t* out_count)` returns an nl_status; it is called once with a null buffer to count, then
/// with a buffer of that many copies of `init_element` (for elements that may grow, the nl_*_init()
/// value that sets `size`; a plain T{} for ids), again while it says BUFFER_TOO_SMALL (the list grew
/// between the calls). Throws navlink::Error on any other failure. E.g.
///   two_call([&](nl_link* out, uint32_t capacity, uint32_t* count) {
///       return nl_navmesh_get_links(world.get(), navmesh, out, capacity, count); }, nl_link_init());
template <typename T, typename Fn>
std::vector<T> two_call(Fn&& fn, const T& init_element = T{}) {
    uint32_t count = 0;
    check(fn(static_cast<T*>(nullptr), uint32_t{0}, &count));
    std::vector<T> items;
    while (count > 0) {
        const uint32_t capacity = count;
        items.assign(capacity, init_element);
        const nl_status status = fn(items.data(), capacity, &count);
        if (NL_SUCCEEDED(status)) {
            items.resize(count <= capacity ? count : capacity);
            return items;
        }
        // Only a failure with BUFFER_TOO_SMALL that asks for more than we gave goes round again.
        if (!NL_FAILED(status) || (status & NL_STATUS_BUFFER_TOO_SMALL) == 0u || count <= capacity)
            throw Error(Status(status), nl_get_last_error_message());
    }
    items.clear();
    return items;
}

// ---------------------------------------------------------------------------------------------
// Requests, paths
// ---------------------------------------------------------------------------------------------

/// nl_default_path_request_def() for `agent` from `start` to `goal` on `navmesh` (the rest default).
inline nl_path_request_def path_request(NavmeshId navmesh, const float (&start)[3], const float (&goal)[3],
                                        const nl_agent_capabilities& agent = nl_default_agent_capabilities()) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    for (int k = 0; k < 3; ++k) {
        def.start[k] = start[k];
        def.goal[k] = goal[k];
    }
    def.capabilities = agent;
    return def;
}

/// nl_default_agent_def() on `navmesh` at `position` with `capabilities` (the rest default).
inline nl_agent_def agent_def(NavmeshId navmesh, const float (&position)[3],
                              const nl_agent_capabilities& capabilities = nl_default_agent_capabilities()) {
    nl_agent_def def = nl_default_agent_def();
    def.navmesh = navmesh;
    for (int k = 0; k < 3; ++k) def.position[k] = position[k];
    def.capabilities = capabilities;
    return def;
}

/// A planned path (World::find_path): nl_path_find's result and its points.
struct Path {
    nl_path_result result = nl_path_result_init();
    std::vector<nl_path_point> points;

    bool complete() const noexcept { return result.outcome == NL_PATH_COMPLETE; }  ///< Reaches the goal.
    bool partial() const noexcept { return result.outcome == NL_PATH_PARTIAL; }    ///< Goes as near as it can.
};

// ---------------------------------------------------------------------------------------------
// The world
// ---------------------------------------------------------------------------------------------

/// Owns an nl_world: created by the constructor, destroyed (nl_world_destroy) by the destructor,
/// reset() or a move assignment over it. Move-only; a moved-from World holds no world (get() is null,
/// and its methods throw INVALID_ARGUMENT as the C functions refuse a null world). Thread rules are
/// the C ones: methods may run on several threads at once, except destruction.
class World {
public:
    /// nl_world_create(NULL): every default.
    World() { check(nl_world_create(nullptr, &world_)); }
    /// nl_world_create(&def).
    explicit World(const nl_world_def& def) { check(nl_world_create(&def, &world_)); }
    /// Takes ownership of a world made by nl_world_create (may be null).
    explicit World(nl_world* owned) noexcept : world_(owned) {}
    ~World() { reset(); }

    World(World&& other) noexcept : world_(std::exchange(other.world_, nullptr)) {}
    World& operator=(World&& other) noexcept {
        if (this != &other) {
            reset();
            world_ = std::exchange(other.world_, nullptr);
        }
        return *this;
    }
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    nl_world* get() const noexcept { return world_; }
    explicit operator bool() const noexcept { return world_ != nullptr; }
    /// Gives the world up without destroying it: the caller calls nl_world_destroy.
    nl_world* release() noexcept { return std::exchange(world_, nullptr); }
    /// nl_world_destroy, if it holds a world (it must not race with any other call on it).
    void reset() noexcept {
        if (world_) nl_world_destroy(std::exchange(world_, nullptr));
    }

    /// nl_world_get_worker_count (-1 for no world; never throws).
    int32_t worker_count() const noexcept { return nl_world_get_worker_count(world_); }

    // --- Level geometry -------------------------------------------------------------------------

    /// nl_mesh_add(def).
    MeshId add_mesh(const nl_mesh_def& def) {
        nl_mesh_id id{};
        check(nl_mesh_add(world_, &def, &id));
        return id;
    }
    /// nl_mesh_add with def's vertices, vertex_count, indices and triangle_count set from these (all
    /// copied by the call); def's other fields (flags, transform, area, stride...) as given.
    MeshId add_mesh(const float* vertices, uint32_t vertex_count, const uint32_t* indices, uint32_t triangle_count,
                    nl_mesh_def def = nl_default_mesh_def()) {
        def.vertices = vertices;
        def.vertex_count = vertex_count;
        def.indices = indices;
        def.triangle_count = triangle_count;
        return add_mesh(def);
    }
    /// nl_mesh_add from vectors: x y z per vertex (or def.vertex_stride bytes apart), 3 indices per
    /// triangle. A vertex or index count that does not divide evenly is INVALID_ARGUMENT.
    MeshId add_mesh(const std::vector<float>& vertices, const std::vector<uint32_t>& indices,
                    nl_mesh_def def = nl_default_mesh_def()) {
        const std::size_t stride = def.vertex_stride != 0u ? def.vertex_stride : 3 * sizeof(float);
        const std::size_t bytes = vertices.size() * sizeof(float);
        if (bytes % stride != 0u || indices.size() % 3u != 0u)
            throw Error(Status(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT),
                        "navlink::World::add_mesh: " + std::to_string(vertices.size()) + " floats (stride " +
                            std::to_string(stride) + " bytes) and " + std::to_string(indices.size()) +
                            " indices do not make whole vertices and triangles");
        return add_mesh(vertices.data(), detail::count32(bytes / stride, "vertices"), indices.data(),
                        detail::count32(indices.size() / 3u, "indices"), def);
    }
    /// nl_mesh_add_obj_file(path, def): def's vertex and index fields must be empty.
    MeshId add_obj_file(const std::string& path, const nl_mesh_def& def = nl_default_mesh_def()) {
        nl_mesh_id id{};
        check(nl_mesh_add_obj_file(world_, path.c_str(), &def, &id));
        return id;
    }
    /// nl_mesh_add_obj_memory(data, def).
    MeshId add_obj_memory(std::string_view data, const nl_mesh_def& def = nl_default_mesh_def()) {
        nl_mesh_id id{};
        check(nl_mesh_add_obj_memory(world_, data.data(), data.size(), &def, &id));
        return id;
    }
    /// nl_mesh_remove.
    void remove_mesh(MeshId mesh) { check(nl_mesh_remove(world_, mesh)); }
    /// nl_mesh_set_transform (16 floats, column-major, copied).
    void set_mesh_transform(MeshId mesh, const float (&transform)[16]) {
        check(nl_mesh_set_transform(world_, mesh, transform));
    }
    /// nl_mesh_get_info.
    nl_mesh_info mesh_info(MeshId mesh) const {
        nl_mesh_info info = nl_mesh_info_init();
        check(nl_mesh_get_info(world_, mesh, &info));
        return info;
    }
    /// nl_world_get_meshes, every id.
    std::vector<MeshId> meshes() const {
        const std::vector<nl_mesh_id> ids = two_call<nl_mesh_id>(
            [this](nl_mesh_id* out, uint32_t capacity, uint32_t* count) {
                return nl_world_get_meshes(world_, out, capacity, count);
            });
        return std::vector<MeshId>(ids.begin(), ids.end());
    }
    /// nl_world_cast_rays: the closest hit of each ray.
    std::vector<nl_ray_hit> cast_rays(const std::vector<nl_ray>& rays) {
        std::vector<nl_ray_hit> hits(rays.size(), nl_ray_hit_init());
        if (!rays.empty()) check(nl_world_cast_rays(world_, rays.data(), detail::count32(rays.size(), "rays"), hits.data()));
        return hits;
    }

    // --- Navmeshes ------------------------------------------------------------------------------

    /// nl_navmesh_add: the host's own navmesh.
    NavmeshId add_navmesh(const nl_navmesh_def& def) {
        nl_navmesh_id id{};
        check(nl_navmesh_add(world_, &def, &id));
        return id;
    }
    /// nl_navmesh_build(def): builder "recast" and its defaults unless def says otherwise.
    NavmeshId build_navmesh(const nl_navmesh_build_def& def = nl_default_navmesh_build_def()) {
        nl_navmesh_id id{};
        check(nl_navmesh_build(world_, &def, &id));
        return id;
    }
    /// nl_navmesh_build with def.settings_json set to `settings_json` (a JSON object, e.g.
    /// R"({"cell_size": 0.2})"; an empty string is not one: PARSE_ERROR, as in C).
    NavmeshId build_navmesh(std::string_view settings_json, nl_navmesh_build_def def = nl_default_navmesh_build_def()) {
        def.settings_json = settings_json.data();
        def.settings_json_length = settings_json.size();
        return build_navmesh(def);
    }
    /// nl_navmesh_remove.
    void remove_navmesh(NavmeshId navmesh) { check(nl_navmesh_remove(world_, navmesh)); }
    /// nl_navmesh_get_info.
    nl_navmesh_info navmesh_info(NavmeshId navmesh) const {
        nl_navmesh_info info = nl_navmesh_info_init();
        check(nl_navmesh_get_info(world_, navmesh, &info));
        return info;
    }
    /// nl_world_get_navmeshes, every id.
    std::vector<NavmeshId> navmeshes() const {
        const std::vector<nl_navmesh_id> ids = two_call<nl_navmesh_id>(
            [this](nl_navmesh_id* out, uint32_t capacity, uint32_t* count) {
                return nl_world_get_navmeshes(world_, out, capacity, count);
            });
        return std::vector<NavmeshId>(ids.begin(), ids.end());
    }

    // --- Links ----------------------------------------------------------------------------------

    /// nl_navmesh_generate_links(settings, progress, user): replaces the navmesh's generated links;
    /// returns the generation's report.
    nl_link_generation_report generate_links(NavmeshId navmesh,
                                             const nl_link_settings& settings = nl_default_link_settings(),
                                             nl_progress_fn* progress = nullptr, void* user = nullptr) {
        nl_link_generation_report report = nl_link_generation_report_init();
        check(nl_navmesh_generate_links(world_, navmesh, &settings, progress, user, &report));
        return report;
    }
    /// nl_link_add: a manual (or cross) link.
    LinkId add_link(NavmeshId navmesh, const nl_link_def& def) {
        nl_link_id id{};
        check(nl_link_add(world_, navmesh, &def, &id));
        return id;
    }
    /// nl_link_remove.
    void remove_link(LinkId link) { check(nl_link_remove(world_, link)); }
    /// nl_link_get.
    nl_link link(LinkId id) const {
        nl_link out = nl_link_init();
        check(nl_link_get(world_, id, &out));
        return out;
    }
    /// nl_navmesh_get_links: the navmesh's links, in the order they were added.
    std::vector<nl_link> links(NavmeshId navmesh) const {
        return two_call([this, navmesh](nl_link* out, uint32_t capacity, uint32_t* count) {
            return nl_navmesh_get_links(world_, navmesh, out, capacity, count);
        }, nl_link_init());
    }

    // --- Paths ----------------------------------------------------------------------------------

    /// nl_path_find: plans now, on this thread. Succeeds whatever the search found (read
    /// path.result.outcome: COMPLETE, PARTIAL, NO_PATH, START_/GOAL_OFF_NAVMESH); throws on a failure.
    Path find_path(const nl_path_request_def& def) {
        Path path;
        path.points = two_call([this, &def, &path](nl_path_point* out, uint32_t capacity, uint32_t* count) {
            return nl_path_find(world_, &def, &path.result, out, capacity, count);
        }, nl_path_point_init());
        return path;
    }
    /// nl_path_explain: why the request's path falls short of its goal (reason NONE when it does not).
    nl_path_shortfall explain_path(const nl_path_request_def& def) {
        nl_path_shortfall shortfall = nl_path_shortfall_init();
        check(nl_path_explain(world_, &def, &shortfall));
        return shortfall;
    }

    // --- Agents ---------------------------------------------------------------------------------

    /// nl_agent_add (navlink::agent_def makes a def).
    AgentId add_agent(const nl_agent_def& def) {
        nl_agent_id id{};
        check(nl_agent_add(world_, &def, &id));
        return id;
    }
    /// nl_agent_remove.
    void remove_agent(AgentId agent) { check(nl_agent_remove(world_, agent)); }
    /// nl_agent_set_destination: planned in a coming step.
    void set_destination(AgentId agent, const float (&point)[3]) {
        check(nl_agent_set_destination(world_, agent, point));
    }
    /// nl_agent_stop.
    void stop_agent(AgentId agent) { check(nl_agent_stop(world_, agent)); }
    /// nl_world_step: moves every agent by dt seconds.
    void step(float dt) { check(nl_world_step(world_, dt)); }
    /// nl_agent_get_info.
    nl_agent_info agent_info(AgentId agent) const {
        nl_agent_info info = nl_agent_info_init();
        check(nl_agent_get_info(world_, agent, &info));
        return info;
    }
    /// nl_world_get_agents: every agent's state.
    std::vector<nl_agent_info> agents() const {
        return two_call([this](nl_agent_info* out, uint32_t capacity, uint32_t* count) {
            return nl_world_get_agents(world_, out, capacity, count);
        }, nl_agent_info_init());
    }
    /// nl_agent_get_corners: the path points the agent has yet to reach, the next first.
    std::vector<nl_path_point> agent_corners(AgentId agent) const {
        return two_call([this, agent](nl_path_point* out, uint32_t capacity, uint32_t* count) {
            return nl_agent_get_corners(world_, agent, out, capacity, count);
        }, nl_path_point_init());
    }
    /// nl_agent_get_trajectory: the link it is taking now (kind NL_TRAJECTORY_NONE on the ground).
    nl_agent_trajectory agent_trajectory(AgentId agent) const {
        nl_agent_trajectory trajectory = nl_agent_trajectory_init();
        check(nl_agent_get_trajectory(world_, agent, &trajectory));
        return trajectory;
    }
    /// nl_world_get_agent_events: the last step's events (read them after every step).
    std::vector<nl_agent_event> agent_events() const {
        return two_call([this](nl_agent_event* out, uint32_t capacity, uint32_t* count) {
            return nl_world_get_agent_events(world_, out, capacity, count);
        }, nl_agent_event_init());
    }

    // --- Plugins (a plugin stays loaded until the world is destroyed) ----------------------------

    /// nl_plugin_load.
    PluginId load_plugin(const std::string& path) {
        nl_plugin_id id{};
        check(nl_plugin_load(world_, path.c_str(), &id));
        return id;
    }
    /// nl_world_get_plugins, built-in ones first.
    std::vector<PluginId> plugins() const {
        const std::vector<nl_plugin_id> ids = two_call<nl_plugin_id>(
            [this](nl_plugin_id* out, uint32_t capacity, uint32_t* count) {
                return nl_world_get_plugins(world_, out, capacity, count);
            });
        return std::vector<PluginId>(ids.begin(), ids.end());
    }
    /// nl_plugin_get_description (its strings live as long as the world).
    nl_plugin_description plugin_description(PluginId plugin) const {
        nl_plugin_description description = nl_plugin_description_init();
        check(nl_plugin_get_description(world_, plugin, &description));
        return description;
    }

    // --- Validity (nl_*_is_valid: never throw; false for a stale, null or foreign id) -------------

    bool is_valid(MeshId mesh) const noexcept { return nl_mesh_is_valid(world_, mesh) != 0; }
    bool is_valid(NavmeshId navmesh) const noexcept { return nl_navmesh_is_valid(world_, navmesh) != 0; }
    bool is_valid(LinkId id) const noexcept { return nl_link_is_valid(world_, id) != 0; }
    bool is_valid(AgentId agent) const noexcept { return nl_agent_is_valid(world_, agent) != 0; }

private:
    nl_world* world_ = nullptr;
};

}  // namespace navlink

#endif  // NAVLINK_NAVLINK_HPP
