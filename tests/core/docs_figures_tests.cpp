// The figures the documentation states that are constants of the code, or that a run measures: each
// sentence is found in its file (line breaks read as spaces) and its number compared with the
// constant or the measurement, so the docs cannot fall behind a change of the code, nor the code
// behind the docs.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>

#include "core_world.h"
#include "navmesh/navmesh.h"
#include "navmesh/random_points.h"
#include "path/polygon_astar.h"
#include "path/reachability.h"
#include "util/handle_tag.h"

namespace {

// A file's text with every run of whitespace and comment leaders ("*", "//") read as one space.
std::string flowing_text(const std::string& path) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = std::regex_replace(buffer.str(), std::regex(R"(\s*\n\s*(\*(?!/)|//)?\s*)"), " ");
    return std::regex_replace(text, std::regex(R"([ \t]+)"), " ");
}

// The number the pattern's first group captures in `file` (under the repository), which must occur.
double stated(const std::string& file, const std::string& pattern) {
    const std::string text = flowing_text(std::string(NAVLINK_SOURCE_DIR) + "/" + file);
    std::smatch match;
    INFO(file << ": " << pattern);
    REQUIRE(std::regex_search(text, match, std::regex(pattern)));
    return std::stod(match[1].str());
}

}  // namespace

TEST_CASE("the figures the documentation states are the code's") {
    CHECK(stated("docs/pathfinding.md", R"(cancellation is checked every (\d+) expansions)") ==
          nl::kCancelCheckExpansions);
    CHECK(stated("docs/architecture.md", R"(at most (\d+) at once)") == nl::HandleTag::kCount);
    CHECK(stated("docs/queries.md", R"(When links join more than (\d+) islands)") ==
          nl::ReachabilityMap::kMaxClosureIslands);
    const double closure_mib = double(nl::ReachabilityMap::kMaxClosureIslands) *
                               nl::ReachabilityMap::kMaxClosureIslands / 8.0 / (1024.0 * 1024.0);
    CHECK(stated("docs/queries.md", R"(the closure would pass (\d+) MiB)") == closure_mib);
    CHECK(stated("sdk/path/reachability.h", R"(kMaxClosureIslands\^2 bits \((\d+) MiB\))") == closure_mib);
    CHECK(stated("capi/include/navlink/queries.h", R"(so thin that (\d+) tries per point)") == nl::kTriesPerPoint);
    CHECK(stated("capi/include/navlink/navmesh.h", R"(may have at most (\d+) detail vertices)") ==
          nl::kMaxDetailVertices);
    CHECK(stated("capi/include/navlink/navmesh.h", R"(besides its corners, and (\d+) detail triangles)") ==
          nl::kMaxDetailTriangles);
}

// pathfinding.md states how far a generated jump's recorded gap (rim to rim) reads from the gap as
// built: measured here over platforms 1 to 4 m apart, the gap of the jump straightest across each.
TEST_CASE("a generated jump's gap reads as much narrower than built as pathfinding.md says") {
    const float gaps[] = {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.5f};
    nl::levelgen::GeneratedLevel level;
    for (size_t row = 0; row < std::size(gaps); ++row) {
        const float z = 12.0f * float(row);
        level.add_box({{0, -1, z}, {10, 0, z + 6}});
        level.add_box({{10 + gaps[row], -1, z}, {20 + gaps[row], 0, z + 6}});
    }
    level.add_box({{-5, -41, -5}, {30, -40, 12.0f * float(std::size(gaps))}});  // a pit floor beyond any drop
    nl::test::RecastWorld r = nl::test::recast_world(level, 2);
    r.world->generate_links(r.navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
    double least_short = 1e9, most_short = -1e9;
    for (size_t row = 0; row < std::size(gaps); ++row) {
        const float z = 12.0f * float(row);
        float straightest = INFINITY;
        for (const nl::StoredLink& l : nl::test::links_of(*r.world, r.navmesh))
            if (l.link.kind == nl::LinkKind::Jump && l.link.start.z() > z && l.link.start.z() < z + 6)
                straightest = std::min(straightest, l.link.requirements.gap);
        INFO("gap built " << gaps[row] << " m");
        REQUIRE(std::isfinite(straightest));
        MESSAGE("built " << gaps[row] << " m, recorded " << straightest << " m");
        least_short = std::min(least_short, double(gaps[row] - straightest));
        most_short = std::max(most_short, double(gaps[row] - straightest));
    }
    const double stated_least =
        stated("docs/pathfinding.md", R"(a gap reads ([\d.]+) to [\d.]+ cm narrower than built)") / 100.0;
    const double stated_most =
        stated("docs/pathfinding.md", R"(a gap reads [\d.]+ to ([\d.]+) cm narrower than built)") / 100.0;
    CHECK(least_short >= stated_least - 1e-3);
    CHECK(most_short <= stated_most + 1e-3);
}
