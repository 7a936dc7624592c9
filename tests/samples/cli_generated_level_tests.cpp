// navlink level, generate, path and demo on the generated default level: exit statuses, the links file,
// the JSON path, and links where the level's features put them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

#include "cli_fixture.h"
#include "level_generator.h"

using nl::test::navlink;
using nl::test::ProgramRun;
using nl::test::SimulatedArrival;
using nl::test::simulated_arrival;
using nlohmann::json;

namespace {

struct GeneratedLevelFiles {
    std::string dir;
    nl::levelgen::GeneratedLevel level = nl::levelgen::generate_default_level(1);
    GeneratedLevelFiles(const std::string& name) : dir(nl::test::scratch_dir(name)) {
        const ProgramRun run = navlink({"level", "--out", "level.obj"}, dir);
        REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    }
};

float x_of(const json& point) { return point.at(0).get<float>(); }
float z_of(const json& point) { return point.at(2).get<float>(); }

// Jump links whose ends lie on either side of the gap between boxes a and a + 1 (along x).
std::vector<json> jumps_across(const json& links, const nl::levelgen::GeneratedLevel& level, int a) {
    const float gap_start = level.boxes[a].max[0], gap_end = level.boxes[a + 1].min[0];
    std::vector<json> out;
    for (const auto& l : links.at("links")) {
        if (l.at("kind") != "jump") continue;
        const float x0 = std::min(x_of(l.at("start")), x_of(l.at("end")));
        const float x1 = std::max(x_of(l.at("start")), x_of(l.at("end")));
        if (x0 < gap_start && x1 > gap_end && z_of(l.at("start")) > 0.0f && z_of(l.at("end")) > 0.0f) out.push_back(l);
    }
    return out;
}

void write_agent(const std::string& path, const char* json_text) { nl::test::write_file(path, json_text); }

}  // namespace

TEST_CASE("navlink level writes the generated level as OBJ, with its markers") {
    GeneratedLevelFiles files("level");
    const std::string obj = nl::test::read_file(files.dir + "/level.obj");
    size_t faces = 0;
    for (size_t at = obj.find("\nf "); at != std::string::npos; at = obj.find("\nf ", at + 1)) ++faces;
    CHECK(faces == files.level.triangle_count());
    const ProgramRun again = navlink({"level", "--out", "again.obj", "--seed", "1"}, files.dir);
    CHECK(again.out.find("start: 2.00,0.00,3.00") != std::string::npos);
    CHECK(nl::test::read_file(files.dir + "/again.obj") == obj);  // a seed makes the same level
    CHECK(navlink({"level", "--out", "other.obj", "--seed", "7"}, files.dir).exit_code == 0);
    CHECK(nl::test::read_file(files.dir + "/other.obj") != obj);  // another seed, another level
}

TEST_CASE(
    "navlink generate on the generated level: links file, report and picture agree, links are where the level says") {
    GeneratedLevelFiles files("generate");
    const ProgramRun run = navlink({"generate", "level.obj", "--out", "links.json", "--png", "view.png"}, files.dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    CHECK(run.err.empty());
    const json links = nl::test::parse_json_file(files.dir + "/links.json");
    CHECK(links.at("format") == "navlink-links");
    CHECK(links.at("version") == 1);
    const auto counts = nl::test::count_kinds(links);
    CHECK(counts.jump > 0);
    CHECK(counts.drop > 0);
    CHECK(counts.other == 0);
    // The report counts what the file holds.
    std::smatch m;
    REQUIRE(std::regex_search(run.out, m, std::regex(R"(links: (\d+) \((\d+) jump, (\d+) drop)")));
    CHECK(std::stoul(m[1]) == links.at("links").size());
    CHECK(std::stoul(m[2]) == counts.jump);
    CHECK(std::stoul(m[3]) == counts.drop);
    for (const char* line : {"rejected:", "body touches the level", "walking is about as short", "drop too deep",
                             "time (ms):", "navmesh", "links total", "exact body tests"})
        CHECK_MESSAGE(run.out.find(line) != std::string::npos, line);
    CHECK(nl::test::is_png(files.dir + "/view.png", 1600));

    // Jumps across the first gap, but not under its low ceiling (z 4 to 6); across the second gap
    // (2.8 to 3.2 m, rim to rim, within the default 4 m) but not past its wall (z 0 to 2); one-way
    // drops from the third platform to the fourth.
    const auto first = jumps_across(links, files.level, 0);
    CHECK(first.size() >= 3);
    for (const auto& l : first) {
        CHECK(z_of(l.at("start")) < 4.0f);
        CHECK(z_of(l.at("end")) < 4.0f);
        CHECK(l.at("bidirectional") == true);
    }
    const auto second = jumps_across(links, files.level, 1);
    CHECK(!second.empty());
    for (const auto& l : second) {
        CHECK(z_of(l.at("start")) > 2.0f);
        CHECK(z_of(l.at("end")) > 2.0f);
        const float gap = l.at("requires").at("gap").get<float>();
        CHECK(gap >= 2.75f);
        CHECK(gap <= 3.25f);
    }
    size_t onto_last = 0;
    const auto& p2 = files.level.boxes[2];
    const auto& p3 = files.level.boxes[3];
    for (const auto& l : links.at("links")) {
        if (l.at("kind") != "drop") continue;
        const bool from_p2 =
            x_of(l.at("start")) < p2.max[0] && std::fabs(l.at("start").at(1).get<float>() - p2.max[1]) < 0.5f;
        const bool onto_p3 =
            x_of(l.at("end")) > p3.min[0] && std::fabs(l.at("end").at(1).get<float>() - p3.max[1]) < 0.5f;
        if (from_p2 && onto_p3) {
            ++onto_last;
            CHECK(l.at("bidirectional") == false);  // 2 m and more: too high to jump back up
        }
    }
    CHECK(onto_last >= 3);
}

TEST_CASE("navlink generate reads settings and agent files: shorter links leave the second gap unjumped") {
    GeneratedLevelFiles files("generate_settings");
    nl::test::write_file(files.dir + "/short.json", R"({"max_jump_gap": 2.5, "recast": {"cell_size": 0.25}})");
    const ProgramRun run =
        navlink({"generate", "level.obj", "--settings", "short.json", "--out", "links.json"}, files.dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const json links = nl::test::parse_json_file(files.dir + "/links.json");
    CHECK(!jumps_across(links, files.level, 0).empty());  // 1.4 to 1.8 m
    CHECK(jumps_across(links, files.level, 1).empty());   // 2.8 to 3.2 m

    // A thinner body: its navmesh reaches closer to the rims, so the same gap is a shorter jump end to
    // end (the gap itself, rim to rim, is the same).
    write_agent(files.dir + "/thin.json", R"({"name": "thin", "radius": 0.3})");
    REQUIRE(
        navlink({"generate", "level.obj", "--agent", "thin.json", "--out", "thin.json.links"}, files.dir).exit_code ==
        0);
    REQUIRE(navlink({"generate", "level.obj", "--out", "default.links"}, files.dir).exit_code == 0);
    auto shortest = [&](const std::string& file, const char* what) {
        float best = 1e9f;
        for (const auto& l : jumps_across(nl::test::parse_json_file(files.dir + "/" + file), files.level, 0))
            best = std::min(best, l.at("requires").at(what).get<float>());
        return best;
    };
    CHECK(shortest("thin.json.links", "length") < shortest("default.links", "length") - 0.3f);
    CHECK(shortest("thin.json.links", "gap") == doctest::Approx(shortest("default.links", "gap")).epsilon(0.03));
}

TEST_CASE("navlink generate and path with a navmesh handed over as OBJ (--navmesh)") {
    GeneratedLevelFiles files("host_navmesh");
    // The host's navmesh: one quad on each of the first two platforms, 0.6 m inside their rims, as an
    // engine would export it (Y up, counter-clockwise seen from above).
    std::string obj;
    for (int b = 0; b < 2; ++b) {
        const auto& box = files.level.boxes[b];
        const float x0 = box.min[0] + 0.6f, x1 = box.max[0] - 0.6f, z0 = box.min[2] + 0.6f, z1 = box.max[2] - 0.6f;
        const float y = box.max[1];
        for (const auto& [x, z] : {std::pair{x0, z0}, std::pair{x0, z1}, std::pair{x1, z1}, std::pair{x1, z0}})
            obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
    obj += "f 1 2 3 4\nf 5 6 7 8\n";
    nl::test::write_file(files.dir + "/nav.obj", obj);
    const ProgramRun generate =
        navlink({"generate", "level.obj", "--navmesh", "nav.obj", "--out", "links.json"}, files.dir);
    REQUIRE_MESSAGE(generate.exit_code == 0, generate.err);
    CHECK(generate.out.find("navmesh: 2 polygons, 8 boundary edges (nav.obj)") != std::string::npos);
    const json links = nl::test::parse_json_file(files.dir + "/links.json");
    CHECK(!jumps_across(links, files.level, 0).empty());

    // From one quad to the other: the only way is a jump.
    const auto& p0 = files.level.boxes[0];
    const auto& p1 = files.level.boxes[1];
    const std::string from = std::to_string(p0.min[0] + 2.0f) + ",0,2", to = std::to_string(p1.max[0] - 2.0f) + ",0,2";
    const ProgramRun path = navlink(
        {"path", "level.obj", "--navmesh", "nav.obj", "--links", "links.json", "--from", from, "--to", to, "--json"},
        files.dir);
    REQUIRE_MESSAGE(path.exit_code == 0, path.err);
    const json result = json::parse(path.out);
    CHECK(result.at("outcome") == "complete");
    CHECK(result.at("links_used") == 1);
}

TEST_CASE("navlink path --json: each demo agent's route is complete, continuous and within its body's reach") {
    GeneratedLevelFiles files("path");
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json"}, files.dir).exit_code == 0);
    const json links = nl::test::parse_json_file(files.dir + "/links.json").at("links");
    write_agent(files.dir + "/walker.json",
                R"({"name": "walker", "max_jump_distance": 0, "max_jump_height": 0, "max_drop_height": 0})");
    write_agent(files.dir + "/short.json",
                R"({"max_jump_distance": 2.0, "max_jump_height": 1.0, "max_drop_height": 0})");
    write_agent(files.dir + "/long.json",
                R"({"max_jump_distance": 3.5, "max_jump_height": 1.5, "max_drop_height": 4})");
    const std::string from = "2,0,3", to = "33.91,-1.03,3.5";  // the level's start and goal markers

    std::map<std::string, json> paths;
    for (const std::string agent : {"walker", "short", "long"}) {
        INFO(agent);
        const ProgramRun run = navlink({"path", "level.obj", "--links", "links.json", "--from", from, "--to", to,
                                        "--agent", agent + ".json", "--json"},
                                       files.dir);
        REQUIRE_MESSAGE(run.exit_code == 0, run.err);
        const json path = json::parse(run.out);
        CHECK(path.at("outcome") == "complete");
        const auto& segments = path.at("segments");
        REQUIRE(!segments.empty());
        CHECK(segments.size() + 1 == path.at("points").size());
        float sum = 0.0f;
        for (size_t i = 0; i < segments.size(); ++i) {
            const auto& s = segments[i];
            sum += s.at("length").get<float>();
            if (i > 0) CHECK(s.at("from") == segments[i - 1].at("to"));  // no holes between segments
            if (s.at("kind") == "walk") continue;
            const long index = s.at("link").get<long>();
            REQUIRE(index >= 0);
            REQUIRE(index < static_cast<long>(links.size()));
            const json& link = links[static_cast<size_t>(index)];
            // A drop climbed back up is travelled as a jump; otherwise the segment is the link's kind.
            CHECK((s.at("kind") == link.at("kind") || (s.at("kind") == "jump" && s.at("reversed") == true)));
        }
        CHECK(sum == doctest::Approx(path.at("straight_length").get<float>()).epsilon(0.01));
        // Walked along the surface: over slopes and steps, longer than straight between the points.
        CHECK(path.at("length").get<float>() >= path.at("straight_length").get<float>() - 1e-3f);
        CHECK(segments.front().at("from").at(0).get<float>() == doctest::Approx(2.0f).epsilon(0.05));
        paths[agent] = path;
    }
    auto segments_of = [&](const std::string& agent, const char* kind) {
        std::vector<json> out;
        for (const auto& s : paths[agent].at("segments"))
            if (s.at("kind") == kind) out.push_back(s);
        return out;
    };
    CHECK(paths["walker"].at("links_used") == 0);
    CHECK(segments_of("short", "drop").empty());
    CHECK(!segments_of("short", "jump").empty());
    for (const auto& s : segments_of("short", "jump"))
        CHECK(links[s.at("link").get<size_t>()].at("requires").at("gap").get<float>() <= 2.0f);
    CHECK(!segments_of("long", "drop").empty());
    bool long_jump = false;
    for (const auto& s : segments_of("long", "jump"))
        long_jump = long_jump || links[s.at("link").get<size_t>()].at("requires").at("gap").get<float>() > 2.0f;
    CHECK(long_jump);  // a jump the short jumper could not make
    CHECK(paths["walker"].at("length").get<float>() > paths["short"].at("length").get<float>());
    CHECK(paths["short"].at("length").get<float>() > paths["long"].at("length").get<float>());

    // The text form says the same, and names the links taken.
    const ProgramRun text = navlink({"path", "level.obj", "--links", "links.json", "--from", from, "--to", to,
                                     "--agent", "long.json", "--png", "path.png"},
                                    files.dir);
    CHECK(text.exit_code == 0);
    CHECK(text.out.find("path: complete") != std::string::npos);
    CHECK(text.out.find("drop   #") != std::string::npos);
    CHECK(nl::test::is_png(files.dir + "/path.png", 1600));
}

TEST_CASE("navlink path exits 1 when the goal cannot be reached, and says why") {
    GeneratedLevelFiles files("path_unreachable");
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json"}, files.dir).exit_code == 0);
    nl::test::write_file(files.dir + "/walker.json",
                         R"({"max_jump_distance": 0, "max_drop_height": 0, "max_jump_height": 0})");
    // The third platform: reached only by the long jump, so a walker gets as near as it can.
    const auto& p2 = files.level.boxes[2];
    const std::string on_p2 = std::to_string(0.5f * (p2.min[0] + p2.max[0])) + "," + std::to_string(p2.max[1]) + ",3";
    ProgramRun run = navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", on_p2, "--agent",
                              "walker.json", "--json"},
                             files.dir);
    CHECK(run.exit_code == 1);
    const json partial = json::parse(run.out);
    CHECK(partial.at("outcome") == "partial");
    // It says how far from the goal it ends: the distance from its last point to --to.
    const json& last = partial.at("points").back().at("position");
    const json& to = partial.at("to");
    float squared = 0.0f;
    for (size_t k = 0; k < 3; ++k) squared += std::pow(last[k].get<float>() - to[k].get<float>(), 2.0f);
    CHECK(partial.at("ends_from_goal").get<float>() == doctest::Approx(std::sqrt(squared)).epsilon(1e-4));
    CHECK(partial.at("ends_from_goal").get<float>() > 1.0f);
    run = navlink(
        {"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", on_p2, "--agent", "walker.json"},
        files.dir);
    CHECK(run.out.find("partial: it ends ") != std::string::npos);
    CHECK(run.out.find("arrive") == std::string::npos);

    // A goal off the navmesh: where the navmesh is nearest, and that point is on it.
    run = navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", "500,0,500", "--json"},
                  files.dir);
    CHECK(run.exit_code == 1);
    const json off = json::parse(run.out);
    CHECK(off.at("outcome") == "goal off navmesh");
    const json& nearest = off.at("nearest_goal");
    REQUIRE(nearest.is_object());
    CHECK(nearest.at("distance").get<float>() > 400.0f);
    const json& p = nearest.at("point");
    const std::string on_navmesh = std::to_string(p[0].get<float>()) + "," + std::to_string(p[1].get<float>()) + "," +
                                   std::to_string(p[2].get<float>());
    run = navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", on_navmesh, "--json"},
                  files.dir);
    CHECK(json::parse(run.out).at("outcome") != "goal off navmesh");
    run = navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", "500,0,500"}, files.dir);
    CHECK(run.out.find("the goal (500.00, 0.00, 500.00) is off the navmesh: the nearest navmesh point is") !=
          std::string::npos);
    // A search box the host sets: wide enough, the same goal is found on the navmesh.
    run = navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", "500,0,500", "--search",
                   "1000,1000,1000", "--json"},
                  files.dir);
    CHECK(json::parse(run.out).at("outcome") != "goal off navmesh");
}

TEST_CASE("navlink path without --links walks the navmesh alone") {
    GeneratedLevelFiles files("path_walk_only");
    const ProgramRun run = navlink({"path", "level.obj", "--from", "2,0,3", "--to", "4,0,3", "--json"}, files.dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const json path = json::parse(run.out);
    CHECK(path.at("outcome") == "complete");
    CHECK(path.at("links_used") == 0);
}

TEST_CASE("navlink demo prints a route for each of its three agents and writes its picture and links") {
    const std::string dir = nl::test::scratch_dir("demo");
    const ProgramRun run = navlink({"demo"}, dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    std::smatch m;
    for (const char* agent : {"walker", "short jumper", "long jumper"}) {
        INFO(agent);
        REQUIRE(std::regex_search(run.out, m,
                                  std::regex(std::string("\n") + agent + R"( .*\| complete +[0-9.]+ m +(.*))")));
    }
    CHECK(std::regex_search(run.out, std::regex(R"(\nwalker .*no links +walk [0-9.]+\n)")));  // walks all the way
    CHECK(std::regex_search(run.out, std::regex(R"(\nlong jumper .*\d+ jumps?, 1 drop)")));
    CHECK(nl::test::is_png(dir + "/demo.png", 1600));
    const json links = nl::test::parse_json_file(dir + "/demo.links.json");
    CHECK(nl::test::count_kinds(links).jump > 0);
    CHECK(navlink({"demo", "--seed", "2", "--out-dir", dir, "--oblique"}, dir).exit_code == 0);  // another level
    // A folder that does not exist yet is made, parents too.
    REQUIRE(navlink({"demo", "--out-dir", "fresh/deeper"}, dir).exit_code == 0);
    CHECK(nl::test::is_png(dir + "/fresh/deeper/demo.png", 1600));
}

TEST_CASE(
    "navlink simulate: the three bodies arrive as agents, each by the links it can take, and the tracks are drawn") {
    const std::string dir = nl::test::scratch_dir("simulate");
    const ProgramRun run = navlink({"simulate"}, dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const SimulatedArrival walker = simulated_arrival(run.out, "walker");
    const SimulatedArrival short_jumper = simulated_arrival(run.out, "short jumper");
    const SimulatedArrival long_jumper = simulated_arrival(run.out, "long jumper");
    for (const SimulatedArrival* a : {&walker, &short_jumper, &long_jumper}) {
        CHECK(a->outcome == "arrived");
        CHECK(a->to_goal < 2.0);  // the goal's spot is taken by the first to arrive: the others stop beside it
    }
    CHECK(walker.links == "no links");
    CHECK(short_jumper.links == "2 jumps");
    CHECK(long_jumper.links == "2 jumps, 1 drop");
    CHECK(long_jumper.seconds < short_jumper.seconds);  // the shorter route, as navlink demo plans it
    CHECK(short_jumper.seconds < walker.seconds);
    // Each take-off is printed as it happens, with the trajectory the agent flies.
    CHECK(std::regex_search(
        run.out, std::regex(R"(\n +[0-9.]+ s  long jumper +drops +from \([^)]*\) to \([^)]*\) in [0-9.]+ s\n)")));
    CHECK(nl::test::is_png(dir + "/simulate.png", 1600));

    // Another step rate moves the agents along the same routes.
    const ProgramRun coarse = navlink({"simulate", "--hz", "30", "--out-dir", dir}, dir);
    REQUIRE_MESSAGE(coarse.exit_code == 0, coarse.err);
    CHECK(simulated_arrival(coarse.out, "long jumper").links == "2 jumps, 1 drop");
    // Too little time: nobody arrives, exit status 1.
    const ProgramRun cut = navlink({"simulate", "--seconds", "2", "--out-dir", dir}, dir);
    CHECK(cut.exit_code == 1);
    CHECK(simulated_arrival(cut.out, "walker").outcome == "on its way");
}

TEST_CASE("navlink --help and COMMAND --help describe the tool and exit 0") {
    const std::string dir = nl::test::scratch_dir("help");
    const ProgramRun main_help = navlink({"--help"}, dir);
    CHECK(main_help.exit_code == 0);
    for (const char* command : {"demo", "simulate", "generate", "path", "level"}) {
        CHECK(main_help.out.find(std::string("  ") + command) != std::string::npos);
        const ProgramRun help = navlink({command, "--help"}, dir);
        CHECK(help.exit_code == 0);
        CHECK(help.out.rfind(std::string("usage: navlink ") + command, 0) == 0);
    }
}

// The default level with every face turned over (Godot's export of it): generate builds on it and
// says it looks wound clockwise, naming --clockwise; with --clockwise it is the level as exported
// counter-clockwise, and nothing is said.
TEST_CASE("navlink generate says when a level looks wound clockwise, and --clockwise reads it so") {
    GeneratedLevelFiles files("clockwise");
    std::string obj = nl::test::read_file(files.dir + "/level.obj"), turned;
    const std::regex face(R"(^f (\S+) (\S+) (\S+)$)");
    std::istringstream lines(obj);
    for (std::string line; std::getline(lines, line);) turned += std::regex_replace(line, face, "f $1 $3 $2") + "\n";
    REQUIRE(turned != obj);
    nl::test::write_file(files.dir + "/clockwise.obj", turned);

    const ProgramRun as_given = navlink({"generate", "level.obj", "--out", "given.json"}, files.dir);
    REQUIRE_MESSAGE(as_given.exit_code == 0, as_given.err);
    CHECK(as_given.err.find("wound clockwise") == std::string::npos);

    const ProgramRun unflagged = navlink({"generate", "clockwise.obj", "--out", "unflagged.json"}, files.dir);
    REQUIRE_MESSAGE(unflagged.exit_code == 0, unflagged.err);
    CHECK(unflagged.err.find("warning: the navmesh was built on 1 mesh that looks wound clockwise") !=
          std::string::npos);
    CHECK(unflagged.err.find("pass --clockwise") != std::string::npos);

    const ProgramRun flagged =
        navlink({"generate", "clockwise.obj", "--clockwise", "--out", "flagged.json"}, files.dir);
    REQUIRE_MESSAGE(flagged.exit_code == 0, flagged.err);
    CHECK(flagged.err.find("wound clockwise") == std::string::npos);
    // Read as wound clockwise, it is the level as given: the same navmesh and links.
    CHECK(flagged.out.substr(flagged.out.find("navmesh:"), 40) ==
          as_given.out.substr(as_given.out.find("navmesh:"), 40));
    CHECK(nl::test::read_file(files.dir + "/flagged.json").size() ==
          nl::test::read_file(files.dir + "/given.json").size());
}

namespace {

// LEVEL.obj's vertices, each (x, y, z) written as `rewrite` gives it.
std::string with_vertices(const std::string& obj,
                          const std::function<std::array<double, 3>(double, double, double)>& rewrite) {
    std::istringstream lines(obj);
    std::ostringstream out;
    out << std::setprecision(10);
    for (std::string line; std::getline(lines, line);) {
        double x, y, z;
        if (line.rfind("v ", 0) == 0 && std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3) {
            const std::array<double, 3> p = rewrite(x, y, z);
            out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        } else {
            out << line << '\n';
        }
    }
    return out.str();
}

std::string navmesh_line(const ProgramRun& run) { return run.out.substr(run.out.find("navmesh:"), 40); }

}  // namespace

// The default level written in centimetres, and with z up (Blender's own frame): generate builds on
// each, warns of what it looks like and names the option; with --units cm or --up z it is the level
// in metres with y up, the same navmesh and links, and nothing is said.
TEST_CASE(
    "navlink generate says when a level looks given in centimetres or with z up, and --units and --up read it so") {
    GeneratedLevelFiles files("level_frame");
    const std::string obj = nl::test::read_file(files.dir + "/level.obj");
    nl::test::write_file(files.dir + "/cm.obj", with_vertices(obj, [](double x, double y, double z) {
                             return std::array<double, 3>{100 * x, 100 * y, 100 * z};
                         }));
    nl::test::write_file(files.dir + "/z_up.obj", with_vertices(obj, [](double x, double y, double z) {
                             return std::array<double, 3>{x, -z, y};
                         }));
    // Read as metres, the centimetre level is 4 km across: coarse cells keep its build short.
    nl::test::write_file(files.dir + "/coarse.json", R"({"recast": {"cell_size": 3.0, "cell_height": 2.0}})");

    const ProgramRun as_given = navlink({"generate", "level.obj", "--out", "given.json"}, files.dir);
    REQUIRE_MESSAGE(as_given.exit_code == 0, as_given.err);
    CHECK(as_given.err.find("warning") == std::string::npos);

    const ProgramRun cm_unsaid =
        navlink({"generate", "cm.obj", "--settings", "coarse.json", "--out", "cm_unsaid.json"}, files.dir);
    REQUIRE_MESSAGE(cm_unsaid.exit_code == 0, cm_unsaid.err);
    CHECK_MESSAGE(cm_unsaid.err.find("warning: the level's walls are ") != std::string::npos, cm_unsaid.err);
    CHECK(cm_unsaid.err.find("are its units metres?") != std::string::npos);
    CHECK(cm_unsaid.err.find("hint: if cm.obj is not in metres, pass --units") != std::string::npos);
    const ProgramRun cm = navlink({"generate", "cm.obj", "--units", "cm", "--out", "cm.json"}, files.dir);
    REQUIRE_MESSAGE(cm.exit_code == 0, cm.err);
    CHECK(cm.err.find("warning") == std::string::npos);
    CHECK(navmesh_line(cm) == navmesh_line(as_given));
    CHECK(cm.out.substr(cm.out.find("links:"), 40) == as_given.out.substr(as_given.out.find("links:"), 40));

    const ProgramRun z_unsaid = navlink({"generate", "z_up.obj", "--out", "z_unsaid.json"}, files.dir);
    REQUIRE_MESSAGE(z_unsaid.exit_code == 0, z_unsaid.err);
    CHECK_MESSAGE(z_unsaid.err.find("warning: the level looks as if z were its up axis") != std::string::npos,
                  z_unsaid.err);
    CHECK(z_unsaid.err.find("pass --up z") != std::string::npos);
    CHECK(navmesh_line(z_unsaid) != navmesh_line(as_given));
    const ProgramRun z_up = navlink({"generate", "z_up.obj", "--up", "z", "--out", "z_up.json"}, files.dir);
    REQUIRE_MESSAGE(z_up.exit_code == 0, z_up.err);
    CHECK(z_up.err.find("warning") == std::string::npos);
    CHECK(navmesh_line(z_up) == navmesh_line(as_given));
    CHECK(nl::test::read_file(files.dir + "/z_up.json").size() ==
          nl::test::read_file(files.dir + "/given.json").size());

    const ProgramRun bad_units = navlink({"generate", "cm.obj", "--units", "furlong", "--out", "bad.json"}, files.dir);
    CHECK(bad_units.exit_code != 0);
    CHECK(bad_units.err.find("--units must be m, cm, mm, km, in, ft or the metres in one unit") != std::string::npos);
    const ProgramRun bad_up = navlink({"generate", "z_up.obj", "--up", "x", "--out", "bad.json"}, files.dir);
    CHECK(bad_up.exit_code != 0);
    CHECK(bad_up.err.find("--up must be y or z, got 'x'") != std::string::npos);
}

// A platform 4.2 m above a floor with no stairs, and two rooms joined by a corridor 1.6 m wide: a
// partial path says why (the drop the body cannot take, with its depth and the link's number; no
// links loaded; a body too wide for the corridor), and a body wider than the navmesh is said to be.
TEST_CASE("navlink path says why a path falls short, and when the body is wider than the navmesh") {
    const std::string dir = nl::test::scratch_dir("path_shortfall");
    nl::levelgen::GeneratedLevel level;
    level.add_box({{-10, -1, -10}, {20, 0, 10}});
    level.add_box({{0, 0, -3}, {6, 4.2f, 3}});
    level.add_box({{30, -1, -10}, {70, 0, 10}});
    level.add_box({{49, 0, -10}, {51, 3, -0.8f}});
    level.add_box({{49, 0, 0.8f}, {51, 3, 10}});
    nl::test::write_file(dir + "/level.obj", level.to_obj());
    nl::test::write_file(dir + "/drops_4.json", R"({"max_drop_height": 4})");
    nl::test::write_file(dir + "/wide.json", R"({"radius": 1.0})");
    const ProgramRun generated = navlink({"generate", "level.obj", "--out", "links.json"}, dir);
    REQUIRE_MESSAGE(generated.exit_code == 0, generated.err);

    const ProgramRun short_drop = navlink({"path", "level.obj", "--links", "links.json", "--agent", "drops_4.json",
                                           "--from", "3,4.2,0", "--to", "15,0,0"},
                                          dir);
    CHECK(short_drop.exit_code == 1);
    CHECK_MESSAGE(short_drop.out.find("why: a drop at (") != std::string::npos, short_drop.out);
    CHECK(std::regex_search(
        short_drop.out,
        std::regex(R"(it needs a drop of 4\.[0-4]\d? m, and the body drops 4 m \(max_drop_height\) \(link #\d+;)")));
    const ProgramRun no_links =
        navlink({"path", "level.obj", "--agent", "drops_4.json", "--from", "3,4.2,0", "--to", "15,0,0"}, dir);
    CHECK_MESSAGE(
        no_links.out.find("the navmesh has no links: generate or load them (--links LINKS.json)") != std::string::npos,
        no_links.out);
    const ProgramRun json_out = navlink({"path", "level.obj", "--links", "links.json", "--agent", "drops_4.json",
                                         "--from", "3,4.2,0", "--to", "15,0,0", "--json"},
                                        dir);
    const json parsed = json::parse(json_out.out);
    CHECK(parsed.at("why").get<std::string>().find("(max_drop_height)") != std::string::npos);
    CHECK(parsed.at("why_link").get<long>() >= 0);

    // Built for the body, the navmesh leaves the corridor out, and says so.
    const ProgramRun built_wide =
        navlink({"path", "level.obj", "--agent", "wide.json", "--from", "40,0,0", "--to", "60,0,0"}, dir);
    CHECK(built_wide.exit_code == 1);
    CHECK_MESSAGE(built_wide.out.find("(built for a body of radius 1 m, it leaves out passages narrower than 2 m)") !=
                      std::string::npos,
                  built_wide.out);
    // Baked for the default body (radius 0.6 m), planned for a wider one.
    const ProgramRun baked = navlink({"bake", "level.obj", "--out", "level.nlnav"}, dir);
    REQUIRE_MESSAGE(baked.exit_code == 0, baked.err);
    const ProgramRun wide =
        navlink({"path", "level.nlnav", "--agent", "wide.json", "--from", "40,0,0", "--to", "60,0,0"}, dir);
    CHECK(wide.exit_code == 1);
    CHECK_MESSAGE(
        wide.out.find(
            "the body (radius 1.00 m) is wider than the navmesh's (0.60 m): it keeps 0.40 m more from walls") !=
            std::string::npos,
        wide.out);
    CHECK(wide.out.find("why: the body (radius 1 m) is too wide for the passages on the way") != std::string::npos);
    const ProgramRun fits = navlink({"path", "level.nlnav", "--from", "40,0,0", "--to", "60,0,0"}, dir);
    CHECK(fits.exit_code == 0);
    CHECK(fits.out.find("why:") == std::string::npos);
}

// Agents on the host's own level: a platform 4.2 m above a floor, with no stairs and drops the demo's
// bodies cannot take. From the floor to the floor every agent arrives (exit 0); from the platform to
// the floor none does, and both tools say so and exit 1; a destination off the navmesh is an error.
TEST_CASE("navlink simulate LEVEL and navlink-viewer --from --to exit 0 only when every agent arrived") {
    const std::string dir = nl::test::scratch_dir("own_level_trips");
    nl::levelgen::GeneratedLevel level;
    level.add_box({{-10, -1, -10}, {20, 0, 10}});
    level.add_box({{0, 0, -3}, {6, 4.2f, 3}});
    nl::test::write_file(dir + "/tower.obj", level.to_obj());

    const ProgramRun floor =
        navlink({"simulate", "tower.obj", "--from", "15,0,0", "--to", "10,0,7", "--seconds", "30"}, dir);
    CHECK_MESSAGE(floor.exit_code == 0, floor.out << floor.err);
    CHECK(floor.out.find("NavLink simulate: tower.obj") != std::string::npos);
    CHECK(floor.out.find("not every agent arrived") == std::string::npos);
    const ProgramRun down =
        navlink({"simulate", "tower.obj", "--from", "3,4.2,0", "--to", "15,0,0", "--seconds", "20"}, dir);
    CHECK_MESSAGE(down.exit_code == 1, down.out << down.err);
    CHECK(down.out.find("not every agent arrived") != std::string::npos);
    const ProgramRun generated_only =
        navlink({"simulate", "tower.obj", "--from", "15,0,0", "--to", "10,0,7", "--platforms"}, dir);
    CHECK(generated_only.exit_code == 2);
    CHECK(generated_only.err.find("--platforms is for the generated default level") != std::string::npos);

    const auto viewer = [&](const std::string& from, const std::string& to) {
        return nl::test::run_program(
            {NAVLINK_VIEWER_PATH, "tower.obj", "--headless", "--frames", dir, "--from", from, "--to", to}, dir);
    };
    const ProgramRun viewer_floor = viewer("15,0,0", "10,0,7");
    CHECK_MESSAGE(viewer_floor.exit_code == 0, viewer_floor.out << viewer_floor.err);
    CHECK(viewer_floor.out.find("agents: every agent arrived") != std::string::npos);
    const ProgramRun viewer_down = viewer("3,4.2,0", "15,0,0");
    CHECK_MESSAGE(viewer_down.exit_code == 1, viewer_down.out << viewer_down.err);
    CHECK(viewer_down.out.find("agents: not every agent arrived") != std::string::npos);
    const ProgramRun viewer_off = viewer("15,0,0", "60,0,0");
    CHECK(viewer_off.exit_code == 2);
    CHECK(viewer_off.err.find("--to 60,0,0: not every agent can go there") != std::string::npos);
}

// The README shows the demo's output: its counts and every agent's row are what the demo prints now
// (the milliseconds aside), so the README cannot fall behind the program.
TEST_CASE("the README's demo output is what navlink demo prints") {
    const std::string dir = nl::test::scratch_dir("readme_demo");
    const ProgramRun run = navlink({"demo"}, dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const std::string readme = nl::test::read_file(std::string(NAVLINK_SOURCE_DIR) + "/README.md");
    const auto without_times = [](const std::string& text) {
        return std::regex_replace(text, std::regex(R"( in \d+ ms)"), "");
    };
    const std::string printed = without_times(run.out), shown = without_times(readme);
    std::istringstream lines(printed);
    int compared = 0;
    for (std::string line; std::getline(lines, line);) {
        const bool row = std::regex_search(line, std::regex(R"(^(walker|short jumper|long jumper) .*\| )"));
        const bool count = line.rfind("NavLink demo:", 0) == 0 || line.rfind("  navmesh:", 0) == 0 ||
                           line.rfind("  links:", 0) == 0 || line.rfind("  route:", 0) == 0;
        if (!row && !count) continue;
        CHECK_MESSAGE(shown.find(line + "\n") != std::string::npos, "README.md does not show: " << line);
        ++compared;
    }
    CHECK(compared == 7);
}

// Links from another level are refused saying so; links for another body are refused naming
// --any-body, and load with a warning with it.
TEST_CASE(
    "navlink path says when links were made for another level, and --any-body loads links made for another body") {
    GeneratedLevelFiles files("links_elsewhere");
    nl::levelgen::GeneratedLevel tower;
    tower.add_box({{-10, -1, -10}, {20, 0, 10}});
    tower.add_box({{0, 0, -3}, {6, 4.2f, 3}});
    nl::test::write_file(files.dir + "/tower.obj", tower.to_obj());
    nl::test::write_file(files.dir + "/thin.json", R"({"radius": 0.4})");
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json"}, files.dir).exit_code == 0);

    const ProgramRun elsewhere =
        navlink({"path", "tower.obj", "--links", "links.json", "--from", "15,0,0", "--to", "10,0,7"}, files.dir);
    CHECK(elsewhere.exit_code == 2);
    CHECK_MESSAGE(elsewhere.err.find("these links were made for another level (level hash ") != std::string::npos,
                  elsewhere.err);

    const std::vector<std::string> thin = {"path",      "level.obj", "--links", "links.json", "--agent",
                                           "thin.json", "--from",    "2,0,3",   "--to",       "33.9,-1,3.5"};
    const ProgramRun refused = navlink(thin, files.dir);
    CHECK(refused.exit_code == 2);
    CHECK_MESSAGE(
        refused.err.find("load them anyway with NL_LINKS_LOAD_ANY_BODY (navlink: --any-body)") != std::string::npos,
        refused.err);
    std::vector<std::string> any_body = thin;
    any_body.push_back("--any-body");
    const ProgramRun loaded = navlink(any_body, files.dir);
    CHECK_MESSAGE(loaded.exit_code != 2, loaded.err);
    CHECK(loaded.err.find("warning: the links were generated for a body of radius 0.6 m") != std::string::npos);
    CHECK(loaded.err.find("loaded anyway (NL_LINKS_LOAD_ANY_BODY)") != std::string::npos);
}

// A walker's path round the default level turns at many corners; its route line is one walk.
TEST_CASE("navlink path prints the route in one line, consecutive walking merged") {
    GeneratedLevelFiles files("route_line");
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json"}, files.dir).exit_code == 0);
    const ProgramRun walker = navlink({"path", "level.obj", "--from", "2,0,3", "--to", "33.9,-1,3.5"}, files.dir);
    REQUIRE_MESSAGE(walker.exit_code == 0, walker.out << walker.err);
    std::smatch route;
    REQUIRE(std::regex_search(walker.out, route, std::regex(R"(\n  route: (.*)\n)")));
    CHECK_MESSAGE(std::regex_match(route[1].str(), std::regex(R"(walk [0-9.]+)")), route[1].str());
    CHECK(std::count(walker.out.begin(), walker.out.end(), '\n') > 6);  // many corners in the table above it
    const ProgramRun jumper =
        navlink({"path", "level.obj", "--links", "links.json", "--from", "2,0,3", "--to", "33.9,-1,3.5"}, files.dir);
    REQUIRE(std::regex_search(jumper.out, route, std::regex(R"(\n  route: (.*)\n)")));
    CHECK_MESSAGE(std::regex_search(route[1].str(), std::regex(R"(^walk [0-9.]+, (jump|drop) [0-9.]+, walk )")),
                  route[1].str());
}

// A world baked in tiles: one file per tile and an index; info lists them with their hashes; a bake
// again keeps every tile; path plans over the tiles as over the level built in the same tiles with
// the same links; a tile's file changed on disk is refused by name.
TEST_CASE("navlink bake --tile-size writes a tile per file and an index; info lists them; path plans over them") {
    GeneratedLevelFiles files("tile_bake");
    const ProgramRun baked = navlink({"bake", "level.obj", "--tile-size", "32", "--out", "tiles"}, files.dir);
    REQUIRE_MESSAGE(baked.exit_code == 0, baked.err);
    const json index = nl::test::parse_json_file(files.dir + "/tiles/index.json");
    CHECK(index.at("format") == "navlink-tiles");
    const size_t tiles = index.at("tiles").size();
    CHECK(tiles >= 9);
    for (const json& t : index.at("tiles")) {
        CHECK(std::filesystem::is_regular_file(files.dir + "/tiles/" + t.at("file").get<std::string>()));
        CHECK(t.at("hash").get<std::string>().size() == 16);
    }
    CHECK(baked.out.find(std::to_string(tiles) + " tiles written") != std::string::npos);
    const ProgramRun again = navlink({"bake", "level.obj", "--tile-size", "32", "--out", "tiles"}, files.dir);
    CHECK_MESSAGE(again.out.find("0 tiles written (0 bytes), " + std::to_string(tiles) + " kept") != std::string::npos,
                  again.out);

    const ProgramRun info = navlink({"info", "tiles"}, files.dir);
    REQUIRE_MESSAGE(info.exit_code == 0, info.err);
    CHECK(info.out.find("NavLink tile bake, " + std::to_string(tiles) + " tiles") != std::string::npos);
    for (const json& t : index.at("tiles")) CHECK(info.out.find(t.at("hash").get<std::string>()) != std::string::npos);

    // The same route over the tiles as over the level built in tiles of 32 with its links.
    nl::test::write_file(files.dir + "/tiled.json", R"({"recast": {"tile_size": 32}})");
    REQUIRE(
        navlink({"generate", "level.obj", "--settings", "tiled.json", "--out", "links.json"}, files.dir).exit_code ==
        0);
    const std::string from = "2,0,3", to = "33.91,-1.03,3.5";
    const ProgramRun over_tiles = navlink({"path", "tiles", "--from", from, "--to", to, "--json"}, files.dir);
    const ProgramRun over_level = navlink({"path", "level.obj", "--settings", "tiled.json", "--links", "links.json",
                                           "--from", from, "--to", to, "--json"},
                                          files.dir);
    REQUIRE_MESSAGE(over_tiles.exit_code == 0, over_tiles.err);
    REQUIRE_MESSAGE(over_level.exit_code == 0, over_level.err);
    const json a = json::parse(over_tiles.out), b = json::parse(over_level.out);
    CHECK(a.at("outcome") == "complete");
    CHECK(a.at("points") == b.at("points"));
    CHECK(a.at("length") == b.at("length"));

    // A tile's file changed on disk: refused, naming it.
    const std::string victim = files.dir + "/tiles/" + index.at("tiles")[0].at("file").get<std::string>();
    std::string bytes = nl::test::read_file(victim);
    bytes[bytes.size() / 2] ^= 0x20;
    nl::test::write_file(victim, bytes);
    const ProgramRun damaged = navlink({"path", "tiles", "--from", from, "--to", to}, files.dir);
    CHECK(damaged.exit_code == 2);
    CHECK_MESSAGE(damaged.err.find("corrupted") != std::string::npos, damaged.err);
}
