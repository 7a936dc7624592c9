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
/* The rows of every def of polygons: nl_navmesh_add's and nl_navmesh_add_tile's. */
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

/* nl_navmesh_add's tile fields: a def with tile_width > 0 is a tiled navmesh of one tile. */
static const def_case k_navmesh_tile_defs[] = {
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
};

/* nl_navmesh_add_tile's: the valid def is tile (2, 0) of the tiled navmesh's grid (tiles of 8 m from
   (60, -4), tiles (0, 0) and (1, 0) loaded). */
static const def_case k_add_tile_defs[] = {
    {"def->tile_width NaN", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, NAN)}},
    {"def->tile_width inf", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, INFINITY)}},
    {"def->tile_width negative", INVALID, "tile_width", {SET_F32(nl_navmesh_def, tile_width, -8.0f)}},
    {"def->tile_width 0 (not a tile)", INVALID, "not a tile", {SET_F32(nl_navmesh_def, tile_width, 0.0f)}},
    {"def->tile_width 4 (another grid)", INVALID, "another grid", {SET_F32(nl_navmesh_def, tile_width, 4.0f)}},
    {"def->tile_origin_x NaN", INVALID, "tile_origin", {SET_F32(nl_navmesh_def, tile_origin_x, NAN)}},
    {"def->tile_origin_x inf", INVALID, "tile_origin", {SET_F32(nl_navmesh_def, tile_origin_x, INFINITY)}},
    {"def->tile_origin_x 61 (another grid)", INVALID, "another grid", {SET_F32(nl_navmesh_def, tile_origin_x, 61.0f)}},
    {"def->tile_origin_z NaN", INVALID, "tile_origin", {SET_F32(nl_navmesh_def, tile_origin_z, NAN)}},
    {"def->tile_origin_z inf", INVALID, "tile_origin", {SET_F32(nl_navmesh_def, tile_origin_z, -INFINITY)}},
    {"def->tile_origin_z 4 (another grid: one tile up)",
     INVALID,
     "another grid",
     {SET_F32(nl_navmesh_def, tile_origin_z, 4.0f)}},
    {"def->tile_x 0 (tile (0, 0): loaded already)", INVALID, "loaded already", {SET_I32(nl_navmesh_def, tile_x, 0)}},
    {"def->tile_x 1 (tile (1, 0): loaded already)", INVALID, "loaded already", {SET_I32(nl_navmesh_def, tile_x, 1)}},
    {"def->tile_z 1 (allowed: tile (2, 1), a new row)", ALLOWED, NULL, {SET_I32(nl_navmesh_def, tile_z, 1)}},
    {"def->agent_type.radius 0.3 (another agent type)",
     INVALID,
     "another agent type",
     {SET_F32(nl_navmesh_def, agent_type.radius, 0.3f)}},
    {"def->agent_type.max_climb 0.5 (another agent type)",
     INVALID,
     "another agent type",
     {SET_F32(nl_navmesh_def, agent_type.max_climb, 0.5f)}},
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
    def_cases("nl_navmesh_add", &valid, sizeof valid, k_navmesh_tile_defs,
              sizeof k_navmesh_tile_defs / sizeof *k_navmesh_tile_defs, def_refuses, def_accepts);
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
    world_list_cases("nl_world_get_navmeshes", "out_ids", sizeof(nl_navmesh_id), 3u, get_navmeshes);
}

/* ---------------------------------------------------------------------------------------------
 * Building navmeshes
 * ------------------------------------------------------------------------------------------- */

static nl_status build_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_build(world, (const nl_navmesh_build_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_build = {
    "nl_navmesh_build", build_call, sizeof(nl_navmesh_id), remove_navmesh_out, 0, 0, 0};

/* Recast's settings made bad, through def->settings of a default def given to g_def (nl_navmesh_build
   or nl_navmesh_build_tiles: recast_settings_cases sets it). */
static void build_with_recast_refuses(const void* settings, nl_status detail, const char* needle) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    def_refuses(&def, detail, needle);
}
static void build_with_recast_accepts(const void* settings) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings = settings;
    def_accepts(&def);
}
/* Recast's settings given to `f` through def->settings: their sizes, then `cases` from `valid`. */
static void recast_settings_cases(const def_function* f, const nl_recast_settings* valid, const def_case* cases,
                                  size_t count) {
    g_def = f;
    def_sizes(f->function, "settings", valid, sizeof *valid, build_with_recast_refuses, build_with_recast_accepts);
    def_cases(f->function, valid, sizeof *valid, cases, count, build_with_recast_refuses, build_with_recast_accepts);
}

/* def->progress that cancels at once (refused, nothing `changed`; then `unchanged` checks it, when
   given) and def->progress_user NULL, on `f` from `valid`. */
static void progress_cases(const def_function* f, const nl_navmesh_build_def* valid, const char* changed,
                           void (*unchanged)(void)) {
    g_def = f;
    CASE(f->function, "def->progress cancels (returns 0 at once: CANCELLED, nothing %s)", changed) {
        nl_navmesh_build_def def = *valid;
        int calls = 0;
        def.progress = cancel_at_once;
        def.progress_user = &calls;
        def_refuses(&def, NL_STATUS_CANCELLED, "cancelled");
        EXPECT(calls == 1, "the progress callback was called %d times, expected once (it cancelled)", calls);
        if (unchanged) unchanged();
    }
    CASE(f->function, "def->progress_user NULL (allowed: passed back as it is)") {
        nl_navmesh_build_def def = *valid;
        int calls = 0;
        g_user_seen = &calls;
        def.progress = note_user;
        def.progress_user = NULL;
        def_accepts(&def);
        EXPECT(g_user_seen == NULL, "the progress callback received user %p, not NULL", g_user_seen);
    }
}

/* The rows of a build def: those nl_navmesh_build and nl_navmesh_build_tiles share (k_build_shared_defs),
   then each one's own (k_build_defs, k_build_tiles_defs). */
static const def_case k_build_shared_defs[] = {
    {"def->builder NULL (allowed: recast)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, builder, NULL)}},
    {"def->builder empty", NL_STATUS_NOT_FOUND, "''", {SET_PTR(nl_navmesh_build_def, builder, "")}},
    {"def->builder unknown",
     NL_STATUS_NOT_FOUND,
     "no-such-builder",
     {SET_PTR(nl_navmesh_build_def, builder, "no-such-builder")}},
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
    {"def->progress NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, progress, NULL)}},
};
#define JSON(text)                                      \
    SET_PTR(nl_navmesh_build_def, settings_json, text), \
        SET_LENGTH(nl_navmesh_build_def, settings_json_length, sizeof text - 1)
static const def_case k_build_defs[] = {
    {"def->settings NULL (allowed: Recast's defaults)", ALLOWED, NULL, {SET_PTR(nl_navmesh_build_def, settings, NULL)}},
    {"def->settings_json not an object", INVALID, "settings_json", {JSON("[1]")}},
    {"def->settings_json malformed", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": ")}},
    {"def->settings_json inf (1e400)", INVALID, "cell_size", {JSON("{\"cell_size\": 1e400}")}},
    {"def->settings_json -inf (-1e400)", INVALID, "edge_max_error", {JSON("{\"edge_max_error\": -1e400}")}},
    {"def->settings_json NaN (not JSON)", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"cell_size\": NaN}")}},
};
/* nl_navmesh_build_tiles' rows from its valid def (def->settings the tiles' settings, tiles_recast_settings). */
static const def_case k_build_tiles_defs[] = {
    {"def->settings NULL (Recast's defaults: tile_size 0, one solo mesh)",
     INVALID,
     "tile_size is 0",
     {SET_PTR(nl_navmesh_build_def, settings, NULL)}},
    {"def->settings NULL with settings_json giving the tiles' settings (allowed)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_navmesh_build_def, settings, NULL), JSON("{\"tile_size\": 16, \"cell_size\": 0.5}")}},
    {"def->settings_json malformed", NL_STATUS_PARSE_ERROR, "settings_json", {JSON("{\"tile_size\": ")}},
    {"def->settings_json tile_size 0 (over def->settings: one solo mesh)",
     INVALID,
     "tile_size is 0",
     {JSON("{\"tile_size\": 0}")}},
    {"def->settings_json tile_size 32 (over def->settings: tiles of 16 m)",
     INVALID,
     "makes tiles of",
     {JSON("{\"tile_size\": 32}")}},
    {"def->agent_type.radius 0.3 (another agent type)",
     INVALID,
     "agent type",
     {SET_F32(nl_navmesh_build_def, agent_type.radius, 0.3f)}},
    {"def->agent_type.height 1 (another agent type)",
     INVALID,
     "agent type",
     {SET_F32(nl_navmesh_build_def, agent_type.height, 1.0f)}},
    {"def->agent_type.max_climb 0.5 (another agent type)",
     INVALID,
     "agent type",
     {SET_F32(nl_navmesh_build_def, agent_type.max_climb, 0.5f)}},
    {"def->agent_type.max_slope 30 (another agent type)",
     INVALID,
     "agent type",
     {SET_F32(nl_navmesh_build_def, agent_type.max_slope, 30.0f)}},
};
#undef JSON

/* The tile fields of a build def: the world sets them for its builder (nl_navmesh_build_tiles takes a
   box); a host leaves them 0, and any other value is refused naming them. The rows of nl_navmesh_build
   and nl_navmesh_build_tiles alike. */
static const def_case k_build_tile_fields[] = {
    {"def->tile_origin_x 60 (the tiled navmesh's: set by the world, not the host)",
     INVALID,
     "tile_origin_x",
     {SET_F32(nl_navmesh_build_def, tile_origin_x, TILE_ORIGIN_X)}},
    {"def->tile_origin_z -4 (the tiled navmesh's: set by the world, not the host)",
     INVALID,
     "tile_origin_z",
     {SET_F32(nl_navmesh_build_def, tile_origin_z, TILE_ORIGIN_Z)}},
    {"def->tile_origin_x -0 (allowed: 0)", ALLOWED, NULL, {SET_F32(nl_navmesh_build_def, tile_origin_x, -0.0f)}},
    {"def->tile_width 8 (the tiled navmesh's: set by the world, not the host)",
     INVALID,
     "tile_width",
     {SET_F32(nl_navmesh_build_def, tile_width, TILE_WIDTH)}},
    {"def->tile_width negative", INVALID, "tile_width", {SET_F32(nl_navmesh_build_def, tile_width, -8.0f)}},
    {"def->first_tile.x 1", INVALID, "first_tile", {SET_I32(nl_navmesh_build_def, first_tile.x, 1)}},
    {"def->first_tile.z -1", INVALID, "first_tile", {SET_I32(nl_navmesh_build_def, first_tile.z, -1)}},
    {"def->tile_columns 1", INVALID, "tile_columns", {SET_U32(nl_navmesh_build_def, tile_columns, 1u)}},
    {"def->tile_rows huge", INVALID, "tile_rows", {SET_U32(nl_navmesh_build_def, tile_rows, UINT32_MAX)}},
    {"def->tile_width 8 with the rest of a builder's request (tile (0, 0) of the tiled navmesh's grid)",
     INVALID,
     "tile_width",
     {SET_F32(nl_navmesh_build_def, tile_origin_x, TILE_ORIGIN_X),
      SET_F32(nl_navmesh_build_def, tile_origin_z, TILE_ORIGIN_Z),
      SET_F32(nl_navmesh_build_def, tile_width, TILE_WIDTH), SET_U32(nl_navmesh_build_def, tile_columns, 1u),
      SET_U32(nl_navmesh_build_def, tile_rows, 1u)}},
};
static const float_field k_build_tile_floats[] = {FLOAT_FIELD(nl_navmesh_build_def, tile_origin_x, 1),
                                                  FLOAT_FIELD(nl_navmesh_build_def, tile_origin_z, 1),
                                                  FLOAT_FIELD(nl_navmesh_build_def, tile_width, 1)};

/* A build def's rows on `f` from `valid`: the shared ones, `own`, then the tile fields. */
static void build_def_cases(const def_function* f, const nl_navmesh_build_def* valid, const def_case* own,
                            size_t count) {
    g_def = f;
    def_cases(f->function, valid, sizeof *valid, k_build_shared_defs,
              sizeof k_build_shared_defs / sizeof *k_build_shared_defs, def_refuses, def_accepts);
    def_cases(f->function, valid, sizeof *valid, own, count, def_refuses, def_accepts);
    def_cases(f->function, valid, sizeof *valid, k_build_tile_fields,
              sizeof k_build_tile_fields / sizeof *k_build_tile_fields, def_refuses, def_accepts);
    bad_float_fields(f->function, "def", valid, sizeof *valid, k_build_tile_floats,
                     sizeof k_build_tile_floats / sizeof *k_build_tile_floats, def_refuses);
}

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
    build_def_cases(&k_build, &valid, k_build_defs, sizeof k_build_defs / sizeof *k_build_defs);
    bad_agent_floats("nl_navmesh_build", &valid, sizeof valid, offsetof(nl_navmesh_build_def, agent_type), def_refuses);
    {
        nl_navmesh_build_def small =
            valid; /* the 4 m lift, eroded by a 0.6 m body, is below Recast's smallest region */
        small.agent_type.radius = 0.2f;
        carrier_cases(&k_build, &valid, &small, sizeof valid, offsetof(nl_navmesh_build_def, carrier));
    }
    progress_cases(&k_build, &valid, "added", NULL);
    recast_settings_cases(&k_build, &recast, k_recast_settings, sizeof k_recast_settings / sizeof *k_recast_settings);
    bad_float_fields("nl_navmesh_build", "settings", &recast, sizeof recast, k_recast_floats,
                     sizeof k_recast_floats / sizeof *k_recast_floats, build_with_recast_refuses);
}

/* ---------------------------------------------------------------------------------------------
 * Tiles, on A's tiled navmesh (tiles (0, 0) and (1, 0) of 8 m from (60, -4); B's issues the
 * foreign id in its slot)
 * ------------------------------------------------------------------------------------------- */

/* The tiles A's tiled navmesh holds are the fixture's two, and its info says so. */
static void expect_fixture_tiles(void) {
    nl_tile_coord tiles[8];
    uint32_t count;
    memset(tiles, 0, sizeof tiles);
    count = navmesh_tiles(&A, A.tiled, tiles, 8);
    EXPECT(count == 2u && tiles[0].x == 0 && tiles[0].z == 0 && tiles[1].x == 1 && tiles[1].z == 0,
           "the tiled navmesh holds %u tiles, (%d, %d), (%d, %d) first, not (0, 0) and (1, 0)", (unsigned)count,
           (int)tiles[0].x, (int)tiles[0].z, (int)tiles[1].x, (int)tiles[1].z);
    EXPECT(navmesh_info(&A, A.tiled).tile_count == 2u, "tile_count %u, expected 2",
           (unsigned)navmesh_info(&A, A.tiled).tile_count);
}

static nl_status add_tile_def_call(nl_world* world, const void* def, void* out) {
    (void)out;
    return nl_navmesh_add_tile(world, A.tiled, (const nl_navmesh_def*)def);
}
/* An accepted tile is the one tile more the navmesh holds: removed again, the navmesh is as it was. */
static void remove_added_tile(const void* out) {
    nl_tile_coord tiles[8];
    uint32_t count, i, removed = 0;
    (void)out;
    count = navmesh_tiles(&A, A.tiled, tiles, 8);
    EXPECT(count == 3u, "the tiled navmesh holds %u tiles after the tile was added, expected 3", (unsigned)count);
    EXPECT(navmesh_info(&A, A.tiled).tile_count == count, "tile_count %u, nl_navmesh_get_tiles %u",
           (unsigned)navmesh_info(&A, A.tiled).tile_count, (unsigned)count);
    for (i = 0; i < count && i < 8; ++i) {
        if ((tiles[i].x == 0 || tiles[i].x == 1) && tiles[i].z == 0) continue;
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, tiles[i]));
        ++removed;
    }
    EXPECT(removed == 1u, "%u tiles beside the fixture's", (unsigned)removed);
    expect_fixture_tiles();
}
static const def_function k_add_tile = {"nl_navmesh_add_tile", add_tile_def_call, 0, remove_added_tile, 0, 0, 1};

/* The id cases: a valid tile (2, 0), added to the navmesh each bad id names. */
static const nl_navmesh_def* g_tile_def;
static nl_status add_tile_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_add_tile(w, AS(nl_navmesh_id, id), g_tile_def);
}
static nl_status remove_tile_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_remove_tile(w, AS(nl_navmesh_id, id), (nl_tile_coord){1, 0});
}
/* nl_navmesh_build_tiles' id cases build with a valid def over the empty box (below). */
static const nl_navmesh_build_def* g_tiles_def;
static const float k_empty_box_min[3] = {77, 0, -3}, k_empty_box_max[3] = {83, 0, 3};
static nl_status build_tiles_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_build_tiles(w, AS(nl_navmesh_id, id), g_tiles_def, k_empty_box_min, k_empty_box_max);
}
static const id_function k_tile_functions[] = {
    {"nl_navmesh_add_tile", "navmesh", NULL, 0, 0, 0, add_tile_id_call, 0},
    {"nl_navmesh_remove_tile", "navmesh", NULL, 0, 0, 0, remove_tile_id_call, 0},
    {"nl_navmesh_build_tiles", "navmesh", NULL, 0, 0, 0, build_tiles_id_call, 0},
};

static void group_navmesh_add_tile(void) {
    static const float_field weld[] = {FLOAT_FIELD(nl_navmesh_def, weld_tolerance, 1)};
    const nl_navmesh_def valid = tile_navmesh_def(2, 0);
    g_tile_def = &valid;
    id_cases(&k_tile_functions[0], RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    def_function_cases(&k_add_tile, &valid, sizeof valid);
    geometry_cases("nl_navmesh_add_tile", &valid, sizeof valid, &k_navmesh_geometry);
    def_cases("nl_navmesh_add_tile", &valid, sizeof valid, k_navmesh_defs,
              sizeof k_navmesh_defs / sizeof *k_navmesh_defs, def_refuses, def_accepts);
    def_cases("nl_navmesh_add_tile", &valid, sizeof valid, k_add_tile_defs,
              sizeof k_add_tile_defs / sizeof *k_add_tile_defs, def_refuses, def_accepts);
    bad_float_fields("nl_navmesh_add_tile", "def", &valid, sizeof valid, weld, 1, def_refuses);
    bad_agent_floats("nl_navmesh_add_tile", &valid, sizeof valid, offsetof(nl_navmesh_def, agent_type), def_refuses);
    optional_id_cases(&k_add_tile, &valid, sizeof valid, offsetof(nl_navmesh_def, carrier), "def->carrier",
                      RAW(A.movable), RAW(A.stale_mesh), RAW(B.movable));
    CASE("nl_navmesh_add_tile", "def->carrier the movable lift (the navmesh rides none)") {
        nl_navmesh_def def = valid;
        def.carrier = A.movable;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->carrier");
    }
    CASE("nl_navmesh_add_tile", "navmesh solo (the host's quad: not tiled)") {
        EXPECT_INVALID(A.world, nl_navmesh_add_tile(A.world, A.host_navmesh, &valid), "not tiled");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_add_tile", "navmesh solo (built whole: not tiled)") {
        EXPECT_INVALID(A.world, nl_navmesh_add_tile(A.world, A.navmesh, &valid), "not tiled");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_add_tile", "def a tile loaded already (tile (1, 0) again, as it was given)") {
        const nl_navmesh_def again = tile_navmesh_def(1, 0);
        EXPECT_INVALID(A.world, nl_navmesh_add_tile(A.world, A.tiled, &again), "loaded already");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_add_tile", "def a tile of another grid (tile_width 8 from (0, 0))") {
        nl_navmesh_def other = valid;
        other.tile_origin_x = 0.0f;
        other.tile_origin_z = 0.0f;
        other.tile_x = 9;
        other.tile_z = 0;
        EXPECT_INVALID(A.world, nl_navmesh_add_tile(A.world, A.tiled, &other), "another grid");
        expect_fixture_tiles();
    }
    {
        /* A tile whose square lies far beyond NL_COORDINATE_LIMIT (its polygons are tile (2, 0)'s: nothing
           documented ties them to their square): refused naming the field, or a tile like any other,
           removed cleanly. */
        static const nl_tile_coord far[3] = {{INT32_MAX, 0}, {0, INT32_MIN}, {INT32_MIN, INT32_MAX}};
        static const char* what[3] = {"def->tile_x huge (INT32_MAX)", "def->tile_z huge negative (INT32_MIN)",
                                      "def->tile_x huge negative and tile_z huge (INT32_MIN, INT32_MAX)"};
        int k;
        for (k = 0; k < 3; ++k) {
            CASE("nl_navmesh_add_tile", "%s: refused, or added and removed cleanly", what[k]) {
                nl_navmesh_def def = valid;
                nl_status status;
                def.tile_x = far[k].x;
                def.tile_z = far[k].z;
                status = nl_navmesh_add_tile(A.world, A.tiled, &def);
                if (NL_FAILED(status)) {
                    EXPECT_INVALID(A.world, status, k == 1 ? "tile_z" : "tile_x");
                    expect_fixture_tiles();
                } else {
                    nl_tile_coord tiles[4];
                    EXPECT_OK(status);
                    EXPECT(navmesh_tiles(&A, A.tiled, tiles, 4) == 3u, "not 3 tiles after it was added");
                    EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, far[k]));
                    expect_fixture_tiles();
                }
            }
        }
    }
    CASE("nl_navmesh_add_tile", "def the tile (2, 0) (allowed: joined, then removed)") {
        nl_navmesh_info before = navmesh_info(&A, A.tiled), after;
        EXPECT_OK(nl_navmesh_add_tile(A.world, A.tiled, &valid));
        after = navmesh_info(&A, A.tiled);
        EXPECT(after.tile_count == 3u && after.polygon_count == before.polygon_count + 1u,
               "tile_count %u, polygons %u (before %u)", (unsigned)after.tile_count, (unsigned)after.polygon_count,
               (unsigned)before.polygon_count);
        EXPECT(after.tile_width == TILE_WIDTH && after.tile_origin[0] == TILE_ORIGIN_X &&
                   after.tile_origin[1] == TILE_ORIGIN_Z,
               "the grid became %g m from (%g, %g)", (double)after.tile_width, (double)after.tile_origin[0],
               (double)after.tile_origin[1]);
        remove_added_tile(NULL);
    }
}

static void group_navmesh_remove_tile(void) {
    static const nl_tile_coord missing[] = {{2, 0}, {0, 1}, {-1, 0}, {INT32_MAX, INT32_MAX}, {INT32_MIN, INT32_MIN}};
    static const char* missing_what[] = {"(2, 0): never loaded", "(0, 1): never loaded", "(-1, 0): never loaded",
                                         "huge (INT32_MAX, INT32_MAX)", "huge negative (INT32_MIN, INT32_MIN)"};
    size_t k;
    id_cases(&k_tile_functions[1], RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    for (k = 0; k < sizeof missing / sizeof *missing; ++k) {
        CASE("nl_navmesh_remove_tile", "tile not loaded %s", missing_what[k]) {
            EXPECT_FAILURE(A.world, nl_navmesh_remove_tile(A.world, A.tiled, missing[k]), NL_STATUS_NOT_FOUND,
                           "is loaded");
            expect_fixture_tiles();
        }
    }
    CASE("nl_navmesh_remove_tile", "navmesh solo (the host's quad: not tiled)") {
        EXPECT_INVALID(A.world, nl_navmesh_remove_tile(A.world, A.host_navmesh, (nl_tile_coord){0, 0}), "not tiled");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_remove_tile", "navmesh solo (built whole: not tiled)") {
        EXPECT_INVALID(A.world, nl_navmesh_remove_tile(A.world, A.navmesh, (nl_tile_coord){0, 0}), "not tiled");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_remove_tile", "tile removed twice (NOT_FOUND the second time; added back after)") {
        const nl_navmesh_def second = tile_navmesh_def(1, 0);
        nl_tile_coord tiles[4];
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){1, 0}));
        EXPECT(navmesh_tiles(&A, A.tiled, tiles, 4) == 1u && tiles[0].x == 0 && tiles[0].z == 0,
               "the navmesh does not hold tile (0, 0) alone");
        EXPECT(navmesh_info(&A, A.tiled).tile_count == 1u, "tile_count %u, expected 1",
               (unsigned)navmesh_info(&A, A.tiled).tile_count);
        EXPECT_FAILURE(A.world, nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){1, 0}), NL_STATUS_NOT_FOUND,
                       "(1, 0)");
        EXPECT(navmesh_tiles(&A, A.tiled, tiles, 4) == 1u && tiles[0].x == 0 && tiles[0].z == 0,
               "the failed removal changed the tiles");
        /* Back as it was: the runner checks the navmesh is the same as before. */
        EXPECT_OK(nl_navmesh_add_tile(A.world, A.tiled, &second));
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_remove_tile", "tile the last (INVALID_ARGUMENT: remove the navmesh instead)") {
        /* A host's tile alone is a tiled navmesh of one tile. */
        const nl_navmesh_def only = tile_navmesh_def(3, 1);
        nl_navmesh_id one;
        nl_tile_coord tiles[4];
        memset(&one, 0, sizeof one);
        EXPECT_OK(nl_navmesh_add(A.world, &only, &one));
        EXPECT(navmesh_tiles(&A, one, tiles, 4) == 1u && tiles[0].x == 3 && tiles[0].z == 1,
               "the one-tile navmesh does not hold tile (3, 1)");
        EXPECT_INVALID(A.world, nl_navmesh_remove_tile(A.world, one, (nl_tile_coord){3, 1}), "last");
        EXPECT(navmesh_tiles(&A, one, tiles, 4) == 1u && tiles[0].x == 3 && tiles[0].z == 1,
               "the failed removal changed the tiles");
        EXPECT_OK(nl_navmesh_remove(A.world, one));
    }
    CASE("nl_navmesh_remove_tile", "tile the last but one, then the last (the fixture's, added back after)") {
        const nl_navmesh_def first = tile_navmesh_def(0, 0);
        nl_tile_coord tiles[4];
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){0, 0}));
        EXPECT_INVALID(A.world, nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){1, 0}), "last");
        EXPECT(navmesh_tiles(&A, A.tiled, tiles, 4) == 1u && tiles[0].x == 1 && tiles[0].z == 0,
               "the failed removal changed the tiles");
        EXPECT_OK(nl_navmesh_add_tile(A.world, A.tiled, &first));
        expect_fixture_tiles();
    }
}

/* nl_navmesh_build_tiles into A's tiled navmesh. The def cases build over the empty box: tile (2, 0)'s
   square less 1 m each side, where the level has nothing walkable and no tile is loaded, so a success
   builds nothing and leaves the navmesh as it was. Recast makes tiles of tile_size * cell_size: 16 cells
   of 0.5 m are the navmesh's 8 m; the grid's origin is the navmesh's. */
static nl_recast_settings tiles_recast_settings(void) {
    nl_recast_settings settings = nl_default_recast_settings();
    settings.tile_size = 16;
    settings.cell_size = 0.5f;
    return settings;
}

static nl_status build_tiles_def_call(nl_world* world, const void* def, void* out) {
    (void)out;
    return nl_navmesh_build_tiles(world, A.tiled, (const nl_navmesh_build_def*)def, k_empty_box_min, k_empty_box_max);
}
/* An accepted def built nothing in the empty box: the navmesh holds the fixture's tiles (the runner
   compares the rest). */
static void nothing_built(const void* out) {
    (void)out;
    expect_fixture_tiles();
}
static const def_function k_build_tiles = {"nl_navmesh_build_tiles", build_tiles_def_call, 0, nothing_built, 0, 0, 1};
/* Its def's rows are k_build_tiles_defs, beside nl_navmesh_build's (they share most of them). */

/* Recast's settings against the navmesh's tiles (the valid ones: tiles_recast_settings). */
static const def_case k_build_tiles_settings[] = {
    {"settings->tile_size 0 (one solo mesh)", INVALID, "tile_size is 0", {SET_U32(nl_recast_settings, tile_size, 0u)}},
    {"settings->tile_size 32 (tiles of 16 m, not the navmesh's 8)",
     INVALID,
     "makes tiles of",
     {SET_U32(nl_recast_settings, tile_size, 32u)}},
    {"settings->tile_size 20 (tiles of 10 m, not the navmesh's 8)",
     INVALID,
     "makes tiles of",
     {SET_U32(nl_recast_settings, tile_size, 20u)}},
    {"settings->tile_size 15 (below the 16 cells of a tile)",
     INVALID,
     "tile_size",
     {SET_U32(nl_recast_settings, tile_size, 15u)}},
    {"settings->tile_size huge", INVALID, "tile_size", {SET_U32(nl_recast_settings, tile_size, UINT32_MAX)}},
    {"settings->cell_size 0.25 (tile_size 16 makes tiles of 4 m)",
     INVALID,
     "makes tiles of",
     {SET_F32(nl_recast_settings, cell_size, 0.25f)}},
    {"settings->tile_size 32 with cell_size 0.25 (allowed: tiles of 8 m, the navmesh's)",
     ALLOWED,
     NULL,
     {SET_U32(nl_recast_settings, tile_size, 32u), SET_F32(nl_recast_settings, cell_size, 0.25f)}},
    {"settings->tile_border 1 (less than the radius in cells + 1)",
     INVALID,
     "tile_border",
     {SET_U32(nl_recast_settings, tile_border, 1u)}},
};

/* A box refused naming `needle`: the tiles as they were (the runner compares the rest). */
static void box_refused(const nl_navmesh_build_def* def, const float* box_min, const float* box_max,
                        const char* needle) {
    EXPECT_INVALID(A.world, nl_navmesh_build_tiles(A.world, A.tiled, def, box_min, box_max), needle);
    expect_fixture_tiles();
}

/* The tile (-7, 0) of the grid (x 4..12, z -4..4) holds most of the right platform: built there, it is
   the one tile more the navmesh holds (first in row order), with polygons; removed again, the navmesh
   is as it was. */
static const float k_platform_point[3] = {6, 0, 0};
static void expect_platform_tile_built(const nl_navmesh_info* before) {
    nl_tile_coord tiles[8];
    const uint32_t count = navmesh_tiles(&A, A.tiled, tiles, 8);
    const nl_navmesh_info after = navmesh_info(&A, A.tiled);
    EXPECT(count == 3u && tiles[0].x == -7 && tiles[0].z == 0 && tiles[1].x == 0 && tiles[1].z == 0 &&
               tiles[2].x == 1 && tiles[2].z == 0,
           "the tiled navmesh holds %u tiles, (%d, %d) first, not (-7, 0), (0, 0) and (1, 0)", (unsigned)count,
           (int)tiles[0].x, (int)tiles[0].z);
    EXPECT(after.tile_count == 3u && after.polygon_count > before->polygon_count,
           "tile_count %u, polygons %u (before %u)", (unsigned)after.tile_count, (unsigned)after.polygon_count,
           (unsigned)before->polygon_count);
    EXPECT(after.tile_width == TILE_WIDTH && after.tile_origin[0] == TILE_ORIGIN_X &&
               after.tile_origin[1] == TILE_ORIGIN_Z,
           "the grid became %g m from (%g, %g)", (double)after.tile_width, (double)after.tile_origin[0],
           (double)after.tile_origin[1]);
}

static void group_navmesh_build_tiles(void) {
    const nl_recast_settings recast = tiles_recast_settings();
    nl_navmesh_build_def valid = nl_default_navmesh_build_def();
    size_t v;
    int which, k;
    valid.settings = &recast;
    g_tiles_def = &valid;
    id_cases(&k_tile_functions[2], RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    def_function_cases(&k_build_tiles, &valid, sizeof valid);
    build_def_cases(&k_build_tiles, &valid, k_build_tiles_defs, sizeof k_build_tiles_defs / sizeof *k_build_tiles_defs);
    /* A bad float of the agent type is not the navmesh's agent type: refused naming agent_type. */
    for (k = 0; k < 4; ++k) {
        for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
            CASE("nl_navmesh_build_tiles", "def->agent_type.%s %s (not the navmesh's agent type)",
                 k_agent_type_floats[k].name, k_bad_floats[v].name) {
                nl_navmesh_build_def def = valid;
                memcpy((unsigned char*)&def.agent_type + k_agent_type_floats[k].offset, &k_bad_floats[v].value,
                       sizeof(float));
                def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "agent_type");
            }
        }
    }
    /* def->carrier is ignored (the navmesh's own is built on): any id is accepted, nothing checked. */
    FOR_BAD_IDS(bad, A.movable, A.stale_mesh, B.movable) {
        CASE("nl_navmesh_build_tiles", "def->carrier %s (allowed: ignored)", bad->what) {
            nl_navmesh_build_def def = valid;
            def.carrier = AS(nl_mesh_id, bad->id);
            def_accepts(&def);
        }
    }
    CASE("nl_navmesh_build_tiles", "def->carrier the movable lift (ignored: the tile is built from the static level)") {
        const nl_navmesh_info before = navmesh_info(&A, A.tiled);
        nl_navmesh_build_def def = valid;
        def.carrier = A.movable;
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &def, k_platform_point, k_platform_point));
        expect_platform_tile_built(&before);
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){-7, 0}));
        expect_fixture_tiles();
    }
    progress_cases(&k_build_tiles, &valid, "changed", expect_fixture_tiles);
    recast_settings_cases(&k_build_tiles, &recast, k_build_tiles_settings,
                          sizeof k_build_tiles_settings / sizeof *k_build_tiles_settings);

    /* The box. */
    CASE("nl_navmesh_build_tiles", "box_min NULL") { box_refused(&valid, NULL, k_empty_box_max, "box_min"); }
    CASE("nl_navmesh_build_tiles", "box_max NULL") { box_refused(&valid, k_empty_box_min, NULL, "box_max"); }
    for (which = 0; which < 2; ++which) {
        const char* name = which == 0 ? "box_min" : "box_max";
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT + 1; ++v) {
                const float value = v < BAD_FLOAT_COUNT ? k_bad_floats[v].value : 2.0e9f;
                const char* what = v < BAD_FLOAT_COUNT ? k_bad_floats[v].name : "beyond the limit (2e9)";
                float lo[3], hi[3];
                memcpy(lo, k_empty_box_min, sizeof lo);
                memcpy(hi, k_empty_box_max, sizeof hi);
                if (k == 1) {
                    /* y: the header says it is not read, while the box is checked as a position: refused
                       naming it, or accepted with nothing built. */
                    CASE("nl_navmesh_build_tiles", "%s[1] %s (y: refused, or not read)", name, what) {
                        nl_status status;
                        (which == 0 ? lo : hi)[1] = value;
                        status = nl_navmesh_build_tiles(A.world, A.tiled, &valid, lo, hi);
                        if (NL_FAILED(status))
                            EXPECT_INVALID(A.world, status, name);
                        else
                            EXPECT_OK(status);
                        expect_fixture_tiles();
                    }
                    continue;
                }
                CASE("nl_navmesh_build_tiles", "%s[%d] %s", name, k, what) {
                    (which == 0 ? lo : hi)[k] = value;
                    box_refused(&valid, lo, hi, name);
                }
            }
        }
    }
    for (k = 0; k < 3; k += 2) {
        CASE("nl_navmesh_build_tiles", "box_min beyond box_max in %s (by 1 cm)", k == 0 ? "x" : "z") {
            float lo[3], hi[3];
            memcpy(lo, k_empty_box_min, sizeof lo);
            memcpy(hi, k_empty_box_min, sizeof hi);
            hi[k] -= 0.01f;
            box_refused(&valid, lo, hi, "box_min is beyond box_max");
        }
    }
    CASE("nl_navmesh_build_tiles", "box_min above box_max in y (allowed: y is not read)") {
        float lo[3], hi[3];
        memcpy(lo, k_empty_box_min, sizeof lo);
        memcpy(hi, k_empty_box_max, sizeof hi);
        lo[1] = 5.0f;
        hi[1] = -5.0f;
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &valid, lo, hi));
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_build_tiles", "box_min equal to box_max (allowed: the tile the point is in)") {
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &valid, k_empty_box_min, k_empty_box_min));
        expect_fixture_tiles();
    }
    {
        /* From tile (0, 0): 2049 columns by 2048 rows, 4 196 352 tiles, one column more than 2^22. */
        static const float lo[3] = {TILE_ORIGIN_X + 0.5f, 0, TILE_ORIGIN_Z + 0.5f};
        static const float hi[3] = {TILE_ORIGIN_X + 2048 * TILE_WIDTH + 0.5f, 0,
                                    TILE_ORIGIN_Z + 2047 * TILE_WIDTH + 0.5f};
        CASE("nl_navmesh_build_tiles", "box_max huge (2049 x 2048 tiles: more than 2^22)") {
            box_refused(&valid, lo, hi, "2^22");
        }
    }
    CASE("nl_navmesh_build_tiles", "box over every loaded tile (none walkable now: no tile would be left)") {
        static const float lo[3] = {61, 0, -3}, hi[3] = {75, 0, 3};
        box_refused(&valid, lo, hi, "no tile would be left");
    }
    CASE("nl_navmesh_build_tiles", "navmesh solo (the host's quad: not tiled)") {
        EXPECT_INVALID(A.world,
                       nl_navmesh_build_tiles(A.world, A.host_navmesh, &valid, k_empty_box_min, k_empty_box_max),
                       "not tiled");
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_build_tiles", "navmesh solo (built whole: not tiled)") {
        EXPECT_INVALID(A.world, nl_navmesh_build_tiles(A.world, A.navmesh, &valid, k_empty_box_min, k_empty_box_max),
                       "not tiled");
        expect_fixture_tiles();
    }

    /* Successes that change the navmesh, undone. */
    CASE("nl_navmesh_build_tiles", "box on the platform's tile (-7, 0) (allowed: built, built again, removed)") {
        const nl_navmesh_info before = navmesh_info(&A, A.tiled);
        nl_navmesh_info built;
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &valid, k_platform_point, k_platform_point));
        expect_platform_tile_built(&before);
        built = navmesh_info(&A, A.tiled);
        /* Built again: the tile loaded there is replaced by the same. */
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &valid, k_platform_point, k_platform_point));
        expect_platform_tile_built(&before);
        EXPECT(navmesh_info(&A, A.tiled).polygon_count == built.polygon_count &&
                   navmesh_info(&A, A.tiled).vertex_count == built.vertex_count,
               "built again: %u polygons and %u vertices, not %u and %u",
               (unsigned)navmesh_info(&A, A.tiled).polygon_count, (unsigned)navmesh_info(&A, A.tiled).vertex_count,
               (unsigned)built.polygon_count, (unsigned)built.vertex_count);
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){-7, 0}));
        expect_fixture_tiles();
    }
    CASE("nl_navmesh_build_tiles",
         "box on tile (1, 0) alone (allowed: nothing walkable there now: removed, added back)") {
        static const float lo[3] = {69, 0, -3}, hi[3] = {75, 0, 3};
        const nl_navmesh_def second = tile_navmesh_def(1, 0);
        nl_tile_coord tiles[4];
        EXPECT_OK(nl_navmesh_build_tiles(A.world, A.tiled, &valid, lo, hi));
        EXPECT(navmesh_tiles(&A, A.tiled, tiles, 4) == 1u && tiles[0].x == 0 && tiles[0].z == 0,
               "the navmesh does not hold tile (0, 0) alone");
        EXPECT(navmesh_info(&A, A.tiled).tile_count == 1u, "tile_count %u, expected 1",
               (unsigned)navmesh_info(&A, A.tiled).tile_count);
        /* Back as it was: the runner checks the navmesh is the same as before. */
        EXPECT_OK(nl_navmesh_add_tile(A.world, A.tiled, &second));
        expect_fixture_tiles();
    }
}

static nl_status list_tiles(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_tiles(w, n, (nl_tile_coord*)out, capacity, count);
}

static void group_navmesh_get_tiles(void) {
    navmesh_list_cases_on("nl_navmesh_get_tiles", "out_tiles", sizeof(nl_tile_coord), 2u, list_tiles, A.tiled, B.tiled);
    CASE("nl_navmesh_get_tiles", "navmesh solo (allowed: no tiles)") {
        const nl_navmesh_id solo[2] = {A.navmesh, A.host_navmesh};
        nl_tile_coord tiles[4];
        uint32_t count;
        int k;
        for (k = 0; k < 2; ++k) {
            fill(tiles, sizeof tiles);
            count = 0xdeadbeefu;
            EXPECT_OK(nl_navmesh_get_tiles(A.world, solo[k], tiles, 4, &count));
            EXPECT(count == 0u, "out_count = %u for a solo navmesh", (unsigned)count);
            EXPECT_UNTOUCHED(tiles, sizeof tiles, "out_tiles");
            EXPECT(navmesh_info(&A, solo[k]).tile_count == 0u, "tile_count of a solo navmesh");
        }
    }
    CASE("nl_navmesh_get_tiles", "out_tiles room for 2 (allowed: row order)") {
        nl_tile_coord tiles[3];
        uint32_t count = 0;
        fill(tiles, sizeof tiles);
        EXPECT_OK(nl_navmesh_get_tiles(A.world, A.tiled, tiles, 2, &count));
        EXPECT(count == 2u && tiles[0].x == 0 && tiles[0].z == 0 && tiles[1].x == 1 && tiles[1].z == 0,
               "%u tiles, not (0, 0), (1, 0)", (unsigned)count);
        EXPECT_UNTOUCHED(&tiles[2], sizeof tiles[2], "the entry past out_count");
    }
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
    {"navmesh_add_tile", group_navmesh_add_tile},
    {"navmesh_remove_tile", group_navmesh_remove_tile},
    {"navmesh_build_tiles", group_navmesh_build_tiles},
    {"navmesh_get_tiles", group_navmesh_get_tiles},
};
const hostile_part hostile_navmesh_part = {k_groups, sizeof k_groups / sizeof *k_groups};
