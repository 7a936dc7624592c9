// Where the shared OBJ levels are, and whether tests may skip when they are missing.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace nl::test {

inline std::filesystem::path levels_dir() {
    if (const char* env = std::getenv("NAVLINK_LEVELS_DIR")) return env;
    return NAVLINK_LEVELS_DIR;  // compile definition from CMake
}

// The shared levels present on this machine. CI sets NAVLINK_REQUIRE_LEVELS=1 so that a missing
// folder fails the run instead of silently testing less.
inline std::vector<std::filesystem::path> shared_levels() {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(levels_dir(), ec)) {
        if (entry.path().extension() == ".obj") out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

inline bool levels_required() {
    const char* env = std::getenv("NAVLINK_REQUIRE_LEVELS");
    return env && std::string(env) == "1";
}

}  // namespace nl::test
