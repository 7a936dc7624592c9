/*
 * The hostile cases of navlink/queries.h: query filters, reachability, islands, moves along the
 * surface, raycasts and random points, on A's navmesh (the gap level): a walk on the near
 * platform from polygon g_near.
 */
#include "hostile_fixtures.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

static const float k_walk_start[3] = {-6.0f, 0.0f, 0.0f};
static const float k_walk_end[3] = {-7.0f, 0.0f, 1.0f};
static uint32_t g_near = NL_NO_POLYGON; /* the polygon under k_walk_start */

static uint32_t polygon_under(const float* point) {
    const float extents[3] = {1.0f, 2.0f, 1.0f};
    nl_nav_point p;
    return NL_SUCCEEDED(nl_navmesh_find_nearest(A.world, A.navmesh, point, 1, extents, &p)) && p.found ? p.polygon
                                                                                                       : NL_NO_POLYGON;
}
static uint32_t near_polygon(void) {
    if (g_near == NL_NO_POLYGON) g_near = polygon_under(k_walk_start);
    return g_near;
}

static const float_field k_filter_floats[] = {
    FLOAT_FIELD(nl_query_filter, capabilities.max_jump_distance, 1),
    FLOAT_FIELD(nl_query_filter, capabilities.max_jump_height, 1),
    FLOAT_FIELD(nl_query_filter, capabilities.max_drop_height, 1),
    FLOAT_FIELD(nl_query_filter, capabilities.radius, 1),
};

static const def_case k_filter_defs[] = {
    {"filter->capabilities.radius negative", INVALID, "radius", {SET_F32(nl_query_filter, capabilities.radius, -1.0f)}},
    {"filter->area_costs NULL (area_cost_count 3)",
     INVALID,
     "area_costs",
     {SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_cost_count huge (area_costs NULL: not read)",
     INVALID,
     "area_cost_count",
     {SET_U32(nl_query_filter, area_cost_count, UINT32_MAX)}},
    {"filter->area_cost_count 257",
     INVALID,
     "area_cost_count",
     {SET_PTR(nl_query_filter, area_costs, k_costs_257), SET_U32(nl_query_filter, area_cost_count, 257u)}},
    {"filter->area_costs NaN ([1])",
     INVALID,
     "area_costs[1]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_nan), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_costs inf ([1])",
     INVALID,
     "area_costs[1]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_inf), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_costs negative ([2])",
     INVALID,
     "area_costs[2]",
     {SET_PTR(nl_query_filter, area_costs, k_costs_negative), SET_U32(nl_query_filter, area_cost_count, 3u)}},
    {"filter->area_cost_count 0 (allowed: area_costs not read)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_query_filter, area_costs, "not floats"), SET_U32(nl_query_filter, area_cost_count, 0u)}},
};

/* The query the filter cases run now: it calls its function with `filter` and every other argument
   valid, its outputs in `out` (filled by the caller). */
typedef nl_status query_call_fn(const nl_query_filter* filter, void* out);
static query_call_fn* g_query;
static size_t g_query_out_size;
static size_t g_query_out_skip; /* bytes the call sets itself (an output's size) */

static void query_refuses(const void* filter, nl_status detail, const char* needle) {
    aligned_buffer out;
    fill(out.bytes, sizeof out.bytes);
    EXPECT_FAILURE(A.world, g_query((const nl_query_filter*)filter, out.bytes), detail, needle);
    EXPECT_UNTOUCHED(out.bytes + g_query_out_skip, g_query_out_size - g_query_out_skip, "the outputs");
}
static void query_accepts(const void* filter) {
    aligned_buffer out;
    fill(out.bytes, sizeof out.bytes);
    EXPECT_OK(g_query((const nl_query_filter*)filter, out.bytes));
}

/* Everything about a query's filter: NULL (the defaults), its sizes, areas and capabilities. */
static void filter_cases(const char* function, query_call_fn* call, size_t out_size, size_t out_skip) {
    nl_query_filter valid = nl_default_query_filter();
    g_query = call;
    g_query_out_size = out_size;
    g_query_out_skip = out_skip;
    CASE(function, "filter NULL (allowed: the default walker)") { query_accepts(NULL); }
    def_sizes(function, "filter", &valid, sizeof valid, query_refuses, query_accepts);
    def_cases(function, &valid, sizeof valid, k_filter_defs, sizeof k_filter_defs / sizeof *k_filter_defs,
              query_refuses, query_accepts);
    bad_float_fields(function, "filter", &valid, sizeof valid, k_filter_floats,
                     sizeof k_filter_floats / sizeof *k_filter_floats, query_refuses);
}

static void group_default_query_filter(void) {
    CASE("nl_default_query_filter", "the defaults") {
        const nl_query_filter f = nl_default_query_filter();
        const nl_agent_capabilities walker = nl_default_agent_capabilities();
        EXPECT(f.size == sizeof f && f.area_costs == NULL && f.area_cost_count == 0 && f.reserved == 0 &&
                   memcmp(&f.capabilities, &walker, sizeof walker) == 0,
               "not a default walker keeping out of no area");
    }
}

/* nl_navmesh_can_reach: two pairs, (near, near) and (near, 0). */
static uint32_t g_reach_from[2], g_reach_to[2];
static nl_status can_reach_call(const nl_query_filter* filter, void* out) {
    g_reach_from[0] = g_reach_from[1] = g_reach_to[0] = near_polygon();
    g_reach_to[1] = 0;
    return nl_navmesh_can_reach(A.world, A.navmesh, filter, g_reach_from, g_reach_to, 2, (uint8_t*)out);
}
static nl_status can_reach_id_call(nl_world* w, raw_id id, void* out) {
    g_reach_from[0] = g_reach_from[1] = g_reach_to[0] = g_reach_to[1] = 0;
    return nl_navmesh_can_reach(w, AS(nl_navmesh_id, id), NULL, g_reach_from, g_reach_to, 2, (uint8_t*)out);
}

static void group_navmesh_can_reach(void) {
    static const id_function f = {"nl_navmesh_can_reach", "navmesh", "out_reachable", 2, 0, 0, can_reach_id_call, 0};
    const uint32_t zero = 0, beyond = 1000000u;
    uint8_t answer[2];
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases("nl_navmesh_can_reach", can_reach_call, sizeof answer, 0);
    CASE("nl_navmesh_can_reach", "from_polygons NULL") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, &zero, 1, answer),
                       "from_polygons");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "to_polygons NULL") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &zero, NULL, 1, answer), "to_polygons");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "count 0 (allowed, with the arrays and out_reachable NULL)") {
        EXPECT_OK(nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, NULL, 0, NULL));
    }
    CASE("nl_navmesh_can_reach", "count huge (from_polygons NULL: not read)") {
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, NULL, &zero, UINT32_MAX, answer),
                       "from_polygons");
    }
    CASE("nl_navmesh_can_reach", "from_polygons out of range (1000000)") {
        fill(answer, sizeof answer);
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &beyond, &zero, 1, answer),
                       "from_polygons[0]");
        EXPECT_UNTOUCHED(answer, sizeof answer, "out_reachable");
    }
    CASE("nl_navmesh_can_reach", "to_polygons NL_NO_POLYGON") {
        const uint32_t none = NL_NO_POLYGON;
        EXPECT_INVALID(A.world, nl_navmesh_can_reach(A.world, A.navmesh, NULL, &zero, &none, 1, answer),
                       "to_polygons[0]");
    }
}

static nl_status list_reachable(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_reachable_polygons(w, n, NULL, 0, (uint32_t*)out, capacity, count);
}
static nl_status reachable_call(const nl_query_filter* filter, void* out) {
    uint32_t* listed = (uint32_t*)out; /* the count first, then room for the polygons */
    return nl_navmesh_get_reachable_polygons(A.world, A.navmesh, filter, near_polygon(), listed + 1,
                                             (uint32_t)(sizeof(aligned_buffer) / 4 - 1), listed);
}

static void group_navmesh_get_reachable_polygons(void) {
    uint32_t count = 0;
    nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, 0, NULL, 0, &count);
    navmesh_list_cases("nl_navmesh_get_reachable_polygons", "out_polygons", sizeof(uint32_t), count, list_reachable);
    filter_cases("nl_navmesh_get_reachable_polygons", reachable_call, 4, 0);
    CASE("nl_navmesh_get_reachable_polygons", "from_polygon 0 (allowed)") {
        EXPECT_OK(nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, 0, NULL, 0, &count));
        EXPECT(count >= 1, "polygon 0 reaches %u polygons", (unsigned)count);
    }
    CASE("nl_navmesh_get_reachable_polygons", "from_polygon huge") {
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world,
                       nl_navmesh_get_reachable_polygons(A.world, A.navmesh, NULL, UINT32_MAX, NULL, 0, &count),
                       "from_polygon");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
}

static nl_status list_islands(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_islands(w, n, NULL, (uint32_t*)out, capacity, count, NULL);
}
static nl_status islands_call(const nl_query_filter* filter, void* out) {
    uint32_t* counts = (uint32_t*)out;
    return nl_navmesh_get_islands(A.world, A.navmesh, filter, NULL, 0, &counts[0], &counts[1]);
}

static void group_navmesh_get_islands(void) {
    navmesh_list_cases("nl_navmesh_get_islands", "out_islands", sizeof(uint32_t),
                       navmesh_info(&A, A.navmesh).polygon_count, list_islands);
    filter_cases("nl_navmesh_get_islands", islands_call, 8, 0);
    CASE("nl_navmesh_get_islands", "out_island_count NULL (allowed)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_get_islands(A.world, A.navmesh, NULL, NULL, 0, &count, NULL));
    }
    CASE("nl_navmesh_get_islands", "out_island_count given: at least one island") {
        uint32_t count = 0, islands = 0;
        EXPECT_OK(nl_navmesh_get_islands(A.world, A.navmesh, NULL, NULL, 0, &count, &islands));
        EXPECT(islands >= 1 && islands <= count, "%u islands of %u polygons", (unsigned)islands, (unsigned)count);
    }
}

/* nl_navmesh_move_along_surface from k_walk_start toward k_walk_end. */
static nl_status move_filter_call(const nl_query_filter* filter, void* out) {
    return nl_navmesh_move_along_surface(A.world, A.navmesh, filter, near_polygon(), k_walk_start, k_walk_end,
                                         (nl_nav_point*)out, NULL, 0, NULL);
}
static nl_status move_id_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_move_along_surface(w, AS(nl_navmesh_id, id), NULL, 0, k_walk_start, k_walk_end,
                                         (nl_nav_point*)out, NULL, 0, NULL);
}
static void move_refused(uint32_t polygon, const float* start, const float* target, uint32_t* polygons,
                         uint32_t capacity, const char* needle) {
    nl_nav_point out;
    uint32_t count;
    fill(&out, sizeof out);
    fill(&count, sizeof count);
    EXPECT_INVALID(A.world,
                   nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, polygon, start, target, &out, polygons,
                                                 capacity, &count),
                   needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_point");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
}

static void group_navmesh_move_along_surface(void) {
    static const char* const function = "nl_navmesh_move_along_surface";
    static const id_function f = {
        "nl_navmesh_move_along_surface", "navmesh", "out_point", sizeof(nl_nav_point), 0, 0, move_id_call, 0};
    const float far_platform[3] = {6.0f, 0.0f, 0.0f};
    size_t v;
    int k, which;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases(function, move_filter_call, sizeof(nl_nav_point), 0);
    CASE(function, "start_polygon 0 or any other the start is not over (the far platform's): refused") {
        move_refused(polygon_under(far_platform), k_walk_start, k_walk_end, NULL, 0, "start is not over start_polygon");
    }
    CASE(function, "start_polygon huge") {
        move_refused(UINT32_MAX, k_walk_start, k_walk_end, NULL, 0, "start_polygon");
    }
    CASE(function, "start NULL") { move_refused(near_polygon(), NULL, k_walk_end, NULL, 0, "start"); }
    CASE(function, "target NULL") { move_refused(near_polygon(), k_walk_start, NULL, NULL, 0, "target"); }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE(function, "%s[%d] %s", which == 0 ? "start" : "target", k, k_bad_floats[v].name) {
                    float start[3], target[3];
                    memcpy(start, k_walk_start, sizeof start);
                    memcpy(target, k_walk_end, sizeof target);
                    (which == 0 ? start : target)[k] = k_bad_floats[v].value;
                    move_refused(near_polygon(), start, target, NULL, 0, which == 0 ? "start" : "target");
                }
            }
        }
    }
    CASE(function, "target beyond the limit (2e9)") {
        const float far[3] = {2.0e9f, 0.0f, 0.0f};
        move_refused(near_polygon(), k_walk_start, far, NULL, 0, "target");
    }
    CASE(function, "out_polygons NULL (capacity 1)") {
        move_refused(near_polygon(), k_walk_start, k_walk_end, NULL, 1, "out_polygons");
    }
    CASE(function, "capacity huge (out_polygons NULL)") {
        move_refused(near_polygon(), k_walk_start, k_walk_end, NULL, UINT32_MAX, "out_polygons");
    }
    CASE(function, "capacity 0 (a buffer given: BUFFER_TOO_SMALL, the point written, the count of all)") {
        nl_nav_point out;
        uint32_t polygons[4], count = 0;
        fill(polygons, sizeof polygons);
        EXPECT_FAILURE(A.world,
                       nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, near_polygon(), k_walk_start, k_walk_end,
                                                     &out, polygons, 0, &count),
                       NL_STATUS_BUFFER_TOO_SMALL, "capacity is 0");
        EXPECT(count >= 1 && out.found == 1, "out_count %u, found %u", (unsigned)count, (unsigned)out.found);
        EXPECT_UNTOUCHED(polygons, sizeof polygons, "out_polygons");
    }
    CASE(function, "out_count NULL (allowed)") {
        nl_nav_point out;
        uint32_t polygons[64];
        EXPECT_OK(nl_navmesh_move_along_surface(A.world, A.navmesh, NULL, near_polygon(), k_walk_start, k_walk_end,
                                                &out, polygons, 64, NULL));
        EXPECT(polygons[0] == near_polygon(), "the first polygon is %u, not the start's", (unsigned)polygons[0]);
    }
}

/* nl_navmesh_raycast: two rays from k_walk_start, the second one made bad by the cases. */
static nl_navmesh_ray walk_ray(void) {
    nl_navmesh_ray r;
    memcpy(r.start, k_walk_start, sizeof r.start);
    memcpy(r.end, k_walk_end, sizeof r.end);
    r.start_polygon = near_polygon();
    return r;
}
static void raycast_refused(const nl_navmesh_ray* rays, uint32_t count, uint32_t* polygons, uint32_t per_ray,
                            const char* needle) {
    nl_navmesh_raycast_hit hits[2];
    fill(hits, sizeof hits);
    set_size(hits, (uint32_t)sizeof hits[0]);
    EXPECT_INVALID(A.world, nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, count, hits, polygons, per_ray), needle);
    EXPECT_UNTOUCHED((unsigned char*)hits + 4, sizeof hits - 4, "out_hits");
}
static nl_status raycast_filter_call(const nl_query_filter* filter, void* out) {
    const nl_navmesh_ray r = walk_ray();
    set_size(out, (uint32_t)sizeof(nl_navmesh_raycast_hit));
    return nl_navmesh_raycast(A.world, A.navmesh, filter, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}
static nl_status raycast_id_call(nl_world* w, raw_id id, void* out) {
    nl_navmesh_ray r = walk_ray();
    r.start_polygon = 0;
    if (out) set_size(out, (uint32_t)sizeof(nl_navmesh_raycast_hit));
    return nl_navmesh_raycast(w, AS(nl_navmesh_id, id), NULL, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}
static nl_status raycast_into(void* out) {
    const nl_navmesh_ray r = walk_ray();
    return nl_navmesh_raycast(A.world, A.navmesh, NULL, &r, 1, (nl_navmesh_raycast_hit*)out, NULL, 0);
}

static void group_navmesh_raycast(void) {
    static const char* const function = "nl_navmesh_raycast";
    static const id_function f = {"nl_navmesh_raycast", "navmesh", "out_hits", sizeof(nl_navmesh_raycast_hit), 1, 0,
                                  raycast_id_call,      0};
    const float far_platform[3] = {6.0f, 0.0f, 0.0f};
    nl_navmesh_ray rays[2];
    size_t v;
    int k, which;
    rays[0] = rays[1] = walk_ray();
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    filter_cases(function, raycast_filter_call, sizeof(nl_navmesh_raycast_hit), 4);
    out_sizes(function, "out_hits", sizeof(nl_navmesh_raycast_hit), raycast_into);
    CASE(function, "rays NULL") { raycast_refused(NULL, 2, NULL, 0, "rays"); }
    CASE(function, "count 0 (allowed, rays and out_hits NULL)") {
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, NULL, 0, NULL, NULL, 0));
    }
    CASE(function, "count huge (rays NULL: not read)") { raycast_refused(NULL, UINT32_MAX, NULL, 0, "rays"); }
    CASE(function, "rays->start_polygon of another polygon (the far platform's): refused, naming the ray") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].start_polygon = polygon_under(far_platform);
        raycast_refused(bad, 2, NULL, 0, "rays[1].start is not over rays[1].start_polygon");
    }
    CASE(function, "rays->start_polygon huge") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].start_polygon = UINT32_MAX;
        raycast_refused(bad, 2, NULL, 0, "rays[1].start_polygon");
    }
    for (which = 0; which < 2; ++which) {
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE(function, "rays->%s[%d] %s (ray 1)", which == 0 ? "start" : "end", k, k_bad_floats[v].name) {
                    nl_navmesh_ray bad[2] = {rays[0], rays[1]};
                    (which == 0 ? bad[1].start : bad[1].end)[k] = k_bad_floats[v].value;
                    raycast_refused(bad, 2, NULL, 0, which == 0 ? "rays[1].start" : "rays[1].end");
                }
            }
        }
    }
    CASE(function, "rays->end beyond the limit (2e9, ray 1)") {
        nl_navmesh_ray bad[2] = {rays[0], rays[1]};
        bad[1].end[0] = 2.0e9f;
        raycast_refused(bad, 2, NULL, 0, "rays[1].end");
    }
    CASE(function, "out_polygons NULL (polygons_per_ray 1)") { raycast_refused(rays, 2, NULL, 1, "out_polygons"); }
    CASE(function, "polygons_per_ray huge (out_polygons NULL)") {
        raycast_refused(rays, 2, NULL, UINT32_MAX, "out_polygons");
    }
    CASE(function, "polygons_per_ray 0 (allowed with out_polygons NULL)") {
        nl_navmesh_raycast_hit hits[2];
        hits[0] = nl_navmesh_raycast_hit_init();
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, 2, hits, NULL, 0));
        EXPECT(hits[1].size == sizeof hits[1] && hits[1].polygon_count >= 1, "second hit: size %u, %u polygons",
               (unsigned)hits[1].size, (unsigned)hits[1].polygon_count);
    }
    CASE(function, "polygons_per_ray 1 (the first polygon of each ray; the count of all)") {
        nl_navmesh_raycast_hit hits[2];
        uint32_t polygons[2];
        hits[0] = nl_navmesh_raycast_hit_init();
        EXPECT_OK(nl_navmesh_raycast(A.world, A.navmesh, NULL, rays, 2, hits, polygons, 1));
        EXPECT(polygons[0] == near_polygon() && polygons[1] == near_polygon(), "first polygons %u, %u",
               (unsigned)polygons[0], (unsigned)polygons[1]);
    }
}

/* nl_navmesh_random_points: three points with a def. */
static const float_field k_random_floats[] = {
    FLOAT_FIELD(nl_random_points_def, centre, 3),
    FLOAT_FIELD(nl_random_points_def, radius, 1),
};
static const nl_query_filter k_bad_filter = {sizeof(nl_query_filter), {0.0f, 0.0f, -1.0f, 0.6f, 0u}, NULL, 0u, 0u};
static const def_case k_random_defs[] = {
    {"def->radius negative", INVALID, "radius", {SET_F32(nl_random_points_def, radius, -1.0f)}},
    {"def->radius beyond the limit (2e9)", INVALID, "radius", {SET_F32(nl_random_points_def, radius, 2.0e9f)}},
    {"def->centre beyond the limit (2e9)", INVALID, "centre", {SET_F32(nl_random_points_def, centre[2], 2.0e9f)}},
    {"def->filter NULL (allowed: every polygon)", ALLOWED, NULL, {SET_PTR(nl_random_points_def, filter, NULL)}},
    {"def->filter refused (a negative drop)",
     INVALID,
     "def->filter->capabilities.max_drop_height",
     {SET_PTR(nl_random_points_def, filter, &k_bad_filter)}},
    {"def->reachable_from out of range",
     INVALID,
     "reachable_from",
     {SET_U32(nl_random_points_def, reachable_from, 1000000u)}},
    {"def->reachable_from 0 (allowed)", ALLOWED, NULL, {SET_U32(nl_random_points_def, reachable_from, 0u)}},
};

static void random_refuses(const void* def, nl_status detail, const char* needle) {
    nl_nav_point points[3];
    uint32_t found;
    fill(points, sizeof points);
    fill(&found, sizeof found);
    EXPECT_FAILURE(A.world,
                   nl_navmesh_random_points(A.world, A.navmesh, (const nl_random_points_def*)def, points, 3, &found),
                   detail, needle);
    EXPECT_UNTOUCHED(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&found, sizeof found, "out_found");
}
static void random_accepts(const void* def) {
    nl_nav_point points[3];
    uint32_t found = 0;
    EXPECT_OK(nl_navmesh_random_points(A.world, A.navmesh, (const nl_random_points_def*)def, points, 3, &found));
    EXPECT(found == 3 && points[2].found == 1, "%u points", (unsigned)found);
}
static nl_status random_id_call(nl_world* w, raw_id id, void* out) {
    const nl_random_points_def def = nl_default_random_points_def();
    uint32_t found;
    return nl_navmesh_random_points(w, AS(nl_navmesh_id, id), &def, (nl_nav_point*)out, 2, &found);
}

static void group_default_random_points_def(void) {
    CASE("nl_default_random_points_def", "the defaults") {
        const nl_random_points_def d = nl_default_random_points_def();
        EXPECT(d.size == sizeof d && d.filter == NULL && d.radius == 0.0f && d.reachable_from == NL_NO_POLYGON &&
                   d.seed == 1u,
               "not the whole navmesh with seed 1");
    }
}

static void group_navmesh_random_points(void) {
    static const id_function f = {
        "nl_navmesh_random_points", "navmesh", "out_points", 2 * sizeof(nl_nav_point), 0, 0, random_id_call, 0};
    const nl_random_points_def valid = nl_default_random_points_def();
    nl_nav_point points[2];
    uint32_t found;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_random_points", "def NULL") { random_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes("nl_navmesh_random_points", "def", &valid, sizeof valid, random_refuses, random_accepts);
    def_cases("nl_navmesh_random_points", &valid, sizeof valid, k_random_defs,
              sizeof k_random_defs / sizeof *k_random_defs, random_refuses, random_accepts);
    bad_float_fields("nl_navmesh_random_points", "def", &valid, sizeof valid, k_random_floats,
                     sizeof k_random_floats / sizeof *k_random_floats, random_refuses);
    CASE("nl_navmesh_random_points", "count 0 (allowed, out_points NULL)") {
        found = 77;
        EXPECT_OK(nl_navmesh_random_points(A.world, A.navmesh, &valid, NULL, 0, &found));
        EXPECT(found == 0, "out_found %u", (unsigned)found);
    }
    CASE("nl_navmesh_random_points", "count huge (out_points NULL)") {
        fill(&found, sizeof found);
        EXPECT_INVALID(A.world, nl_navmesh_random_points(A.world, A.navmesh, &valid, NULL, UINT32_MAX, &found),
                       "out_points");
        EXPECT_UNTOUCHED(&found, sizeof found, "out_found");
    }
    CASE("nl_navmesh_random_points", "out_found NULL") {
        fill(points, sizeof points);
        EXPECT_INVALID(A.world, nl_navmesh_random_points(A.world, A.navmesh, &valid, points, 2, NULL), "out_found");
        EXPECT_UNTOUCHED(points, sizeof points, "out_points");
    }
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"default_query_filter", group_default_query_filter},
    {"navmesh_can_reach", group_navmesh_can_reach},
    {"navmesh_get_reachable_polygons", group_navmesh_get_reachable_polygons},
    {"navmesh_get_islands", group_navmesh_get_islands},
    {"navmesh_raycast", group_navmesh_raycast},
    {"navmesh_move_along_surface", group_navmesh_move_along_surface},
    {"default_random_points_def", group_default_random_points_def},
    {"navmesh_random_points", group_navmesh_random_points},
};
const hostile_part hostile_queries_part = {k_groups, sizeof k_groups / sizeof *k_groups};
