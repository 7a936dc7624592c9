// What the navlink CLI tests share: the program, a scratch folder per test, and small checks.
#pragma once

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "run_program.h"
#include "shared_levels.h"

namespace nl::test {

// A fresh, empty folder under the build tree for one test. The test cases' folders are apart from those
// of the shell-command tests beside them in the work folder (samples_viewer_headless_nav_test's
// viewer_nav_test was also the viewer script case's folder for nav_test: run at once, each removed the
// other's log).
inline std::string scratch_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(SAMPLES_TEST_WORK_DIR) / "cases" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

// The shared levels; none, after saying so, when the folder is missing (a failure where CI requires them).
inline std::vector<std::filesystem::path> shared_levels_or_skip() {
    const auto levels = shared_levels();
    if (levels.empty()) {
        if (levels_required()) FAIL("no shared levels in " << levels_dir());
        MESSAGE("no shared levels in " << levels_dir() << ": skipped");
    }
    return levels;
}

// Runs `navlink ARGS...` in `dir`.
inline ProgramRun navlink(const std::vector<std::string>& args, const std::string& dir) {
    std::vector<std::string> all{NAVLINK_CLI_PATH};
    all.insert(all.end(), args.begin(), args.end());
    return run_program(all, dir);
}

inline nlohmann::json parse_json_file(const std::string& path) {
    const std::string text = read_file(path);
    INFO(path);
    REQUIRE(!text.empty());
    return nlohmann::json::parse(text);
}

// True if `path` is a PNG whose header says `width` x `height` (height 0: any).
inline bool is_png(const std::string& path, uint32_t width, uint32_t height = 0) {
    const std::string bytes = read_file(path);
    if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return false;
    auto be32 = [&bytes](size_t at) {
        return (uint32_t(uint8_t(bytes[at])) << 24) | (uint32_t(uint8_t(bytes[at + 1])) << 16) |
               (uint32_t(uint8_t(bytes[at + 2])) << 8) | uint32_t(uint8_t(bytes[at + 3]));
    };
    return be32(16) == width && (height == 0 ? be32(20) > 0 : be32(20) == height);
}

// Counts the links of each kind in a links JSON document.
struct KindCounts {
    size_t jump = 0, drop = 0, other = 0;
};
inline KindCounts count_kinds(const nlohmann::json& links_file) {
    KindCounts c;
    for (const auto& l : links_file.at("links")) {
        const std::string kind = l.at("kind").is_string() ? l.at("kind").get<std::string>() : "plugin";
        (kind == "jump" ? c.jump : kind == "drop" ? c.drop : c.other)++;
    }
    return c;
}

// The line of `agent` in navlink simulate's table: outcome, seconds, metres to its destination, the
// links it took, and the seconds it waited at take-offs (0 when the line says none).
struct SimulatedArrival {
    std::string outcome;
    double seconds = 0, to_goal = 0;
    std::string links;
    double waited = 0;
};

inline SimulatedArrival simulated_arrival(const std::string& out, const std::string& agent) {
    std::smatch m;
    REQUIRE_MESSAGE(
        std::regex_search(
            out, m,
            std::regex(
                "\n" + agent +
                R"( +\| (arrived|on its way|failed: [a-z ]+?) +([0-9.]+) s +\([^)]*\) +([0-9.]+) m +[0-9.]+ m  (.*), \d+ replans(, waited ([0-9.]+) s)?)")),
        out);
    return {m[1], std::stod(m[2]), std::stod(m[3]), m[4], m[6].matched ? std::stod(m[6]) : 0.0};
}

}  // namespace nl::test
