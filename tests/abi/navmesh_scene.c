/* The grid, the box and the navmesh checks of navmesh_scene.h. */
#include "navmesh_scene.h"

#include "abi_test.h"
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const float k_grid_vertices[27] = {
    -1.0f, GRID_Y, -1.0f, 0.0f, GRID_Y, -1.0f, 1.0f, GRID_Y, -1.0f, /* row z = -1: 0 1 2 */
    -1.0f, GRID_Y, 0.0f,  0.0f, GRID_Y, 0.0f,  1.0f, GRID_Y, 0.0f,  /* row z = 0:  3 4 5 */
    -1.0f, GRID_Y, 1.0f,  0.0f, GRID_Y, 1.0f,  1.0f, GRID_Y, 1.0f,  /* row z = 1:  6 7 8 */
};
const uint32_t k_grid_quads[16] = {
    0, 3, 4, 1, /* quadrant 0: x in [-1, 0], z in [-1, 0] */
    1, 4, 5, 2, /* quadrant 1: x in [0, 1],  z in [-1, 0] */
    3, 6, 7, 4, /* quadrant 2: x in [-1, 0], z in [0, 1] */
    4, 7, 8, 5, /* quadrant 3: x in [0, 1],  z in [0, 1] */
};
const uint8_t k_quad_counts[4] = {4, 4, 4, 4};

/* The grid with polygon_vertex_counts: four quads. */
nl_navmesh_def grid_def(void) { return navmesh_def_of(k_grid_vertices, 9, k_grid_quads, k_quad_counts, 4); }

/* Which quadrant of the grid a point (seen from above) lies in; the point must not be on x = 0 or z = 0. */
int quadrant_of(float x, float z) { return (z > 0.0f ? 2 : 0) + (x > 0.0f ? 1 : 0); }

uint32_t navmesh_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_navmeshes(world, NULL, 0, &count);
    return count;
}

uint32_t plugin_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_plugins(world, NULL, 0, &count);
    return count;
}

int same_navmesh(nl_navmesh_id a, nl_navmesh_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

int same_plugin(nl_plugin_id a, nl_plugin_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

int same_agent(nl_agent_type a, nl_agent_type b) {
    return a.radius == b.radius && a.height == b.height && a.max_climb == b.max_climb && a.max_slope == b.max_slope;
}

nl_navmesh_info navmesh_info(const nl_world* world, nl_navmesh_id id) {
    nl_navmesh_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_get_info(world, id, &info))) memset(&info, 0, sizeof info);
    return info;
}

/* The navmesh's vertices in a malloc'ed array (3 floats each); NULL on failure. */
const char* navmesh_made_for(const nl_world* world, nl_navmesh_id id) {
    static char json[4096];
    static unsigned char file[65536];
    size_t size = 0, length = 0;
    json[0] = '\0';
    if (NL_FAILED(nl_navmesh_save(world, id, file, sizeof file, &size)) ||
        NL_FAILED(nl_navmesh_file_describe(file, size, NULL, json, sizeof json, &length)))
        CHECK_MSG(0, "saving and describing the navmesh failed: %s", nl_get_last_error_message());
    return json;
}

float* navmesh_vertices(const nl_world* world, nl_navmesh_id id, uint32_t* out_count) {
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

nl_boundary_edge* navmesh_edges(const nl_world* world, nl_navmesh_id id, uint32_t* out_count) {
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

float dot3(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

float length3(const float* a) { return sqrtf(dot3(a, a)); }

int near3(const float* a, float x, float y, float z, float tol) {
    return fabsf(a[0] - x) <= tol && fabsf(a[1] - y) <= tol && fabsf(a[2] - z) <= tol;
}

int equal3(const float* a, const float* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* Twice the signed area of a polygon seen from above; positive when counter-clockwise with +Y up. */
float area_from_above(const float* xyz, const nl_nav_polygon* p) {
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
int check_navmesh_structure(const nl_world* world, nl_navmesh_id id, const char* label) {
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
        polygons[p] = nl_nav_polygon_init();
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
        bad += !CHECK_MSG(equal3(edge->normal, poly->normal), "%s: boundary edge %u normal is not its polygon's", label,
                          (unsigned)e);
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
void check_grid_navmesh(const nl_world* world, nl_navmesh_id id, uint32_t polygons, const uint8_t* areas,
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
        nl_nav_polygon poly = nl_nav_polygon_init();
        memset(&poly, 0xcd, sizeof poly);
        poly.size = sizeof poly; /* the element size the library lays out with */
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
            nl_nav_polygon poly = nl_nav_polygon_init();
            CHECK_MSG((ox != 0.0f) != (oz != 0.0f), "%s: boundary edge %u (mid %g %g) is not on the outline", label,
                      (unsigned)i, mx, mz);
            CHECK_MSG(near3(e->outward, ox, 0.0f, oz, TOL), "%s: edge %u outward (%g %g %g), expected (%g 0 %g)", label,
                      (unsigned)i, e->outward[0], e->outward[1], e->outward[2], ox, oz);
            CHECK_MSG(e->outward[0] * mx + e->outward[2] * mz > 0.0f, "%s: edge %u outward points to the centre", label,
                      (unsigned)i);
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

/* A box 20 m x 1 m x 20 m, its top at y = 1: vertex k has x, y, z from bits 0, 1, 2 of k. */
nl_mesh_id add_floor_box(nl_world* world) {
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

void check_build_fails(nl_world* world, const nl_navmesh_build_def* def, nl_status detail, const char* needle,
                       const char* file, int line) {
    const uint32_t before = navmesh_count(world);
    nl_navmesh_id out = {77u, 77u};
    const nl_status status = nl_navmesh_build(world, def, &out);
    check_fail_at(status, detail, needle, "nl_navmesh_build", file, line);
    check_at(strstr(nl_get_last_error_message(), "nl_navmesh_build") != NULL, file, line,
             "the message does not name nl_navmesh_build (%s)", needle);
    check_at(out.index1 == 77u && out.revision == 77u, file, line, "out_id was written on failure (%s)", needle);
    check_at(navmesh_count(world) == before, file, line, "a navmesh was added on failure (%s)", needle);
}

nl_plugin_description describe(const nl_world* world, nl_plugin_id id) {
    nl_plugin_description d;
    memset(&d, 0, sizeof d);
    d.size = sizeof d;
    if (NL_FAILED(nl_plugin_get_description(world, id, &d))) memset(&d, 0, sizeof d);
    return d;
}

static void keep_warning(void* user, nl_log_level level, nl_status status, const char* message) {
    warnings* w = (warnings*)user;
    size_t used = strlen(w->text);
    (void)status;
    if (level != NL_LOG_WARNING) return;
    ++w->count;
    snprintf(w->text + used, sizeof w->text - used, "%s\n", message);
}

nl_world* make_listening_world(warnings* heard) {
    nl_world_def def = nl_default_world_def();
    nl_world* world = NULL;
    memset(heard, 0, sizeof *heard);
    def.worker_count = 2;
    def.log_fn = keep_warning;
    def.log_user = heard;
    CHECK_OK(nl_world_create(&def, &world));
    return world;
}
