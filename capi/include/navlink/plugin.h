/*
 * NavLink plugin ABI: what a plugin library exports and what the host offers it.
 *
 * A plugin exports one function, `nl_plugin_entry` (NL_PLUGIN_ENTRY_SYMBOL), of type
 * nl_plugin_entry_fn. The host calls it once with the highest ABI version it speaks and a table of host
 * functions; the plugin fills an nl_plugin_info with the version it will speak (at most the host's),
 * its name and what it provides, or refuses with NL_STATUS_VERSION_MISMATCH. Versions are negotiated
 * downward, as Vulkan layers do: a newer host still loads an older plugin.
 *
 * Plugins compiled into the host program are registered with nl_plugin_register instead of loaded.
 * All plugin functions may be called from any thread and concurrently; a plugin guards its own state.
 */
#ifndef NAVLINK_PLUGIN_H
#define NAVLINK_PLUGIN_H

#include "navlink/navlink.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The plugin ABI version this header describes. */
#define NL_PLUGIN_ABI_VERSION 1u

/** The name of the entry function a plugin library exports. */
#define NL_PLUGIN_ENTRY_SYMBOL "nl_plugin_entry"

/** One task of nl_plugin_host.run_tasks: the work numbered `index`, with the user pointer given. */
typedef void nl_plugin_task_fn(void* user, uint32_t index);

/** Functions the host offers a plugin. `context` is passed back as the first argument of each. Valid
 *  for as long as the plugin is loaded. */
typedef struct nl_plugin_host {
    uint32_t size;        /**< sizeof(nl_plugin_host) of the host. */
    uint32_t abi_version; /**< The host's highest ABI version. */
    void* context;

    /** Logs through the world's log callback. */
    void (*log)(void* context, nl_log_level level, const char* message);

    /** Gives the reason of the failure the plugin is about to return, naming the bad setting or input
     *  (e.g. "settings_json: cell_size must be > 0"); the host makes it the failing call's last error
     *  message. The host copies `message`. Call it from the thread that called into the plugin. */
    void (*set_error)(void* context, const char* message);

    /** Copies the world-space triangles of every registered mesh (under current transforms); called
     *  from a navmesh builder's build (on the thread that called it), the triangles that build is for
     *  instead: every static mesh in world space, or with def->carrier, that movable mesh alone in
     *  its own space. Vertex
     *  positions into `vertices` (room for `vertex_capacity` vertices, 3 floats each) and 3 indices per
     *  triangle into `indices` (room for `triangle_capacity` triangles). The counts are always written;
     *  BUFFER_TOO_SMALL (nothing copied) when either buffer is short. The count-only call (capacities
     *  0, buffers may be NULL) succeeds. Within one build every call sees the level as it was at the
     *  build's first call (the navmesh records the hash of that level); outside a build the level may
     *  change between two calls: retry on BUFFER_TOO_SMALL. */
    nl_status (*get_level_triangles)(void* context, float* vertices, uint32_t vertex_capacity,
                                     uint32_t* out_vertex_count, uint32_t* indices, uint32_t triangle_capacity,
                                     uint32_t* out_triangle_count);

    /* The world's queries, for link-kind plugins; each behaves as the nl_* function of the same name
       in navlink.h, on the world the plugin is loaded in (set the `size` of output structs, of the
       first element of an output array: nl_navmesh_info_init, nl_ray_hit_init). A failed query
       returns its status and does not touch the host thread's last status. */
    nl_status (*navmesh_get_boundary_edges)(void* context, nl_navmesh_id navmesh, nl_boundary_edge* out_edges,
                                            uint32_t capacity, uint32_t* out_count);
    nl_status (*navmesh_get_info)(void* context, nl_navmesh_id navmesh, nl_navmesh_info* out_info);
    nl_status (*navmesh_find_nearest)(void* context, nl_navmesh_id navmesh, const float* points, uint32_t count,
                                      const float* half_extents, nl_nav_point* out);
    nl_status (*cast_rays)(void* context, const nl_ray* rays, uint32_t count, nl_ray_hit* out_hits);
    nl_status (*segments_blocked)(void* context, const nl_segment* segments, uint32_t count, uint8_t* out_blocked);

    /** For a navmesh builder: records the settings this build used, complete (its defaults filled
     *  in), as a JSON object of `length` bytes (UTF-8; copied). The world keeps it with the navmesh
     *  as what it was built with: nl_navmesh_save writes it, nl_navmesh_file_describe shows it as
     *  "builder_settings". Call it from build, on the thread that called build, before returning;
     *  the last call wins. A build whose record is not a JSON object fails with INTERNAL_ERROR
     *  naming the builder. A builder that records nothing is recorded with the settings JSON it was
     *  given (def->settings_json), or none: a settings struct alone is then not recorded.
     *  Returns SUCCESS, or a failure with INVALID_ARGUMENT (settings_json NULL; called outside a
     *  build of this plugin on this thread). Present when `size` covers it (added in 0.3). */
    nl_status (*record_build_settings)(void* context, const char* settings_json, size_t length);

    /** For a navmesh builder: what the build is for, as get_level_triangles, with each triangle's
     *  area in `areas` (room for `triangle_capacity`; the mesh's nl_mesh_def.area, or
     *  NL_BUILD_AREA_OBSTACLE for a triangle of an NL_MESH_OBSTACLE mesh, which blocks and is never
     *  walked on). Meshes flagged NL_MESH_NOT_IN_NAVMESH are left out (get_level_triangles leaves
     *  them out too, and shows obstacles as any triangle). The counts are always written;
     *  BUFFER_TOO_SMALL (nothing copied) when a buffer is short; the count-only call (capacities 0)
     *  succeeds. Outside a build, every mesh of the world with area 0. Present when `size` covers
     *  it (added in 0.3). */
    nl_status (*get_build_triangles)(void* context, float* vertices, uint32_t vertex_capacity,
                                     uint32_t* out_vertex_count, uint32_t* indices, uint8_t* areas,
                                     uint32_t triangle_capacity, uint32_t* out_triangle_count);

    /** For a navmesh builder: reports the build's progress, `fraction` of it done (0..1; the host
     *  keeps what the caller sees from going back) in the stage `stage` (NUL-terminated, borrowed
     *  for the call; NULL: "building"). Returns SUCCESS, or a failure with CANCELLED when the
     *  host's caller asked to stop: the builder then returns that status at once (the host adds
     *  nothing whatever it returns), or INVALID_ARGUMENT outside a build of this plugin on this
     *  thread. Call it often enough that a cancel is prompt (the Recast builder: between Recast's
     *  steps and every 64k triangles rasterised). Present when `size` covers it (added in 0.3). */
    nl_status (*report_build_progress)(void* context, float fraction, const char* stage);

    /** For a navmesh builder: calls task(user, i) once for every i in 0..count-1 on the world's task
     *  system (the host's own scheduler when it gave one), several at once on as many threads as it
     *  has, and returns when all have returned. A task must not call this table's functions, throw,
     *  or wait for another task; it reports its own failure through `user`. Call it from build, on
     *  the thread that called build. Returns SUCCESS, or a failure with INVALID_ARGUMENT (task NULL;
     *  called outside a build of this plugin on this thread). Present when `size` covers it (added
     *  in 0.3); without it, run the tasks one after another. */
    nl_status (*run_tasks)(void* context, uint32_t count, nl_plugin_task_fn* task, void* user);

    /** For a navmesh builder building some tiles: what get_build_triangles gives, only the triangles
     *  whose bounds seen from above meet the columns columns[0] <= x <= columns[2], columns[1] <= z
     *  <= columns[3] (every height, in the build's space), in the same order and with the same
     *  areas, with only the vertices they use; the host finds them in its spatial index rather than
     *  copying the level, so a tile of a large world reads what lies around it. `out_bounds` (6
     *  floats: min x, y, z, then max x, y, z; may be NULL) receives the bounds of every vertex
     *  get_build_triangles gives, so that the tiles' heights can be placed as a build of the whole
     *  level places them (all zero for an empty level). `columns`: 4 doubles, borrowed for the call.
     *  Two calls as get_build_triangles (the counts and the bounds written by both); within one build,
     *  calls with the same columns see the same triangles. None meets them: counts 0 and SUCCESS.
     *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (nothing copied) or INVALID_ARGUMENT
     *  (columns NULL, not finite, or min > max; called outside a navmesh build of this plugin on this
     *  thread). Present when `size` covers it (added in 0.3); without it, read get_build_triangles. */
    nl_status (*get_build_triangles_in_columns)(void* context, const double* columns, float* vertices,
                                                uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                                uint32_t* indices, uint8_t* areas, uint32_t triangle_capacity,
                                                uint32_t* out_triangle_count, float* out_bounds);
} nl_plugin_host;

/** The area get_build_triangles gives an obstacle's triangles. */
#define NL_BUILD_AREA_OBSTACLE 255u

/** Receives a built navmesh; the host copies it before returning. */
typedef nl_status nl_navmesh_sink_fn(void* sink_context, const nl_navmesh_def* navmesh);

/** What a navmesh-builder plugin provides. */
typedef struct nl_navmesh_builder {
    /** Builds a navmesh for def->agent from the host's level triangles, with the builder's settings
     *  (def->settings and/or def->settings_json), and hands it to `sink` exactly once on success; or,
     *  a tiled navmesh, each tile that has polygons once (tile_width > 0, one grid, each tile once),
     *  on the thread that called build.
     *  Returns what the sink returned, or its own failure (NOT_FOUND: no walkable surface;
     *  INVALID_ARGUMENT / PARSE_ERROR: bad settings, the field named through host->set_error). */
    nl_status (*build)(void* plugin_state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                       nl_navmesh_sink_fn* sink, void* sink_context);
} nl_navmesh_builder;

/** Receives one generated link; the host validates and copies it before returning. */
typedef nl_status nl_link_sink_fn(void* sink_context, const nl_link_def* link);

/** What a link-kind plugin provides: links of a kind of its own, generated with the built-in ones by
 *  nl_navmesh_generate_links (and again in full by nl_navmesh_update_links_in_box). */
typedef struct nl_link_kind_provider {
    nl_link_kind kind;      /**< >= NL_LINK_FIRST_PLUGIN_KIND; unique in the world. */
    const char* kind_name;  /**< e.g. "climb". Static storage. */
    /** Proposes links of this kind for `navmesh`, each through `sink` (whose def's kind must be this
     *  kind). `settings_json` is the object under the kind's name in the generation's plugin settings
     *  (NULL when there is none). Returns SUCCESS, or a failure whose reason goes to host->set_error. */
    nl_status (*generate)(void* plugin_state, const nl_plugin_host* host, nl_navmesh_id navmesh,
                          const char* settings_json, size_t settings_json_length, nl_link_sink_fn* sink,
                          void* sink_context);
} nl_link_kind_provider;

/** What a plugin tells the host about itself. The host zero-fills it and sets `size` first. */
typedef struct nl_plugin_info {
    uint32_t size;                 /**< Set by the host to sizeof(nl_plugin_info). */
    uint32_t abi_version;          /**< Set by the plugin: the version it will speak, <= the host's. */
    const char* name;              /**< Unique within a world, e.g. "recast". Static storage. */
    const char* version;           /**< The plugin's own version. Static storage. */
    const char* description;       /**< One line. Static storage. */
    uint32_t kinds;                /**< NL_PLUGIN_* bits: which of the tables below are filled. */
    void* state;                   /**< The plugin's own state, passed to its functions. */
    void (*destroy)(void* state);  /**< Called once when the world is destroyed; may be NULL. */
    nl_navmesh_builder navmesh_builder;
    nl_link_kind_provider link_kind;  /**< When kinds has NL_PLUGIN_LINK_KIND. */
} nl_plugin_info;

/** The entry function a plugin exports. Returns SUCCESS after filling `out_info`, or
 *  NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH when it speaks no version <= host_abi_version. */
typedef nl_status nl_plugin_entry_fn(uint32_t host_abi_version, const nl_plugin_host* host,
                                     nl_plugin_info* out_info);

/** Registers a plugin compiled into the host program, through its entry function. Errors as
 *  nl_plugin_load, without the file ones. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] entry  The plugin's entry function.
 *  @param[out] out_id  Receives the plugin's id. */
NL_API nl_status nl_plugin_register(nl_world* world, nl_plugin_entry_fn* entry, nl_plugin_id* out_id);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_PLUGIN_H */
