// The figures the documentation states that are constants of the code: each sentence is found in
// its file (line breaks read as spaces) and its number compared with the constant, so the docs
// cannot fall behind a change of the code, nor the code behind the docs.
#include <doctest/doctest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "navmesh/navmesh.h"
#include "navmesh/random_points.h"
#include "path/corridor_search.h"
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
    CHECK(stated("docs/pathfinding.md", R"(cancellation is checked every (\d+) expansions)") == nl::kCancelCheckExpansions);
    CHECK(stated("docs/architecture.md", R"(at most (\d+) at once)") == nl::HandleTag::kCount);
    CHECK(stated("docs/queries.md", R"(When links join more than (\d+) islands)") == nl::ReachabilityMap::kMaxClosureIslands);
    const double closure_mib = double(nl::ReachabilityMap::kMaxClosureIslands) * nl::ReachabilityMap::kMaxClosureIslands / 8.0 /
                               (1024.0 * 1024.0);
    CHECK(stated("docs/queries.md", R"(the closure would pass (\d+) MiB)") == closure_mib);
    CHECK(stated("sdk/path/reachability.h", R"(kMaxClosureIslands\^2 bits \((\d+) MiB\))") == closure_mib);
    CHECK(stated("capi/include/navlink/navlink.h", R"(so thin that (\d+) tries per point)") == nl::kTriesPerPoint);
    CHECK(stated("capi/include/navlink/navlink.h", R"(may have at most (\d+) detail vertices)") == nl::kMaxDetailVertices);
    CHECK(stated("capi/include/navlink/navlink.h", R"(besides its corners, and (\d+) detail triangles)") ==
          nl::kMaxDetailTriangles);
}
