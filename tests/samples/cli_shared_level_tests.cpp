// navlink generate and path on every shared level (levels nobody on this project designed): each generates,
// its links file matches its report, and paths between places known to be connected are complete.
#include <navlink/navlink.h>

#include <cmath>
#include <regex>

#include "cli_fixture.h"
#include "shared_levels.h"

using nl::test::navlink;
using nl::test::ProgramRun;
using nlohmann::json;

namespace {

std::string xyz(const float* p) {
    return std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]);
}
std::string xyz(const json& p) {
    const float v[3] = {p.at(0).get<float>(), p.at(1).get<float>(), p.at(2).get<float>()};
    return xyz(v);
}

// Two neighbouring polygons' centres of the level's navmesh, built here through the C ABI with the
// CLI's defaults: walking between them must always work.
bool neighbouring_centres(const std::string& level, float a[3], float b[3]) {
    nl_world* world = nullptr;
    REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
    nl_mesh_id mesh{};
    nl_navmesh_id navmesh{};
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    bool found = false;
    if (NL_SUCCEEDED(nl_mesh_add_obj_file(world, level.c_str(), nullptr, &mesh)) &&
        NL_SUCCEEDED(nl_navmesh_build(world, &build, &navmesh))) {
        nl_nav_polygon polygon = nl_nav_polygon_init();
        for (uint32_t p = 0; !found && NL_SUCCEEDED(nl_navmesh_get_polygon(world, navmesh, p, &polygon)); ++p) {
            for (uint32_t k = 0; k < polygon.vertex_count && !found; ++k) {
                nl_nav_polygon other = nl_nav_polygon_init();
                if (polygon.neighbours[k] == NL_NO_POLYGON ||
                    NL_FAILED(nl_navmesh_get_polygon(world, navmesh, polygon.neighbours[k], &other)))
                    continue;
                for (int i = 0; i < 3; ++i) {
                    a[i] = polygon.centre[i];
                    b[i] = other.centre[i];
                }
                found = true;
            }
        }
    }
    nl_world_destroy(world);
    return found;
}

json path_json(const std::string& dir, const std::string& level, const std::string& from, const std::string& to,
               int expected_exit) {
    const ProgramRun run = navlink({"path", level, "--links", "links.json", "--from", from, "--to", to, "--json"}, dir);
    INFO(run.err);
    CHECK(run.exit_code == expected_exit);
    return json::parse(run.out);
}

}  // namespace

TEST_CASE("navlink generate and path on every shared level") {
    const auto levels = nl::test::shared_levels_or_skip();
    if (levels.empty()) return;
    CHECK(levels.size() >= 7);
    for (const auto& level_path : levels) {
        const std::string name = level_path.stem().string();
        const std::string level = level_path.string();
        INFO(name);
        const std::string dir = nl::test::scratch_dir("shared_" + name);
        const ProgramRun generate = navlink({"generate", level, "--out", "links.json"}, dir);
        REQUIRE_MESSAGE(generate.exit_code == 0, generate.err);
        const json links = nl::test::parse_json_file(dir + "/links.json");
        std::smatch m;
        REQUIRE(std::regex_search(generate.out, m, std::regex(R"(links: (\d+) \((\d+) jump, (\d+) drop)")));
        CHECK(std::stoul(m[1]) == links.at("links").size());
        CHECK(std::stoul(m[2]) == nl::test::count_kinds(links).jump);
        CHECK(std::stoul(m[3]) == nl::test::count_kinds(links).drop);

        // Walking between neighbouring polygons.
        float a[3], b[3];
        REQUIRE(neighbouring_centres(level, a, b));
        const json walk = path_json(dir, level, xyz(a), xyz(b), 0);
        CHECK(walk.at("outcome") == "complete");

        // Baked: the file says what it holds, and a path over it is the path over the level and its
        // links file, point for point (nothing is rebuilt, and the file holds every coordinate exactly).
        const ProgramRun bake = navlink({"bake", level, "--out", "level.nlnav"}, dir);
        REQUIRE_MESSAGE(bake.exit_code == 0, bake.err);
        const ProgramRun info = navlink({"info", "level.nlnav"}, dir);
        CHECK_MESSAGE(info.exit_code == 0, info.err);
        CHECK_MESSAGE(info.out.find("links: " + std::to_string(links.at("links").size()) + " (") != std::string::npos,
                      info.out);
        CHECK_MESSAGE(info.out.find("\"builder\":\"recast\"") != std::string::npos, info.out);
        const ProgramRun baked = navlink({"path", "level.nlnav", "--from", xyz(a), "--to", xyz(b), "--json"}, dir);
        CHECK_MESSAGE(baked.exit_code == 0, baked.err);
        CHECK(json::parse(baked.out) == walk);

        // From a link's start to its end, for the default agent (it takes every default link): the
        // link itself, or a walk no longer than it. The start and goal snap to the navmesh's surface
        // (its detail height), which may lie a little above or below the link's ends: that much
        // walking is allowed on top.
        for (const auto& link : links.at("links")) {
            const json path = path_json(dir, level, xyz(link.at("start")), xyz(link.at("end")), 0);
            CHECK(path.at("outcome") == "complete");
            auto distance = [](const json& p, const json& q) {
                float sum = 0.0f;
                for (int k = 0; k < 3; ++k) sum += std::pow(p.at(k).get<float>() - q.at(k).get<float>(), 2.0f);
                return std::sqrt(sum);
            };
            const float via_link = distance(path.at("start"), link.at("start")) +
                                   distance(link.at("start"), link.at("end")) +
                                   distance(link.at("end"), path.at("goal"));
            CHECK(path.at("length").get<float>() <= via_link + 0.01f);
            break;  // one per level keeps the test quick; the generated level's tests go further
        }
    }
}
