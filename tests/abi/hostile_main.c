/*
 * navlink-abi-hostile-test: every public nl_* function called with bad input, through the C ABI
 * only, in strict C11. For each call it checks what the header promises of a failure:
 *
 * - the status is exactly FAILURE with the documented detail bit (INVALID_ARGUMENT, INVALID_HANDLE,
 *   BUFFER_TOO_SMALL, NOT_FOUND, ...), and it is the thread's last status;
 * - the last error message starts with the function's name and names the bad argument, and the
 *   world's log callback received the same failure once (nothing when there is no world);
 * - the outputs are untouched (they are filled with a sentinel byte first), but for the count of a
 *   list that did not fit;
 * - the worlds are as they were: after every case the runner compares everything both worlds hold
 *   (meshes and their info, navmeshes, every link, plugins, the path queue, a known link, a known
 *   path, two rays, every agent's info, corners and trajectory, the last step's agent events) with
 *   how it was when the group started.
 *
 * Calls the header allows (a NULL optional output, count 0, a NULL world to nl_world_destroy) are
 * checked as documented. Cases are rows of tables where they can be (def_case, text_case, the id
 * functions): a new field or function gets its cases by a row, and the coverage check says which. The bad inputs: each pointer NULL in turn; counts and lengths 0 and huge (a
 * huge count with a NULL pointer must not be read); ids null, stale (their slot reused by a live
 * object), garbage and foreign (issued by the second live world, with the same slot and counter as
 * a live id of the first: only the world tag differs), and for agents ids of other kinds; `size` fields 0, too small and larger than
 * the library's struct; NaN and infinities in every float input.
 *
 * Two worlds, A (under test) and B (foreign), are built the same way in each child process (see
 * build_world in hostile_fixtures.c). The cases are in one file per part of the headers,
 * hostile_<part>_tests.c, each with its table of groups; this file runs the parts in the headers'
 * order. Each group runs in its own child (hostile_runner.c), so a crash names its case. At the
 * end, the coverage check (hostile_coverage.c) reads the public headers and fails for any NL_API
 * function, parameter or input field without its cases.
 *
 * A defect that needs a core fix is listed in k_known_failures: its case prints "KNOWN FAILURE" and
 * does not fail the run, and fails it once it passes (so the list stays true).
 *
 * Usage: navlink-abi-hostile-test --headers DIR... [--library LIBNAVLINK] [--plugin CLIMB_PLUGIN]
 *                                   [--only GROUP]
 */
#include "hostile_fixtures.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The parts in the order navlink.h includes them, then plugin.h: their groups run in this order. */
static const hostile_part* const k_parts[] = {
    &hostile_base_part,   &hostile_world_part,        &hostile_level_part,      &hostile_navmesh_part,
    &hostile_links_part,  &hostile_navmesh_file_part, &hostile_paths_part,      &hostile_queries_part,
    &hostile_agents_part, &hostile_plugins_part,      &hostile_plugin_abi_part,
};
#define PART_COUNT (sizeof k_parts / sizeof *k_parts)

const char* g_library_path;
const char* g_plugin_path;

static const coverage_exemption k_exemptions[] = {
    {"nl_plugin_get_description", "plugin", "stale",
     "plugins stay loaded until the world is destroyed: no plugin id goes stale"},
};

/* Defects whose fix belongs in the core (sdk/) or a plugin, not in the C mapping layer. An entry is
   {function, case, why}. (The JSON readers' number overflow, listed here before, is fixed.)
   Ids of every kind count their slots alike in a world (sdk/util/handle.h: the generation holds the
   world's tag and the slot's counter, nothing of the kind), so an id of another kind whose slot and
   counter are a live agent's is that agent: A's navmesh id is A's walker. The C types keep the kinds
   apart; a binding that stores ids as plain integers does not. A kind in the generation is a change
   of the handle layout for every kind. */
const known_failure k_known_failures[1] = {{NULL, NULL, NULL}};
const size_t k_known_failure_count = 0;

int main(int argc, char** argv) {
    const char* header_dirs[8];
    size_t dir_count = 0, case_count = 0, p, g, group_count = 0, selected_count = 0;
    const char* only = NULL;
    case_record* cases = NULL;
    hostile_group* selected;
    int failed, gaps = 0, i, mode = 0;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--headers") == 0)
            mode = 1;
        else if (strcmp(argv[i], "--library") == 0 && i + 1 < argc)
            g_library_path = argv[++i];
        else if (strcmp(argv[i], "--plugin") == 0 && i + 1 < argc)
            g_plugin_path = argv[++i];
        else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (mode == 1 && dir_count < sizeof header_dirs / sizeof *header_dirs)
            header_dirs[dir_count++] = argv[i];
        else {
            fprintf(stderr, "usage: %s --headers DIR... [--library LIBNAVLINK] [--plugin PLUGIN] [--only GROUP]\n",
                    argv[0]);
            return 2;
        }
    }
    for (p = 0; p < PART_COUNT; ++p) group_count += k_parts[p]->count;
    selected = (hostile_group*)malloc(group_count * sizeof *selected);
    if (!selected) return 2;
    for (p = 0; p < PART_COUNT; ++p)
        for (g = 0; g < k_parts[p]->count; ++g)
            if (!only || strcmp(only, k_parts[p]->groups[g].name) == 0)
                selected[selected_count++] = k_parts[p]->groups[g];
    failed = run_groups(selected, selected_count, &hostile_worlds, &cases, &case_count);
    free(selected);
    if (only) {
        printf("coverage: not checked (--only %s)\n", only);
    } else if (dir_count == 0) {
        printf("coverage: FAILED: no --headers given, so no check that every function has its cases\n");
        gaps = 1;
    } else {
        gaps = check_coverage(header_dirs, dir_count, cases, case_count, k_exemptions,
                              sizeof k_exemptions / sizeof *k_exemptions);
    }
    free(cases);
    printf("%s\n", failed == 0 && gaps == 0 ? "PASSED" : "FAILED");
    return failed == 0 && gaps == 0 ? 0 : 1;
}
