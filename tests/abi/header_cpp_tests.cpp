// The C++ layer, <navlink/navlink.hpp>, compiled as C++17 against the navlink target alone (the C ABI:
// no sdk/ or capi/src/ header is on its include path) and run: World's ownership, errors as
// exceptions with the library's status and message, ids, the two-call helpers, and the common flow on
// a level with known answers (a floor box with a platform on it 1.2 m high, which Recast's agent can
// only leave by its drop links and only climb by taking one back up as a jump).
#include <navlink/navlink.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace {

int g_failures = 0;

#define CHECK(cond)                                                                       \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            std::fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            ++g_failures;                                                                 \
        }                                                                                 \
    } while (0)

// Runs `body`, which must throw navlink::Error; returns it (a default Error if nothing was thrown).
template <typename Body>
navlink::Error thrown(Body&& body, int line) {
    try {
        body();
    } catch (const navlink::Error& e) {
        return e;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s:%d: threw something else than navlink::Error: %s\n", __FILE__, line, e.what());
        ++g_failures;
        return navlink::Error(navlink::Status(), "");
    }
    std::fprintf(stderr, "%s:%d: nothing was thrown\n", __FILE__, line);
    ++g_failures;
    return navlink::Error(navlink::Status(), "");
}
#define THROWN(...) thrown([&] { __VA_ARGS__; }, __LINE__)

bool contains(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

// The ids are the C structs: the same bytes, passed by value to nl_* functions, blittable.
static_assert(std::is_base_of<nl_mesh_id, navlink::MeshId>::value, "MeshId is an nl_mesh_id");
static_assert(sizeof(navlink::MeshId) == sizeof(nl_mesh_id) && sizeof(navlink::AgentId) == sizeof(nl_agent_id),
              "an id wrapper adds no bytes");
static_assert(std::is_standard_layout<navlink::LinkId>::value && std::is_trivially_copyable<navlink::LinkId>::value,
              "an id wrapper is blittable");
static_assert(!std::is_convertible<navlink::MeshId, bool>::value && std::is_constructible<bool, navlink::MeshId>::value,
              "ids test as bool explicitly only");
static_assert(!std::is_copy_constructible<navlink::World>::value &&
                  std::is_nothrow_move_constructible<navlink::World>::value &&
                  std::is_nothrow_move_assignable<navlink::World>::value,
              "World is move-only");
static_assert(std::is_base_of<std::runtime_error, navlink::Error>::value, "Error is a std::runtime_error");
static_assert(std::is_nothrow_copy_constructible<navlink::Error>::value, "copying an Error never throws");

// A box from (x0, y0, z0) to (x1, y1, z1): 8 corners and 12 triangles facing out.
navlink::MeshId add_box(navlink::World& world, float x0, float y0, float z0, float x1, float y1, float z1) {
    const std::vector<float> v = {x0, y0, z0, x1, y0, z0, x0, y1, z0, x1, y1, z0,
                                  x0, y0, z1, x1, y0, z1, x0, y1, z1, x1, y1, z1};
    const std::vector<uint32_t> box = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                                       2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
    return world.add_mesh(v, box);
}

// The level: a 20 x 20 m floor box (top at y = 0) and a 6 x 6 m platform on it, its top at y = 1.2 (over
// max_climb 0.9: no walking up), built with Recast's defaults and its links generated.
struct Level {
    navlink::World world;
    navlink::MeshId floor, platform;
    navlink::NavmeshId navmesh;
    nl_link_generation_report report{};

    Level() : world(small_world()) {
        floor = add_box(world, -10, -1, -10, 10, 0, 10);
        platform = add_box(world, 2, 0, -3, 8, 1.2f, 3);
        navmesh = world.build_navmesh(R"({"cell_size": 0.3})");
        report = world.generate_links(navmesh);
    }
    static nl_world_def small_world() {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 2;
        def.path_worker_count = 0;
        return def;
    }
};

const float k_on_floor[3] = {-6, 0, 0};
const float k_on_platform[3] = {5, 1.2f, 0};

nl_agent_capabilities walker() { return nl_default_agent_capabilities(); }
nl_agent_capabilities jumper() {
    nl_agent_capabilities c = nl_default_agent_capabilities();
    c.max_jump_distance = 2.0f;
    c.max_jump_height = 1.5f;
    c.max_drop_height = 2.0f;
    return c;
}

// --- Cases ---------------------------------------------------------------------------------------

void status_and_check() {
    const navlink::Status partial = navlink::check(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT);
    CHECK(partial.succeeded() && !partial.failed() && partial.partial());
    CHECK(partial.detail() == NL_STATUS_PARTIAL_RESULT && partial.has(NL_STATUS_PARTIAL_RESULT));
    CHECK(partial.to_string() == nl_status_string(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(navlink::Status() == navlink::Status(NL_STATUS_SUCCESS) && navlink::Status() != partial);
    CHECK(navlink::check(NL_STATUS_IN_PROGRESS).in_progress());

    const navlink::Status bad(NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE);
    CHECK(bad.failed() && !bad.partial() && bad.has(NL_STATUS_INVALID_HANDLE) && !bad.has(NL_STATUS_INVALID_ARGUMENT));
    CHECK(bad.to_string() == "failure: invalid handle");

    // check() throws with the calling thread's last message: that of the call that failed.
    const nl_status status = nl_world_create(nullptr, nullptr);
    const navlink::Error e = THROWN(navlink::check(status));
    CHECK(e.status().value() == status && e.status().has(NL_STATUS_INVALID_ARGUMENT));
    CHECK(contains(e.message(), "nl_world_create") && contains(e.what(), e.message().c_str()) &&
          contains(e.what(), "failure: invalid argument"));
}

void ids() {
    const navlink::MeshId null_id;
    CHECK(!null_id && null_id.index1 == 0u && null_id.revision == 0u);
    const nl_mesh_id raw = {3, 7};
    const navlink::MeshId id = raw;
    CHECK(static_cast<bool>(id) && id == raw && raw == id && id != null_id);
    const nl_mesh_id other = {3, 8};
    CHECK(id != other && navlink::MeshId(other) != id);
    CHECK(id.raw().index1 == 3u && id.raw().revision == 7u);
    CHECK(navlink::MeshId(nl_mesh_id{0, 1}));  // only the all-zero id is null
}

// A path request queued in a world with no path worker runs only when the world is destroyed: its
// callback then says CANCELLED. That is how these cases see a World destroy its nl_world.
struct Destroyed {
    int calls = 0;
    nl_path_outcome outcome = NL_PATH_PENDING;
};
void on_finished(void* user, nl_path_ticket, nl_path_outcome outcome) {
    Destroyed* d = static_cast<Destroyed*>(user);
    ++d->calls;
    d->outcome = outcome;
}
// A world with one 4 x 4 m quad navmesh and a request queued on it that tells `destroyed` when it ends.
navlink::World watched_world(Destroyed& destroyed) {
    navlink::World world(Level::small_world());
    static const float quad[] = {0, 0, 0, 0, 0, 4, 4, 0, 4, 4, 0, 0};
    static const uint32_t corners[] = {0, 1, 2, 3};
    static const uint8_t counts[] = {4};
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = quad;
    def.vertex_count = 4;
    def.indices = corners;
    def.polygon_vertex_counts = counts;
    def.polygon_count = 1;
    const navlink::NavmeshId navmesh = world.add_navmesh(def);
    nl_path_request_def request = navlink::path_request(navmesh, {1, 0, 1}, {3, 0, 3});
    request.callback = on_finished;
    request.user = &destroyed;
    nl_path_ticket ticket{};
    navlink::check(nl_path_request(world.get(), &request, &ticket));
    return world;  // moved out: the world lives on in the caller's World
}

void world_raii() {
    Destroyed first, second;
    {
        navlink::World a = watched_world(first);
        CHECK(a && a.get() != nullptr && first.calls == 0);
        nl_world* const raw = a.get();

        navlink::World b(std::move(a));  // move: b owns it, a holds nothing
        CHECK(!a && a.get() == nullptr && b.get() == raw && first.calls == 0);
        CHECK(b.navmeshes().size() == 1u);

        // A moved-from World's methods fail as the C functions do on a null world.
        const navlink::Error e = THROWN(a.meshes());
        CHECK(e.status().has(NL_STATUS_INVALID_ARGUMENT) && contains(e.message(), "nl_world_get_meshes"));

        navlink::World c = watched_world(second);
        b = std::move(c);  // move assignment destroys b's world first
        CHECK(first.calls == 1 && first.outcome == NL_PATH_CANCELLED);
        CHECK(second.calls == 0 && !c && b);

        navlink::World& same = b;
        b = std::move(same);  // self-move leaves it as it was
        CHECK(b && second.calls == 0);
    }
    CHECK(second.calls == 1 && second.outcome == NL_PATH_CANCELLED);  // the destructor

    // release() gives the pointer up; World(nl_world*) takes one over; reset() destroys now.
    Destroyed third;
    navlink::World d = watched_world(third);
    nl_world* const raw = d.release();
    CHECK(!d && third.calls == 0);
    navlink::World e(raw);
    CHECK(e.get() == raw && e.worker_count() == 2);
    e.reset();
    CHECK(!e && third.calls == 1);
    e.reset();  // nothing to destroy
}

void errors_as_exceptions() {
    navlink::World world;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    add_box(world, -1, -1, -1, 1, 0, 1);

    // A NaN vertex: nl_mesh_add's INVALID_ARGUMENT, with its message naming the vertex.
    const navlink::Error e = THROWN(world.add_mesh({0, 0, 0, 1, 0, 0, 0, nan, 1}, {0, 1, 2}));
    CHECK(e.status().failed() && e.status().detail() == NL_STATUS_INVALID_ARGUMENT);
    CHECK(e.message() == "nl_mesh_add: def->vertices[2].y is not finite (nan)");
    CHECK(std::string(e.what()) == e.message() + " (failure: invalid argument)");
    CHECK(world.meshes().size() == 1u);  // a failed call changes nothing

    // Caught as a std::runtime_error too.
    bool caught = false;
    try {
        world.add_obj_memory("v 0 0 0\nf 1 2 3\n");
    } catch (const std::runtime_error& r) {
        caught = contains(r.what(), "nl_mesh_add_obj_memory") && contains(r.what(), "parse error");
    }
    CHECK(caught);

    // The vector overload's own check, before any C call.
    const navlink::Error odd = THROWN(world.add_mesh({0, 0, 0, 1, 0}, {0, 1, 2}));
    CHECK(odd.status().has(NL_STATUS_INVALID_ARGUMENT) && contains(odd.message(), "navlink::World::add_mesh"));

    // Stale ids: INVALID_HANDLE.
    const navlink::MeshId tile = world.add_mesh({0, 2, 0, 0, 2, 1, 1, 2, 0}, {0, 1, 2});
    CHECK(world.is_valid(tile));
    world.remove_mesh(tile);
    CHECK(!world.is_valid(tile));
    CHECK(THROWN(world.mesh_info(tile)).status().has(NL_STATUS_INVALID_HANDLE));
    CHECK(THROWN(world.remove_mesh(tile)).status().has(NL_STATUS_INVALID_HANDLE));

    // An empty settings JSON is refused as nl_navmesh_build refuses it; a plugin that is not there.
    CHECK(THROWN(world.build_navmesh(std::string_view(""))).status().has(NL_STATUS_PARSE_ERROR));
    CHECK(THROWN(world.load_plugin("/nonexistent/libnothing.so")).status().has(NL_STATUS_NOT_FOUND));
}

void two_call_helper() {
    // The generic helper, with a list that grows between the calls (3, then 5 when the buffer comes).
    int calls = 0;
    const std::vector<nl_link> grown = navlink::two_call(
        [&calls](nl_link* out, uint32_t capacity, uint32_t* count) -> nl_status {
            ++calls;
            const uint32_t have = calls == 1 ? 3u : 5u;
            *count = have;
            if (!out) return NL_STATUS_SUCCESS;
            if (out[0].size != sizeof(nl_link)) return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
            if (capacity < have) return NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL;
            for (uint32_t i = 0; i < have; ++i) out[i].id.index1 = i + 1;
            return NL_STATUS_SUCCESS;
        },
        nl_link_init());
    CHECK(calls == 3 && grown.size() == 5u && grown[4].id.index1 == 5u && grown[4].size == sizeof(nl_link));

    // Empty: one call. Another failure: thrown.
    calls = 0;
    const auto none = navlink::two_call<nl_mesh_id>([&calls](nl_mesh_id*, uint32_t, uint32_t* count) {
        ++calls;
        *count = 0;
        return NL_STATUS_SUCCESS;
    });
    CHECK(none.empty() && calls == 1);
    const navlink::Error e = THROWN(navlink::two_call<nl_mesh_id>([](nl_mesh_id* out, uint32_t, uint32_t* count) {
        *count = 2;
        return out ? NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY : NL_STATUS_SUCCESS;
    }));
    CHECK(e.status().has(NL_STATUS_OUT_OF_MEMORY));

    // On the C functions: the level's meshes, navmeshes, links, plugins.
    Level level;
    const std::vector<navlink::MeshId> meshes = level.world.meshes();
    CHECK(meshes.size() == 2u && meshes[0] == level.floor && meshes[1] == level.platform);
    const std::vector<navlink::NavmeshId> navmeshes = level.world.navmeshes();
    CHECK(navmeshes.size() == 1u && navmeshes[0] == level.navmesh);
    const auto raw_navmeshes =
        navlink::two_call<nl_navmesh_id>([&level](nl_navmesh_id* out, uint32_t capacity, uint32_t* count) {
            return nl_world_get_navmeshes(level.world.get(), out, capacity, count);
        });
    CHECK(raw_navmeshes.size() == 1u && raw_navmeshes[0] == level.navmesh);

    const std::vector<nl_link> links = level.world.links(level.navmesh);
    CHECK(!links.empty() &&
          links.size() == level.report.jump_links + level.report.drop_links + level.report.plugin_links);
    for (const nl_link& l : links) {
        CHECK(l.size == sizeof(nl_link) && l.kind == NL_LINK_DROP && l.generated == 1 && l.bidirectional == 1);
        CHECK(std::fabs(l.requirements.drop - 1.2f) < 0.05f && level.world.is_valid(navlink::LinkId(l.id)));
        CHECK(level.world.link(l.id).navmesh == level.navmesh);
    }

    const std::vector<navlink::PluginId> plugins = level.world.plugins();
    CHECK(!plugins.empty());
    bool recast = false;
    for (const navlink::PluginId plugin : plugins)
        recast |= std::strcmp(level.world.plugin_description(plugin).name, "recast") == 0;
    CHECK(recast);

    // A ray onto the platform.
    const std::vector<nl_ray_hit> hits = level.world.cast_rays({nl_ray{{5, 5, 0}, {0, -1, 0}, 10}});
    CHECK(hits.size() == 1u && hits[0].hit == 1 && hits[0].mesh == level.platform &&
          std::fabs(hits[0].point[1] - 1.2f) < 1e-5f);
}

void paths() {
    Level level;
    navlink::World& world = level.world;

    // A jumper gets onto the platform: a drop link taken back up, as a jump.
    const navlink::Path path =
        world.find_path(navlink::path_request(level.navmesh, k_on_floor, k_on_platform, jumper()));
    CHECK(path.complete() && !path.partial() && path.result.size == sizeof(nl_path_result));
    CHECK(path.points.size() == path.result.point_count && path.points.size() >= 3u && path.result.links_used == 1u);
    const std::vector<nl_link> links = world.links(level.navmesh);
    int jumps = 0;
    for (const nl_path_point& p : path.points) {
        CHECK(p.size == sizeof(nl_path_point));
        if (p.segment == NL_SEGMENT_WALK) {
            CHECK(!navlink::LinkId(p.link));
            continue;
        }
        ++jumps;
        CHECK(p.segment == NL_LINK_JUMP && p.reversed == 1);
        bool known = false;
        for (const nl_link& l : links) known |= l.id == navlink::LinkId(p.link);
        CHECK(known);
    }
    CHECK(jumps == 1);
    const nl_path_point& last = path.points.back();
    CHECK(std::fabs(last.position[0] - 5.0f) < 0.01f && std::fabs(last.position[2]) < 0.01f && last.position[1] > 1.1f);

    // Nothing to explain about a path that gets there.
    const nl_path_shortfall none =
        world.explain_path(navlink::path_request(level.navmesh, k_on_floor, k_on_platform, jumper()));
    CHECK(none.reason == NL_PATH_SHORTFALL_NONE && none.text[0] == '\0');

    // A walker's path stops at the platform's foot: partial, and explained.
    const nl_path_request_def request = navlink::path_request(level.navmesh, k_on_floor, k_on_platform, walker());
    const navlink::Path short_path = world.find_path(request);
    CHECK(short_path.partial() && short_path.points.size() == short_path.result.point_count &&
          !short_path.points.empty());
    CHECK(short_path.points.back().position[1] < 0.5f);
    const nl_path_shortfall why = world.explain_path(request);
    CHECK(why.size == sizeof(nl_path_shortfall) && why.reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY);
    CHECK(why.limit == NL_LINK_LIMIT_JUMP_DISTANCE && why.has == 0.0f && why.needed > 1.0f && why.reversed == 1u);
    CHECK(world.is_valid(navlink::LinkId(why.link)) && contains(why.text, "max_jump_distance"));

    // No path at all when partial paths are not accepted: still no exception (the search ran).
    nl_path_request_def strict = request;
    strict.accept_partial = 0;
    const navlink::Path no_path = world.find_path(strict);
    CHECK(no_path.result.outcome == NL_PATH_NO_PATH && no_path.points.empty());

    // A bad request is an exception.
    nl_path_request_def bad = request;
    bad.goal[1] = std::numeric_limits<float>::infinity();
    CHECK(THROWN(world.find_path(bad)).status().has(NL_STATUS_INVALID_ARGUMENT));
    CHECK(THROWN(world.explain_path(bad)).status().has(NL_STATUS_INVALID_ARGUMENT));
}

void agents() {
    Level level;
    navlink::World& world = level.world;
    const navlink::AgentId agent = world.add_agent(navlink::agent_def(level.navmesh, k_on_floor, jumper()));
    CHECK(agent && world.is_valid(agent) && world.agent_info(agent).state == NL_AGENT_IDLE);
    world.set_destination(agent, k_on_platform);

    bool path_ready = false, took_off = false, landed = false, arrived = false, saw_corners = false, saw_arc = false;
    for (int step = 0; step < 1200 && !arrived; ++step) {
        world.step(1.0f / 60.0f);
        for (const nl_agent_event& e : world.agent_events()) {
            CHECK(e.size == sizeof(nl_agent_event) && e.agent == agent);
            path_ready |= e.kind == NL_AGENT_EVENT_PATH_READY;
            took_off |= e.kind == NL_AGENT_EVENT_LINK_STARTED;
            landed |= e.kind == NL_AGENT_EVENT_LINK_FINISHED && took_off;
            arrived |= e.kind == NL_AGENT_EVENT_ARRIVED && landed;
            CHECK(e.kind != NL_AGENT_EVENT_FAILED);
        }
        // As many corners as nl_agent_get_corners counts, each with its size written back.
        const std::vector<nl_path_point> corners = world.agent_corners(agent);
        uint32_t count = 0;
        navlink::check(nl_agent_get_corners(world.get(), agent, nullptr, 0, &count));
        CHECK(corners.size() == count);
        for (const nl_path_point& p : corners) saw_corners |= p.size == sizeof(nl_path_point);
        saw_arc |= world.agent_trajectory(agent).kind == NL_TRAJECTORY_ARC;
    }
    CHECK(path_ready && took_off && landed && arrived && saw_corners && saw_arc);

    const nl_agent_info info = world.agent_info(agent);
    CHECK(info.state == NL_AGENT_ARRIVED && std::fabs(info.position[1] - 1.2f) < 0.3f);
    CHECK(std::hypot(info.position[0] - 5.0f, info.position[2]) < 0.5f);
    const std::vector<nl_agent_info> all = world.agents();
    CHECK(all.size() == 1u && all[0].id == agent && all[0].size == sizeof(nl_agent_info));

    world.remove_agent(agent);
    CHECK(!world.is_valid(agent) && world.agents().empty());
    CHECK(THROWN(world.set_destination(agent, k_on_floor)).status().has(NL_STATUS_INVALID_HANDLE));
    CHECK(THROWN(world.step(-1.0f)).status().has(NL_STATUS_INVALID_ARGUMENT));
}

struct Case {
    const char* name;
    void (*run)();
};

}  // namespace

int main() {
    const Case cases[] = {{"status_and_check", status_and_check},
                          {"ids", ids},
                          {"world_raii", world_raii},
                          {"errors_as_exceptions", errors_as_exceptions},
                          {"two_call", two_call_helper},
                          {"paths", paths},
                          {"agents", agents}};
    for (const Case& c : cases) {
        const int before = g_failures;
        try {
            c.run();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: unexpected exception: %s\n", c.name, e.what());
            ++g_failures;
        }
        std::printf("%s %s\n", g_failures == before ? "ok    " : "FAILED", c.name);
    }
    return g_failures == 0 ? 0 : 1;
}
