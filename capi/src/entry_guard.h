// Every nl_* entry point runs its body through guarded(): it records the call's status and message
// for the calling thread, sends failures to the world's log callback, and stops every C++ exception
// at the ABI boundary.
#pragma once

#include <new>
#include <string>

#include "navlink/navlink.h"
#include "util/error.h"

struct nl_world;

namespace nl::capi {

nl_status to_status(ErrorCode code) noexcept;

// Records the outcome of the current call on this thread (and logs failures through `world`).
nl_status record(const char* function, const nl_world* world, nl_status status, const char* message) noexcept;
inline nl_status record_success() noexcept { return record(nullptr, nullptr, NL_STATUS_SUCCESS, ""); }

template <typename Body>
nl_status guarded(const char* function, const nl_world* world, Body&& body) noexcept {
    try {
        body();
        return record_success();
    } catch (const Error& e) {
        return record(function, world, NL_STATUS_FAILURE | to_status(e.code()), e.what());
    } catch (const std::bad_alloc&) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception& e) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, e.what());
    } catch (...) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, "unknown exception");
    }
}

// Throws InvalidArgument naming `name` when `pointer` is null.
inline void require(const void* pointer, const char* name) {
    if (!pointer) fail(ErrorCode::InvalidArgument, name, " is null");
}

// Throws InvalidArgument unless a growable struct's caller-set size covers at least `minimum`.
inline void require_size(uint32_t size, size_t minimum, const char* name) {
    if (size < minimum)
        fail(ErrorCode::InvalidArgument, name, "->size is ", size, ", expected at least ", minimum,
             " (initialise it from its nl_default_* function or with sizeof)");
}

}  // namespace nl::capi
