// The samples' one kind of failure: a single line for stderr (a bad argument, a missing file, bad
// JSON, or a NavLink call that failed, with the library's own message). Programs catch it in main
// and exit with status 2.
#pragma once

#include <navlink/navlink.h>

#include <stdexcept>
#include <string>

namespace nl::samples {

class SampleError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws SampleError("<what>: <the calling thread's last NavLink error message>") if `status` failed.
inline void check(nl_status status, const std::string& what) {
    if (NL_FAILED(status)) throw SampleError(what + ": " + nl_get_last_error_message());
}

}  // namespace nl::samples
