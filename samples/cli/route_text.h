// A path as one line of its legs, consecutive walking merged: "walk 5.6, jump 3.3, walk 36.4".
#pragma once

#include <string>

#include "path_plan.h"

namespace nl::cli {

std::string route_text(const samples::PlannedPath& path);

}  // namespace nl::cli
