/*
 * Level geometry (navlink.h): meshes added from arrays and OBJ text or files, their info, lists, ids,
 * transforms and refusals, on the floor of floor_scene.h; dungeon.obj from the shared levels.
 */
#include "abi_test.h"
#include "floor_scene.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void mesh_add_and_info(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u}, moved = {0u, 0u};
    nl_mesh_info info;
    float m[16];
    int k;

    def = nl_default_mesh_def();
    CHECK(def.size == sizeof(nl_mesh_def));
    CHECK(def.vertices == NULL && def.indices == NULL && def.transform == NULL);
    CHECK(def.vertex_count == 0 && def.triangle_count == 0 && def.vertex_stride == 0);
    CHECK(def.flags == 0 && def.user_data == 0);

    def = floor_def();
    def.user_data = 0x0123456789abcdefull;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    CHECK(id.index1 != 0u);
    CHECK(nl_mesh_is_valid(world, id) == 1);
    CHECK(mesh_count(world) == 1);

    memset(&info, 0xab, sizeof info);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.size == sizeof info);
    CHECK(info.vertex_count == 4);
    CHECK(info.triangle_count == 2);
    CHECK(info.degenerate_triangle_count == 0);
    CHECK(info.flags == 0);
    CHECK(memcmp(info.transform, k_identity, sizeof k_identity) == 0);
    CHECK(info.bounds_min[0] == -10.0f && info.bounds_min[1] == 1.0f && info.bounds_min[2] == -10.0f);
    CHECK(info.bounds_max[0] == 10.0f && info.bounds_max[1] == 1.0f && info.bounds_max[2] == 10.0f);
    CHECK(info.user_data == 0x0123456789abcdefull);

    /* With a transform and a flag: both reported, bounds in world space. */
    translation(m, 100.0f, 2.0f, -3.0f);
    def = floor_def();
    def.transform = m;
    def.flags = NL_MESH_MOVABLE;
    def.user_data = 7u;
    CHECK_OK(nl_mesh_add(world, &def, &moved));
    CHECK(!same_id(id, moved));
    m[12] = 12345.0f; /* the transform was copied */
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, moved, &info));
    CHECK(info.flags == NL_MESH_MOVABLE);
    CHECK(info.transform[12] == 100.0f && info.transform[13] == 2.0f && info.transform[14] == -3.0f);
    CHECK(info.transform[0] == 1.0f && info.transform[5] == 1.0f && info.transform[10] == 1.0f &&
          info.transform[15] == 1.0f);
    CHECK(info.bounds_min[0] == 90.0f && info.bounds_min[1] == 3.0f && info.bounds_min[2] == -13.0f);
    CHECK(info.bounds_max[0] == 110.0f && info.bounds_max[1] == 3.0f && info.bounds_max[2] == 7.0f);
    CHECK(info.user_data == 7u);
    CHECK(mesh_count(world) == 2);

    /* get_info failures write nothing. */
    memset(&info, 0xab, sizeof info);
    info.size = 0;
    CHECK_INVALID(nl_mesh_get_info(world, id, &info), "size");
    CHECK(info.vertex_count == 0xabababab);
    info.size = sizeof info;
    CHECK_INVALID(nl_mesh_get_info(world, id, NULL), "out_info");
    CHECK_INVALID(nl_mesh_get_info(NULL, id, &info), "world");
    CHECK(info.vertex_count == 0xabababab);

    /* Interleaved position + normal (stride 24); the normal slots hold NaN, which must never be read. */
    {
        float interleaved[8 * 6];
        /* Vertex k has x, y, z from bits 0, 1, 2 of k; faces wound counter-clockwise seen from outside. */
        static const uint32_t box[36] = {2, 6, 7, 2, 7, 3,  /* top, +y */
                                         0, 1, 5, 0, 5, 4,  /* bottom, -y */
                                         1, 3, 7, 1, 7, 5,  /* +x */
                                         0, 4, 6, 0, 6, 2,  /* -x */
                                         4, 5, 7, 4, 7, 6,  /* +z */
                                         0, 2, 3, 0, 3, 1}; /* -z */
        nl_mesh_id box_id = {0u, 0u};
        for (k = 0; k < 8; ++k) {
            interleaved[6 * k + 0] = (k & 1) ? 3.0f : 1.0f;
            interleaved[6 * k + 1] = (k & 2) ? 6.0f : 2.0f;
            interleaved[6 * k + 2] = (k & 4) ? -1.0f : -5.0f;
            interleaved[6 * k + 3] = NAN;
            interleaved[6 * k + 4] = INFINITY;
            interleaved[6 * k + 5] = NAN;
        }
        def = nl_default_mesh_def();
        def.vertices = interleaved;
        def.vertex_count = 8;
        def.vertex_stride = 6 * sizeof(float);
        def.indices = box;
        def.triangle_count = 12;
        CHECK_OK(nl_mesh_add(world, &def, &box_id));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, box_id, &info));
        CHECK(info.vertex_count == 8 && info.triangle_count == 12 && info.degenerate_triangle_count == 0);
        CHECK(info.bounds_min[0] == 1.0f && info.bounds_min[1] == 2.0f && info.bounds_min[2] == -5.0f);
        CHECK(info.bounds_max[0] == 3.0f && info.bounds_max[1] == 6.0f && info.bounds_max[2] == -1.0f);
        {
            /* Straight down from y = 10 onto the box top (y = 6), and sideways onto its +x face. */
            nl_ray r[2];
            nl_ray_hit h[2];
            h[0] = nl_ray_hit_init();
            r[0] = down_ray(2.0f, -3.0f, 10.0f, INFINITY);
            r[1] = down_ray(8.0f, -2.0f, 3.0f, INFINITY);
            r[1].direction[0] = -2.0f, r[1].direction[1] = 0.0f;
            CHECK_OK(nl_world_cast_rays(world, r, 2, h));
            CHECK(h[0].hit == 1 && same_id(h[0].mesh, box_id) && h[0].triangle < 2);
            CHECK_NEAR(h[0].distance, 4.0f, TOL);
            CHECK_NEAR(h[0].point[1], 6.0f, TOL);
            CHECK_NEAR(h[0].normal[1], 1.0f, TOL);
            CHECK(h[1].hit == 1 && same_id(h[1].mesh, box_id) && h[1].triangle >= 4 && h[1].triangle < 6);
            CHECK_NEAR(h[1].distance, 5.0f, TOL);
            CHECK_NEAR(h[1].point[0], 3.0f, TOL);
            CHECK_NEAR(h[1].normal[0], 1.0f, TOL);
        }
        CHECK_OK(nl_mesh_remove(world, box_id));
    }

    /* A stride that is not a multiple of 4 (13 bytes, unaligned floats) reads the same positions. */
    {
        unsigned char packed[4 * 13];
        nl_mesh_id odd = {0u, 0u};
        memset(packed, 0xff, sizeof packed); /* the padding byte is garbage */
        for (k = 0; k < 4; ++k) memcpy(packed + 13 * k, k_floor_vertices + 3 * k, 3 * sizeof(float));
        def = floor_def();
        def.vertices = (const float*)(const void*)packed;
        def.vertex_stride = 13;
        CHECK_OK(nl_mesh_add(world, &def, &odd));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, odd, &info));
        CHECK(info.bounds_min[0] == -10.0f && info.bounds_max[2] == 10.0f && info.bounds_max[1] == 1.0f);
        CHECK_OK(nl_mesh_remove(world, odd));
    }

    /* Arrays are copied: the caller's buffers may change after the call. */
    {
        float vertices[12];
        uint32_t indices[6];
        nl_mesh_id copied = {0u, 0u};
        nl_ray_hit h = nl_ray_hit_init();
        memcpy(vertices, k_floor_vertices, sizeof vertices);
        memcpy(indices, k_floor_indices, sizeof indices);
        def = floor_def();
        def.vertices = vertices;
        def.indices = indices;
        translation(m, 0.0f, 10.0f, 0.0f); /* floor at y = 11 */
        def.transform = m;
        CHECK_OK(nl_mesh_add(world, &def, &copied));
        memset(vertices, 0, sizeof vertices);
        memset(indices, 0, sizeof indices);
        {
            const nl_ray r = down_ray(0.5f, 0.25f, 20.0f, INFINITY);
            CHECK_OK(nl_world_cast_rays(world, &r, 1, &h));
            CHECK(h.hit == 1 && same_id(h.mesh, copied));
            CHECK_NEAR(h.distance, 9.0f, TOL);
        }
        CHECK_OK(nl_mesh_remove(world, copied));
    }
    nl_world_destroy(world);
}

static void degenerate_triangles(void) {
    nl_world* world = make_world(1);
    /* Input triangles: 0 repeated index, 1 real (floor tri 0), 2 collinear, 3 real (floor tri 1). */
    static const float vertices[] = {
        -10.0f, 1.0f,  -10.0f, -10.0f, 1.0f, 10.0f, 10.0f, 1.0f,
        10.0f,  10.0f, 1.0f,   -10.0f, 0.0f, 1.0f,  0.0f, /* 4: on the diagonal v0-v2 */
    };
    static const uint32_t indices[] = {0, 0, 1, 0, 1, 2, 0, 4, 2, 0, 2, 3};
    nl_mesh_def def = nl_default_mesh_def();
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h = nl_ray_hit_init();

    def.vertices = vertices;
    def.vertex_count = 5;
    def.indices = indices;
    def.triangle_count = 4;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.triangle_count == 2);
    CHECK(info.degenerate_triangle_count == 2);
    CHECK(info.vertex_count == 5);
    /* Hits report the input triangle index, counting the skipped ones. */
    h = cast_down(world, -2.0f, 3.0f); /* z > x: input triangle 1 */
    CHECK(h.hit == 1 && h.triangle == 1);
    h = cast_down(world, 3.0f, -2.0f); /* z < x: input triangle 3 */
    CHECK(h.hit == 1 && h.triangle == 3);
    /* The same through a movable mesh's instance. */
    {
        nl_mesh_id movable = {0u, 0u};
        float m[16];
        translation(m, 0.0f, 1.0f, 0.0f);
        def.flags = NL_MESH_MOVABLE;
        def.transform = m;
        CHECK_OK(nl_mesh_add(world, &def, &movable));
        info.size = sizeof info;
        CHECK_OK(nl_mesh_get_info(world, movable, &info));
        CHECK(info.triangle_count == 2 && info.degenerate_triangle_count == 2);
        h = cast_down(world, -2.0f, 3.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, movable) && h.triangle == 1);
        h = cast_down(world, 3.0f, -2.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, movable) && h.triangle == 3);
        CHECK_OK(nl_mesh_remove(world, movable));
        def.flags = 0;
        def.transform = NULL;
    }

    /* Every triangle degenerate: nothing registered. */
    {
        nl_mesh_id untouched = {77u, 77u};
        def.triangle_count = 1; /* only {0, 0, 1} */
        CHECK_INVALID(nl_mesh_add(world, &def, &untouched), "def->indices: all 1 triangles are degenerate");
        CHECK(untouched.index1 == 77u && untouched.revision == 77u);
        CHECK(mesh_count(world) == 1);
    }
    /* From an OBJ, the same failures in the file's words: its faces and its vertices by their `v`
       line's number, not a def the host never filled. */
    {
        static const char degenerate[] = "v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n";
        static const char far_away[] = "v 0 0 0\nv 2e9 0 0\nv 0 0 1\nf 1 2 3\n";
        nl_mesh_id untouched = {77u, 77u};
        CHECK_INVALID(nl_mesh_add_obj_memory(world, degenerate, sizeof degenerate - 1, NULL, &untouched),
                      "nl_mesh_add_obj_memory: data: faces: all 1 triangles are degenerate");
        CHECK_INVALID(nl_mesh_add_obj_memory(world, far_away, sizeof far_away - 1, NULL, &untouched),
                      "nl_mesh_add_obj_memory: data: vertex 2: x = 2e+09 is beyond the coordinate limit");
        CHECK(strstr(nl_get_last_error_message(), "def->") == NULL);
        CHECK(untouched.index1 == 77u && mesh_count(world) == 1);
    }
    nl_world_destroy(world);
}

/* One rejected nl_mesh_add: INVALID_ARGUMENT naming `needle`, nothing registered, out_id untouched. */
#define CHECK_REJECTED_MESH(world, def, needle) check_rejected_mesh((world), (def), (needle), __FILE__, __LINE__)
static void check_rejected_mesh(nl_world* world, const nl_mesh_def* def, const char* needle, const char* file,
                                int line) {
    const uint32_t before = mesh_count(world);
    nl_mesh_id out = {77u, 77u};
    const nl_status status = nl_mesh_add(world, def, &out);
    check_fail_at(status, NL_STATUS_INVALID_ARGUMENT, needle, "nl_mesh_add", file, line);
    check_at(out.index1 == 77u && out.revision == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(mesh_count(world) == before, file, line, "a mesh was registered on failure (%s)", needle);
}

static void mesh_rejections(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def;
    nl_mesh_id id = {0u, 0u};
    float vertices[12];
    uint32_t indices[6];
    float m[16];

    /* A zero-initialised def (not from nl_default_mesh_def) has size 0. */
    CHECK_INVALID(nl_mesh_add(world, &(nl_mesh_def){0}, &id), "size");
    CHECK(mesh_count(world) == 0);
    def = floor_def();
    CHECK_OK(nl_mesh_add(world, &def, &id)); /* one mesh present, so "unchanged" is not just "still zero" */

    memcpy(vertices, k_floor_vertices, sizeof vertices);
    memcpy(indices, k_floor_indices, sizeof indices);
    def = floor_def();
    def.vertices = vertices;
    def.indices = indices;

    vertices[4] = NAN; /* vertices[1].y */
    CHECK_REJECTED_MESH(world, &def, "vertices[1]");
    vertices[4] = 1.0f;
    vertices[8] = INFINITY; /* vertices[2].z */
    CHECK_REJECTED_MESH(world, &def, "vertices[2]");
    vertices[8] = -INFINITY;
    CHECK_REJECTED_MESH(world, &def, "vertices[2]");
    vertices[8] = 10.0f;

    indices[4] = 4; /* == vertex_count */
    CHECK_REJECTED_MESH(world, &def, "indices[4]");
    indices[4] = UINT32_MAX;
    CHECK_REJECTED_MESH(world, &def, "indices[4]");
    indices[4] = 2;

    def.vertices = NULL;
    CHECK_REJECTED_MESH(world, &def, "vertices");
    def.vertices = vertices;
    def.indices = NULL;
    CHECK_REJECTED_MESH(world, &def, "indices");
    def.indices = indices;
    def.vertex_count = 0;
    CHECK_REJECTED_MESH(world, &def, "vertex_count");
    def.vertex_count = 4;
    def.triangle_count = 0;
    CHECK_REJECTED_MESH(world, &def, "triangle_count");
    def.triangle_count = 2;
    def.vertex_stride = 8;
    CHECK_REJECTED_MESH(world, &def, "vertex_stride");
    def.vertex_stride = 0;
    def.flags = 0x80u;
    CHECK_REJECTED_MESH(world, &def, "flags");
    def.flags = NL_MESH_MOVABLE | 0x100u;
    CHECK_REJECTED_MESH(world, &def, "flags");
    def.flags = 0;
    def.size = 0;
    CHECK_REJECTED_MESH(world, &def, "size");
    def.size = (uint32_t)offsetof(nl_mesh_def, user_data); /* short of the first release's def */
    CHECK_REJECTED_MESH(world, &def, "size");
    def.size = sizeof def;

    /* Transforms: non-affine (last row not 0 0 0 1), singular, non-finite. */
    def.transform = m;
    memcpy(m, k_identity, sizeof m);
    m[3] = 0.5f; /* row 3, column 0 */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[15] = 2.0f;
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[5] = 0.0f; /* flattens Y */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[0] = 1.0f, m[1] = 2.0f, m[4] = 2.0f, m[5] = 4.0f; /* two parallel columns */
    CHECK_REJECTED_MESH(world, &def, "transform");
    memset(m, 0, sizeof m);
    m[15] = 1.0f;
    CHECK_REJECTED_MESH(world, &def, "transform");
    memcpy(m, k_identity, sizeof m);
    m[13] = NAN;
    CHECK_REJECTED_MESH(world, &def, "transform");
    m[13] = INFINITY;
    CHECK_REJECTED_MESH(world, &def, "transform");
    def.flags = NL_MESH_MOVABLE; /* the movable path validates as well */
    CHECK_REJECTED_MESH(world, &def, "transform");
    def.transform = NULL;

    /* Null pointers. */
    {
        nl_mesh_id out = {77u, 77u};
        CHECK_INVALID(nl_mesh_add(world, NULL, &out), "def");
        CHECK_INVALID(nl_mesh_add(world, &def, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add(NULL, &def, &out), "world");
        CHECK(out.index1 == 77u && out.revision == 77u);
    }
    CHECK(mesh_count(world) == 1);
    nl_world_destroy(world);
}

static void get_meshes(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id ids[3], out[5];
    uint32_t count = 0xdeadbeefu;
    int found[3] = {0, 0, 0};
    uint32_t i, j;

    CHECK_OK(nl_world_get_meshes(world, NULL, 0, &count));
    CHECK(count == 0);
    for (i = 0; i < 3; ++i) {
        def.user_data = i;
        CHECK_OK(nl_mesh_add(world, &def, &ids[i]));
    }

    count = 0xdeadbeefu;
    CHECK_OK(nl_world_get_meshes(world, NULL, 0, &count)); /* a count query succeeds */
    CHECK(count == 3);
    memset(out, 0xcd, sizeof out);
    count = 0;
    CHECK_FAIL(nl_world_get_meshes(world, out, 2, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 3);
    CHECK(all_bytes(out, sizeof out, 0xcd)); /* nothing written */

    count = 0;
    CHECK_OK(nl_world_get_meshes(world, out, 3, &count));
    CHECK(count == 3);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (same_id(out[i], ids[j])) ++found[j];
        }
    }
    CHECK(found[0] == 1 && found[1] == 1 && found[2] == 1);

    memset(out, 0xcd, sizeof out);
    CHECK_OK(nl_world_get_meshes(world, out, 5, &count));
    CHECK(count == 3);
    CHECK(all_bytes(&out[3], 2 * sizeof out[0], 0xcd)); /* only `count` entries written */

    CHECK_OK(nl_mesh_remove(world, ids[1]));
    CHECK_OK(nl_world_get_meshes(world, out, 5, &count));
    CHECK(count == 2);
    CHECK((same_id(out[0], ids[0]) && same_id(out[1], ids[2])) || (same_id(out[0], ids[2]) && same_id(out[1], ids[0])));

    count = 0xdeadbeefu;
    CHECK_INVALID(nl_world_get_meshes(world, NULL, 1, &count), "out_ids");
    CHECK_INVALID(nl_world_get_meshes(world, out, 5, NULL), "out_count");
    CHECK_INVALID(nl_world_get_meshes(NULL, out, 5, &count), "world");
    nl_world_destroy(world);
}

static void stale_ids(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u}, reused = {0u, 0u}, other = {0u, 0u};
    const nl_mesh_id null_id = {0u, 0u};
    nl_mesh_info info;
    float m[16];

    translation(m, 0.0f, 1.0f, 0.0f);
    CHECK_OK(nl_mesh_add(world, &def, &other));
    CHECK_OK(nl_mesh_add(world, &def, &id));
    CHECK(nl_mesh_is_valid(world, id) == 1);
    CHECK_OK(nl_mesh_remove(world, id));
    CHECK(nl_mesh_is_valid(world, id) == 0);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS); /* a stale id is an answer, not an error */
    CHECK_FAIL(nl_mesh_remove(world, id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    memset(&info, 0xab, sizeof info);
    info.size = sizeof info;
    CHECK_FAIL(nl_mesh_get_info(world, id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK(info.vertex_count == 0xabababab);
    CHECK_FAIL(nl_mesh_set_transform(world, id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");
    CHECK(mesh_count(world) == 1);

    /* The null id. */
    CHECK(nl_mesh_is_valid(world, null_id) == 0);
    CHECK_FAIL(nl_mesh_remove(world, null_id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    CHECK_FAIL(nl_mesh_get_info(world, null_id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK_FAIL(nl_mesh_set_transform(world, null_id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");

    /* Ids that were never issued. */
    {
        const nl_mesh_id far = {1000u, 1u}, wrong_revision = {other.index1, other.revision + 1u};
        const nl_mesh_id zero_generation = {other.index1, 0u};
        CHECK(nl_mesh_is_valid(world, far) == 0);
        CHECK(nl_mesh_is_valid(world, wrong_revision) == 0);
        CHECK(nl_mesh_is_valid(world, zero_generation) == 0);
        CHECK_FAIL(nl_mesh_remove(world, far), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
        CHECK_FAIL(nl_mesh_remove(world, wrong_revision), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
        CHECK(nl_mesh_is_valid(world, other) == 1);
    }

    /* A new mesh may take the removed slot; the old id stays stale and cannot touch it. */
    def.user_data = 42u;
    CHECK_OK(nl_mesh_add(world, &def, &reused));
    CHECK(!same_id(reused, id));
    CHECK_MSG(reused.index1 == id.index1, "slot not reused (old {%u,%u}, new {%u,%u}); the reuse checks are vacuous",
              (unsigned)id.index1, (unsigned)id.revision, (unsigned)reused.index1, (unsigned)reused.revision);
    CHECK(nl_mesh_is_valid(world, id) == 0);
    CHECK(nl_mesh_is_valid(world, reused) == 1);
    CHECK_FAIL(nl_mesh_remove(world, id), NL_STATUS_INVALID_HANDLE, "nl_mesh_remove");
    CHECK_FAIL(nl_mesh_set_transform(world, id, m), NL_STATUS_INVALID_HANDLE, "nl_mesh_set_transform");
    CHECK_FAIL(nl_mesh_get_info(world, id, &info), NL_STATUS_INVALID_HANDLE, "nl_mesh_get_info");
    CHECK(nl_mesh_is_valid(world, reused) == 1);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, reused, &info));
    CHECK(info.user_data == 42u && info.transform[13] == 0.0f);
    CHECK(mesh_count(world) == 2);

    /* A ray hitting the reused slot reports the new id. */
    CHECK_OK(nl_mesh_remove(world, other));
    {
        const nl_ray_hit h = cast_down(world, 1.0f, 2.0f);
        CHECK(h.hit == 1 && same_id(h.mesh, reused));
    }
    CHECK(nl_mesh_is_valid(NULL, reused) == 0);
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_INVALID(nl_mesh_remove(NULL, reused), "world");
    CHECK_INVALID(nl_mesh_set_transform(NULL, reused, m), "world");
    CHECK_INVALID(nl_mesh_set_transform(world, reused, NULL), "transform");
    nl_world_destroy(world);
}

static void move(uint32_t flags) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h = nl_ray_hit_init();
    float m[16];

    def.flags = flags;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.distance, 4.0f, TOL);

    /* Up by 2: the floor is at y = 3. */
    translation(m, 0.0f, 2.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 1);
    CHECK_NEAR(h.distance, 2.0f, TOL);
    CHECK_NEAR(h.point[1], 3.0f, TOL);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.transform[13] == 2.0f);
    CHECK(info.bounds_min[1] == 3.0f && info.bounds_max[1] == 3.0f);
    CHECK(info.flags == flags);

    /* Sideways by 30 in x: the old place is empty, the new one is hit. */
    translation(m, 30.0f, 0.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 0);
    h = cast_down(world, 30.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id));
    CHECK_NEAR(h.distance, 4.0f, TOL);
    CHECK_NEAR(h.point[0], 30.5f, TOL);

    /* Turned upside down (180 degrees about X) and scaled by 2 in x: normal -Y, the floor at y = -1,
       reaching x = 20. The world point (15, -1, 0.25) is object (7.5, 1, -0.25): triangle 1. */
    memcpy(m, k_identity, sizeof m);
    m[0] = 2.0f;
    m[5] = -1.0f;
    m[10] = -1.0f;
    CHECK_OK(nl_mesh_set_transform(world, id, m));
    h = cast_down(world, 15.0f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 1);
    CHECK_NEAR(h.distance, 6.0f, TOL);
    CHECK_NEAR(h.point[1], -1.0f, TOL);
    CHECK_NEAR(h.normal[0], 0.0f, TOL);
    CHECK_NEAR(h.normal[1], -1.0f, TOL);
    CHECK_NEAR(h.normal[2], 0.0f, TOL);
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.bounds_min[0] == -20.0f && info.bounds_max[0] == 20.0f && info.bounds_min[1] == -1.0f);

    /* A rejected transform changes nothing. */
    memcpy(m, k_identity, sizeof m);
    m[7] = 1.0f; /* row 3, column 1 */
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    m[7] = 0.0f;
    m[10] = 0.0f; /* singular */
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    m[10] = 1.0f;
    m[14] = NAN;
    CHECK_INVALID(nl_mesh_set_transform(world, id, m), "transform");
    CHECK_INVALID(nl_mesh_set_transform(world, id, NULL), "transform");
    h = cast_down(world, 15.0f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.point[1], -1.0f, TOL);
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.transform[0] == 2.0f && info.transform[5] == -1.0f && info.transform[14] == 0.0f);

    /* Back to identity, then removal. */
    CHECK_OK(nl_mesh_set_transform(world, id, k_identity));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    CHECK_NEAR(h.distance, 4.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, id));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 0);
    nl_world_destroy(world);
}

static void move_movable(void) { move(NL_MESH_MOVABLE); }

static void move_static(void) { move(0u); }

/* A static and a movable mesh together: each hit resolves to the right id after edits. */
static void mixed_scene(void) {
    nl_world* world = make_world(2);
    nl_mesh_def def = floor_def();
    nl_mesh_id a = {0u, 0u}, b = {0u, 0u}, c = {0u, 0u};
    float m[16];
    nl_ray_hit h = nl_ray_hit_init();

    CHECK_OK(nl_mesh_add(world, &def, &a)); /* static, y = 1 */
    translation(m, 0.0f, 2.0f, 0.0f);
    def.transform = m;
    def.flags = NL_MESH_MOVABLE;
    CHECK_OK(nl_mesh_add(world, &def, &b)); /* movable, y = 3 */
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, b));
    CHECK_NEAR(h.point[1], 3.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, b));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, a));
    CHECK_NEAR(h.point[1], 1.0f, TOL);
    translation(m, 0.0f, 1.0f, 0.0f);
    def.flags = 0; /* static, y = 2, may take b's slot */
    CHECK_OK(nl_mesh_add(world, &def, &c));
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, c));
    CHECK_NEAR(h.point[1], 2.0f, TOL);
    CHECK_OK(nl_mesh_remove(world, a));
    translation(m, 0.0f, -3.0f, 0.0f);
    CHECK_OK(nl_mesh_set_transform(world, c, m)); /* y = -2 */
    h = cast_down(world, 0.5f, 0.25f);
    CHECK(h.hit == 1 && same_id(h.mesh, c));
    CHECK_NEAR(h.point[1], -2.0f, TOL);
    nl_world_destroy(world);
}

static const char k_quad_obj[] = FLOOR_QUAD_OBJ;

#define CHECK_PARSE_ERROR(world, text, length) check_parse_error((world), (text), (length), __FILE__, __LINE__)
static void check_parse_error(nl_world* world, const char* text, size_t length, const char* file, int line) {
    const uint32_t before = mesh_count(world);
    nl_mesh_id out = {77u, 77u};
    const nl_status status = nl_mesh_add_obj_memory(world, text, length, NULL, &out);
    check_at(status == (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR) && nl_get_last_status() == status &&
                 strstr(nl_get_last_error_message(), "nl_mesh_add_obj_memory") != NULL,
             file, line, "OBJ text gave 0x%08x (%s), expected a parse error: \"%.*s\"", (unsigned)status,
             nl_status_string(status), (int)(length > 60 ? 60 : length), text ? text : "");
    check_at(out.index1 == 77u && out.revision == 77u && mesh_count(world) == before, file, line,
             "a malformed OBJ registered something");
}

static void obj(void) {
    nl_world* world = make_world(1);
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    nl_ray_hit h = nl_ray_hit_init();

    CHECK_OK(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), NULL, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK(info.vertex_count == 4);
    CHECK(info.triangle_count == 2); /* the quad, fan-triangulated */
    CHECK(info.degenerate_triangle_count == 0);
    CHECK(info.bounds_min[0] == -10.0f && info.bounds_max[2] == 10.0f && info.bounds_min[1] == 1.0f);
    h = cast_down(world, -2.0f, 3.0f); /* fan (1 2 3), (1 3 4): the same triangles as the floor */
    CHECK(h.hit == 1 && same_id(h.mesh, id) && h.triangle == 0);
    CHECK_NEAR(h.normal[1], 1.0f, TOL);
    h = cast_down(world, 3.0f, -2.0f);
    CHECK(h.hit == 1 && h.triangle == 1);
    CHECK_OK(nl_mesh_remove(world, id));

    /* The text is `length` bytes, not NUL-terminated: what follows is not read. */
    {
        char buffer[sizeof k_quad_obj + 16];
        memcpy(buffer, k_quad_obj, strlen(k_quad_obj));
        memcpy(buffer + strlen(k_quad_obj), "f 1 2 99\nf 7 8", 15); /* would be malformed */
        CHECK_OK(nl_mesh_add_obj_memory(world, buffer, strlen(k_quad_obj), NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.triangle_count == 2);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* Relative (negative) indices, a pentagon (3 triangles) and a triangle, CRLF line ends. */
    {
        static const char text[] =
            "v 0 0 0\r\nv 1 0 0\r\nv 1 0 1\r\nv 0.5 0 1.5\r\nv 0 0 1\r\n"
            "f -5 -1 -2 -3 -4\r\nf 1 3 2\r\n";
        CHECK_OK(nl_mesh_add_obj_memory(world, text, sizeof text - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 5 && info.triangle_count + info.degenerate_triangle_count == 4);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* Texture and normal indices are accepted (and ignored); several objects make one mesh. */
    {
        static const char with_vt_vn[] =
            "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nvt 0 0\nvn 0 1 0\n"
            "usemtl stone\ns off\nf 1/1/1 3/1/1 2/1/1\nl 1 2\n";
        static const char two_objects[] =
            "o a\nv 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 3\n"
            "o b\ng part\nv 0 1 0\nv 1 1 0\nv 1 1 1\nf 4 5 6\nf -3 -2 -1\n";
        CHECK_OK(nl_mesh_add_obj_memory(world, with_vt_vn, sizeof with_vt_vn - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 3 && info.triangle_count == 1);
        CHECK_OK(nl_mesh_remove(world, id));
        CHECK_OK(nl_mesh_add_obj_memory(world, two_objects, sizeof two_objects - 1, NULL, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.vertex_count == 6 && info.triangle_count + info.degenerate_triangle_count == 3);
        CHECK_OK(nl_mesh_remove(world, id));
    }

    /* A def's flags, transform and user_data apply. */
    {
        nl_mesh_def def = nl_default_mesh_def();
        float m[16];
        translation(m, 0.0f, 4.0f, 0.0f);
        def.transform = m;
        def.flags = NL_MESH_MOVABLE;
        def.user_data = 99u;
        CHECK_OK(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id));
        CHECK_OK(nl_mesh_get_info(world, id, &info));
        CHECK(info.flags == NL_MESH_MOVABLE && info.user_data == 99u && info.transform[13] == 4.0f);
        CHECK(info.bounds_min[1] == 5.0f);
        CHECK_OK(nl_mesh_remove(world, id));
        /* ... but not geometry, a bad size, or a bad transform. */
        def.vertex_count = 3;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "def");
        def.vertex_count = 0;
        def.size = 0;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "size");
        def.size = sizeof def;
        m[3] = 1.0f;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "transform");
        def.transform = NULL;
        def.flags = 0x40u;
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), &def, &id), "flags");
        CHECK(mesh_count(world) == 0);
    }

    /* Malformed text: a parse error, nothing registered. */
    {
        static const char out_of_range[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 99\n";
        static const char before_first[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf -9 1 2\n";
        static const char garbage[] = "this is not an OBJ file\n\x01\x02\x03 {}[] 12 34\n";
        static const char no_faces[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\n";
        static const char zero_index[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 0 1 2\n";
        static const char letter_index[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf a b c\n";
        static const char missing_texcoord[] = "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1/5 3/5 2/5\n";
        CHECK_PARSE_ERROR(world, zero_index, sizeof zero_index - 1);
        CHECK_PARSE_ERROR(world, letter_index, sizeof letter_index - 1);
        CHECK_PARSE_ERROR(world, missing_texcoord, sizeof missing_texcoord - 1);
        CHECK_PARSE_ERROR(world, out_of_range, sizeof out_of_range - 1);
        CHECK_PARSE_ERROR(world, before_first, sizeof before_first - 1);
        CHECK_PARSE_ERROR(world, garbage, sizeof garbage - 1);
        CHECK_PARSE_ERROR(world, no_faces, sizeof no_faces - 1);
        CHECK_PARSE_ERROR(world, "", 0);
        CHECK_PARSE_ERROR(world, NULL, 0);
        {
            /* A coordinate that is not a number must not load as 0. */
            static const char bad_number[] = "v abc 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 3\n";
            nl_mesh_id out = {0u, 0u};
            const nl_status st = nl_mesh_add_obj_memory(world, bad_number, sizeof bad_number - 1, NULL, &out);
            CHECK_THAT(
                st == (NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR),
                "nl_mesh_add_obj_memory: a coordinate that is not a number (\"v abc 0 0\") is a PARSE_ERROR, not 0");
            if (NL_SUCCEEDED(st)) nl_mesh_remove(world, out);
        }
    }

    /* Files: written next to the test, then read back. */
    {
        const char* path = "navlink_abi_test_quad.obj";
        FILE* f = fopen(path, "wb");
        CHECK(f != NULL);
        if (f) {
            fputs(k_quad_obj, f);
            fclose(f);
            id.index1 = 0;
            CHECK_OK(nl_mesh_add_obj_file(world, path, NULL, &id));
            CHECK(nl_mesh_is_valid(world, id) == 1);
            CHECK_OK(nl_mesh_get_info(world, id, &info));
            CHECK(info.vertex_count == 4 && info.triangle_count == 2);
            CHECK_OK(nl_mesh_remove(world, id));
            remove(path);
        }
    }
    {
        nl_mesh_id out = {77u, 77u};
        CHECK_FAIL(nl_mesh_add_obj_file(world, "no/such/dir/missing-level.obj", NULL, &out), NL_STATUS_NOT_FOUND,
                   "missing-level.obj");
        CHECK(out.index1 == 77u && out.revision == 77u);
        CHECK_FAIL(nl_mesh_add_obj_file(world, "", NULL, &out), NL_STATUS_NOT_FOUND, "nl_mesh_add_obj_file");
        /* A directory cannot be read as a file, and a file that fails while it is read (/proc/self/mem
           from offset 0: EIO) is an I/O error, not a parse error of the bytes read before. */
        CHECK_FAIL(nl_mesh_add_obj_file(world, ".", NULL, &out), NL_STATUS_IO_ERROR, "directory");
        {
            FILE* mem = fopen("/proc/self/mem", "rb");
            if (mem) {
                fclose(mem);
                CHECK_FAIL(nl_mesh_add_obj_file(world, "/proc/self/mem", NULL, &out), NL_STATUS_IO_ERROR,
                           "cannot read '/proc/self/mem'");
            }
        }
        CHECK(mesh_count(world) == 0);

        /* Null pointers. */
        CHECK_INVALID(nl_mesh_add_obj_file(world, NULL, NULL, &out), "path");
        CHECK_INVALID(nl_mesh_add_obj_file(world, "x.obj", NULL, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add_obj_file(NULL, "x.obj", NULL, &out), "world");
        CHECK_INVALID(nl_mesh_add_obj_memory(world, NULL, 10, NULL, &out), "data");
        CHECK_INVALID(nl_mesh_add_obj_memory(world, k_quad_obj, strlen(k_quad_obj), NULL, NULL), "out_id");
        CHECK_INVALID(nl_mesh_add_obj_memory(NULL, k_quad_obj, strlen(k_quad_obj), NULL, &out), "world");
        CHECK(out.index1 == 77u && out.revision == 77u);
    }
    CHECK(mesh_count(world) == 0);
    nl_world_destroy(world);
}

/* Counts the vertices and the fan triangles of an OBJ file (faces of n corners give n - 2). */
static int count_obj(const char* path, unsigned long* vertices, unsigned long* triangles) {
    char line[4096];
    FILE* f = fopen(path, "rb");
    *vertices = *triangles = 0;
    if (!f) return 0;
    while (fgets(line, sizeof line, f)) {
        const char* p = line;
        while (*p == ' ' || *p == '\t') ++p;
        if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            ++*vertices;
        } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            unsigned long corners = 0;
            ++p;
            for (;;) {
                while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
                if (*p == '\0' || *p == '#') break;
                ++corners;
                while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') ++p;
            }
            if (corners >= 3) *triangles += corners - 2;
        }
    }
    fclose(f);
    return 1;
}

static void dungeon_obj(void) {
    const char* levels_dir = abi_levels_dir();
    char path[4096];
    unsigned long vertices = 0, triangles = 0;
    nl_world* world;
    nl_mesh_id id = {0u, 0u};
    nl_mesh_info info;
    if (levels_dir == NULL) abi_skip("no levels directory given, dungeon.obj not checked");
    snprintf(path, sizeof path, "%s/dungeon.obj", levels_dir);
    if (!CHECK_MSG(count_obj(path, &vertices, &triangles), "cannot read %s", path)) return;
    CHECK(triangles == 10133); /* the README's figure */
    world = make_world(NL_WORKERS_AUTO);
    CHECK_OK(nl_mesh_add_obj_file(world, path, NULL, &id));
    info.size = sizeof info;
    CHECK_OK(nl_mesh_get_info(world, id, &info));
    CHECK_MSG(info.vertex_count == vertices, "vertex_count %u, the file has %lu", (unsigned)info.vertex_count,
              vertices);
    CHECK_MSG(info.triangle_count + info.degenerate_triangle_count == triangles,
              "%u kept + %u degenerate triangles, the file's faces fan into %lu", (unsigned)info.triangle_count,
              (unsigned)info.degenerate_triangle_count, triangles);
    CHECK(info.triangle_count > 0 && info.bounds_min[1] < info.bounds_max[1]);
    {
        /* A ray down through the middle of the level finds something. */
        nl_ray r;
        nl_ray_hit h = nl_ray_hit_init();
        r.origin[0] = 0.5f * (info.bounds_min[0] + info.bounds_max[0]);
        r.origin[1] = info.bounds_max[1] + 1.0f;
        r.origin[2] = 0.5f * (info.bounds_min[2] + info.bounds_max[2]);
        r.direction[0] = 0.0f, r.direction[1] = -1.0f, r.direction[2] = 0.0f;
        r.max_distance = INFINITY;
        CHECK_OK(nl_world_cast_rays(world, &r, 1, &h));
        CHECK(h.hit == 0 || (same_id(h.mesh, id) && h.triangle < triangles));
    }
    nl_world_destroy(world);
}

/* Awkward edges of the contract: the header's example message, ids of another world. */
static void contract_edges(void) {
    nl_world* world = make_world(1);
    nl_mesh_def def = floor_def();
    nl_mesh_id floor = {0u, 0u};
    CHECK_OK(nl_mesh_add(world, &def, &floor));

    /* The header's example message names the def's field ("def->indices[7] = 120 is out of range"). */
    {
        uint32_t indices[6];
        nl_mesh_id out = {0u, 0u};
        memcpy(indices, k_floor_indices, sizeof indices);
        indices[4] = 120;
        def.indices = indices;
        (void)nl_mesh_add(world, &def, &out);
        CHECK_THAT(strstr(nl_get_last_error_message(), "def->indices[4] = 120") != NULL,
                   "nl_mesh_add: an index out of range is named as the def's field, \"def->indices[4] = 120\"");
        def.indices = k_floor_indices;
    }

    /* Ids of one world used on another: the header lists "from another world" under INVALID_HANDLE. */
    {
        nl_world* other = make_world(1);
        nl_mesh_id mine = {0u, 0u}, theirs = {0u, 0u};
        def = floor_def();
        CHECK_OK(nl_mesh_add(other, &def, &theirs));
        CHECK(nl_mesh_is_valid(world, floor) == 1);
        mine = floor;
        CHECK_THAT(!same_id(mine, theirs) ? nl_mesh_is_valid(other, mine) == 0 : 0,
                   "an id from another world is not valid here");
        nl_world_destroy(other);
    }
    nl_world_destroy(world);
}

ABI_SECTION(level, ABI_CASE(mesh_add_and_info), ABI_CASE(degenerate_triangles), ABI_CASE(mesh_rejections),
            ABI_CASE(get_meshes), ABI_CASE(stale_ids), ABI_CASE(move_movable), ABI_CASE(move_static),
            ABI_CASE(mixed_scene), ABI_CASE(obj), ABI_CASE(dungeon_obj), ABI_CASE(contract_edges));
