// Where the core's messages go: the host's log callback, behind a sink the C layer sets up.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "util/error.h"

namespace nl {

enum class LogLevel : uint32_t { Error = 0, Warning = 1, Info = 2, Debug = 3 };

class Logger {
public:
    // `failure`: the code of the failure a message reports, if it reports one.
    using Sink = std::function<void(LogLevel level, std::optional<ErrorCode> failure, const std::string& message)>;

    Logger() = default;
    Logger(Sink sink, LogLevel most_verbose) : sink_(std::move(sink)), most_verbose_(most_verbose) {}

    bool wants(LogLevel level) const noexcept { return sink_ && level <= most_verbose_; }
    // Never throws: a failing sink loses the message, not the call that logs it.
    void log(LogLevel level, const std::string& message,
             std::optional<ErrorCode> failure = std::nullopt) const noexcept {
        if (!wants(level)) return;
        try {
            sink_(level, failure, message);
        } catch (...) {}
    }

private:
    Sink sink_;
    LogLevel most_verbose_ = LogLevel::Warning;
};

}  // namespace nl
