// The core's error model: functions throw nl::Error; capi/ turns it into an nl_status and a message.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace nl {

enum class ErrorCode {
    InvalidArgument,
    InvalidHandle,
    BufferTooSmall,
    OutOfMemory,
    Cancelled,
    NotFound,
    Internal,
    Io,
    Parse,
    VersionMismatch,
};

class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::string& message, bool starts_with_field = false)
        : std::runtime_error(message), code_(code), starts_with_field_(starts_with_field) {}
    ErrorCode code() const noexcept { return code_; }
    // True when the message starts with the path of the input field it is about ("vertices[7].x is
    // not finite"): the core names fields in its own terms, and a caller that knows the input by
    // another name (the C layer's "def->") puts that name in front (naming_fields).
    bool starts_with_field() const noexcept { return starts_with_field_; }

private:
    ErrorCode code_;
    bool starts_with_field_;
};

// Concatenates anything streamable; keeps error sites to one readable line.
template <typename... Parts>
std::string concat(Parts&&... parts) {
    std::ostringstream out;
    (out << ... << std::forward<Parts>(parts));
    return out.str();
}

template <typename... Parts>
[[noreturn]] void fail(ErrorCode code, Parts&&... parts) {
    throw Error(code, concat(std::forward<Parts>(parts)...));
}

// A failure about one field of the input being read; the message must start with the field's path
// ("vertices[", i, "].x is not finite").
template <typename... Parts>
[[noreturn]] void fail_field(ErrorCode code, Parts&&... parts) {
    throw Error(code, concat(std::forward<Parts>(parts)...), true);
}

// Runs fn; a failure about a field of its input gets `owner` in front of the field's path ("def->",
// "settings."), and is still about a field (owners nest).
template <typename Fn>
decltype(auto) naming_fields(const char* owner, Fn&& fn) {
    try {
        return fn();
    } catch (const Error& e) {
        if (!e.starts_with_field()) throw;
        throw Error(e.code(), concat(owner, e.what()), true);
    }
}

}  // namespace nl
