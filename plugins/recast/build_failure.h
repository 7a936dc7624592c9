// How the builder's steps report a failure: an nl_status and the message the host makes the caller's
// last error. Thrown inside the plugin only; build() turns it into its return value.
#pragma once

#include <exception>
#include <sstream>
#include <string>
#include <utility>

#include "navlink/navlink.h"

namespace nl::recast {

class BuildFailure : public std::exception {
public:
    BuildFailure(nl_status detail, std::string message)
        : status_(NL_STATUS_FAILURE | detail), message_(std::move(message)) {}
    nl_status status() const noexcept { return status_; }
    const char* what() const noexcept override { return message_.c_str(); }

private:
    nl_status status_;
    std::string message_;
};

// Throws a BuildFailure with `detail` (an NL_STATUS_* detail bit) and the parts streamed together.
template <typename... Parts>
[[noreturn]] void fail(nl_status detail, Parts&&... parts) {
    std::ostringstream out;
    (out << ... << std::forward<Parts>(parts));
    throw BuildFailure(detail, out.str());
}

}  // namespace nl::recast
