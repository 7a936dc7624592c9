/*
 * The hostile cases of navlink/navmesh.h: navmeshes handed over and built (with Recast's settings,
 * navlink/recast.h), their ids, info, vertices, polygons, boundary edges and nearest points, the
 * world's navmeshes.
 */
#include "hostile_fixtures.h"

#include <navlink/recast.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static nl_status navmesh_add_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_add(world, (const nl_navmesh_def*)def, (nl_navmesh_id*)out);
}

/* The quad, and its parts made bad. */
static const float k_quad_nan[12] = {40, 0, -2, 40, NAN, 2, 44, 0, 2, 44, 0, -2};
static const float k_quad_inf[12] = {40, 0, -2, INFINITY, 0, 2, 44, 0, 2, 44, 0, -2};
static const float k_quad_minus_inf[12] = {40, 0, -2, 40, 0, -INFINITY, 44, 0, 2, 44, 0, -2};
static const float k_dart[12] = {40, 0, -2, 42, 0, -1, 44, 0, -2, 42, 0, 2}; /* concave at corner 1 */
static const float k_quad_detail_nan[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, NAN, 2, 44, 0.1f, -2};
static const float k_quad_detail_inf[12] = {40, 0.1f, -2, 40, 0.1f, 2, INFINITY, 0.1f, 2, 44, 0.1f, -2};
static const float k_quad_detail_minus_inf[12] = {40, 0.1f, -2, 40, 0.1f, 2, 44, 0.1f, -INFINITY, 44, 0.1f, -2};
static const uint32_t k_quad_index_4[4] = {0, 1, 2, 4};
static const uint8_t k_corners_2[1] = {2}, k_corners_17[1] = {17}, k_corners_0[1] = {0};
static const uint32_t k_detail_starts_short[2] = {0, 1};
static const uint32_t k_detail_triangles_9[6] = {0, 1, 2, 0, 2, 9};

#define NO_DETAIL                                                                                            \
    SET_PTR(nl_navmesh_def, detail_vertices, NULL), SET_U32(nl_navmesh_def, detail_vertex_count, 0u),        \
        SET_PTR(nl_navmesh_def, detail_triangles, NULL), SET_U32(nl_navmesh_def, detail_triangle_count, 0u), \
        SET_PTR(nl_navmesh_def, detail_triangle_starts, NULL)
static const geometry_fields k_navmesh_geometry = {
    GEOMETRY_FIELDS(nl_navmesh_def), {k_quad_nan, k_quad_inf, k_quad_minus_inf}, "vertices[1]"};
static const def_case k_navmesh_defs[] = {
    {"def->indices out of range (4)", INVALID, "indices[3]", {SET_PTR(nl_navmesh_def, indices, k_quad_index_4)}},
    {"def->indices concave polygon", INVALID, "convex", {SET_PTR(nl_navmesh_def, vertices, k_dart), NO_DETAIL}},
    {"def->polygon_count 0", INVALID, "polygon_count", {SET_U32(nl_navmesh_def, polygon_count, 0u)}},
    {"def->polygon_count huge (indices NULL: no per-polygon array read)",
     INVALID,
     "indices",
     {SET_PTR(nl_navmesh_def, indices, NULL), SET_U32(nl_navmesh_def, polygon_count, UINT32_MAX)}},
    {"def->polygon_vertex_counts NULL (allowed: triangles)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, NULL), NO_DETAIL}},
    {"def->polygon_vertex_counts 2",
     INVALID,
     "polygon_vertex_counts[0]",
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_2)}},
    {"def->polygon_vertex_counts 17",
     INVALID,
     "polygon_vertex_counts[0]",
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_17)}},
    {"def->polygon_vertex_counts 0",
     INVALID,
     "polygon_vertex_counts[0]",
     {SET_PTR(nl_navmesh_def, polygon_vertex_counts, k_corners_0)}},
    {"def->areas NULL (allowed: area 0)", ALLOWED, NULL, {SET_PTR(nl_navmesh_def, areas, NULL)}},
    {"def->weld_tolerance negative", INVALID, "weld_tolerance", {SET_F32(nl_navmesh_def, weld_tolerance, -1.0f)}},
    {"def->weld_tolerance 2 (more than 1 m)",
     INVALID,
     "weld_tolerance",
     {SET_F32(nl_navmesh_def, weld_tolerance, 2.0f)}},
    {"def->agent_type.radius negative", INVALID, "radius", {SET_F32(nl_navmesh_def, agent_type.radius, -0.5f)}},
    {"def->tile_width NaN", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, NAN)}},
    {"def->tile_width inf", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, INFINITY)}},
    {"def->tile_width negative", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, -4.0f)}},
    {"def->tile_width 8 (allowed: a tiled navmesh of one tile)",
     ALLOWED,
     NULL,
     {SET_F32(nl_navmesh_def, tile_width, 8.0f), SET_F32(nl_navmesh_def, tile_origin_x, 36.0f)}},
    {"def->tile_origin_x NaN (a tile)",
     INVALID,
     "tile_origin",
     {SET_F32(nl_navmesh_def, tile_width, 8.0f), SET_F32(nl_navmesh_def, tile_origin_x, NAN)}},
    {"def->tile_origin_x inf (a tile)",
     INVALID,
     "tile_origin",
     {SET_F32(nl_navmesh_def, tile_width, 8.0f), SET_F32(nl_navmesh_def, tile_origin_x, INFINITY)}},
    {"def->tile_origin_z NaN (a tile)",
     INVALID,
     "tile_origin",
     {SET_F32(nl_navmesh_def, tile_width, 8.0f), SET_F32(nl_navmesh_def, tile_origin_z, NAN)}},
    {"def->tile_origin_z inf (a tile)",
     INVALID,
     "tile_origin",
     {SET_F32(nl_navmesh_def, tile_width, 8.0f), SET_F32(nl_navmesh_def, tile_origin_z, -INFINITY)}},
    {"def->detail_vertices NULL (allowed with no detail at all)", ALLOWED, NULL, {NO_DETAIL}},
    {"def->detail_vertices NULL (the rest of the detail given)",
     INVALID,
     "detail_vertices",
     {SET_PTR(nl_navmesh_def, detail_vertices, NULL)}},
    {"def->detail_vertices NaN (detail vertex 2)",
     INVALID,
     "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_nan)}},
    {"def->detail_vertices inf (detail vertex 2)",
     INVALID,
     "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_inf)}},
    {"def->detail_vertices -inf (detail vertex 2)",
     INVALID,
     "detail_vertices[2]",
     {SET_PTR(nl_navmesh_def, detail_vertices, k_quad_detail_minus_inf)}},
    {"def->detail_vertex_count 0", INVALID, "detail_vertex_count", {SET_U32(nl_navmesh_def, detail_vertex_count, 0u)}},
    {"def->detail_vertex_count huge (detail_vertices NULL: not read)",
     INVALID,
     "detail_vertices",
     {SET_PTR(nl_navmesh_def, detail_vertices, NULL), SET_U32(nl_navmesh_def, detail_vertex_count, UINT32_MAX)}},
    {"def->detail_triangles NULL", INVALID, "detail_triangles", {SET_PTR(nl_navmesh_def, detail_triangles, NULL)}},
    {"def->detail_triangles out of range (9)",
     INVALID,
     "detail_triangles[5]",
     {SET_PTR(nl_navmesh_def, detail_triangles, k_detail_triangles_9)}},
    {"def->detail_triangle_count 0",
     INVALID,
     "detail_triangle_count",
     {SET_U32(nl_navmesh_def, detail_triangle_count, 0u)}},
    {"def->detail_triangle_count huge (detail_triangles NULL: not read)",
     INVALID,
     "detail_triangles",
     {SET_PTR(nl_navmesh_def, detail_triangles, NULL), SET_U32(nl_navmesh_def, detail_triangle_count, UINT32_MAX)}},
    {"def->detail_triangle_starts NULL",
     INVALID,
     "detail_triangle_starts",
     {SET_PTR(nl_navmesh_def, detail_triangle_starts, NULL)}},
    {"def->detail_triangle_starts not ending at the count",
     INVALID,
     "detail_triangle_starts",
     {SET_PTR(nl_navmesh_def, detail_triangle_starts, k_detail_starts_short)}},
};
#undef NO_DETAIL

static const float_field k_agent_type_floats[] = {
    FLOAT_FIELD(nl_agent_type, radius, 1), FLOAT_FIELD(nl_agent_type, height, 1),
    FLOAT_FIELD(nl_agent_type, max_climb, 1), FLOAT_FIELD(nl_agent_type, max_slope, 1)};

/* The agent type's floats at `offset` in a def, named "agent_type.FIELD". */
static void bad_agent_floats(const char* function, const void* valid, size_t size, size_t offset, refuse_fn* refuse) {
    float_field fields[4];
    char names[4][32];
    size_t i;
    for (i = 0; i < 4; ++i) {
        snprintf(names[i], sizeof names[i], "agent_type.%s", k_agent_type_floats[i].name);
        fields[i].name = names[i];
        fields[i].offset = offset + k_agent_type_floats[i].offset;
        fields[i].count = 1;
    }
    bad_float_fields(function, "def", valid, size, fields, 4, refuse);
}

/* A def's `carrier` mesh id (at `offset`): the movable lift is allowed too (the navmesh rides it;
   `riding` is a def that fits on the lift), a static mesh is INVALID_ARGUMENT. */
static void carrier_cases(const def_function* f, const void* valid, const void* riding, size_t size, size_t offset) {
    aligned_buffer def;
    optional_id_cases(f, valid, size, offset, "def->carrier", RAW(A.movable), RAW(A.stale_mesh), RAW(B.movable));
    CASE(f->function, "def->carrier the movable lift (allowed: the navmesh rides it)") {
        memcpy(def.bytes, riding, size);
        memcpy(def.bytes + offset, &A.movable, sizeof A.movable);
        def_accepts(def.bytes);
    }
    CASE(f->function, "def->carrier a static mesh") {
        memcpy(def.bytes, valid, size);
        memcpy(def.bytes + offset, &A.mesh, sizeof A.mesh);
        def_refuses(def.bytes, NL_STATUS_INVALID_ARGUMENT, "def->carrier is not a movable mesh");
    }
}

static void group_navmesh_add(void) {
    static const def_function add = {
        "nl_navmesh_add", navmesh_add_call, sizeof(nl_navmesh_id), remove_navmesh_out, 0, 0, 0};
    static const float_field weld[] = {FLOAT_FIELD(nl_navmesh_def, weld_tolerance, 1)};
    const nl_navmesh_def valid = quad_navmesh_def();
    def_function_cases(&add, &valid, sizeof valid);
    geometry_cases("nl_navmesh_add", &valid, sizeof valid, &k_navmesh_geometry);
    def_cases("nl_navmesh_add", &valid, sizeof valid, k_navmesh_defs, sizeof k_navmesh_defs / sizeof *k_navmesh_defs,
              def_refuses, def_accepts);
    bad_float_fields("nl_navmesh_add", "def", &valid, sizeof valid, weld, 1, def_refuses);
    bad_agent_floats("nl_navmesh_add", &valid, sizeof valid, offsetof(nl_navmesh_def, agent_type), def_refuses);
    carrier_cases(&add, &valid, &valid, sizeof valid, offsetof(nl_navmesh_def, carrier));
}

/* The functions that take a navmesh id and no more than an output. */
ID_CALL(navmesh_remove_call, nl_navmesh_id, nl_navmesh_remove)
ID_VALID_CALL(navmesh_is_valid_call, nl_navmesh_id, nl_navmesh_is_valid)
static nl_status navmesh_get_polygon_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_get_polygon(w, AS(nl_navmesh_id, id), 0, (nl_nav_polygon*)out);
}
static const id_function k_navmesh_functions[] = {
    {"nl_navmesh_remove", "navmesh", NULL, 0, 0, 0, navmesh_remove_call, 0},
    {"nl_navmesh_is_valid", "navmesh", NULL, 0, 0, 1, navmesh_is_valid_call, 0},
    {"nl_navmesh_get_info", "navmesh", "out_info", sizeof(nl_navmesh_info), 1, 0, navmesh_get_info_call, 0},
    {"nl_navmesh_get_polygon", "navmesh", "out_polygon", sizeof(nl_nav_polygon), 0, 0, navmesh_get_polygon_call, 0},
};

static void navmesh_id_cases(size_t which) {
    id_cases(&k_navmesh_functions[which], RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
}

static void group_navmesh_remove(void) { navmesh_id_cases(0); }
static void group_navmesh_is_valid(void) { navmesh_id_cases(1); }

static nl_status navmesh_info_into(void* out) { return nl_navmesh_get_info(A.world, A.navmesh, (nl_navmesh_info*)out); }

static void group_navmesh_get_info(void) {
    navmesh_id_cases(2);
    out_sizes("nl_navmesh_get_info", "out_info", sizeof(nl_navmesh_info), navmesh_info_into);
}

static nl_status polygon_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_navmesh_get_polygon(A.world, A.navmesh, 0, (nl_nav_polygon*)out);
}

static void group_navmesh_get_polygon(void) {
    const uint32_t polygons = navmesh_info(&A, A.navmesh).polygon_count;
    const uint32_t out_of_range[2] = {polygons, UINT32_MAX};
    int k;
    navmesh_id_cases(3);
    CASE("nl_navmesh_get_polygon", "polygon 0 (allowed: the first)") {
        nl_nav_polygon out = nl_nav_polygon_init();
        EXPECT_OK(nl_navmesh_get_polygon(A.world, A.navmesh, 0, &out));
        EXPECT(out.vertex_count >= 3 && out.vertex_count <= NL_MAX_POLYGON_VERTICES, "vertex_count %u",
               (unsigned)out.vertex_count);
    }
    for (k = 0; k < 2; ++k) {
        CASE("nl_navmesh_get_polygon", k == 0 ? "polygon out of range (polygon_count)" : "polygon huge") {
            nl_nav_polygon out = nl_nav_polygon_init();
            fill(&out, sizeof out);
            EXPECT_INVALID(A.world, nl_navmesh_get_polygon(A.world, A.navmesh, out_of_range[k], &out), "polygon");
            EXPECT_UNTOUCHED(&out, sizeof out, "out_polygon");
        }
    }
    out_element_sizes("nl_navmesh_get_polygon", "out_polygon", sizeof(nl_nav_polygon), polygon_into);
}

static nl_status list_vertices(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_vertices(w, n, (float*)out, capacity, count);
}
static nl_status list_edges(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_boundary_edges(w, n, (nl_boundary_edge*)out, capacity, count);
}

static void group_navmesh_get_vertices(void) {
    navmesh_list_cases("nl_navmesh_get_vertices", "out_xyz", 3 * sizeof(float),
                       navmesh_info(&A, A.navmesh).vertex_count, list_vertices);
}

static void group_navmesh_get_boundary_edges(void) {
    navmesh_list_cases("nl_navmesh_get_boundary_edges", "out_edges", sizeof(nl_boundary_edge),
                       navmesh_info(&A, A.navmesh).boundary_edge_count, list_edges);
}

/* nl_navmesh_find_nearest on A's navmesh, with two points (the second one made bad) and a box. */
static const float k_points[6] = {-6, 1, 0, 6, 1, 0};
static const float k_extents[3] = {2, 4, 2};
static const float* g_nearest_points = k_points;
static const float* g_nearest_extents = k_extents;
static nl_status find_nearest_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_find_nearest(w, AS(nl_navmesh_id, id), g_nearest_points, 2, g_nearest_extents,
                                   (nl_nav_point*)out);
}

static void nearest_refused(const float* points, uint32_t count, const float* extents, const char* needle) {
    nl_nav_point out[2];
    fill(out, sizeof out);
    EXPECT_INVALID(A.world, nl_navmesh_find_nearest(A.world, A.navmesh, points, count, extents, out), needle);
    EXPECT_UNTOUCHED(out, sizeof out, "out");
}

static void group_navmesh_find_nearest(void) {
    static const id_function f = {"nl_navmesh_find_nearest", "navmesh", "out", 2 * sizeof(nl_nav_point), 0, 0,
                                  find_nearest_call,         0};
    size_t v;
    int k, which;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_find_nearest", "points NULL") { nearest_refused(NULL, 2, k_extents, "points"); }
    CASE("nl_navmesh_find_nearest", "count huge (points NULL: not read)") {
        nearest_refused(NULL, UINT32_MAX, k_extents, "points");
    }
    CASE("nl_navmesh_find_nearest", "count huge (out NULL: points past the first not read)") {
        EXPECT_INVALID(A.world, nl_navmesh_find_nearest(A.world, A.navmesh, k_points, UINT32_MAX, k_extents, NULL),
                       "out");
    }
    CASE("nl_navmesh_find_nearest", "count 0 (allowed, with points and out NULL)") {
        EXPECT_OK(nl_navmesh_find_nearest(A.world, A.navmesh, NULL, 0, k_extents, NULL));
    }
    CASE("nl_navmesh_find_nearest", "half_extents NULL") { nearest_refused(k_points, 2, NULL, "half_extents"); }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT + 2; ++v) {
                static const char* more[2] = {"0", "negative (-1)"};
                const float value = v < BAD_FLOAT_COUNT ? k_bad_floats[v].value : v == BAD_FLOAT_COUNT ? 0.0f : -1.0f;
                const char* what = v < BAD_FLOAT_COUNT ? k_bad_floats[v].name : more[v - BAD_FLOAT_COUNT];
                if (which == 0 && v >= BAD_FLOAT_COUNT) continue; /* 0 and -1 are fine coordinates */
                CASE("nl_navmesh_find_nearest", which == 0 ? "points[%d] %s (point 1)" : "half_extents[%d] %s",
                     which == 0 ? 3 + k : k, what) {
                    float p[6], e[3];
                    memcpy(p, k_points, sizeof p);
                    memcpy(e, k_extents, sizeof e);
                    if (which == 0)
                        p[3 + k] = value;
                    else
                        e[k] = value;
                    nearest_refused(p, 2, e, which == 0 ? "points[1]" : "half_extents");
                }
            }
        }
    }
    CASE("nl_navmesh_find_nearest", "points beyond the limit (point 1, 2e9)") {
        float p[6];
        memcpy(p, k_points, sizeof p);
        p[5] = 2.0e9f;
        nearest_refused(p, 2, k_extents, "points[1]");
    }
}

static void group_world_get_navmeshes(void) {
    world_list_cases("nl_world_get_navmeshes", "out_ids", sizeof(nl_navmesh_id), 2u, get_navmeshes);
}

/* ---------------------------------------------------------------------------------------------
 * Building navmeshes
 * ------------------------------------------------------------------------------------------- */

static nl_status build_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_build(world, (const nl_navmesh_build_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_build = {
    "nl_navmesh_build", build_call, sizeof(nl_navmesh_id), remove_navmesh_out, 0, 0, 0};

/* Recast's settings made bad, through def->settings. */
static void build_with_recast_refuses(const void* settings, nl_status detail, const char* needle) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    g_def = &k_build;
    def_refuses(&def, detail, needle);
}
static void build_with_recast_accepts(const void* settings) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    g_def = &k_build;
    def_accepts(&def);
}

#define JSON(text)                                      \
    SET_PTR(nl_navmesh_build_def, settings_json, text), \
        SET_LENGTH(nl_navmesh_build_def, settings_json_length, sizeof text - 1)
static const def_case k_build_defs[] = {
    {"def->builder NULL (allowed: recast)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, builder, NULL)}},
    {"def->builder empty", NL_STATUS_NOT_FOUND, "''", {SET_PTR(nl_navmesh_build_def, builder, "")}},
    {"def->builder unknown",
     NL_STATUS_NOT_FOUND,
     "no-such-builder",
     {SET_PTR(nl_navmesh_build_def, builder, "no-such-builder")}},
    {"def->settings NULL (allowed: Recast's defaults)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, settings, NULL)}},
    {"def->settings_json NULL (allowed with length 0)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_navmesh_build_def, settings_json, NULL)}},
    {"def->settings_json_length huge (settings_json NULL: not read)",
     INVALID,
     "settings_json",
     {SET_LENGTH(nl_navmesh_build_def, settings_json_length, SIZE_MAX)}},
    {"def->settings_json_length 0 (an empty string is not a JSON object)",
     NL_STATUS_PARSE_ERROR,
     "settings_json",
     {SET_PTR(nl_navmesh_build_def, settings_json, "{}")}},
    {"def->settings_json not an object", INVALID, "settings_json", {JSON("[1]")}},
    {"def->settings_json malformed", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": ")}},
    {"def->settings_json inf (1e400)", INVALID, "cell_size", {JSON("{\"cell_size\": 1e400}")}},
    {"def->settings_json -inf (-1e400)", INVALID, "edge_max_error", {JSON("{\"edge_max_error\": -1e400}")}},
    {"def->settings_json NaN (not JSON)", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": NaN}")}},
    {"def->progress NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, progress, NULL)}},
};
#undef JSON

static const def_case k_recast_settings[] = {
    {"settings->vertices_per_polygon 0",
     INVALID,
     "vertices_per_polygon",
     {SET_U32(nl_recast_settings, vertices_per_polygon, 0u)}},
    {"settings->vertices_per_polygon 2",
     INVALID,
     "vertices_per_polygon",
     {SET_U32(nl_recast_settings, vertices_per_polygon, 2u)}},
    {"settings->vertices_per_polygon 7",
     INVALID,
     "vertices_per_polygon",
     {SET_U32(nl_recast_settings, vertices_per_polygon, 7u)}},
    {"settings->vertices_per_polygon huge",
     INVALID,
     "vertices_per_polygon",
     {SET_U32(nl_recast_settings, vertices_per_polygon, UINT32_MAX)}},
    {"settings->partition 3", INVALID, "partition", {SET_U32(nl_recast_settings, partition, 3u)}},
    {"settings->partition huge", INVALID, "partition", {SET_U32(nl_recast_settings, partition, UINT32_MAX)}},
};

static const float_field k_recast_floats[] = {FLOAT_FIELD(nl_recast_settings, cell_size, 1),
                                              FLOAT_FIELD(nl_recast_settings, cell_height, 1),
                                              FLOAT_FIELD(nl_recast_settings, region_min_size, 1),
                                              FLOAT_FIELD(nl_recast_settings, region_merge_size, 1),
                                              FLOAT_FIELD(nl_recast_settings, edge_max_length, 1),
                                              FLOAT_FIELD(nl_recast_settings, edge_max_error, 1),
                                              FLOAT_FIELD(nl_recast_settings, detail_sample_distance, 1),
                                              FLOAT_FIELD(nl_recast_settings, detail_sample_max_error, 1)};

static void group_navmesh_build(void) {
    const nl_navmesh_build_def valid = nl_default_navmesh_build_def();
    const nl_recast_settings recast = nl_default_recast_settings();
    def_function_cases(&k_build, &valid, sizeof valid);
    def_cases("nl_navmesh_build", &valid, sizeof valid, k_build_defs, sizeof k_build_defs / sizeof *k_build_defs,
              def_refuses, def_accepts);
    bad_agent_floats("nl_navmesh_build", &valid, sizeof valid, offsetof(nl_navmesh_build_def, agent_type), def_refuses);
    {
        nl_navmesh_build_def small =
            valid; /* the 4 m lift, eroded by a 0.6 m body, is below Recast's smallest region */
        small.agent_type.radius = 0.2f;
        carrier_cases(&k_build, &valid, &small, sizeof valid, offsetof(nl_navmesh_build_def, carrier));
    }
    CASE("nl_navmesh_build", "def->progress cancels (returns 0 at once: CANCELLED, nothing added)") {
        nl_navmesh_build_def def = valid;
        int calls = 0;
        def.progress = cancel_at_once;
        def.progress_user = &calls;
        def_refuses(&def, NL_STATUS_CANCELLED, "cancelled");
        EXPECT(calls == 1, "the progress callback was called %d times, expected once (it cancelled)", calls);
    }
    CASE("nl_navmesh_build", "def->progress_user NULL (allowed: passed back as it is)") {
        nl_navmesh_build_def def = valid;
        int calls = 0;
        g_user_seen = &calls;
        def.progress = note_user;
        def.progress_user = NULL;
        def_accepts(&def);
        EXPECT(g_user_seen == NULL, "the progress callback received user %p, not NULL", g_user_seen);
    }
    def_sizes("nl_navmesh_build", "settings", &recast, sizeof recast, build_with_recast_refuses,
              build_with_recast_accepts);
    def_cases("nl_navmesh_build", &recast, sizeof recast, k_recast_settings,
              sizeof k_recast_settings / sizeof *k_recast_settings, build_with_recast_refuses,
              build_with_recast_accepts);
    bad_float_fields("nl_navmesh_build", "settings", &recast, sizeof recast, k_recast_floats,
                     sizeof k_recast_floats / sizeof *k_recast_floats, build_with_recast_refuses);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"navmesh_add", group_navmesh_add},
    {"navmesh_remove", group_navmesh_remove},
    {"navmesh_is_valid", group_navmesh_is_valid},
    {"navmesh_get_info", group_navmesh_get_info},
    {"navmesh_get_vertices", group_navmesh_get_vertices},
    {"navmesh_get_polygon", group_navmesh_get_polygon},
    {"navmesh_get_boundary_edges", group_navmesh_get_boundary_edges},
    {"navmesh_find_nearest", group_navmesh_find_nearest},
    {"world_get_navmeshes", group_world_get_navmeshes},
    {"navmesh_build", group_navmesh_build},
};
const hostile_part hostile_navmesh_part = {k_groups, sizeof k_groups / sizeof *k_groups};
