#include "util/shortest_decimal.h"

#include <cstdio>
#include <cstdlib>

namespace nl {

double shortest_decimal(float v) {
    char text[32];
    for (int digits = 6; digits < 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(v));
        if (std::strtof(text, nullptr) == v) return std::strtod(text, nullptr);
    }
    std::snprintf(text, sizeof text, "%.9g", double(v));
    return std::strtod(text, nullptr);
}

}  // namespace nl
