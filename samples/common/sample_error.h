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

// The calling thread's last NavLink error message without the name of the function that failed
// ("nl_mesh_add_obj_file: level.obj:4: ..." reads "level.obj:4: ..."): the samples' user called a
// command, not that function.
inline std::string last_error_for_user() {
    std::string message = nl_get_last_error_message();
    if (message.rfind("nl_", 0) == 0) {
        const size_t end = message.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_");
        if (end != std::string::npos && message.compare(end, 2, ": ") == 0) message.erase(0, end + 2);
    }
    return message;
}

// Throws SampleError("<what>: <the calling thread's last NavLink error message>") if `status` failed.
inline void check(nl_status status, const std::string& what) {
    if (NL_FAILED(status)) throw SampleError(what + ": " + last_error_for_user());
}

}  // namespace nl::samples
