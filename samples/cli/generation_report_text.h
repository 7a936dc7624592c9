// The generation report as text: links by kind, rejections by reason, time per stage.
#pragma once

#include <navlink/navlink.h>

#include <cstdio>
#include <vector>

namespace nl::cli {

struct GenerationTimes {
    double load_ms = 0;     // reading and registering the level
    double navmesh_ms = 0;  // building (or adding) the navmesh
};

void print_generation_report(std::FILE* out, const nl_link_generation_report& report, const std::vector<nl_link>& links,
                             const GenerationTimes& times);

}  // namespace nl::cli
