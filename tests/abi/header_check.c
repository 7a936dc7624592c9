/* Compile check: <navlink/navlink.h>, <navlink/recast.h> and <navlink/plugin.h> must build as strict C11
 * (-std=c11 -Wall -Wextra -pedantic -Werror) and every function they declare must be exported by
 * libnavlink.so (this program takes the address of each one, so a declared but missing symbol fails the
 * link). Running it checks the version agreement. */
#include <navlink/navlink.h>
#include <navlink/plugin.h>
#include <navlink/recast.h>

#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* The layouts bindings (C#, Rust, Python) mirror field by field. A change here is an ABI break. */
_Static_assert(offsetof(nl_world_def, size) == 0, "nl_world_def starts with size");
_Static_assert(offsetof(nl_mesh_def, size) == 0, "nl_mesh_def starts with size");
_Static_assert(offsetof(nl_mesh_info, size) == 0, "nl_mesh_info starts with size");
_Static_assert(sizeof(nl_version) == 12, "nl_version is three int32");
_Static_assert(sizeof(nl_mesh_id) == 8, "nl_mesh_id is two uint32");
_Static_assert(sizeof(nl_status) == 4, "nl_status is a uint32");
_Static_assert(sizeof(nl_log_level) == 4, "nl_log_level is a uint32");
_Static_assert(sizeof(nl_ray) == 28, "nl_ray is seven floats");
_Static_assert(sizeof(nl_segment) == 24, "nl_segment is six floats");
/* Growable array elements: their first release's offsets are fixed, and they may grow at their end. */
_Static_assert(sizeof(nl_ray_hit) == 48 && offsetof(nl_ray_hit, size) == 0 && offsetof(nl_ray_hit, distance) == 4,
               "nl_ray_hit has no hidden padding");
_Static_assert(offsetof(nl_ray_hit, mesh) == 32, "nl_ray_hit.mesh offset");
_Static_assert(offsetof(nl_ray_hit, hit) == 44, "nl_ray_hit.hit offset");
/* Structs with a size field may grow at their end, so only the offsets of today's fields are fixed. */
#if UINTPTR_MAX == 0xffffffffffffffffu
_Static_assert(offsetof(nl_world_def, worker_count) == 4 && offsetof(nl_world_def, log_fn) == 8 &&
                   offsetof(nl_world_def, log_user) == 16 && offsetof(nl_world_def, log_level) == 24,
               "nl_world_def on LP64");
/* The task callbacks start where the previous version's struct (with its padding) ended. */
_Static_assert(offsetof(nl_world_def, path_worker_count) == 32 && offsetof(nl_world_def, task_enqueue_fn) == 40 &&
                   offsetof(nl_world_def, task_finish_fn) == 48 && offsetof(nl_world_def, task_user) == 56,
               "nl_world_def's task callbacks on LP64");
_Static_assert(offsetof(nl_world_def, agent_paths_per_step) == 64 && offsetof(nl_world_def, reserved2) == 68 &&
                   sizeof(nl_world_def) == 72,
               "nl_world_def's agent budget on LP64");
_Static_assert(offsetof(nl_agent_def, navmesh) == 4 && offsetof(nl_agent_def, height) == 12 &&
                   offsetof(nl_agent_def, capabilities) == 16 && offsetof(nl_agent_def, max_speed) == 40 &&
                   offsetof(nl_agent_def, position) == 56 && offsetof(nl_agent_def, avoidance) == 68 &&
                   offsetof(nl_agent_def, user_data) == 72 && offsetof(nl_agent_def, give_up_seconds) == 80 &&
                   sizeof(nl_agent_def) == 88,
               "nl_agent_def (no hidden padding)");
_Static_assert(offsetof(nl_mesh_def, vertices) == 8 && offsetof(nl_mesh_def, vertex_stride) == 20 &&
                   offsetof(nl_mesh_def, indices) == 24 && offsetof(nl_mesh_def, flags) == 36 &&
                   offsetof(nl_mesh_def, transform) == 40 && offsetof(nl_mesh_def, user_data) == 48,
               "nl_mesh_def on LP64");
_Static_assert(offsetof(nl_mesh_info, transform) == 20 && offsetof(nl_mesh_info, bounds_min) == 84 &&
                   offsetof(nl_mesh_info, bounds_max) == 96 && offsetof(nl_mesh_info, user_data) == 112,
               "nl_mesh_info on LP64");
#endif

/* Navmeshes. Structs without a size field are fixed forever: every offset and the size. */
_Static_assert(sizeof(nl_navmesh_id) == 8 && offsetof(nl_navmesh_id, revision) == 4, "nl_navmesh_id");
_Static_assert(sizeof(nl_plugin_id) == 8 && offsetof(nl_plugin_id, revision) == 4, "nl_plugin_id");
_Static_assert(NL_MAX_POLYGON_VERTICES == 16, "NL_MAX_POLYGON_VERTICES");
_Static_assert(NL_NO_POLYGON == 0xffffffffu, "NL_NO_POLYGON");
_Static_assert(offsetof(nl_agent_type, radius) == 0 && offsetof(nl_agent_type, height) == 4 &&
                   offsetof(nl_agent_type, max_climb) == 8 && offsetof(nl_agent_type, max_slope) == 12 &&
                   sizeof(nl_agent_type) == 16,
               "nl_agent_type is four floats");
_Static_assert(offsetof(nl_nav_polygon, size) == 0 && offsetof(nl_nav_polygon, vertex_count) == 4 &&
                   offsetof(nl_nav_polygon, vertices) == 8 && offsetof(nl_nav_polygon, neighbours) == 72 &&
                   offsetof(nl_nav_polygon, area) == 136 && offsetof(nl_nav_polygon, normal) == 140 &&
                   offsetof(nl_nav_polygon, centre) == 152 && sizeof(nl_nav_polygon) == 164,
               "nl_nav_polygon layout (growable: set size)");
_Static_assert(offsetof(nl_boundary_edge, start) == 0 && offsetof(nl_boundary_edge, end) == 12 &&
                   offsetof(nl_boundary_edge, outward) == 24 && offsetof(nl_boundary_edge, normal) == 36 &&
                   offsetof(nl_boundary_edge, polygon) == 48 && offsetof(nl_boundary_edge, edge) == 52 &&
                   sizeof(nl_boundary_edge) == 56,
               "nl_boundary_edge layout");
_Static_assert(offsetof(nl_nav_point, point) == 0 && offsetof(nl_nav_point, distance) == 12 &&
                   offsetof(nl_nav_point, polygon) == 16 && offsetof(nl_nav_point, found) == 20 &&
                   offsetof(nl_nav_point, beyond_box) == 21 && offsetof(nl_nav_point, reserved) == 22 &&
                   sizeof(nl_nav_point) == 24,
               "nl_nav_point layout");
_Static_assert(offsetof(nl_query_filter, size) == 0 && offsetof(nl_query_filter, capabilities) == 8 &&
                   offsetof(nl_query_filter, area_costs) == 32 && offsetof(nl_random_points_def, size) == 0 &&
                   offsetof(nl_navmesh_raycast_hit, size) == 0 && offsetof(nl_navmesh_raycast_hit, t) == 8 &&
                   offsetof(nl_navmesh_ray, start_polygon) == 12 && offsetof(nl_navmesh_ray, end) == 16 &&
                   sizeof(nl_navmesh_ray) == 28,
               "query struct layouts (growable: set size)");
_Static_assert(offsetof(nl_navmesh_builder, build) == 0, "nl_navmesh_builder");
/* Structs with a size field grow at their end: only today's offsets are fixed. */
_Static_assert(offsetof(nl_navmesh_def, size) == 0 && offsetof(nl_navmesh_build_def, size) == 0 &&
                   offsetof(nl_navmesh_info, size) == 0 && offsetof(nl_plugin_description, size) == 0 &&
                   offsetof(nl_recast_settings, size) == 0 && offsetof(nl_plugin_host, size) == 0 &&
                   offsetof(nl_plugin_info, size) == 0,
               "growable structs start with size");
/* Baked navmesh files (0.3). */
_Static_assert(offsetof(nl_navmesh_load_def, size) == 0 && offsetof(nl_navmesh_load_def, carrier) == 4 &&
                   offsetof(nl_navmesh_load_def, flags) == 12 && sizeof(nl_navmesh_load_def) == 16,
               "nl_navmesh_load_def layout");
_Static_assert(offsetof(nl_navmesh_file_info, size) == 0 && offsetof(nl_navmesh_file_info, version) == 4 &&
                   offsetof(nl_navmesh_file_info, file_size) == 8 && offsetof(nl_navmesh_file_info, agent_type) == 16 &&
                   offsetof(nl_navmesh_file_info, vertex_count) == 32 &&
                   offsetof(nl_navmesh_file_info, polygon_count) == 36 &&
                   offsetof(nl_navmesh_file_info, detail_triangle_count) == 40 &&
                   offsetof(nl_navmesh_file_info, link_count) == 44 &&
                   offsetof(nl_navmesh_file_info, generated_link_count) == 48 &&
                   offsetof(nl_navmesh_file_info, rides_carrier) == 52 &&
                   offsetof(nl_navmesh_file_info, quantum) == 56 && offsetof(nl_navmesh_file_info, reserved) == 60 &&
                   offsetof(nl_navmesh_file_info, level_hash) == 64 &&
                   offsetof(nl_navmesh_file_info, content_hash) == 72 && offsetof(nl_navmesh_file_info, tile) == 80 &&
                   offsetof(nl_navmesh_file_info, tile_width) == 88 &&
                   offsetof(nl_navmesh_file_info, tile_origin_x) == 92 &&
                   offsetof(nl_navmesh_file_info, tile_origin_z) == 96 &&
                   offsetof(nl_navmesh_file_info, is_tile) == 100 && sizeof(nl_navmesh_file_info) == 104,
               "nl_navmesh_file_info layout");
_Static_assert(offsetof(nl_navmesh_info, vertex_count) == 4 && offsetof(nl_navmesh_info, polygon_count) == 8 &&
                   offsetof(nl_navmesh_info, portal_count) == 12 &&
                   offsetof(nl_navmesh_info, boundary_edge_count) == 16 &&
                   offsetof(nl_navmesh_info, welded_vertex_count) == 20 &&
                   offsetof(nl_navmesh_info, flipped_polygon_count) == 24 &&
                   offsetof(nl_navmesh_info, dropped_polygon_count) == 28 &&
                   offsetof(nl_navmesh_info, non_manifold_edge_count) == 32 &&
                   offsetof(nl_navmesh_info, agent_type) == 36 && offsetof(nl_navmesh_info, bounds_min) == 52 &&
                   offsetof(nl_navmesh_info, bounds_max) == 64 &&
                   offsetof(nl_navmesh_info, turned_over_mesh_count) == 84 &&
                   offsetof(nl_navmesh_info, t_junction_corner_count) == 92 &&
                   offsetof(nl_navmesh_info, unjoined_t_junction_count) == 96 &&
                   offsetof(nl_navmesh_info, tile_count) == 100 && offsetof(nl_navmesh_info, tile_width) == 104 &&
                   offsetof(nl_navmesh_info, tile_origin) == 108 && sizeof(nl_navmesh_info) == 116,
               "nl_navmesh_info");
_Static_assert(offsetof(nl_recast_settings, cell_size) == 4 && offsetof(nl_recast_settings, cell_height) == 8 &&
                   offsetof(nl_recast_settings, region_min_size) == 12 &&
                   offsetof(nl_recast_settings, region_merge_size) == 16 &&
                   offsetof(nl_recast_settings, edge_max_length) == 20 &&
                   offsetof(nl_recast_settings, edge_max_error) == 24 &&
                   offsetof(nl_recast_settings, vertices_per_polygon) == 28 &&
                   offsetof(nl_recast_settings, detail_sample_distance) == 32 &&
                   offsetof(nl_recast_settings, detail_sample_max_error) == 36 &&
                   offsetof(nl_recast_settings, partition) == 40 &&
                   offsetof(nl_recast_settings, filter_low_hanging_obstacles) == 44 &&
                   offsetof(nl_recast_settings, filter_ledge_spans) == 45 &&
                   offsetof(nl_recast_settings, filter_walkable_low_height_spans) == 46 &&
                   offsetof(nl_recast_settings, reserved) == 47 && offsetof(nl_recast_settings, tile_size) == 48 &&
                   offsetof(nl_recast_settings, tile_border) == 52 && sizeof(nl_recast_settings) == 56,
               "nl_recast_settings");
#if UINTPTR_MAX == 0xffffffffffffffffu
_Static_assert(offsetof(nl_navmesh_def, vertices) == 8 && offsetof(nl_navmesh_def, vertex_count) == 16 &&
                   offsetof(nl_navmesh_def, vertex_stride) == 20 && offsetof(nl_navmesh_def, indices) == 24 &&
                   offsetof(nl_navmesh_def, polygon_vertex_counts) == 32 &&
                   offsetof(nl_navmesh_def, polygon_count) == 40 && offsetof(nl_navmesh_def, areas) == 48 &&
                   offsetof(nl_navmesh_def, weld_tolerance) == 56 && offsetof(nl_navmesh_def, agent_type) == 60 &&
                   offsetof(nl_navmesh_def, detail_vertices) == 80 &&
                   offsetof(nl_navmesh_def, detail_vertex_count) == 88 &&
                   offsetof(nl_navmesh_def, detail_triangles) == 96 &&
                   offsetof(nl_navmesh_def, detail_triangle_count) == 104 &&
                   offsetof(nl_navmesh_def, detail_triangle_starts) == 112 &&
                   offsetof(nl_navmesh_def, carrier) == 120 && offsetof(nl_navmesh_def, tile_width) == 128 &&
                   offsetof(nl_navmesh_def, tile_z) == 144 && sizeof(nl_navmesh_def) == 152,
               "nl_navmesh_def on LP64");
_Static_assert(offsetof(nl_navmesh_build_def, builder) == 8 && offsetof(nl_navmesh_build_def, agent_type) == 16 &&
                   offsetof(nl_navmesh_build_def, settings) == 32 &&
                   offsetof(nl_navmesh_build_def, settings_json) == 40 &&
                   offsetof(nl_navmesh_build_def, settings_json_length) == 48,
               "nl_navmesh_build_def on LP64");
_Static_assert(offsetof(nl_plugin_description, abi_version) == 4 && offsetof(nl_plugin_description, kinds) == 8 &&
                   offsetof(nl_plugin_description, builtin) == 12 && offsetof(nl_plugin_description, name) == 16 &&
                   offsetof(nl_plugin_description, version) == 24 && offsetof(nl_plugin_description, description) == 32,
               "nl_plugin_description on LP64");
_Static_assert(offsetof(nl_plugin_host, abi_version) == 4 && offsetof(nl_plugin_host, context) == 8 &&
                   offsetof(nl_plugin_host, log) == 16 && offsetof(nl_plugin_host, set_error) == 24 &&
                   offsetof(nl_plugin_host, get_level_triangles) == 32,
               "nl_plugin_host on LP64");
_Static_assert(offsetof(nl_plugin_info, abi_version) == 4 && offsetof(nl_plugin_info, name) == 8 &&
                   offsetof(nl_plugin_info, version) == 16 && offsetof(nl_plugin_info, description) == 24 &&
                   offsetof(nl_plugin_info, kinds) == 32 && offsetof(nl_plugin_info, state) == 40 &&
                   offsetof(nl_plugin_info, destroy) == 48 && offsetof(nl_plugin_info, navmesh_builder) == 56,
               "nl_plugin_info on LP64");
#endif

/* Agents: growable outputs, no hidden padding. */
_Static_assert(sizeof(nl_agent_id) == 8 && offsetof(nl_agent_id, revision) == 4, "nl_agent_id");
_Static_assert(offsetof(nl_agent_info, state) == 4 && offsetof(nl_agent_info, id) == 8 &&
                   offsetof(nl_agent_info, position) == 16 && offsetof(nl_agent_info, velocity) == 28 &&
                   offsetof(nl_agent_info, polygon) == 40 && offsetof(nl_agent_info, reason) == 44 &&
                   offsetof(nl_agent_info, link) == 48 && offsetof(nl_agent_info, link_progress) == 56 &&
                   offsetof(nl_agent_info, destination) == 60 && offsetof(nl_agent_info, has_destination) == 72 &&
                   offsetof(nl_agent_info, corners_ahead) == 76 && offsetof(nl_agent_info, user_data) == 80 &&
                   offsetof(nl_agent_info, navmesh) == 88 && offsetof(nl_agent_info, carrier) == 96 &&
                   offsetof(nl_agent_info, carrier_position) == 104 && offsetof(nl_agent_info, reserved2) == 116 &&
                   sizeof(nl_agent_info) == 120,
               "nl_agent_info layout");
_Static_assert(offsetof(nl_agent_event, kind) == 4 && offsetof(nl_agent_event, agent) == 8 &&
                   offsetof(nl_agent_event, link) == 16 && offsetof(nl_agent_event, reason) == 24 &&
                   offsetof(nl_agent_event, user_data) == 32 && sizeof(nl_agent_event) == 40,
               "nl_agent_event layout");
_Static_assert(offsetof(nl_agent_trajectory, link) == 8 && offsetof(nl_agent_trajectory, from) == 16 &&
                   offsetof(nl_agent_trajectory, points) == 52 && offsetof(nl_agent_trajectory, duration) == 100 &&
                   sizeof(nl_agent_trajectory) == 108,
               "nl_agent_trajectory layout");

/* Links. nl_link_id and nl_link_requirements have no size field: fixed from 1.0 (CHANGELOG.md lists
   their changes before it). nl_link grows at its end (its size field). */
_Static_assert(sizeof(nl_link_id) == 8 && offsetof(nl_link_id, index1) == 0 && offsetof(nl_link_id, revision) == 4,
               "nl_link_id");
_Static_assert(sizeof(nl_link_kind) == 4, "nl_link_kind is a uint32");
_Static_assert(NL_LINK_JUMP == 1u && NL_LINK_DROP == 2u && NL_LINK_MANUAL == 3u && NL_LINK_FIRST_PLUGIN_KIND == 256u,
               "link kinds");
_Static_assert(offsetof(nl_link_requirements, gap) == 0 && offsetof(nl_link_requirements, rise) == 4 &&
                   offsetof(nl_link_requirements, drop) == 8 && offsetof(nl_link_requirements, clearance_width) == 12 &&
                   offsetof(nl_link_requirements, abilities) == 16 && offsetof(nl_link_requirements, length) == 24 &&
                   offsetof(nl_link_requirements, reserved) == 28 && sizeof(nl_link_requirements) == 32,
               "nl_link_requirements layout");
_Static_assert(offsetof(nl_link, size) == 0 && offsetof(nl_link, kind) == 4 && offsetof(nl_link, id) == 8 &&
                   offsetof(nl_link, navmesh) == 16 && offsetof(nl_link, start) == 24 && offsetof(nl_link, end) == 36 &&
                   offsetof(nl_link, apex) == 48 && offsetof(nl_link, bidirectional) == 60 &&
                   offsetof(nl_link, generated) == 61 && offsetof(nl_link, enabled) == 62 &&
                   offsetof(nl_link, reserved) == 63 && offsetof(nl_link, cost_modifier) == 64 &&
                   offsetof(nl_link, start_polygon) == 68 && offsetof(nl_link, end_polygon) == 72 &&
                   offsetof(nl_link, reserved2) == 76 && offsetof(nl_link, user_data) == 80 &&
                   offsetof(nl_link, requirements) == 88 && offsetof(nl_link, landing_navmesh) == 120 &&
                   offsetof(nl_link, tolerance) == 128 && offsetof(nl_link, holds) == 132 &&
                   offsetof(nl_link, reserved3) == 133 && sizeof(nl_link) == 136,
               "nl_link layout (no hidden padding)");
/* Growable link structs: only today's offsets are fixed. */
_Static_assert(offsetof(nl_link_def, size) == 0 && offsetof(nl_link_def, kind) == 4 &&
                   offsetof(nl_link_def, start) == 8 && offsetof(nl_link_def, end) == 20 &&
                   offsetof(nl_link_def, bidirectional) == 32 && offsetof(nl_link_def, enabled) == 33 &&
                   offsetof(nl_link_def, requirements_as_given) == 34 && offsetof(nl_link_def, reserved) == 35 &&
                   offsetof(nl_link_def, cost_modifier) == 36 && offsetof(nl_link_def, user_data) == 40 &&
                   offsetof(nl_link_def, requirements) == 48 && offsetof(nl_link_def, landing_navmesh) == 80 &&
                   offsetof(nl_link_def, tolerance) == 88 && offsetof(nl_link_def, reserved2) == 92 &&
                   sizeof(nl_link_def) == 96,
               "nl_link_def");
_Static_assert(
    offsetof(nl_link_settings, size) == 0 && offsetof(nl_link_settings, min_edge_length) == 4 &&
        offsetof(nl_link_settings, min_group_size) == 8 && offsetof(nl_link_settings, max_group_size) == 12 &&
        offsetof(nl_link_settings, sample_spacing) == 16 && offsetof(nl_link_settings, falloff_distance) == 20 &&
        offsetof(nl_link_settings, max_jump_gap) == 24 && offsetof(nl_link_settings, min_link_distance) == 28 &&
        offsetof(nl_link_settings, short_link_distance) == 32 && offsetof(nl_link_settings, max_jump_up) == 36 &&
        offsetof(nl_link_settings, jump_arc_height) == 40 && offsetof(nl_link_settings, strict_forward_angle) == 44 &&
        offsetof(nl_link_settings, permissive_forward_angle) == 48 &&
        offsetof(nl_link_settings, strict_incline_angle) == 52 &&
        offsetof(nl_link_settings, permissive_incline_angle) == 56 &&
        offsetof(nl_link_settings, max_drop_distance) == 60 && offsetof(nl_link_settings, drop_angles) == 64 &&
        sizeof(((nl_link_settings*)0)->drop_angles) == 16 * sizeof(float) &&
        offsetof(nl_link_settings, drop_angle_count) == 128 && offsetof(nl_link_settings, drop_steepness) == 132 &&
        offsetof(nl_link_settings, merge_distance) == 136 && offsetof(nl_link_settings, clearance_margin) == 140 &&
        offsetof(nl_link_settings, arc_segments) == 144,
    "nl_link_settings");
_Static_assert(offsetof(nl_link_generation_report, size) == 0 && offsetof(nl_link_generation_report, edges) == 4 &&
                   offsetof(nl_link_generation_report, groups) == 8 &&
                   offsetof(nl_link_generation_report, samples) == 12 &&
                   offsetof(nl_link_generation_report, takeoff_points) == 16 &&
                   offsetof(nl_link_generation_report, jump_candidates) == 20 &&
                   offsetof(nl_link_generation_report, drop_candidates) == 24 &&
                   offsetof(nl_link_generation_report, jump_links) == 28 &&
                   offsetof(nl_link_generation_report, drop_links) == 32 &&
                   offsetof(nl_link_generation_report, plugin_links) == 36 &&
                   offsetof(nl_link_generation_report, rejected_wall) == 40 &&
                   offsetof(nl_link_generation_report, rejected_not_ledge) == 44 &&
                   offsetof(nl_link_generation_report, rejected_distance) == 48 &&
                   offsetof(nl_link_generation_report, rejected_rise) == 52 &&
                   offsetof(nl_link_generation_report, rejected_angle) == 56 &&
                   offsetof(nl_link_generation_report, rejected_no_landing) == 60 &&
                   offsetof(nl_link_generation_report, rejected_clearance) == 64 &&
                   offsetof(nl_link_generation_report, rejected_duplicate) == 68 &&
                   offsetof(nl_link_generation_report, rays_cast) == 72 &&
                   offsetof(nl_link_generation_report, milliseconds_edges) == 80 &&
                   offsetof(nl_link_generation_report, milliseconds_takeoff) == 88 &&
                   offsetof(nl_link_generation_report, milliseconds_jumps) == 96 &&
                   offsetof(nl_link_generation_report, milliseconds_drops) == 104 &&
                   offsetof(nl_link_generation_report, milliseconds_merge) == 112 &&
                   offsetof(nl_link_generation_report, milliseconds_total) == 120 &&
                   offsetof(nl_link_generation_report, box_queries) == 128 &&
                   offsetof(nl_link_generation_report, body_tests) == 136 &&
                   offsetof(nl_link_generation_report, rejected_walkable) == 144 &&
                   offsetof(nl_link_generation_report, rejected_too_shallow) == 148 &&
                   offsetof(nl_link_generation_report, rejected_too_deep) == 152 &&
                   offsetof(nl_link_generation_report, reserved) == 156 && sizeof(nl_link_generation_report) == 160,
               "nl_link_generation_report (no hidden padding)");
#if UINTPTR_MAX == 0xffffffffffffffffu
/* On LP64 the pointer after arc_segments leaves 4 bytes of padding at 148. */
_Static_assert(offsetof(nl_link_settings, plugin_settings_json) == 152 &&
                   offsetof(nl_link_settings, plugin_settings_json_length) == 160 &&
                   offsetof(nl_link_settings, walk_factor) == 168 && offsetof(nl_link_settings, walk_distance) == 172,
               "nl_link_settings on LP64");
#endif

/* Plugins and the Recast builder's constants. */
_Static_assert(NL_PLUGIN_ABI_VERSION == 1u, "NL_PLUGIN_ABI_VERSION");
_Static_assert((NL_PLUGIN_NAVMESH_BUILDER & NL_PLUGIN_LINK_KIND) == 0u, "plugin kinds are distinct bits");
_Static_assert(NL_RECAST_PARTITION_WATERSHED == 0u && NL_RECAST_PARTITION_MONOTONE == 1u &&
                   NL_RECAST_PARTITION_LAYERS == 2u,
               "Recast partitions");

/* Every status bit is distinct and inside its part of the word. */
_Static_assert((NL_STATUS_FAILURE & NL_STATUS_SUCCESS) == 0u, "kinds are distinct");
_Static_assert(((NL_STATUS_INVALID_ARGUMENT | NL_STATUS_INVALID_HANDLE | NL_STATUS_BUFFER_TOO_SMALL |
                 NL_STATUS_OUT_OF_MEMORY | NL_STATUS_CANCELLED | NL_STATUS_PARTIAL_RESULT | NL_STATUS_NOT_FOUND |
                 NL_STATUS_INTERNAL_ERROR | NL_STATUS_IO_ERROR | NL_STATUS_PARSE_ERROR | NL_STATUS_VERSION_MISMATCH) &
                ~NL_STATUS_DETAIL_MASK) == 0u,
               "detail bits stay in the detail mask");
_Static_assert(NL_WORKERS_AUTO == -1, "NL_WORKERS_AUTO");

static void log_sink(void* user, nl_log_level level, nl_status status, const char* message) {
    (void)user;
    (void)level;
    (void)status;
    (void)message;
}

/* One pointer per declared function, typed by its declaration. */
struct api_table {
    nl_version (*get_version)(void);
    const char* (*status_string)(nl_status);
    nl_status (*get_last_status)(void);
    const char* (*get_last_error_message)(void);
    nl_world_def (*default_world_def)(void);
    nl_status (*world_create)(const nl_world_def*, nl_world**);
    void (*world_destroy)(nl_world*);
    int32_t (*world_get_worker_count)(const nl_world*);
    nl_mesh_def (*default_mesh_def)(void);
    nl_status (*mesh_add)(nl_world*, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_add_obj_file)(nl_world*, const char*, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_add_obj_memory)(nl_world*, const char*, size_t, const nl_mesh_def*, nl_mesh_id*);
    nl_status (*mesh_remove)(nl_world*, nl_mesh_id);
    nl_status (*mesh_set_transform)(nl_world*, nl_mesh_id, const float*);
    int32_t (*mesh_is_valid)(const nl_world*, nl_mesh_id);
    nl_status (*mesh_get_info)(const nl_world*, nl_mesh_id, nl_mesh_info*);
    nl_status (*world_get_meshes)(const nl_world*, nl_mesh_id*, uint32_t, uint32_t*);
    nl_status (*world_cast_rays)(nl_world*, const nl_ray*, uint32_t, nl_ray_hit*);
    nl_status (*world_segments_blocked)(nl_world*, const nl_segment*, uint32_t, uint8_t*);
    nl_log_fn* log;
    /* Navmeshes */
    nl_agent_type (*default_agent_type)(void);
    nl_navmesh_def (*default_navmesh_def)(void);
    nl_status (*navmesh_add)(nl_world*, const nl_navmesh_def*, nl_navmesh_id*);
    nl_status (*navmesh_remove)(nl_world*, nl_navmesh_id);
    int32_t (*navmesh_is_valid)(const nl_world*, nl_navmesh_id);
    nl_status (*navmesh_get_info)(const nl_world*, nl_navmesh_id, nl_navmesh_info*);
    nl_status (*navmesh_get_vertices)(const nl_world*, nl_navmesh_id, float*, uint32_t, uint32_t*);
    nl_status (*navmesh_get_polygon)(const nl_world*, nl_navmesh_id, uint32_t, nl_nav_polygon*);
    nl_status (*navmesh_get_boundary_edges)(const nl_world*, nl_navmesh_id, nl_boundary_edge*, uint32_t, uint32_t*);
    nl_status (*navmesh_find_nearest)(const nl_world*, nl_navmesh_id, const float*, uint32_t, const float*,
                                      nl_nav_point*);
    nl_status (*world_get_navmeshes)(const nl_world*, nl_navmesh_id*, uint32_t, uint32_t*);
    /* Building */
    nl_navmesh_build_def (*default_navmesh_build_def)(void);
    nl_status (*navmesh_build)(nl_world*, const nl_navmesh_build_def*, nl_navmesh_id*);
    nl_recast_settings (*default_recast_settings)(void);
    /* Plugins */
    nl_status (*plugin_load)(nl_world*, const char*, nl_plugin_id*);
    nl_status (*plugin_get_description)(const nl_world*, nl_plugin_id, nl_plugin_description*);
    nl_status (*world_get_plugins)(const nl_world*, nl_plugin_id*, uint32_t, uint32_t*);
    nl_status (*plugin_register)(nl_world*, nl_plugin_entry_fn*, nl_plugin_id*);
    /* Links */
    nl_link_def (*default_link_def)(void);
    nl_status (*link_add)(nl_world*, nl_navmesh_id, const nl_link_def*, nl_link_id*);
    nl_status (*link_update)(nl_world*, nl_link_id, const nl_link_def*);
    nl_status (*link_remove)(nl_world*, nl_link_id);
    int32_t (*link_is_valid)(const nl_world*, nl_link_id);
    nl_status (*link_get)(const nl_world*, nl_link_id, nl_link*);
    nl_status (*navmesh_get_links)(const nl_world*, nl_navmesh_id, nl_link*, uint32_t, uint32_t*);
    nl_status (*navmesh_remove_generated_links)(nl_world*, nl_navmesh_id, uint32_t*);
    nl_link_settings (*default_link_settings)(void);
    nl_status (*link_settings_from_json)(const char*, size_t, nl_link_settings*);
    nl_status (*navmesh_generate_links)(nl_world*, nl_navmesh_id, const nl_link_settings*, nl_progress_fn*, void*,
                                        nl_link_generation_report*);
    nl_status (*navmesh_update_links_in_box)(nl_world*, nl_navmesh_id, const float*, const float*, nl_progress_fn*,
                                             void*, nl_link_generation_report*);
    nl_status (*navmesh_save_links_json)(const nl_world*, nl_navmesh_id, char*, size_t, size_t*);
    nl_status (*navmesh_load_links_json)(nl_world*, nl_navmesh_id, const char*, size_t, uint32_t, uint32_t*);
    nl_progress_fn* progress;
    /* Baked navmesh files */
    nl_status (*navmesh_save)(const nl_world*, nl_navmesh_id, void*, size_t, size_t*);
    nl_status (*navmesh_save_file)(const nl_world*, nl_navmesh_id, const char*);
    nl_navmesh_load_def (*default_navmesh_load_def)(void);
    nl_status (*navmesh_load)(nl_world*, const void*, size_t, const nl_navmesh_load_def*, nl_navmesh_id*);
    nl_status (*navmesh_load_file)(nl_world*, const char*, const nl_navmesh_load_def*, nl_navmesh_id*);
    nl_status (*navmesh_file_describe)(const void*, size_t, nl_navmesh_file_info*, char*, size_t, size_t*);
    /* Paths */
    nl_agent_capabilities (*default_agent_capabilities)(void);
    nl_path_request_def (*default_path_request_def)(void);
    nl_status (*path_find)(nl_world*, const nl_path_request_def*, nl_path_result*, nl_path_point*, uint32_t, uint32_t*);
    nl_status (*path_request)(nl_world*, const nl_path_request_def*, nl_path_ticket*);
    nl_status (*path_poll)(const nl_world*, nl_path_ticket, nl_path_outcome*);
    nl_status (*path_wait)(nl_world*, nl_path_ticket, uint32_t, nl_path_outcome*);
    nl_status (*path_get_result)(const nl_world*, nl_path_ticket, nl_path_result*, nl_path_point*, uint32_t, uint32_t*);
    nl_status (*path_cancel)(nl_world*, nl_path_ticket);
    nl_status (*path_release)(nl_world*, nl_path_ticket);
    nl_path_budget (*default_path_budget)(void);
    nl_status (*path_process)(nl_world*, const nl_path_budget*, uint32_t*);
    nl_status (*path_take_finished)(nl_world*, nl_path_finished*, uint32_t, uint32_t*, uint32_t*);
    nl_status (*path_get_queue_stats)(const nl_world*, nl_path_queue_stats*);
    /* Queries */
    nl_query_filter (*default_query_filter)(void);
    nl_status (*navmesh_can_reach)(const nl_world*, nl_navmesh_id, const nl_query_filter*, const uint32_t*,
                                   const uint32_t*, uint32_t, uint8_t*);
    nl_status (*navmesh_get_reachable_polygons)(const nl_world*, nl_navmesh_id, const nl_query_filter*, uint32_t,
                                                uint32_t*, uint32_t, uint32_t*);
    nl_status (*navmesh_get_islands)(const nl_world*, nl_navmesh_id, const nl_query_filter*, uint32_t*, uint32_t,
                                     uint32_t*, uint32_t*);
    nl_status (*navmesh_raycast)(const nl_world*, nl_navmesh_id, const nl_query_filter*, const nl_navmesh_ray*,
                                 uint32_t, nl_navmesh_raycast_hit*, uint32_t*, uint32_t);
    nl_status (*navmesh_move_along_surface)(const nl_world*, nl_navmesh_id, const nl_query_filter*, uint32_t,
                                            const float*, const float*, nl_nav_point*, uint32_t*, uint32_t, uint32_t*);
    nl_random_points_def (*default_random_points_def)(void);
    nl_status (*navmesh_random_points)(const nl_world*, nl_navmesh_id, const nl_random_points_def*, nl_nav_point*,
                                       uint32_t, uint32_t*);
    /* Agents */
    nl_agent_def (*default_agent_def)(void);
    nl_status (*agent_add)(nl_world*, const nl_agent_def*, nl_agent_id*);
    nl_status (*agent_remove)(nl_world*, nl_agent_id);
    int32_t (*agent_is_valid)(const nl_world*, nl_agent_id);
    nl_status (*agent_set_destination)(nl_world*, nl_agent_id, const float*);
    nl_status (*agent_stop)(nl_world*, nl_agent_id);
    nl_status (*agent_teleport)(nl_world*, nl_agent_id, const float*);
    nl_status (*agent_set_capabilities)(nl_world*, nl_agent_id, const nl_agent_capabilities*);
    nl_status (*agent_set_speed)(nl_world*, nl_agent_id, float, float);
    nl_status (*world_step)(nl_world*, float);
    nl_status (*agent_get_info)(const nl_world*, nl_agent_id, nl_agent_info*);
    nl_status (*world_get_agents)(const nl_world*, nl_agent_info*, uint32_t, uint32_t*);
    nl_status (*agent_get_corners)(const nl_world*, nl_agent_id, nl_path_point*, uint32_t, uint32_t*);
    nl_status (*agent_get_trajectory)(const nl_world*, nl_agent_id, nl_agent_trajectory*);
    nl_status (*world_get_agent_events)(const nl_world*, nl_agent_event*, uint32_t, uint32_t*);
    /* The plugin side's function types */
    nl_plugin_entry_fn* entry;
    nl_navmesh_sink_fn* sink;
};

/* A generation progress callback as a host writes it. */
static int32_t generation_progress(void* user, float fraction, const char* stage) {
    (void)user;
    (void)stage;
    return fraction <= 1.0f;
}

/* A plugin entry and a sink as a C plugin would write them (typed by the header's function types). */
static nl_status plugin_entry(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    (void)host_abi_version;
    (void)host;
    (void)out_info;
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}

static nl_status navmesh_sink(void* sink_context, const nl_navmesh_def* navmesh) {
    (void)sink_context;
    (void)navmesh;
    return NL_STATUS_SUCCESS;
}

int main(void) {
    const struct api_table api = {
        nl_get_version,
        nl_status_string,
        nl_get_last_status,
        nl_get_last_error_message,
        nl_default_world_def,
        nl_world_create,
        nl_world_destroy,
        nl_world_get_worker_count,
        nl_default_mesh_def,
        nl_mesh_add,
        nl_mesh_add_obj_file,
        nl_mesh_add_obj_memory,
        nl_mesh_remove,
        nl_mesh_set_transform,
        nl_mesh_is_valid,
        nl_mesh_get_info,
        nl_world_get_meshes,
        nl_world_cast_rays,
        nl_world_segments_blocked,
        log_sink,
        nl_default_agent_type,
        nl_default_navmesh_def,
        nl_navmesh_add,
        nl_navmesh_remove,
        nl_navmesh_is_valid,
        nl_navmesh_get_info,
        nl_navmesh_get_vertices,
        nl_navmesh_get_polygon,
        nl_navmesh_get_boundary_edges,
        nl_navmesh_find_nearest,
        nl_world_get_navmeshes,
        nl_default_navmesh_build_def,
        nl_navmesh_build,
        nl_default_recast_settings,
        nl_plugin_load,
        nl_plugin_get_description,
        nl_world_get_plugins,
        nl_plugin_register,
        nl_default_link_def,
        nl_link_add,
        nl_link_update,
        nl_link_remove,
        nl_link_is_valid,
        nl_link_get,
        nl_navmesh_get_links,
        nl_navmesh_remove_generated_links,
        nl_default_link_settings,
        nl_link_settings_from_json,
        nl_navmesh_generate_links,
        nl_navmesh_update_links_in_box,
        nl_navmesh_save_links_json,
        nl_navmesh_load_links_json,
        generation_progress,
        nl_navmesh_save,
        nl_navmesh_save_file,
        nl_default_navmesh_load_def,
        nl_navmesh_load,
        nl_navmesh_load_file,
        nl_navmesh_file_describe,
        nl_default_agent_capabilities,
        nl_default_path_request_def,
        nl_path_find,
        nl_path_request,
        nl_path_poll,
        nl_path_wait,
        nl_path_get_result,
        nl_path_cancel,
        nl_path_release,
        nl_default_path_budget,
        nl_path_process,
        nl_path_take_finished,
        nl_path_get_queue_stats,
        nl_default_query_filter,
        nl_navmesh_can_reach,
        nl_navmesh_get_reachable_polygons,
        nl_navmesh_get_islands,
        nl_navmesh_raycast,
        nl_navmesh_move_along_surface,
        nl_default_random_points_def,
        nl_navmesh_random_points,
        nl_default_agent_def,
        nl_agent_add,
        nl_agent_remove,
        nl_agent_is_valid,
        nl_agent_set_destination,
        nl_agent_stop,
        nl_agent_teleport,
        nl_agent_set_capabilities,
        nl_agent_set_speed,
        nl_world_step,
        nl_agent_get_info,
        nl_world_get_agents,
        nl_agent_get_corners,
        nl_agent_get_trajectory,
        nl_world_get_agent_events,
        plugin_entry,
        navmesh_sink,
    };
    const nl_link_id null_link = {0u, 0u};
    const nl_navmesh_id null_navmesh = {0u, 0u};
    nl_plugin_info info;
    nl_plugin_host host;
    const nl_mesh_id null_id = {0u, 0u};
    const nl_version v = api.get_version();
    if (v.major != NL_VERSION_MAJOR || v.minor != NL_VERSION_MINOR || v.patch != NL_VERSION_PATCH) {
        fprintf(stderr, "header says %d.%d.%d, library says %d.%d.%d\n", NL_VERSION_MAJOR, NL_VERSION_MINOR,
                NL_VERSION_PATCH, (int)v.major, (int)v.minor, (int)v.patch);
        return 1;
    }
    if (api.mesh_is_valid(NULL, null_id) != 0 || !NL_FAILED(api.get_last_status())) return 1;
    if (api.navmesh_is_valid(NULL, null_navmesh) != 0 || !NL_FAILED(api.get_last_status())) return 1;
    if (api.link_is_valid(NULL, null_link) != 0 || !NL_FAILED(api.get_last_status())) return 1;
    /* The output initialisers set their sizes and zero the rest (inline: no library call). */
    {
        const nl_link link = nl_link_init();
        const nl_path_point point = nl_path_point_init();
        const nl_ray_hit hit = nl_ray_hit_init();
        const nl_nav_polygon polygon = nl_nav_polygon_init();
        const nl_path_finished finished = nl_path_finished_init();
        const nl_path_result result = nl_path_result_init();
        if (link.size != sizeof link || link.kind != 0u || link.user_data != 0u || point.size != sizeof point ||
            point.polygon != 0u || hit.size != sizeof hit || hit.hit != 0u || polygon.size != sizeof polygon ||
            finished.size != sizeof finished || finished.user != NULL || result.size != sizeof result ||
            nl_mesh_info_init().size != sizeof(nl_mesh_info) ||
            nl_navmesh_info_init().size != sizeof(nl_navmesh_info) ||
            nl_link_generation_report_init().size != sizeof(nl_link_generation_report) ||
            nl_path_queue_stats_init().size != sizeof(nl_path_queue_stats) ||
            nl_navmesh_raycast_hit_init().size != sizeof(nl_navmesh_raycast_hit) ||
            api.default_query_filter().size != sizeof(nl_query_filter) ||
            api.default_random_points_def().reachable_from != NL_NO_POLYGON ||
            nl_plugin_description_init().size != sizeof(nl_plugin_description) ||
            api.default_path_budget().size != sizeof(nl_path_budget) || api.default_path_budget().max_requests != 0u)
            return 1;
    }
    /* The link defaults set their sizes. */
    if (api.default_link_def().size != sizeof(nl_link_def) ||
        api.default_link_settings().size != sizeof(nl_link_settings) || api.progress(NULL, 1.0f, "done") != 1)
        return 1;
    /* The defaults set their sizes; the plugin-side types are usable from C. */
    if (api.default_navmesh_def().size != sizeof(nl_navmesh_def) ||
        api.default_navmesh_build_def().size != sizeof(nl_navmesh_build_def) ||
        api.default_recast_settings().size != sizeof(nl_recast_settings) || api.default_agent_type().height <= 0.0f)
        return 1;
    memset(&info, 0, sizeof info);
    memset(&host, 0, sizeof host);
    info.size = sizeof info;
    host.size = sizeof host;
    return api.entry(NL_PLUGIN_ABI_VERSION, &host, &info) == (NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH) &&
                   api.sink(NULL, NULL) == NL_STATUS_SUCCESS && api.plugin_register != NULL &&
                   strcmp(NL_PLUGIN_ENTRY_SYMBOL, "nl_plugin_entry") == 0
               ? 0
               : 1;
}
