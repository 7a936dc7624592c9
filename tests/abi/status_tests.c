/*
 * Status (navlink.h): the descriptions of statuses and the NL_SUCCEEDED / NL_FAILED macros. (The last
 * status and message are checked with the calls that set them, in every other section.)
 */
#include "abi_test.h"

#include <string.h>

static void strings_and_macros(void) {
    static const nl_status details[] = {
        NL_STATUS_INVALID_ARGUMENT, NL_STATUS_INVALID_HANDLE,   NL_STATUS_BUFFER_TOO_SMALL, NL_STATUS_OUT_OF_MEMORY,
        NL_STATUS_CANCELLED,        NL_STATUS_NOT_FOUND,        NL_STATUS_INTERNAL_ERROR,   NL_STATUS_IO_ERROR,
        NL_STATUS_PARSE_ERROR,      NL_STATUS_VERSION_MISMATCH,
    };
    const size_t n = sizeof details / sizeof details[0];
    size_t i, j;

    CHECK(strcmp(nl_status_string(NL_STATUS_SUCCESS), "success") == 0);
    CHECK(strstr(nl_status_string(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT), "success") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT), "partial") != NULL);
    CHECK(strcmp(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT), "failure: invalid argument") == 0);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_INVALID_HANDLE), "invalid handle") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_BUFFER_TOO_SMALL), "buffer too small") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND), "not found") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_PARSE_ERROR), "parse") != NULL);
    CHECK(strstr(nl_status_string(NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY), "memory") != NULL);
    CHECK(strncmp(nl_status_string(NL_STATUS_FAILURE), "failure", 7) == 0);
    CHECK(nl_status_string(NL_STATUS_IN_PROGRESS) != NULL && nl_status_string(NL_STATUS_IN_PROGRESS)[0] != '\0');
    CHECK(nl_status_string(0u) != NULL && nl_status_string(0xffffffffu) != NULL);
    {
        /* Each failure detail has its own description, all starting with "failure". */
        int distinct = 1, prefixed = 1;
        for (i = 0; i < n; ++i) {
            const char* a = nl_status_string(NL_STATUS_FAILURE | details[i]);
            if (a == NULL || strncmp(a, "failure", 7) != 0) prefixed = 0;
            for (j = i + 1; j < n; ++j) {
                if (a != NULL && strcmp(a, nl_status_string(NL_STATUS_FAILURE | details[j])) == 0) distinct = 0;
            }
        }
        CHECK(prefixed);
        CHECK(distinct);
    }

    CHECK(NL_SUCCEEDED(NL_STATUS_SUCCESS));
    CHECK(!NL_FAILED(NL_STATUS_SUCCESS));
    CHECK(NL_SUCCEEDED(NL_STATUS_SUCCESS | NL_STATUS_PARTIAL_RESULT));
    CHECK(NL_FAILED(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(!NL_SUCCEEDED(NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(!NL_SUCCEEDED(NL_STATUS_IN_PROGRESS) && !NL_FAILED(NL_STATUS_IN_PROGRESS));
}

ABI_SECTION(status, ABI_CASE(strings_and_macros));
