// Compile check: <navlink/navlink.h>, <navlink/recast.h> and <navlink/plugin.h> must build as C++
// (-Wall -Wextra -pedantic -Werror), with every declaration inside extern "C" (the link fails on a
// mangled name) and every struct trivially copyable and standard-layout (blittable for bindings).
#include <navlink/navlink.h>
#include <navlink/plugin.h>
#include <navlink/recast.h>

#include <cstdio>
#include <type_traits>

namespace {

template <typename T>
constexpr bool blittable() {
    return std::is_trivially_copyable<T>::value && std::is_standard_layout<T>::value;
}

static_assert(blittable<nl_version>(), "nl_version");
static_assert(blittable<nl_world_def>(), "nl_world_def");
static_assert(blittable<nl_mesh_id>(), "nl_mesh_id");
static_assert(blittable<nl_mesh_def>(), "nl_mesh_def");
static_assert(blittable<nl_mesh_info>(), "nl_mesh_info");
static_assert(blittable<nl_ray>(), "nl_ray");
static_assert(blittable<nl_ray_hit>(), "nl_ray_hit");
static_assert(blittable<nl_segment>(), "nl_segment");
static_assert(blittable<nl_navmesh_id>(), "nl_navmesh_id");
static_assert(blittable<nl_agent_type>(), "nl_agent_type");
static_assert(blittable<nl_navmesh_def>(), "nl_navmesh_def");
static_assert(blittable<nl_navmesh_info>(), "nl_navmesh_info");
static_assert(blittable<nl_nav_polygon>(), "nl_nav_polygon");
static_assert(blittable<nl_boundary_edge>(), "nl_boundary_edge");
static_assert(blittable<nl_nav_point>(), "nl_nav_point");
static_assert(blittable<nl_query_filter>(), "nl_query_filter");
static_assert(blittable<nl_navmesh_raycast_hit>(), "nl_navmesh_raycast_hit");
static_assert(blittable<nl_navmesh_ray>(), "nl_navmesh_ray");
static_assert(blittable<nl_random_points_def>(), "nl_random_points_def");
static_assert(blittable<nl_navmesh_build_def>(), "nl_navmesh_build_def");
static_assert(blittable<nl_plugin_id>(), "nl_plugin_id");
static_assert(blittable<nl_plugin_description>(), "nl_plugin_description");
static_assert(blittable<nl_recast_settings>(), "nl_recast_settings");
static_assert(blittable<nl_plugin_host>(), "nl_plugin_host");
static_assert(blittable<nl_navmesh_builder>(), "nl_navmesh_builder");
static_assert(blittable<nl_plugin_info>(), "nl_plugin_info");
static_assert(blittable<nl_link_id>(), "nl_link_id");
static_assert(blittable<nl_link_requirements>(), "nl_link_requirements");
static_assert(blittable<nl_link>(), "nl_link");
static_assert(blittable<nl_link_def>(), "nl_link_def");
static_assert(blittable<nl_link_settings>(), "nl_link_settings");
static_assert(blittable<nl_link_generation_report>(), "nl_link_generation_report");
static_assert(sizeof(nl_link) == 136 && sizeof(nl_link_requirements) == 32 && sizeof(nl_link_id) == 8,
              "fixed link structs have the same size in C++ as in C");
static_assert(std::is_same<nl_link_kind, uint32_t>::value, "nl_link_kind is uint32_t");
static_assert(sizeof(nl_nav_polygon) == 164 && sizeof(nl_boundary_edge) == 56 && sizeof(nl_nav_point) == 24 &&
                  sizeof(nl_agent_type) == 16,
              "fixed structs have the same size in C++ as in C");
static_assert(std::is_same<nl_status, uint32_t>::value, "nl_status is uint32_t");

// Functions the plugin side of the ABI is written as, in C++.
nl_status plugin_entry(uint32_t, const nl_plugin_host*, nl_plugin_info*) {
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}
nl_status navmesh_sink(void*, const nl_navmesh_def*) { return NL_STATUS_SUCCESS; }

// True if every function pointer is set (taking each address makes the linker resolve it).
bool all_set() { return true; }
template <typename F, typename... Rest>
bool all_set(F* f, Rest*... rest) {
    return f != nullptr && all_set(rest...);
}

void log_sink(void*, nl_log_level, nl_status, const char*) {}
int32_t generation_progress(void*, float, const char*) { return 1; }

}  // namespace

int main() {
    nl_log_fn* log = log_sink;
    (void)log;
    nl_plugin_entry_fn* entry = plugin_entry;
    nl_navmesh_sink_fn* sink = navmesh_sink;
    (void)sink;
    // extern "C" linkage of the navmesh and plugin functions: a mangled declaration fails the link.
    if (!all_set(&nl_default_agent_type, &nl_default_navmesh_def, &nl_navmesh_add, &nl_navmesh_remove,
                 &nl_navmesh_is_valid, &nl_navmesh_get_info, &nl_navmesh_get_vertices, &nl_navmesh_get_polygon,
                 &nl_navmesh_get_boundary_edges, &nl_navmesh_find_nearest, &nl_world_get_navmeshes,
                 &nl_default_navmesh_build_def, &nl_navmesh_build, &nl_default_recast_settings, &nl_plugin_load,
                 &nl_plugin_get_description, &nl_world_get_plugins, &nl_plugin_register))
        return 1;
    // ... and of the link functions.
    if (!all_set(&nl_default_link_def, &nl_link_add, &nl_link_update, &nl_link_remove, &nl_link_is_valid, &nl_link_get,
                 &nl_navmesh_get_links, &nl_navmesh_remove_generated_links, &nl_default_link_settings,
                 &nl_link_settings_from_json, &nl_navmesh_generate_links, &nl_navmesh_update_links_in_box,
                 &nl_navmesh_save_links_json, &nl_navmesh_load_links_json))
        return 1;
    // ... and of the baked navmesh files.
    if (!all_set(&nl_navmesh_save, &nl_navmesh_save_file, &nl_default_navmesh_load_def, &nl_navmesh_load,
                 &nl_navmesh_load_file, &nl_navmesh_file_describe))
        return 1;
    // ... and of the path functions.
    if (!all_set(&nl_default_agent_capabilities, &nl_default_path_request_def, &nl_path_find, &nl_path_request,
                 &nl_path_poll, &nl_path_wait, &nl_path_get_result, &nl_path_cancel, &nl_path_release,
                 &nl_default_path_budget, &nl_path_process, &nl_path_take_finished, &nl_path_get_queue_stats))
        return 1;
    // ... and of the agent functions.
    if (!all_set(&nl_default_agent_def, &nl_agent_add, &nl_agent_remove, &nl_agent_is_valid, &nl_agent_set_destination,
                 &nl_agent_stop, &nl_agent_teleport, &nl_agent_set_capabilities, &nl_agent_set_speed, &nl_world_step,
                 &nl_agent_get_info, &nl_world_get_agents, &nl_agent_get_corners, &nl_agent_get_trajectory,
                 &nl_world_get_agent_events))
        return 1;
    // The output initialisers compile in C++11 too and set the size.
    if (nl_link_init().size != sizeof(nl_link) || nl_path_point_init().size != sizeof(nl_path_point) ||
        nl_ray_hit_init().size != sizeof(nl_ray_hit) || nl_path_finished_init().size != sizeof(nl_path_finished))
        return 1;
    nl_progress_fn* progress = generation_progress;
    if (progress(nullptr, 0.5f, "jumps") != 1) return 1;
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    nl_world* world = nullptr;
    nl_plugin_info info{};
    info.size = sizeof info;
    if (entry(NL_PLUGIN_ABI_VERSION, nullptr, &info) != (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH)) return 1;
    if (NL_FAILED(nl_world_create(&def, &world))) {
        std::fprintf(stderr, "nl_world_create: %s\n", nl_get_last_error_message());
        return 1;
    }
    const nl_version v = nl_get_version();
    const bool ok = v.major == NL_VERSION_MAJOR && v.minor == NL_VERSION_MINOR && v.patch == NL_VERSION_PATCH &&
                    nl_world_get_worker_count(world) == 1;
    nl_world_destroy(world);
    return ok ? 0 : 1;
}
