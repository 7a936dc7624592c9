#include <cstdio>
#include <string>

#include "entry_guard.h"
#include "world.h"

namespace nl::capi {
namespace {

struct LastCall {
    nl_status status = NL_STATUS_SUCCESS;
    std::string message;
};

// Per thread by design (as errno and Embree's device errors): the record of one thread's calls
// must not be overwritten by another's.
thread_local LastCall last_call;

}  // namespace

nl_status to_status(ErrorCode code) noexcept {
    switch (code) {
        case ErrorCode::InvalidArgument: return NL_STATUS_INVALID_ARGUMENT;
        case ErrorCode::InvalidHandle: return NL_STATUS_INVALID_HANDLE;
        case ErrorCode::BufferTooSmall: return NL_STATUS_BUFFER_TOO_SMALL;
        case ErrorCode::OutOfMemory: return NL_STATUS_OUT_OF_MEMORY;
        case ErrorCode::Cancelled: return NL_STATUS_CANCELLED;
        case ErrorCode::NotFound: return NL_STATUS_NOT_FOUND;
        case ErrorCode::Internal: return NL_STATUS_INTERNAL_ERROR;
        case ErrorCode::Io: return NL_STATUS_IO_ERROR;
        case ErrorCode::Parse: return NL_STATUS_PARSE_ERROR;
        case ErrorCode::VersionMismatch: return NL_STATUS_VERSION_MISMATCH;
    }
    return NL_STATUS_INTERNAL_ERROR;
}

ErrorCode to_error_code(nl_status status) noexcept {
    static const ErrorCode codes[] = {ErrorCode::InvalidHandle,
                                      ErrorCode::InvalidArgument,
                                      ErrorCode::BufferTooSmall,
                                      ErrorCode::OutOfMemory,
                                      ErrorCode::Cancelled,
                                      ErrorCode::NotFound,
                                      ErrorCode::Io,
                                      ErrorCode::Parse,
                                      ErrorCode::VersionMismatch};
    for (ErrorCode code : codes) {
        if (status & to_status(code)) return code;
    }
    return ErrorCode::Internal;
}

nl_status record(const char* function, const nl_world* world, nl_status status, const char* message) noexcept {
    LastCall& last = last_call;
    last.status = status;
    if (!function) {
        last.message.clear();
        return status;
    }
    try {
        last.message.assign(function).append(": ").append(message);
    } catch (...) {
        last.message.clear();  // keep the status even when the message cannot be stored
    }
    if (world && world->core) world->core->logger().log(LogLevel::Error, last.message, to_error_code(status));
    return status;
}

}  // namespace nl::capi

extern "C" {

NL_API nl_version nl_get_version(void) { return nl_version{NL_VERSION_MAJOR, NL_VERSION_MINOR, NL_VERSION_PATCH}; }

NL_API const char* nl_status_string(nl_status status) {
    if (NL_SUCCEEDED(status)) {
        if (status & NL_STATUS_PARTIAL_RESULT) return "success: partial result";
        return "success";
    }
    if (status & NL_STATUS_IN_PROGRESS) return "in progress";
    if (!NL_FAILED(status)) return "unknown status";
    // The most specific reason first, when several detail bits are set.
    static const struct {
        nl_status bit;
        const char* text;
    } reasons[] = {
        {NL_STATUS_INVALID_HANDLE, "failure: invalid handle"},
        {NL_STATUS_INVALID_ARGUMENT, "failure: invalid argument"},
        {NL_STATUS_BUFFER_TOO_SMALL, "failure: buffer too small"},
        {NL_STATUS_OUT_OF_MEMORY, "failure: out of memory"},
        {NL_STATUS_CANCELLED, "failure: cancelled"},
        {NL_STATUS_NOT_FOUND, "failure: not found"},
        {NL_STATUS_IO_ERROR, "failure: input/output error"},
        {NL_STATUS_PARSE_ERROR, "failure: parse error"},
        {NL_STATUS_VERSION_MISMATCH, "failure: version mismatch"},
        {NL_STATUS_INTERNAL_ERROR, "failure: internal error"},
        {NL_STATUS_PARTIAL_RESULT, "failure: partial result"},
    };
    for (const auto& r : reasons) {
        if (status & r.bit) return r.text;
    }
    return "failure";
}

NL_API nl_status nl_get_last_status(void) { return nl::capi::last_call.status; }

NL_API const char* nl_get_last_error_message(void) { return nl::capi::last_call.message.c_str(); }

}  // extern "C"
