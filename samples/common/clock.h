// Wall-clock timing for the samples and benchmarks.
#pragma once

#include <chrono>

namespace nl::samples {

inline double now_ms() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace nl::samples
