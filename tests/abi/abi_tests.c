/*
 * navlink-abi-tests: NavLink's behaviour through the C ABI only, written in strict C11, one file per
 * section of navlink.h (abi_test.h says how a case is written).
 *
 * Usage: navlink-abi-tests [--levels DIR | DIR] [--list | --case NAME]
 *   --list        prints every case's name (abi.<section>.<case>), one a line
 *   --case NAME   runs that case alone in this process: exit 0 if every check held, 1 if not, 77 if
 *                 it skipped (ctest's SKIP_RETURN_CODE), 2 for a bad command line
 *   (neither)     runs every case, each in a child process; exit 0 if all passed or skipped
 *   DIR           the shared levels (dungeon.obj); the cases that need them skip without
 *
 * Every check is counted; a case ends with "NAME: N passed, N failed".
 */
/* fork(), pipe() and waitpid() run each case in a child; strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "abi_test.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------------------
 * The sections, in the header's order: abi_sections.h is written by CMake from the list of
 * <section>_tests.c files it builds (tests/abi/CMakeLists.txt), one ABI_SECTION_ENTRY(section) each.
 * ------------------------------------------------------------------------------------------- */

#define ABI_SECTION_ENTRY(section) extern const abi_section abi_section_##section;
#include "abi_sections.h"
#undef ABI_SECTION_ENTRY

static const abi_section* const k_sections[] = {
#define ABI_SECTION_ENTRY(section) &abi_section_##section,
#include "abi_sections.h"
#undef ABI_SECTION_ENTRY
};
enum { k_section_count = sizeof k_sections / sizeof k_sections[0] };

#define EXIT_SKIPPED 77
#define NAME_SIZE 160

/* ---------------------------------------------------------------------------------------------
 * Checks (declared in abi_test.h)
 * ------------------------------------------------------------------------------------------- */

int g_passed;
int g_failed;
const char* g_section = "";

int check_at(int ok, const char* file, int line, const char* what, ...) {
    if (ok) {
        ++g_passed;
        return 1;
    }
    ++g_failed;
    fprintf(stderr, "%s:%d: FAILED [%s] ", file, line, g_section);
    {
        va_list args;
        va_start(args, what);
        vfprintf(stderr, what, args);
        va_end(args);
    }
    fprintf(stderr, "\n    last status 0x%08x (%s), last message \"%s\"\n", (unsigned)nl_get_last_status(),
            nl_status_string(nl_get_last_status()), nl_get_last_error_message());
    return 0;
}

int check_ok_at(nl_status got, const char* expr, const char* file, int line) {
    return check_at(
        got == NL_STATUS_SUCCESS && nl_get_last_status() == NL_STATUS_SUCCESS && nl_get_last_error_message()[0] == '\0',
        file, line, "%s returned 0x%08x (%s): %s", expr, (unsigned)got, nl_status_string(got),
        nl_get_last_error_message());
}

int check_fail_at(nl_status got, nl_status detail, const char* needle, const char* expr, const char* file, int line) {
    const nl_status expected = NL_STATUS_FAILURE | detail;
    const char* message = nl_get_last_error_message();
    return check_at(
        got == expected && nl_get_last_status() == expected && message != NULL && strstr(message, needle) != NULL, file,
        line, "%s returned 0x%08x (%s), expected 0x%08x (%s) with a message containing \"%s\"", expr, (unsigned)got,
        nl_status_string(got), (unsigned)expected, nl_status_string(expected), needle);
}

int check_near_at(double a, double b, double tol, const char* ea, const char* eb, const char* file, int line) {
    return check_at(fabs(a - b) <= tol, file, line, "%s = %.9g, expected %s = %.9g (tolerance %g)", ea, a, eb, b, tol);
}

int all_bytes(const void* p, size_t n, unsigned char value) {
    const unsigned char* b = (const unsigned char*)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (b[i] != value) return 0;
    }
    return 1;
}

nl_world* make_world(int32_t workers) {
    nl_world_def def = nl_default_world_def();
    nl_world* world = NULL;
    def.worker_count = workers;
    if (NL_FAILED(nl_world_create(&def, &world))) {
        fprintf(stderr, "cannot create a world: %s\n", nl_get_last_error_message());
        exit(2);
    }
    return world;
}

int run_forked(int (*fn)(size_t), size_t arg) {
    pid_t pid;
    int status = 0;
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        if (!freopen("/dev/null", "w", stderr)) { /* a library's abort message is not this test's output */
        }
        _exit(fn(arg) ? 0 : 3);
    }
    if (waitpid(pid, &status, 0) != pid) return 0;
    if (!WIFEXITED(status)) return -1;
    return WEXITSTATUS(status) == 0 ? 1 : WEXITSTATUS(status) == 3 ? 0 : -1;
}

/* ---------------------------------------------------------------------------------------------
 * Running one case
 * ------------------------------------------------------------------------------------------- */

static const char* g_levels_dir;
static int g_report = -1; /* in a child of the run of every case: the pipe its counts go to */

const char* abi_levels_dir(void) { return g_levels_dir; }

/* Prints the case's counts, sends them to the parent if there is one, and exits with its status. */
static _Noreturn void finish_case(int skipped) {
    int status = g_failed > 0 ? EXIT_FAILURE : skipped ? EXIT_SKIPPED : EXIT_SUCCESS;
    if (!skipped && g_failed == 0 && g_passed == 0) {
        fprintf(stderr, "FAILED [%s]: the case made no check\n", g_section);
        status = EXIT_FAILURE;
    }
    if (g_report < 0)
        printf("%s: %d passed, %d failed%s\n", g_section, g_passed, g_failed, skipped ? " (skipped)" : "");
    fflush(stdout);
    fflush(stderr);
    if (g_report >= 0) {
        char line[64];
        const int n = snprintf(line, sizeof line, "%d %d\n", g_passed, g_failed);
        if (n > 0 && write(g_report, line, (size_t)n) != n) {}
        close(g_report);
    }
    exit(status);
}

void abi_skip(const char* why) {
    printf("%s: skipped: %s\n", g_section, why);
    finish_case(1);
}

static _Noreturn void run_case(const char* name, const abi_case* c) {
    g_passed = 0;
    g_failed = 0;
    g_section = name;
    c->run();
    finish_case(0);
}

/* ---------------------------------------------------------------------------------------------
 * The table
 * ------------------------------------------------------------------------------------------- */

static void full_name(char out[NAME_SIZE], const abi_section* s, const abi_case* c) {
    snprintf(out, NAME_SIZE, "abi.%s.%s", s->name, c->name);
}

/* The case named `name` (its section in *out_section), or NULL. */
static const abi_case* find_case(const char* name, const abi_section** out_section) {
    size_t s, c;
    char candidate[NAME_SIZE];
    for (s = 0; s < k_section_count; ++s) {
        for (c = 0; c < k_sections[s]->count; ++c) {
            full_name(candidate, k_sections[s], &k_sections[s]->cases[c]);
            if (strcmp(candidate, name) == 0) {
                *out_section = k_sections[s];
                return &k_sections[s]->cases[c];
            }
        }
    }
    return NULL;
}

/* 1 if every name is unique (two sections or two tables could share a name); else names the first
   repeated one. */
static int names_unique(void) {
    size_t s, c;
    for (s = 0; s < k_section_count; ++s) {
        for (c = 0; c < k_sections[s]->count; ++c) {
            const abi_section* found_section = NULL;
            char name[NAME_SIZE];
            full_name(name, k_sections[s], &k_sections[s]->cases[c]);
            if (find_case(name, &found_section) != &k_sections[s]->cases[c]) {
                fprintf(stderr, "navlink-abi-tests: two cases are named %s\n", name);
                return 0;
            }
        }
    }
    return 1;
}

/* Runs every case in a child of its own; returns the exit status. */
static int run_all(void) {
    int cases = 0, failed = 0, skipped = 0;
    long passed_checks = 0, failed_checks = 0;
    size_t s, c;
    if (g_levels_dir == NULL) printf("note: no levels directory given: the cases that need one skip\n");
    for (s = 0; s < k_section_count; ++s) {
        for (c = 0; c < k_sections[s]->count; ++c) {
            char name[NAME_SIZE], counts[64];
            int fds[2], status = 0, checks_passed = 0, checks_failed = 0;
            size_t got = 0;
            ssize_t n;
            pid_t pid;
            const char* outcome;
            full_name(name, k_sections[s], &k_sections[s]->cases[c]);
            ++cases;
            fflush(stdout);
            fflush(stderr);
            if (pipe(fds) != 0 || (pid = fork()) < 0) {
                fprintf(stderr, "%s: cannot start a child process\n", name);
                ++failed;
                continue;
            }
            if (pid == 0) {
                close(fds[0]);
                g_report = fds[1];
                run_case(name, &k_sections[s]->cases[c]);
            }
            close(fds[1]);
            while (got < sizeof counts - 1 && (n = read(fds[0], counts + got, sizeof counts - 1 - got)) > 0)
                got += (size_t)n;
            counts[got] = '\0';
            close(fds[0]);
            if (waitpid(pid, &status, 0) != pid) status = -1;
            if (sscanf(counts, "%d %d", &checks_passed, &checks_failed) != 2) checks_passed = checks_failed = 0;
            passed_checks += checks_passed;
            failed_checks += checks_failed;
            if (WIFEXITED(status) && WEXITSTATUS(status) == EXIT_SUCCESS) {
                outcome = "ok";
            } else if (WIFEXITED(status) && WEXITSTATUS(status) == EXIT_SKIPPED) {
                outcome = "skipped";
                ++skipped;
            } else if (WIFSIGNALED(status)) {
                outcome = "CRASHED";
                ++failed;
            } else {
                outcome = "FAILED";
                ++failed;
            }
            printf("%-8s %s (%d checks passed, %d failed)\n", outcome, name, checks_passed, checks_failed);
        }
    }
    printf("%d cases: %d passed, %d failed, %d skipped; checks: %ld passed, %ld failed\n", cases,
           cases - failed - skipped, failed, skipped, passed_checks, failed_checks);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

static int usage(void) {
    fprintf(stderr, "usage: navlink-abi-tests [--levels DIR | DIR] [--list | --case NAME]\n");
    return 2;
}

int main(int argc, char** argv) {
    const char* only = NULL;
    int list = 0, i;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--list") == 0) {
            list = 1;
        } else if (strcmp(argv[i], "--case") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else if (strcmp(argv[i], "--levels") == 0 && i + 1 < argc) {
            g_levels_dir = argv[++i];
        } else if (argv[i][0] != '-' && g_levels_dir == NULL) {
            g_levels_dir = argv[i];
        } else {
            return usage();
        }
    }
    if (g_levels_dir != NULL && g_levels_dir[0] == '\0') g_levels_dir = NULL;
    if (!names_unique()) return 2;

    if (list) {
        size_t s, c;
        char name[NAME_SIZE];
        if (only != NULL) return usage();
        for (s = 0; s < k_section_count; ++s) {
            for (c = 0; c < k_sections[s]->count; ++c) {
                full_name(name, k_sections[s], &k_sections[s]->cases[c]);
                printf("%s\n", name);
            }
        }
        return EXIT_SUCCESS;
    }
    if (only != NULL) {
        const abi_section* section = NULL;
        const abi_case* c = find_case(only, &section);
        if (c == NULL) {
            fprintf(stderr, "navlink-abi-tests: no case is named '%s' (--list prints them)\n", only);
            return 2;
        }
        run_case(only, c);
    }
    return run_all();
}
