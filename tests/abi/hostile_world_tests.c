/*
 * The hostile cases of navlink/world.h: a world created and destroyed, its worker count.
 */
/* Built with a sanitizer (GCC says so with __SANITIZE_*__, clang with __has_feature). */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define NAVLINK_HOSTILE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define NAVLINK_HOSTILE_SANITIZED 1
#endif
#endif

/* getrlimit(), setrlimit(); strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile_fixtures.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>

static nl_status world_create_call(nl_world* world, const void* def, void* out) {
    (void)world;
    return nl_world_create((const nl_world_def*)def, (nl_world**)out);
}

/* A world created as documented: it works, and is destroyed. */
static void world_destroy_out(const void* out) {
    nl_world* world;
    memcpy(&world, out, sizeof world);
    EXPECT(world != NULL && nl_world_get_worker_count(world) >= 1, "no working world was returned");
    nl_world_destroy(world);
}

static const def_case k_world_defs[] = {
    {"def->worker_count -2", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, -2)}},
    {"def->worker_count INT32_MIN", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, INT32_MIN)}},
    {"def->worker_count huge (INT32_MAX)", INVALID, "worker_count", {SET_I32(nl_world_def, worker_count, INT32_MAX)}},
    {"def->worker_count huge (NL_MAX_WORKERS + 1)",
     INVALID,
     "NL_MAX_WORKERS",
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS + 1)}},
    {"def->worker_count 0 (allowed: the calling thread only)", ALLOWED, NULL, {SET_I32(nl_world_def, worker_count, 0)}},
    {"def->path_worker_count -2", INVALID, "path_worker_count", {SET_I32(nl_world_def, path_worker_count, -2)}},
    {"def->path_worker_count huge (INT32_MAX)",
     INVALID,
     "path_worker_count",
     {SET_I32(nl_world_def, path_worker_count, INT32_MAX)}},
    {"def->path_worker_count 0 (allowed: the host runs the queue)",
     ALLOWED,
     NULL,
     {SET_I32(nl_world_def, path_worker_count, 0)}},
    {"def->log_level 4", INVALID, "log_level", {SET_U32(nl_world_def, log_level, 4u)}},
    {"def->log_level huge", INVALID, "log_level", {SET_U32(nl_world_def, log_level, UINT32_MAX)}},
    {"def->log_fn NULL (allowed)", ALLOWED, NULL, {SET_PTR(nl_world_def, log_fn, NULL)}},
    {"def->log_user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_world_def, log_user, NULL)}},
};

/* A host task system that runs every task at once (and returns NULL), for defs with task callbacks. */
static void* hostile_task_enqueue(void* user, nl_task_fn* task, void* task_context, uint32_t item_count,
                                  uint32_t min_range) {
    (void)user;
    (void)min_range;
    task(task_context, 0u, item_count, 0u);
    return NULL;
}
static void hostile_task_finish(void* user, void* host_task) {
    (void)user;
    (void)host_task;
}

/* Made bad from a def with both task callbacks set and worker_count 2. */
static const def_case k_world_task_defs[] = {
    {"def->task_enqueue_fn NULL (task_finish_fn set)",
     INVALID,
     "def->task_enqueue_fn is NULL",
     {SET_PTR(nl_world_def, task_enqueue_fn, NULL)}},
    {"def->task_finish_fn NULL (task_enqueue_fn set)",
     INVALID,
     "def->task_finish_fn is NULL",
     {SET_PTR(nl_world_def, task_finish_fn, NULL)}},
    {"def->task_enqueue_fn NULL and task_finish_fn NULL (allowed: TBB)",
     ALLOWED,
     NULL,
     {SET_PTR(nl_world_def, task_enqueue_fn, NULL), SET_PTR(nl_world_def, task_finish_fn, NULL)}},
    {"def->task_user NULL (allowed: never dereferenced)", ALLOWED, NULL, {SET_PTR(nl_world_def, task_user, NULL)}},
    {"def->worker_count 0 (with task callbacks: the host's workers, at least 1)",
     INVALID,
     "worker_count",
     {SET_I32(nl_world_def, worker_count, 0)}},
    {"def->worker_count -1 (NL_WORKERS_AUTO, with task callbacks)",
     INVALID,
     "worker_count",
     {SET_I32(nl_world_def, worker_count, NL_WORKERS_AUTO)}},
    {"def->worker_count huge (NL_MAX_WORKERS + 1, with task callbacks)",
     INVALID,
     "NL_MAX_WORKERS",
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS + 1)}},
    {"def->worker_count NL_MAX_WORKERS (allowed with task callbacks: no thread starts)",
     ALLOWED,
     NULL,
     {SET_I32(nl_world_def, worker_count, NL_MAX_WORKERS)}},
    {"def->size small (ends inside the task callbacks)",
     INVALID,
     "def->size",
     {SET_U32(nl_world_def, size, (uint32_t)offsetof(nl_world_def, task_finish_fn))}},
    {"def->size small (before the task callbacks: they are not read)",
     ALLOWED,
     NULL,
     {SET_U32(nl_world_def, size, (uint32_t)offsetof(nl_world_def, task_enqueue_fn)),
      SET_PTR(nl_world_def, task_finish_fn, NULL)}},
};

static void group_world_create(void) {
    static const def_function create = {
        "nl_world_create", world_create_call, sizeof(nl_world*), world_destroy_out, 1, 1, 0};
    nl_world_def with_tasks;
    nl_world_def valid = nl_default_world_def();
#if !defined(NAVLINK_HOSTILE_SANITIZED)
    /* A library that starts the absurd thread counts runs out of stacks in milliseconds here instead
       of taking the machine's threads (not under sanitizers: their shadow memory needs the room). */
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > ((rlim_t)8 << 30))) {
        limit.rlim_cur = (rlim_t)8 << 30;
        setrlimit(RLIMIT_AS, &limit);
    }
#endif
    valid.worker_count = 1;
    valid.path_worker_count = 0;
    valid.log_fn = hostile_log; /* nl_world_create never logs: there is no world yet */
    def_function_cases(&create, &valid, sizeof valid);
    def_cases("nl_world_create", &valid, sizeof valid, k_world_defs, sizeof k_world_defs / sizeof *k_world_defs,
              def_refuses, def_accepts);
    with_tasks = valid;
    with_tasks.worker_count = 2;
    with_tasks.task_enqueue_fn = hostile_task_enqueue;
    with_tasks.task_finish_fn = hostile_task_finish;
    with_tasks.task_user = &with_tasks;
    def_cases("nl_world_create", &with_tasks, sizeof with_tasks, k_world_task_defs,
              sizeof k_world_task_defs / sizeof *k_world_task_defs, def_refuses, def_accepts);
}

static void group_world_destroy(void) {
    CASE("nl_world_destroy", "world NULL (allowed: ignored)") {
        fail_on_purpose();
        nl_world_destroy(NULL);
        EXPECT(nl_get_last_status() == NL_STATUS_SUCCESS && nl_get_last_error_message()[0] == '\0',
               "nl_world_destroy(NULL) left the status 0x%08x, \"%s\"", (unsigned)nl_get_last_status(),
               nl_get_last_error_message());
    }
}

static void group_world_get_worker_count(void) {
    CASE("nl_world_get_worker_count", "world NULL") {
        const int32_t n = nl_world_get_worker_count(NULL);
        EXPECT(n == 0, "returned %d for a NULL world", (int)n);
        EXPECT_INVALID(NULL, nl_get_last_status(), "world");
    }
    CASE("nl_world_get_worker_count", "world valid (1 worker, recorded as a success)") {
        const int32_t n = nl_world_get_worker_count(A.world);
        EXPECT(n == 1, "returned %d", (int)n);
        EXPECT_OK(nl_get_last_status());
    }
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"world_create", group_world_create},
    {"world_destroy", group_world_destroy},
    {"world_get_worker_count", group_world_get_worker_count},
};
const hostile_part hostile_world_part = {k_groups, sizeof k_groups / sizeof *k_groups};
