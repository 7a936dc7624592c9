/*
 * Navmeshes (navlink.h): navmeshes handed over with nl_navmesh_add (quads, triangle soups, detail
 * heights, areas, welding, refusals), their lists, polygons, boundary edges and ids, and point location
 * with nl_navmesh_find_nearest, on the grid of navmesh_scene.h.
 */
/* pthread for the querying threads; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "navmesh_scene.h"
#include "scene.h"

#include <navlink/recast.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The grid as a Unity-style triangle soup: each quad (a b c d) is triangles (a b c) and (a c d), and
   every triangle has its own three vertices (24 vertices, indices 0..23). */
static void grid_soup(float vertices[72], uint32_t indices[24]) {
    int q, t, k, n = 0;
    for (q = 0; q < 4; ++q) {
        const uint32_t* quad = k_grid_quads + 4 * q;
        for (t = 0; t < 2; ++t) {
            const uint32_t corners[3] = {quad[0], quad[1 + t], quad[2 + t]};
            for (k = 0; k < 3; ++k, ++n) {
                memcpy(vertices + 3 * n, k_grid_vertices + 3 * corners[k], 3 * sizeof(float));
                indices[n] = (uint32_t)n;
            }
        }
    }
}

static uint32_t polygon_of_quadrant(const nl_world* world, nl_navmesh_id id, int quadrant) {
    uint32_t p;
    for (p = 0; p < 4; ++p) {
        nl_nav_polygon poly = nl_nav_polygon_init();
        if (NL_SUCCEEDED(nl_navmesh_get_polygon(world, id, p, &poly)) &&
            quadrant_of(poly.centre[0], poly.centre[2]) == quadrant)
            return p;
    }
    return NL_NO_POLYGON;
}

/* Extremes that might crash the process: add_variants and find_nearest run each first in a child
   (run_forked), and their own detailed checks only if it did not crash. */

/* The soup scaled to 1000 km squares, weld tolerance 1e-30 m: 9 vertices, 15 welded. */
static int isolated_weld(size_t unused) {
    nl_world* world = make_world(1);
    float soup[72];
    uint32_t indices[24];
    nl_navmesh_def def = nl_default_navmesh_def();
    nl_navmesh_id id = {0u, 0u};
    nl_navmesh_info info;
    int k, ok;
    (void)unused;
    grid_soup(soup, indices);
    for (k = 0; k < 72; ++k) soup[k] *= 1.0e6f;
    def.vertices = soup;
    def.vertex_count = 24;
    def.indices = indices;
    def.polygon_count = 8;
    def.weld_tolerance = 1.0e-30f;
    ok = NL_SUCCEEDED(nl_navmesh_add(world, &def, &id));
    info = navmesh_info(world, id);
    ok = ok && info.vertex_count == 9 && info.welded_vertex_count == 15 && info.portal_count == 8;
    nl_world_destroy(world);
    return ok;
}

/* The grid scaled to 1 cm squares; half extents 1e9 from just above quadrant 3 find the point below. */
static int isolated_far(size_t unused) {
    nl_world* world = make_world(1);
    float tiny[27];
    const float above_3[3] = {0.005f, 1.0f, 0.005f}, anywhere[3] = {1.0e9f, 1.0e9f, 1.0e9f};
    const float far_point[3] = {1.0e9f, 0.5f, 1.0e9f}, reaching[3] = {1.0e9f, 1.0f, 1.0e9f};
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    nl_nav_point out[2];
    int k, ok;
    (void)unused;
    for (k = 0; k < 27; ++k) tiny[k] = k % 3 == 1 ? k_grid_vertices[k] : 0.01f * k_grid_vertices[k];
    def.vertices = tiny;
    ok = NL_SUCCEEDED(nl_navmesh_add(world, &def, &id)) &&
         NL_SUCCEEDED(nl_navmesh_find_nearest(world, id, above_3, 1, anywhere, &out[0])) &&
         NL_SUCCEEDED(nl_navmesh_find_nearest(world, id, far_point, 1, reaching, &out[1]));
    ok = ok && out[0].found == 1 && out[0].polygon == polygon_of_quadrant(world, id, 3) &&
         near3(out[0].point, 0.005f, GRID_Y, 0.005f, 1e-6f) && out[1].found == 1;
    nl_world_destroy(world);
    return ok;
}

static void defaults(void) {
    const nl_agent_type agent = nl_default_agent_type();
    const nl_navmesh_def def = nl_default_navmesh_def();

    /* nl_agent_type: Recast's usual agent. */
    CHECK(agent.radius == 0.6f);
    CHECK(agent.height == 2.0f);
    CHECK(agent.max_climb == 0.9f);
    CHECK(agent.max_slope == 45.0f);

    CHECK(def.size == sizeof(nl_navmesh_def));
    CHECK(def.vertices == NULL && def.vertex_count == 0 && def.vertex_stride == 0);
    CHECK(def.indices == NULL && def.polygon_vertex_counts == NULL && def.polygon_count == 0 && def.areas == NULL);
    CHECK(def.weld_tolerance == 0.001f);
    CHECK(same_agent(def.agent_type, agent));
    CHECK(def.detail_vertices == NULL && def.detail_vertex_count == 0 && def.detail_triangles == NULL &&
          def.detail_triangle_starts == NULL);

    /* The defaults are values: nothing recorded, nothing shared between calls. */
    CHECK_INVALID(nl_navmesh_add(NULL, NULL, NULL), "world");
    (void)nl_default_agent_type();
    (void)nl_default_navmesh_def();
    (void)nl_default_navmesh_build_def();
    (void)nl_default_recast_settings();
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
}

static void add_grid(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    nl_navmesh_info info;

    CHECK(navmesh_count(world) == 0);
    CHECK_OK(nl_navmesh_add(world, &def, &id));
    CHECK(id.index1 != 0u);
    CHECK(nl_navmesh_is_valid(world, id) == 1);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS);
    CHECK(navmesh_count(world) == 1);
    info = navmesh_info(world, id);
    CHECK(info.welded_vertex_count == 0);
    CHECK(info.flipped_polygon_count == 0);
    CHECK(same_agent(info.agent_type, nl_default_agent_type()));
    check_grid_navmesh(world, id, 4, NULL, "quads");

    /* Exact neighbours, found by position: across each inner edge lies the quadrant on the other side. */
    {
        uint32_t p, k, vertex_count = 0;
        float* xyz = navmesh_vertices(world, id, &vertex_count);
        int wrong = 0;
        for (p = 0; xyz && p < 4; ++p) {
            nl_nav_polygon poly = nl_nav_polygon_init();
            if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &poly))) {
                ++wrong;
                continue;
            }
            for (k = 0; k < poly.vertex_count; ++k) {
                const float* a = xyz + 3 * poly.vertices[k];
                const float* b = xyz + 3 * poly.vertices[(k + 1) % poly.vertex_count];
                /* The neighbour's centre is this centre mirrored through the edge's midpoint. */
                const float nx = a[0] + b[0] - poly.centre[0], nz = a[2] + b[2] - poly.centre[2];
                if (fabsf(nx) > 1.0f || fabsf(nz) > 1.0f) {
                    wrong += poly.neighbours[k] != NL_NO_POLYGON;
                } else {
                    nl_nav_polygon other = nl_nav_polygon_init();
                    if (poly.neighbours[k] == NL_NO_POLYGON ||
                        NL_FAILED(nl_navmesh_get_polygon(world, id, poly.neighbours[k], &other)) ||
                        quadrant_of(other.centre[0], other.centre[2]) != quadrant_of(nx, nz))
                        ++wrong;
                }
            }
        }
        CHECK_MSG(xyz != NULL && wrong == 0, "%d neighbours of the quads are wrong", wrong);
        free(xyz);
    }

    /* Input arrays are copied: changing them afterwards changes nothing. */
    {
        float vertices[27];
        uint32_t quads[16];
        uint8_t counts[4] = {4, 4, 4, 4};
        nl_navmesh_id copied = {0u, 0u};
        memcpy(vertices, k_grid_vertices, sizeof vertices);
        memcpy(quads, k_grid_quads, sizeof quads);
        def = grid_def();
        def.vertices = vertices;
        def.indices = quads;
        def.polygon_vertex_counts = counts;
        CHECK_OK(nl_navmesh_add(world, &def, &copied));
        memset(vertices, 0, sizeof vertices);
        memset(quads, 0, sizeof quads);
        memset(counts, 0, sizeof counts);
        check_grid_navmesh(world, copied, 4, NULL, "quads, arrays reused after the call");
        CHECK(!same_navmesh(id, copied));
        CHECK(navmesh_count(world) == 2);
    }
    nl_world_destroy(world);
}

static void add_variants(void) {
    /* First, in a child, while this process has no threads. */
    const int weld_in_child = run_forked(isolated_weld, 0);
    nl_world* world;
    nl_navmesh_def def;
    nl_navmesh_id id = {0u, 0u};
    nl_navmesh_info info;
    float soup[72];
    uint32_t soup_indices[24];
    CHECK_MSG(weld_in_child == 1, "nl_navmesh_add: weld tolerance 1e-30 m on 1000 km squares (%s)",
              weld_in_child < 0 ? "crashed, or a sanitizer stopped it" : "wrong answer");
    world = make_world(1);
    grid_soup(soup, soup_indices);

    /* Unity-style triangle soup: every triangle has its own vertices; welding connects them. */
    def = nl_default_navmesh_def();
    def.vertices = soup;
    def.vertex_count = 24;
    def.indices = soup_indices;
    def.polygon_count = 8; /* polygon_vertex_counts NULL: triangles */
    CHECK_OK(nl_navmesh_add(world, &def, &id));
    info = navmesh_info(world, id);
    CHECK(info.welded_vertex_count == 15);
    CHECK(info.flipped_polygon_count == 0);
    check_grid_navmesh(world, id, 8, NULL, "triangle soup");

    /* Weld tolerance 0 still welds exact duplicates. */
    def.weld_tolerance = 0.0f;
    CHECK_OK(nl_navmesh_add(world, &def, &id));
    info = navmesh_info(world, id);
    CHECK(info.welded_vertex_count == 15);
    check_grid_navmesh(world, id, 8, NULL, "triangle soup, tolerance 0");

    /* Copies of a vertex up to 22 mm apart, no two equal (each a whole step of the 1/1024 m grid navmeshes
       keep their vertices on from the others): welded by a 3 cm tolerance, not by tolerance 0. */
    {
        float jittered[72];
        int k;
        memcpy(jittered, soup, sizeof jittered);
        for (k = 0; k < 24; ++k) jittered[3 * k + 0] += (float)k / 1024.0f;
        def.vertices = jittered;
        def.weld_tolerance = 0.03f;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        info = navmesh_info(world, id);
        CHECK(info.vertex_count == 9 && info.welded_vertex_count == 15);
        CHECK(info.portal_count == 8 && info.boundary_edge_count == 8);
        def.weld_tolerance = 0.0f;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        info = navmesh_info(world, id);
        CHECK_MSG(info.vertex_count == 24 && info.welded_vertex_count == 0, "%u vertices, %u welded",
                  (unsigned)info.vertex_count, (unsigned)info.welded_vertex_count);
        CHECK(info.portal_count == 0 && info.boundary_edge_count == 24 && info.polygon_count == 8);
        check_navmesh_structure(world, id, "unwelded soup");
        def.vertices = soup;
    }

    /* Extreme but valid: squares of 1000 km and a weld tolerance of 1e-30 m (exact duplicates only). Run
       first in a child (isolated_weld); here only if that did not crash. */
    if (CHECK_MSG(weld_in_child >= 0, "a weld tolerance of 1e-30 m on 1000 km squares crashed (in a child)")) {
        float huge[72];
        int k;
        for (k = 0; k < 72; ++k) huge[k] = soup[k] * 1.0e6f;
        def.vertices = huge;
        def.weld_tolerance = 1.0e-30f;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        info = navmesh_info(world, id);
        CHECK_MSG(info.vertex_count == 9 && info.welded_vertex_count == 15 && info.portal_count == 8 &&
                      info.boundary_edge_count == 8,
                  "%u vertices, %u welded, %u portals, %u boundary edges", (unsigned)info.vertex_count,
                  (unsigned)info.welded_vertex_count, (unsigned)info.portal_count, (unsigned)info.boundary_edge_count);
        CHECK(info.bounds_min[0] == -1.0e6f && info.bounds_max[2] == 1.0e6f);
        def.vertices = soup;
        def.weld_tolerance = 0.001f;
    }

    /* A T-junction, as at a tile border: one quad on the left, two on the right whose shared corner lies on
       the left quad's edge. The corner joins that edge (counted) and the three connect; with a weld
       tolerance of 0 the polygons are taken as given and the left quad stays apart. */
    {
        static const float tee[] = {0, 0, 0, 0, 0, 2, 2, 0, 2, 2, 0, 0, 2, 0, 1, 4, 0, 2, 4, 0, 1, 4, 0, 0};
        static const uint32_t tee_quads[] = {0, 1, 2, 3, 4, 2, 5, 6, 3, 4, 6, 7};
        static const uint8_t tee_counts[] = {4, 4, 4};
        nl_navmesh_def t = nl_default_navmesh_def();
        t.vertices = tee;
        t.vertex_count = 8;
        t.indices = tee_quads;
        t.polygon_vertex_counts = tee_counts;
        t.polygon_count = 3;
        CHECK_OK(nl_navmesh_add(world, &t, &id));
        info = navmesh_info(world, id);
        CHECK_MSG(info.t_junction_corner_count == 1 && info.unjoined_t_junction_count == 0 && info.portal_count == 3,
                  "%u corners joined, %u left, %u portals", (unsigned)info.t_junction_corner_count,
                  (unsigned)info.unjoined_t_junction_count, (unsigned)info.portal_count);
        t.weld_tolerance = 0.0f;
        CHECK_OK(nl_navmesh_add(world, &t, &id));
        info = navmesh_info(world, id);
        CHECK(info.t_junction_corner_count == 0 && info.portal_count == 1);
    }

    /* Clockwise input: turned over, counted, with the same topology and areas. */
    {
        uint32_t clockwise[16];
        static const uint8_t areas[4] = {1, 2, 3, 63};
        int q, k;
        for (q = 0; q < 4; ++q) {
            for (k = 0; k < 4; ++k) clockwise[4 * q + k] = k_grid_quads[4 * q + (q == 1 || q == 2 ? 3 - k : k)];
        }
        def = grid_def();
        def.indices = clockwise;
        def.areas = areas;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        info = navmesh_info(world, id);
        CHECK_MSG(info.flipped_polygon_count == 2, "%u polygons flipped, 2 were clockwise",
                  (unsigned)info.flipped_polygon_count);
        check_grid_navmesh(world, id, 4, areas, "two quads clockwise, with areas");

        /* Areas on the counter-clockwise grid and on the soup (one id per triangle: both of a quad alike). */
        def.indices = k_grid_quads;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        CHECK(navmesh_info(world, id).flipped_polygon_count == 0);
        check_grid_navmesh(world, id, 4, areas, "quads with areas");
        {
            static const uint8_t soup_areas[8] = {1, 1, 2, 2, 3, 3, 63, 63};
            def = nl_default_navmesh_def();
            def.vertices = soup;
            def.vertex_count = 24;
            def.indices = soup_indices;
            def.polygon_count = 8;
            def.areas = soup_areas;
            CHECK_OK(nl_navmesh_add(world, &def, &id));
            check_grid_navmesh(world, id, 8, areas, "soup with areas");
        }
        /* Every polygon clockwise. */
        for (q = 0; q < 16; ++q) clockwise[q] = k_grid_quads[4 * (q / 4) + 3 - q % 4];
        def = grid_def();
        def.indices = clockwise;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        CHECK(navmesh_info(world, id).flipped_polygon_count == 4);
        check_grid_navmesh(world, id, 4, NULL, "all quads clockwise");
    }

    /* Interleaved vertices, stride 24: position then 3 floats the library must not read (NaN). */
    {
        float interleaved[9 * 6];
        int k;
        for (k = 0; k < 9; ++k) {
            memcpy(interleaved + 6 * k, k_grid_vertices + 3 * k, 3 * sizeof(float));
            interleaved[6 * k + 3] = NAN;
            interleaved[6 * k + 4] = INFINITY;
            interleaved[6 * k + 5] = NAN;
        }
        def = grid_def();
        def.vertices = interleaved;
        def.vertex_stride = 24;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        check_grid_navmesh(world, id, 4, NULL, "stride 24");
    }

    /* The agent is kept as given. */
    {
        nl_agent_type agent;
        agent.radius = 0.25f;
        agent.height = 1.5f;
        agent.max_climb = 0.3f;
        agent.max_slope = 30.0f;
        def = grid_def();
        def.agent_type = agent;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        CHECK(same_agent(navmesh_info(world, id).agent_type, agent));
    }

    /* Repairs: a polygon of no area is dropped; an edge of three polygons connects none of them. */
    {
        static const float vertices[] = {
            -1.0f,  GRID_Y, -1.0f,  0.0f,   GRID_Y, -1.0f,  1.0f,   GRID_Y, -1.0f, -1.0f,
            GRID_Y, 0.0f,   0.0f,   GRID_Y, 0.0f,   1.0f,   GRID_Y, 0.0f,   -1.0f, GRID_Y,
            1.0f,   0.0f,   GRID_Y, 1.0f,   1.0f,   GRID_Y, 1.0f,   0.5f,   1.5f,  -0.5f, /* 9: above quadrant 1 */
            -0.5f,  GRID_Y, -1.0f,                                                        /* 10: on the edge 0-1 */
        };
        uint32_t indices[16 + 3 + 3];
        static const uint8_t counts[6] = {4, 4, 4, 4, 3, 3};
        memcpy(indices, k_grid_quads, sizeof k_grid_quads);
        /* A triangle on the inner edge 1-4 (shared by quadrants 0 and 1), rising to vertex 9. */
        indices[16] = 1, indices[17] = 4, indices[18] = 9;
        /* A triangle with no area (three points on a line). */
        indices[19] = 0, indices[20] = 10, indices[21] = 1;
        def = grid_def();
        def.vertices = vertices;
        def.vertex_count = 11;
        def.indices = indices;
        def.polygon_vertex_counts = counts;
        def.polygon_count = 6;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        info = navmesh_info(world, id);
        CHECK_MSG(info.polygon_count == 5 && info.dropped_polygon_count == 1, "%u polygons, %u dropped",
                  (unsigned)info.polygon_count, (unsigned)info.dropped_polygon_count);
        CHECK_MSG(info.non_manifold_edge_count == 1, "%u non-manifold edges", (unsigned)info.non_manifold_edge_count);
        CHECK_MSG(info.portal_count == 3, "%u portals (the grid's 4 minus the shared one)",
                  (unsigned)info.portal_count);
        CHECK_MSG(info.boundary_edge_count == 10, "%u boundary edges (8 + the raised triangle's 2)",
                  (unsigned)info.boundary_edge_count);
        CHECK(info.bounds_max[1] == 1.5f);
        check_navmesh_structure(world, id, "repairs");
    }
    nl_world_destroy(world);
}

/* The grid with height detail: quadrants 0-2 flat (two triangles each), quadrant 3 a pyramid rising
   to 0.75 m over its centre (four triangles). */
static const float k_detail_vertices[30] = {
    -1.0f, GRID_Y, -1.0f, 0.0f,  GRID_Y, -1.0f, 1.0f, GRID_Y, -1.0f, -1.0f, GRID_Y, 0.0f, 0.0f, GRID_Y, 0.0f,
    1.0f,  GRID_Y, 0.0f,  -1.0f, GRID_Y, 1.0f,  0.0f, GRID_Y, 1.0f,  1.0f,  GRID_Y, 1.0f, 0.5f, 0.75f,  0.5f,
};

static const uint32_t k_detail_triangles[30] = {
    0, 3, 4, 0, 4, 1,                   /* quadrant 0 */
    1, 4, 5, 1, 5, 2,                   /* quadrant 1 */
    3, 6, 7, 3, 7, 4,                   /* quadrant 2 */
    4, 7, 9, 7, 8, 9, 8, 5, 9, 5, 4, 9, /* quadrant 3: the bump */
};

static const uint32_t k_detail_starts[5] = {0, 2, 4, 6, 10};

static nl_navmesh_def detail_grid_def(void) {
    nl_navmesh_def def = grid_def();
    set_navmesh_detail(&def, k_detail_vertices, 10, k_detail_triangles, 10, k_detail_starts);
    return def;
}

static void detail(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = detail_grid_def();
    nl_navmesh_id flat = {0u, 0u}, bumpy = {0u, 0u};
    nl_navmesh_info info;
    const float half[3] = {0.25f, 3.0f, 0.25f};
    float points[9];
    nl_nav_point out[3];

    CHECK_OK(nl_navmesh_add(world, &def, &bumpy));
    def = grid_def();
    CHECK_OK(nl_navmesh_add(world, &def, &flat));
    info = navmesh_info(world, bumpy);
    CHECK(info.polygon_count == 4 && info.vertex_count == 9 && info.boundary_edge_count == 8);
    CHECK_MSG(info.bounds_max[1] == 0.75f && info.bounds_min[1] == GRID_Y, "bounds y %g..%g include the bump",
              info.bounds_min[1], info.bounds_max[1]);
    check_navmesh_structure(world, bumpy, "detail grid");

    /* Over the bump's top, over quadrant 0 (flat) and just off the bump's side. */
    points[0] = 0.5f, points[1] = 2.0f, points[2] = 0.5f;
    points[3] = -0.5f, points[4] = 2.0f, points[5] = -0.5f;
    points[6] = 0.25f, points[7] = 2.0f, points[8] = 0.5f;
    memset(out, 0xab, sizeof out);
    CHECK_OK(nl_navmesh_find_nearest(world, bumpy, points, 3, half, out));
    CHECK(out[0].found == 1 && out[0].polygon < 4);
    CHECK_NEAR(out[0].point[0], 0.5f, TOL);
    CHECK_NEAR(out[0].point[1], 0.75f, TOL); /* the detail height, not the polygon's 0.5 */
    CHECK_NEAR(out[0].point[2], 0.5f, TOL);
    CHECK_NEAR(out[0].distance, 1.25f, TOL);
    CHECK(out[1].found == 1);
    CHECK_NEAR(out[1].point[1], GRID_Y, TOL);
    CHECK_NEAR(out[1].distance, 1.5f, TOL);
    {
        nl_nav_polygon poly = nl_nav_polygon_init();
        CHECK_OK(nl_navmesh_get_polygon(world, bumpy, out[0].polygon, &poly));
        CHECK(quadrant_of(poly.centre[0], poly.centre[2]) == 3);
        CHECK_OK(nl_navmesh_get_polygon(world, bumpy, out[1].polygon, &poly));
        CHECK(quadrant_of(poly.centre[0], poly.centre[2]) == 0);
    }
    /* Over the bump's flank at (0.25, 0.5): the header says the point straight below, at the detail height
       (halfway up from the edge at 0.5 m to the top at 0.75 m). */
    CHECK_THAT(out[2].found == 1 && fabsf(out[2].point[0] - 0.25f) <= TOL && fabsf(out[2].point[2] - 0.5f) <= TOL &&
                   fabsf(out[2].point[1] - 0.625f) <= TOL && fabsf(out[2].distance - 1.375f) <= TOL,
               "nl_navmesh_find_nearest: a point over a polygon finds the surface straight below it, at the detail "
               "height (0.25, 0.625, 0.5)");

    /* The same points on the flat navmesh: the polygons' own height. */
    CHECK_OK(nl_navmesh_find_nearest(world, flat, points, 3, half, out));
    CHECK(out[0].found == 1);
    CHECK_NEAR(out[0].point[1], GRID_Y, TOL);
    CHECK_NEAR(out[0].distance, 1.5f, TOL);
    CHECK_NEAR(out[2].point[1], GRID_Y, TOL);
    nl_world_destroy(world);
}

/* One refused nl_navmesh_add: INVALID_ARGUMENT naming `needle`, nothing added, out_id untouched. */
#define CHECK_REJECTED_NAVMESH(world, def, needle) check_rejected_navmesh((world), (def), (needle), __FILE__, __LINE__)

static void check_rejected_navmesh(nl_world* world, const nl_navmesh_def* def, const char* needle, const char* file,
                                   int line) {
    const uint32_t before = navmesh_count(world);
    nl_navmesh_id out = {77u, 77u};
    const nl_status status = nl_navmesh_add(world, def, &out);
    check_fail_at(status, NL_STATUS_INVALID_ARGUMENT, needle, "nl_navmesh_add", file, line);
    check_at(strstr(nl_get_last_error_message(), "nl_navmesh_add") != NULL, file, line,
             "the message does not name nl_navmesh_add (%s)", needle);
    check_at(out.index1 == 77u && out.revision == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(navmesh_count(world) == before, file, line, "a navmesh was added on failure (%s)", needle);
}

static void rejections(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    float vertices[27];
    uint32_t quads[64]; /* room beyond the 16 used, so a wrong polygon size never reads past the array */
    uint8_t counts[4];

    CHECK_OK(nl_navmesh_add(world, &def, &id)); /* one present, so "unchanged" is not just "still zero" */
    memcpy(vertices, k_grid_vertices, sizeof vertices);
    memset(quads, 0, sizeof quads);
    memcpy(quads, k_grid_quads, sizeof k_grid_quads);
    memcpy(counts, k_quad_counts, sizeof counts);
    def.vertices = vertices;
    def.indices = quads;
    def.polygon_vertex_counts = counts;
    CHECK_OK(nl_navmesh_add(world, &def, &id)); /* the mutable copy is valid as it is */
    CHECK(navmesh_count(world) == 2);

    /* Null pointers and zero counts. */
    {
        nl_navmesh_id out = {77u, 77u};
        CHECK_INVALID(nl_navmesh_add(NULL, &def, &out), "world");
        CHECK_INVALID(nl_navmesh_add(world, NULL, &out), "def");
        CHECK_INVALID(nl_navmesh_add(world, &def, NULL), "out_id");
        CHECK(out.index1 == 77u && out.revision == 77u);
        CHECK(navmesh_count(world) == 2);
    }
    def.vertices = NULL;
    CHECK_REJECTED_NAVMESH(world, &def, "vertices");
    def.vertices = vertices;
    def.indices = NULL;
    CHECK_REJECTED_NAVMESH(world, &def, "indices");
    def.indices = quads;
    def.vertex_count = 0;
    CHECK_REJECTED_NAVMESH(world, &def, "vertex_count");
    def.vertex_count = 9;
    def.polygon_count = 0;
    CHECK_REJECTED_NAVMESH(world, &def, "polygon_count");
    def.polygon_count = 4;
    def.vertex_stride = 8;
    CHECK_REJECTED_NAVMESH(world, &def, "vertex_stride");
    def.vertex_stride = 0;

    /* Coordinates: NaN, infinite, beyond NL_COORDINATE_LIMIT. */
    vertices[3 * 4 + 1] = NAN;
    CHECK_REJECTED_NAVMESH(world, &def, "vertices[4]");
    vertices[3 * 4 + 1] = GRID_Y;
    vertices[3 * 7 + 0] = 2.0e9f;
    CHECK_REJECTED_NAVMESH(world, &def, "vertices[7]");
    vertices[3 * 7 + 0] = 0.0f;
    vertices[3 * 8 + 2] = -INFINITY;
    CHECK_REJECTED_NAVMESH(world, &def, "vertices[8]");
    vertices[3 * 8 + 2] = 1.0f;

    /* Indices. */
    quads[5] = 9; /* == vertex_count */
    CHECK_REJECTED_NAVMESH(world, &def, "indices[5]");
    quads[5] = UINT32_MAX;
    CHECK_REJECTED_NAVMESH(world, &def, "indices[5]");
    quads[5] = k_grid_quads[5];

    /* Polygon sizes: 3..NL_MAX_POLYGON_VERTICES. */
    counts[1] = 2;
    CHECK_REJECTED_NAVMESH(world, &def, "polygon_vertex_counts[1]");
    counts[1] = 4;
    counts[2] = NL_MAX_POLYGON_VERTICES + 1;
    CHECK_REJECTED_NAVMESH(world, &def, "polygon_vertex_counts[2]");
    counts[2] = 0;
    CHECK_REJECTED_NAVMESH(world, &def, "polygon_vertex_counts[2]");
    counts[2] = 4;

    /* A weld tolerance that is NaN or negative. */
    def.weld_tolerance = NAN;
    CHECK_REJECTED_NAVMESH(world, &def, "weld_tolerance");
    def.weld_tolerance = -0.01f;
    CHECK_REJECTED_NAVMESH(world, &def, "weld_tolerance");
    def.weld_tolerance = 0.001f;

    /* A bad agent. */
    def.agent_type.radius = -1.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent_type.radius");
    def.agent_type = nl_default_agent_type();
    def.agent_type.height = 0.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent_type.height");
    def.agent_type = nl_default_agent_type();
    def.agent_type.max_slope = 90.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent_type.max_slope");
    def.agent_type = nl_default_agent_type();
    def.agent_type.max_climb = NAN;
    CHECK_REJECTED_NAVMESH(world, &def, "agent_type.max_climb");
    def.agent_type = nl_default_agent_type();

    /* def->size too small (a zeroed def, one from a header that never existed). */
    def.size = 0;
    CHECK_REJECTED_NAVMESH(world, &def, "size");
    def.size = (uint32_t)offsetof(nl_navmesh_def, detail_triangle_starts); /* short of the first release */
    CHECK_REJECTED_NAVMESH(world, &def, "size");
    def.size = sizeof def;
    CHECK_REJECTED_NAVMESH(world, &(nl_navmesh_def){0}, "size");

    /* Not convex seen from above: a square with one side pushed in (a pentagon with a reflex corner). */
    {
        static const float dart[] = {0, 0, 0, 0, 0, 2, 2, 0, 2, 2, 0, 0, 1, 0, 1};
        static const uint32_t ring[] = {0, 1, 2, 3, 4};
        static const uint8_t five[] = {5};
        nl_navmesh_def bad = nl_default_navmesh_def();
        bad.vertices = dart;
        bad.vertex_count = 5;
        bad.indices = ring;
        bad.polygon_vertex_counts = five;
        bad.polygon_count = 1;
        CHECK_REJECTED_NAVMESH(world, &bad, "not convex");
        CHECK_REJECTED_NAVMESH(world, &bad, "polygon 0");
    }
    /* A pentagram: every corner turns the same way, but it winds twice round its centre. */
    {
        float star[15];
        static const uint32_t order[] = {0, 2, 4, 1, 3};
        static const uint8_t five[] = {5};
        nl_navmesh_def bad = nl_default_navmesh_def();
        int k;
        for (k = 0; k < 5; ++k) {
            const double angle = 6.283185307179586 * (double)k / 5.0;
            star[3 * k + 0] = (float)cos(angle);
            star[3 * k + 1] = 0.0f;
            star[3 * k + 2] = (float)sin(angle);
        }
        bad.vertices = star;
        bad.vertex_count = 5;
        bad.indices = order;
        bad.polygon_vertex_counts = five;
        bad.polygon_count = 1;
        CHECK_REJECTED_NAVMESH(world, &bad, "polygon 0");
        {
            /* The same five corners in pentagon order are fine. */
            static const uint32_t pentagon[] = {0, 4, 3, 2, 1};
            nl_navmesh_id ok = {0u, 0u};
            bad.indices = pentagon;
            CHECK_OK(nl_navmesh_add(world, &bad, &ok));
            CHECK_OK(nl_navmesh_remove(world, ok));
        }
    }
    /* Every polygon degenerate. */
    {
        static const float line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
        static const uint32_t tri[] = {0, 1, 2};
        nl_navmesh_def bad = nl_default_navmesh_def();
        bad.vertices = line;
        bad.vertex_count = 3;
        bad.indices = tri;
        bad.polygon_count = 1;
        CHECK_REJECTED_NAVMESH(world, &bad, "degenerate");
    }

    /* Inconsistent height detail. */
    {
        float detail_vertices[30];
        uint32_t detail_triangles[30];
        uint32_t starts[5];
        memcpy(detail_vertices, k_detail_vertices, sizeof detail_vertices);
        memcpy(detail_triangles, k_detail_triangles, sizeof detail_triangles);
        memcpy(starts, k_detail_starts, sizeof starts);
        def = detail_grid_def();
        def.detail_vertices = detail_vertices;
        def.detail_triangles = detail_triangles;
        def.detail_triangle_starts = starts;
        CHECK_OK(nl_navmesh_add(world, &def, &id)); /* valid as it is */

        /* Starts one entry short (polygon_count entries, and a 0 where the last should be). */
        starts[4] = 0;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_starts");
        starts[4] = 10;
        starts[0] = 1;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_starts");
        starts[0] = 0;
        starts[2] = 1; /* out of order */
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_starts");
        starts[2] = 4;
        def.detail_triangle_count = 9; /* disagrees with starts[4] */
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_starts");
        def.detail_triangle_count = 0;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_count");
        def.detail_triangle_count = 10;
        detail_triangles[13] = 10; /* == detail_vertex_count */
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangles[13]");
        detail_triangles[13] = 4;
        detail_vertices[3 * 9 + 1] = NAN;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_vertices[9]");
        detail_vertices[3 * 9 + 1] = 0.75f;
        CHECK_OK(nl_navmesh_add(world, &def, &id)); /* repaired again */

        /* Only some of the three detail pointers. */
        def.detail_vertices = NULL;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_vertices");
        def.detail_vertices = detail_vertices;
        def.detail_triangles = NULL;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangles");
        def.detail_triangles = detail_triangles;
        def.detail_triangle_starts = NULL;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_triangle_starts");
        def.detail_vertices = NULL;
        def.detail_triangles = NULL;
        def.detail_triangle_starts = starts;
        CHECK_REJECTED_NAVMESH(world, &def, "detail_vertices");
    }
    CHECK(navmesh_count(world) == 4);
    nl_world_destroy(world);
}

static void find_nearest(void) {
    /* First, in a child, while this process has no threads. */
    const int far_in_child = run_forked(isolated_far, 0);
    nl_world* world;
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    uint32_t by_quadrant[4];
    const float half[3] = {1.0f, 5.0f, 1.0f};
    float points[6 * 3] = {
        0.3f, 2.5f,   -0.6f, /* above quadrant 1 */
        0.3f, -1.0f,  -0.6f, /* below it */
        1.5f, GRID_Y, 0.2f,  /* beside the grid, level with it: the outline of quadrant 3 */
        5.0f, GRID_Y, 5.0f,  /* far outside the box */
        0.0f, 2.0f,   -0.5f, /* over the edge shared by quadrants 0 and 1: a tie */
        0.0f, 2.0f,   0.0f,  /* over the vertex all four share */
    };
    nl_nav_point out[6];
    int q;
    CHECK_MSG(far_in_child == 1,
              "nl_navmesh_find_nearest: half extents 1e9 over 1 cm squares find the polygon below (%s)",
              far_in_child < 0 ? "crashed, or a sanitizer stopped it" : "wrong answer");
    world = make_world(1);

    CHECK_OK(nl_navmesh_add(world, &def, &id));
    for (q = 0; q < 4; ++q) by_quadrant[q] = polygon_of_quadrant(world, id, q);
    CHECK(by_quadrant[0] != NL_NO_POLYGON && by_quadrant[1] != NL_NO_POLYGON && by_quadrant[2] != NL_NO_POLYGON &&
          by_quadrant[3] != NL_NO_POLYGON);

    memset(out, 0xab, sizeof out);
    CHECK_OK(nl_navmesh_find_nearest(world, id, points, 6, half, out));
    CHECK(out[0].found == 1 && out[0].polygon == by_quadrant[1]);
    CHECK(near3(out[0].point, 0.3f, GRID_Y, -0.6f, TOL));
    CHECK_NEAR(out[0].distance, 2.0f, TOL);
    CHECK(out[1].found == 1 && out[1].polygon == by_quadrant[1]);
    CHECK(near3(out[1].point, 0.3f, GRID_Y, -0.6f, TOL));
    CHECK_NEAR(out[1].distance, 1.5f, TOL);
    CHECK(out[2].found == 1 && out[2].polygon == by_quadrant[3]);
    CHECK(near3(out[2].point, 1.0f, GRID_Y, 0.2f, TOL));
    CHECK_NEAR(out[2].distance, 0.5f, TOL);
    CHECK(out[3].found == 0);
    CHECK(out[3].polygon == NL_NO_POLYGON);
    CHECK_THAT(
        out[3].beyond_box == 1 && near3(out[3].point, 1.0f, GRID_Y, 1.0f, TOL),
        "nl_navmesh_find_nearest: a point whose box holds no polygon gets the navmesh's nearest point beyond it");
    CHECK_NEAR(out[3].distance, sqrtf(32.0f), 1e-4);
    CHECK(out[4].found == 1);
    CHECK_NEAR(out[4].distance, 1.5f, TOL);
    CHECK_MSG(out[4].polygon == (by_quadrant[0] < by_quadrant[1] ? by_quadrant[0] : by_quadrant[1]),
              "a tie between polygons %u and %u went to %u, not the lower index", (unsigned)by_quadrant[0],
              (unsigned)by_quadrant[1], (unsigned)out[4].polygon);
    CHECK(out[5].found == 1);
    CHECK_NEAR(out[5].distance, 1.5f, TOL);
    CHECK_MSG(out[5].polygon == 0, "a tie between all four polygons went to %u, not 0", (unsigned)out[5].polygon);
    for (q = 0; q < 6; ++q) {
        CHECK_MSG(out[q].reserved[0] == 0 && out[q].reserved[1] == 0, "out[%d].reserved is not zero", q);
        CHECK_MSG(out[q].found || out[q].beyond_box, "out[%d] is neither found nor beyond the box", q);
        CHECK_MSG(!(out[q].found && out[q].beyond_box), "out[%d] is found and beyond the box", q);
    }

    /* A smaller box: a point 1.5 m above the grid is out of reach of a box 1 m high. */
    {
        const float low[3] = {0.5f, 1.0f, 0.5f};
        CHECK_OK(nl_navmesh_find_nearest(world, id, points + 4 * 3, 1, low, out));
        CHECK(out[0].found == 0 && out[0].polygon == NL_NO_POLYGON);
        CHECK(out[0].beyond_box == 1 && near3(out[0].point, 0.0f, GRID_Y, -0.5f, TOL));
        CHECK_NEAR(out[0].distance, 1.5f, TOL);
    }

    /* Huge boxes on a navmesh of 1 cm squares: "anywhere" (half extents 1e9) from just above quadrant 3
       finds the point straight below; from the coordinate limit, a box that just reaches the squares
       finds them; a small box out there finds nothing. Run first in a child (isolated_far); here
       only if that did not crash. */
    if (CHECK_MSG(far_in_child >= 0, "huge search boxes on 1 cm squares crashed (in a child)")) {
        float tiny[27];
        const float above_3[3] = {0.005f, 1.0f, 0.005f};
        const float far_points[6] = {1.0e9f, 0.5f, 1.0e9f, -1.0e9f, 0.5f, -1.0e9f};
        const float anywhere[3] = {1.0e9f, 1.0e9f, 1.0e9f};
        const float small_box[3] = {1.0f, 1.0f, 1.0f}, reaching[3] = {1.0e9f, 1.0f, 1.0e9f};
        nl_navmesh_def small = grid_def();
        nl_navmesh_id small_id = {0u, 0u};
        int k;
        for (k = 0; k < 27; ++k) tiny[k] = k % 3 == 1 ? k_grid_vertices[k] : 0.01f * k_grid_vertices[k];
        small.vertices = tiny;
        CHECK_OK(nl_navmesh_add(world, &small, &small_id));
        memset(out, 0xab, sizeof out);
        CHECK_OK(nl_navmesh_find_nearest(world, small_id, above_3, 1, anywhere, out));
        CHECK_MSG(out[0].found == 1 && out[0].polygon == polygon_of_quadrant(world, small_id, 3) &&
                      near3(out[0].point, 0.005f, GRID_Y, 0.005f, 1e-6f) && fabsf(out[0].distance - 0.5f) <= TOL,
                  "half extents 1e9 from (0.005, 1, 0.005) over quadrant 3 (polygon %u) found %u: polygon %u at "
                  "(%g %g %g), %g m",
                  (unsigned)polygon_of_quadrant(world, small_id, 3), (unsigned)out[0].found, (unsigned)out[0].polygon,
                  out[0].point[0], out[0].point[1], out[0].point[2], out[0].distance);
        CHECK_OK(nl_navmesh_find_nearest(world, small_id, far_points, 2, small_box, out));
        CHECK(out[0].found == 0 && out[0].polygon == NL_NO_POLYGON);
        CHECK(out[1].found == 0 && out[1].polygon == NL_NO_POLYGON);
        CHECK_OK(nl_navmesh_find_nearest(world, small_id, far_points, 1, reaching, out));
        /* 1.4e9 m away, a centimetre is below float resolution: any point of the squares will do. */
        CHECK_MSG(out[0].found == 1 && out[0].polygon < 4 && fabsf(out[0].point[0]) <= 0.01f &&
                      out[0].point[1] == GRID_Y && fabsf(out[0].point[2]) <= 0.01f,
                  "a box from (1e9, 0.5, 1e9) reaching the squares found %u: polygon %u at (%g %g %g)",
                  (unsigned)out[0].found, (unsigned)out[0].polygon, out[0].point[0], out[0].point[1], out[0].point[2]);
        CHECK_OK(nl_navmesh_remove(world, small_id));
    }

    /* count == 0 succeeds and writes nothing, even with null points and out. */
    memset(out, 0xab, sizeof out);
    CHECK_OK(nl_navmesh_find_nearest(world, id, points, 0, half, out));
    CHECK(all_bytes(out, sizeof out, 0xab));
    CHECK_OK(nl_navmesh_find_nearest(world, id, NULL, 0, half, NULL));

    /* Bad half extents: zero, negative, NaN, infinite, null. Nothing written. */
    {
        static const float bad_extents[][3] = {
            {0.0f, 1.0f, 1.0f},
            {1.0f, 0.0f, 1.0f},
            {1.0f, 1.0f, -1.0f},
            {-1.0f, -1.0f, -1.0f},
        };
        float extents[3];
        size_t b;
        for (b = 0; b < sizeof bad_extents / sizeof bad_extents[0]; ++b) {
            memset(out, 0xab, sizeof out);
            CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, bad_extents[b], out), "half_extents");
            CHECK_MSG(all_bytes(out, sizeof out, 0xab), "out written on failure (extents case %d)", (int)b);
        }
        extents[0] = 1.0f, extents[1] = NAN, extents[2] = 1.0f;
        CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, extents, out), "half_extents");
        extents[1] = INFINITY;
        CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, extents, out), "half_extents");
        CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, NULL, out), "half_extents");
        CHECK(all_bytes(out, sizeof out, 0xab));
    }

    /* Bad points: the index is named and nothing is written. */
    points[2 * 3 + 1] = NAN;
    CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, half, out), "points[2]");
    CHECK(all_bytes(out, sizeof out, 0xab));
    points[2 * 3 + 1] = GRID_Y;
    points[5 * 3 + 0] = 2.0e9f;
    CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, half, out), "points[5]");
    points[5 * 3 + 0] = -INFINITY;
    CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, half, out), "points[5]");
    CHECK(all_bytes(out, sizeof out, 0xab));
    points[5 * 3 + 0] = 0.0f;
    CHECK_INVALID(nl_navmesh_find_nearest(world, id, NULL, 6, half, out), "points");
    CHECK_INVALID(nl_navmesh_find_nearest(world, id, points, 6, half, NULL), "out");
    CHECK_INVALID(nl_navmesh_find_nearest(NULL, id, points, 6, half, out), "world");
    CHECK(all_bytes(out, sizeof out, 0xab));
    nl_world_destroy(world);
}

/* A few thousand points around the grid, in worlds of 1 and 2 workers: every answer as computed here,
   and the two worlds' answers identical to the byte. */
static void find_nearest_batches(void) {
    enum { side = 64, count = side * side };
    nl_world* worlds[2];
    nl_navmesh_id ids[2] = {{0u, 0u}, {0u, 0u}};
    float* points = (float*)malloc(3 * sizeof(float) * count);
    nl_nav_point* out[2];
    const float half[3] = {0.75f, 2.0f, 0.75f};
    int w, i, wrong = 0, found = 0;
    out[0] = (nl_nav_point*)malloc(sizeof(nl_nav_point) * count);
    out[1] = (nl_nav_point*)malloc(sizeof(nl_nav_point) * count);
    if (!points || !out[0] || !out[1]) {
        CHECK(!"out of memory");
        free(points);
        free(out[0]);
        free(out[1]);
        return;
    }
    /* x and z in [-2.4, 2.4], never 0 (an even number of steps each side); y within 1.2 m of the grid. */
    for (i = 0; i < count; ++i) {
        points[3 * i + 0] = -2.4f + 4.8f * (float)(i % side) / (float)(side - 1);
        points[3 * i + 1] = GRID_Y + 0.4f * (float)(i % 7 - 3);
        points[3 * i + 2] = -2.4f + 4.8f * (float)(i / side) / (float)(side - 1);
    }
    worlds[0] = make_world(1);
    worlds[1] = make_world(2);
    CHECK(nl_world_get_worker_count(worlds[1]) == 2);
    for (w = 0; w < 2; ++w) {
        nl_navmesh_def def = grid_def();
        uint32_t by_quadrant[4];
        int q;
        CHECK_OK(nl_navmesh_add(worlds[w], &def, &ids[w]));
        for (q = 0; q < 4; ++q) by_quadrant[q] = polygon_of_quadrant(worlds[w], ids[w], q);
        memset(out[w], 0xab, sizeof(nl_nav_point) * count);
        CHECK_OK(nl_navmesh_find_nearest(worlds[w], ids[w], points, count, half, out[w]));
        for (i = 0; i < count; ++i) {
            const float x = points[3 * i], y = points[3 * i + 1], z = points[3 * i + 2];
            const float cx = x < -1.0f ? -1.0f : x > 1.0f ? 1.0f : x;
            const float cz = z < -1.0f ? -1.0f : z > 1.0f ? 1.0f : z;
            const int reachable = fabsf(x) - half[0] <= 1.0f && fabsf(z) - half[2] <= 1.0f;
            const nl_nav_point* r = &out[w][i];
            if (!reachable) {
                wrong += r->found != 0 || r->polygon != NL_NO_POLYGON;
                continue;
            }
            ++found;
            {
                const float dx = x - cx, dy = y - GRID_Y, dz = z - cz;
                const float distance = sqrtf(dx * dx + dy * dy + dz * dz);
                if (r->found != 1 || r->polygon != by_quadrant[quadrant_of(cx, cz)] ||
                    !near3(r->point, cx, GRID_Y, cz, TOL) || fabsf(r->distance - distance) > TOL) {
                    if (wrong < 3) {
                        fprintf(stderr, "    point (%g %g %g): found %u polygon %u at (%g %g %g) %g m\n", x, y, z,
                                (unsigned)r->found, (unsigned)r->polygon, r->point[0], r->point[1], r->point[2],
                                r->distance);
                    }
                    ++wrong;
                }
            }
        }
    }
    CHECK_MSG(wrong == 0, "%d of %d nearest points were wrong", wrong, 2 * count);
    CHECK_MSG(found > count / 2 && found < 2 * count, "the batch has %d reachable points of %d: it tests both kinds",
              found / 2, count);
    CHECK_THAT(memcmp(out[0], out[1], sizeof(nl_nav_point) * count) == 0,
               "nl_navmesh_find_nearest gives the same bytes with 1 and 2 workers");
    nl_world_destroy(worlds[0]);
    nl_world_destroy(worlds[1]);
    free(points);
    free(out[0]);
    free(out[1]);
}

static void lists(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id ids[3], out_ids[5];
    float xyz[3 * 12];
    nl_boundary_edge edges[10];
    uint32_t count, i, j;

    /* nl_world_get_navmeshes */
    count = 0xdeadbeefu;
    CHECK_OK(nl_world_get_navmeshes(world, NULL, 0, &count));
    CHECK(count == 0);
    for (i = 0; i < 3; ++i) CHECK_OK(nl_navmesh_add(world, &def, &ids[i]));
    count = 0xdeadbeefu;
    CHECK_OK(nl_world_get_navmeshes(world, NULL, 0, &count));
    CHECK(count == 3);
    memset(out_ids, 0xcd, sizeof out_ids);
    count = 0;
    CHECK_FAIL(nl_world_get_navmeshes(world, out_ids, 2, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 3);
    CHECK(all_bytes(out_ids, sizeof out_ids, 0xcd));
    count = 0;
    CHECK_FAIL(nl_world_get_navmeshes(world, out_ids, 0, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 3);
    CHECK(all_bytes(out_ids, sizeof out_ids, 0xcd));
    CHECK_OK(nl_world_get_navmeshes(world, out_ids, 5, &count));
    CHECK(count == 3);
    CHECK(all_bytes(&out_ids[3], 2 * sizeof out_ids[0], 0xcd)); /* only `count` entries written */
    {
        int found[3] = {0, 0, 0};
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) found[j] += same_navmesh(out_ids[i], ids[j]);
        }
        CHECK(found[0] == 1 && found[1] == 1 && found[2] == 1);
    }
    CHECK_OK(nl_navmesh_remove(world, ids[1]));
    CHECK_OK(nl_world_get_navmeshes(world, out_ids, 3, &count));
    CHECK(count == 2);
    CHECK((same_navmesh(out_ids[0], ids[0]) && same_navmesh(out_ids[1], ids[2])) ||
          (same_navmesh(out_ids[0], ids[2]) && same_navmesh(out_ids[1], ids[0])));
    count = 0xdeadbeefu;
    CHECK_INVALID(nl_world_get_navmeshes(world, NULL, 1, &count), "out_ids");
    CHECK_INVALID(nl_world_get_navmeshes(world, out_ids, 5, NULL), "out_count");
    CHECK_INVALID(nl_world_get_navmeshes(NULL, out_ids, 5, &count), "world");

    /* nl_navmesh_get_vertices: 9 vertices of 3 floats. */
    count = 0xdeadbeefu;
    CHECK_OK(nl_navmesh_get_vertices(world, ids[0], NULL, 0, &count));
    CHECK(count == 9);
    memset(xyz, 0xcd, sizeof xyz);
    count = 0;
    CHECK_FAIL(nl_navmesh_get_vertices(world, ids[0], xyz, 8, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 9);
    CHECK(all_bytes(xyz, sizeof xyz, 0xcd));
    CHECK_OK(nl_navmesh_get_vertices(world, ids[0], xyz, 12, &count));
    CHECK(count == 9);
    CHECK(all_bytes(xyz + 27, 9 * sizeof(float), 0xcd));
    count = 0xdeadbeefu;
    CHECK_INVALID(nl_navmesh_get_vertices(world, ids[0], NULL, 9, &count), "out_xyz");
    CHECK_INVALID(nl_navmesh_get_vertices(world, ids[0], xyz, 12, NULL), "out_count");
    CHECK_INVALID(nl_navmesh_get_vertices(NULL, ids[0], xyz, 12, &count), "world");

    /* nl_navmesh_get_boundary_edges: 8 edges. */
    count = 0xdeadbeefu;
    CHECK_OK(nl_navmesh_get_boundary_edges(world, ids[0], NULL, 0, &count));
    CHECK(count == 8);
    memset(edges, 0xcd, sizeof edges);
    count = 0;
    CHECK_FAIL(nl_navmesh_get_boundary_edges(world, ids[0], edges, 7, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 8);
    CHECK(all_bytes(edges, sizeof edges, 0xcd));
    CHECK_OK(nl_navmesh_get_boundary_edges(world, ids[0], edges, 10, &count));
    CHECK(count == 8);
    CHECK(all_bytes(&edges[8], 2 * sizeof edges[0], 0xcd));
    count = 0xdeadbeefu;
    CHECK_INVALID(nl_navmesh_get_boundary_edges(world, ids[0], NULL, 3, &count), "out_edges");
    CHECK_INVALID(nl_navmesh_get_boundary_edges(world, ids[0], edges, 10, NULL), "out_count");
    CHECK_INVALID(nl_navmesh_get_boundary_edges(NULL, ids[0], edges, 10, &count), "world");

    /* nl_navmesh_get_polygon out of range, or without a place to write to. */
    {
        nl_nav_polygon poly = nl_nav_polygon_init();
        memset(&poly, 0xcd, sizeof poly);
        poly.size = sizeof poly; /* the element size the library lays out with */
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], 4, &poly), "polygon");
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], UINT32_MAX, &poly), "polygon");
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], NL_NO_POLYGON, &poly), "polygon");
        CHECK(all_bytes((const unsigned char*)&poly + sizeof(uint32_t), sizeof poly - sizeof(uint32_t), 0xcd));
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], 0, NULL), "out_polygon");
        CHECK_INVALID(nl_navmesh_get_polygon(NULL, ids[0], 0, &poly), "world");
        CHECK_OK(nl_navmesh_get_polygon(world, ids[0], 3, &poly));
    }

    /* nl_navmesh_get_info: `size` too small, or no place to write to. */
    {
        nl_navmesh_info info;
        memset(&info, 0xab, sizeof info);
        info.size = 0;
        CHECK_INVALID(nl_navmesh_get_info(world, ids[0], &info), "size");
        CHECK(info.vertex_count == 0xabababab);
        info.size = (uint32_t)offsetof(nl_navmesh_info, bounds_max); /* shorter than the first release */
        CHECK_INVALID(nl_navmesh_get_info(world, ids[0], &info), "size");
        CHECK(info.vertex_count == 0xabababab);
        CHECK_INVALID(nl_navmesh_get_info(world, ids[0], NULL), "out_info");
        info.size = sizeof info;
        CHECK_INVALID(nl_navmesh_get_info(NULL, ids[0], &info), "world");
        CHECK(info.vertex_count == 0xabababab);
        CHECK_OK(nl_navmesh_get_info(world, ids[0], &info));
        CHECK(info.size == sizeof info && info.vertex_count == 9);
    }
    nl_world_destroy(world);
}

/* Every function that takes a navmesh id refuses `id` with INVALID_HANDLE, naming itself, writing nothing. */
#define CHECK_BAD_NAVMESH_ID(world, id) check_bad_navmesh_id((world), (id), __FILE__, __LINE__)

static void check_bad_navmesh_id(nl_world* world, nl_navmesh_id id, const char* file, int line) {
    nl_navmesh_info info;
    nl_nav_polygon poly = nl_nav_polygon_init();
    nl_boundary_edge edge;
    nl_nav_point nearest;
    float xyz[3];
    const float point[3] = {0.0f, 1.0f, 0.0f}, half[3] = {1.0f, 1.0f, 1.0f};
    uint32_t count = 0xdeadbeefu;
    const uint32_t before = navmesh_count(world);
    memset(&info, 0xab, sizeof info);
    memset(&poly, 0xab, sizeof poly);
    poly.size = sizeof poly; /* the element size the library lays out with */
    memset(&edge, 0xab, sizeof edge);
    memset(&nearest, 0xab, sizeof nearest);
    memset(xyz, 0xab, sizeof xyz);
    info.size = sizeof info;
    check_at(nl_navmesh_is_valid(world, id) == 0 && nl_get_last_status() == NL_STATUS_SUCCESS, file, line,
             "nl_navmesh_is_valid: a bad id is an answer (0), not an error");
    check_fail_at(nl_navmesh_remove(world, id), NL_STATUS_INVALID_HANDLE, "nl_navmesh_remove", "nl_navmesh_remove",
                  file, line);
    check_fail_at(nl_navmesh_get_info(world, id, &info), NL_STATUS_INVALID_HANDLE, "nl_navmesh_get_info",
                  "nl_navmesh_get_info", file, line);
    check_fail_at(nl_navmesh_get_vertices(world, id, NULL, 0, &count), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_get_vertices", "nl_navmesh_get_vertices (count)", file, line);
    check_fail_at(nl_navmesh_get_vertices(world, id, xyz, 1, &count), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_get_vertices", "nl_navmesh_get_vertices", file, line);
    check_fail_at(nl_navmesh_get_polygon(world, id, 0, &poly), NL_STATUS_INVALID_HANDLE, "nl_navmesh_get_polygon",
                  "nl_navmesh_get_polygon", file, line);
    check_fail_at(nl_navmesh_get_boundary_edges(world, id, NULL, 0, &count), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_get_boundary_edges", "nl_navmesh_get_boundary_edges (count)", file, line);
    check_fail_at(nl_navmesh_get_boundary_edges(world, id, &edge, 1, &count), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_get_boundary_edges", "nl_navmesh_get_boundary_edges", file, line);
    check_fail_at(nl_navmesh_find_nearest(world, id, point, 1, half, &nearest), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_find_nearest", "nl_navmesh_find_nearest", file, line);
    check_fail_at(nl_navmesh_find_nearest(world, id, point, 0, half, &nearest), NL_STATUS_INVALID_HANDLE,
                  "nl_navmesh_find_nearest", "nl_navmesh_find_nearest (count 0)", file, line);
    check_at(info.vertex_count == 0xabababab &&
                 all_bytes((const unsigned char*)&poly + sizeof(uint32_t), sizeof poly - sizeof(uint32_t), 0xab) &&
                 all_bytes(&edge, sizeof edge, 0xab) && all_bytes(&nearest, sizeof nearest, 0xab) &&
                 all_bytes(xyz, sizeof xyz, 0xab) && count == 0xdeadbeefu,
             file, line, "an output was written for a bad navmesh id");
    check_at(navmesh_count(world) == before, file, line, "the navmesh count changed");
}

static void ids(void) {
    nl_world* world = make_world(1);
    nl_world* other = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id a = {0u, 0u}, b = {0u, 0u}, reused = {0u, 0u}, theirs = {0u, 0u};
    const nl_navmesh_id null_id = {0u, 0u};

    CHECK_OK(nl_navmesh_add(world, &def, &a));
    CHECK_OK(nl_navmesh_add(world, &def, &b));
    CHECK(nl_navmesh_is_valid(world, a) == 1 && nl_navmesh_is_valid(world, b) == 1);
    CHECK_OK(nl_navmesh_remove(world, a));
    CHECK(nl_navmesh_is_valid(world, a) == 0);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS);
    CHECK(navmesh_count(world) == 1);
    CHECK_BAD_NAVMESH_ID(world, a);
    CHECK_BAD_NAVMESH_ID(world, null_id);
    {
        const nl_navmesh_id far = {1000u, 1u}, wrong_revision = {b.index1, b.revision + 1u};
        const nl_navmesh_id zero_generation = {b.index1, 0u};
        CHECK_BAD_NAVMESH_ID(world, far);
        CHECK_BAD_NAVMESH_ID(world, wrong_revision);
        CHECK_BAD_NAVMESH_ID(world, zero_generation);
    }

    /* A new navmesh may take the removed slot; the old id stays stale. */
    CHECK_OK(nl_navmesh_add(world, &def, &reused));
    CHECK(!same_navmesh(reused, a));
    CHECK_MSG(reused.index1 == a.index1, "slot not reused (old {%u,%u}, new {%u,%u}); the reuse check is vacuous",
              (unsigned)a.index1, (unsigned)a.revision, (unsigned)reused.index1, (unsigned)reused.revision);
    CHECK_BAD_NAVMESH_ID(world, a);
    CHECK(nl_navmesh_is_valid(world, reused) == 1);

    /* Another world's id, at a slot this world has in use as well. */
    CHECK_OK(nl_navmesh_add(other, &def, &theirs));
    CHECK(nl_navmesh_is_valid(other, theirs) == 1);
    CHECK_MSG(theirs.index1 == reused.index1 || theirs.index1 == b.index1,
              "the other world's id {%u,%u} shares no slot number with this world's; the check is weaker",
              (unsigned)theirs.index1, (unsigned)theirs.revision);
    CHECK_BAD_NAVMESH_ID(world, theirs);
    CHECK_BAD_NAVMESH_ID(other, b);
    CHECK_BAD_NAVMESH_ID(other, reused);
    CHECK(nl_navmesh_is_valid(other, theirs) == 1 && nl_navmesh_is_valid(world, b) == 1);

    /* A null world. */
    CHECK(nl_navmesh_is_valid(NULL, b) == 0);
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_INVALID(nl_navmesh_remove(NULL, b), "world");
    CHECK(navmesh_count(world) == 2 && navmesh_count(other) == 1);
    nl_world_destroy(other);
    nl_world_destroy(world);
}

typedef struct navmesh_job {
    nl_world* world;
    nl_navmesh_id id;
    uint32_t by_quadrant[4];
    int failures;
    int wrong;
} navmesh_job;

static void* nearest_thread(void* arg) {
    navmesh_job* job = (navmesh_job*)arg;
    const float half[3] = {0.5f, 2.0f, 0.5f};
    int i, k;
    for (i = 0; i < 300; ++i) {
        float points[16 * 3];
        nl_nav_point out[16];
        uint32_t count = 0;
        nl_navmesh_info info;
        for (k = 0; k < 16; ++k) {
            points[3 * k + 0] = -0.9f + 0.12f * (float)k;
            points[3 * k + 1] = GRID_Y + 0.1f * (float)(i % 5);
            points[3 * k + 2] = (k & 1) ? 0.45f : -0.55f;
        }
        if (NL_FAILED(nl_navmesh_find_nearest(job->world, job->id, points, 16, half, out))) {
            ++job->failures;
            continue;
        }
        for (k = 0; k < 16; ++k) {
            const float* p = points + 3 * k;
            if (out[k].found != 1 || out[k].polygon != job->by_quadrant[quadrant_of(p[0], p[2])] ||
                !near3(out[k].point, p[0], GRID_Y, p[2], TOL))
                ++job->wrong;
        }
        if ((i & 15) == 0) {
            info.size = sizeof info;
            if (NL_FAILED(nl_world_get_navmeshes(job->world, NULL, 0, &count)) ||
                NL_FAILED(nl_navmesh_get_info(job->world, job->id, &info)) || info.polygon_count != 4)
                ++job->failures;
        }
    }
    return NULL;
}

static void threads(void) {
    enum { thread_count = 3 };
    nl_world* world = make_world(2);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    navmesh_job jobs[thread_count];
    pthread_t threads[thread_count];
    int started[thread_count];
    float far_vertices[27];
    int i, q, edits_ok = 1;

    CHECK_OK(nl_navmesh_add(world, &def, &id));
    memset(jobs, 0, sizeof jobs);
    for (i = 0; i < thread_count; ++i) {
        jobs[i].world = world;
        jobs[i].id = id;
        for (q = 0; q < 4; ++q) jobs[i].by_quadrant[q] = polygon_of_quadrant(world, id, q);
        started[i] = pthread_create(&threads[i], NULL, nearest_thread, &jobs[i]) == 0;
        CHECK(started[i]);
    }
    /* Meanwhile: add and remove other navmeshes (the grid moved 100 m away, and as a soup). */
    memcpy(far_vertices, k_grid_vertices, sizeof far_vertices);
    for (i = 0; i < 9; ++i) far_vertices[3 * i] += 100.0f;
    def.vertices = far_vertices;
    for (i = 0; i < 100; ++i) {
        nl_navmesh_id other = {0u, 0u};
        if (NL_FAILED(nl_navmesh_add(world, &def, &other))) edits_ok = 0;
        if (NL_FAILED(nl_navmesh_remove(world, other))) edits_ok = 0;
        if (i % 10 == 0 && NL_FAILED(nl_navmesh_add(world, &def, &other))) edits_ok = 0; /* some stay */
    }
    CHECK(edits_ok);
    for (i = 0; i < thread_count; ++i) {
        if (started[i]) pthread_join(threads[i], NULL);
        CHECK_MSG(jobs[i].failures == 0, "thread %d: %d calls failed", i, jobs[i].failures);
        CHECK_MSG(jobs[i].wrong == 0, "thread %d: %d nearest points were wrong", i, jobs[i].wrong);
    }
    CHECK(navmesh_count(world) == 11);
    CHECK(nl_navmesh_is_valid(world, id) == 1);
    nl_world_destroy(world);
}

ABI_SECTION(navmeshes, ABI_CASE(defaults), ABI_CASE(add_grid), ABI_CASE(add_variants), ABI_CASE(detail),
            ABI_CASE(rejections), ABI_CASE(find_nearest), ABI_CASE(find_nearest_batches), ABI_CASE(lists),
            ABI_CASE(ids), ABI_CASE(threads));
