// The bake report as text: links by kind, rejections by reason, time per stage.
#pragma once

#include <navlink/navlink.h>

#include <cstdio>
#include <vector>

namespace nl::cli {

struct BakeTimes {
    double load_ms = 0;     // reading and registering the level
    double navmesh_ms = 0;  // building (or adding) the navmesh
};

void print_bake_report(std::FILE* out, const nl_bake_report& report, const std::vector<nl_link>& links,
                       const BakeTimes& times);

}  // namespace nl::cli
