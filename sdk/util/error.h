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
    Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const noexcept { return code_; }

private:
    ErrorCode code_;
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

}  // namespace nl
