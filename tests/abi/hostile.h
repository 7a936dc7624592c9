/*
 * navlink-abi-hostile-test: every public nl_* function called with bad input, run group by group
 * in child processes (hostile_runner.c), and held against the public headers: each function, and
 * each of its parameters, needs the hostile cases its type calls for (hostile_coverage.c derives
 * them from the declarations). The cases are in one file per part of the headers,
 * hostile_<part>_tests.c (base, world, level, navmesh, links, navmesh_file, paths, queries,
 * agents, plugins; plugin_abi for plugin.h), on the worlds and with the helpers of
 * hostile_fixtures.c; hostile_main.c runs the parts in the headers' order. Strict C11 through the
 * C ABI only.
 */
#ifndef NAVLINK_ABI_HOSTILE_H
#define NAVLINK_ABI_HOSTILE_H

#include <navlink/navlink.h>

/* An nl_path_process budget of requests and milliseconds, as a pointer (C11 compound literal). */
#define NL_TEST_BUDGET(requests, milliseconds) \
    (&(nl_path_budget){sizeof(nl_path_budget), (requests), (milliseconds), 0})

#include <stddef.h>

/* ---------------------------------------------------------------------------------------------
 * Cases. A case is a block run once; it fails if any EXPECT in it fails. Its name is the function
 * it calls and a description "SUBJECT CONDITION [details]": SUBJECT is the parameter or field made
 * bad ("def->start[1]", "out_count"), CONDITION one word saying how ("NULL", "0", "huge", "NaN",
 * "inf", "null", "stale", "garbage", "foreign", "small", "large", ...). The coverage check matches
 * these two words against what each declaration needs, so keep to that form.
 * ------------------------------------------------------------------------------------------- */

int case_begin(const char* function, const char* format, ...);
int case_end(void);
#define CASE(function, ...) \
    for (int case_open_ = case_begin((function), __VA_ARGS__); case_open_; case_open_ = case_end())

void case_failed(const char* file, int line, const char* format, ...);
#define EXPECT(cond, ...) ((cond) ? (void)0 : case_failed(__FILE__, __LINE__, __VA_ARGS__))

/* The call failed with exactly FAILURE | `detail`, recorded it as the thread's last status, with a
   message "FUNCTION: ..." that contains `needle`; the failure went to the log callback of `world`
   once with the same status and message (no log at all when `world` is NULL). */
void expect_failure_at(const char* file, int line, const nl_world* world, nl_status got, nl_status detail,
                       const char* needle);
#define EXPECT_FAILURE(world, got, detail, needle) \
    expect_failure_at(__FILE__, __LINE__, (world), (got), (detail), (needle))
#define EXPECT_INVALID(world, got, needle) EXPECT_FAILURE((world), (got), NL_STATUS_INVALID_ARGUMENT, (needle))
#define EXPECT_BAD_HANDLE(world, got, needle) EXPECT_FAILURE((world), (got), NL_STATUS_INVALID_HANDLE, (needle))
/* The call returned `expected` (a success kind), recorded it, left an empty message and logged nothing. */
void expect_success_at(const char* file, int line, nl_status got, nl_status expected);
#define EXPECT_STATUS(got, expected) expect_success_at(__FILE__, __LINE__, (got), (expected))
#define EXPECT_OK(got) EXPECT_STATUS((got), NL_STATUS_SUCCESS)

/* Outputs are filled with SENTINEL before a call; on failure every byte must still be SENTINEL. */
#define SENTINEL 0xa5
void fill(void* p, size_t n);
void expect_untouched_at(const char* file, int line, const void* p, size_t n, const char* name);
#define EXPECT_UNTOUCHED(p, n, name) expect_untouched_at(__FILE__, __LINE__, (p), (n), (name))
/* A growable output struct: untouched but for its `size` field, which the caller set. */
#define EXPECT_UNTOUCHED_AFTER_SIZE(p, n, name)                                                                   \
    expect_untouched_at(__FILE__, __LINE__, (const unsigned char*)(p) + sizeof(uint32_t), (n) - sizeof(uint32_t), \
                        (name))

/* A case whose failure is a known defect of the library that needs a core change: the runner prints
   "KNOWN FAILURE: ..." instead of failing the run, and fails it if the case starts to pass. */
typedef struct known_failure {
    const char* function;
    const char* description; /* the case's whole description */
    const char* why;
} known_failure;
extern const known_failure k_known_failures[];
extern const size_t k_known_failure_count;

/* ---------------------------------------------------------------------------------------------
 * Groups: each runs in its own child process, so a crash names its group and case and the other
 * groups still run. `setup` builds the fixture in the child (no NavLink thread exists before).
 * ------------------------------------------------------------------------------------------- */

typedef struct hostile_group {
    const char* name;
    void (*run)(void);
} hostile_group;

/* The groups of one part of the headers, in its file's table (hostile_<part>_tests.c). A group holds
   the cases of one function (or a few the part declares together); hostile_main.c runs the parts in
   the order navlink.h includes them, plugin.h last. */
typedef struct hostile_part {
    const hostile_group* groups;
    size_t count;
} hostile_part;
extern const hostile_part hostile_base_part, hostile_world_part, hostile_level_part, hostile_navmesh_part,
    hostile_links_part, hostile_navmesh_file_part, hostile_paths_part, hostile_queries_part, hostile_agents_part,
    hostile_plugins_part, hostile_plugin_abi_part;

/* What the runner needs from the test: `setup` builds the worlds in the child before its group;
   `unchanged` runs after every case and says (in `why`) what differs from the worlds as they were
   when the group started, or returns 1; `refresh` makes the worlds as they are now the reference
   (after a case that changed them as documented, and checked that); `teardown` destroys them after
   the group, before the child exits normally (so a leak checker sees what the failures left). */
typedef struct hostile_fixture {
    void (*setup)(void);
    int (*unchanged)(char* why, size_t why_size);
    void (*refresh)(void);
    void (*teardown)(void);
} hostile_fixture;
void fixture_refresh(void);

/* The log callback every world of the fixture is created with: it records what reaches it. */
void hostile_log(void* user, nl_log_level level, nl_status status, const char* message);

typedef struct case_record {
    char function[64];
    char description[160];
} case_record;

/* Runs every group, each in a child; returns the number of failed cases (crashes included). Fills
   the list of cases run (malloc'ed), for the coverage check. */
int run_groups(const hostile_group* groups, size_t count, const hostile_fixture* fixture, case_record** out_cases,
               size_t* out_case_count);

/* ---------------------------------------------------------------------------------------------
 * Coverage (hostile_coverage.c)
 * ------------------------------------------------------------------------------------------- */

/* A requirement that does not apply, with the reason (printed with the summary). */
typedef struct coverage_exemption {
    const char* function;
    const char* subject;
    const char* condition;
    const char* reason;
} coverage_exemption;

/* Reads every .h file of each directory, derives what each NL_API function needs (per parameter: a
   pointer NULL; an id null, stale, garbage and foreign; an integer 0 and huge; a float NaN and inf;
   a struct's size 0, small and large; in input structs the same per field), and checks `cases`
   against it. Prints each gap; returns the number of gaps (and 1 if no header could be read). */
int check_coverage(const char* const* header_dirs, size_t dir_count, const case_record* cases, size_t case_count,
                   const coverage_exemption* exemptions, size_t exemption_count);

#endif /* NAVLINK_ABI_HOSTILE_H */
