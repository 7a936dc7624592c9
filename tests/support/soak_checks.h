// What the soak programs (tests/stress) share: a failure count that prints the first twenty, a status
// check that allows only the failures a call's documentation names, and a thread's progress and the
// watchdog that reads it.
#pragma once

#include <navlink/navlink.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <thread>
#include <vector>

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

// Watches `workers` until `stop` is set. One whose steps stay the same for `stall` seconds is a hang:
// it is named with what it was doing, and the process aborts, so the sanitizer or a debugger shows
// every thread instead of the test's timeout showing none.
inline void watch_workers(const char* program, const std::atomic<bool>& stop, const std::vector<SoakWorker*>& workers,
                          double stall) {
    using Clock = std::chrono::steady_clock;
    std::vector<uint64_t> last(workers.size());
    std::vector<Clock::time_point> moved(workers.size(), Clock::now());
    while (!stop) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        for (size_t k = 0; k < workers.size(); ++k) {
            const uint64_t now_steps = workers[k]->steps;
            if (now_steps != last[k]) last[k] = now_steps, moved[k] = Clock::now();
            if (std::chrono::duration<double>(Clock::now() - moved[k]).count() > stall) {
                std::fprintf(stderr, "%s: %s made no progress for %.0f s, in %s\n", program, workers[k]->name, stall,
                             workers[k]->doing.load());
                std::fflush(stderr);
                std::abort();
            }
        }
    }
}

}  // namespace nl::test
