/*
 * What the files of navlink-c-api-test share: the counted checks (defined in c_api_test.c) and the
 * entry points of the test groups kept in other files. Strict C11 through the C ABI only.
 */
#ifndef NAVLINK_ABI_TEST_H
#define NAVLINK_ABI_TEST_H

#include <navlink/navlink.h>

#include <stddef.h>

/* ---------------------------------------------------------------------------------------------
 * Checks: every one is counted; a failure prints the file, line, section and the last error.
 * ------------------------------------------------------------------------------------------- */

extern int g_passed;
extern int g_failed;
extern const char* g_section;

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

/* ---------------------------------------------------------------------------------------------
 * Navmeshes, navmesh building and plugins (c_api_navmesh_test.c).
 * ------------------------------------------------------------------------------------------- */

/* The cases that may crash the process, each in a forked child: call while the process has no
   threads (before any world exists in it). */
void test_navmesh_isolated(void);
/* Everything else. */
void test_navmesh_all(void);

/* ---------------------------------------------------------------------------------------------
 * Paths, synchronous and queued (c_api_path_test.c). Creates threads: call after the forked cases.
 * ------------------------------------------------------------------------------------------- */

void test_paths_all(void);

#endif /* NAVLINK_ABI_TEST_H */
