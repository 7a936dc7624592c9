// What every fuzz target shares: one world per process, and the rule every refusal must keep.
#pragma once

#include <navlink/navlink.h>

#include <cstdlib>
#include <cstring>

namespace nl::fuzz {

// One world for the whole run, with one worker: inputs run one after the other and nothing depends
// on thread timing, so a crash replays from its input alone.
inline nl_world* shared_world() {
    static nl_world* const world = [] {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        nl_world* created = nullptr;
        if (NL_FAILED(nl_world_create(&def, &created))) std::abort();
        return created;
    }();
    return world;
}

// Bad input is refused as bad input: a failure always says why, and never with INTERNAL_ERROR,
// which the library keeps for its own bugs. Traps otherwise, so libFuzzer saves the input.
inline void require_reasoned(nl_status status) {
    if (NL_SUCCEEDED(status)) return;
    if ((status & NL_STATUS_INTERNAL_ERROR) != 0 || std::strlen(nl_get_last_error_message()) == 0) __builtin_trap();
}

}  // namespace nl::fuzz
