#include "route_text.h"

#include <cstdio>

namespace nl::cli {

std::string route_text(const samples::PlannedPath& path) {
    if (path.points.size() < 2) return "-";
    std::string out;
    float walked = 0.0f;
    auto leg = [&out](const char* kind, float length) {
        char text[48];
        std::snprintf(text, sizeof text, "%s%s %.1f", out.empty() ? "" : ", ", kind, length);
        out += text;
    };
    for (const samples::PathSegment& s : samples::path_segments(path)) {
        if (s.kind == NL_SEGMENT_WALK) {
            walked += s.length;
            continue;
        }
        if (walked > 0.0f) leg("walk", walked);
        walked = 0.0f;
        leg(samples::segment_name(s.kind), s.length);
    }
    if (walked > 0.0f) leg("walk", walked);
    return out;
}

}  // namespace nl::cli
