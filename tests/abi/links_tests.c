/*
 * Links (navlink.h): generation, manual links, the link store, ids, lists, JSON and settings,
 * cancelling, updates in a box, through the C ABI only, in strict C11.
 *
 * Levels are boxes registered with nl_mesh_add; navmeshes are built from them by the built-in Recast
 * builder with its defaults (agent radius 0.6, height 2, climb 0.9). Two levels give exact answers:
 *
 * - "gap":   two 10 x 10 m platforms (top y = 0, 1 m thick), x in [-11, -1] and [1, 11], z in [-5, 5],
 *            2 m apart over a pit 20 m deep (its floor, y = -20, is far beyond max_drop_distance).
 *            Jumps cross the gap both ways; nothing drops.
 * - "ledge": a 20 x 20 m floor (top y = 0) with a 3 m high block on its x < 0 half. Drops go off the
 *            block's edge (x = 0) onto the floor, one way (3 m is more than max_jump_up).
 *
 * Recast's navmesh edges lie 0.6 to 0.9 m inside each rim (the agent radius, then the ledge-span filter
 * and the voxel grid), and its detail heights up to two cell heights (0.4 m) above the floor, so
 * positions are checked with those tolerances; everything else is exact.
 */
/* pthread_equal and the readers' threads; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"
#include "scene.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---------------------------------------------------------------------------------------------
 * Levels and helpers
 * ------------------------------------------------------------------------------------------- */

enum { LEVEL_GAP, LEVEL_LEDGE, LEVEL_WIDE_GAP, LEVEL_WALLED_GAP };

/* A box from (x0, y0, z0) to (x1, y1, z1) (scene.h). */
static nl_status add_box_id(nl_world* world, float x0, float y0, float z0, float x1, float y1, float z1,
                            nl_mesh_id* out_id) {
    const float lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
    return add_box_mesh(world, lo, hi, 0u, out_id);
}

static nl_status add_box(nl_world* world, float x0, float y0, float z0, float x1, float y1, float z1) {
    nl_mesh_id id = {0u, 0u};
    return add_box_id(world, x0, y0, z0, x1, y1, z1, &id);
}

/* Registers a level's boxes and builds its navmesh with Recast's defaults. */
static nl_navmesh_id build_level(nl_world* world, int level) {
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_id id = {0u, 0u};
    int ok = 1;
    switch (level) {
        case LEVEL_GAP:
        case LEVEL_WALLED_GAP:
            ok = NL_SUCCEEDED(add_box(world, -11.0f, -1.0f, -5.0f, -1.0f, 0.0f, 5.0f)) &&
                 NL_SUCCEEDED(add_box(world, 1.0f, -1.0f, -5.0f, 11.0f, 0.0f, 5.0f)) &&
                 NL_SUCCEEDED(add_box(world, -12.0f, -21.0f, -6.0f, 12.0f, -20.0f, 6.0f));
            /* A thin wall standing in the pit, up to 6 m: it blocks every jump across. */
            if (ok && level == LEVEL_WALLED_GAP)
                ok = NL_SUCCEEDED(add_box(world, -0.1f, -20.0f, -6.0f, 0.1f, 6.0f, 6.0f));
            break;
        case LEVEL_WIDE_GAP: /* 4.5 m apart, rim to rim: wider than max_jump_gap */
            ok = NL_SUCCEEDED(add_box(world, -11.0f, -1.0f, -5.0f, -1.0f, 0.0f, 5.0f)) &&
                 NL_SUCCEEDED(add_box(world, 3.5f, -1.0f, -5.0f, 13.5f, 0.0f, 5.0f));
            break;
        case LEVEL_LEDGE:
            ok = NL_SUCCEEDED(add_box(world, -10.0f, -1.0f, -10.0f, 10.0f, 0.0f, 10.0f)) &&
                 NL_SUCCEEDED(add_box(world, -10.0f, 0.0f, -10.0f, 0.0f, 3.0f, 10.0f));
            break;
        default: ok = 0;
    }
    CHECK_MSG(ok, "level %d: a box was refused", level);
    CHECK_MSG(NL_SUCCEEDED(nl_navmesh_build(world, &build, &id)), "level %d: nl_navmesh_build failed", level);
    return id;
}

/* The navmesh's links in a malloc'ed array (never NULL unless out of memory); *count = 0 on failure. */
static nl_link* list_links(const nl_world* world, nl_navmesh_id navmesh, uint32_t* count) {
    uint32_t n = 0;
    nl_link* links;
    *count = 0;
    if (NL_FAILED(nl_navmesh_get_links(world, navmesh, NULL, 0, &n))) return (nl_link*)calloc(1, sizeof(nl_link));
    links = (nl_link*)calloc(n + 1u, sizeof(nl_link));
    if (links) links[0] = nl_link_init();
    if (links && NL_SUCCEEDED(nl_navmesh_get_links(world, navmesh, links, n, &n))) *count = n;
    return links;
}

static uint32_t link_count(const nl_world* world, nl_navmesh_id navmesh) {
    uint32_t n = 0xdeadbeefu;
    nl_navmesh_get_links(world, navmesh, NULL, 0, &n);
    return n;
}

static uint32_t count_kind(const nl_link* links, uint32_t n, nl_link_kind kind) {
    uint32_t i, k = 0;
    for (i = 0; i < n; ++i) k += links[i].kind == kind;
    return k;
}

static int same_link_id(nl_link_id a, nl_link_id b) { return a.index1 == b.index1 && a.revision == b.revision; }
static int same_navmesh_id(nl_navmesh_id a, nl_navmesh_id b) {
    return a.index1 == b.index1 && a.revision == b.revision;
}

/* Two lists equal byte for byte (ids included): "nothing changed". */
static int same_list(const nl_link* a, uint32_t na, const nl_link* b, uint32_t nb) {
    return na == nb && (na == 0 || memcmp(a, b, na * sizeof *a) == 0);
}

/* Every field but the id (and, with `with_navmesh` 0, the navmesh) equal. */
static int same_fields(const nl_link* a, const nl_link* b, int with_navmesh) {
    nl_link x = *a, y = *b;
    memset(&x.id, 0, sizeof x.id);
    memset(&y.id, 0, sizeof y.id);
    if (!with_navmesh) {
        memset(&x.navmesh, 0, sizeof x.navmesh);
        memset(&y.navmesh, 0, sizeof y.navmesh);
    }
    return memcmp(&x, &y, sizeof x) == 0;
}

static float horizontal_distance(const float* a, const float* b) {
    return sqrtf((a[0] - b[0]) * (a[0] - b[0]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static void set3(float* p, float x, float y, float z) {
    p[0] = x;
    p[1] = y;
    p[2] = z;
}

static nl_link_generation_report empty_report(void) {
    nl_link_generation_report r;
    memset(&r, 0xab, sizeof r);
    r.size = sizeof r;
    return r;
}

/* The polygon count of a navmesh (0 on failure). */
static uint32_t polygon_count(const nl_world* world, nl_navmesh_id navmesh) {
    nl_navmesh_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_get_info(world, navmesh, &info))) return 0;
    return info.polygon_count;
}

/* A manual link across the gap level: from platform A to platform B, both ends on the navmesh. */
static nl_link_def manual_def(void) {
    nl_link_def def = nl_default_link_def();
    set3(def.start, -6.0f, 0.0f, 1.0f);
    set3(def.end, 6.0f, 0.0f, -1.0f);
    def.bidirectional = 1;
    def.cost_modifier = 2.5f;
    def.user_data = 0xfeedfacecafebeefull;
    return def;
}

/* ---------------------------------------------------------------------------------------------
 * Defaults
 * ------------------------------------------------------------------------------------------- */

static void defaults(void) {
    const nl_link_def def = nl_default_link_def();
    const nl_link_settings s = nl_default_link_settings();
    uint32_t i;

    CHECK(def.size == sizeof(nl_link_def));
    CHECK(def.kind == NL_LINK_MANUAL);
    CHECK(def.start[0] == 0.0f && def.start[1] == 0.0f && def.start[2] == 0.0f);
    CHECK(def.end[0] == 0.0f && def.end[1] == 0.0f && def.end[2] == 0.0f);
    CHECK(def.bidirectional == 0);
    CHECK(def.enabled == 1);
    CHECK(def.requirements_as_given == 0);
    CHECK(def.reserved == 0);
    CHECK(def.cost_modifier == 1.0f);
    CHECK(def.user_data == 0u);
    CHECK(def.requirements.gap == 0.0f && def.requirements.rise == 0.0f && def.requirements.drop == 0.0f &&
          def.requirements.clearance_width == 0.0f && def.requirements.abilities == 0u);

    /* Every default the header's comments give. */
    CHECK(s.size == sizeof(nl_link_settings));
    CHECK(s.min_edge_length == 0.4f);
    CHECK(s.min_group_size == 2u);
    CHECK(s.max_group_size == 8u);
    CHECK(s.sample_spacing == 1.0f);
    CHECK(s.falloff_distance == 1.5f);
    CHECK(s.max_jump_gap == 4.0f);
    CHECK(s.min_link_distance == 0.3f);
    CHECK(s.short_link_distance == 2.0f);
    CHECK(s.max_jump_up == 1.5f);
    CHECK(s.jump_arc_height == 1.0f);
    CHECK(s.strict_forward_angle == 35.0f);
    CHECK(s.permissive_forward_angle == 60.0f);
    CHECK(s.strict_incline_angle == 45.0f);
    CHECK(s.permissive_incline_angle == 70.0f);
    CHECK(s.max_drop_distance == 5.0f);
    CHECK(s.drop_angle_count == 3u);
    CHECK(s.drop_angles[0] == 0.0f && s.drop_angles[1] == -30.0f && s.drop_angles[2] == 30.0f);
    {
        int rest_zero = 1;
        for (i = 3; i < 16; ++i) rest_zero &= s.drop_angles[i] == 0.0f;
        CHECK_THAT(rest_zero, "nl_default_link_settings: drop_angles past drop_angle_count are 0");
    }
    CHECK(s.drop_steepness == 60.0f);
    CHECK(s.merge_distance == 0.6f);
    CHECK(s.clearance_margin == 0.1f);
    CHECK(s.arc_segments == 12u);
    CHECK(NL_LINK_JUMP == 1u && NL_LINK_DROP == 2u && NL_LINK_MANUAL == 3u && NL_LINK_FIRST_PLUGIN_KIND == 256u);
}

/* ---------------------------------------------------------------------------------------------
 * Generation: jumps across a gap, with progress and report
 * ------------------------------------------------------------------------------------------- */

typedef struct progress_log {
    int calls;
    int decreasing;   /* a fraction lower than the one before */
    int out_of_range; /* a fraction outside [0, 1] */
    int bad_stage;    /* a NULL or empty stage name */
    int other_thread; /* called on a thread other than the caller's */
    float first, last;
    pthread_t caller;
    int cancel_at_call;          /* 1-based call to return 0 from (0: never) */
    const char* cancel_at_stage; /* or the first call with this stage name */
    char last_stage[64];
} progress_log;

static int record_progress(void* user, float fraction, const char* stage) {
    progress_log* log = (progress_log*)user;
    ++log->calls;
    if (log->calls == 1)
        log->first = fraction;
    else if (fraction < log->last)
        ++log->decreasing;
    if (!(fraction >= 0.0f && fraction <= 1.0f)) ++log->out_of_range;
    if (!stage || !stage[0]) ++log->bad_stage;
    if (!pthread_equal(pthread_self(), log->caller)) ++log->other_thread;
    log->last = fraction;
    snprintf(log->last_stage, sizeof log->last_stage, "%s", stage ? stage : "");
    if (log->cancel_at_call && log->calls == log->cancel_at_call) return 0;
    if (log->cancel_at_stage && stage && strcmp(stage, log->cancel_at_stage) == 0) return 0;
    return 1;
}

static progress_log new_progress_log(void) {
    progress_log log;
    memset(&log, 0, sizeof log);
    log.caller = pthread_self();
    return log;
}

/* The report's own consistency, whatever the level. */
static void check_report(const nl_link_generation_report* r, uint32_t listed_generated, const char* label) {
    CHECK_MSG(r->size == sizeof *r, "%s: report.size changed to %u", label, (unsigned)r->size);
    CHECK_MSG(r->jump_links + r->drop_links == listed_generated,
              "%s: report says %u jumps + %u drops, %u generated links are listed", label, (unsigned)r->jump_links,
              (unsigned)r->drop_links, (unsigned)listed_generated);
    CHECK_MSG(r->samples == r->takeoff_points + r->rejected_wall + r->rejected_not_ledge,
              "%s: %u samples, %u take-off points + %u in a wall + %u not a ledge", label, (unsigned)r->samples,
              (unsigned)r->takeoff_points, (unsigned)r->rejected_wall, (unsigned)r->rejected_not_ledge);
    CHECK_MSG(r->jump_candidates >= r->jump_links && r->drop_candidates >= r->drop_links,
              "%s: fewer candidates than links (jumps %u/%u, drops %u/%u)", label, (unsigned)r->jump_candidates,
              (unsigned)r->jump_links, (unsigned)r->drop_candidates, (unsigned)r->drop_links);
    CHECK_MSG(r->edges > 0 && r->samples > 0 && r->rays_cast > 0, "%s: edges %u, samples %u, rays %llu", label,
              (unsigned)r->edges, (unsigned)r->samples, (unsigned long long)r->rays_cast);
    CHECK_MSG(r->milliseconds_edges >= 0.0 && r->milliseconds_takeoff >= 0.0 && r->milliseconds_jumps >= 0.0 &&
                  r->milliseconds_drops >= 0.0 && r->milliseconds_merge >= 0.0 &&
                  r->milliseconds_total + 1e-6 >= r->milliseconds_edges + r->milliseconds_takeoff +
                                                      r->milliseconds_jumps + r->milliseconds_drops +
                                                      r->milliseconds_merge - 0.01,
              "%s: stage times are negative or add up to more than the total", label);
}

static void generation_gap(void) {
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    nl_link_generation_report report = empty_report();
    progress_log log = new_progress_log();
    nl_link *links, *again, *before;
    uint32_t n = 0, n_again = 0, n_before = 0, i, polygons = polygon_count(world, navmesh);
    int wrong_kind = 0, wrong_flags = 0, wrong_ends = 0, wrong_gap = 0, wrong_height = 0, narrow = 0, bad_apex = 0,
        bad_polygon = 0, get_differs = 0, renewed = 1;
    float min_z = 1e9f, max_z = -1e9f;

    CHECK(link_count(world, navmesh) == 0u);
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, record_progress, &log, &report));
    links = list_links(world, navmesh, &n);
    check_report(&report, n, "gap");
    CHECK_MSG(report.jump_links >= 5u, "%u jump links across a 10 m wide gap (one per metre or so expected)",
              (unsigned)report.jump_links);
    CHECK(report.drop_links == 0u); /* the pit floor is 20 m down, beyond max_drop_distance */
    CHECK(report.takeoff_points > 0u && report.jump_candidates > 0u);
    CHECK(report.rejected_clearance == 0u); /* nothing stands in the way */

    /* Progress: fractions never decrease, end at 1, all on the calling thread. */
    CHECK(log.calls >= 3);
    CHECK(log.first >= 0.0f);
    CHECK(log.last == 1.0f);
    CHECK(log.decreasing == 0 && log.out_of_range == 0 && log.bad_stage == 0);
    CHECK_THAT(log.other_thread == 0, "nl_navmesh_generate_links: progress is called on the caller's thread");

    for (i = 0; i < n; ++i) {
        const nl_link* l = &links[i];
        const float* west = l->start[0] < l->end[0] ? l->start : l->end;
        const float* east = l->start[0] < l->end[0] ? l->end : l->start;
        nl_link got = nl_link_init();
        wrong_kind += l->kind != NL_LINK_JUMP;
        wrong_flags += !(l->bidirectional == 1 && l->generated == 1 && l->enabled == 1 && l->reserved == 0 &&
                         l->cost_modifier == 1.0f && l->user_data == 0u && l->requirements.abilities == 0u &&
                         same_navmesh_id(l->navmesh, navmesh) && l->id.index1 != 0u);
        /* One end on each platform, 0.55 to 0.95 m inside its rim (x = -1 and x = 1). */
        wrong_ends += !(west[0] >= -1.95f && west[0] <= -1.55f && east[0] >= 1.55f && east[0] <= 1.95f &&
                        fabsf(west[2]) < 5.0f && fabsf(east[2]) < 5.0f);
        /* The gap is rim to rim (the platforms are 2 m apart); the length is the ends'. */
        wrong_gap += !(fabsf(l->requirements.length - horizontal_distance(l->start, l->end)) <= 1e-3f &&
                       l->requirements.length >= 3.1f && l->requirements.length <= 3.9f &&
                       fabsf(l->requirements.gap - 2.0f) <= 0.05f);
        /* Ends on the floor (the platforms' tops at y = 0), not at the navmesh's height. */
        wrong_height += !(l->requirements.rise <= 0.01f && l->requirements.drop <= 0.01f &&
                          fabsf(l->start[1]) <= 0.01f && fabsf(l->end[1]) <= 0.01f);
        narrow += !(l->requirements.clearance_width >= 1.2f);
        /* The arc's top: jump_arc_height (1 m) above the higher end, between the ends. */
        bad_apex += !(fabsf(l->apex[1] - (fmaxf(l->start[1], l->end[1]) + 1.0f)) <= 0.01f && l->apex[0] > west[0] &&
                      l->apex[0] < east[0]);
        bad_polygon +=
            !(l->start_polygon < polygons && l->end_polygon < polygons && l->start_polygon != l->end_polygon);
        if (NL_FAILED(nl_link_get(world, l->id, &got)) || memcmp(&got, l, sizeof got) != 0) ++get_differs;
        if (l->start[2] < min_z) min_z = l->start[2];
        if (l->start[2] > max_z) max_z = l->start[2];
    }
    CHECK_MSG(wrong_kind == 0, "%d of %u links are not NL_LINK_JUMP", wrong_kind, (unsigned)n);
    CHECK_MSG(wrong_flags == 0, "%d links: not bidirectional/generated/enabled, or cost, user data, navmesh wrong",
              wrong_flags);
    CHECK_MSG(wrong_ends == 0, "%d links do not go from one platform's rim to the other's", wrong_ends);
    CHECK_MSG(wrong_gap == 0, "%d links: requirements.gap is not the rims' 2 m, or length not the ends' ~3.2-3.8 m",
              wrong_gap);
    CHECK_MSG(wrong_height == 0, "%d links: rise or drop not ~0, or an end off the platforms' tops", wrong_height);
    CHECK_MSG(narrow == 0, "%d links: clearance_width below the agent's diameter (1.2 m)", narrow);
    CHECK_MSG(bad_apex == 0, "%d links: apex is not 1 m above the higher end, between the ends", bad_apex);
    CHECK_MSG(bad_polygon == 0, "%d links: start/end polygons out of range or equal", bad_polygon);
    CHECK_MSG(get_differs == 0, "%d links: nl_link_get does not return what nl_navmesh_get_links listed", get_differs);
    CHECK_MSG(n == 0 || (min_z < -2.5f && max_z > 2.5f), "the links span z from %g to %g (the platforms: -5..5)", min_z,
              max_z);

    /* A second generation gives the same links (deterministic), under new ids. */
    before = links;
    n_before = n;
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    again = list_links(world, navmesh, &n_again);
    CHECK(n_again == n_before);
    for (i = 0; i < n_again && i < n_before; ++i) {
        nl_link a = again[i], b = before[i];
        if (same_link_id(a.id, b.id)) renewed = 0;
        CHECK_MSG(same_fields(&a, &b, 1), "link %u differs from the first generation's", (unsigned)i);
        /* The old ids are stale everywhere. */
        if (!same_link_id(a.id, b.id)) {
            nl_link got = nl_link_init();
            nl_link_def def = nl_default_link_def();
            CHECK(nl_link_is_valid(world, b.id) == 0 && nl_get_last_status() == NL_STATUS_SUCCESS);
            CHECK_FAIL(nl_link_get(world, b.id, &got), NL_STATUS_INVALID_HANDLE, "link");
            CHECK_FAIL(nl_link_update(world, b.id, &def), NL_STATUS_INVALID_HANDLE, "link");
            CHECK_FAIL(nl_link_remove(world, b.id), NL_STATUS_INVALID_HANDLE, "link");
        }
    }
    CHECK_THAT(renewed, "nl_navmesh_generate_links: generated links get new ids");
    CHECK(link_count(world, navmesh) == n_before);

    /* A wall standing in the gap: every candidate is refused for clearance, none kept. */
    {
        nl_world* walled = make_world(1);
        const nl_navmesh_id id = build_level(walled, LEVEL_WALLED_GAP);
        nl_link_generation_report r = empty_report();
        CHECK_OK(nl_navmesh_generate_links(walled, id, NULL, NULL, NULL, &r));
        CHECK(r.jump_links == 0u && link_count(walled, id) == 0u);
        CHECK_MSG(r.jump_candidates > 0u && r.rejected_clearance >= r.jump_candidates,
                  "a wall in the gap: %u candidates, %u rejected for clearance", (unsigned)r.jump_candidates,
                  (unsigned)r.rejected_clearance);
        nl_world_destroy(walled);
    }

    /* A gap wider than max_jump_gap: no jump, and the report has to say why. */
    {
        nl_world* wide = make_world(1);
        const nl_navmesh_id id = build_level(wide, LEVEL_WIDE_GAP);
        nl_link_generation_report r = empty_report();
        CHECK_OK(nl_navmesh_generate_links(wide, id, NULL, NULL, NULL, &r));
        CHECK(r.jump_links == 0u && link_count(wide, id) == 0u);
        CHECK_THAT(
            r.rejected_distance > 0u,
            "nl_link_generation_report.rejected_distance (\"A jump's gap too wide or too narrow\"): a gap wider than "
            "max_jump_gap between two facing edges is counted, so the report answers why there is no "
            "jump there");
        nl_world_destroy(wide);
    }

    /* Settings are honoured: a max_jump_gap below the gap, then a denser sampling. */
    {
        nl_link_settings s = nl_default_link_settings();
        nl_link_generation_report r = empty_report();
        s.max_jump_gap = 1.8f;
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &r));
        CHECK(r.jump_links == 0u && link_count(world, navmesh) == 0u);
        s = nl_default_link_settings();
        s.sample_spacing = 0.5f;
        r = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &r));
        CHECK_MSG(r.jump_links > n_before, "sample_spacing 0.5: %u jumps, %u with 1 m", (unsigned)r.jump_links,
                  (unsigned)n_before);
        CHECK(link_count(world, navmesh) == r.jump_links);
    }
    free(links);
    free(again);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Generation: drops off a ledge
 * ------------------------------------------------------------------------------------------- */

static void generation_ledge(void) {
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_LEDGE);
    nl_link_generation_report report = empty_report();
    nl_link* links;
    uint32_t n = 0, i;
    int wrong_kind = 0, wrong_way = 0, wrong_drop = 0, wrong_ends = 0, bad_apex = 0;

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &report));
    links = list_links(world, navmesh, &n);
    check_report(&report, n, "ledge");
    CHECK(report.jump_links == 0u);
    CHECK_MSG(report.drop_links >= 10u, "%u drops off a 20 m long ledge", (unsigned)report.drop_links);
    for (i = 0; i < n; ++i) {
        const nl_link* l = &links[i];
        wrong_kind += l->kind != NL_LINK_DROP;
        wrong_way += !(l->bidirectional == 0 && l->generated == 1 && l->enabled == 1);
        /* Floor to floor: the block's top at y = 3 to the floor at y = 0. The gap is from the rim (x = 0)
           to the landing, so shorter than the ends' horizontal distance (the length). */
        wrong_drop += !(fabsf(l->requirements.drop - 3.0f) <= 0.01f && l->requirements.rise == 0.0f &&
                        fabsf(l->requirements.drop - (l->start[1] - l->end[1])) <= 1e-3f &&
                        fabsf(l->requirements.length - horizontal_distance(l->start, l->end)) <= 1e-3f &&
                        l->requirements.gap < l->requirements.length - 0.5f && l->requirements.gap > 0.0f);
        /* From the block's top, inside its edge at x = 0, to the floor beyond it. */
        wrong_ends += !(l->start[0] >= -0.95f && l->start[0] <= -0.55f && fabsf(l->start[1] - 3.0f) <= 0.01f &&
                        l->end[0] > 0.6f && fabsf(l->end[1]) <= 0.01f);
        /* The apex is where the fall leaves the ground: 0.2 m past the rim (x = 0), at the start's height. */
        bad_apex += !(fabsf(l->apex[0] - 0.2f) <= 0.05f && l->apex[1] == l->start[1] &&
                      fabsf(l->apex[2] - l->start[2]) <= 1e-3f);
    }
    CHECK_MSG(wrong_kind == 0, "%d of %u links are not NL_LINK_DROP", wrong_kind, (unsigned)n);
    CHECK_MSG(wrong_way == 0, "%d drops are bidirectional (3 m > max_jump_up) or not generated/enabled", wrong_way);
    CHECK_MSG(
        wrong_drop == 0,
        "%d drops: requirements.drop not 3 m floor to floor, rise not 0, length not the ends' or gap not from the rim",
        wrong_drop);
    CHECK_MSG(wrong_ends == 0, "%d drops do not go from the block's edge down to the floor", wrong_ends);
    CHECK_MSG(bad_apex == 0, "%d drops: apex is not where the fall leaves the ground, 0.2 m past the rim", bad_apex);
    free(links);

    /* A max_jump_up above the ledge's height: the drops work both ways. */
    {
        nl_link_settings s = nl_default_link_settings();
        s.max_jump_up = 3.5f;
        report = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &report));
        links = list_links(world, navmesh, &n);
        CHECK(count_kind(links, n, NL_LINK_DROP) > 0u);
        for (i = 0, wrong_way = 0; i < n; ++i)
            wrong_way += links[i].kind == NL_LINK_DROP && links[i].bidirectional != 1;
        CHECK_MSG(wrong_way == 0, "max_jump_up 3.5: %d drops of ~3 m are still one-way", wrong_way);
        free(links);
    }
    /* A ledge deeper than max_drop_distance: no drop, counted under rejected_too_deep. */
    {
        nl_link_settings s = nl_default_link_settings();
        s.max_drop_distance = 2.9f;
        report = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &report));
        CHECK(report.drop_links == 0u && link_count(world, navmesh) == 0u);
        CHECK(report.rejected_too_deep > 0u);
    }
    /* One drop direction instead of three: as many drops, one way down per take-off point either way;
       with three, the turned probes that land on the same floor are counted as duplicates. */
    {
        nl_link_settings s = nl_default_link_settings();
        nl_link_generation_report three = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &three));
        s.drop_angle_count = 1;
        report = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &report));
        CHECK_MSG(report.drop_links > 0u && report.drop_links == three.drop_links,
                  "drop_angle_count 1: %u drops, %u with three angles", (unsigned)report.drop_links,
                  (unsigned)three.drop_links);
        CHECK(three.rejected_duplicate > report.rejected_duplicate);
    }
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Manual links: add, get, keep across regeneration, update, remove
 * ------------------------------------------------------------------------------------------- */

static void manual(void) {
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    const uint32_t polygons = polygon_count(world, navmesh);
    nl_link_def def = manual_def(), plugin_def = nl_default_link_def();
    nl_link_id manual = {0u, 0u}, plugin = {0u, 0u};
    nl_link got, got_plugin;
    nl_link* links;
    nl_link_generation_report report = empty_report();
    uint32_t n = 0, generated = 0, removed = 0xdeadbeefu, i;

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &report));
    generated = report.jump_links + report.drop_links;
    CHECK(generated > 0u);

    /* Added, and got back with every field. */
    CHECK_OK(nl_link_add(world, navmesh, &def, &manual));
    CHECK(manual.index1 != 0u);
    CHECK(nl_link_is_valid(world, manual) == 1);
    memset(&got, 0xab, sizeof got);
    got.size = sizeof got; /* the element size the library lays out with */
    CHECK_OK(nl_link_get(world, manual, &got));
    CHECK(same_link_id(got.id, manual));
    CHECK(same_navmesh_id(got.navmesh, navmesh));
    CHECK(got.kind == NL_LINK_MANUAL);
    CHECK(got.start[0] == -6.0f && got.start[1] == 0.0f && got.start[2] == 1.0f); /* kept as given */
    CHECK(got.end[0] == 6.0f && got.end[1] == 0.0f && got.end[2] == -1.0f);
    CHECK(got.apex[0] == 6.0f && got.apex[1] == 0.0f && got.apex[2] == -1.0f); /* the higher end (a tie: the end) */
    CHECK(got.bidirectional == 1 && got.generated == 0 && got.enabled == 1 && got.reserved == 0);
    CHECK(got.cost_modifier == 2.5f);
    CHECK(got.user_data == 0xfeedfacecafebeefull);
    /* requirements_as_given 0 (the default): measured from the ends. */
    CHECK_NEAR(got.requirements.gap, sqrtf(12.0f * 12.0f + 2.0f * 2.0f), 1e-4f);
    CHECK(got.requirements.rise == 0.0f && got.requirements.drop == 0.0f);
    CHECK(got.requirements.clearance_width == 0.0f && got.requirements.abilities == 0u);
    CHECK(got.start_polygon < polygons && got.end_polygon < polygons && got.start_polygon != got.end_polygon);

    /* A plugin kind with its own requirements (kept as given) and a rising link: apex = the end. */
    plugin_def.kind = NL_LINK_FIRST_PLUGIN_KIND + 44u;
    set3(plugin_def.start, -8.0f, -0.5f, 3.0f);
    set3(plugin_def.end, -4.0f, 0.5f, 3.0f);
    plugin_def.enabled = 0;
    plugin_def.cost_modifier = 0.0f;
    plugin_def.requirements_as_given = 1;
    plugin_def.requirements.gap = 1.0f;
    plugin_def.requirements.rise = 2.0f;
    plugin_def.requirements.clearance_width = 0.8f;
    plugin_def.requirements.abilities = 0x5u;
    CHECK_OK(nl_link_add(world, navmesh, &plugin_def, &plugin));
    got_plugin = nl_link_init();
    CHECK_OK(nl_link_get(world, plugin, &got_plugin));
    CHECK(got_plugin.kind == 300u && got_plugin.generated == 0 && got_plugin.enabled == 0 &&
          got_plugin.bidirectional == 0 && got_plugin.cost_modifier == 0.0f);
    CHECK(got_plugin.requirements.gap == 1.0f && got_plugin.requirements.rise == 2.0f &&
          got_plugin.requirements.drop == 0.0f && got_plugin.requirements.clearance_width == 0.8f &&
          got_plugin.requirements.abilities == 0x5u);
    CHECK(got_plugin.apex[0] == -4.0f && got_plugin.apex[1] == 0.5f && got_plugin.apex[2] == 3.0f);
    /* Its length was left 0: measured from the ends, along the ground. */
    CHECK_NEAR(got_plugin.requirements.length, 4.0f, 1e-5f);
    CHECK(got_plugin.start_polygon < polygons && got_plugin.end_polygon < polygons);
    CHECK(link_count(world, navmesh) == generated + 2u);

    /* Kept across regeneration: same ids, same fields, first in the list (they are now the oldest). */
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    links = list_links(world, navmesh, &n);
    CHECK(n == generated + 2u);
    CHECK(n >= 2u && same_link_id(links[0].id, manual) && memcmp(&links[0], &got, sizeof got) == 0);
    CHECK(n >= 2u && same_link_id(links[1].id, plugin) && memcmp(&links[1], &got_plugin, sizeof got) == 0);
    for (i = 2; i < n; ++i)
        CHECK_MSG(links[i].generated == 1, "link %u after the manual ones is not generated", (unsigned)i);
    free(links);
    CHECK(nl_link_is_valid(world, manual) == 1 && nl_link_is_valid(world, plugin) == 1);

    /* Removing the generated links keeps the manual ones. */
    CHECK_OK(nl_navmesh_remove_generated_links(world, navmesh, &removed));
    CHECK(removed == generated);
    CHECK(link_count(world, navmesh) == 2u);
    CHECK_OK(nl_navmesh_remove_generated_links(world, navmesh, NULL)); /* out_removed is optional */
    removed = 77u;
    CHECK_OK(nl_navmesh_remove_generated_links(world, navmesh, &removed));
    CHECK(removed == 0u);
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    CHECK(link_count(world, navmesh) == generated + 2u);

    /* Updated: disabled, cheaper, one-way; it keeps its id, navmesh and "manual". */
    def.enabled = 0;
    def.cost_modifier = 0.5f;
    def.bidirectional = 0;
    def.user_data = 42u;
    CHECK_OK(nl_link_update(world, manual, &def));
    CHECK_OK(nl_link_get(world, manual, &got));
    CHECK(same_link_id(got.id, manual) && same_navmesh_id(got.navmesh, navmesh));
    CHECK(got.enabled == 0 && got.cost_modifier == 0.5f && got.bidirectional == 0 && got.user_data == 42u);
    CHECK(got.generated == 0 && got.kind == NL_LINK_MANUAL);
    /* New ends: moved, requirements recomputed, polygons located again. */
    set3(def.end, -3.0f, 0.0f, 4.0f);
    CHECK_OK(nl_link_update(world, manual, &def));
    CHECK_OK(nl_link_get(world, manual, &got));
    CHECK(got.end[0] == -3.0f && got.end[2] == 4.0f);
    CHECK_NEAR(got.requirements.gap, sqrtf(3.0f * 3.0f + 3.0f * 3.0f), 1e-4f);
    CHECK(got.end_polygon < polygons);

    /* A generated link can be updated too (disabled); it stays generated, and the next generation
       replaces it. */
    links = list_links(world, navmesh, &n);
    if (CHECK(n == generated + 2u && links[2].generated == 1)) {
        nl_link_def off = nl_default_link_def();
        nl_link g = nl_link_init();
        off.kind = links[2].kind;
        memcpy(off.start, links[2].start, sizeof off.start);
        memcpy(off.end, links[2].end, sizeof off.end);
        off.bidirectional = links[2].bidirectional;
        off.enabled = 0;
        off.requirements = links[2].requirements;
        CHECK_OK(nl_link_update(world, links[2].id, &off));
        CHECK_OK(nl_link_get(world, links[2].id, &g));
        CHECK(g.enabled == 0 && g.generated == 1 && g.kind == links[2].kind);
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
        CHECK(nl_link_is_valid(world, links[2].id) == 0);
        free(links);
        links = list_links(world, navmesh, &n);
        for (i = 2; i < n; ++i) CHECK_MSG(links[i].enabled == 1, "regenerated link %u is still disabled", (unsigned)i);
    }
    free(links);

    /* Removed: gone from the list, its id stale everywhere; the other stays. */
    CHECK_OK(nl_link_remove(world, manual));
    CHECK(nl_link_is_valid(world, manual) == 0 && nl_get_last_status() == NL_STATUS_SUCCESS);
    CHECK_FAIL(nl_link_get(world, manual, &got), NL_STATUS_INVALID_HANDLE, "link");
    CHECK_FAIL(nl_link_update(world, manual, &def), NL_STATUS_INVALID_HANDLE, "link");
    CHECK_FAIL(nl_link_remove(world, manual), NL_STATUS_INVALID_HANDLE, "link");
    CHECK(link_count(world, navmesh) == generated + 1u);
    CHECK(nl_link_is_valid(world, plugin) == 1);
    /* A new link may take the slot: the old id still does not reach it. */
    {
        nl_link_id again = {0u, 0u};
        CHECK_OK(nl_link_add(world, navmesh, &def, &again));
        CHECK(!same_link_id(again, manual));
        CHECK(nl_link_is_valid(world, manual) == 0);
        CHECK_FAIL(nl_link_get(world, manual, &got), NL_STATUS_INVALID_HANDLE, "link");
    }

    /* Removing the navmesh removes its links. */
    CHECK_OK(nl_navmesh_remove(world, navmesh));
    CHECK(nl_link_is_valid(world, plugin) == 0);
    CHECK_FAIL(nl_link_get(world, plugin, &got), NL_STATUS_INVALID_HANDLE, "link");
    CHECK_FAIL(nl_navmesh_get_links(world, navmesh, NULL, 0, &n), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK_FAIL(nl_link_add(world, navmesh, &def, &manual), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK_FAIL(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK_FAIL(nl_navmesh_remove_generated_links(world, navmesh, NULL), NL_STATUS_INVALID_HANDLE, "navmesh");
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Refusals: INVALID_ARGUMENT naming the field, and nothing changed
 * ------------------------------------------------------------------------------------------- */

/* Adds `def` (expecting a refusal naming `needle`) and updates `existing` with it (the same refusal);
   neither may change the navmesh's links. */
static void check_def_refused(nl_world* world, nl_navmesh_id navmesh, nl_link_id existing, const nl_link_def* def,
                              const char* needle, const char* what) {
    uint32_t n0 = 0, n1 = 0;
    nl_link* before = list_links(world, navmesh, &n0);
    nl_link_id out = {77u, 77u};
    nl_link* after;
    if (!CHECK_FAIL(nl_link_add(world, navmesh, def, &out), NL_STATUS_INVALID_ARGUMENT, needle))
        fprintf(stderr, "    (nl_link_add: %s)\n", what);
    CHECK_MSG(out.index1 == 77u && out.revision == 77u, "nl_link_add (%s) wrote out_id", what);
    if (!CHECK_FAIL(nl_link_update(world, existing, def), NL_STATUS_INVALID_ARGUMENT, needle))
        fprintf(stderr, "    (nl_link_update: %s)\n", what);
    after = list_links(world, navmesh, &n1);
    CHECK_MSG(same_list(before, n0, after, n1), "a refused def (%s) changed the links", what);
    free(before);
    free(after);
}

static void refusals(void) {
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    const nl_link_def good = manual_def();
    nl_link_def def;
    nl_link_id id = {0u, 0u};
    nl_link got = nl_link_init();
    nl_link* before;
    uint32_t n0 = 0, count = 0xdeadbeefu;

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    CHECK_OK(nl_link_add(world, navmesh, &good, &id));

    /* Null pointers. */
    CHECK_INVALID(nl_link_add(world, navmesh, NULL, &id), "def");
    CHECK_INVALID(nl_link_add(world, navmesh, &good, NULL), "out_id");
    CHECK_INVALID(nl_link_update(world, id, NULL), "def");
    CHECK_INVALID(nl_link_get(world, id, NULL), "out_link");
    CHECK_INVALID(nl_navmesh_get_links(world, navmesh, NULL, 0, NULL), "out_count");
    {
        nl_link one = nl_link_init();
        CHECK_INVALID(nl_navmesh_get_links(world, navmesh, NULL, 3, &count), "out_links");
        CHECK_INVALID(nl_navmesh_get_links(world, navmesh, &one, 1, NULL), "out_count");
    }

    /* The def's fields, each refused by add and update alike. */
    def = good;
    def.start[1] = NAN;
    check_def_refused(world, navmesh, id, &def, "def->start", "a NaN start");
    def = good;
    def.end[0] = INFINITY;
    check_def_refused(world, navmesh, id, &def, "def->end", "an infinite end");
    def = good;
    def.start[2] = 2.0e9f;
    check_def_refused(world, navmesh, id, &def, "def->start", "a start beyond NL_COORDINATE_LIMIT");
    def = good;
    def.end[1] = 50.0f;
    check_def_refused(world, navmesh, id, &def, "def->end", "an end 50 m above the navmesh");
    def = good;
    set3(def.start, 0.0f, 0.0f, 0.0f); /* over the gap: 1.6 m from either platform's navmesh */
    check_def_refused(world, navmesh, id, &def, "def->start", "a start over the gap");
    def = good;
    def.cost_modifier = -1.0f;
    check_def_refused(world, navmesh, id, &def, "def->cost_modifier", "a negative cost modifier");
    def = good;
    def.cost_modifier = NAN;
    check_def_refused(world, navmesh, id, &def, "def->cost_modifier", "a NaN cost modifier");
    def = good;
    def.requirements.gap = -1.0f;
    check_def_refused(world, navmesh, id, &def, "def->requirements.gap", "a negative gap");
    def = good;
    def.requirements.rise = -0.5f;
    check_def_refused(world, navmesh, id, &def, "def->requirements.rise", "a negative rise");
    def = good;
    def.requirements.drop = -2.0f;
    check_def_refused(world, navmesh, id, &def, "def->requirements.drop", "a negative drop");
    def = good;
    def.requirements.clearance_width = -0.1f;
    check_def_refused(world, navmesh, id, &def, "def->requirements.clearance_width", "a negative clearance width");
    def = good;
    def.requirements.gap = NAN;
    check_def_refused(world, navmesh, id, &def, "def->requirements.gap", "a NaN gap");
    def = good;
    def.kind = 7u;
    check_def_refused(world, navmesh, id, &def, "def->kind", "kind 7");
    def = good;
    def.kind = 0u;
    check_def_refused(world, navmesh, id, &def, "def->kind", "kind 0");
    def = good;
    def.kind = NL_LINK_FIRST_PLUGIN_KIND - 1u;
    check_def_refused(world, navmesh, id, &def, "def->kind", "kind 255");
    def = good;
    def.size = 0u;
    check_def_refused(world, navmesh, id, &def, "def->size", "size 0");
    def = good;
    def.size = (uint32_t)offsetof(nl_link_def, requirements);
    check_def_refused(world, navmesh, id, &def, "def->size", "a size without the requirements");

    /* Generation settings, each named; nothing generated, the links as they were. */
    before = list_links(world, navmesh, &n0);
    {
        static const struct {
            const char* needle;
            int which;
        } bad[] = {
            {"settings->size", 0},
            {"settings->drop_angle_count", 1},
            {"settings->max_jump_gap", 2},
            {"settings->jump_arc_height", 3},
            {"min_group_size", 4},
            {"settings->arc_segments", 5},
            {"settings->merge_distance", 6},
            {"settings->clearance_margin", 7},
            {"settings->drop_steepness", 8},
            {"settings->strict_forward_angle", 9},
            {"settings->min_link_distance", 10},
            {"settings->drop_angles[1]", 11},
        };
        size_t k;
        for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
            nl_link_settings s = nl_default_link_settings();
            nl_link_generation_report r = empty_report();
            nl_link* after;
            uint32_t n1 = 0;
            switch (bad[k].which) {
                case 0: s.size = 4u; break;
                case 1: s.drop_angle_count = 17u; break;
                case 2: s.max_jump_gap = -1.0f; break;
                case 3: s.jump_arc_height = NAN; break;
                case 4: s.min_group_size = 0u; break;
                case 5: s.arc_segments = 1u; break;
                case 6: s.merge_distance = -0.5f; break;
                case 7: s.clearance_margin = 0.5f; break;
                case 8: s.drop_steepness = 5.0f; break;
                case 9: s.strict_forward_angle = 95.0f; break;
                case 10: s.min_link_distance = 4.0f; break; /* not below max_jump_gap */
                default: s.drop_angles[1] = 100.0f; break;  /* the index is named */
            }
            if (!CHECK_FAIL(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &r), NL_STATUS_INVALID_ARGUMENT,
                            bad[k].needle))
                fprintf(stderr, "    (settings case %d)\n", bad[k].which);
            CHECK_MSG(all_bytes((const char*)&r + sizeof r.size, sizeof r - sizeof r.size, 0xab),
                      "settings case %d: the report was written", bad[k].which);
            after = list_links(world, navmesh, &n1);
            CHECK_MSG(same_list(before, n0, after, n1), "settings case %d changed the links", bad[k].which);
            free(after);
        }
    }
    {
        nl_link_generation_report r = empty_report();
        nl_link* after;
        uint32_t n1 = 0;
        r.size = 8u;
        CHECK_INVALID(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &r), "out_report->size");
        after = list_links(world, navmesh, &n1);
        CHECK(same_list(before, n0, after, n1));
        free(after);
    }
    free(before);

    /* A null world, everywhere. */
    {
        nl_link_settings s = nl_default_link_settings();
        size_t length = 0;
        CHECK_INVALID(nl_link_add(NULL, navmesh, &good, &id), "world");
        CHECK_INVALID(nl_link_update(NULL, id, &good), "world");
        CHECK_INVALID(nl_link_remove(NULL, id), "world");
        CHECK(nl_link_is_valid(NULL, id) == 0);
        CHECK(nl_get_last_status() == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
        CHECK_INVALID(nl_link_get(NULL, id, &got), "world");
        CHECK_INVALID(nl_navmesh_get_links(NULL, navmesh, NULL, 0, &count), "world");
        CHECK_INVALID(nl_navmesh_remove_generated_links(NULL, navmesh, NULL), "world");
        CHECK_INVALID(nl_navmesh_generate_links(NULL, navmesh, &s, NULL, NULL, NULL), "world");
        CHECK_INVALID(nl_navmesh_save_links_json(NULL, navmesh, NULL, 0, &length), "world");
        CHECK_INVALID(nl_navmesh_load_links_json(NULL, navmesh, "{}", 2, 0, NULL), "world");
    }
    CHECK(nl_link_is_valid(world, id) == 1);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Ids: null, stale, another world's
 * ------------------------------------------------------------------------------------------- */

static void check_stale_everywhere(nl_world* world, nl_link_id id, const char* what) {
    const nl_link_def def = manual_def();
    nl_link got = nl_link_init();
    memset(&got, 0xab, sizeof got);
    got.size = sizeof got; /* the element size the library lays out with */
    CHECK_MSG(nl_link_is_valid(world, id) == 0 && nl_get_last_status() == NL_STATUS_SUCCESS,
              "nl_link_is_valid: %s is valid", what);
    if (!CHECK_FAIL(nl_link_get(world, id, &got), NL_STATUS_INVALID_HANDLE, "link"))
        fprintf(stderr, "    (%s)\n", what);
    CHECK_MSG(all_bytes((const unsigned char*)&got + sizeof(uint32_t), sizeof got - sizeof(uint32_t), 0xab),
              "nl_link_get wrote out_link for %s", what);
    if (!CHECK_FAIL(nl_link_update(world, id, &def), NL_STATUS_INVALID_HANDLE, "link"))
        fprintf(stderr, "    (%s)\n", what);
    if (!CHECK_FAIL(nl_link_remove(world, id), NL_STATUS_INVALID_HANDLE, "link")) fprintf(stderr, "    (%s)\n", what);
}

/* A slot reused 2^20 times used to wrap its generation: the first id of the slot came back to life and
   nl_link_remove on it removed whichever link then held the slot. */
static void ids_never_come_back(void) {
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    const nl_link_def def = manual_def();
    nl_link_id first = {0u, 0u}, live = {0u, 0u}, id = {0u, 0u};
    uint32_t i, same_slot = 0, came_back = 0;

    CHECK_OK(nl_link_add(world, navmesh, &def, &first));
    CHECK_OK(nl_link_remove(world, first));
    /* Past the 20-bit generation counter of the slot: every removed id must stay refused. */
    for (i = 0; i < (1u << 20) + 8u; ++i) {
        if (!NL_SUCCEEDED(nl_link_add(world, navmesh, &def, &id))) break;
        same_slot += id.index1 == first.index1;
        if (same_link_id(id, first)) ++came_back;
        if (!NL_SUCCEEDED(nl_link_remove(world, id))) break;
    }
    CHECK_MSG(i == (1u << 20) + 8u, "add/remove stopped after %u rounds", (unsigned)i);
    CHECK_MSG(same_slot >= (1u << 20) - 2u, "the slot was reused %u times only; the test is vacuous",
              (unsigned)same_slot);
    CHECK(came_back == 0u);
    CHECK_OK(nl_link_add(world, navmesh, &def, &live));
    CHECK(nl_link_is_valid(world, first) == 0);
    CHECK_FAIL(nl_link_remove(world, first), NL_STATUS_INVALID_HANDLE, "nl_link_remove");
    CHECK(nl_link_is_valid(world, live) == 1); /* the live link is untouched */
    nl_world_destroy(world);
}

static void ids(void) {
    nl_world* world = make_world(1);
    nl_world* other = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    const nl_navmesh_id other_navmesh = build_level(other, LEVEL_GAP);
    const nl_link_def def = manual_def();
    const nl_link_id null_id = {0u, 0u};
    nl_link_id manual = {0u, 0u}, theirs = {0u, 0u};
    nl_link* first;
    uint32_t n = 0, i, count = 0;

    check_stale_everywhere(world, null_id, "the null id");
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    first = list_links(world, navmesh, &n);
    CHECK(n > 0u);

    /* After removal. */
    CHECK_OK(nl_link_add(world, navmesh, &def, &manual));
    CHECK_OK(nl_link_remove(world, manual));
    check_stale_everywhere(world, manual, "a removed manual link's id");

    /* After regeneration: every generated id of the previous generation. */
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    for (i = 0; i < n; ++i) check_stale_everywhere(world, first[i].id, "a generated link's id after regeneration");
    free(first);

    /* After nl_navmesh_remove_generated_links. */
    first = list_links(world, navmesh, &n);
    CHECK_OK(nl_navmesh_remove_generated_links(world, navmesh, NULL));
    for (i = 0; i < n; ++i) check_stale_everywhere(world, first[i].id, "a generated link's id after removing them");
    free(first);

    /* Another world's link, even with the same slot. */
    CHECK_OK(nl_link_add(other, other_navmesh, &def, &theirs));
    CHECK(nl_link_is_valid(other, theirs) == 1);
    CHECK_OK(nl_link_add(world, navmesh, &def, &manual));
    CHECK(!same_link_id(manual, theirs));
    check_stale_everywhere(world, theirs, "another world's link id");
    CHECK(nl_link_is_valid(other, theirs) == 1); /* untouched there */
    /* ... and another world's navmesh. */
    CHECK_FAIL(nl_navmesh_get_links(world, other_navmesh, NULL, 0, &count), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK_FAIL(nl_link_add(world, other_navmesh, &def, &manual), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK(nl_link_is_valid(world, manual) == 1);
    nl_world_destroy(other);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Lists: the two-call pattern
 * ------------------------------------------------------------------------------------------- */

static void lists(void) {
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    nl_link* buffer;
    nl_link* listed;
    uint32_t n = 0, count = 0xdeadbeefu;

    /* No links yet: a count of 0, with or without a buffer. */
    CHECK_OK(nl_navmesh_get_links(world, navmesh, NULL, 0, &count));
    CHECK(count == 0u);
    {
        nl_link one = nl_link_init();
        memset(&one, 0xab, sizeof one);
        one.size = sizeof one; /* the element size the library lays out with */
        count = 77u;
        CHECK_OK(nl_navmesh_get_links(world, navmesh, &one, 1, &count));
        CHECK(count == 0u &&
              all_bytes((const unsigned char*)&one + sizeof(uint32_t), sizeof one - sizeof(uint32_t), 0xab));
    }

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    CHECK_OK(nl_navmesh_get_links(world, navmesh, NULL, 0, &n));
    CHECK(n >= 2u);
    buffer = (nl_link*)malloc((n + 1u) * sizeof *buffer);
    if (!CHECK(buffer != NULL)) {
        nl_world_destroy(world);
        return;
    }
    /* Short: BUFFER_TOO_SMALL, the count still written, the buffer untouched. */
    memset(buffer, 0xab, (n + 1u) * sizeof *buffer);
    count = 0;
    /* The first element's size unset: refused before anything else, whatever fits. */
    CHECK_INVALID(nl_navmesh_get_links(world, navmesh, buffer, n, &count), "out_links[0].size");
    buffer[0].size = sizeof *buffer;
    CHECK_FAIL(nl_navmesh_get_links(world, navmesh, buffer, n - 1u, &count), NL_STATUS_BUFFER_TOO_SMALL, "");
    CHECK(count == n);
    CHECK(
        all_bytes((const unsigned char*)buffer + sizeof(uint32_t), (n + 1u) * sizeof *buffer - sizeof(uint32_t), 0xab));
    count = 0;
    CHECK_FAIL(nl_navmesh_get_links(world, navmesh, buffer, 0, &count), NL_STATUS_BUFFER_TOO_SMALL, "");
    CHECK(count == n &&
          all_bytes((const unsigned char*)buffer + sizeof(uint32_t), sizeof *buffer - sizeof(uint32_t), 0xab));
    /* Exact, and larger: n entries written, nothing past them. */
    count = 0;
    CHECK_OK(nl_navmesh_get_links(world, navmesh, buffer, n, &count));
    CHECK(count == n);
    memset(buffer, 0xab, (n + 1u) * sizeof *buffer);
    buffer[0] = nl_link_init();
    CHECK_OK(nl_navmesh_get_links(world, navmesh, buffer, n + 1u, &count));
    CHECK(count == n && all_bytes(buffer + n, sizeof *buffer, 0xab));
    listed = list_links(world, navmesh, &count);
    CHECK(same_list(buffer, n, listed, count));
    free(listed);
    free(buffer);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * JSON: save, load, refusals
 * ------------------------------------------------------------------------------------------- */

/* The navmesh's links as JSON in a malloc'ed string (NULL on failure). */
static char* save_json(const nl_world* world, nl_navmesh_id navmesh, size_t* length) {
    size_t n = 0;
    char* text;
    *length = 0;
    if (NL_FAILED(nl_navmesh_save_links_json(world, navmesh, NULL, 0, &n))) return NULL;
    text = (char*)malloc(n + 1u);
    if (text && NL_FAILED(nl_navmesh_save_links_json(world, navmesh, text, n + 1u, &n))) {
        free(text);
        return NULL;
    }
    *length = n;
    return text;
}

/* Loading `json` fails with `detail`, naming `needle`, and changes nothing. */
static void check_load_refused(nl_world* world, nl_navmesh_id navmesh, const char* json, nl_status detail,
                               const char* needle) {
    uint32_t n0 = 0, n1 = 0, count = 777u;
    nl_link* before = list_links(world, navmesh, &n0);
    nl_link* after;
    if (!CHECK_FAIL(nl_navmesh_load_links_json(world, navmesh, json, strlen(json), 0, &count), detail, needle))
        fprintf(stderr, "    (the JSON: %s)\n", json);
    CHECK_MSG(count == 777u, "a refused load wrote out_count (%s)", json);
    after = list_links(world, navmesh, &n1);
    CHECK_MSG(same_list(before, n0, after, n1), "a refused load changed the links (%s)", json);
    free(before);
    free(after);
}

#define LINKS_HEAD "{\"format\": \"navlink-links\", \"version\": 1, \"links\": "

static void json(void) {
    nl_world* world = make_world(1);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    nl_link_def def = manual_def(), plugin_def = nl_default_link_def();
    nl_link_id manual = {0u, 0u}, plugin = {0u, 0u};
    nl_link *saved, *loaded;
    uint32_t n_saved = 0, n_loaded = 0, count = 0, i;
    size_t length = 0, n = 0;
    char* text;
    char* buffer;

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    CHECK_OK(nl_link_add(world, navmesh, &def, &manual));
    plugin_def.kind = 300u;
    set3(plugin_def.start, -8.0f, 0.25f, 3.0f);
    set3(plugin_def.end, -4.0f, 0.5f, -3.0f);
    plugin_def.enabled = 0;
    plugin_def.cost_modifier = 0.1f;
    plugin_def.user_data = 0xffffffffffffffffull;
    plugin_def.requirements.clearance_width = 0.7f;
    plugin_def.requirements.abilities = 0x8000000000000001ull;
    CHECK_OK(nl_link_add(world, navmesh, &plugin_def, &plugin));
    saved = list_links(world, navmesh, &n_saved);
    CHECK(n_saved >= 3u);

    /* Save: measure, too small (untouched), exact; NUL-terminated. */
    CHECK_OK(nl_navmesh_save_links_json(world, navmesh, NULL, 0, &n));
    CHECK(n > 0u);
    buffer = (char*)malloc(n + 2u);
    if (!CHECK(buffer != NULL)) {
        nl_world_destroy(world);
        return;
    }
    memset(buffer, 0x5a, n + 2u);
    length = 0;
    CHECK_FAIL(nl_navmesh_save_links_json(world, navmesh, buffer, n, &length), NL_STATUS_BUFFER_TOO_SMALL, "");
    CHECK_THAT(length == n,
               "nl_navmesh_save_links_json: out_length receives the length even when the buffer is too small");
    CHECK(all_bytes(buffer, n + 2u, 0x5a));
    CHECK_FAIL(nl_navmesh_save_links_json(world, navmesh, buffer, 1, &length), NL_STATUS_BUFFER_TOO_SMALL, "");
    CHECK(all_bytes(buffer, n + 2u, 0x5a));
    length = 0;
    CHECK_OK(nl_navmesh_save_links_json(world, navmesh, buffer, n + 1u, &length));
    CHECK(length == n && buffer[n] == '\0' && strlen(buffer) == n && (unsigned char)buffer[n + 1] == 0x5a);
    CHECK(strstr(buffer, "\"navlink-links\"") != NULL);
    CHECK(strstr(buffer, "\"version\": 1") != NULL);
    CHECK(strstr(buffer, "\"requires\"") != NULL && strstr(buffer, "\"jump\"") != NULL &&
          strstr(buffer, "\"manual\"") != NULL);
    CHECK_INVALID(nl_navmesh_save_links_json(world, navmesh, buffer, n + 1u, NULL), "out_length");
    CHECK_INVALID(nl_navmesh_save_links_json(world, navmesh, NULL, 10, &length), "buffer");
    free(buffer);

    /* Load what was saved: the same links, field for field, under new ids. */
    text = save_json(world, navmesh, &length);
    if (!CHECK(text != NULL)) {
        nl_world_destroy(world);
        return;
    }
    count = 0;
    CHECK_OK(nl_navmesh_load_links_json(world, navmesh, text, length, 0, &count));
    CHECK(count == n_saved);
    loaded = list_links(world, navmesh, &n_loaded);
    CHECK(n_loaded == n_saved);
    for (i = 0; i < n_loaded && i < n_saved; ++i) {
        CHECK_MSG(same_fields(&loaded[i], &saved[i], 1), "link %u (kind %u) changed in a JSON round trip", (unsigned)i,
                  (unsigned)saved[i].kind);
        CHECK_MSG(!same_link_id(loaded[i].id, saved[i].id), "link %u kept its id through a load", (unsigned)i);
    }
    CHECK(nl_link_is_valid(world, manual) == 0 && nl_link_is_valid(world, plugin) == 0);
    free(loaded);

    /* Into another world with the same level: the same links there. */
    {
        nl_world* other = make_world(1);
        const nl_navmesh_id there = build_level(other, LEVEL_GAP);
        CHECK_OK(nl_navmesh_load_links_json(other, there, text, length, 0, NULL)); /* out_count is optional */
        loaded = list_links(other, there, &n_loaded);
        CHECK(n_loaded == n_saved);
        for (i = 0; i < n_loaded && i < n_saved; ++i)
            CHECK_MSG(same_fields(&loaded[i], &saved[i], 0) && same_navmesh_id(loaded[i].navmesh, there),
                      "link %u differs when loaded in another world", (unsigned)i);
        free(loaded);
        nl_world_destroy(other);
    }
    /* Generated links stay generated: a generation replaces them, the manual ones stay. */
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    CHECK(link_count(world, navmesh) == n_saved);
    free(text);

    /* Refusals, each changing nothing. */
    check_load_refused(world, navmesh, LINKS_HEAD "[", NL_STATUS_PARSE_ERROR, "");
    check_load_refused(world, navmesh, "not json", NL_STATUS_PARSE_ERROR, "");
    check_load_refused(world, navmesh, "", NL_STATUS_PARSE_ERROR, "");
    check_load_refused(world, navmesh, "{\"format\": \"navlink-paths\", \"version\": 1, \"links\": []}",
                       NL_STATUS_VERSION_MISMATCH, "format");
    check_load_refused(world, navmesh, "{\"format\": \"navlink-links\", \"version\": 2, \"links\": []}",
                       NL_STATUS_VERSION_MISMATCH, "version");
    check_load_refused(world, navmesh, LINKS_HEAD "[{\"kind\": \"manual\", \"end\": [6, 0, 0]}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].start");
    check_load_refused(world, navmesh,
                       LINKS_HEAD
                       "[{\"kind\": \"manual\", \"start\": [-6, 0, 0], \"end\": [6, 0, 0]},"
                       " {\"kind\": \"drop\", \"start\": [-6, 0, 0]}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[1].end");
    check_load_refused(world, navmesh, LINKS_HEAD "[{\"start\": [-6, 0, 0], \"end\": [6, 0, 0]}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].kind");
    check_load_refused(world, navmesh,
                       LINKS_HEAD "[{\"kind\": \"teleport\", \"start\": [-6, 0, 0], \"end\": [6, 0, 0]}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].kind");
    check_load_refused(world, navmesh, LINKS_HEAD "[{\"kind\": \"manual\", \"start\": [-6, 0], \"end\": [6, 0, 0]}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].start");
    check_load_refused(world, navmesh,
                       LINKS_HEAD
                       "[{\"kind\": \"manual\", \"start\": [-6, 0, 0], \"end\": [6, 0, 0], "
                       "\"cost_modifier\": -1}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].cost_modifier");
    check_load_refused(world, navmesh,
                       LINKS_HEAD
                       "[{\"kind\": \"manual\", \"start\": [-6, 0, 0], \"end\": [6, 0, 0], "
                       "\"bidirectional\": 1}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].bidirectional");
    /* The path named is the file's: the key is "requires". */
    check_load_refused(world, navmesh,
                       LINKS_HEAD
                       "[{\"kind\": \"manual\", \"start\": [-6, 0, 0], \"end\": [6, 0, 0], "
                       "\"requires\": {\"gap\": \"wide\"}}]}",
                       NL_STATUS_INVALID_ARGUMENT, "links[0].requires.gap");
    check_load_refused(world, navmesh, LINKS_HEAD "{}}", NL_STATUS_INVALID_ARGUMENT, "links");
    {
        uint32_t n0 = 0, n1 = 0;
        nl_link* before = list_links(world, navmesh, &n0);
        nl_link* after;
        CHECK_INVALID(nl_navmesh_load_links_json(world, navmesh, NULL, 10, 0, &count), "json");
        CHECK_FAIL(nl_navmesh_load_links_json(world, navmesh, NULL, 0, 0, &count), NL_STATUS_PARSE_ERROR, "");
        after = list_links(world, navmesh, &n1);
        CHECK(same_list(before, n0, after, n1));
        free(before);
        free(after);
    }

    /* Optional fields take their defaults: one-way, enabled, cost 1, manual, apex the higher end. */
    {
        static const char minimal[] =
            LINKS_HEAD "[{\"kind\": \"manual\", \"start\": [-6, 0.5, 0], \"end\": [6, 0, 0]}]}";
        nl_link* l;
        CHECK_OK(nl_navmesh_load_links_json(world, navmesh, minimal, sizeof minimal - 1u, 0, &count));
        CHECK(count == 1u);
        l = list_links(world, navmesh, &n_loaded);
        if (CHECK(n_loaded == 1u)) {
            CHECK(l[0].kind == NL_LINK_MANUAL && l[0].bidirectional == 0 && l[0].enabled == 1 && l[0].generated == 0 &&
                  l[0].cost_modifier == 1.0f && l[0].user_data == 0u);
            CHECK(l[0].apex[0] == -6.0f && l[0].apex[1] == 0.5f && l[0].apex[2] == 0.0f);
            CHECK(l[0].start_polygon != NL_NO_POLYGON && l[0].end_polygon != NL_NO_POLYGON);
        }
        free(l);
    }
    /* An empty list empties the navmesh. */
    CHECK_OK(nl_navmesh_load_links_json(world, navmesh, LINKS_HEAD "[]}", strlen(LINKS_HEAD "[]}"), 0, &count));
    CHECK(count == 0u && link_count(world, navmesh) == 0u);

    /* A stale navmesh. */
    CHECK_OK(nl_navmesh_remove(world, navmesh));
    CHECK_FAIL(nl_navmesh_save_links_json(world, navmesh, NULL, 0, &length), NL_STATUS_INVALID_HANDLE, "navmesh");
    CHECK_FAIL(nl_navmesh_load_links_json(world, navmesh, LINKS_HEAD "[]}", strlen(LINKS_HEAD "[]}"), 0, &count),
               NL_STATUS_INVALID_HANDLE, "navmesh");
    free(saved);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Settings from JSON
 * ------------------------------------------------------------------------------------------- */

/* Field by field: the struct has padding on LP64 (before plugin_settings_json). */
static int same_settings(const nl_link_settings* a, const nl_link_settings* b) {
    return a->size == b->size && a->min_edge_length == b->min_edge_length && a->min_group_size == b->min_group_size &&
           a->max_group_size == b->max_group_size && a->sample_spacing == b->sample_spacing &&
           a->falloff_distance == b->falloff_distance && a->max_jump_gap == b->max_jump_gap &&
           a->min_link_distance == b->min_link_distance && a->short_link_distance == b->short_link_distance &&
           a->max_jump_up == b->max_jump_up && a->jump_arc_height == b->jump_arc_height &&
           a->strict_forward_angle == b->strict_forward_angle &&
           a->permissive_forward_angle == b->permissive_forward_angle &&
           a->strict_incline_angle == b->strict_incline_angle &&
           a->permissive_incline_angle == b->permissive_incline_angle && a->max_drop_distance == b->max_drop_distance &&
           memcmp(a->drop_angles, b->drop_angles, sizeof a->drop_angles) == 0 &&
           a->drop_angle_count == b->drop_angle_count && a->drop_steepness == b->drop_steepness &&
           a->merge_distance == b->merge_distance && a->clearance_margin == b->clearance_margin &&
           a->arc_segments == b->arc_segments && a->plugin_settings_json == b->plugin_settings_json &&
           a->plugin_settings_json_length == b->plugin_settings_json_length;
}

static void check_settings_refused(const char* json, nl_status detail, const char* needle) {
    nl_link_settings s = nl_default_link_settings(), copy;
    s.merge_distance = 0.9f; /* not all defaults: nothing may be reset */
    copy = s;
    if (!CHECK_FAIL(nl_link_settings_from_json(json, strlen(json), &s), detail, needle))
        fprintf(stderr, "    (the JSON: %s)\n", json);
    CHECK_MSG(same_settings(&s, &copy), "settings changed by a refused JSON (%s)", json);
}

static void settings_json(void) {
    static const char good[] =
        "{\"max_jump_gap\": 6, \"min_group_size\": 3, \"drop_angles\": [0, 45], \"jump_arc_height\": 1.5}";
    nl_link_settings s = nl_default_link_settings(), expected;

    s.merge_distance = 0.9f;
    expected = s;
    expected.max_jump_gap = 6.0f;
    expected.min_group_size = 3u;
    expected.drop_angle_count = 2u;
    expected.drop_angles[0] = 0.0f;
    expected.drop_angles[1] = 45.0f;
    expected.drop_angles[2] = 0.0f;
    expected.jump_arc_height = 1.5f;
    CHECK_OK(nl_link_settings_from_json(good, sizeof good - 1u, &s));
    CHECK_MSG(same_settings(&s, &expected), "the keys given were applied over the struct and nothing else changed");
    CHECK_OK(nl_link_settings_from_json("{}", 2, &s));
    CHECK(same_settings(&s, &expected));
    /* The host's borrowed plugin settings pointer is the host's: applying JSON keeps it. */
    {
        static const char plugin_json[] = "{\"climb\": {\"max_height\": 3}}";
        static const char merge[] = "{\"merge_distance\": 0.7}";
        s.plugin_settings_json = plugin_json;
        s.plugin_settings_json_length = sizeof plugin_json - 1u;
        expected = s;
        CHECK_OK(nl_link_settings_from_json(merge, sizeof merge - 1u, &s));
        expected.merge_distance = 0.7f;
        CHECK_THAT(same_settings(&s, &expected),
                   "nl_link_settings_from_json: plugin_settings_json and its length are kept (only the JSON's keys "
                   "change)");
        s = nl_default_link_settings();
        s.merge_distance = 0.9f;
        expected = s;
    }

    check_settings_refused("{\"max_link_distanse\": 6}", NL_STATUS_INVALID_ARGUMENT, "max_link_distanse");
    check_settings_refused("{\"max_jump_gap\": ", NL_STATUS_PARSE_ERROR, "");
    check_settings_refused("[1, 2]", NL_STATUS_INVALID_ARGUMENT, "settings");
    check_settings_refused("", NL_STATUS_PARSE_ERROR, "");
    check_settings_refused("{\"max_jump_gap\": \"far\"}", NL_STATUS_INVALID_ARGUMENT, "max_jump_gap");
    check_settings_refused("{\"max_jump_gap\": -1}", NL_STATUS_INVALID_ARGUMENT, "max_jump_gap");
    check_settings_refused("{\"arc_segments\": -1}", NL_STATUS_INVALID_ARGUMENT, "arc_segments");
    check_settings_refused("{\"arc_segments\": 1}", NL_STATUS_INVALID_ARGUMENT, "arc_segments");
    check_settings_refused("{\"drop_angles\": 30}", NL_STATUS_INVALID_ARGUMENT, "drop_angles");
    check_settings_refused("{\"drop_angles\": [0, \"x\"]}", NL_STATUS_INVALID_ARGUMENT, "drop_angles[1]");
    check_settings_refused("{\"drop_angles\": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17]}", NL_STATUS_INVALID_ARGUMENT,
                           "drop_angles");
    /* A good key before a bad one: still nothing applied. */
    check_settings_refused("{\"max_jump_gap\": 6, \"nope\": 1}", NL_STATUS_INVALID_ARGUMENT, "nope");

    CHECK_INVALID(nl_link_settings_from_json("{}", 2, NULL), "settings");
    CHECK_INVALID(nl_link_settings_from_json(NULL, 2, &s), "json");
    {
        nl_link_settings small = nl_default_link_settings();
        small.size = 4u;
        CHECK_INVALID(nl_link_settings_from_json("{}", 2, &small), "settings->size");
        CHECK(small.size == 4u && small.max_jump_gap == 4.0f);
    }
    /* Settings from JSON generate: a max_jump_gap below the gap leaves no jump. */
    {
        nl_world* world = make_world(1);
        const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
        static const char short_reach[] = "{\"max_jump_gap\": 1.8}";
        nl_link_generation_report r = empty_report();
        s = nl_default_link_settings();
        CHECK_OK(nl_link_settings_from_json(short_reach, sizeof short_reach - 1u, &s));
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &s, NULL, NULL, &r));
        CHECK(r.jump_links == 0u);
        nl_world_destroy(world);
    }
}

/* ---------------------------------------------------------------------------------------------
 * Cancelling a generation
 * ------------------------------------------------------------------------------------------- */

/* A progress callback that generates another navmesh: refused at once (it could wait for the generation that
   called it; two threads doing it crosswise used to hang forever), and the outer generation goes on. */
typedef struct {
    nl_world* world;
    nl_navmesh_id other;
    nl_status inner_generate, inner_update;
    int calls;
} nested_generation;

static int32_t generate_from_progress(void* user, float fraction, const char* stage) {
    nested_generation* n = (nested_generation*)user;
    static const float lo[3] = {-1.0f, -1.0f, -1.0f}, hi[3] = {1.0f, 1.0f, 1.0f};
    (void)fraction;
    (void)stage;
    if (n->calls++ == 0) {
        n->inner_generate = nl_navmesh_generate_links(n->world, n->other, NULL, NULL, NULL, NULL);
        n->inner_update = nl_navmesh_update_links_in_box(n->world, n->other, lo, hi, NULL, NULL, NULL);
    }
    return 1;
}

static void nested_generation_refused(void) {
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_LEDGE);
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nested_generation n;
    memset(&n, 0, sizeof n);
    n.world = world;
    CHECK_OK(nl_navmesh_build(world, &build, &n.other));
    CHECK_OK(nl_navmesh_generate_links(world, n.other, NULL, NULL, NULL, NULL));
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, generate_from_progress, &n, NULL));
    CHECK(n.calls > 1);
    CHECK(n.inner_generate == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(n.inner_update == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(link_count(world, navmesh) > 0u);
    /* After it, on the same thread, generations run again. */
    CHECK_OK(nl_navmesh_generate_links(world, n.other, NULL, NULL, NULL, NULL));
    nl_world_destroy(world);
}

static void cancel(void) {
    static const char* const stages[] = {"edges", "take-off points", "jumps", "drops", "merge"};
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_LEDGE);
    nl_link* before;
    uint32_t n0 = 0, i;
    size_t k;

    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL));
    before = list_links(world, navmesh, &n0);
    CHECK(n0 > 0u);

    for (k = 0; k < sizeof stages / sizeof stages[0]; ++k) {
        progress_log log = new_progress_log();
        nl_link_generation_report r = empty_report();
        nl_link_settings s = nl_default_link_settings();
        nl_link* after;
        uint32_t n1 = 0;
        s.drop_angle_count = 1; /* another result, were it kept */
        log.cancel_at_stage = stages[k];
        CHECK_FAIL(nl_navmesh_generate_links(world, navmesh, &s, record_progress, &log, &r), NL_STATUS_CANCELLED,
                   "cancel");
        CHECK_MSG(strcmp(log.last_stage, stages[k]) == 0, "cancelled at \"%s\", the last stage seen was \"%s\"",
                  stages[k], log.last_stage);
        CHECK_MSG(all_bytes((const char*)&r + sizeof r.size, sizeof r - sizeof r.size, 0xab),
                  "a cancelled generation wrote the report (stage %s)", stages[k]);
        after = list_links(world, navmesh, &n1);
        CHECK_MSG(same_list(before, n0, after, n1), "cancelled at \"%s\": the links are not as they were", stages[k]);
        for (i = 0; i < n0; ++i) CHECK(nl_link_is_valid(world, before[i].id) == 1);
        free(after);
    }
    /* Cancelled at the first call. */
    {
        progress_log log = new_progress_log();
        log.cancel_at_call = 1;
        CHECK_FAIL(nl_navmesh_generate_links(world, navmesh, NULL, record_progress, &log, NULL), NL_STATUS_CANCELLED,
                   "");
        CHECK(log.calls == 1);
        CHECK(link_count(world, navmesh) == n0);
    }
    free(before);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Incremental regeneration: nl_navmesh_update_links_in_box
 * ------------------------------------------------------------------------------------------- */

static void update_in_box(void) {
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_GAP);
    const float wall_min[3] = {-0.1f, -20.0f, -6.0f}, wall_max[3] = {0.1f, 6.0f, 6.0f};
    const float far_min[3] = {8.0f, -1.0f, -1.0f}, far_max[3] = {9.0f, 1.0f, 1.0f};
    const nl_link_def def = manual_def();
    nl_link_id manual = {0u, 0u};
    nl_mesh_id wall = {0u, 0u};
    nl_link_generation_report full = empty_report(), r = empty_report();
    progress_log log = new_progress_log();
    nl_link *original, *now, *after;
    uint32_t n_original = 0, n_now = 0, n_after = 0, i;

    /* Never generated: nothing to update. */
    CHECK_FAIL(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, NULL, NULL, NULL),
               NL_STATUS_NOT_FOUND, "nl_navmesh_generate_links");
    CHECK(link_count(world, navmesh) == 0u);

    CHECK_OK(nl_link_add(world, navmesh, &def, &manual));
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &full));
    CHECK(full.jump_links > 0u);
    original = list_links(world, navmesh, &n_original);

    /* Refusals, each changing nothing. */
    {
        const float nan_min[3] = {NAN, 0.0f, 0.0f}, inverted_max[3] = {-1.0f, 6.0f, 6.0f};
        nl_link_generation_report small = empty_report();
        small.size = 8u;
        CHECK_INVALID(nl_navmesh_update_links_in_box(world, navmesh, NULL, wall_max, NULL, NULL, NULL), "box_min");
        CHECK_INVALID(nl_navmesh_update_links_in_box(world, navmesh, wall_min, NULL, NULL, NULL, NULL), "box_max");
        CHECK_INVALID(nl_navmesh_update_links_in_box(world, navmesh, nan_min, wall_max, NULL, NULL, NULL), "box_min");
        CHECK_INVALID(nl_navmesh_update_links_in_box(world, navmesh, wall_min, inverted_max, NULL, NULL, NULL), "box");
        CHECK_INVALID(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, NULL, NULL, &small),
                      "out_report->size");
        CHECK_INVALID(nl_navmesh_update_links_in_box(NULL, navmesh, wall_min, wall_max, NULL, NULL, NULL), "world");
        log.cancel_at_stage = "jumps";
        CHECK_FAIL(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, record_progress, &log, &r),
                   NL_STATUS_CANCELLED, "cancel");
        CHECK(all_bytes((const char*)&r + sizeof r.size, sizeof r - sizeof r.size, 0xab));
        now = list_links(world, navmesh, &n_now);
        CHECK_THAT(same_list(original, n_original, now, n_now), "refused or cancelled updates change nothing");
        free(now);
    }

    /* Nothing changed in the level: the same links (generated ones under new ids), the manual one kept. */
    log = new_progress_log();
    r = empty_report();
    CHECK_OK(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, record_progress, &log, &r));
    CHECK(log.calls >= 3 && log.decreasing == 0 && log.out_of_range == 0 && log.last == 1.0f && log.other_thread == 0);
    now = list_links(world, navmesh, &n_now);
    check_report(&r, n_now - 1u, "update, nothing changed");
    CHECK(n_now == n_original && r.jump_links == full.jump_links);
    CHECK_MSG(r.rays_cast < full.rays_cast, "an update cast %llu rays, the full generation %llu",
              (unsigned long long)r.rays_cast, (unsigned long long)full.rays_cast);
    for (i = 0; i < n_now && i < n_original; ++i)
        CHECK_MSG(same_fields(&now[i], &original[i], 1), "link %u changed", (unsigned)i);
    CHECK(n_now > 0u && same_link_id(now[0].id, manual) && nl_link_is_valid(world, manual) == 1);
    for (i = 1; i < n_original; ++i) CHECK(nl_link_is_valid(world, original[i].id) == 0);
    free(now);

    /* A wall stands up in the gap: the update in its box removes every jump, as a full generation does. */
    CHECK_OK(add_box_id(world, wall_min[0], wall_min[1], wall_min[2], wall_max[0], wall_max[1], wall_max[2], &wall));
    r = empty_report();
    CHECK_OK(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, NULL, NULL, &r));
    now = list_links(world, navmesh, &n_now);
    CHECK(r.jump_links == 0u && r.rejected_clearance > 0u);
    CHECK(n_now == 1u && same_link_id(now[0].id, manual));
    CHECK_OK(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, &full));
    after = list_links(world, navmesh, &n_after);
    CHECK_THAT(n_after == n_now && full.jump_links == 0u && full.rejected_clearance == r.rejected_clearance,
               "nl_navmesh_update_links_in_box equals nl_navmesh_generate_links after a wall was added");
    free(now);
    free(after);

    /* The wall goes: an update in a box that misses it keeps the old answer (the box matters) ... */
    CHECK_OK(nl_mesh_remove(world, wall));
    CHECK_OK(nl_navmesh_update_links_in_box(world, navmesh, far_min, far_max, NULL, NULL, NULL));
    CHECK(link_count(world, navmesh) == 1u);
    /* ... and one in the wall's box brings back the original links, field for field. */
    CHECK_OK(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, NULL, NULL, &r));
    now = list_links(world, navmesh, &n_now);
    CHECK(n_now == n_original);
    for (i = 0; i < n_now && i < n_original; ++i)
        CHECK_MSG(same_fields(&now[i], &original[i], 1), "after the wall went, link %u differs from the original",
                  (unsigned)i);
    free(now);

    /* Removing the navmesh forgets its generation. */
    CHECK_OK(nl_navmesh_remove(world, navmesh));
    CHECK_FAIL(nl_navmesh_update_links_in_box(world, navmesh, wall_min, wall_max, NULL, NULL, NULL),
               NL_STATUS_INVALID_HANDLE, "navmesh");
    free(original);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * A navmesh removed while its links are being generated
 * ------------------------------------------------------------------------------------------- */

typedef struct remove_during_generation {
    nl_world* world;
    nl_navmesh_id navmesh;
    nl_status removed;
    int done;
} remove_during_generation;

static int remove_navmesh_late(void* user, float fraction, const char* stage) {
    remove_during_generation* job = (remove_during_generation*)user;
    (void)stage;
    if (fraction >= 0.9f && !job->done) { /* as another thread could, at any moment */
        job->done = 1;
        job->removed = nl_navmesh_remove(job->world, job->navmesh);
    }
    return 1;
}

static void navmesh_removed_during_generation(void) {
    nl_world* world = make_world(1);
    remove_during_generation job;
    nl_link* old;
    uint32_t n = 0, i, live = 0;

    job.world = world;
    job.navmesh = build_level(world, LEVEL_GAP);
    job.removed = 0;
    job.done = 0;
    CHECK_OK(nl_navmesh_generate_links(world, job.navmesh, NULL, NULL, NULL, NULL));
    old = list_links(world, job.navmesh, &n);
    {
        const nl_status st = nl_navmesh_generate_links(world, job.navmesh, NULL, remove_navmesh_late, &job, NULL);
        CHECK(job.done && job.removed == NL_STATUS_SUCCESS);
        CHECK_THAT(
            st == (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE) || st == NL_STATUS_SUCCESS,
            "nl_navmesh_generate_links: a navmesh removed during the generation is INVALID_HANDLE (or a success whose "
            "links went with the navmesh)");
    }
    CHECK(nl_navmesh_is_valid(world, job.navmesh) == 0);
    /* "Removes a navmesh and its links": no link of the removed navmesh may be reachable afterwards. The
       generation's links are not listed anywhere, so look for them where c-api.md says ids come from:
       the same slots, next generations. */
    for (i = 0; i < n; ++i) {
        uint32_t k;
        for (k = 1; k <= 4; ++k) {
            nl_link_id probe = old[i].id;
            nl_link got = nl_link_init();
            probe.revision += k;
            if (nl_link_is_valid(world, probe) && NL_SUCCEEDED(nl_link_get(world, probe, &got))) ++live;
        }
    }
    CHECK_MSG(live == 0,
              "nl_navmesh_generate_links stored %u links for a navmesh removed while it ran (nl_link_get finds "
              "them; their navmesh id is stale)",
              (unsigned)live);
    free(old);
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * Threads: lists read while another thread regenerates
 * ------------------------------------------------------------------------------------------- */

enum { GENERATIONS = 3, READERS = 2, CAPACITY = 1024 };

typedef struct reader_job {
    nl_world* world;
    nl_navmesh_id navmesh;
    uint32_t jumps[GENERATIONS], drops[GENERATIONS], manual;
    atomic_int* stop;
    int lists, failures, inconsistent, get_differs;
    nl_link buffer[CAPACITY];
} reader_job;

static void* reader_thread(void* arg) {
    reader_job* job = (reader_job*)arg;
    while (!atomic_load(job->stop) || job->lists < 20) {
        uint32_t n = 0, g, i, k, jumps, drops, manual;
        int matches = 0, distinct = 1;
        if (NL_FAILED(nl_navmesh_get_links(job->world, job->navmesh, job->buffer, CAPACITY, &n))) {
            ++job->failures;
            continue;
        }
        ++job->lists;
        jumps = count_kind(job->buffer, n, NL_LINK_JUMP);
        drops = count_kind(job->buffer, n, NL_LINK_DROP);
        manual = count_kind(job->buffer, n, NL_LINK_MANUAL);
        for (g = 0; g < GENERATIONS; ++g)
            matches |= jumps == job->jumps[g] && drops == job->drops[g] && manual == job->manual &&
                       n == job->jumps[g] + job->drops[g] + job->manual;
        for (i = 0; i < n && i < 64; ++i)
            for (k = i + 1; k < n; ++k) distinct &= !same_link_id(job->buffer[i].id, job->buffer[k].id);
        if (!matches || !distinct) ++job->inconsistent;
        /* A listed link is either gone since, or exactly as listed. */
        for (i = 0; i < n; i += 7) {
            nl_link got = nl_link_init();
            const nl_status st = nl_link_get(job->world, job->buffer[i].id, &got);
            if (st == NL_STATUS_SUCCESS ? memcmp(&got, &job->buffer[i], sizeof got) != 0
                                        : st != (NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE))
                ++job->get_differs;
        }
    }
    return NULL;
}

static void threads(void) {
    nl_world* world = make_world(2);
    const nl_navmesh_id navmesh = build_level(world, LEVEL_LEDGE);
    nl_link_settings settings[GENERATIONS];
    reader_job* jobs = (reader_job*)calloc(READERS, sizeof *jobs);
    pthread_t threads[READERS];
    int started[READERS];
    atomic_int stop;
    nl_link_def manual = nl_default_link_def();
    nl_link_id manual_id = {0u, 0u};
    int g, i, regenerations_ok = 1, distinct;
    atomic_init(&stop, 0);
    if (!CHECK(jobs != NULL)) {
        nl_world_destroy(world);
        return;
    }

    /* Three settings with three different results on the ledge (and one manual link throughout). */
    settings[0] = nl_default_link_settings();
    settings[1] = nl_default_link_settings();
    settings[1].max_drop_distance = 2.9f;
    settings[2] = nl_default_link_settings();
    settings[2].sample_spacing = 0.5f;
    set3(manual.start, -5.0f, 3.0f, 0.0f);
    set3(manual.end, 5.0f, 0.0f, 0.0f);
    CHECK_OK(nl_link_add(world, navmesh, &manual, &manual_id));
    for (g = 0; g < GENERATIONS; ++g) {
        nl_link_generation_report r = empty_report();
        CHECK_OK(nl_navmesh_generate_links(world, navmesh, &settings[g], NULL, NULL, &r));
        for (i = 0; i < READERS; ++i) {
            jobs[i].jumps[g] = r.jump_links;
            jobs[i].drops[g] = r.drop_links;
        }
    }
    distinct = jobs[0].drops[0] != jobs[0].drops[1] && jobs[0].drops[0] != jobs[0].drops[2] &&
               jobs[0].drops[1] != jobs[0].drops[2];
    CHECK_MSG(distinct, "the three settings give %u, %u and %u drops: the test needs three different counts",
              (unsigned)jobs[0].drops[0], (unsigned)jobs[0].drops[1], (unsigned)jobs[0].drops[2]);
    CHECK(jobs[0].jumps[0] + jobs[0].drops[0] + 1u < CAPACITY && jobs[0].jumps[2] + jobs[0].drops[2] + 1u < CAPACITY);

    for (i = 0; i < READERS; ++i) {
        jobs[i].world = world;
        jobs[i].navmesh = navmesh;
        jobs[i].manual = 1;
        jobs[i].buffer[0] = nl_link_init();
        jobs[i].stop = &stop;
        started[i] = pthread_create(&threads[i], NULL, reader_thread, &jobs[i]) == 0;
        CHECK(started[i]);
    }
    for (g = 0; g < 24; ++g) {
        if (NL_FAILED(nl_navmesh_generate_links(world, navmesh, &settings[g % GENERATIONS], NULL, NULL, NULL)))
            regenerations_ok = 0;
    }
    atomic_store(&stop, 1);
    CHECK(regenerations_ok);
    for (i = 0; i < READERS; ++i) {
        if (started[i]) pthread_join(threads[i], NULL);
        CHECK_MSG(jobs[i].failures == 0, "reader %d: %d lists failed", i, jobs[i].failures);
        CHECK_MSG(jobs[i].inconsistent == 0, "reader %d: %d of %d lists were not one generation's links", i,
                  jobs[i].inconsistent, jobs[i].lists);
        CHECK_MSG(jobs[i].get_differs == 0, "reader %d: %d listed links read back differently", i, jobs[i].get_differs);
        CHECK(jobs[i].lists >= 20);
    }
    CHECK(nl_link_is_valid(world, manual_id) == 1);
    free(jobs);
    nl_world_destroy(world);
}

ABI_SECTION(links, ABI_CASE(defaults), ABI_CASE(generation_gap), ABI_CASE(generation_ledge), ABI_CASE(manual),
            ABI_CASE(refusals), ABI_CASE(ids), ABI_CASE(ids_never_come_back), ABI_CASE(lists), ABI_CASE(json),
            ABI_CASE(settings_json), ABI_CASE(cancel), ABI_CASE(nested_generation_refused), ABI_CASE(update_in_box),
            ABI_CASE(navmesh_removed_during_generation), ABI_CASE(threads));
