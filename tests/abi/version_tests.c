/*
 * Version (navlink.h): the loaded library's version is the header's.
 */
#include "abi_test.h"

static void matches_header(void) {
    nl_version v;

    v = nl_get_version();
    CHECK(v.major == NL_VERSION_MAJOR);
    CHECK(v.minor == NL_VERSION_MINOR);
    CHECK(v.patch == NL_VERSION_PATCH);
}

ABI_SECTION(version, ABI_CASE(matches_header));
