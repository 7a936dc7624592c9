/*
 * navlink-c-api-test, part two: navmeshes, navmesh building and plugins, through the C ABI only, in
 * strict C11. The checks are counted with the rest (c_api_test.h).
 *
 * The scene most cases use is a 2 x 2 grid of 1 m squares at y = 0.5, x and z in [-1, 1]: nine
 * vertices, vertex r * 3 + c at (-1 + c, 0.5, -1 + r), and four quads wound counter-clockwise seen
 * from above (normal +Y). The polygon of the quadrant x in [0, 1], z in [-1, 0] is "quadrant 1", and
 * so on: quadrant = 2 * (z > 0) + (x > 0). Expectations are found by position (a polygon's centre, an
 * edge's ends), never by the order the library happens to store things in.
 */
/* fork() and waitpid() isolate the cases that may crash the process; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "scene.h"

#include <navlink/plugin.h>
#include <navlink/recast.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------------------
 * Scenes and helpers
 * ------------------------------------------------------------------------------------------- */

#define GRID_Y 0.5f

static const float k_grid_vertices[27] = {
    -1.0f, GRID_Y, -1.0f, 0.0f, GRID_Y, -1.0f, 1.0f, GRID_Y, -1.0f, /* row z = -1: 0 1 2 */
    -1.0f, GRID_Y, 0.0f,  0.0f, GRID_Y, 0.0f,  1.0f, GRID_Y, 0.0f,  /* row z = 0:  3 4 5 */
    -1.0f, GRID_Y, 1.0f,  0.0f, GRID_Y, 1.0f,  1.0f, GRID_Y, 1.0f,  /* row z = 1:  6 7 8 */
};
/* Counter-clockwise seen from above: (x0, z0) -> (x0, z1) -> (x1, z1) -> (x1, z0). */
static const uint32_t k_grid_quads[16] = {
    0, 3, 4, 1, /* quadrant 0: x in [-1, 0], z in [-1, 0] */
    1, 4, 5, 2, /* quadrant 1: x in [0, 1],  z in [-1, 0] */
    3, 6, 7, 4, /* quadrant 2: x in [-1, 0], z in [0, 1] */
    4, 7, 8, 5, /* quadrant 3: x in [0, 1],  z in [0, 1] */
};
static const uint8_t k_quad_counts[4] = {4, 4, 4, 4};

/* The grid with polygon_vertex_counts: four quads. */
static nl_navmesh_def grid_def(void) { return navmesh_def_of(k_grid_vertices, 9, k_grid_quads, k_quad_counts, 4); }

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

/* Which quadrant of the grid a point (seen from above) lies in; the point must not be on x = 0 or z = 0. */
static int quadrant_of(float x, float z) { return (z > 0.0f ? 2 : 0) + (x > 0.0f ? 1 : 0); }

static uint32_t navmesh_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_navmeshes(world, NULL, 0, &count);
    return count;
}

static uint32_t plugin_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_plugins(world, NULL, 0, &count);
    return count;
}

static int same_navmesh(nl_navmesh_id a, nl_navmesh_id b) {
    return a.index1 == b.index1 && a.generation == b.generation;
}
static int same_plugin(nl_plugin_id a, nl_plugin_id b) {
    return a.index1 == b.index1 && a.generation == b.generation;
}

static int same_agent(nl_agent_type a, nl_agent_type b) {
    return a.radius == b.radius && a.height == b.height && a.max_climb == b.max_climb && a.max_slope == b.max_slope;
}

static nl_navmesh_info navmesh_info(const nl_world* world, nl_navmesh_id id) {
    nl_navmesh_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_get_info(world, id, &info))) memset(&info, 0, sizeof info);
    return info;
}

/* The navmesh's vertices in a malloc'ed array (3 floats each); NULL on failure. */
static float* navmesh_vertices(const nl_world* world, nl_navmesh_id id, uint32_t* out_count) {
    uint32_t count = 0;
    float* xyz;
    *out_count = 0;
    if (NL_FAILED(nl_navmesh_get_vertices(world, id, NULL, 0, &count))) return NULL;
    xyz = (float*)malloc(3 * sizeof(float) * (count ? count : 1));
    if (!xyz) return NULL;
    if (NL_FAILED(nl_navmesh_get_vertices(world, id, xyz, count, &count))) {
        free(xyz);
        return NULL;
    }
    *out_count = count;
    return xyz;
}

static nl_boundary_edge* navmesh_edges(const nl_world* world, nl_navmesh_id id, uint32_t* out_count) {
    uint32_t count = 0;
    nl_boundary_edge* edges;
    *out_count = 0;
    if (NL_FAILED(nl_navmesh_get_boundary_edges(world, id, NULL, 0, &count))) return NULL;
    edges = (nl_boundary_edge*)malloc(sizeof(nl_boundary_edge) * (count ? count : 1));
    if (!edges) return NULL;
    if (NL_FAILED(nl_navmesh_get_boundary_edges(world, id, edges, count, &count))) {
        free(edges);
        return NULL;
    }
    *out_count = count;
    return edges;
}

static float dot3(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static float length3(const float* a) { return sqrtf(dot3(a, a)); }
static int near3(const float* a, float x, float y, float z, float tol) {
    return fabsf(a[0] - x) <= tol && fabsf(a[1] - y) <= tol && fabsf(a[2] - z) <= tol;
}
static int equal3(const float* a, const float* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* Twice the signed area of a polygon seen from above; positive when counter-clockwise with +Y up. */
static float area_from_above(const float* xyz, const nl_nav_polygon* p) {
    float sum = 0.0f;
    uint32_t k;
    for (k = 0; k < p->vertex_count; ++k) {
        const float* a = xyz + 3 * p->vertices[k];
        const float* b = xyz + 3 * p->vertices[(k + 1) % p->vertex_count];
        sum += a[2] * b[0] - a[0] * b[2]; /* (a x b).y */
    }
    return sum;
}

/* Structure every navmesh must have, whatever made it: corners in range and counter-clockwise from
   above, unit upward normals, symmetric neighbours (across the same two vertices), portal and boundary
   counts that agree with the polygons, and boundary edges that are the polygons' unconnected edges with
   unit outward directions square to the edge and away from the polygon. Returns the number of
   problems (each one also a failed check). */
static int check_navmesh_structure(const nl_world* world, nl_navmesh_id id, const char* label) {
    const nl_navmesh_info info = navmesh_info(world, id);
    uint32_t vertex_count = 0, edge_count = 0, p, k, e;
    float* xyz = navmesh_vertices(world, id, &vertex_count);
    nl_boundary_edge* edges = navmesh_edges(world, id, &edge_count);
    nl_nav_polygon* polygons = (nl_nav_polygon*)malloc(sizeof(nl_nav_polygon) * (info.polygon_count + 1u));
    uint32_t connected = 0, unconnected = 0;
    int bad = 0;
    if (!CHECK_MSG(xyz && edges && polygons && info.polygon_count > 0, "%s: cannot read the navmesh", label)) {
        free(xyz);
        free(edges);
        free(polygons);
        return 1;
    }
    bad += !CHECK_MSG(vertex_count == info.vertex_count, "%s: %u vertices listed, info says %u", label,
                      (unsigned)vertex_count, (unsigned)info.vertex_count);
    bad += !CHECK_MSG(edge_count == info.boundary_edge_count, "%s: %u boundary edges listed, info says %u", label,
                      (unsigned)edge_count, (unsigned)info.boundary_edge_count);
    for (p = 0; p < info.polygon_count; ++p) {
        if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &polygons[p]))) {
            bad += !CHECK_MSG(0, "%s: nl_navmesh_get_polygon(%u) failed", label, (unsigned)p);
            memset(&polygons[p], 0, sizeof polygons[p]);
        }
    }
    for (p = 0; p < info.polygon_count && !bad; ++p) {
        const nl_nav_polygon* poly = &polygons[p];
        int ok = poly->vertex_count >= 3 && poly->vertex_count <= NL_MAX_POLYGON_VERTICES;
        for (k = 0; ok && k < poly->vertex_count; ++k) ok = poly->vertices[k] < vertex_count;
        if (!CHECK_MSG(ok, "%s: polygon %u has %u corners or a corner out of range", label, (unsigned)p,
                       (unsigned)poly->vertex_count)) {
            ++bad;
            continue;
        }
        bad += !CHECK_MSG(area_from_above(xyz, poly) > 0.0f, "%s: polygon %u is not counter-clockwise from above",
                          label, (unsigned)p);
        bad += !CHECK_MSG(fabsf(length3(poly->normal) - 1.0f) <= 1e-4f && poly->normal[1] > 0.0f,
                          "%s: polygon %u normal (%g %g %g) is not unit and up", label, (unsigned)p, poly->normal[0],
                          poly->normal[1], poly->normal[2]);
        {
            /* The centre is the average of the corners. */
            float c[3] = {0.0f, 0.0f, 0.0f};
            for (k = 0; k < poly->vertex_count; ++k) {
                c[0] += xyz[3 * poly->vertices[k]] / (float)poly->vertex_count;
                c[1] += xyz[3 * poly->vertices[k] + 1] / (float)poly->vertex_count;
                c[2] += xyz[3 * poly->vertices[k] + 2] / (float)poly->vertex_count;
            }
            bad += !CHECK_MSG(near3(poly->centre, c[0], c[1], c[2], 1e-3f), "%s: polygon %u centre is wrong", label,
                              (unsigned)p);
        }
        for (k = 0; k < poly->vertex_count; ++k) {
            const uint32_t n = poly->neighbours[k];
            const uint32_t a = poly->vertices[k], b = poly->vertices[(k + 1) % poly->vertex_count];
            uint32_t j, back = 0;
            if (n == NL_NO_POLYGON) {
                ++unconnected;
                continue;
            }
            ++connected;
            if (!CHECK_MSG(n < info.polygon_count && n != p, "%s: polygon %u edge %u has neighbour %u", label,
                           (unsigned)p, (unsigned)k, (unsigned)n)) {
                ++bad;
                continue;
            }
            /* The neighbour has the same edge, the other way round, pointing back here. */
            for (j = 0; j < polygons[n].vertex_count; ++j) {
                if (polygons[n].vertices[j] == b && polygons[n].vertices[(j + 1) % polygons[n].vertex_count] == a &&
                    polygons[n].neighbours[j] == p)
                    ++back;
            }
            bad += !CHECK_MSG(back == 1, "%s: polygon %u edge %u -> polygon %u is not symmetric", label, (unsigned)p,
                              (unsigned)k, (unsigned)n);
        }
    }
    bad += !CHECK_MSG(connected == 2 * info.portal_count, "%s: %u connected edge sides for %u portals", label,
                      (unsigned)connected, (unsigned)info.portal_count);
    bad += !CHECK_MSG(unconnected >= info.boundary_edge_count, "%s: %u unconnected edges, %u boundary edges", label,
                      (unsigned)unconnected, (unsigned)info.boundary_edge_count);
    for (e = 0; e < edge_count && !bad; ++e) {
        const nl_boundary_edge* edge = &edges[e];
        const nl_nav_polygon* poly;
        float along[3], mid_to_centre[3];
        if (!CHECK_MSG(edge->polygon < info.polygon_count && edge->edge < polygons[edge->polygon].vertex_count,
                       "%s: boundary edge %u names polygon %u edge %u", label, (unsigned)e, (unsigned)edge->polygon,
                       (unsigned)edge->edge)) {
            ++bad;
            continue;
        }
        poly = &polygons[edge->polygon];
        bad += !CHECK_MSG(poly->neighbours[edge->edge] == NL_NO_POLYGON, "%s: boundary edge %u is a portal", label,
                          (unsigned)e);
        bad += !CHECK_MSG(equal3(edge->start, xyz + 3 * poly->vertices[edge->edge]) &&
                              equal3(edge->end, xyz + 3 * poly->vertices[(edge->edge + 1) % poly->vertex_count]),
                          "%s: boundary edge %u ends are not its polygon's corners %u, %u", label, (unsigned)e,
                          (unsigned)edge->edge, (unsigned)(edge->edge + 1));
        bad += !CHECK_MSG(equal3(edge->normal, poly->normal), "%s: boundary edge %u normal is not its polygon's",
                          label, (unsigned)e);
        along[0] = edge->end[0] - edge->start[0];
        along[1] = edge->end[1] - edge->start[1];
        along[2] = edge->end[2] - edge->start[2];
        mid_to_centre[0] = poly->centre[0] - 0.5f * (edge->start[0] + edge->end[0]);
        mid_to_centre[1] = poly->centre[1] - 0.5f * (edge->start[1] + edge->end[1]);
        mid_to_centre[2] = poly->centre[2] - 0.5f * (edge->start[2] + edge->end[2]);
        bad += !CHECK_MSG(fabsf(length3(edge->outward) - 1.0f) <= 1e-4f &&
                              fabsf(dot3(edge->outward, along)) <= 1e-4f * length3(along) &&
                              dot3(edge->outward, mid_to_centre) < 0.0f,
                          "%s: boundary edge %u outward (%g %g %g) is not unit, square to the edge and away from the "
                          "polygon",
                          label, (unsigned)e, edge->outward[0], edge->outward[1], edge->outward[2]);
    }
    free(xyz);
    free(edges);
    free(polygons);
    return bad;
}

/* The grid's own answers: 9 vertices where the grid has them, `polygons` polygons (4 quads or 8
   triangles) covering the four quadrants, the outline of 8 unit edges with outward pointing straight
   away from the square, area ids by quadrant (`areas` NULL: all 0). */
static void check_grid_navmesh(const nl_world* world, nl_navmesh_id id, uint32_t polygons, const uint8_t* areas,
                               const char* label) {
    const nl_navmesh_info info = navmesh_info(world, id);
    uint32_t vertex_count = 0, edge_count = 0, i, j;
    float* xyz;
    nl_boundary_edge* edges;
    int found[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    int per_quadrant[4] = {0, 0, 0, 0};
    CHECK_MSG(info.size == sizeof info, "%s: info.size changed", label);
    CHECK_MSG(info.vertex_count == 9, "%s: %u vertices, expected 9", label, (unsigned)info.vertex_count);
    CHECK_MSG(info.polygon_count == polygons, "%s: %u polygons, expected %u", label, (unsigned)info.polygon_count,
              (unsigned)polygons);
    CHECK_MSG(info.portal_count == (polygons == 4 ? 4u : 8u), "%s: %u portals", label, (unsigned)info.portal_count);
    CHECK_MSG(info.boundary_edge_count == 8, "%s: %u boundary edges, expected 8", label,
              (unsigned)info.boundary_edge_count);
    CHECK_MSG(info.dropped_polygon_count == 0 && info.non_manifold_edge_count == 0, "%s: repairs reported", label);
    CHECK_MSG(info.bounds_min[0] == -1.0f && info.bounds_min[1] == GRID_Y && info.bounds_min[2] == -1.0f &&
                  info.bounds_max[0] == 1.0f && info.bounds_max[1] == GRID_Y && info.bounds_max[2] == 1.0f,
              "%s: bounds (%g %g %g)..(%g %g %g)", label, info.bounds_min[0], info.bounds_min[1], info.bounds_min[2],
              info.bounds_max[0], info.bounds_max[1], info.bounds_max[2]);

    xyz = navmesh_vertices(world, id, &vertex_count);
    if (CHECK_MSG(xyz != NULL && vertex_count == 9, "%s: nl_navmesh_get_vertices", label)) {
        /* Each grid vertex exactly once. */
        for (i = 0; i < 9; ++i) {
            for (j = 0; j < 9; ++j) {
                if (equal3(xyz + 3 * i, k_grid_vertices + 3 * j)) ++found[j];
            }
        }
        for (j = 0; j < 9; ++j) {
            CHECK_MSG(found[j] == 1, "%s: grid vertex %u found %d times", label, (unsigned)j, found[j]);
        }
    }
    for (i = 0; i < info.polygon_count; ++i) {
        nl_nav_polygon poly;
        memset(&poly, 0xcd, sizeof poly);
        if (!CHECK_OK(nl_navmesh_get_polygon(world, id, i, &poly))) continue;
        CHECK_MSG(poly.vertex_count == (polygons == 4 ? 4u : 3u), "%s: polygon %u has %u corners", label, (unsigned)i,
                  (unsigned)poly.vertex_count);
        CHECK_MSG(poly.normal[0] == 0.0f && poly.normal[1] == 1.0f && poly.normal[2] == 0.0f,
                  "%s: polygon %u normal (%g %g %g)", label, (unsigned)i, poly.normal[0], poly.normal[1],
                  poly.normal[2]);
        CHECK_MSG(fabsf(poly.centre[1] - GRID_Y) <= TOL, "%s: polygon %u centre y %g", label, (unsigned)i,
                  poly.centre[1]);
        if (poly.centre[0] != 0.0f && poly.centre[2] != 0.0f) {
            const int q = quadrant_of(poly.centre[0], poly.centre[2]);
            ++per_quadrant[q];
            CHECK_MSG(poly.area == (areas ? areas[q] : 0u), "%s: polygon %u (quadrant %d) has area %u, expected %u",
                      label, (unsigned)i, q, (unsigned)poly.area, (unsigned)(areas ? areas[q] : 0u));
            if (polygons == 4) {
                CHECK_MSG(fabsf(fabsf(poly.centre[0]) - 0.5f) <= TOL && fabsf(fabsf(poly.centre[2]) - 0.5f) <= TOL,
                          "%s: quad %u centre (%g %g)", label, (unsigned)i, poly.centre[0], poly.centre[2]);
            }
        } else {
            CHECK_MSG(0, "%s: polygon %u centre (%g %g %g) is on an axis", label, (unsigned)i, poly.centre[0],
                      poly.centre[1], poly.centre[2]);
        }
    }
    for (i = 0; i < 4; ++i) {
        CHECK_MSG(per_quadrant[i] == (int)polygons / 4, "%s: %d polygons in quadrant %u", label, per_quadrant[i],
                  (unsigned)i);
    }

    edges = navmesh_edges(world, id, &edge_count);
    if (CHECK_MSG(edges != NULL && edge_count == 8, "%s: nl_navmesh_get_boundary_edges", label)) {
        float sum[3] = {0.0f, 0.0f, 0.0f};
        for (i = 0; i < edge_count; ++i) {
            const nl_boundary_edge* e = &edges[i];
            const float mx = 0.5f * (e->start[0] + e->end[0]), mz = 0.5f * (e->start[2] + e->end[2]);
            /* On the outline: the side it lies on gives its outward direction. */
            const float ox = fabsf(mx) == 1.0f ? mx : 0.0f, oz = fabsf(mz) == 1.0f ? mz : 0.0f;
            nl_nav_polygon poly;
            CHECK_MSG((ox != 0.0f) != (oz != 0.0f), "%s: boundary edge %u (mid %g %g) is not on the outline", label,
                      (unsigned)i, mx, mz);
            CHECK_MSG(near3(e->outward, ox, 0.0f, oz, TOL), "%s: edge %u outward (%g %g %g), expected (%g 0 %g)",
                      label, (unsigned)i, e->outward[0], e->outward[1], e->outward[2], ox, oz);
            CHECK_MSG(e->outward[0] * mx + e->outward[2] * mz > 0.0f, "%s: edge %u outward points to the centre",
                      label, (unsigned)i);
            CHECK_MSG(fabsf(length3(e->outward) - 1.0f) <= TOL, "%s: edge %u outward is not unit", label, (unsigned)i);
            CHECK_MSG(e->normal[0] == 0.0f && e->normal[1] == 1.0f && e->normal[2] == 0.0f,
                      "%s: edge %u normal (%g %g %g)", label, (unsigned)i, e->normal[0], e->normal[1], e->normal[2]);
            CHECK_MSG(e->start[1] == GRID_Y && e->end[1] == GRID_Y &&
                          fabsf(e->end[0] - e->start[0]) + fabsf(e->end[2] - e->start[2]) == 1.0f,
                      "%s: edge %u is not a unit grid edge", label, (unsigned)i);
            /* Counter-clockwise around the square seen from above: outward = edge x up = (-dz, 0, dx). */
            CHECK_MSG(-(e->end[2] - e->start[2]) == ox && (e->end[0] - e->start[0]) == oz,
                      "%s: edge %u runs the wrong way round the outline", label, (unsigned)i);
            if (CHECK_OK(nl_navmesh_get_polygon(world, id, e->polygon, &poly)) && e->edge < poly.vertex_count) {
                CHECK_MSG(poly.neighbours[e->edge] == NL_NO_POLYGON, "%s: edge %u's polygon has a neighbour there",
                          label, (unsigned)i);
                CHECK_MSG(quadrant_of(mx - 0.01f * ox, mz - 0.01f * oz) == quadrant_of(poly.centre[0], poly.centre[2]),
                          "%s: edge %u belongs to a polygon of another quadrant", label, (unsigned)i);
            } else {
                CHECK_MSG(0, "%s: edge %u names polygon %u edge %u", label, (unsigned)i, (unsigned)e->polygon,
                          (unsigned)e->edge);
            }
            sum[0] += e->end[0] - e->start[0];
            sum[2] += e->end[2] - e->start[2];
        }
        CHECK_MSG(sum[0] == 0.0f && sum[2] == 0.0f, "%s: the outline is not closed", label);
    }
    check_navmesh_structure(world, id, label);
    free(xyz);
    free(edges);
}

/* Cases run first in a child process (test_navmesh_isolated): -1 crashed, 0 wrong answer, 1 right.
   The in-process versions, with their detailed checks, run only when the child did not crash. */
enum { ISOLATED_WELD, ISOLATED_FAR, ISOLATED_COUNT };
static int g_isolated[ISOLATED_COUNT];

/* ---------------------------------------------------------------------------------------------
 * Defaults
 * ------------------------------------------------------------------------------------------- */

static void test_defaults(void) {
    const nl_agent_type agent = nl_default_agent_type();
    const nl_navmesh_def def = nl_default_navmesh_def();
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    const nl_recast_settings recast = nl_default_recast_settings();
    g_section = "navmesh defaults";

    /* nl_agent_type: Recast's usual agent. */
    CHECK(agent.radius == 0.6f);
    CHECK(agent.height == 2.0f);
    CHECK(agent.max_climb == 0.9f);
    CHECK(agent.max_slope == 45.0f);

    CHECK(def.size == sizeof(nl_navmesh_def));
    CHECK(def.vertices == NULL && def.vertex_count == 0 && def.vertex_stride == 0);
    CHECK(def.indices == NULL && def.polygon_vertex_counts == NULL && def.polygon_count == 0 && def.areas == NULL);
    CHECK(def.weld_tolerance == 0.001f);
    CHECK(same_agent(def.agent, agent));
    CHECK(def.detail_vertices == NULL && def.detail_vertex_count == 0 && def.detail_triangles == NULL &&
          def.detail_triangle_starts == NULL);

    CHECK(build.size == sizeof(nl_navmesh_build_def));
    CHECK_THAT(build.builder == NULL || strcmp(build.builder, "recast") == 0,
               "nl_default_navmesh_build_def: builder \"recast\" (or NULL, which means it)");
    CHECK(same_agent(build.agent, agent));
    CHECK(build.settings == NULL && build.settings_json == NULL && build.settings_json_length == 0);

    CHECK(recast.size == sizeof(nl_recast_settings));
    CHECK(recast.cell_size == 0.3f);
    CHECK(recast.cell_height == 0.2f);
    CHECK(recast.region_min_size == 8.0f);
    CHECK(recast.region_merge_size == 20.0f);
    CHECK(recast.edge_max_length == 12.0f);
    CHECK(recast.edge_max_error == 1.3f);
    CHECK(recast.vertices_per_polygon == 6);
    CHECK(recast.detail_sample_distance == 6.0f);
    CHECK(recast.detail_sample_max_error == 1.0f);
    CHECK(recast.partition == NL_RECAST_PARTITION_WATERSHED);
    CHECK(recast.filter_low_hanging_obstacles == 1 && recast.filter_ledge_spans == 1 &&
          recast.filter_walkable_low_height_spans == 1);
    CHECK(recast.reserved == 0);
    /* The defaults are values: nothing recorded, nothing shared between calls. */
    CHECK_INVALID(nl_navmesh_add(NULL, NULL, NULL), "world");
    (void)nl_default_agent_type();
    (void)nl_default_navmesh_def();
    (void)nl_default_navmesh_build_def();
    (void)nl_default_recast_settings();
    CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
}

/* ---------------------------------------------------------------------------------------------
 * nl_navmesh_add: hand-made navmeshes with exact answers
 * ------------------------------------------------------------------------------------------- */

static void test_navmesh_add_grid(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    nl_navmesh_info info;
    g_section = "navmesh add: quads";

    CHECK(navmesh_count(world) == 0);
    CHECK_OK(nl_navmesh_add(world, &def, &id));
    CHECK(id.index1 != 0u);
    CHECK(nl_navmesh_is_valid(world, id) == 1);
    CHECK(nl_get_last_status() == NL_STATUS_SUCCESS);
    CHECK(navmesh_count(world) == 1);
    info = navmesh_info(world, id);
    CHECK(info.welded_vertex_count == 0);
    CHECK(info.flipped_polygon_count == 0);
    CHECK(same_agent(info.agent, nl_default_agent_type()));
    check_grid_navmesh(world, id, 4, NULL, "quads");

    /* Exact neighbours, found by position: across each inner edge lies the quadrant on the other side. */
    {
        uint32_t p, k, vertex_count = 0;
        float* xyz = navmesh_vertices(world, id, &vertex_count);
        int wrong = 0;
        for (p = 0; xyz && p < 4; ++p) {
            nl_nav_polygon poly;
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
                    nl_nav_polygon other;
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

static void test_navmesh_add_variants(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def;
    nl_navmesh_id id = {0u, 0u};
    nl_navmesh_info info;
    float soup[72];
    uint32_t soup_indices[24];
    g_section = "navmesh add: variants";
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

    /* Copies of a vertex up to 0.33 mm apart, no two equal: welded by the default tolerance (1 mm), not by
       tolerance 0. */
    {
        float jittered[72];
        int k;
        memcpy(jittered, soup, sizeof jittered);
        for (k = 0; k < 24; ++k) {
            jittered[3 * k + 0] += 1e-5f * (float)k;
            jittered[3 * k + 2] -= 1e-5f * (float)k;
        }
        def.vertices = jittered;
        def.weld_tolerance = 0.001f;
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
       first in a child (test_navmesh_isolated); here only if that did not crash. */
    if (CHECK_MSG(g_isolated[ISOLATED_WELD] >= 0,
                  "a weld tolerance of 1e-30 m on 1000 km squares crashed (in a child)")) {
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
        def.agent = agent;
        CHECK_OK(nl_navmesh_add(world, &def, &id));
        CHECK(same_agent(navmesh_info(world, id).agent, agent));
    }

    /* Repairs: a polygon of no area is dropped; an edge of three polygons connects none of them. */
    {
        static const float vertices[] = {
            -1.0f, GRID_Y, -1.0f, 0.0f, GRID_Y, -1.0f, 1.0f, GRID_Y, -1.0f, -1.0f, GRID_Y, 0.0f, 0.0f, GRID_Y, 0.0f,
            1.0f,  GRID_Y, 0.0f,  -1.0f, GRID_Y, 1.0f, 0.0f, GRID_Y, 1.0f, 1.0f, GRID_Y, 1.0f,
            0.5f,  1.5f,   -0.5f, /* 9: above quadrant 1 */
            -0.5f, GRID_Y, -1.0f, /* 10: on the edge 0-1 */
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
    -1.0f, GRID_Y, -1.0f, 0.0f, GRID_Y, -1.0f, 1.0f, GRID_Y, -1.0f, -1.0f, GRID_Y, 0.0f, 0.0f, GRID_Y, 0.0f,
    1.0f,  GRID_Y, 0.0f,  -1.0f, GRID_Y, 1.0f, 0.0f, GRID_Y, 1.0f, 1.0f, GRID_Y, 1.0f, 0.5f, 0.75f, 0.5f,
};
static const uint32_t k_detail_triangles[30] = {
    0, 3, 4, 0, 4, 1,                    /* quadrant 0 */
    1, 4, 5, 1, 5, 2,                    /* quadrant 1 */
    3, 6, 7, 3, 7, 4,                    /* quadrant 2 */
    4, 7, 9, 7, 8, 9, 8, 5, 9, 5, 4, 9, /* quadrant 3: the bump */
};
static const uint32_t k_detail_starts[5] = {0, 2, 4, 6, 10};

static nl_navmesh_def detail_grid_def(void) {
    nl_navmesh_def def = grid_def();
    set_navmesh_detail(&def, k_detail_vertices, 10, k_detail_triangles, 10, k_detail_starts);
    return def;
}

static void test_navmesh_detail(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = detail_grid_def();
    nl_navmesh_id flat = {0u, 0u}, bumpy = {0u, 0u};
    nl_navmesh_info info;
    const float half[3] = {0.25f, 3.0f, 0.25f};
    float points[9];
    nl_nav_point out[3];
    g_section = "navmesh detail";

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
        nl_nav_polygon poly;
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

/* ---------------------------------------------------------------------------------------------
 * nl_navmesh_add refusals
 * ------------------------------------------------------------------------------------------- */

/* One refused nl_navmesh_add: INVALID_ARGUMENT naming `needle`, nothing added, out_id untouched. */
#define CHECK_REJECTED_NAVMESH(world, def, needle) \
    check_rejected_navmesh((world), (def), (needle), __FILE__, __LINE__)
static void check_rejected_navmesh(nl_world* world, const nl_navmesh_def* def, const char* needle, const char* file,
                                   int line) {
    const uint32_t before = navmesh_count(world);
    nl_navmesh_id out = {77u, 77u};
    const nl_status status = nl_navmesh_add(world, def, &out);
    check_fail_at(status, NL_STATUS_INVALID_ARGUMENT, needle, "nl_navmesh_add", file, line);
    check_at(strstr(nl_get_last_error_message(), "nl_navmesh_add") != NULL, file, line,
             "the message does not name nl_navmesh_add (%s)", needle);
    check_at(out.index1 == 77u && out.generation == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(navmesh_count(world) == before, file, line, "a navmesh was added on failure (%s)", needle);
}

static void test_navmesh_rejections(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    float vertices[27];
    uint32_t quads[64]; /* room beyond the 16 used, so a wrong polygon size never reads past the array */
    uint8_t counts[4];
    g_section = "navmesh rejections";

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
        CHECK(out.index1 == 77u && out.generation == 77u);
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
    def.agent.radius = -1.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent.radius");
    def.agent = nl_default_agent_type();
    def.agent.height = 0.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent.height");
    def.agent = nl_default_agent_type();
    def.agent.max_slope = 90.0f;
    CHECK_REJECTED_NAVMESH(world, &def, "agent.max_slope");
    def.agent = nl_default_agent_type();
    def.agent.max_climb = NAN;
    CHECK_REJECTED_NAVMESH(world, &def, "agent.max_climb");
    def.agent = nl_default_agent_type();

    /* def->size too small (a zeroed def, one from a header that never existed). */
    def.size = 0;
    CHECK_REJECTED_NAVMESH(world, &def, "size");
    def.size = (uint32_t)sizeof def - 8u;
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

/* ---------------------------------------------------------------------------------------------
 * nl_navmesh_find_nearest
 * ------------------------------------------------------------------------------------------- */

static uint32_t polygon_of_quadrant(const nl_world* world, nl_navmesh_id id, int quadrant) {
    uint32_t p;
    for (p = 0; p < 4; ++p) {
        nl_nav_polygon poly;
        if (NL_SUCCEEDED(nl_navmesh_get_polygon(world, id, p, &poly)) &&
            quadrant_of(poly.centre[0], poly.centre[2]) == quadrant)
            return p;
    }
    return NL_NO_POLYGON;
}

static void test_find_nearest(void) {
    nl_world* world = make_world(1);
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
    g_section = "find_nearest";

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
    CHECK(out[4].found == 1);
    CHECK_NEAR(out[4].distance, 1.5f, TOL);
    CHECK_MSG(out[4].polygon == (by_quadrant[0] < by_quadrant[1] ? by_quadrant[0] : by_quadrant[1]),
              "a tie between polygons %u and %u went to %u, not the lower index", (unsigned)by_quadrant[0],
              (unsigned)by_quadrant[1], (unsigned)out[4].polygon);
    CHECK(out[5].found == 1);
    CHECK_NEAR(out[5].distance, 1.5f, TOL);
    CHECK_MSG(out[5].polygon == 0, "a tie between all four polygons went to %u, not 0", (unsigned)out[5].polygon);
    for (q = 0; q < 6; ++q) {
        CHECK_MSG(out[q].reserved[0] == 0 && out[q].reserved[1] == 0 && out[q].reserved[2] == 0,
                  "out[%d].reserved is not zero", q);
    }

    /* A smaller box: a point 1.5 m above the grid is out of reach of a box 1 m high. */
    {
        const float low[3] = {0.5f, 1.0f, 0.5f};
        CHECK_OK(nl_navmesh_find_nearest(world, id, points + 4 * 3, 1, low, out));
        CHECK(out[0].found == 0 && out[0].polygon == NL_NO_POLYGON);
    }

    /* Huge boxes on a navmesh of 1 cm squares: "anywhere" (half extents 1e9) from just above quadrant 3
       finds the point straight below; from the coordinate limit, a box that just reaches the squares
       finds them; a small box out there finds nothing. Run first in a child (test_navmesh_isolated); here
       only if that did not crash. */
    if (CHECK_MSG(g_isolated[ISOLATED_FAR] >= 0, "huge search boxes on 1 cm squares crashed (in a child)")) {
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
            {0.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {1.0f, 1.0f, -1.0f}, {-1.0f, -1.0f, -1.0f},
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
static void test_find_nearest_batches(void) {
    enum { side = 64, count = side * side };
    nl_world* worlds[2];
    nl_navmesh_id ids[2] = {{0u, 0u}, {0u, 0u}};
    float* points = (float*)malloc(3 * sizeof(float) * count);
    nl_nav_point* out[2];
    const float half[3] = {0.75f, 2.0f, 0.75f};
    int w, i, wrong = 0, found = 0;
    g_section = "find_nearest batches";
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

/* ---------------------------------------------------------------------------------------------
 * Lists (the two-call pattern), polygons and info
 * ------------------------------------------------------------------------------------------- */

static void test_navmesh_lists(void) {
    nl_world* world = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id ids[3], out_ids[5];
    float xyz[3 * 12];
    nl_boundary_edge edges[10];
    uint32_t count, i, j;
    g_section = "navmesh lists";

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
        nl_nav_polygon poly;
        memset(&poly, 0xcd, sizeof poly);
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], 4, &poly), "polygon");
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], UINT32_MAX, &poly), "polygon");
        CHECK_INVALID(nl_navmesh_get_polygon(world, ids[0], NL_NO_POLYGON, &poly), "polygon");
        CHECK(all_bytes(&poly, sizeof poly, 0xcd));
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

/* ---------------------------------------------------------------------------------------------
 * Ids: stale, null, another world's
 * ------------------------------------------------------------------------------------------- */

/* Every function that takes a navmesh id refuses `id` with INVALID_HANDLE, naming itself, writing nothing. */
#define CHECK_BAD_NAVMESH_ID(world, id) check_bad_navmesh_id((world), (id), __FILE__, __LINE__)
static void check_bad_navmesh_id(nl_world* world, nl_navmesh_id id, const char* file, int line) {
    nl_navmesh_info info;
    nl_nav_polygon poly;
    nl_boundary_edge edge;
    nl_nav_point nearest;
    float xyz[3];
    const float point[3] = {0.0f, 1.0f, 0.0f}, half[3] = {1.0f, 1.0f, 1.0f};
    uint32_t count = 0xdeadbeefu;
    const uint32_t before = navmesh_count(world);
    memset(&info, 0xab, sizeof info);
    memset(&poly, 0xab, sizeof poly);
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
    check_at(info.vertex_count == 0xabababab && all_bytes(&poly, sizeof poly, 0xab) &&
                 all_bytes(&edge, sizeof edge, 0xab) && all_bytes(&nearest, sizeof nearest, 0xab) &&
                 all_bytes(xyz, sizeof xyz, 0xab) && count == 0xdeadbeefu,
             file, line, "an output was written for a bad navmesh id");
    check_at(navmesh_count(world) == before, file, line, "the navmesh count changed");
}

static void test_navmesh_ids(void) {
    nl_world* world = make_world(1);
    nl_world* other = make_world(1);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id a = {0u, 0u}, b = {0u, 0u}, reused = {0u, 0u}, theirs = {0u, 0u};
    const nl_navmesh_id null_id = {0u, 0u};
    g_section = "navmesh ids";

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
        const nl_navmesh_id far = {1000u, 1u}, wrong_generation = {b.index1, b.generation + 1u};
        const nl_navmesh_id zero_generation = {b.index1, 0u};
        CHECK_BAD_NAVMESH_ID(world, far);
        CHECK_BAD_NAVMESH_ID(world, wrong_generation);
        CHECK_BAD_NAVMESH_ID(world, zero_generation);
    }

    /* A new navmesh may take the removed slot; the old id stays stale. */
    CHECK_OK(nl_navmesh_add(world, &def, &reused));
    CHECK(!same_navmesh(reused, a));
    CHECK_MSG(reused.index1 == a.index1, "slot not reused (old {%u,%u}, new {%u,%u}); the reuse check is vacuous",
              (unsigned)a.index1, (unsigned)a.generation, (unsigned)reused.index1, (unsigned)reused.generation);
    CHECK_BAD_NAVMESH_ID(world, a);
    CHECK(nl_navmesh_is_valid(world, reused) == 1);

    /* Another world's id, at a slot this world has in use as well. */
    CHECK_OK(nl_navmesh_add(other, &def, &theirs));
    CHECK(nl_navmesh_is_valid(other, theirs) == 1);
    CHECK_MSG(theirs.index1 == reused.index1 || theirs.index1 == b.index1,
              "the other world's id {%u,%u} shares no slot number with this world's; the check is weaker",
              (unsigned)theirs.index1, (unsigned)theirs.generation);
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

/* ---------------------------------------------------------------------------------------------
 * nl_navmesh_build with the built-in Recast builder
 * ------------------------------------------------------------------------------------------- */

/* A box 20 m x 1 m x 20 m, its top at y = 1: vertex k has x, y, z from bits 0, 1, 2 of k. */
static nl_mesh_id add_box(nl_world* world) {
    static const uint32_t box[36] = {2, 6, 7, 2, 7, 3,  /* top, +y */
                                     0, 1, 5, 0, 5, 4,  /* bottom, -y */
                                     1, 3, 7, 1, 7, 5,  /* +x */
                                     0, 4, 6, 0, 6, 2,  /* -x */
                                     4, 5, 7, 4, 7, 6,  /* +z */
                                     0, 2, 3, 0, 3, 1}; /* -z */
    float vertices[24];
    nl_mesh_def def = nl_default_mesh_def();
    nl_mesh_id id = {0u, 0u};
    int k;
    for (k = 0; k < 8; ++k) {
        vertices[3 * k + 0] = (k & 1) ? 10.0f : -10.0f;
        vertices[3 * k + 1] = (k & 2) ? 1.0f : 0.0f;
        vertices[3 * k + 2] = (k & 4) ? 10.0f : -10.0f;
    }
    def.vertices = vertices;
    def.vertex_count = 8;
    def.indices = box;
    def.triangle_count = 12;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    return id;
}

/* A built navmesh of the box: on its top (Recast's sits up to two cell heights above the floor, as the
   header says: from 1 to 1 + 2 * cell_height), inside it, and well-formed. */
static void check_box_navmesh(const nl_world* world, nl_navmesh_id id, nl_agent_type agent, float cell_height,
                              const char* label) {
    const float top = 1.0f, highest = top + 2.0f * cell_height + 1e-3f;
    const nl_navmesh_info info = navmesh_info(world, id);
    const float point[3] = {1.0f, 3.0f, -2.0f}, half[3] = {2.0f, 4.0f, 2.0f};
    nl_nav_point nearest;
    CHECK_MSG(info.polygon_count > 0 && info.vertex_count >= 3 && info.boundary_edge_count >= 3,
              "%s: %u polygons, %u vertices, %u boundary edges", label, (unsigned)info.polygon_count,
              (unsigned)info.vertex_count, (unsigned)info.boundary_edge_count);
    CHECK_MSG(same_agent(info.agent, agent), "%s: info.agent is (%g %g %g %g), the def's (%g %g %g %g)", label,
              info.agent.radius, info.agent.height, info.agent.max_climb, info.agent.max_slope, agent.radius,
              agent.height, agent.max_climb, agent.max_slope);
    /* On the top, inside the box, reaching near its edges (less the agent's radius). */
    CHECK_MSG(info.bounds_min[0] >= -10.0f && info.bounds_max[0] <= 10.0f && info.bounds_min[2] >= -10.0f &&
                  info.bounds_max[2] <= 10.0f && info.bounds_min[0] < -8.0f && info.bounds_max[0] > 8.0f &&
                  info.bounds_min[2] < -8.0f && info.bounds_max[2] > 8.0f,
              "%s: bounds x %g..%g, z %g..%g", label, info.bounds_min[0], info.bounds_max[0], info.bounds_min[2],
              info.bounds_max[2]);
    CHECK_MSG(info.bounds_min[1] >= top - 1e-3f && info.bounds_max[1] <= highest,
              "%s: bounds y %g..%g, the top is at %g (%g with two cell heights)", label, info.bounds_min[1],
              info.bounds_max[1], top, highest);
    CHECK_OK(nl_navmesh_find_nearest(world, id, point, 1, half, &nearest));
    CHECK_MSG(nearest.found == 1 && nearest.polygon < info.polygon_count && nearest.point[1] >= top - 1e-3f &&
                  nearest.point[1] <= highest && fabsf(nearest.point[0] - 1.0f) <= 1e-3f &&
                  fabsf(nearest.point[2] + 2.0f) <= 1e-3f,
              "%s: the point over the box's middle finds (%g %g %g) on polygon %u", label, nearest.point[0],
              nearest.point[1], nearest.point[2], (unsigned)nearest.polygon);
    check_navmesh_structure(world, id, label);
}

/* One refused nl_navmesh_build: `detail` naming `needle`, nothing added, out_id untouched. */
#define CHECK_BUILD_FAILS(world, def, detail, needle) \
    check_build_fails((world), (def), (detail), (needle), __FILE__, __LINE__)
static void check_build_fails(nl_world* world, const nl_navmesh_build_def* def, nl_status detail, const char* needle,
                              const char* file, int line) {
    const uint32_t before = navmesh_count(world);
    nl_navmesh_id out = {77u, 77u};
    const nl_status status = nl_navmesh_build(world, def, &out);
    check_fail_at(status, detail, needle, "nl_navmesh_build", file, line);
    check_at(strstr(nl_get_last_error_message(), "nl_navmesh_build") != NULL, file, line,
             "the message does not name nl_navmesh_build (%s)", needle);
    check_at(out.index1 == 77u && out.generation == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(navmesh_count(world) == before, file, line, "a navmesh was added on failure (%s)", needle);
}

static void test_navmesh_build(void) {
    nl_world* world = make_world(2);
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id id = {0u, 0u}, second = {0u, 0u};
    nl_agent_type agent;
    g_section = "navmesh build (recast)";

    /* An empty world: nothing to walk on is a failure, not an empty navmesh. */
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "walkable");
    /* Only a wall: nothing flat enough. */
    {
        static const float wall[] = {0, 0, 0, 0, 3, 0, 0, 3, 5, 0, 0, 5};
        static const uint32_t quad[] = {0, 1, 2, 0, 2, 3};
        nl_mesh_def mesh = nl_default_mesh_def();
        nl_mesh_id wall_id = {0u, 0u};
        mesh.vertices = wall;
        mesh.vertex_count = 4;
        mesh.indices = quad;
        mesh.triangle_count = 2;
        CHECK_OK(nl_mesh_add(world, &mesh, &wall_id));
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "walkable");
        CHECK_OK(nl_mesh_remove(world, wall_id));
    }

    add_box(world);
    agent.radius = 0.5f;
    agent.height = 1.8f;
    agent.max_climb = 0.4f;
    agent.max_slope = 40.0f;
    def.agent = agent;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(nl_navmesh_is_valid(world, id) == 1);
    CHECK(navmesh_count(world) == 1);
    check_box_navmesh(world, id, agent, 0.2f, "recast, defaults");

    /* builder NULL means "recast". */
    def.builder = NULL;
    CHECK_OK(nl_navmesh_build(world, &def, &second));
    CHECK(!same_navmesh(id, second));
    check_box_navmesh(world, second, agent, 0.2f, "recast, builder NULL");
    def.builder = "recast";

    /* Settings as JSON, and as a struct. */
    {
        static const char json[] = "{\"cell_size\": 0.2}";
        static const char json_more[] =
            "{\"cell_height\": 0.1, \"partition\": \"monotone\", \"vertices_per_polygon\": 3}";
        nl_recast_settings settings = nl_default_recast_settings();
        nl_navmesh_info info;
        def.settings_json = json;
        def.settings_json_length = strlen(json);
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.2f, "recast, cell_size 0.2 (JSON)");
        def.settings_json = json_more;
        def.settings_json_length = strlen(json_more);
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.1f, "recast, monotone triangles (JSON)");
        {
            /* vertices_per_polygon 3: every polygon a triangle. */
            uint32_t p, triangles = 1;
            info = navmesh_info(world, id);
            for (p = 0; p < info.polygon_count; ++p) {
                nl_nav_polygon poly;
                if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &poly)) || poly.vertex_count != 3) triangles = 0;
            }
            CHECK_THAT(triangles, "settings_json vertices_per_polygon 3 gives triangles only");
        }
        def.settings_json = NULL;
        def.settings_json_length = 0;
        settings.cell_size = 0.25f;
        def.settings = &settings;
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.2f, "recast, cell_size 0.25 (struct)");

        /* Struct and JSON together: the JSON is applied over the struct. */
        {
            static const char triangles_json[] = "{\"vertices_per_polygon\": 3}";
            uint32_t p, triangles = 1;
            def.settings_json = triangles_json;
            def.settings_json_length = strlen(triangles_json);
            CHECK_OK(nl_navmesh_build(world, &def, &id));
            check_box_navmesh(world, id, agent, 0.2f, "recast, struct and JSON");
            info = navmesh_info(world, id);
            for (p = 0; p < info.polygon_count; ++p) {
                nl_nav_polygon poly;
                if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &poly)) || poly.vertex_count != 3) triangles = 0;
            }
            CHECK_THAT(triangles, "settings_json vertices_per_polygon 3 applies over a struct's 6");
            /* An empty string is not a JSON object. */
            def.settings_json = "";
            def.settings_json_length = 0;
            CHECK_BUILD_FAILS(world, &def, NL_STATUS_PARSE_ERROR, "settings_json");
            def.settings_json = NULL;
        }

        /* Refused settings, each naming what is wrong. */
        settings.size = 0;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "size");
        settings = nl_default_recast_settings();
        settings.cell_size = 0.0f;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        settings = nl_default_recast_settings();
        settings.vertices_per_polygon = 7;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "vertices_per_polygon");
        def.settings = NULL;
    }
    {
        static const char negative[] = "{\"cell_size\": -1}";
        static const char malformed[] = "{bad json";
        static const char unknown[] = "{\"cell_size\": 0.3, \"cel_height\": 0.2}";
        static const char not_object[] = "[0.3]";
        static const char wrong_type[] = "{\"cell_size\": \"big\"}";
        def.settings_json = negative;
        def.settings_json_length = strlen(negative);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        def.settings_json = malformed;
        def.settings_json_length = strlen(malformed);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_PARSE_ERROR, "settings_json");
        def.settings_json = unknown;
        def.settings_json_length = strlen(unknown);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cel_height");
        {
            /* Valid JSON, but a navmesh 1e18 m high: the settings' fault (INVALID_ARGUMENT), not the builder's. */
            static const char huge_cell[] = "{\"cell_height\": 1.1e18}";
            def.settings_json = huge_cell;
            def.settings_json_length = strlen(huge_cell);
            CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_height");
        }
        def.settings_json = not_object;
        def.settings_json_length = strlen(not_object);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "settings_json");
        def.settings_json = wrong_type;
        def.settings_json_length = strlen(wrong_type);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        /* The JSON is `settings_json_length` bytes: what follows is not read. */
        def.settings_json = "{\"cell_size\": 0.3}{{{";
        def.settings_json_length = 18;
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        def.settings_json = NULL;
        def.settings_json_length = 3;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "settings_json");
        def.settings_json_length = 0;
    }

    /* No such builder: NOT_FOUND, listing the builders there are. */
    def.builder = "nope";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "'recast'");
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "nope");
    def.builder = "";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "'recast'");
    def.builder = "recast";

    /* A bad agent, a bad def. */
    def.agent.radius = -1.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "radius");
    def.agent = agent;
    def.agent.height = 0.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "height");
    def.agent = agent;
    def.agent.max_slope = 90.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "max_slope");
    def.agent = agent;
    def.size = 0;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "size");
    def.size = sizeof def;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        CHECK_INVALID(nl_navmesh_build(NULL, &def, &out), "world");
        CHECK_INVALID(nl_navmesh_build(world, NULL, &out), "def");
        CHECK_INVALID(nl_navmesh_build(world, &def, NULL), "out_id");
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Plugins registered from this program
 * ------------------------------------------------------------------------------------------- */

/* The test builder's behaviour, chosen per build through its settings struct. */
enum test_build_mode {
    MODE_GRID,                  /* hands the grid to the sink and returns what the sink said */
    MODE_SINK_TWICE,            /* hands it twice, returns the second answer */
    MODE_SINK_TWICE_SUCCEED,    /* hands it twice, returns success whatever the sink said */
    MODE_NO_SINK,               /* returns success without calling the sink */
    MODE_SINK_THEN_FAIL,        /* hands it over, then fails (NOT_FOUND) */
    MODE_BAD_INDEX,             /* hands over a grid with an index out of range, returns the sink's answer */
    MODE_BAD_INDEX_SUCCEED,     /* the same, returning success anyway */
    MODE_REPORT_ERROR,          /* set_error and INVALID_ARGUMENT, no sink */
    MODE_NULL_NAVMESH           /* calls the sink with NULL */
};

typedef struct test_builder_settings {
    uint32_t size;
    uint32_t mode;
} test_builder_settings;

typedef struct test_plugin_state {
    int entries_ok;     /* entry calls that returned success */
    int destroys;       /* destroy calls */
    int entry_checks;   /* entry calls that saw the host table and a zero-filled info as promised */
    int builds;
    int build_checks;   /* builds that saw their state, the host table and level triangle counts */
    nl_status sink_status[2];
    uint32_t level_vertices, level_triangles;
    nl_status short_copy_status; /* get_level_triangles with a buffer one vertex short */
    nl_agent_type agent;
} test_plugin_state;

static test_plugin_state g_plugin;

static int host_table_ok(uint32_t host_abi_version, const nl_plugin_host* host) {
    return host != NULL && host_abi_version == NL_PLUGIN_ABI_VERSION && host->size >= sizeof(nl_plugin_host) &&
           host->abi_version == NL_PLUGIN_ABI_VERSION && host->log != NULL && host->set_error != NULL &&
           host->get_level_triangles != NULL;
}

static void test_plugin_destroy(void* state) {
    if (state == &g_plugin) ++g_plugin.destroys;
}

static nl_status test_build(void* state, const nl_plugin_host* host, const nl_navmesh_build_def* def,
                            nl_navmesh_sink_fn* sink, void* sink_context) {
    test_plugin_state* self = (test_plugin_state*)state;
    const test_builder_settings* settings = (const test_builder_settings*)def->settings;
    const uint32_t mode = settings && settings->size >= sizeof *settings ? settings->mode : MODE_GRID;
    uint32_t bad_quads[16];
    nl_navmesh_def navmesh;
    nl_status status;
    ++self->builds;
    self->agent = def->agent;
    self->sink_status[0] = self->sink_status[1] = 0u;
    self->level_vertices = self->level_triangles = 0xdeadbeefu;
    self->short_copy_status = 0u;
    if (state == &g_plugin && host != NULL && host_table_ok(host->abi_version, host) &&
        NL_SUCCEEDED(host->get_level_triangles(host->context, NULL, 0, &self->level_vertices, NULL, 0,
                                               &self->level_triangles)))
        ++self->build_checks;
    if (self->level_vertices > 1 && self->level_vertices < 100 && self->level_triangles < 100) {
        float vertices[300];
        uint32_t indices[300], vertex_count = 0, triangle_count = 0;
        memset(vertices, 0, sizeof vertices);
        self->short_copy_status = host->get_level_triangles(host->context, vertices, self->level_vertices - 1,
                                                            &vertex_count, indices, 100, &triangle_count);
    }
    host->log(host->context, NL_LOG_DEBUG, "test builder: building");

    /* Filled by hand, as a plugin that uses no symbol of the library would. */
    memset(&navmesh, 0, sizeof navmesh);
    navmesh.size = (uint32_t)sizeof navmesh;
    navmesh.vertices = k_grid_vertices;
    navmesh.vertex_count = 9;
    navmesh.indices = k_grid_quads;
    navmesh.polygon_vertex_counts = k_quad_counts;
    navmesh.polygon_count = 4;
    navmesh.weld_tolerance = 0.001f;
    navmesh.agent = def->agent;
    switch (mode) {
    case MODE_GRID:
        return self->sink_status[0] = sink(sink_context, &navmesh);
    case MODE_SINK_TWICE:
        self->sink_status[0] = sink(sink_context, &navmesh);
        return self->sink_status[1] = sink(sink_context, &navmesh);
    case MODE_SINK_TWICE_SUCCEED:
        self->sink_status[0] = sink(sink_context, &navmesh);
        self->sink_status[1] = sink(sink_context, &navmesh);
        return NL_STATUS_SUCCESS;
    case MODE_NO_SINK:
        return NL_STATUS_SUCCESS;
    case MODE_SINK_THEN_FAIL:
        self->sink_status[0] = sink(sink_context, &navmesh);
        host->set_error(host->context, "test builder: changed its mind after the sink");
        return NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND;
    case MODE_BAD_INDEX:
    case MODE_BAD_INDEX_SUCCEED:
        memcpy(bad_quads, k_grid_quads, sizeof bad_quads);
        bad_quads[6] = 99;
        navmesh.indices = bad_quads;
        status = self->sink_status[0] = sink(sink_context, &navmesh);
        return mode == MODE_BAD_INDEX ? status : NL_STATUS_SUCCESS;
    case MODE_REPORT_ERROR:
        host->set_error(host->context, "test builder: setting 'flavour' must be 'vanilla'");
        return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    case MODE_NULL_NAVMESH:
        return self->sink_status[0] = sink(sink_context, NULL);
    default:
        return NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR;
    }
}

/* Checks what the host promises an entry function, then describes the plugin. */
static int entry_preamble(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    /* The host zero-fills the info and sets its size. */
    if (host_table_ok(host_abi_version, host) && out_info->size == sizeof(nl_plugin_info) &&
        out_info->abi_version == 0 && out_info->name == NULL && out_info->version == NULL &&
        out_info->description == NULL && out_info->kinds == 0 && out_info->state == NULL &&
        out_info->destroy == NULL && out_info->navmesh_builder.build == NULL)
        ++g_plugin.entry_checks;
    out_info->abi_version = NL_PLUGIN_ABI_VERSION;
    out_info->version = "2.5.1";
    out_info->description = "C test builder: a 2 x 2 grid";
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER;
    out_info->state = &g_plugin;
    out_info->destroy = test_plugin_destroy;
    out_info->navmesh_builder.build = test_build;
    ++g_plugin.entries_ok;
    return 1;
}

static nl_status entry_builder(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-builder";
    return NL_STATUS_SUCCESS;
}

/* The same plugin under another name, so each world can hold two. */
static nl_status entry_builder_two(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-builder-2";
    return NL_STATUS_SUCCESS;
}

static nl_status entry_links_only(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-links";
    out_info->kinds = NL_PLUGIN_LINK_KIND;
    out_info->navmesh_builder.build = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_named_recast(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "recast";
    return NL_STATUS_SUCCESS;
}

static nl_status entry_version_mismatch(uint32_t host_abi_version, const nl_plugin_host* host,
                                        nl_plugin_info* out_info) {
    (void)host_abi_version;
    (void)out_info;
    host->set_error(host->context, "c-test-old needs plugin ABI 7");
    return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
}

static nl_status entry_abi_zero(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-abi-zero";
    out_info->abi_version = 0;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_abi_newer(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-abi-newer";
    out_info->abi_version = host_abi_version + 1u;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_no_name(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_no_build(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-no-build";
    out_info->navmesh_builder.build = NULL;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_unknown_kind(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    entry_preamble(host_abi_version, host, out_info);
    out_info->name = "c-test-unknown-kind";
    out_info->kinds = NL_PLUGIN_NAVMESH_BUILDER | 0x100u;
    return NL_STATUS_SUCCESS;
}

static nl_status entry_refuses(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    (void)host_abi_version;
    (void)out_info;
    host->set_error(host->context, "c-test-refuses: no licence");
    return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
}

static nl_plugin_description describe(const nl_world* world, nl_plugin_id id) {
    nl_plugin_description d;
    memset(&d, 0, sizeof d);
    d.size = sizeof d;
    if (NL_FAILED(nl_plugin_get_description(world, id, &d))) memset(&d, 0, sizeof d);
    return d;
}

/* One refused nl_plugin_register: `detail` naming `needle`, nothing registered, out_id untouched. */
#define CHECK_REGISTER_FAILS(world, entry, detail, needle) \
    check_register_fails((world), (entry), (detail), (needle), __FILE__, __LINE__)
static void check_register_fails(nl_world* world, nl_plugin_entry_fn* entry, nl_status detail, const char* needle,
                                 const char* file, int line) {
    const uint32_t before = plugin_count(world);
    nl_plugin_id out = {77u, 77u};
    const nl_status status = nl_plugin_register(world, entry, &out);
    check_fail_at(status, detail, needle, "nl_plugin_register", file, line);
    check_at(out.index1 == 77u && out.generation == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(plugin_count(world) == before, file, line, "a plugin was registered on failure (%s)", needle);
}

static void test_plugins_listed(void) {
    nl_world* world = make_world(1);
    nl_plugin_id ids[4];
    uint32_t count = 0xdeadbeefu;
    nl_plugin_description d;
    g_section = "plugins: built in";

    CHECK_OK(nl_world_get_plugins(world, NULL, 0, &count));
    CHECK(count == 1);
    memset(ids, 0xcd, sizeof ids);
    CHECK_OK(nl_world_get_plugins(world, ids, 4, &count));
    CHECK(count == 1);
    CHECK(all_bytes(&ids[1], 3 * sizeof ids[0], 0xcd));
    d = describe(world, ids[0]);
    CHECK(d.size == sizeof d);
    CHECK(d.name != NULL && strcmp(d.name, "recast") == 0);
    CHECK(d.builtin == 1);
    CHECK(d.kinds == NL_PLUGIN_NAVMESH_BUILDER);
    CHECK(d.abi_version == NL_PLUGIN_ABI_VERSION);
    CHECK(d.version != NULL && d.version[0] != '\0');
    CHECK(d.description != NULL && d.description[0] != '\0');
    {
        /* The built-in plugin carries the library's version. */
        char expected[64];
        const nl_version v = nl_get_version();
        snprintf(expected, sizeof expected, "%d.%d.%d", (int)v.major, (int)v.minor, (int)v.patch);
        CHECK_MSG(d.version != NULL && strcmp(d.version, expected) == 0, "recast version \"%s\", library %s",
                  d.version ? d.version : "(null)", expected);
    }

    /* The two-call pattern. */
    memset(ids, 0xcd, sizeof ids);
    count = 0;
    CHECK_FAIL(nl_world_get_plugins(world, ids, 0, &count), NL_STATUS_BUFFER_TOO_SMALL, "capacity");
    CHECK(count == 1);
    CHECK(all_bytes(ids, sizeof ids, 0xcd));
    count = 0xdeadbeefu;
    CHECK_INVALID(nl_world_get_plugins(world, NULL, 2, &count), "out_ids");
    CHECK_INVALID(nl_world_get_plugins(world, ids, 4, NULL), "out_count");
    CHECK_INVALID(nl_world_get_plugins(NULL, ids, 4, &count), "world");

    /* Description failures. */
    {
        const nl_plugin_id null_id = {0u, 0u}, far = {1000u, 1u};
        CHECK_OK(nl_world_get_plugins(world, ids, 4, &count));
        memset(&d, 0xab, sizeof d);
        d.size = 0;
        CHECK_INVALID(nl_plugin_get_description(world, ids[0], &d), "size");
        CHECK(d.kinds == 0xabababab);
        d.size = sizeof d;
        CHECK_INVALID(nl_plugin_get_description(world, ids[0], NULL), "out_description");
        CHECK_INVALID(nl_plugin_get_description(NULL, ids[0], &d), "world");
        CHECK_FAIL(nl_plugin_get_description(world, null_id, &d), NL_STATUS_INVALID_HANDLE,
                   "nl_plugin_get_description");
        CHECK_FAIL(nl_plugin_get_description(world, far, &d), NL_STATUS_INVALID_HANDLE, "nl_plugin_get_description");
        CHECK(d.kinds == 0xabababab);
    }

    /* nl_plugin_load: arguments, then files that are not plugins. */
    {
        nl_plugin_id out = {77u, 77u};
        const char* text_path = "navlink_c_api_test_not_a_plugin.so";
        FILE* f;
        CHECK_INVALID(nl_plugin_load(world, NULL, &out), "path");
        CHECK_INVALID(nl_plugin_load(world, "navlink_c_api_test_missing_plugin.so", NULL), "out_id");
        CHECK_INVALID(nl_plugin_load(NULL, "navlink_c_api_test_missing_plugin.so", &out), "world");
        CHECK_FAIL(nl_plugin_load(world, "navlink_c_api_test_missing_plugin.so", &out), NL_STATUS_NOT_FOUND,
                   "navlink_c_api_test_missing_plugin.so");
        f = fopen(text_path, "wb");
        if (CHECK(f != NULL)) {
            fputs("this is not a shared library\n", f);
            fclose(f);
            CHECK_FAIL(nl_plugin_load(world, text_path, &out), NL_STATUS_IO_ERROR, text_path);
            remove(text_path);
        }
        CHECK(out.index1 == 77u && out.generation == 77u);
        CHECK(plugin_count(world) == 1);
    }
    nl_world_destroy(world);
}

static void test_plugins_registered(void) {
    nl_world* world;
    nl_plugin_id builder = {0u, 0u}, links = {0u, 0u}, second = {0u, 0u};
    nl_plugin_description d;
    const char *name, *version, *description;
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    test_builder_settings settings;
    nl_navmesh_id id = {0u, 0u};
    g_section = "plugins: registered";
    memset(&g_plugin, 0, sizeof g_plugin);

    world = make_world(1);
    add_box(world);
    CHECK_OK(nl_plugin_register(world, entry_builder, &builder));
    CHECK(builder.index1 != 0u);
    CHECK(g_plugin.entries_ok == 1 && g_plugin.entry_checks == 1);
    CHECK(plugin_count(world) == 2);
    {
        /* Built-in first, then in registration order. */
        nl_plugin_id ids[2];
        uint32_t count = 0;
        CHECK_OK(nl_world_get_plugins(world, ids, 2, &count));
        CHECK(count == 2 && same_plugin(ids[1], builder) && describe(world, ids[0]).builtin == 1);
    }
    d = describe(world, builder);
    CHECK(d.name != NULL && strcmp(d.name, "c-test-builder") == 0);
    CHECK(d.version != NULL && strcmp(d.version, "2.5.1") == 0);
    CHECK(d.description != NULL && strcmp(d.description, "C test builder: a 2 x 2 grid") == 0);
    CHECK(d.builtin == 0 && d.kinds == NL_PLUGIN_NAVMESH_BUILDER && d.abi_version == NL_PLUGIN_ABI_VERSION);
    name = d.name;
    version = d.version;
    description = d.description;

    /* Built through nl_navmesh_build with builder = its name: the builder got the def's agent, its
       state, the host's table and the level (the box: 8 vertices, 12 triangles). */
    def.builder = "c-test-builder";
    def.agent.radius = 0.35f;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(g_plugin.builds == 1 && g_plugin.build_checks == 1);
    CHECK(same_agent(g_plugin.agent, def.agent));
    CHECK_MSG(g_plugin.level_vertices == 8 && g_plugin.level_triangles == 12, "the level has %u vertices, %u triangles",
              (unsigned)g_plugin.level_vertices, (unsigned)g_plugin.level_triangles);
    CHECK(g_plugin.short_copy_status == (NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL));
    CHECK(g_plugin.sink_status[0] == NL_STATUS_SUCCESS);
    check_grid_navmesh(world, id, 4, NULL, "built by the C test builder");
    CHECK(same_agent(navmesh_info(world, id).agent, def.agent));
    CHECK(navmesh_count(world) == 1);

    /* Registering it again is refused by name; so is a plugin named like the built-in one. */
    CHECK_REGISTER_FAILS(world, entry_builder, NL_STATUS_INVALID_ARGUMENT, "c-test-builder");
    CHECK_REGISTER_FAILS(world, entry_named_recast, NL_STATUS_INVALID_ARGUMENT, "recast");
    /* Version negotiation. */
    CHECK_REGISTER_FAILS(world, entry_version_mismatch, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    CHECK_REGISTER_FAILS(world, entry_abi_zero, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    CHECK_REGISTER_FAILS(world, entry_abi_newer, NL_STATUS_VERSION_MISMATCH, "nl_plugin_register");
    /* Plugins that describe themselves wrongly, or refuse to start. */
    CHECK_REGISTER_FAILS(world, entry_no_name, NL_STATUS_INVALID_ARGUMENT, "name");
    CHECK_REGISTER_FAILS(world, entry_no_build, NL_STATUS_INVALID_ARGUMENT, "c-test-no-build");
    CHECK_REGISTER_FAILS(world, entry_unknown_kind, NL_STATUS_INVALID_ARGUMENT, "c-test-unknown-kind");
    {
        const uint32_t before = plugin_count(world);
        nl_plugin_id out = {77u, 77u};
        const nl_status status = nl_plugin_register(world, entry_refuses, &out);
        CHECK(NL_FAILED(status));
        CHECK(strstr(nl_get_last_error_message(), "no licence") != NULL);
        CHECK(out.index1 == 77u && plugin_count(world) == before);
    }
    /* Arguments. */
    {
        nl_plugin_id out = {77u, 77u};
        CHECK_INVALID(nl_plugin_register(world, NULL, &out), "entry");
        CHECK_INVALID(nl_plugin_register(world, entry_builder_two, NULL), "out_id");
        CHECK_INVALID(nl_plugin_register(NULL, entry_builder_two, &out), "world");
        CHECK(out.index1 == 77u);
    }

    /* A plugin that says it provides a link kind but fills no link-kind table is refused; it is
       no builder either. */
    CHECK_INVALID(nl_plugin_register(world, entry_links_only, &links), "link kind");
    def.builder = "c-test-links";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "c-test-links");
    {
        nl_navmesh_id out = {77u, 77u};
        CHECK_FAIL(nl_navmesh_build(world, &def, &out), NL_STATUS_NOT_FOUND, "c-test-links");
        CHECK_THAT(strstr(nl_get_last_error_message(), "'c-test-builder'") != NULL &&
                       strstr(nl_get_last_error_message(), "'recast'") != NULL,
                   "nl_navmesh_build: an unknown builder's message lists the builders there are");
    }
    CHECK_OK(nl_plugin_register(world, entry_builder_two, &second));
    CHECK(plugin_count(world) == 3);

    /* The description's strings are the world's: still there, unchanged, after all of that. */
    CHECK(strcmp(name, "c-test-builder") == 0);
    CHECK(strcmp(version, "2.5.1") == 0);
    CHECK(strcmp(description, "C test builder: a 2 x 2 grid") == 0);
    d = describe(world, builder);
    CHECK(d.name == name || strcmp(d.name, name) == 0);

    /* A builder's own failure, with the reason it gave. */
    def.builder = "c-test-builder";
    settings.size = sizeof settings;
    settings.mode = MODE_REPORT_ERROR;
    def.settings = &settings;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "'flavour' must be 'vanilla'");
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "c-test-builder");

    /* A builder that hands over an invalid navmesh: the navmesh's problem is in the message. */
    settings.mode = MODE_BAD_INDEX;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        const nl_status status = nl_navmesh_build(world, &def, &out);
        CHECK_MSG(NL_FAILED(status), "nl_navmesh_build with a builder whose navmesh is invalid returned 0x%08x",
                  (unsigned)status);
        CHECK(NL_FAILED(g_plugin.sink_status[0]));
        CHECK_MSG(strstr(nl_get_last_error_message(), "indices[6]") != NULL, "message \"%s\" lacks indices[6]",
                  nl_get_last_error_message());
        CHECK(strstr(nl_get_last_error_message(), "nl_navmesh_build") != NULL);
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    settings.mode = MODE_BAD_INDEX_SUCCEED;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        const nl_status status = nl_navmesh_build(world, &def, &out);
        CHECK_THAT(NL_FAILED(status) && strstr(nl_get_last_error_message(), "indices[6]") != NULL,
                   "nl_navmesh_build: a builder that ignores the sink's refusal and returns success still fails, "
                   "with the navmesh's problem");
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    settings.mode = MODE_NULL_NAVMESH;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        CHECK(NL_FAILED(nl_navmesh_build(world, &def, &out)));
        CHECK(NL_FAILED(g_plugin.sink_status[0]));
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    /* The other misbehaving builders (sink twice, no sink, sink then failure) are in
       test_plugin_misbehaviour, after running once each in a child process. */

    /* Still works after all the failures. */
    settings.mode = MODE_GRID;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    check_grid_navmesh(world, id, 4, NULL, "built after failures");
    def.settings = NULL;
    def.builder = "c-test-builder-2";
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(navmesh_count(world) == 3);

    /* Destroying the world destroys each plugin state the entry made, once. */
    nl_world_destroy(world);
    CHECK_MSG(g_plugin.destroys == g_plugin.entries_ok,
              "%d plugin states destroyed, %d made by successful entry calls (refused registrations included)",
              g_plugin.destroys, g_plugin.entries_ok);
    CHECK(g_plugin.entry_checks == g_plugin.entries_ok);

    /* Plugins are per world: a new world has only the built-in one, and takes the same names again. */
    world = make_world(1);
    CHECK(plugin_count(world) == 1);
    CHECK_OK(nl_plugin_register(world, entry_builder, &builder));
    CHECK(strcmp(describe(world, builder).name, "c-test-builder") == 0);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Misbehaving builders: a failure, never a crash, never a navmesh added behind the caller's back.
 * ------------------------------------------------------------------------------------------- */

static const struct misbehaviour {
    uint32_t mode;
    const char* what;
} k_misbehaviours[] = {
    {MODE_SINK_TWICE, "a builder that calls the sink twice (returning the second answer)"},
    {MODE_SINK_TWICE_SUCCEED, "a builder that calls the sink twice and returns success"},
    {MODE_NO_SINK, "a builder that returns success without calling the sink"},
    {MODE_SINK_THEN_FAIL, "a builder that fails after the sink took its navmesh"},
};
enum { k_misbehaviour_count = sizeof k_misbehaviours / sizeof k_misbehaviours[0] };

/* -1: the child crashed; 0: wrong answer; 1: a failure and nothing added. */
static int g_misbehaviour_isolated[k_misbehaviour_count];

/* Runs misbehaviour `m` on a fresh world; 1 if the build failed and added nothing. */
static int run_misbehaviour(size_t m) {
    nl_world* world = make_world(1);
    nl_plugin_id plugin = {0u, 0u};
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    test_builder_settings settings;
    nl_navmesh_id out = {77u, 77u};
    nl_status status;
    int ok;
    settings.size = sizeof settings;
    settings.mode = k_misbehaviours[m].mode;
    def.builder = "c-test-builder";
    def.settings = &settings;
    if (NL_FAILED(nl_plugin_register(world, entry_builder, &plugin))) {
        nl_world_destroy(world);
        return 0;
    }
    status = nl_navmesh_build(world, &def, &out);
    ok = NL_FAILED(status) && nl_get_last_error_message()[0] != '\0' && out.index1 == 77u && navmesh_count(world) == 0;
    nl_world_destroy(world);
    return ok;
}

static void test_plugin_misbehaviour(void) {
    size_t m;
    g_section = "plugins: misbehaving builders";
    for (m = 0; m < k_misbehaviour_count; ++m) {
        nl_world* world;
        nl_plugin_id plugin = {0u, 0u};
        nl_navmesh_build_def def = nl_default_navmesh_build_def();
        test_builder_settings settings;
        nl_navmesh_id out = {77u, 77u};
        nl_status status;
        if (!CHECK_MSG(g_misbehaviour_isolated[m] >= 0, "%s crashed the process (in a child)", k_misbehaviours[m].what))
            continue; /* it would crash this process too */
        world = make_world(1);
        settings.size = sizeof settings;
        settings.mode = k_misbehaviours[m].mode;
        def.builder = "c-test-builder";
        def.settings = &settings;
        CHECK_OK(nl_plugin_register(world, entry_builder, &plugin));
        status = nl_navmesh_build(world, &def, &out);
        CHECK_MSG(NL_FAILED(status), "%s: nl_navmesh_build returned 0x%08x (%s)", k_misbehaviours[m].what,
                  (unsigned)status, nl_status_string(status));
        CHECK_MSG(strstr(nl_get_last_error_message(), "c-test-builder") != NULL,
                  "%s: the message names the builder: \"%s\"", k_misbehaviours[m].what, nl_get_last_error_message());
        CHECK_MSG(out.index1 == 77u && out.generation == 77u, "%s: out_id was written", k_misbehaviours[m].what);
        CHECK_MSG(navmesh_count(world) == 0, "%s: the failed build left %u navmesh(es) in the world",
                  k_misbehaviours[m].what, (unsigned)navmesh_count(world));
        nl_world_destroy(world);
    }
}

/* ---------------------------------------------------------------------------------------------
 * Threads: queries on one navmesh while other navmeshes come and go.
 * ------------------------------------------------------------------------------------------- */

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

static void test_navmesh_threads(void) {
    enum { thread_count = 3 };
    nl_world* world = make_world(2);
    nl_navmesh_def def = grid_def();
    nl_navmesh_id id = {0u, 0u};
    navmesh_job jobs[thread_count];
    pthread_t threads[thread_count];
    int started[thread_count];
    float far_vertices[27];
    int i, q, edits_ok = 1;
    g_section = "navmesh threads";

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

/* ---------------------------------------------------------------------------------------------
 * Entry points
 * ------------------------------------------------------------------------------------------- */

/* Runs `fn(arg)` in a child process: 1 if it returned nonzero, 0 if zero, -1 if the child crashed or
   was stopped by a sanitizer (which exits with status 1: a wrong answer exits with 3). */
static int run_forked(int (*fn)(size_t), size_t arg) {
    pid_t pid;
    int status = 0;
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        if (!freopen("/dev/null", "w", stderr)) { /* a library's abort message is not this test's output */
        }
        _exit(fn(arg) ? 0 : 3);
    }
    if (waitpid(pid, &status, 0) != pid) return 0;
    if (!WIFEXITED(status)) return -1;
    return WEXITSTATUS(status) == 0 ? 1 : WEXITSTATUS(status) == 3 ? 0 : -1;
}

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

void test_navmesh_isolated(void) {
    size_t m;
    g_section = "navmesh extremes (isolated)";
    g_isolated[ISOLATED_WELD] = run_forked(isolated_weld, 0);
    CHECK_MSG(g_isolated[ISOLATED_WELD] == 1, "nl_navmesh_add: weld tolerance 1e-30 m on 1000 km squares (%s)",
              g_isolated[ISOLATED_WELD] < 0 ? "crashed, or a sanitizer stopped it" : "wrong answer");
    g_isolated[ISOLATED_FAR] = run_forked(isolated_far, 0);
    CHECK_MSG(g_isolated[ISOLATED_FAR] == 1,
              "nl_navmesh_find_nearest: half extents 1e9 over 1 cm squares find the polygon below (%s)",
              g_isolated[ISOLATED_FAR] < 0 ? "crashed, or a sanitizer stopped it" : "wrong answer");
    g_section = "plugins: misbehaving builders (isolated)";
    for (m = 0; m < k_misbehaviour_count; ++m) {
        g_misbehaviour_isolated[m] = run_forked(run_misbehaviour, m);
        CHECK_MSG(g_misbehaviour_isolated[m] == 1, "%s: %s", k_misbehaviours[m].what,
                  g_misbehaviour_isolated[m] < 0 ? "crashed, or a sanitizer stopped it"
                                                 : "did not fail cleanly (a success, or a navmesh left in the world)");
    }
}

void test_navmesh_all(void) {
    test_defaults();
    test_navmesh_add_grid();
    test_navmesh_add_variants();
    test_navmesh_detail();
    test_navmesh_rejections();
    test_find_nearest();
    test_find_nearest_batches();
    test_navmesh_lists();
    test_navmesh_ids();
    test_navmesh_build();
    test_plugins_listed();
    test_plugins_registered();
    test_plugin_misbehaviour();
    test_navmesh_threads();
}
