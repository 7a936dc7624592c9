// What a benchmark reports of its timed repeats: the median, robust to the bursts of other work on a
// shared machine, and the fastest and slowest, which show how much of that there was.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace nl::bench {

// The middle value (the mean of the two middle ones for an even count); NaN for none.
inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n == 0 ? std::nan("") : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Spread {
    double min = std::nan(""), median = std::nan(""), max = std::nan("");
};

inline Spread spread(const std::vector<double>& values) {
    Spread s;
    if (values.empty()) return s;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    s.min = *lo;
    s.median = median(values);
    s.max = *hi;
    return s;
}

}  // namespace nl::bench
