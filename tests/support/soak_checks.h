// What the soak programs (tests/stress) share: a failure count that prints the first twenty, a status
// check that allows only the failures a call's documentation names, and a thread's progress for the
// watchdog.
#pragma once

#include <navlink/navlink.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>

namespace nl::test {

class SoakFailures {
public:
    explicit SoakFailures(const char* program) : program_(program) {}
    void fail(const std::string& what) {
        if (count_.fetch_add(1) < 20) std::fprintf(stderr, "%s: %s\n", program_, what.c_str());
    }
    // A failure outside `allowed` (successes are always allowed, with their detail bits, as a partial
    // path's) is one, naming the call; false for any failure.
    bool expect(nl_status status, const char* call, std::initializer_list<nl_status> allowed = {}) {
        if (!NL_FAILED(status)) return true;
        for (nl_status a : allowed)
            if (status == (NL_STATUS_FAILURE | a)) return false;
        fail(std::string(call) + " returned " + nl_status_string(status) + ": " + nl_get_last_error_message());
        return false;
    }
    int count() const { return count_.load(); }

private:
    const char* program_;
    std::atomic<int> count_{0};
};

// What a soak thread has done; the watchdog reads `steps` to see that it still moves.
struct SoakWorker {
    const char* name;
    std::atomic<uint64_t> steps{0};
    std::atomic<const char*> doing{"starting"};
};

}  // namespace nl::test
