/*
 * The runner and the checks of navlink-abi-hostile-test. Each group runs in a forked child, which
 * reports every case over a pipe as it goes, one line per event:
 *   C <tab> function <tab> description   a case starts
 *   F <tab> text                          a check of it failed
 *   E <tab> P|F|K|R                       it ended: passed, failed, known failure, known failure that passed
 *   D                                     the group finished
 * so a child that crashes or hangs (an alarm stops it) names the case it was in, and the groups after
 * it still run.
 */
/* fork(), pipe(), waitpid() and alarm(); strict C11 otherwise. */
#define _POSIX_C_SOURCE 200809L

#include "hostile.h"

#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* Seconds a group may take before its child is stopped (a hang is a failure too). */
#define GROUP_TIMEOUT_SECONDS 300

/* ---------------------------------------------------------------------------------------------
 * The child's side: the current case and what reached the log callback
 * ------------------------------------------------------------------------------------------- */

static int g_report = -1; /* the pipe to the parent */
static const hostile_fixture* g_fixture;
static char g_function[64];
static char g_description[160];
static int g_case_failures;

static struct {
    unsigned count;
    nl_log_level level;
    nl_status status;
    char message[16384];
} g_log;
static unsigned g_log_mark; /* g_log.count at the case's start or its last check: each check sees its own call */

void hostile_log(void* user, nl_log_level level, nl_status status, const char* message) {
    (void)user;
    ++g_log.count;
    g_log.level = level;
    g_log.status = status;
    snprintf(g_log.message, sizeof g_log.message, "%s", message ? message : "(null)");
}

static void report(const char* kind, const char* text) {
    char line[2400];
    size_t n, k;
    int length = snprintf(line, sizeof line, "%s\t%s", kind, text);
    if (length < 0) return;
    n = (size_t)length < sizeof line - 2 ? (size_t)length : sizeof line - 2;
    for (k = 2; k < n; ++k)
        if (line[k] == '\n') line[k] = ' ';
    line[n++] = '\n';
    for (k = 0; k < n;) {
        const ssize_t w = write(g_report, line + k, n - k);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return;
        k += (size_t)w;
    }
}

static const known_failure* known(const char* function, const char* description) {
    size_t i;
    for (i = 0; i < k_known_failure_count; ++i) {
        if (strcmp(k_known_failures[i].function, function) == 0 &&
            strcmp(k_known_failures[i].description, description) == 0)
            return &k_known_failures[i];
    }
    return NULL;
}

int case_begin(const char* function, const char* format, ...) {
    char line[256];
    va_list args;
    snprintf(g_function, sizeof g_function, "%s", function);
    va_start(args, format);
    vsnprintf(g_description, sizeof g_description, format, args);
    va_end(args);
    g_case_failures = 0;
    g_log_mark = g_log.count;
    snprintf(line, sizeof line, "%s\t%s", g_function, g_description);
    report("C", line);
    return 1;
}

int case_end(void) {
    char why[1024] = "";
    const known_failure* k;
    if (g_fixture && g_fixture->unchanged && !g_fixture->unchanged(why, sizeof why))
        case_failed(__FILE__, __LINE__, "the worlds changed: %s", why);
    k = known(g_function, g_description);
    report("E", g_case_failures ? (k ? "K" : "F") : (k ? "R" : "P"));
    return 0;
}

void case_failed(const char* file, int line, const char* format, ...) {
    char text[1800];
    int n;
    va_list args;
    ++g_case_failures;
    n = snprintf(text, sizeof text, "%s:%d: ", file, line);
    va_start(args, format);
    vsnprintf(text + n, sizeof text - (size_t)n, format, args);
    va_end(args);
    report("F", text);
}

void fixture_refresh(void) {
    if (g_fixture && g_fixture->refresh) g_fixture->refresh();
}

/* ---------------------------------------------------------------------------------------------
 * Checks
 * ------------------------------------------------------------------------------------------- */

/* The messages that reached the log since the last check (each check sees its own call's). */
static unsigned logged_since_last_check(void) {
    const unsigned n = g_log.count - g_log_mark;
    g_log_mark = g_log.count;
    return n;
}

/* 1 if the call returned `expected`; reports it, and a last status that disagrees, otherwise. */
static int returned(const char* file, int line, nl_status got, nl_status expected) {
    const char* message = nl_get_last_error_message();
    if (got != expected) {
        case_failed(file, line, "returned 0x%08x (%s), expected 0x%08x (%s); message \"%s\"", (unsigned)got,
                    nl_status_string(got), (unsigned)expected, nl_status_string(expected),
                    message ? message : "(null)");
        return 0;
    }
    if (nl_get_last_status() != got)
        case_failed(file, line, "returned 0x%08x but the last status is 0x%08x", (unsigned)got,
                    (unsigned)nl_get_last_status());
    return 1;
}

void expect_failure_at(const char* file, int line, const nl_world* world, nl_status got, nl_status detail,
                       const char* needle) {
    const char* message = nl_get_last_error_message();
    const size_t prefix = strlen(g_function);
    const unsigned logged = logged_since_last_check();
    if (!returned(file, line, got, NL_STATUS_FAILURE | detail)) return;
    if (!message) {
        case_failed(file, line, "the last error message is NULL");
        return;
    }
    if (strncmp(message, g_function, prefix) != 0 || strncmp(message + prefix, ": ", 2) != 0 ||
        message[prefix + 2] == '\0')
        case_failed(file, line, "the message \"%s\" does not start with \"%s: \" and a reason", message, g_function);
    if (needle && !strstr(message, needle))
        case_failed(file, line, "the message \"%s\" does not name \"%s\"", message, needle);
    if (world) {
        if (logged != 1)
            case_failed(file, line, "the world's log callback received %u messages, expected the failure once", logged);
        else if (g_log.level != NL_LOG_ERROR || g_log.status != got || strcmp(g_log.message, message) != 0)
            case_failed(file, line, "the log callback received level %u, status 0x%08x, \"%s\"; expected the failure",
                        (unsigned)g_log.level, (unsigned)g_log.status, g_log.message);
    } else if (logged != 0) {
        case_failed(file, line, "a call without a world logged %u messages (\"%s\")", logged, g_log.message);
    }
}

void expect_success_at(const char* file, int line, nl_status got, nl_status expected) {
    const char* message = nl_get_last_error_message();
    const unsigned logged = logged_since_last_check();
    if (!returned(file, line, got, expected)) return;
    if (!message || message[0] != '\0')
        case_failed(file, line, "succeeded with the message \"%s\"", message ? message : "(null)");
    if (logged != 0) case_failed(file, line, "a success logged \"%s\"", g_log.message);
}

void fill(void* p, size_t n) { memset(p, SENTINEL, n); }

void expect_untouched_at(const char* file, int line, const void* p, size_t n, const char* name) {
    const unsigned char* b = (const unsigned char*)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (b[i] != SENTINEL) {
            case_failed(file, line, "%s was written (byte %u of %u is 0x%02x)", name, (unsigned)i, (unsigned)n, b[i]);
            return;
        }
    }
}

/* ---------------------------------------------------------------------------------------------
 * The parent's side
 * ------------------------------------------------------------------------------------------- */

typedef struct tally {
    size_t cases, passed, failed, known;
} tally;

static void add_record(case_record** cases, size_t* count, size_t* capacity, const char* function,
                       const char* description) {
    if (*count == *capacity) {
        *capacity = *capacity ? 2 * *capacity : 1024;
        *cases = (case_record*)realloc(*cases, *capacity * sizeof **cases);
        if (!*cases) exit(2);
    }
    snprintf((*cases)[*count].function, sizeof(*cases)[0].function, "%s", function);
    snprintf((*cases)[*count].description, sizeof(*cases)[0].description, "%s", description);
    ++*count;
}

/* Reads everything the child writes until it closes the pipe. */
static char* read_all(int fd) {
    size_t size = 0, capacity = 65536;
    char* text = (char*)malloc(capacity + 1);
    if (!text) exit(2);
    for (;;) {
        ssize_t n;
        if (size == capacity) {
            capacity *= 2;
            text = (char*)realloc(text, capacity + 1);
            if (!text) exit(2);
        }
        n = read(fd, text + size, capacity - size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        size += (size_t)n;
    }
    text[size] = '\0';
    return text;
}

/* Parses one child's report; returns 1 if it said it finished. `*in_case` says whether it stopped
   inside `last_case` or after it. */
static int parse_report(const char* group, char* text, tally* t, case_record** cases, size_t* count, size_t* capacity,
                        char* last_case, size_t last_case_size, int* in_case) {
    char* line = text;
    char failures[8192] = "";
    int done = 0;
    last_case[0] = '\0';
    *in_case = 0;
    while (line && *line) {
        char* next = strchr(line, '\n');
        if (next) *next++ = '\0';
        if (line[0] == 'C' && line[1] == '\t') {
            char* tab = strchr(line + 2, '\t');
            if (tab) {
                *tab = '\0';
                add_record(cases, count, capacity, line + 2, tab + 1);
                snprintf(last_case, last_case_size, "%s: %s", line + 2, tab + 1);
            }
            *in_case = 1;
            failures[0] = '\0';
            ++t->cases;
        } else if (line[0] == 'F' && line[1] == '\t') {
            const size_t used = strlen(failures);
            snprintf(failures + used, sizeof failures - used, "    %s\n", line + 2);
        } else if (line[0] == 'E' && line[1] == '\t') {
            switch (line[2]) {
                case 'P': ++t->passed; break;
                case 'K': {
                    const known_failure* k = known((*cases)[*count - 1].function, (*cases)[*count - 1].description);
                    ++t->known;
                    printf("KNOWN FAILURE: %s (%s)\n%s", last_case, k ? k->why : "?", failures);
                    break;
                }
                case 'R':
                    ++t->failed;
                    printf("FAILED [%s] %s: listed as a known failure but passes now: take it off the list\n", group,
                           last_case);
                    break;
                default: ++t->failed; printf("FAILED [%s] %s\n%s", group, last_case, failures);
            }
            *in_case = 0;
        } else if (line[0] == 'D') {
            done = 1;
        }
        line = next;
    }
    return done;
}

int run_groups(const hostile_group* groups, size_t count, const hostile_fixture* fixture, case_record** out_cases,
               size_t* out_case_count) {
    size_t g, capacity = 0;
    tally total = {0, 0, 0, 0};
    *out_cases = NULL;
    *out_case_count = 0;
    for (g = 0; g < count; ++g) {
        int fds[2], status = 0, done, in_case;
        pid_t pid;
        char* text;
        char last_case[256];
        tally t = {0, 0, 0, 0};
        fflush(stdout);
        fflush(stderr);
        if (pipe(fds) != 0 || (pid = fork()) < 0) {
            printf("FAILED [%s] cannot start a child process\n", groups[g].name);
            ++total.failed;
            continue;
        }
        if (pid == 0) {
            close(fds[0]);
            g_report = fds[1];
            g_fixture = fixture;
            alarm(GROUP_TIMEOUT_SECONDS);
            if (fixture->setup) fixture->setup();
            groups[g].run();
            if (fixture->teardown) fixture->teardown();
            report("D", "");
            close(g_report);
            exit(0); /* not _exit: a leak checker runs at exit, and its report fails the group */
        }
        close(fds[1]);
        text = read_all(fds[0]);
        close(fds[0]);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        done = parse_report(groups[g].name, text, &t, out_cases, out_case_count, &capacity, last_case, sizeof last_case,
                            &in_case);
        free(text);
        if (!done || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            char how[64];
            if (WIFSIGNALED(status))
                snprintf(how, sizeof how, "signal %d%s", WTERMSIG(status),
                         WTERMSIG(status) == SIGALRM ? ": a hang" : "");
            else
                snprintf(how, sizeof how, "exit code %d", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
            if (in_case)
                printf("FAILED [%s] the child stopped (%s) in %s; the rest of the group did not run\n", groups[g].name,
                       how, last_case);
            else if (last_case[0])
                printf(
                    "FAILED [%s] the child stopped (%s) after its last case, %s: destroying the worlds, or at exit "
                    "(a leak report?)\n",
                    groups[g].name, how, last_case);
            else
                printf("FAILED [%s] the child stopped (%s) before its first case\n", groups[g].name, how);
            ++t.failed;
        }
        printf("group %-34s %4u cases: %4u passed, %u failed, %u known failures\n", groups[g].name, (unsigned)t.cases,
               (unsigned)t.passed, (unsigned)t.failed, (unsigned)t.known);
        total.cases += t.cases;
        total.passed += t.passed;
        total.failed += t.failed;
        total.known += t.known;
    }
    printf("%u cases in %u groups: %u passed, %u failed, %u known failures\n", (unsigned)total.cases, (unsigned)count,
           (unsigned)total.passed, (unsigned)total.failed, (unsigned)total.known);
    return (int)total.failed;
}
