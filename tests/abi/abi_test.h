/*
 * What the files of navlink-abi-tests share: the counted checks, the case tables and the runner
 * (abi_tests.c). Strict C11 through the C ABI only.
 *
 * Each <section>_tests.c file tests one section of navlink.h (plugin_abi_tests.c: plugin.h). A case is
 * a static void function listed in its file's table, and is named abi.<section>.<function>:
 *
 *     static void stale_ids(void) { ... CHECK(...); ... }
 *     ...
 *     ABI_SECTION(level, ABI_CASE(mesh_add_and_info), ABI_CASE(stale_ids), ...);   (in level_tests.c)
 *
 * A case left out of the table is an unused static function, which the strict warnings make a build
 * error. A new section is a new <section>_tests.c named in tests/abi/CMakeLists.txt's section list,
 * which also lists it for the runner (abi_sections.h). `navlink-abi-tests --list` prints the names;
 * ctest registers each as its own test (the build runs --list once the program is linked), so a case
 * added to a table shows up in ctest by itself.
 *
 * Every case runs in a process of its own: `--case NAME` in this one, and with no argument each case
 * in a child forked from a runner that makes no nl_* call. A case starts in a process without
 * threads, so it may fork before it creates its first world (fork() copies only the calling thread).
 */
#ifndef NAVLINK_ABI_TEST_H
#define NAVLINK_ABI_TEST_H

#include <navlink/navlink.h>

/* An nl_path_process budget of requests and milliseconds, as a pointer (C11 compound literal). */
#define NL_TEST_BUDGET(requests, milliseconds) \
    (&(nl_path_budget){sizeof(nl_path_budget), (requests), (milliseconds), 0})

#include <stddef.h>

/* ---------------------------------------------------------------------------------------------
 * Checks: every one is counted; a failure prints the file, line, case and the last error. A case
 * that makes no check fails (unless it says why it skipped).
 * ------------------------------------------------------------------------------------------- */

extern int g_passed;
extern int g_failed;
extern const char* g_section; /* the running case's name, printed with each failure */

int check_at(int ok, const char* file, int line, const char* what, ...);
int check_ok_at(nl_status got, const char* expr, const char* file, int line);
int check_fail_at(nl_status got, nl_status detail, const char* needle, const char* expr, const char* file, int line);
int check_near_at(double a, double b, double tol, const char* ea, const char* eb, const char* file, int line);
/* 1 if the n bytes at p all equal value. */
int all_bytes(const void* p, size_t n, unsigned char value);

#define CHECK(cond) check_at((cond) != 0, __FILE__, __LINE__, "%s", #cond)
#define CHECK_MSG(cond, ...) check_at((cond) != 0, __FILE__, __LINE__, __VA_ARGS__)
/* A success: the status is exactly SUCCESS and the last message is empty. */
#define CHECK_OK(status) check_ok_at((status), #status, __FILE__, __LINE__)
/* A failure with `detail`, whose message contains `needle`. */
#define CHECK_FAIL(status, detail, needle) check_fail_at((status), (detail), (needle), #status, __FILE__, __LINE__)
#define CHECK_INVALID(status, needle) CHECK_FAIL((status), NL_STATUS_INVALID_ARGUMENT, (needle))
#define CHECK_NEAR(a, b, tol) check_near_at((double)(a), (double)(b), (double)(tol), #a, #b, __FILE__, __LINE__)
/* A check with a sentence saying what the library must do. */
#define CHECK_THAT(cond, what) check_at((cond) != 0, __FILE__, __LINE__, "%s", (what))

#define TOL 1e-5f

/* A world with `workers` workers; exits the test if it cannot be created. */
nl_world* make_world(int32_t workers);

/* Runs `fn(arg)` in a child process: 1 if it returned nonzero, 0 if zero, -1 if the child crashed or
   was stopped by a sanitizer (which exits with status 1: a wrong answer exits with 3). Call it before
   the case makes its first world: fork() copies only the calling thread. */
int run_forked(int (*fn)(size_t), size_t arg);

/* ---------------------------------------------------------------------------------------------
 * Cases
 * ------------------------------------------------------------------------------------------- */

typedef void abi_case_fn(void);

typedef struct abi_case {
    const char* name; /* the function's name */
    abi_case_fn* run;
} abi_case;

typedef struct abi_section {
    const char* name;
    const abi_case* cases;
    size_t count;
} abi_section;

#define ABI_CASE(fn) \
    { #fn, fn }

/* Defines the section `abi_section_<name>` (listed in abi_tests.c) with the cases given. */
#define ABI_SECTION(name, ...)                                       \
    static const abi_case abi_cases_##name[] = {__VA_ARGS__};        \
    const abi_section abi_section_##name = {#name, abi_cases_##name, \
                                            sizeof abi_cases_##name / sizeof abi_cases_##name[0]}

/* The directory of the shared levels (dungeon.obj), or NULL when the test was given none. */
const char* abi_levels_dir(void);

/* Ends the case as skipped (ctest shows it as "Not Run"), saying why; checks made before still
   count. Call it only from the case's own thread. */
_Noreturn void abi_skip(const char* why);

#endif /* NAVLINK_ABI_TEST_H */
