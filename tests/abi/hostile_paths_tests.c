/*
 * The hostile cases of navlink/paths.h: paths found, explained and requested, the tickets, the
 * queue's budget, finished requests and stats.
 */
#include "hostile_fixtures.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const float_field k_request_floats[] = {
    FLOAT_FIELD(nl_path_request_def, start, 3),
    FLOAT_FIELD(nl_path_request_def, goal, 3),
    FLOAT_FIELD(nl_path_request_def, search_half_extents, 3),
    FLOAT_FIELD(nl_path_request_def, capabilities.max_jump_distance, 1),
    FLOAT_FIELD(nl_path_request_def, capabilities.max_jump_height, 1),
    FLOAT_FIELD(nl_path_request_def, capabilities.max_drop_height, 1),
    FLOAT_FIELD(nl_path_request_def, capabilities.radius, 1),
    FLOAT_FIELD(nl_path_request_def, link_cost, 1),
};

static const def_case k_request_defs[] = {
    {"def->start beyond the limit (2e9)", INVALID, "start", {SET_F32(nl_path_request_def, start[0], 2.0e9f)}},
    {"def->search_half_extents 0",
     INVALID,
     "search_half_extents",
     {SET_F32(nl_path_request_def, search_half_extents[1], 0.0f)}},
    {"def->search_half_extents negative",
     INVALID,
     "search_half_extents",
     {SET_F32(nl_path_request_def, search_half_extents[1], -1.0f)}},
    {"def->capabilities.radius negative",
     INVALID,
     "radius",
     {SET_F32(nl_path_request_def, capabilities.radius, -1.0f)}},
    {"def->link_cost negative", INVALID, "link_cost", {SET_F32(nl_path_request_def, link_cost, -1.0f)}},
    {"def->area_costs NULL (area_cost_count 3)",
     INVALID,
     "area_costs",
     {SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_cost_count huge (area_costs NULL: not read)",
     INVALID,
     "area_cost_count",
     {SET_U32(nl_path_request_def, area_cost_count, UINT32_MAX)}},
    {"def->area_cost_count 257",
     INVALID,
     "area_cost_count",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_257), SET_U32(nl_path_request_def, area_cost_count, 257u)}},
    {"def->area_costs NaN ([1])",
     INVALID,
     "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_nan), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs inf ([1])",
     INVALID,
     "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_inf), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs -inf ([1])",
     INVALID,
     "area_costs[1]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_minus_inf), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs negative ([2])",
     INVALID,
     "area_costs[2]",
     {SET_PTR(nl_path_request_def, area_costs, k_costs_negative), SET_U32(nl_path_request_def, area_cost_count, 3u)}},
    {"def->area_costs NULL (allowed with area_cost_count 0)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_path_request_def, area_costs, NULL)}},
    {"def->area_cost_count 0 (allowed: area_costs not read)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_path_request_def, area_costs, "not floats"), SET_U32(nl_path_request_def, area_cost_count, 0u)}},
    {"def->callback NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_path_request_def, callback, NULL)}},
    {"def->user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_path_request_def, user, NULL)}},
};

static int g_callbacks; /* callbacks of requests made by the cases */
static void count_callback(void* user, nl_path_ticket ticket, nl_path_outcome outcome) {
    (void)user;
    (void)ticket;
    (void)outcome;
    ++g_callbacks;
}

/* nl_path_find, nl_path_request (g_queued) or nl_path_explain (g_explained) with a def: refused with
   nothing written, no ticket made (the queue's counters, compared after each case, say so) and no
   callback run. */
static int g_queued, g_explained;
static void request_refuses(const void* def, nl_status detail, const char* needle) {
    nl_path_result result;
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_path_ticket ticket;
    nl_path_shortfall shortfall;
    const int callbacks = g_callbacks;
    fill(&result, sizeof result);
    result.size = sizeof result;
    fill(points, sizeof points);
    fill(&count, sizeof count);
    fill(&ticket, sizeof ticket);
    fill(&shortfall, sizeof shortfall);
    shortfall.size = sizeof shortfall;
    if (g_explained) {
        EXPECT_FAILURE(A.world, nl_path_explain(A.world, (const nl_path_request_def*)def, &shortfall), detail, needle);
        EXPECT_UNTOUCHED_AFTER_SIZE(&shortfall, sizeof shortfall, "out_shortfall");
    } else if (g_queued) {
        EXPECT_FAILURE(A.world, nl_path_request(A.world, (const nl_path_request_def*)def, &ticket), detail, needle);
        EXPECT_UNTOUCHED(&ticket, sizeof ticket, "out_ticket");
        EXPECT(g_callbacks == callbacks, "the callback of a refused request ran");
    } else {
        EXPECT_FAILURE(A.world, nl_path_find(A.world, (const nl_path_request_def*)def, &result, points, 64, &count),
                       detail, needle);
        EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
        EXPECT_UNTOUCHED(points, sizeof points, "out_points");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
}

/* A def accepted: it plans as the valid one does (a queued one is released again). */
static void request_accepts(const void* def) {
    if (g_explained) {
        nl_path_shortfall shortfall = nl_path_shortfall_init();
        EXPECT_OK(nl_path_explain(A.world, (const nl_path_request_def*)def, &shortfall));
        EXPECT(shortfall.reason == NL_PATH_SHORTFALL_NONE && shortfall.text[0] == '\0', "reason %u: %s",
               (unsigned)shortfall.reason, shortfall.text);
    } else if (g_queued) {
        nl_path_ticket ticket = {0u, 0u};
        EXPECT_OK(nl_path_request(A.world, (const nl_path_request_def*)def, &ticket));
        EXPECT_OK(nl_path_release(A.world, ticket));
        fixture_refresh();
    } else {
        nl_path_result result;
        nl_path_point points[64];
        points[0] = nl_path_point_init();
        uint32_t count = 0;
        memset(&result, 0, sizeof result);
        result.size = sizeof result;
        EXPECT_OK(nl_path_find(A.world, (const nl_path_request_def*)def, &result, points, 64, &count));
        EXPECT(result.outcome == NL_PATH_COMPLETE, "outcome %u", (unsigned)result.outcome);
    }
}

static const nl_path_request_def* g_request;
static nl_status request_id_call(nl_world* w, raw_id id, void* out) {
    nl_path_request_def def = *g_request;
    nl_path_point points[4];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_status status;
    def.navmesh = AS(nl_navmesh_id, id);
    if (g_explained) return nl_path_explain(w, &def, (nl_path_shortfall*)out);
    if (g_queued) return nl_path_request(w, &def, (nl_path_ticket*)out);
    fill(points, sizeof points);
    points[0].size = sizeof points[0];
    fill(&count, sizeof count);
    status = nl_path_find(w, &def, (nl_path_result*)out, points, 4, &count);
    EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}

/* Everything about the def, shared by nl_path_find and nl_path_request. */
static void request_def_cases(const char* function) {
    nl_path_request_def valid = gap_request(A.navmesh);
    const id_function find = {function, "def->navmesh", "out_result", sizeof(nl_path_result), 1, 0, request_id_call, 1};
    const id_function request = {function, "def->navmesh", "out_ticket", sizeof(nl_path_ticket), 0, 0, request_id_call,
                                 1};
    const id_function explain = {
        function, "def->navmesh", "out_shortfall", sizeof(nl_path_shortfall), 1, 0, request_id_call, 1};
    valid.callback = count_callback;
    g_request = &valid;
    id_cases(g_explained ? &explain
             : g_queued  ? &request
                         : &find,
             RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE(function, "def NULL") { request_refuses(NULL, NL_STATUS_INVALID_ARGUMENT, "def"); }
    def_sizes(function, "def", &valid, sizeof valid, request_refuses, request_accepts);
    def_cases(function, &valid, sizeof valid, k_request_defs, sizeof k_request_defs / sizeof *k_request_defs,
              request_refuses, request_accepts);
    bad_float_fields(function, "def", &valid, sizeof valid, k_request_floats,
                     sizeof k_request_floats / sizeof *k_request_floats, request_refuses);
}

/* The result and points of nl_path_find and nl_path_get_result: `call` runs one of them with the
   outputs given. */
typedef nl_status result_call_fn(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count);
typedef struct result_case {
    const char* what;
    int result, points, count; /* which outputs are given */
    uint32_t capacity;         /* UINT32_MAX - 1: one less than the points */
    nl_status detail;          /* 0: a success */
    const char* needle;
} result_case;

static void result_cases(const char* function, result_call_fn* call) {
    static const result_case cases[] = {
        {"out_result NULL", 0, 1, 1, 64, NL_STATUS_INVALID_ARGUMENT, "out_result"},
        {"out_count NULL", 1, 1, 0, 64, NL_STATUS_INVALID_ARGUMENT, "out_count"},
        {"out_points NULL (allowed with capacity 0: counts)", 1, 0, 1, 0, 0u, NULL},
        {"capacity huge (out_points NULL)", 1, 0, 1, UINT32_MAX, NL_STATUS_INVALID_ARGUMENT, "out_points"},
        {"capacity 0 (points given: the result is written, the points are not)", 1, 1, 1, 0, NL_STATUS_BUFFER_TOO_SMALL,
         "capacity"},
        {"capacity small (one less than the points)", 1, 1, 1, UINT32_MAX - 1, NL_STATUS_BUFFER_TOO_SMALL, "capacity"},
        {"capacity huge (room for 68: only the points written)", 1, 1, 1, UINT32_MAX, 0u, NULL},
    };
    nl_path_result expected;
    uint32_t needed = 0;
    size_t i;
    memset(&expected, 0, sizeof expected);
    expected.size = sizeof expected;
    if (NL_FAILED(call(&expected, NULL, 0, &needed)) || needed < 2 || needed >= 68)
        fixture_failed("the known path's points");
    for (i = 0; i < sizeof cases / sizeof *cases; ++i) {
        const result_case* c = &cases[i];
        CASE(function, "%s", c->what) {
            nl_path_result result;
            nl_path_point points[68];
            points[0] = nl_path_point_init();
            uint32_t count;
            const uint32_t capacity = c->capacity == UINT32_MAX - 1 ? needed - 1 : c->capacity;
            nl_status status;
            fill(&result, sizeof result);
            result.size = sizeof result;
            fill(points, sizeof points);
            points[0].size = sizeof points[0];
            fill(&count, sizeof count);
            status = call(c->result ? &result : NULL, c->points ? points : NULL, capacity, c->count ? &count : NULL);
            if (c->detail == 0u || c->detail == NL_STATUS_BUFFER_TOO_SMALL) {
                /* The result and the count are written; the points only when they fit. */
                if (c->detail == 0u)
                    EXPECT_OK(status);
                else
                    EXPECT_FAILURE(A.world, status, c->detail, c->needle);
                EXPECT(count == needed && memcmp(&result, &expected, sizeof result) == 0, "count %u, or another result",
                       (unsigned)count);
                if (c->detail == 0u)
                    EXPECT_UNTOUCHED(points + needed, (68 - needed) * sizeof *points, "the points past out_count");
                else
                    EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
            } else {
                EXPECT_FAILURE(A.world, status, c->detail, c->needle);
                EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
                EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
                EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
            }
        }
    }
}

static nl_status find_known(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count) {
    const nl_path_request_def def = gap_request(A.navmesh);
    return nl_path_find(A.world, &def, result, points, capacity, count);
}
static nl_status find_into(void* result) {
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count = 0;
    return find_known((nl_path_result*)result, points, 64, &count);
}

static nl_status find_points(void* out, uint32_t* written) {
    nl_path_result result = nl_path_result_init();
    return find_known(&result, (nl_path_point*)out, 256u, written);
}

static void group_path_find(void) {
    g_queued = 0;
    request_def_cases("nl_path_find");
    result_cases("nl_path_find", find_known);
    out_sizes("nl_path_find", "out_result", sizeof(nl_path_result), find_into);
    out_element_sizes("nl_path_find", "out_points", sizeof(nl_path_point), find_points);
}

static nl_status explain_into(void* shortfall) {
    const nl_path_request_def def = gap_request(A.navmesh);
    return nl_path_explain(A.world, &def, (nl_path_shortfall*)shortfall);
}

static void group_path_explain(void) {
    g_queued = 0;
    g_explained = 1;
    CASE("nl_path_explain", "out_shortfall NULL") {
        const nl_path_request_def def = gap_request(A.navmesh);
        EXPECT_INVALID(A.world, nl_path_explain(A.world, &def, NULL), "out_shortfall");
    }
    request_def_cases("nl_path_explain");
    out_sizes("nl_path_explain", "out_shortfall", sizeof(nl_path_shortfall), explain_into);
    g_explained = 0;
}

static void group_path_request(void) {
    const nl_path_request_def valid = gap_request(A.navmesh);
    g_queued = 1;
    CASE("nl_path_request", "out_ticket NULL") {
        nl_path_request_def def = valid;
        const int callbacks = g_callbacks;
        def.callback = count_callback;
        EXPECT_INVALID(A.world, nl_path_request(A.world, &def, NULL), "out_ticket");
        EXPECT(g_callbacks == callbacks, "the callback of a refused request ran");
    }
    request_def_cases("nl_path_request");
    CASE("nl_path_request", "def->callback set, released before it ran (its callback runs once)") {
        nl_path_request_def def = valid;
        nl_path_ticket ticket;
        const int callbacks = g_callbacks;
        def.callback = count_callback;
        EXPECT_OK(nl_path_request(A.world, &def, &ticket));
        EXPECT_OK(nl_path_release(A.world, ticket));
        EXPECT(g_callbacks == callbacks + 1, "the callback ran %d times, expected once", g_callbacks - callbacks);
        fixture_refresh();
    }
}

/* The functions that take a ticket. */
ID_OUT_CALL(poll_call, nl_path_ticket, nl_path_outcome, nl_path_poll)
ID_CALL(cancel_call, nl_path_ticket, nl_path_cancel)
/* Waits forever: a bad ticket must fail at once, not hang. */
static nl_status wait_call(nl_world* w, raw_id id, void* out) {
    return nl_path_wait(w, AS(nl_path_ticket, id), NL_PATH_WAIT_FOREVER, (nl_path_outcome*)out);
}
ID_CALL(release_call, nl_path_ticket, nl_path_release)
/* The result of a ticket, with its points and count untouched too. */
static nl_status get_result_call(nl_world* w, raw_id id, void* out) {
    nl_path_point points[4];
    points[0] = nl_path_point_init();
    uint32_t count;
    nl_status status;
    fill(points, sizeof points);
    points[0].size = sizeof points[0];
    fill(&count, sizeof count);
    status = nl_path_get_result(w, AS(nl_path_ticket, id), (nl_path_result*)out, points, 4, &count);
    EXPECT_UNTOUCHED_AFTER_SIZE(points, sizeof points, "out_points");
    EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    return status;
}
static const id_function k_ticket_functions[] = {
    {"nl_path_poll", "ticket", "out_outcome", sizeof(nl_path_outcome), 0, 0, poll_call, 0},
    {"nl_path_cancel", "ticket", NULL, 0, 0, 0, cancel_call, 0},
    {"nl_path_release", "ticket", NULL, 0, 0, 0, release_call, 0},
    {"nl_path_get_result", "ticket", "out_result", sizeof(nl_path_result), 1, 0, get_result_call, 1},
    {"nl_path_wait", "ticket", "out_outcome", sizeof(nl_path_outcome), 0, 0, wait_call, 0},
};

static void ticket_id_cases(size_t which) {
    id_cases(&k_ticket_functions[which], RAW(A.pending_ticket), RAW(A.stale_ticket), RAW(B.pending_ticket));
}

static void group_path_poll(void) { ticket_id_cases(0); }
static void group_path_cancel(void) { ticket_id_cases(1); }
static void group_path_release(void) { ticket_id_cases(2); }
static void group_path_wait(void) {
    ticket_id_cases(4);
    CASE("nl_path_wait", "timeout_ms 0 on a pending ticket (looks only: IN_PROGRESS, nothing planned)") {
        nl_path_outcome outcome = 99;
        EXPECT(nl_path_wait(A.world, A.pending_ticket, 0, &outcome) == NL_STATUS_IN_PROGRESS, "expected IN_PROGRESS");
        EXPECT(outcome == NL_PATH_PENDING, "outcome %u, expected NL_PATH_PENDING", outcome);
    }
    CASE("nl_path_wait", "timeout_ms huge (NL_PATH_WAIT_FOREVER - 1) on a finished ticket (answers at once)") {
        nl_path_outcome outcome = 99;
        EXPECT_OK(nl_path_wait(A.world, A.done_ticket, NL_PATH_WAIT_FOREVER - 1u, &outcome));
        EXPECT(outcome == NL_PATH_COMPLETE, "outcome %u, expected NL_PATH_COMPLETE", outcome);
    }
    CASE("nl_path_wait",
         "timeout_ms huge (NL_PATH_WAIT_FOREVER - 1) on a pending ticket (no workers: this thread plans it)") {
        nl_path_outcome outcome = 99;
        EXPECT_OK(nl_path_wait(A.world, A.pending_ticket, NL_PATH_WAIT_FOREVER - 1u, &outcome));
        EXPECT(outcome != NL_PATH_PENDING, "still pending after the wait");
        fixture_refresh();
    }
}

static nl_status result_of_done(nl_path_result* result, nl_path_point* points, uint32_t capacity, uint32_t* count) {
    return nl_path_get_result(A.world, A.done_ticket, result, points, capacity, count);
}
static nl_status result_into(void* result) {
    nl_path_point points[64];
    points[0] = nl_path_point_init();
    uint32_t count = 0;
    return result_of_done((nl_path_result*)result, points, 64, &count);
}

static nl_status result_points(void* out, uint32_t* written) {
    nl_path_result result = nl_path_result_init();
    return result_of_done(&result, (nl_path_point*)out, 256u, written);
}

static void group_path_get_result(void) {
    ticket_id_cases(3);
    CASE("nl_path_get_result", "ticket pending (IN_PROGRESS: nothing written)") {
        nl_path_result result;
        fill(&result, sizeof result);
        result.size = sizeof result;
        EXPECT_STATUS(get_result_call(A.world, RAW(A.pending_ticket), &result), NL_STATUS_IN_PROGRESS);
        EXPECT_UNTOUCHED_AFTER_SIZE(&result, sizeof result, "out_result");
    }
    result_cases("nl_path_get_result", result_of_done);
    out_sizes("nl_path_get_result", "out_result", sizeof(nl_path_result), result_into);
    out_element_sizes("nl_path_get_result", "out_points", sizeof(nl_path_point), result_points);
}

/* nl_path_process with `out_processed` given: what it must return and how many it must plan. */
typedef struct process_case {
    const char* what;
    uint32_t max_requests;
    double max_milliseconds;
    int with_out;
    nl_status detail; /* 0: a success */
    uint32_t processed;
} process_case;

static void group_path_process(void) {
    const process_case cases[] = {
        {"budget->max_milliseconds NaN (nothing planned)", 0, (double)NAN, 1, NL_STATUS_INVALID_ARGUMENT, 0},
        {"budget->max_milliseconds -inf (allowed: no limit)", 1, -(double)INFINITY, 1, 0u, 1},
        {"budget->max_milliseconds inf (allowed: no limit)", 0, (double)INFINITY, 1, 0u, 0},
        {"budget->max_requests 0 (allowed: no limit)", 0, 0.0, 1, 0u, 0},
        {"budget->max_requests huge (allowed)", UINT32_MAX, 0.0, 1, 0u, 0},
        {"out_processed NULL (allowed)", 0, 0.0, 0, 0u, 0},
    };
    size_t i;
    CASE("nl_path_process", "world NULL") {
        uint32_t processed;
        fill(&processed, sizeof processed);
        EXPECT_INVALID(NULL, nl_path_process(NULL, NL_TEST_BUDGET(0, 0.0), &processed), "world");
        EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
    }
    for (i = 0; i < sizeof cases / sizeof *cases; ++i) {
        CASE("nl_path_process", "%s", cases[i].what) {
            uint32_t processed;
            nl_status status;
            fill(&processed, sizeof processed);
            status = nl_path_process(A.world, NL_TEST_BUDGET(cases[i].max_requests, cases[i].max_milliseconds),
                                     cases[i].with_out ? &processed : NULL);
            if (cases[i].detail) {
                EXPECT_INVALID(A.world, status, "max_milliseconds");
                EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
            } else {
                EXPECT_OK(status);
                if (cases[i].with_out)
                    EXPECT(processed == cases[i].processed,
                           "planned %u requests, expected %u (the pending one, then none)", (unsigned)processed,
                           (unsigned)cases[i].processed);
                fixture_refresh(); /* the pending request finished */
            }
        }
    }
    {
        /* A request to plan, queued before each case that plans one (the fixture's pending one is
           planned by the cases above). */
        const nl_path_request_def def = gap_request(A.navmesh);
        nl_path_ticket queued;
        static const uint32_t bad[3] = {0u, 4u, (uint32_t)sizeof(nl_path_budget) - 1u};
        static const char* what[3] = {"budget->size 0", "budget->size small (4)", "budget->size small (sizeof - 1)"};
        int k;
        if (NL_FAILED(nl_path_request(A.world, &def, &queued))) fixture_failed("a request to plan");
        fixture_refresh();
        for (k = 0; k < 3; ++k) {
            CASE("nl_path_process", "%s (nothing planned)", what[k]) {
                nl_path_budget budget = nl_default_path_budget();
                uint32_t processed;
                nl_path_outcome outcome = NL_PATH_COMPLETE;
                budget.size = bad[k];
                fill(&processed, sizeof processed);
                EXPECT_INVALID(A.world, nl_path_process(A.world, &budget, &processed), "budget->size");
                EXPECT_UNTOUCHED(&processed, sizeof processed, "out_processed");
                EXPECT(NL_SUCCEEDED(nl_path_poll(A.world, queued, &outcome)) && outcome == NL_PATH_PENDING,
                       "the queued request was planned");
            }
        }
        CASE("nl_path_process", "budget NULL (allowed: no limits)") {
            uint32_t processed;
            fill(&processed, sizeof processed);
            EXPECT_OK(nl_path_process(A.world, NULL, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected the queued one", (unsigned)processed);
            fixture_refresh();
        }
        nl_path_release(A.world, queued);
        if (NL_FAILED(nl_path_request(A.world, &def, &queued)) || NL_FAILED(nl_path_request(A.world, &def, &queued)))
            fixture_failed("requests to plan");
        fixture_refresh();
        CASE("nl_path_process", "budget->size large (sizeof + 64: the fields it knows are read)") {
            aligned_buffer buffer;
            nl_path_budget budget = nl_default_path_budget();
            uint32_t processed = 0;
            fill(buffer.bytes, sizeof buffer.bytes);
            budget.size = (uint32_t)sizeof budget + 64u;
            budget.max_requests = 1u;
            memcpy(buffer.bytes, &budget, sizeof budget);
            EXPECT_OK(nl_path_process(A.world, (const nl_path_budget*)buffer.bytes, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected 1 of 2 (max_requests read)", (unsigned)processed);
            fixture_refresh();
        }
        CASE("nl_path_process", "budget->max_search_nodes 1 (allowed: one request, the one crossing it)") {
            nl_path_budget budget = nl_default_path_budget();
            uint32_t processed = 0;
            budget.max_search_nodes = 1u;
            EXPECT_OK(nl_path_process(A.world, &budget, &processed));
            EXPECT(processed == 1u, "planned %u requests, expected 1", (unsigned)processed);
            fixture_refresh();
        }
    }
}

/* A request planned and finished, waiting to be taken; its ticket in *out. */
static void finish_one(nl_path_ticket* out) {
    const nl_path_request_def def = gap_request(A.navmesh);
    if (NL_FAILED(nl_path_request(A.world, &def, out)) || NL_FAILED(nl_path_process(A.world, NULL, NULL)))
        fixture_failed("a request to take");
}

static nl_status take_into(void* out, uint32_t* written) {
    return nl_path_take_finished(A.world, (nl_path_finished*)out, 256u, written, NULL);
}

static void group_path_take_finished(void) {
    nl_path_ticket ticket;
    uint32_t waiting = 0, taken;
    nl_path_finished drained[64];
    drained[0] = nl_path_finished_init();
    /* The fixture's finished requests taken first: then exactly one waits. */
    if (NL_FAILED(nl_path_take_finished(A.world, drained, 64, &taken, &waiting)) || waiting != 0u)
        fixture_failed("the fixture's finished requests");
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "world NULL") {
        nl_path_finished out[2];
        uint32_t count, remaining;
        fill(out, sizeof out);
        out[0].size = sizeof out[0];
        fill(&count, sizeof count);
        fill(&remaining, sizeof remaining);
        EXPECT_INVALID(NULL, nl_path_take_finished(NULL, out, 2, &count, &remaining), "world");
        EXPECT_UNTOUCHED_AFTER_SIZE(out, sizeof out, "out_finished");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_path_take_finished", "out_count NULL") {
        nl_path_finished out[2];
        fill(out, sizeof out);
        out[0].size = sizeof out[0];
        EXPECT_INVALID(A.world, nl_path_take_finished(A.world, out, 2, NULL, NULL), "out_count");
        EXPECT_UNTOUCHED_AFTER_SIZE(out, sizeof out, "out_finished");
    }
    CASE("nl_path_take_finished", "out_finished NULL with capacity 2") {
        uint32_t count;
        fill(&count, sizeof count);
        EXPECT_INVALID(A.world, nl_path_take_finished(A.world, NULL, 2, &count, NULL), "out_finished");
        EXPECT_UNTOUCHED(&count, sizeof count, "out_count");
    }
    CASE("nl_path_take_finished", "capacity 0 (allowed: takes nothing, says how many wait)") {
        uint32_t count = 77u, remaining = 0u, again = 0u;
        EXPECT_OK(nl_path_take_finished(A.world, NULL, 0, &count, &remaining));
        EXPECT_OK(nl_path_take_finished(A.world, NULL, 0, &count, &again));
        /* finish_one planned the fixture's pending request too: two wait, and stay. */
        EXPECT(count == 0u && remaining == 2u && again == 2u, "took %u, %u then %u waiting", (unsigned)count,
               (unsigned)remaining, (unsigned)again);
    }
    /* Each size refusal keeps the finished request: the size-large case takes it (then the world
       changed: refreshed). */
    /* The refusals below lose nothing: the finished request is still there for the size-large case. */
    out_element_sizes("nl_path_take_finished", "out_finished", sizeof(nl_path_finished), take_into);
    fixture_refresh();
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "capacity huge (allowed: takes what there is)") {
        nl_path_finished out[4];
        uint32_t count = 0u;
        out[0] = nl_path_finished_init();
        EXPECT_OK(nl_path_take_finished(A.world, out, UINT32_MAX, &count, NULL));
        EXPECT(count == 1u && out[0].ticket.index1 == ticket.index1 && out[0].outcome == NL_PATH_COMPLETE,
               "took %u requests", (unsigned)count);
        fixture_refresh();
    }
    finish_one(&ticket);
    fixture_refresh();
    CASE("nl_path_take_finished", "out_remaining NULL (allowed)") {
        nl_path_finished out[1];
        uint32_t count = 0u;
        out[0] = nl_path_finished_init();
        EXPECT_OK(nl_path_take_finished(A.world, out, 1, &count, NULL));
        EXPECT(count == 1u, "took %u requests", (unsigned)count);
        fixture_refresh();
    }
}

static nl_status stats_into(void* stats) { return nl_path_get_queue_stats(A.world, (nl_path_queue_stats*)stats); }
static void group_path_get_queue_stats(void) {
    CASE("nl_path_get_queue_stats", "world NULL") {
        nl_path_queue_stats stats;
        fill(&stats, sizeof stats);
        stats.size = sizeof stats;
        EXPECT_INVALID(NULL, nl_path_get_queue_stats(NULL, &stats), "world");
        EXPECT_UNTOUCHED_AFTER_SIZE(&stats, sizeof stats, "out_stats");
    }
    CASE("nl_path_get_queue_stats", "out_stats NULL") {
        EXPECT_INVALID(A.world, nl_path_get_queue_stats(A.world, NULL), "out_stats");
    }
    out_sizes("nl_path_get_queue_stats", "out_stats", sizeof(nl_path_queue_stats), stats_into);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"path_find", group_path_find},
    {"path_explain", group_path_explain},
    {"path_request", group_path_request},
    {"path_poll", group_path_poll},
    {"path_get_result", group_path_get_result},
    {"path_cancel", group_path_cancel},
    {"path_release", group_path_release},
    {"path_wait", group_path_wait},
    {"path_process", group_path_process},
    {"path_take_finished", group_path_take_finished},
    {"path_get_queue_stats", group_path_get_queue_stats},
};
const hostile_part hostile_paths_part = {k_groups, sizeof k_groups / sizeof *k_groups};
