/*
 * The hostile cases of navlink/level.h: meshes added from arrays, OBJ files and OBJ text, their
 * ids and transforms, the world's meshes, rays and segments.
 */
#include "hostile_fixtures.h"
#include "scene.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A 2 x 2 m floor at y = 3 over the right platform, counter-clockwise from above, and copies of it
   made bad. */
static const float k_tile[12] = {4, 3, -1, 4, 3, 1, 6, 3, 1, 6, 3, -1};
static const float k_tile_nan[12] = {4, 3, -1, 4, 3, 1, 6, NAN, 1, 6, 3, -1};
static const float k_tile_inf[12] = {4, 3, -1, 4, 3, 1, INFINITY, 3, 1, 6, 3, -1};
static const float k_tile_minus_inf[12] = {4, 3, -1, 4, 3, 1, 6, 3, -INFINITY, 6, 3, -1};
static const float k_tile_far[12] = {4, 3, -1, 2.0e9f, 3, 1, 6, 3, 1, 6, 3, -1};
static const uint32_t k_tile_indices[6] = {0, 1, 2, 0, 2, 3};
static const uint32_t k_tile_index_4[6] = {0, 1, 2, 0, 4, 3};
static const uint32_t k_tile_index_huge[6] = {0, 1, 2, 0, UINT32_MAX, 3};
static const uint32_t k_tile_flat[6] = {0, 0, 1, 2, 2, 2};

static nl_mesh_def tile_def(void) { return mesh_def_of(k_tile, 4, k_tile_indices, 2); }

/* Transforms the header refuses: non-finite elements, not affine, singular, or moving the geometry
   beyond the coordinate limit (element 14). */
typedef struct transform_change {
    const char* what;
    int index;
    float value;
} transform_change;
static const transform_change k_bad_transforms[] = {
    {"[0] NaN", 0, NAN},
    {"[5] inf", 5, INFINITY},
    {"[10] -inf", 10, -INFINITY},
    {"[12] NaN", 12, NAN},
    {"[13] inf", 13, INFINITY},
    {"[15] NaN", 15, NAN},
    {"[3] non-affine (1)", 3, 1},
    {"[15] non-affine (2)", 15, 2},
    {"[0] singular (0: flattens x)", 0, 0},
    {"[14] beyond the limit (2e9)", 14, 2.0e9f},
};
#define BAD_TRANSFORM_COUNT (sizeof k_bad_transforms / sizeof *k_bad_transforms)
static const float k_identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static void transform_from(const transform_change* c, float m[16]) {
    memcpy(m, k_identity, sizeof k_identity);
    m[c->index] = c->value;
}
static const char* transform_needle(const transform_change* c) { return c->index == 14 ? "limit" : "transform"; }

/* Each bad transform as a def's (`set` puts it in the def and calls). */
static void bad_def_transforms(const char* function, const char* suffix, const nl_mesh_def* valid, refuse_fn* refuse) {
    size_t i;
    for (i = 0; i < BAD_TRANSFORM_COUNT; ++i) {
        CASE(function, "def->transform%s%s", k_bad_transforms[i].what, suffix) {
            float m[16];
            nl_mesh_def def = *valid;
            transform_from(&k_bad_transforms[i], m);
            def.transform = m;
            refuse(&def, NL_STATUS_INVALID_ARGUMENT, transform_needle(&k_bad_transforms[i]));
        }
    }
}

/* A mesh added as documented is valid, and is removed: the worlds end as they were. */
static void remove_mesh_out(const void* out) {
    nl_mesh_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_mesh_is_valid(A.world, id) == 1, "the new mesh {%u, %u} is not valid", (unsigned)id.index1,
           (unsigned)id.revision);
    EXPECT_OK(nl_mesh_remove(A.world, id));
}

static nl_status mesh_add_call(nl_world* world, const void* def, void* out) {
    return nl_mesh_add(world, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}

/* What nl_mesh_add and the two OBJ loads share: the def function's cases, the flags, the transform. */
static void mesh_def_cases(const def_function* f, const nl_mesh_def* valid) {
    def_function_cases(f, valid, sizeof *valid);
    CASE(f->function, "def->flags unknown (0x10)") {
        nl_mesh_def def = *valid;
        def.flags = 0x10u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "flags");
    }
    CASE(f->function, "def->flags NL_MESH_OBSTACLE | NL_MESH_NOT_IN_NAVMESH (contradictory)") {
        nl_mesh_def def = *valid;
        def.flags = NL_MESH_OBSTACLE | NL_MESH_NOT_IN_NAVMESH;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "NL_MESH_NOT_IN_NAVMESH");
    }
    CASE(f->function, "def->area huge (NL_MESH_MAX_AREA + 1)") {
        nl_mesh_def def = *valid;
        def.area = NL_MESH_MAX_AREA + 1u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "area");
    }
    CASE(f->function, "def->area huge (UINT32_MAX)") {
        nl_mesh_def def = *valid;
        def.area = UINT32_MAX;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "area");
    }
    CASE(f->function, "def->reserved not 0") {
        nl_mesh_def def = *valid;
        def.reserved = 1u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "reserved");
    }
    CASE(f->function, "def->transform NULL (allowed: identity)") { def_accepts(valid); }
    bad_def_transforms(f->function, "", valid, def_refuses);
    {
        static const struct {
            const char* name;
            float value;
        } bad_units[] = {{"def->metres_per_unit NaN", NAN},           {"def->metres_per_unit inf", INFINITY},
                         {"def->metres_per_unit -inf", -INFINITY},    {"def->metres_per_unit negative", -0.01f},
                         {"def->metres_per_unit tiny (1e-7)", 1e-7f}, {"def->metres_per_unit huge (1e7)", 1e7f}};
        size_t i;
        for (i = 0; i < sizeof bad_units / sizeof bad_units[0]; ++i) {
            CASE(f->function, "%s", bad_units[i].name) {
                nl_mesh_def def = *valid;
                def.metres_per_unit = bad_units[i].value;
                def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "metres_per_unit");
            }
        }
    }
    CASE(f->function, "def->up_axis 3") {
        nl_mesh_def def = *valid;
        def.up_axis = 3u;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "up_axis");
    }
    CASE(f->function, "def->up_axis huge (UINT32_MAX)") {
        nl_mesh_def def = *valid;
        def.up_axis = UINT32_MAX;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "up_axis");
    }
}

static const geometry_fields k_mesh_geometry = {
    GEOMETRY_FIELDS(nl_mesh_def), {k_tile_nan, k_tile_inf, k_tile_minus_inf}, "vertices[2]"};
static const def_case k_mesh_defs[] = {
    {"def->vertices beyond the limit (2e9)", INVALID, "vertices[1]", {SET_PTR(nl_mesh_def, vertices, k_tile_far)}},
    {"def->indices out of range (4)", INVALID, "indices[4]", {SET_PTR(nl_mesh_def, indices, k_tile_index_4)}},
    {"def->indices out of range (UINT32_MAX)",
     INVALID,
     "indices[4]",
     {SET_PTR(nl_mesh_def, indices, k_tile_index_huge)}},
    {"def->indices degenerate (every triangle)", INVALID, "degenerate", {SET_PTR(nl_mesh_def, indices, k_tile_flat)}},
    {"def->triangle_count 0", INVALID, "triangle_count", {SET_U32(nl_mesh_def, triangle_count, 0u)}},
    {"def->triangle_count huge (indices NULL: not read)",
     INVALID,
     "indices",
     {SET_PTR(nl_mesh_def, indices, NULL), SET_U32(nl_mesh_def, triangle_count, UINT32_MAX)}},
    {"def->flags unknown (0x80000000)", INVALID, "flags", {SET_U32(nl_mesh_def, flags, 0x80000000u)}},
};

static void group_mesh_add(void) {
    static const def_function add = {"nl_mesh_add", mesh_add_call, sizeof(nl_mesh_id), remove_mesh_out, 0, 0, 0};
    const nl_mesh_def valid = tile_def();
    nl_mesh_def movable = valid;
    movable.flags = NL_MESH_MOVABLE;
    mesh_def_cases(&add, &valid);
    geometry_cases("nl_mesh_add", &valid, sizeof valid, &k_mesh_geometry);
    def_cases("nl_mesh_add", &valid, sizeof valid, k_mesh_defs, sizeof k_mesh_defs / sizeof *k_mesh_defs, def_refuses,
              def_accepts);
    bad_def_transforms("nl_mesh_add", " (movable)", &movable, def_refuses);
}

/* OBJ loads: a file and the same text in memory; g_obj_text is what the memory load reads. */

static const char* g_obj_text;
static size_t g_obj_length;
static nl_status add_obj_file(nl_world* world, const void* def, void* out) {
    return nl_mesh_add_obj_file(world, g_obj_path, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}
static nl_status add_obj_memory(nl_world* world, const void* def, void* out) {
    return nl_mesh_add_obj_memory(world, g_obj_text, g_obj_length, (const nl_mesh_def*)def, (nl_mesh_id*)out);
}
static const def_function k_obj_file = {
    "nl_mesh_add_obj_file", add_obj_file, sizeof(nl_mesh_id), remove_mesh_out, 1, 0, 0};
static const def_function k_obj_memory = {
    "nl_mesh_add_obj_memory", add_obj_memory, sizeof(nl_mesh_id), remove_mesh_out, 1, 0, 0};

/* An OBJ def may set flags, transform and user_data only. */
static const def_case k_obj_defs[] = {
    {"def->vertices NULL (allowed: an OBJ def has no geometry)", ALLOWED, NULL, {SET_PTR(nl_mesh_def, vertices, NULL)}},
    {"def->vertices set (geometry in an OBJ def)", INVALID, "geometry", {SET_PTR(nl_mesh_def, vertices, k_tile)}},
    {"def->vertices NaN (geometry in an OBJ def)",
     INVALID,
     "geometry",
     {SET_PTR(nl_mesh_def, vertices, k_tile_nan), SET_U32(nl_mesh_def, vertex_count, 4u)}},
    {"def->vertices inf (geometry in an OBJ def)",
     INVALID,
     "geometry",
     {SET_PTR(nl_mesh_def, vertices, k_tile_inf), SET_U32(nl_mesh_def, vertex_count, 4u)}},
    {"def->vertex_count 0 (allowed: the default)", ALLOWED, NULL, {SET_U32(nl_mesh_def, vertex_count, 0u)}},
    {"def->vertex_count huge (geometry in an OBJ def)",
     INVALID,
     "geometry",
     {SET_U32(nl_mesh_def, vertex_count, UINT32_MAX)}},
    {"def->indices NULL (allowed: the default)", ALLOWED, NULL, {SET_PTR(nl_mesh_def, indices, NULL)}},
    {"def->indices set (geometry in an OBJ def)", INVALID, "geometry", {SET_PTR(nl_mesh_def, indices, k_tile_indices)}},
    {"def->triangle_count 0 (allowed: the default)", ALLOWED, NULL, {SET_U32(nl_mesh_def, triangle_count, 0u)}},
    {"def->triangle_count huge (geometry in an OBJ def)",
     INVALID,
     "geometry",
     {SET_U32(nl_mesh_def, triangle_count, UINT32_MAX)}},
};

/* Malformed text: non-finite numbers, faces past the vertices, no faces. */
typedef struct bad_obj {
    const char* what;
    const char* text;
    const char* needle;
} bad_obj;
static const bad_obj k_bad_objs[] = {
    {"text NaN coordinate", "v 0 0 0\nv 1 0 0\nv nan 0 1\nf 1 2 3\n", ":3:"},
    {"text inf coordinate", "v 0 0 0\nv 1 0 0\nv 1 inf 1\nf 1 2 3\n", ":3:"},
    {"text -inf coordinate", "v 0 0 0\nv -inf 0 0\nv 1 0 1\nf 1 2 3\n", ":2:"},
    {"text coordinate overflowing float (1e39)", "v 0 0 0\nv 1 0 0\nv 1 0 1e39\nf 1 2 3\n", ":3:"},
    {"text face index past the vertices", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 4\n",
     ":4: vertex index 4 is past the last one"},
    {"text face index huge", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 99999999999999999999\n", ":4:"},
    {"text no faces", "v 0 0 0\nv 1 0 0\n", "face"},
};

/* `from_file`: the text goes to bad.obj and the file is loaded, else it is loaded from memory. */
static void bad_obj_cases(const char* function, int from_file) {
    char path[160];
    size_t i;
    snprintf(path, sizeof path, "%s/bad.obj", g_tmp);
    for (i = 0; i < sizeof k_bad_objs / sizeof *k_bad_objs; ++i) {
        CASE(function, "%s", k_bad_objs[i].what) {
            nl_mesh_id out;
            nl_status status;
            fill(&out, sizeof out);
            if (from_file) {
                write_file(path, k_bad_objs[i].text);
                status = nl_mesh_add_obj_file(A.world, path, NULL, &out);
            } else {
                status = nl_mesh_add_obj_memory(A.world, k_bad_objs[i].text, strlen(k_bad_objs[i].text), NULL, &out);
            }
            EXPECT_FAILURE(A.world, status, NL_STATUS_PARSE_ERROR, k_bad_objs[i].needle);
            EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        }
    }
}

static void obj_def_cases(const def_function* f) {
    const nl_mesh_def valid = nl_default_mesh_def();
    mesh_def_cases(f, &valid);
    def_cases(f->function, &valid, sizeof valid, k_obj_defs, sizeof k_obj_defs / sizeof *k_obj_defs, def_refuses,
              def_accepts);
}

static nl_status load_obj_at(const char* path, void* out) {
    return nl_mesh_add_obj_file(A.world, path, NULL, (nl_mesh_id*)out);
}

static void group_mesh_add_obj_file(void) {
    static const char* made[] = {"bad.obj"};
    make_tmp();
    bad_path_cases("nl_mesh_add_obj_file", load_obj_at, sizeof(nl_mesh_id), k_bad_paths, BAD_PATH_COUNT);
    CASE("nl_mesh_add_obj_file", "path huge (8000 characters)") {
        char* long_path = (char*)malloc(8001);
        nl_mesh_id out;
        nl_status status;
        if (!long_path) exit(2);
        memset(long_path, 'a', 8000);
        long_path[0] = '/';
        long_path[8000] = '\0';
        fill(&out, sizeof out);
        status = nl_mesh_add_obj_file(A.world, long_path, NULL, &out);
        EXPECT(
            status == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND) || status == (NL_STATUS_FAILURE | NL_STATUS_IO_ERROR),
            "returned 0x%08x (%s), expected NOT_FOUND or IO_ERROR", (unsigned)status, nl_status_string(status));
        EXPECT_FAILURE(A.world, status, status & NL_STATUS_DETAIL_MASK, "aaaa");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        free(long_path);
    }
    bad_obj_cases("nl_mesh_add_obj_file", 1);
    obj_def_cases(&k_obj_file);
    remove_tmp(made, 1);
}

static void group_mesh_add_obj_memory(void) {
    const size_t n = strlen(k_obj);
    const text_case texts[] = {
        {"data NULL (length 10)", NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data"},
        {"length huge (data NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data"},
        {"length 0 (no faces)", k_obj, 0, NL_STATUS_PARSE_ERROR, "face"},
        {"length 0 (data NULL: no faces)", NULL, 0, NL_STATUS_PARSE_ERROR, "face"},
        {"length short (the face cut to two corners)", k_obj, n - 5, NL_STATUS_PARSE_ERROR, ":5:"},
    };
    size_t i;
    g_obj_text = k_obj;
    g_obj_length = n;
    for (i = 0; i < sizeof texts / sizeof *texts; ++i) {
        CASE("nl_mesh_add_obj_memory", "%s", texts[i].what) {
            nl_mesh_id out;
            fill(&out, sizeof out);
            EXPECT_FAILURE(A.world, nl_mesh_add_obj_memory(A.world, texts[i].data, texts[i].length, NULL, &out),
                           texts[i].detail, texts[i].needle);
            EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
        }
    }
    CASE("nl_mesh_add_obj_memory", "data not NUL-terminated (allowed: exactly length bytes read)") {
        char* exact = (char*)malloc(n);
        if (!exact) exit(2);
        memcpy(exact, k_obj, n);
        g_obj_text = exact;
        g_def = &k_obj_memory;
        def_accepts(NULL);
        g_obj_text = k_obj;
        free(exact);
    }
    bad_obj_cases("nl_mesh_add_obj_memory", 0);
    obj_def_cases(&k_obj_memory);
}

/* The functions that take a mesh id. */
static float g_moved[16];
ID_CALL(mesh_remove_call, nl_mesh_id, nl_mesh_remove)
static nl_status mesh_set_transform_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_mesh_set_transform(w, AS(nl_mesh_id, id), g_moved);
}
ID_VALID_CALL(mesh_is_valid_call, nl_mesh_id, nl_mesh_is_valid)
static const id_function k_mesh_functions[] = {
    {"nl_mesh_remove", "mesh", NULL, 0, 0, 0, mesh_remove_call, 0},
    {"nl_mesh_set_transform", "mesh", NULL, 0, 0, 0, mesh_set_transform_call, 0},
    {"nl_mesh_is_valid", "mesh", NULL, 0, 0, 1, mesh_is_valid_call, 0},
    {"nl_mesh_get_info", "mesh", "out_info", sizeof(nl_mesh_info), 1, 0, mesh_get_info_call, 0},
};

static void mesh_id_cases(size_t which) {
    id_cases(&k_mesh_functions[which], RAW(A.mesh), RAW(A.stale_mesh), RAW(B.mesh));
}

static void group_mesh_remove(void) { mesh_id_cases(0); }

static void group_mesh_set_transform(void) {
    size_t i;
    int k;
    memcpy(g_moved, k_identity, sizeof g_moved);
    g_moved[13] = 0.5f;
    mesh_id_cases(1);
    for (k = 0; k < 2; ++k) {
        const nl_mesh_id mesh = k ? A.movable : A.mesh;
        const char* suffix = k ? " (movable)" : "";
        CASE("nl_mesh_set_transform", "transform NULL%s", suffix) {
            EXPECT_INVALID(A.world, nl_mesh_set_transform(A.world, mesh, NULL), "transform");
        }
        for (i = 0; i < BAD_TRANSFORM_COUNT; ++i) {
            CASE("nl_mesh_set_transform", "transform%s%s", k_bad_transforms[i].what, suffix) {
                float m[16];
                transform_from(&k_bad_transforms[i], m);
                EXPECT_INVALID(A.world, nl_mesh_set_transform(A.world, mesh, m),
                               transform_needle(&k_bad_transforms[i]));
            }
        }
    }
}

static void group_mesh_is_valid(void) { mesh_id_cases(2); }

static nl_status mesh_info_into(void* out) { return nl_mesh_get_info(A.world, A.mesh, (nl_mesh_info*)out); }

static void group_mesh_get_info(void) {
    mesh_id_cases(3);
    out_sizes("nl_mesh_get_info", "out_info", sizeof(nl_mesh_info), mesh_info_into);
}

static void group_world_get_meshes(void) {
    world_list_cases("nl_world_get_meshes", "out_ids", sizeof(nl_mesh_id), 4u, get_meshes);
}

/* Batches of three items, the last one made bad: nothing is written for any. `batch` calls the
   function with (items, count, out) for the case's items. */
typedef nl_status batch_fn(nl_world* world, const void* items, uint32_t count, void* out);
typedef struct batch_function {
    const char* function;
    const char* items_name; /* "rays" */
    const char* out_name;
    size_t item_size, out_size; /* per item */
    batch_fn* call;
} batch_function;

/* The pointers NULL, the counts 0 and huge (never read through a NULL pointer, nor past the first
   item when the output is NULL). */
static void batch_pointer_cases(const batch_function* f, const void* valid) {
    unsigned char out[256];
    CASE(f->function, "world NULL") {
        fill(out, sizeof out);
        EXPECT_INVALID(NULL, f->call(NULL, valid, 3, out), "world");
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "%s NULL", f->items_name) {
        fill(out, sizeof out);
        EXPECT_INVALID(A.world, f->call(A.world, NULL, 3, out), f->items_name);
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "count huge (%s NULL: not read)", f->items_name) {
        fill(out, sizeof out);
        EXPECT_INVALID(A.world, f->call(A.world, NULL, UINT32_MAX, out), f->items_name);
        EXPECT_UNTOUCHED(out, sizeof out, f->out_name);
    }
    CASE(f->function, "%s NULL", f->out_name) {
        EXPECT_INVALID(A.world, f->call(A.world, valid, 3, NULL), f->out_name);
    }
    CASE(f->function, "count huge (%s NULL: the items past the first not read)", f->out_name) {
        EXPECT_INVALID(A.world, f->call(A.world, valid, UINT32_MAX, NULL), f->out_name);
    }
    CASE(f->function, "count 0 (allowed, with %s and %s NULL)", f->items_name, f->out_name) {
        EXPECT_OK(f->call(A.world, NULL, 0, NULL));
    }
}

/* The batch of three items made bad: refused naming "ITEMS[2].FIELD", nothing written. */
static const batch_function* g_batch;
static void batch_refuses(const void* items, nl_status detail, const char* field) {
    unsigned char out[256];
    char needle[64];
    snprintf(needle, sizeof needle, "%s[2].%s", g_batch->items_name, field);
    fill(out, sizeof out);
    EXPECT_FAILURE(A.world, g_batch->call(A.world, items, 3, out), detail, needle);
    EXPECT_UNTOUCHED(out, sizeof out, g_batch->out_name);
}

/* One more bad value of a field of item 2. */
typedef struct extra_value {
    const char* what; /* "rays->max_distance 0" */
    const char* field;
    size_t offset; /* in the item */
    float value;
} extra_value;

/* Each bad float of each field of item 2, and the extra values. */
static void batch_float_cases(const batch_function* f, const void* valid, const float_field* fields, size_t field_count,
                              const extra_value* extra, size_t extra_count) {
    float_field in_item_2[4];
    size_t i;
    g_batch = f;
    for (i = 0; i < field_count && i < 4; ++i) {
        in_item_2[i] = fields[i];
        in_item_2[i].offset += 2 * f->item_size;
    }
    bad_float_fields(f->function, f->items_name, valid, 3 * f->item_size, in_item_2, i, batch_refuses);
    for (i = 0; i < extra_count; ++i) {
        CASE(f->function, "%s", extra[i].what) {
            aligned_buffer items;
            copy_def(&items, valid, 3 * f->item_size);
            memcpy(items.bytes + 2 * f->item_size + extra[i].offset, &extra[i].value, sizeof(float));
            batch_refuses(items.bytes, NL_STATUS_INVALID_ARGUMENT, extra[i].field);
        }
    }
}

static nl_status cast_rays(nl_world* w, const void* items, uint32_t count, void* out) {
    return nl_world_cast_rays(w, (const nl_ray*)items, count, (nl_ray_hit*)out);
}
static nl_status segments_blocked(nl_world* w, const void* items, uint32_t count, void* out) {
    return nl_world_segments_blocked(w, (const nl_segment*)items, count, (uint8_t*)out);
}

static nl_status cast_known_rays(void* out, uint32_t* written) {
    const nl_ray rays[3] = {{{-6, 5, 0}, {0, -1, 0}, 100}, {{6, 5, 0}, {0, -1, 0}, 100}, {{42, 5, 0}, {0, -1, 0}, 100}};
    *written = 3u;
    return nl_world_cast_rays(A.world, rays, 3, (nl_ray_hit*)out);
}

static void group_world_cast_rays(void) {
    static const batch_function f = {"nl_world_cast_rays", "rays",   "out_hits", sizeof(nl_ray),
                                     sizeof(nl_ray_hit),   cast_rays};
    const nl_ray valid[3] = {
        {{-6, 5, 0}, {0, -1, 0}, 100}, {{6, 5, 0}, {0, -1, 0}, 100}, {{42, 5, 0}, {0, -1, 0}, 100}};
    static const float_field fields[] = {FLOAT_FIELD(nl_ray, origin, 3), FLOAT_FIELD(nl_ray, direction, 3)};
    static const extra_value extra[] = {
        {"rays->origin beyond the limit (2e9)", "origin", offsetof(nl_ray, origin[1]), 2.0e9f},
        {"rays->direction zero", "direction", offsetof(nl_ray, direction[1]), 0.0f},
        {"rays->max_distance NaN", "max_distance", offsetof(nl_ray, max_distance), NAN},
        {"rays->max_distance -inf", "max_distance", offsetof(nl_ray, max_distance), -INFINITY},
        {"rays->max_distance 0", "max_distance", offsetof(nl_ray, max_distance), 0.0f},
        {"rays->max_distance negative (-1)", "max_distance", offsetof(nl_ray, max_distance), -1.0f},
    };
    batch_pointer_cases(&f, valid);
    batch_float_cases(&f, valid, fields, 2, extra, sizeof extra / sizeof *extra);
    CASE("nl_world_cast_rays", "rays->max_distance inf (allowed)") {
        nl_ray rays[3];
        nl_ray_hit hits[3];
        hits[0] = nl_ray_hit_init();
        memcpy(rays, valid, sizeof rays);
        rays[2].max_distance = INFINITY;
        EXPECT_OK(nl_world_cast_rays(A.world, rays, 3, hits));
        EXPECT(hits[0].hit == 1 && hits[2].hit == 1, "the rays down onto the platform and the lift missed");
    }
    out_element_sizes("nl_world_cast_rays", "out_hits", sizeof(nl_ray_hit), cast_known_rays);
}

static void group_world_segments_blocked(void) {
    static const batch_function f = {"nl_world_segments_blocked", "segments", "out_blocked",
                                     sizeof(nl_segment),          1,          segments_blocked};
    const nl_segment valid[3] = {{{-6, 5, 0}, {-6, -5, 0}}, {{-6, 5, 0}, {6, 5, 0}}, {{42, 5, 0}, {42, -5, 0}}};
    static const float_field fields[] = {FLOAT_FIELD(nl_segment, from, 3), FLOAT_FIELD(nl_segment, to, 3)};
    static const extra_value extra[] = {
        {"segments->to beyond the limit (-2e9)", "to", offsetof(nl_segment, to[1]), -2.0e9f}};
    batch_pointer_cases(&f, valid);
    batch_float_cases(&f, valid, fields, 2, extra, 1);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"mesh_add", group_mesh_add},
    {"mesh_add_obj_file", group_mesh_add_obj_file},
    {"mesh_add_obj_memory", group_mesh_add_obj_memory},
    {"mesh_remove", group_mesh_remove},
    {"mesh_set_transform", group_mesh_set_transform},
    {"mesh_is_valid", group_mesh_is_valid},
    {"mesh_get_info", group_mesh_get_info},
    {"world_get_meshes", group_world_get_meshes},
    {"world_cast_rays", group_world_cast_rays},
    {"world_segments_blocked", group_world_segments_blocked},
};
const hostile_part hostile_level_part = {k_groups, sizeof k_groups / sizeof *k_groups};
