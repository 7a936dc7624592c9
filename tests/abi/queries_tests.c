/*
 * abi.queries: reachability, the navmesh raycast and slide, and random points, on navmeshes drawn as
 * rows of 1 m cells whose answers are known exactly. Strict C11 through the C ABI only.
 */
/* pthread for the querying threads; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "navmesh_scene.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* A navmesh of 1 m cells at y = 0: row r is z in [r, r + 1], column c is x in [c, c + 1]. '.' is
   area 0, a digit that area, anything else no navmesh. Cells become polygons in reading order. */
typedef struct cell_navmesh {
    float vertices[256 * 4 * 3];
    uint32_t indices[256 * 4];
    uint8_t counts[256];
    uint8_t areas[256];
    uint32_t polygons;
} cell_navmesh;

static nl_navmesh_def cell_def(cell_navmesh* m, const char* const* rows, int row_count) {
    nl_navmesh_def def = nl_default_navmesh_def();
    uint32_t v = 0;
    int r, c;
    m->polygons = 0;
    for (r = 0; r < row_count; ++r) {
        for (c = 0; rows[r][c] != '\0'; ++c) {
            const char cell = rows[r][c];
            const float x0 = (float)c, z0 = (float)r;
            const float corners[4][2] = {{x0, z0}, {x0, z0 + 1.0f}, {x0 + 1.0f, z0 + 1.0f}, {x0 + 1.0f, z0}};
            int k;
            if (cell != '.' && (cell < '0' || cell > '9')) continue;
            for (k = 0; k < 4; ++k) {
                m->vertices[3 * v] = corners[k][0];
                m->vertices[3 * v + 1] = 0.0f;
                m->vertices[3 * v + 2] = corners[k][1];
                m->indices[v] = v;
                ++v;
            }
            m->counts[m->polygons] = 4;
            m->areas[m->polygons] = cell == '.' ? 0 : (uint8_t)(cell - '0');
            ++m->polygons;
        }
    }
    def.vertices = m->vertices;
    def.vertex_count = v;
    def.indices = m->indices;
    def.polygon_vertex_counts = m->counts;
    def.polygon_count = m->polygons;
    def.areas = m->areas;
    def.agent_type.radius = 0.0f;
    return def;
}

static nl_navmesh_id add_cells(nl_world* world, const char* const* rows, int row_count) {
    static cell_navmesh m;
    const nl_navmesh_def def = cell_def(&m, rows, row_count);
    nl_navmesh_id id = {0u, 0u};
    CHECK_OK(nl_navmesh_add(world, &def, &id));
    return id;
}

/* A one-way manual link between the centres of two cells of row 0 (its gap is its length). */
static void add_link(nl_world* world, nl_navmesh_id navmesh, float from_x, float to_x) {
    nl_link_def def = nl_default_link_def();
    nl_link_id id;
    def.start[0] = from_x + 0.5f;
    def.start[2] = 0.5f;
    def.end[0] = to_x + 0.5f;
    def.end[2] = 0.5f;
    CHECK_OK(nl_link_add(world, navmesh, &def, &id));
}

static nl_query_filter jumper(float distance) {
    nl_query_filter f = nl_default_query_filter();
    f.capabilities.radius = 0.0f;
    f.capabilities.max_jump_distance = distance;
    return f;
}

static int can_reach(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter, uint32_t from,
                     uint32_t to) {
    uint8_t reachable = 0xab;
    if (!NL_SUCCEEDED(nl_navmesh_can_reach(world, navmesh, filter, &from, &to, 1, &reachable))) return -1;
    return reachable;
}

static void reachability(void) {
    /* Polygons 0-1 | 2-3 | 4-5: three islands; a link from column 1 to column 3 joins the first two one way. */
    const char* rows[] = {"..#..#.."};
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = add_cells(world, rows, 1);
    const nl_query_filter walker = jumper(0.0f), able = jumper(3.0f);
    uint32_t from[3] = {0, 3, 5}, to[3] = {3, 0, 4};
    uint8_t answers[3];
    uint32_t listed[8], count = 0, islands[6], island_count = 0;
    add_link(world, navmesh, 1.0f, 3.0f);

    CHECK(can_reach(world, navmesh, &walker, 0, 1) == 1);
    CHECK(can_reach(world, navmesh, &walker, 0, 2) == 0);
    CHECK_THAT(can_reach(world, navmesh, NULL, 0, 1) == 0,
               "the default walker (radius 0.6) does not fit the 1 m corridor of a navmesh built for radius 0");
    CHECK(can_reach(world, navmesh, &walker, 1, 2) == 0);
    CHECK_THAT(can_reach(world, navmesh, &able, 0, 3) == 1, "a body that can take the link reaches the next island");
    CHECK_THAT(can_reach(world, navmesh, &able, 3, 0) == 0, "a one-way link does not lead back");
    CHECK_OK(nl_navmesh_can_reach(world, navmesh, &able, from, to, 3, answers));
    CHECK(answers[0] == 1 && answers[1] == 0 && answers[2] == 1);

    CHECK_OK(nl_navmesh_get_reachable_polygons(world, navmesh, &able, 1, NULL, 0, &count));
    CHECK(count == 4);
    CHECK_FAIL(nl_navmesh_get_reachable_polygons(world, navmesh, &able, 1, listed, 3, &count),
               NL_STATUS_BUFFER_TOO_SMALL, "capacity is 3");
    CHECK_OK(nl_navmesh_get_reachable_polygons(world, navmesh, &able, 1, listed, 8, &count));
    CHECK(count == 4 && listed[0] == 0 && listed[1] == 1 && listed[2] == 2 && listed[3] == 3);

    CHECK_OK(nl_navmesh_get_islands(world, navmesh, &able, islands, 6, &count, &island_count));
    CHECK(count == 6 && island_count == 3);
    CHECK(islands[0] == 0 && islands[1] == 0 && islands[2] == 1 && islands[3] == 1 && islands[4] == 2 &&
          islands[5] == 2);

    /* Keeping out of area 0 leaves no island; a body standing in one still walks out. */
    {
        const float keep_out[1] = {NL_AREA_EXCLUDED};
        nl_query_filter excluded = able;
        excluded.area_costs = keep_out;
        excluded.area_cost_count = 1;
        CHECK_OK(nl_navmesh_get_islands(world, navmesh, &excluded, islands, 6, &count, &island_count));
        CHECK(island_count == 0 && islands[0] == NL_NO_ISLAND && islands[5] == NL_NO_ISLAND);
        CHECK(can_reach(world, navmesh, &excluded, 0, 1) == 0);
        CHECK(can_reach(world, navmesh, &excluded, 0, 0) == 1);
    }

    /* Out of range and refused filters. */
    {
        uint32_t bad = 6, good = 0;
        nl_query_filter negative = able;
        negative.capabilities.max_drop_height = -1.0f;
        CHECK_INVALID(nl_navmesh_can_reach(world, navmesh, &able, &good, &bad, 1, answers), "to_polygons[0] is 6");
        CHECK_INVALID(nl_navmesh_can_reach(world, navmesh, &negative, &good, &good, 1, answers),
                      "filter->capabilities.max_drop_height");
        CHECK_INVALID(nl_navmesh_get_reachable_polygons(world, navmesh, &walker, 9, NULL, 0, &count),
                      "from_polygon is 9");
    }
    nl_world_destroy(world);
}

static void no_path_at_once(void) {
    /* Two rooms with no way between: a request that does not accept partial paths searches once, and
       is then answered by the map its search left built. */
    const char* rows[] = {"....#...."};
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = add_cells(world, rows, 1);
    nl_path_request_def def = nl_default_path_request_def();
    nl_path_result result;
    uint32_t count;
    result = nl_path_result_init();
    def.navmesh = navmesh;
    def.start[0] = 0.5f;
    def.start[2] = 0.5f;
    def.goal[0] = 8.5f;
    def.goal[2] = 0.5f;
    def.capabilities.radius = 0.0f;
    def.accept_partial = 0;
    CHECK_OK(nl_path_find(world, &def, &result, NULL, 0, &count));
    /* Searched (no map was built): the cells it could walk through, not the dead end at the wall. */
    CHECK(result.outcome == NL_PATH_NO_PATH && result.nodes_visited == 3);
    def.goal[0] = 7.5f;
    CHECK_OK(nl_path_find(world, &def, &result, NULL, 0, &count));
    CHECK(result.outcome == NL_PATH_NO_PATH);
    CHECK_THAT(result.nodes_visited == 0,
               "after a search found a goal out of reach, the reachability map answers the next one without a search");
    def.accept_partial = 1;
    nl_path_find(world, &def, &result, NULL, 0, &count);
    CHECK(result.outcome == NL_PATH_PARTIAL && result.nodes_visited == 4);
    nl_world_destroy(world);
}

static nl_navmesh_ray ray(uint32_t polygon, float x0, float z0, float x1, float z1) {
    nl_navmesh_ray r;
    r.start[0] = x0, r.start[1] = 0.0f, r.start[2] = z0;
    r.start_polygon = polygon;
    r.end[0] = x1, r.end[1] = 0.0f, r.end[2] = z1;
    return r;
}

static void raycast(void) {
    /* A room 4 x 2 with a wall cell at column 0 of row 2; area 5 at column 3 of row 1. */
    const char* rows[] = {"....", "...5", "#..."};
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = add_cells(world, rows, 3);
    /* Along row 0 to its far cell; down column 0 toward z = 4.5 (the missing cell of row 2 is a wall at
       z = 2); across row 1 into area 5. */
    const nl_navmesh_ray rays[3] = {ray(0, 0.5f, 0.5f, 3.5f, 0.5f), ray(0, 0.5f, 0.5f, 0.5f, 4.5f),
                                    ray(4, 0.5f, 1.5f, 3.9f, 1.5f)};
    nl_navmesh_raycast_hit hits[3];
    uint32_t crossed[3 * 8];
    hits[0] = nl_navmesh_raycast_hit_init();

    CHECK_OK(nl_navmesh_raycast(world, navmesh, NULL, rays, 3, hits, crossed, 8));
    CHECK(hits[0].hit == 0 && hits[0].t == 1.0f && near3(hits[0].point, 3.5f, 0.0f, 0.5f, TOL));
    CHECK(hits[0].polygon_count == 4 && crossed[0] == 0 && crossed[3] == 3 && hits[0].end_polygon == 3);
    CHECK(hits[0].wall_normal[0] == 0.0f && hits[0].wall_normal[2] == 0.0f);
    CHECK_THAT(hits[1].hit == 1, "nl_navmesh_raycast: a walk into a missing cell stops at its wall");
    CHECK(hits[1].size == sizeof(nl_navmesh_raycast_hit));
    CHECK_NEAR(hits[1].t, 1.5f / 4.0f, TOL);
    CHECK(near3(hits[1].point, 0.5f, 0.0f, 2.0f, TOL));
    CHECK(near3(hits[1].wall_normal, 0.0f, 0.0f, -1.0f, TOL));
    CHECK(hits[1].polygon_count == 2 && crossed[8] == 0 && crossed[9] == 4 && hits[1].end_polygon == 4);
    CHECK(hits[2].hit == 0 && hits[2].end_polygon == 7 && hits[2].polygon_count == 4);

    /* Fewer polygons than crossed: the first ones, and the count of all. */
    {
        uint32_t two[3 * 2];
        CHECK_OK(nl_navmesh_raycast(world, navmesh, NULL, rays, 3, hits, two, 2));
        CHECK(hits[0].polygon_count == 4 && two[0] == 0 && two[1] == 1 && two[2] == 0 && two[3] == 4);
    }
    { /* A filter keeping out of area 5 makes it a wall at x = 3. */
        const float costs[6] = {1, 1, 1, 1, 1, NL_AREA_EXCLUDED};
        nl_query_filter filter = nl_default_query_filter();
        filter.area_costs = costs;
        filter.area_cost_count = 6;
        CHECK_OK(nl_navmesh_raycast(world, navmesh, &filter, rays + 2, 1, hits, NULL, 0));
        CHECK(hits[0].hit == 1 && near3(hits[0].point, 3.0f, 0.0f, 1.5f, TOL) &&
              near3(hits[0].wall_normal, -1.0f, 0.0f, 0.0f, TOL));
    }
    { /* A ray whose start is not over its polygon: the whole batch is refused, nothing written. */
        nl_navmesh_ray bad[2];
        bad[0] = rays[0];
        bad[1] = ray(2, 0.5f, 0.5f, 1.0f, 1.0f);
        memset(hits, 0xab, sizeof hits);
        hits[0] = nl_navmesh_raycast_hit_init();
        CHECK_INVALID(nl_navmesh_raycast(world, navmesh, NULL, bad, 2, hits, NULL, 0),
                      "rays[1].start is not over rays[1].start_polygon 2");
        CHECK(hits[0].hit == 0 && hits[0].t == 0.0f && all_bytes(&hits[1], sizeof hits[1], 0xab));
    }
    /* Two triangles overlapping across a shared edge run the same way (a host navmesh the builder
       accepts): a ray crossing that edge must not bounce between them; the second one's far side is
       a wall. */
    {
        static const float v[] = {0, 0, 0, 1, 0, 0, 0.5f, 0, 1, 0.5f, 0, 2};
        static const uint32_t tris[] = {0, 1, 2, 0, 1, 3};
        static const uint8_t counts[] = {3, 3};
        nl_navmesh_def def = nl_default_navmesh_def();
        nl_navmesh_id overlapping;
        nl_navmesh_ray down = ray(0, 0.5f, 0.3f, 0.5f, -5.0f);
        uint32_t polygons[8];
        def.vertices = v, def.vertex_count = 4, def.indices = tris, def.polygon_vertex_counts = counts;
        def.polygon_count = 2, def.agent_type.radius = 0.0f;
        if (CHECK_OK(nl_navmesh_add(world, &def, &overlapping))) {
            CHECK_OK(nl_navmesh_raycast(world, overlapping, NULL, &down, 1, hits, polygons, 8));
            CHECK_THAT(hits[0].polygon_count <= 2 && hits[0].hit == 1 && hits[0].t < 0.1f,
                       "nl_navmesh_raycast: a ray between overlapping polygons stops, never bounces");
            CHECK(length3(hits[0].wall_normal) > 0.99f);
        }
    }
    /* The same answers from a world with more workers and a batch large enough to be split. */
    {
        nl_world* wide = make_world(2);
        const nl_navmesh_id wide_navmesh = add_cells(wide, rows, 3);
        enum { kBatch = 1000 };
        nl_navmesh_ray* many = (nl_navmesh_ray*)malloc(sizeof(nl_navmesh_ray) * kBatch);
        nl_navmesh_raycast_hit* one = (nl_navmesh_raycast_hit*)malloc(sizeof(nl_navmesh_raycast_hit) * kBatch);
        nl_navmesh_raycast_hit* two = (nl_navmesh_raycast_hit*)malloc(sizeof(nl_navmesh_raycast_hit) * kBatch);
        int i;
        for (i = 0; i < kBatch; ++i) many[i] = rays[i % 3], many[i].end[0] += 0.001f * (float)(i % 7);
        one[0] = nl_navmesh_raycast_hit_init();
        two[0] = nl_navmesh_raycast_hit_init();
        CHECK_OK(nl_navmesh_raycast(world, navmesh, NULL, many, kBatch, one, NULL, 0));
        CHECK_OK(nl_navmesh_raycast(wide, wide_navmesh, NULL, many, kBatch, two, NULL, 0));
        CHECK_THAT(memcmp(one, two, sizeof(nl_navmesh_raycast_hit) * kBatch) == 0,
                   "nl_navmesh_raycast: the same answers on 1 and 2 workers");
        free(many);
        free(one);
        free(two);
        nl_world_destroy(wide);
    }
    nl_world_destroy(world);
}

static void move_along_surface(void) {
    const char* rows[] = {"....", "....", "#..."};
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = add_cells(world, rows, 3);
    const float start[3] = {0.5f, 0.0f, 1.5f};
    nl_nav_point moved;
    uint32_t visited[16], count = 0;
    { /* Straight there. */
        const float target[3] = {2.5f, 0.0f, 0.5f};
        CHECK_OK(nl_navmesh_move_along_surface(world, navmesh, NULL, 4, start, target, &moved, visited, 16, &count));
        CHECK(moved.found == 1 && near3(moved.point, 2.5f, 0.0f, 0.5f, TOL) && moved.polygon == 2 &&
              moved.distance == 0.0f);
        CHECK(count >= 2 && visited[0] == 4 && visited[count - 1] == 2);
        {
            const uint32_t all = count;
            CHECK_FAIL(
                nl_navmesh_move_along_surface(world, navmesh, NULL, 4, start, target, &moved, visited, 1, &count),
                NL_STATUS_BUFFER_TOO_SMALL, "visited");
            CHECK_THAT(count == all && visited[0] == 4,
                       "a slide's out_count is how many it visited, also when they did not fit");
        }
    }
    { /* Into the missing cell: slides to the nearest point of its wall, z = 2 under the target. */
        const float target[3] = {0.3f, 0.0f, 2.5f};
        CHECK_OK(nl_navmesh_move_along_surface(world, navmesh, NULL, 4, start, target, &moved, NULL, 0, NULL));
        CHECK_THAT(near3(moved.point, 0.3f, 0.0f, 2.0f, TOL) && moved.polygon == 4,
                   "nl_navmesh_move_along_surface: a move into a wall slides to the wall's nearest point");
        CHECK_NEAR(moved.distance, 0.5f, TOL);
    }
    nl_world_destroy(world);
}

static void random_points(void) {
    /* Four cells in a row, the third of area 2; and an island of one cell. */
    const char* rows[] = {"..2.#."};
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = add_cells(world, rows, 1);
    enum { kCount = 20000 };
    nl_nav_point* points = (nl_nav_point*)malloc(sizeof(nl_nav_point) * kCount);
    nl_nav_point* again = (nl_nav_point*)malloc(sizeof(nl_nav_point) * kCount);
    nl_random_points_def def = nl_default_random_points_def();
    uint32_t found = 0, per_polygon[5] = {0, 0, 0, 0, 0}, i, inside = 1;
    CHECK(def.radius == 0.0f && def.reachable_from == NL_NO_POLYGON && def.seed == 1 && def.filter == NULL);

    /* Uniform by area over the whole navmesh: 4000 per cell, give or take 5 standard deviations (~280). */
    CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, points, kCount, &found));
    CHECK(found == kCount);
    for (i = 0; i < found; ++i) {
        if (points[i].polygon < 5) ++per_polygon[points[i].polygon];
        inside = inside && points[i].found == 1 && points[i].point[1] == 0.0f &&
                 points[i].point[0] >= (float)(points[i].polygon < 4 ? points[i].polygon : 5) &&
                 points[i].point[0] <= (float)(points[i].polygon < 4 ? points[i].polygon : 5) + 1.0f;
    }
    CHECK_THAT(inside, "every random point lies on its polygon");
    for (i = 0; i < 5; ++i)
        CHECK_MSG(abs((int)per_polygon[i] - 4000) < 280, "polygon %u got %u points of 20000", i, per_polygon[i]);

    /* The same seed, the same points; another seed, others. */
    CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, again, kCount, &found));
    CHECK(memcmp(points, again, sizeof(nl_nav_point) * kCount) == 0);
    def.seed = 2;
    CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, again, kCount, &found));
    CHECK(memcmp(points, again, sizeof(nl_nav_point) * kCount) != 0);

    /* Within 1 m of (1, 0, 0.5): the parts of cells 0 and 1 inside the circle, seen from above, in
       equal shares (cell 2 only touches it). */
    {
        uint32_t in_circle = 1;
        def.centre[0] = 1.0f;
        def.centre[2] = 0.5f;
        def.radius = 1.0f;
        memset(per_polygon, 0, sizeof per_polygon);
        CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, points, kCount, &found));
        CHECK(found == kCount);
        for (i = 0; i < found; ++i) {
            const float dx = points[i].point[0] - 1.0f, dz = points[i].point[2] - 0.5f;
            in_circle = in_circle && dx * dx + dz * dz <= 1.0f + 1e-5f;
            if (points[i].polygon < 5) ++per_polygon[points[i].polygon];
        }
        CHECK_THAT(in_circle, "nl_navmesh_random_points: every point lies within the radius");
        CHECK(per_polygon[2] == 0 && per_polygon[3] == 0 && per_polygon[4] == 0);
        CHECK_MSG(abs((int)per_polygon[0] - (int)per_polygon[1]) < 5 * 142, "cells 0 and 1 got %u and %u",
                  per_polygon[0], per_polygon[1]);
    }

    /* Keeping out of area 2 and only what polygon 0 reaches: cells 0 and 1. */
    {
        const float costs[3] = {1, 1, NL_AREA_EXCLUDED};
        nl_query_filter filter = nl_default_query_filter();
        uint32_t only_first_two = 1;
        filter.capabilities.radius = 0.0f;
        filter.area_costs = costs;
        filter.area_cost_count = 3;
        def.radius = 0.0f;
        def.filter = &filter;
        def.reachable_from = 0;
        CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, points, 1000, &found));
        CHECK(found == 1000);
        for (i = 0; i < found; ++i) only_first_two = only_first_two && points[i].polygon < 2;
        CHECK_THAT(only_first_two, "random points keep to the polygons reachable from reachable_from");
        def.reachable_from = 2; /* in the excluded area: walks out both ways */
        CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, points, 1000, &found));
        CHECK(found == 1000);
        /* A circle with no allowed polygon: none. */
        def.reachable_from = NL_NO_POLYGON;
        def.centre[0] = 2.5f;
        def.radius = 0.4f;
        CHECK_OK(nl_navmesh_random_points(world, navmesh, &def, points, 10, &found));
        CHECK(found == 0 && points[0].found == 0 && points[9].polygon == NL_NO_POLYGON);
    }
    free(points);
    free(again);
    nl_world_destroy(world);
}

/* Queries from several threads while another one adds and removes links: every answer is one of
   the two the links allow (a map of the links before or after an edit), never a crash or a race. */
typedef struct query_job {
    nl_world* world;
    nl_navmesh_id navmesh;
    float jump; /* the body's jump distance: 0 never reaches, 3 reaches while the link is there */
    int wrong, failures;
} query_job;

static void* query_thread(void* arg) {
    query_job* job = (query_job*)arg;
    nl_query_filter filter = jumper(job->jump);
    const uint32_t from[2] = {0, 3}, to[2] = {3, 0};
    int i;
    for (i = 0; i < 2000; ++i) {
        uint8_t answers[2];
        uint32_t count = 0;
        filter.capabilities.max_jump_height = (float)(i % 4); /* four bodies of one class: one map */
        if (NL_FAILED(nl_navmesh_can_reach(job->world, job->navmesh, &filter, from, to, 2, answers)) ||
            NL_FAILED(nl_navmesh_get_reachable_polygons(job->world, job->navmesh, &filter, 1, NULL, 0, &count))) {
            ++job->failures;
            continue;
        }
        if (answers[1] != 0 || (job->jump == 0.0f && answers[0] != 0) || (count != 2 && count != 4)) ++job->wrong;
    }
    return NULL;
}

static void threads(void) {
    const char* rows[] = {"..#..#.."};
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = add_cells(world, rows, 1);
    enum { kThreads = 4 };
    query_job jobs[kThreads];
    pthread_t ids[kThreads];
    int started[kThreads], i;
    for (i = 0; i < kThreads; ++i) {
        jobs[i].world = world;
        jobs[i].navmesh = navmesh;
        jobs[i].jump = (i & 1) ? 3.0f : 0.0f;
        jobs[i].wrong = jobs[i].failures = 0;
        started[i] = pthread_create(&ids[i], NULL, query_thread, &jobs[i]) == 0;
    }
    for (i = 0; i < 200; ++i) { /* the link comes and goes */
        nl_link_def def = nl_default_link_def();
        nl_link_id link;
        def.start[0] = 1.5f, def.start[2] = 0.5f;
        def.end[0] = 3.5f, def.end[2] = 0.5f;
        if (NL_SUCCEEDED(nl_link_add(world, navmesh, &def, &link))) nl_link_remove(world, link);
    }
    for (i = 0; i < kThreads; ++i) {
        if (started[i]) pthread_join(ids[i], NULL);
        CHECK(started[i]);
        CHECK_MSG(jobs[i].failures == 0 && jobs[i].wrong == 0, "thread %d: %d failures, %d wrong answers", i,
                  jobs[i].failures, jobs[i].wrong);
    }
    nl_world_destroy(world);
}

ABI_SECTION(queries, ABI_CASE(reachability), ABI_CASE(no_path_at_once), ABI_CASE(raycast), ABI_CASE(move_along_surface),
            ABI_CASE(random_points), ABI_CASE(threads));
