/*
 * The hostile cases of navlink/links.h: links added and updated, their ids, a navmesh's links,
 * link settings, generation (on a navmesh, across two, in a box), and the links' JSON.
 */
#include "hostile_fixtures.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const float_field k_link_def_floats[] = {
    FLOAT_FIELD(nl_link_def, start, 3),
    FLOAT_FIELD(nl_link_def, end, 3),
    FLOAT_FIELD(nl_link_def, cost_modifier, 1),
    FLOAT_FIELD(nl_link_def, requirements.gap, 1),
    FLOAT_FIELD(nl_link_def, requirements.rise, 1),
    FLOAT_FIELD(nl_link_def, requirements.drop, 1),
    FLOAT_FIELD(nl_link_def, requirements.clearance_width, 1),
    FLOAT_FIELD(nl_link_def, requirements.length, 1),
    FLOAT_FIELD(nl_link_def, tolerance, 1),
};

static const def_case k_link_defs[] = {
    {"def->start off the navmesh (10 m above)", INVALID, "def->start", {SET_F32(nl_link_def, start[1], 10.0f)}},
    {"def->end beyond the limit (2e9)", INVALID, "def->end", {SET_F32(nl_link_def, end[2], 2.0e9f)}},
    {"def->kind 0", INVALID, "kind", {SET_U32(nl_link_def, kind, 0u)}},
    {"def->kind 4", INVALID, "kind", {SET_U32(nl_link_def, kind, 4u)}},
    {"def->kind 255", INVALID, "kind", {SET_U32(nl_link_def, kind, 255u)}},
    {"def->cost_modifier negative", INVALID, "cost_modifier", {SET_F32(nl_link_def, cost_modifier, -1.0f)}},
    {"def->requirements.gap negative", INVALID, "gap", {SET_F32(nl_link_def, requirements.gap, -1.0f)}},
    {"def->requirements.length negative", INVALID, "length", {SET_F32(nl_link_def, requirements.length, -1.0f)}},
    {"def->requirements.clearance_width negative",
     INVALID,
     "clearance_width",
     {SET_F32(nl_link_def, requirements.clearance_width, -1.0f)}},
};

/* nl_link_add on A's navmesh, and nl_link_update of A's manual link (which has no output). */
static nl_status link_add_def_call(nl_world* world, const void* def, void* out) {
    return nl_link_add(world, A.navmesh, (const nl_link_def*)def, (nl_link_id*)out);
}
static nl_status link_update_def_call(nl_world* world, const void* def, void* out) {
    (void)out;
    return nl_link_update(world, A.link, (const nl_link_def*)def);
}
/* An added link is removed again; the manual link updated with the def it was made from is as it was. */
static void remove_link_out(const void* out) {
    nl_link_id id;
    memcpy(&id, out, sizeof id);
    EXPECT(nl_link_is_valid(A.world, id) == 1, "the new link is not valid");
    EXPECT_OK(nl_link_remove(A.world, id));
}
static void nothing_to_undo(const void* out) { (void)out; }
static const def_function k_link_add = {"nl_link_add", link_add_def_call, sizeof(nl_link_id), remove_link_out, 0, 0, 1};
static const def_function k_link_update = {"nl_link_update", link_update_def_call, 0, nothing_to_undo, 0, 0, 1};

/* The def's cases of nl_link_add and nl_link_update. */
static void link_def_cases(const def_function* f) {
    const nl_link_def valid = gap_link_def();
    def_function_cases(f, &valid, sizeof valid);
    def_cases(f->function, &valid, sizeof valid, k_link_defs, sizeof k_link_defs / sizeof *k_link_defs, def_refuses,
              def_accepts);
    bad_float_fields(f->function, "def", &valid, sizeof valid, k_link_def_floats,
                     sizeof k_link_def_floats / sizeof *k_link_def_floats, def_refuses);
    optional_id_cases(f, &valid, sizeof valid, offsetof(nl_link_def, landing_navmesh), "def->landing_navmesh",
                      RAW(A.host_navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(f->function, "def->landing_navmesh the link's own navmesh") {
        nl_link_def def = valid;
        def.landing_navmesh = A.navmesh;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->landing_navmesh is the link's own navmesh");
    }
    CASE(f->function, "def->landing_navmesh with bidirectional set") {
        nl_link_def def = valid;
        def.landing_navmesh = A.host_navmesh;
        def.bidirectional = 1;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->bidirectional");
    }
    CASE(f->function, "def->landing_navmesh with the end off it") {
        nl_link_def def = valid; /* the end lies on the link's own navmesh, 40 m from the lift's */
        def.landing_navmesh = A.host_navmesh;
        def.bidirectional = 0;
        def_refuses(&def, NL_STATUS_INVALID_ARGUMENT, "def->end is not within");
    }
}

static const nl_link_def* g_link_def;
static nl_status link_add_call(nl_world* w, raw_id id, void* out) {
    return nl_link_add(w, AS(nl_navmesh_id, id), g_link_def, (nl_link_id*)out);
}
static nl_status link_update_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_link_update(w, AS(nl_link_id, id), g_link_def);
}
ID_CALL(link_remove_call, nl_link_id, nl_link_remove)
ID_VALID_CALL(link_is_valid_call, nl_link_id, nl_link_is_valid)
ID_OUT_CALL(link_get_call, nl_link_id, nl_link, nl_link_get)
static const id_function k_link_functions[] = {
    {"nl_link_add", "navmesh", "out_id", sizeof(nl_link_id), 0, 0, link_add_call, 0},
    {"nl_link_update", "link", NULL, 0, 0, 0, link_update_call, 0},
    {"nl_link_remove", "link", NULL, 0, 0, 0, link_remove_call, 0},
    {"nl_link_is_valid", "link", NULL, 0, 0, 1, link_is_valid_call, 0},
    {"nl_link_get", "link", "out_link", sizeof(nl_link), 0, 0, link_get_call, 0},
};

/* The link functions' id cases; nl_link_add's id is the navmesh's. The world NULL is id_cases'. */
static void link_id_cases(size_t which) {
    const nl_link_def def = gap_link_def();
    g_link_def = &def;
    if (which == 0)
        id_cases(&k_link_functions[0], RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    else
        id_cases(&k_link_functions[which], RAW(A.link), RAW(A.stale_link), RAW(B.link));
}

static void group_link_add(void) {
    link_id_cases(0);
    link_def_cases(&k_link_add);
}

static void group_link_update(void) {
    link_id_cases(1);
    link_def_cases(&k_link_update);
}

static void group_link_remove(void) { link_id_cases(2); }
static void group_link_is_valid(void) { link_id_cases(3); }
static nl_status link_into(void* out, uint32_t* written) {
    *written = 1u;
    return nl_link_get(A.world, A.link, (nl_link*)out);
}
static void group_link_get(void) {
    link_id_cases(4);
    out_element_sizes("nl_link_get", "out_link", sizeof(nl_link), link_into);
}

static uint32_t link_count(nl_navmesh_id navmesh) {
    uint32_t n = 0;
    if (NL_FAILED(nl_navmesh_get_links(A.world, navmesh, NULL, 0, &n))) fixture_failed("nl_navmesh_get_links");
    return n;
}

static nl_status list_links(const nl_world* w, nl_navmesh_id n, void* out, uint32_t capacity, uint32_t* count) {
    return nl_navmesh_get_links(w, n, (nl_link*)out, capacity, count);
}
static nl_status links_into(void* out, uint32_t* written) {
    return nl_navmesh_get_links(A.world, A.navmesh, (nl_link*)out, 256u, written);
}
static void group_navmesh_get_links(void) {
    g_growable_items = 1;
    navmesh_list_cases("nl_navmesh_get_links", "out_links", sizeof(nl_link), link_count(A.navmesh), list_links);
    g_growable_items = 0;
    out_element_sizes("nl_navmesh_get_links", "out_links", sizeof(nl_link), links_into);
}

ID_OUT_CALL(remove_generated_call, nl_navmesh_id, uint32_t, nl_navmesh_remove_generated_links)

static void group_navmesh_remove_generated_links(void) {
    static const id_function f = {"nl_navmesh_remove_generated_links",
                                  "navmesh",
                                  "out_removed",
                                  sizeof(uint32_t),
                                  0,
                                  0,
                                  remove_generated_call,
                                  1};
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_remove_generated_links", "out_removed NULL (allowed: the manual link stays)") {
        const uint32_t before = link_count(A.navmesh);
        EXPECT_OK(nl_navmesh_remove_generated_links(A.world, A.navmesh, NULL));
        EXPECT(link_count(A.navmesh) == 1u && before > 1u, "%u links before, %u after (the manual one should stay)",
               (unsigned)before, (unsigned)link_count(A.navmesh));
        EXPECT(nl_link_is_valid(A.world, A.link) == 1, "the manual link went too");
        fixture_refresh();
    }
}

/* Link settings: every float of the struct. */
static const float_field k_link_settings_floats[] = {
    FLOAT_FIELD(nl_link_settings, min_edge_length, 1),      FLOAT_FIELD(nl_link_settings, sample_spacing, 1),
    FLOAT_FIELD(nl_link_settings, falloff_distance, 1),     FLOAT_FIELD(nl_link_settings, max_jump_gap, 1),
    FLOAT_FIELD(nl_link_settings, min_link_distance, 1),    FLOAT_FIELD(nl_link_settings, short_link_distance, 1),
    FLOAT_FIELD(nl_link_settings, max_jump_up, 1),          FLOAT_FIELD(nl_link_settings, jump_arc_height, 1),
    FLOAT_FIELD(nl_link_settings, strict_forward_angle, 1), FLOAT_FIELD(nl_link_settings, permissive_forward_angle, 1),
    FLOAT_FIELD(nl_link_settings, strict_incline_angle, 1), FLOAT_FIELD(nl_link_settings, permissive_incline_angle, 1),
    FLOAT_FIELD(nl_link_settings, max_drop_distance, 1),    FLOAT_FIELD(nl_link_settings, drop_angles, 3),
    FLOAT_FIELD(nl_link_settings, drop_steepness, 1),       FLOAT_FIELD(nl_link_settings, merge_distance, 1),
    FLOAT_FIELD(nl_link_settings, clearance_margin, 1),     FLOAT_FIELD(nl_link_settings, walk_factor, 1),
    FLOAT_FIELD(nl_link_settings, walk_distance, 1),
};

/* nl_link_settings_from_json's settings made bad: refused with "{}", the struct unchanged (the
   bytes past it too). */
static void from_json_refuses(const void* settings, nl_status detail, const char* needle) {
    aligned_buffer now, before;
    copy_def(&now, settings, sizeof(nl_link_settings));
    memcpy(before.bytes, now.bytes, sizeof before.bytes);
    EXPECT_FAILURE(NULL, nl_link_settings_from_json("{}", 2, (nl_link_settings*)(void*)now.bytes), detail, needle);
    EXPECT(memcmp(now.bytes, before.bytes, sizeof now.bytes) == 0, "settings changed on failure");
}

/* A larger struct: read and written up to the library's size, nothing past it. */
static void from_json_accepts(const void* settings) {
    aligned_buffer now;
    uint32_t size;
    copy_def(&now, settings, sizeof(nl_link_settings) + 64);
    EXPECT_OK(nl_link_settings_from_json("{\"sample_spacing\": 2}", 21, (nl_link_settings*)(void*)now.bytes));
    memcpy(&size, now.bytes, sizeof size);
    EXPECT(size == sizeof(nl_link_settings) + 64u && ((nl_link_settings*)(void*)now.bytes)->sample_spacing == 2.0f,
           "size %u, sample_spacing %g", (unsigned)size, ((nl_link_settings*)(void*)now.bytes)->sample_spacing);
    EXPECT_UNTOUCHED(now.bytes + sizeof(nl_link_settings), 64, "the bytes past the library's struct");
}

/* (json, length) pairs refused: the settings stay as they were. */
static const text_case k_settings_json[] = {
    {"json NULL (length 2)", NULL, 2, NL_STATUS_INVALID_ARGUMENT, "json"},
    {"length huge (json NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "json"},
    {"length 0 (an empty string is not a JSON object)", "{}", 0, NL_STATUS_PARSE_ERROR, ""},
    {"json malformed", TEXT("{\"sample_spacing\": "), NL_STATUS_PARSE_ERROR, ""},
    {"json NaN (not JSON)", TEXT("{\"merge_distance\": NaN}"), NL_STATUS_PARSE_ERROR, ""},
    {"json not an object", TEXT("[1, 2]"), NL_STATUS_INVALID_ARGUMENT, ""},
    {"json unknown key", TEXT("{\"no_such_key\": 1}"), NL_STATUS_INVALID_ARGUMENT, "no_such_key"},
    {"json wrong type", TEXT("{\"sample_spacing\": \"far\"}"), NL_STATUS_INVALID_ARGUMENT, "sample_spacing"},
    {"json inf (1e400)", TEXT("{\"sample_spacing\": 1e400}"), NL_STATUS_INVALID_ARGUMENT, "sample_spacing"},
    {"json -inf (-1e400)", TEXT("{\"merge_distance\": -1e400}"), NL_STATUS_INVALID_ARGUMENT, "merge_distance"},
    {"json drop_angles 17 entries", TEXT("{\"drop_angles\": [0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]}"),
     NL_STATUS_INVALID_ARGUMENT, "drop_angles"},
};

static const def_case k_settings_counts[] = {
    {"settings->drop_angle_count huge",
     INVALID,
     "drop_angle_count",
     {SET_U32(nl_link_settings, drop_angle_count, UINT32_MAX)}},
};

static void group_link_settings_from_json(void) {
    const nl_link_settings valid = nl_default_link_settings();
    size_t i;
    CASE("nl_link_settings_from_json", "settings NULL") {
        EXPECT_INVALID(NULL, nl_link_settings_from_json("{}", 2, NULL), "settings");
    }
    for (i = 0; i < sizeof k_settings_json / sizeof *k_settings_json; ++i) {
        const text_case* t = &k_settings_json[i];
        CASE("nl_link_settings_from_json", "%s", t->what) {
            nl_link_settings settings = valid;
            EXPECT_FAILURE(NULL, nl_link_settings_from_json(t->data, t->length, &settings), t->detail, t->needle);
            EXPECT(memcmp(&settings, &valid, sizeof settings) == 0, "settings changed on failure");
        }
    }
    def_sizes("nl_link_settings_from_json", "settings", &valid, sizeof valid, from_json_refuses, from_json_accepts);
    bad_float_fields("nl_link_settings_from_json", "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, from_json_refuses);
    def_cases("nl_link_settings_from_json", &valid, sizeof valid, k_settings_counts, 1, from_json_refuses,
              from_json_accepts);
}

/* nl_navmesh_generate_links and nl_navmesh_update_links_in_box on A's navmesh: refused before any
   work, the report untouched, the links as they were. */
static const float k_box_min[3] = {-3, -2, -6}, k_box_max[3] = {3, 2, 6};
static const float* g_box_min = k_box_min;
static const float* g_box_max = k_box_max;
static int g_update;
/* nl_navmesh_generate_cross_links between `navmesh` and A's lift navmesh (the same body's). */
static int g_cross;
static float g_tolerance = 0.25f;
static nl_status generate_call(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                               nl_progress_fn* progress, void* user, nl_link_generation_report* report) {
    if (g_cross)
        return nl_navmesh_generate_cross_links(world, navmesh, A.host_navmesh, g_tolerance, settings, progress, user,
                                               report);
    return g_update ? nl_navmesh_update_links_in_box(world, navmesh, g_box_min, g_box_max, progress, user, report)
                    : nl_navmesh_generate_links(world, navmesh, settings, progress, user, report);
}

static void generate_fails_with(nl_navmesh_id navmesh, const void* settings, nl_progress_fn* progress, void* user,
                                nl_status detail, const char* needle) {
    nl_link_generation_report report;
    fill(&report, sizeof report);
    report.size = sizeof report;
    EXPECT_FAILURE(A.world, generate_call(A.world, navmesh, (const nl_link_settings*)settings, progress, user, &report),
                   detail, needle);
    EXPECT_UNTOUCHED_AFTER_SIZE(&report, sizeof report, "out_report");
}

static void generate_refuses(const void* settings, nl_status detail, const char* needle) {
    generate_fails_with(A.navmesh, settings, NULL, NULL, detail, needle);
}

/* A generation as documented: the generated links get new ids, so the worlds' reference is taken again. */
static void generate_accepts(const void* settings) {
    EXPECT_OK(generate_call(A.world, A.navmesh, (const nl_link_settings*)settings, NULL, NULL, NULL));
    EXPECT(nl_link_is_valid(A.world, A.link) == 1, "the manual link went");
    fixture_refresh();
}

static nl_status generate_id_call(nl_world* w, raw_id id, void* out) {
    return generate_call(w, AS(nl_navmesh_id, id), NULL, NULL, NULL, (nl_link_generation_report*)out);
}

static nl_status generate_into(void* report) {
    const nl_status status = generate_call(A.world, A.navmesh, NULL, NULL, NULL, (nl_link_generation_report*)report);
    if (NL_SUCCEEDED(status)) fixture_refresh();
    return status;
}

/* What they share: the ids (the navmesh's parameter named `param`), the progress callback and its
   user, the report. */
static void generation_cases_of(const char* function, const char* param) {
    const id_function f = {function, param, "out_report", sizeof(nl_link_generation_report), 1, 0, generate_id_call, 1};
    int calls = 0;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "progress cancels (returns 0 at once)") {
        generate_fails_with(A.navmesh, NULL, cancel_at_once, &calls, NL_STATUS_CANCELLED, "");
        EXPECT(calls >= 1, "the progress callback was not called");
    }
    CASE(function, "progress NULL (allowed)") { generate_accepts(NULL); }
    CASE(function, "user NULL (allowed: passed back as it is)") {
        g_user_seen = &calls;
        EXPECT_OK(generate_call(A.world, A.navmesh, NULL, note_user, NULL, NULL));
        EXPECT(g_user_seen == NULL, "the progress callback received user %p, not NULL", g_user_seen);
        fixture_refresh();
    }
    CASE(function, "out_report NULL (allowed)") { generate_accepts(NULL); }
    out_sizes(function, "out_report", sizeof(nl_link_generation_report), generate_into);
}
static void generation_cases(const char* function) { generation_cases_of(function, "navmesh"); }

static const def_case k_generation_settings[] = {
    {"settings->drop_angle_count huge",
     INVALID,
     "drop_angle_count",
     {SET_U32(nl_link_settings, drop_angle_count, UINT32_MAX)}},
    {"settings->drop_angle_count 0 (allowed: no drop probes)",
     ALLOWED,
     NULL,
     {SET_U32(nl_link_settings, drop_angle_count, 0u)}},
    {"settings->min_group_size 0", INVALID, "min_group_size", {SET_U32(nl_link_settings, min_group_size, 0u)}},
    {"settings->max_group_size huge",
     INVALID,
     "max_group_size",
     {SET_U32(nl_link_settings, max_group_size, UINT32_MAX)}},
    {"settings->arc_segments 0", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, 0u)}},
    {"settings->arc_segments 1", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, 1u)}},
    {"settings->arc_segments huge", INVALID, "arc_segments", {SET_U32(nl_link_settings, arc_segments, UINT32_MAX)}},
    {"settings->sample_spacing tiny (1e-6: far too many samples)",
     INVALID,
     "sample_spacing",
     {SET_F32(nl_link_settings, sample_spacing, 1.0e-6f)}},
    {"settings->plugin_settings_json NULL (allowed: none)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_link_settings, plugin_settings_json, NULL)}},
    {"settings->plugin_settings_json not an object",
     INVALID,
     "plugin_settings_json",
     {SET_PTR(nl_link_settings, plugin_settings_json, "[1]"),
      SET_LENGTH(nl_link_settings, plugin_settings_json_length, 3)}},
    {"settings->plugin_settings_json malformed",
     NL_STATUS_PARSE_ERROR,
     "plugin_settings_json",
     {SET_PTR(nl_link_settings, plugin_settings_json, "{\"climb\": "),
      SET_LENGTH(nl_link_settings, plugin_settings_json_length, 10)}},
    {"settings->plugin_settings_json_length 0 (allowed: none)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_link_settings, plugin_settings_json, "{}"),
      SET_LENGTH(nl_link_settings, plugin_settings_json_length, 0)}},
    {"settings->plugin_settings_json_length huge (plugin_settings_json NULL: not read)",
     INVALID,
     "plugin_settings_json",
     {SET_LENGTH(nl_link_settings, plugin_settings_json_length, SIZE_MAX)}},
};

static void group_navmesh_generate_links(void) {
    const nl_link_settings valid = nl_default_link_settings();
    g_update = 0;
    generation_cases("nl_navmesh_generate_links");
    CASE("nl_navmesh_generate_links", "settings NULL (allowed: defaults)") { generate_accepts(NULL); }
    def_sizes("nl_navmesh_generate_links", "settings", &valid, sizeof valid, generate_refuses, generate_accepts);
    def_cases("nl_navmesh_generate_links", &valid, sizeof valid, k_generation_settings,
              sizeof k_generation_settings / sizeof *k_generation_settings, generate_refuses, generate_accepts);
    bad_float_fields("nl_navmesh_generate_links", "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, generate_refuses);
}

/* nl_navmesh_generate_cross_links with A's navmesh first and `id` second. */
static nl_status cross_second_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_generate_cross_links(w, A.navmesh, AS(nl_navmesh_id, id), g_tolerance, NULL, NULL, NULL,
                                           (nl_link_generation_report*)out);
}

static void group_navmesh_generate_cross_links(void) {
    static const char* const function = "nl_navmesh_generate_cross_links";
    const id_function second = {function, "second", "out_report",      sizeof(nl_link_generation_report),
                                1,        0,        cross_second_call, 1};
    const nl_link_settings valid = nl_default_link_settings();
    size_t v;
    g_update = 0;
    g_cross = 1;
    generation_cases_of(function, "first");
    id_cases(&second, RAW(A.host_navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "settings NULL (allowed: defaults)") { generate_accepts(NULL); }
    def_sizes(function, "settings", &valid, sizeof valid, generate_refuses, generate_accepts);
    def_cases(function, &valid, sizeof valid, k_generation_settings,
              sizeof k_generation_settings / sizeof *k_generation_settings, generate_refuses, generate_accepts);
    bad_float_fields(function, "settings", &valid, sizeof valid, k_link_settings_floats,
                     sizeof k_link_settings_floats / sizeof *k_link_settings_floats, generate_refuses);
    for (v = 0; v < sizeof k_bad_floats / sizeof *k_bad_floats; ++v) {
        CASE(function, "tolerance %s", k_bad_floats[v].name) {
            g_tolerance = k_bad_floats[v].value;
            generate_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "tolerance");
            g_tolerance = 0.25f;
        }
    }
    CASE(function, "tolerance negative") {
        g_tolerance = -1.0f;
        generate_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "tolerance");
        g_tolerance = 0.25f;
    }
    CASE(function, "second the same as first") {
        nl_link_generation_report report;
        fill(&report, sizeof report);
        report.size = sizeof report;
        EXPECT_FAILURE(A.world,
                       nl_navmesh_generate_cross_links(A.world, A.navmesh, A.navmesh, 0.25f, NULL, NULL, NULL, &report),
                       NL_STATUS_INVALID_ARGUMENT, "one");
        EXPECT_UNTOUCHED_AFTER_SIZE(&report, sizeof report, "out_report");
    }
    g_cross = 0;
}

static void group_navmesh_update_links_in_box(void) {
    size_t v;
    int k, end;
    g_update = 1;
    generation_cases("nl_navmesh_update_links_in_box");
    CASE("nl_navmesh_update_links_in_box", "navmesh never generated") {
        generate_fails_with(A.host_navmesh, NULL, NULL, NULL, NL_STATUS_NOT_FOUND, "generat");
    }
    for (end = 0; end < 2; ++end) {
        CASE("nl_navmesh_update_links_in_box", "%s NULL", end ? "box_max" : "box_min") {
            g_box_min = end ? k_box_min : NULL;
            g_box_max = end ? NULL : k_box_max;
            generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, end ? "box_max" : "box_min");
        }
        for (k = 0; k < 3; ++k) {
            for (v = 0; v < BAD_FLOAT_COUNT; ++v) {
                CASE("nl_navmesh_update_links_in_box", "%s[%d] %s", end ? "box_max" : "box_min", k,
                     k_bad_floats[v].name) {
                    float lo[3], hi[3];
                    memcpy(lo, k_box_min, sizeof lo);
                    memcpy(hi, k_box_max, sizeof hi);
                    (end ? hi : lo)[k] = k_bad_floats[v].value;
                    g_box_min = lo;
                    g_box_max = hi;
                    generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "box");
                }
            }
        }
    }
    CASE("nl_navmesh_update_links_in_box", "box_min inverted (above box_max)") {
        g_box_min = k_box_max;
        g_box_max = k_box_min;
        generate_fails_with(A.navmesh, NULL, NULL, NULL, NL_STATUS_INVALID_ARGUMENT, "box");
    }
    g_box_min = k_box_min;
    g_box_max = k_box_max;
}

/* The JSON of A's navmesh's links, malloc'ed. */
static char* saved_links(size_t* length) {
    char* json;
    if (NL_FAILED(nl_navmesh_save_links_json(A.world, A.navmesh, NULL, 0, length))) fixture_failed("save_links_json");
    json = (char*)malloc(*length + 1);
    if (!json || NL_FAILED(nl_navmesh_save_links_json(A.world, A.navmesh, json, *length + 1, length)))
        fixture_failed("save_links_json");
    return json;
}

static nl_status save_links_json_saver(const nl_world* w, nl_navmesh_id n, void* buffer, size_t capacity,
                                       size_t* out_length) {
    return nl_navmesh_save_links_json(w, n, (char*)buffer, capacity, out_length);
}

static void group_navmesh_save_links_json(void) {
    size_t needed = 0;
    char* json = saved_links(&needed);
    saver_cases("nl_navmesh_save_links_json", "out_length", save_links_json_saver, (const unsigned char*)json, needed,
                1);
    free(json);
}

/* A saved file with the elements of the first array `key` holds (links[0]'s) replaced by `elements`. */
static char* edited_links(const char* json, const char* key, const char* elements) {
    char pattern[64];
    const char *open, *close;
    char* out;
    snprintf(pattern, sizeof pattern, "\"%s\": [", key);
    open = strstr(json, pattern);
    close = open ? strchr(open, ']') : NULL;
    if (!close) fixture_failed("the saved links lack the array to edit");
    open += strlen(pattern);
    out = (char*)malloc(strlen(json) + strlen(elements) + 1);
    if (!out) exit(2);
    memcpy(out, json, (size_t)(open - json));
    strcpy(out + (open - json), elements);
    strcat(out, close);
    return out;
}

static const char* g_load_json;
static size_t g_load_length;
static nl_status load_id_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_load_links_json(w, AS(nl_navmesh_id, id), g_load_json, g_load_length, 0, (uint32_t*)out);
}

static void load_fails_with(const char* json, size_t length, nl_status detail, const char* needle) {
    uint32_t count;
    fill(&count, sizeof count);
    EXPECT_FAILURE(A.world, nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, &count), detail, needle);
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
}

static void group_navmesh_load_links_json(void) {
    static const id_function f = {
        "nl_navmesh_load_links_json", "navmesh", "out_count", sizeof(uint32_t), 0, 0, load_id_call, 1};
    static const char* values[][2] = {{"1e400", "inf"}, {"-1e400", "-inf"}, {"null", "null"}, {"\"x\"", "a string"}};
    size_t length, i;
    char* json = saved_links(&length);
    const text_case texts[] = {
        {"json NULL (length 10)", NULL, 10, NL_STATUS_INVALID_ARGUMENT, "json"},
        {"length huge (json NULL: not read)", NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "json"},
        {"length 0 (not JSON)", json, 0, NL_STATUS_PARSE_ERROR, ""},
        {"length short (cut in the middle)", json, length / 2, NL_STATUS_PARSE_ERROR, ""},
    };
    g_load_json = json;
    g_load_length = length;
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    for (i = 0; i < sizeof texts / sizeof *texts; ++i) {
        CASE("nl_navmesh_load_links_json", "%s", texts[i].what) {
            load_fails_with(texts[i].data, texts[i].length, texts[i].detail, texts[i].needle);
        }
    }
    CASE("nl_navmesh_load_links_json", "json another format") {
        char* other = (char*)malloc(length + 1);
        const char* at = strstr(json, "navlink-links");
        if (!at || !other) fixture_failed("the saved links have no format");
        memcpy(other, json, length + 1);
        memcpy(other + (at - json), "navlink-other", 13);
        load_fails_with(other, length, NL_STATUS_VERSION_MISMATCH, "");
        free(other);
    }
    for (i = 0; i < sizeof values / sizeof *values; ++i) {
        CASE("nl_navmesh_load_links_json", "json links[0].start %s", values[i][1]) {
            char elements[64], *bad;
            snprintf(elements, sizeof elements, "%s, 0, 3", values[i][0]);
            bad = edited_links(json, "start", elements);
            load_fails_with(bad, strlen(bad), NL_STATUS_INVALID_ARGUMENT, "links[0].start");
            free(bad);
        }
    }
    CASE("nl_navmesh_load_links_json", "json links[0].end off the navmesh (20 m up)") {
        char* bad = edited_links(json, "end", "-6, 20, 0");
        load_fails_with(bad, strlen(bad), NL_STATUS_INVALID_ARGUMENT, "links[0].end");
        free(bad);
    }
    CASE("nl_navmesh_load_links_json", "json not NUL-terminated (allowed: exactly length bytes read)") {
        char* exact = (char*)malloc(length);
        uint32_t count = 0;
        if (!exact) exit(2);
        memcpy(exact, json, length);
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, exact, length, 0, &count));
        EXPECT(count == link_count(A.navmesh), "out_count = %u", (unsigned)count);
        free(exact);
        fixture_refresh(); /* new ids */
    }
    CASE("nl_navmesh_load_links_json", "flags 0 (allowed: the file's body is the navmesh's)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, &count));
        fixture_refresh();
    }
    CASE("nl_navmesh_load_links_json", "flags NL_LINKS_LOAD_ANY_BODY (allowed)") {
        uint32_t count = 0;
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, NL_LINKS_LOAD_ANY_BODY, &count));
        fixture_refresh();
    }
    CASE("nl_navmesh_load_links_json", "flags huge (unknown bits)") {
        uint32_t count;
        fill(&count, sizeof count);
        EXPECT_FAILURE(A.world, nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0xffffffffu, &count),
                       NL_STATUS_INVALID_ARGUMENT, "flags");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_navmesh_load_links_json", "json made for another body (radius 0.25)") {
        const char* at = strstr(json, "\"radius\"");
        char* other = (char*)malloc(length + 16);
        if (!at || !other) fixture_failed("the saved links do not say their body");
        snprintf(other, length + 16, "%.*s\"radius\": 0.25, \"was\": %s", (int)(at - json), json, at + 9);
        load_fails_with(other, strlen(other), NL_STATUS_INVALID_ARGUMENT, "radius 0.25");
        free(other);
    }
    CASE("nl_navmesh_load_links_json", "out_count NULL (allowed)") {
        EXPECT_OK(nl_navmesh_load_links_json(A.world, A.navmesh, json, length, 0, NULL));
        fixture_refresh();
    }
    free(json);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"link_add", group_link_add},
    {"link_update", group_link_update},
    {"link_remove", group_link_remove},
    {"link_is_valid", group_link_is_valid},
    {"link_get", group_link_get},
    {"navmesh_get_links", group_navmesh_get_links},
    {"navmesh_remove_generated_links", group_navmesh_remove_generated_links},
    {"link_settings_from_json", group_link_settings_from_json},
    {"navmesh_generate_links", group_navmesh_generate_links},
    {"navmesh_generate_cross_links", group_navmesh_generate_cross_links},
    {"navmesh_update_links_in_box", group_navmesh_update_links_in_box},
    {"navmesh_save_links_json", group_navmesh_save_links_json},
    {"navmesh_load_links_json", group_navmesh_load_links_json},
};
const hostile_part hostile_links_part = {k_groups, sizeof k_groups / sizeof *k_groups};
