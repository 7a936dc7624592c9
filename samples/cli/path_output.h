// A planned path printed for people (a table of segments) or for programs (a JSON object). Links are
// named by their index in the navmesh's link list, which is their index in the LINKS.json file they
// were loaded from ("links"[i]): ids are only meaningful inside one run.
#pragma once

#include <navlink/navlink.h>

#include <cstdio>
#include <string>
#include <vector>

#include "path_plan.h"

namespace nl::cli {

// The index of `link` in `links`, or -1.
long link_index(const std::vector<nl_link>& links, nl_link_id link);

void print_path_text(std::FILE* out, const samples::PlannedPath& path, const std::vector<nl_link>& links);

std::string path_json(const samples::PlannedPath& path, const std::vector<nl_link>& links);

}  // namespace nl::cli
