// Bad arguments, missing files and bad JSON: one line on stderr naming the problem, exit status 2.
#include <algorithm>
#include <filesystem>

#include "cli_fixture.h"

using nl::test::navlink;
using nl::test::ProgramRun;

namespace {

struct BadCall {
    std::vector<std::string> args;
    std::string expected;  // in the error line
};

void check_one_line_error(const BadCall& call, const std::string& dir) {
    std::string command;
    for (const auto& a : call.args) command += a + " ";
    INFO("navlink " << command);
    const ProgramRun run = navlink(call.args, dir);
    INFO("stderr: " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK(run.err.rfind("navlink: ", 0) == 0);
    CHECK(run.err.find(call.expected) != std::string::npos);
}

}  // namespace

TEST_CASE("bad arguments, files and JSON give one line and exit status 2") {
    const std::string dir = nl::test::scratch_dir("errors");
    REQUIRE(navlink({"level", "--out", "level.obj"}, dir).exit_code == 0);
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json"}, dir).exit_code == 0);
    const std::vector<std::pair<std::string, std::string>> files = {
        {"broken.json", "{\"radius\": "},
        {"list.json", "[1, 2]"},
        {"negative_radius.json", R"({"radius": -1})"},
        {"text_radius.json", R"({"radius": "big"})"},
        {"wings.json", R"({"max_jump_distance": 3, "wings": 2})"},
        {"negative_abilities.json", R"({"abilities": -1})"},
        {"slope.json", R"({"max_slope": 95})"},
        {"bad_distance.json", R"({"max_jump_gap": -1})"},
        {"typo.json", R"({"max_link_distanse": 5})"},
        {"renamed.json", R"({"max_link_distance": 5})"},
        {"jumper.json", R"({"radius": 0.4, "max_jump_distance": 3})"},
        {"bad_recast.json", R"({"recast": 5})"},
        {"bad_cell.json", R"({"recast": {"cell_size": -1}})"},
        {"other_format.json", R"({"format": "something-else", "version": 1, "links": []})"},
        {"half.json", R"({"format": "navlink-links", "version": 1, "links": [)"},
        {"bad_level.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 9\n"},
        {"concave.obj", "v 0 0 0\nv 4 0 0\nv 1 0 1\nv 4 0 4\nv 0 0 4\nf 1 5 4 3 2\n"},
        {"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"},
        {"far.obj", "v 0 0 0\nv 1 0 0\nv 1 0 3e9\nf 1 2 3\n"},
    };
    for (const auto& [name, text] : files) nl::test::write_file(dir + "/" + name, text);

    const std::vector<std::string> path = {"path", "level.obj", "--links", "links.json"};
    auto with = [](std::vector<std::string> a, std::initializer_list<std::string> more) {
        a.insert(a.end(), more);
        return a;
    };
    const std::vector<BadCall> calls = {
        {{}, "missing command"},
        {{"frobnicate"}, "unknown command 'frobnicate'"},
        {{"generate"}, "missing LEVEL.obj"},
        {{"generate", "level.obj"}, "--out is required"},
        {{"generate", "level.obj", "--out"}, "--out needs a value"},
        {{"generate", "level.obj", "--out", "x.json", "--bogus"}, "unknown option '--bogus'"},
        {{"generate", "level.obj", "--out", "x.json", "--out", "y.json"}, "--out given twice"},
        {{"generate", "level.obj", "extra.obj", "--out", "x.json"}, "unexpected argument 'extra.obj'"},
        {{"generate", "/nonexistent/level.obj", "--out", "x.json"}, "cannot open '/nonexistent/level.obj'"},
        {{"generate", "bad_level.obj", "--out", "x.json"}, "bad_level.obj:4:"},
        {{"generate", "level.obj", "--out", "x.json", "--navmesh", "concave.obj"}, "concave.obj"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "/nonexistent.json"},
         "cannot open '/nonexistent.json'"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "."}, "is a directory"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "broken.json"},
         "broken.json:1:12: not valid JSON: unexpected end of input"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "list.json"}, "must be a JSON object"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "negative_radius.json"},
         "radius must be a number > 0"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "text_radius.json"}, "radius must be a number"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "wings.json"}, "unknown key \"wings\""},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "negative_abilities.json"},
         "abilities must be a whole number"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "slope.json"}, "max_slope"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "jumper.json"},
         "max_jump_distance is a capability: capabilities choose links when a path is planned"},
        {{"generate", "level.obj", "--out", "x.json", "--settings", "renamed.json"}, "max_link_distance"},
        {{"generate", "level.obj", "--out", "x.json", "--settings", "bad_distance.json"}, "max_jump_gap"},
        {{"generate", "level.obj", "--out", "x.json", "--settings", "typo.json"}, "max_link_distanse"},
        {{"generate", "level.obj", "--out", "x.json", "--settings", "bad_recast.json"}, "recast must be a JSON object"},
        {{"generate", "level.obj", "--out", "x.json", "--settings", "bad_cell.json"}, "cell_size"},
        {{"generate", "level.obj", "--out", "/nonexistent/x.json"}, "cannot write '/nonexistent/x.json'"},
        {with(path, {"--to", "1,0,1"}), "--from is required"},
        {with(path, {"--from", "1,2", "--to", "1,0,1"}), "--from must be three numbers X,Y,Z (got '1,2')"},
        {with(path, {"--from", "a,b,c", "--to", "1,0,1"}), "--from must be three numbers"},
        {with(path, {"--from", "1,0,1", "--to", "1,0,1,5"}), "--to must be three numbers"},
        {{"path", "level.obj", "--links", "other_format.json", "--from", "1,0,1", "--to", "2,0,2"}, "format"},
        {{"path", "level.obj", "--links", "half.json", "--from", "1,0,1", "--to", "2,0,2"}, "half.json"},
        {{"path", "level.obj", "--links", "missing.json", "--from", "1,0,1", "--to", "2,0,2"},
         "cannot open 'missing.json'"},
        {with(path, {"--from", "1,0,1", "--to", "2,0,2", "--json=yes"}), "--json takes no value"},
        {{"demo", "--seed", "-3"}, "--seed must be a whole number"},
        {{"demo", "now"}, "unexpected argument 'now'"},
        {{"simulate", "--hz", "0"}, "--hz must be a whole number"},
        {{"simulate", "--seconds", "1e9"}, "--seconds must be a whole number"},
        {{"level"}, "--out is required"},
        {{"level", "--out", "/nonexistent/level.obj"}, "cannot write"},
        {with(path, {"--from", "1,0,1", "--to", "2,0,2", "--search", "1,0,1"}),
         "--search must be three half extents above 0, in metres (got '1,0,1')"},
        {{"demo", "--out-dir", "level.obj"}, "--out-dir 'level.obj' is a file, not a folder"},
        {{"generate", "level.obj", "--out", "x.json", "--agent", "slope.json"},
         "slope.json: max_slope must be a number >= 0 and <= 89.9 (got 95)"},
        {{"generate", "bad_level.obj", "--out", "x.json"},
         "loading the level: bad_level.obj:4: vertex index 9 is past the last one (3)"},
        {{"generate", "flat.obj", "--out", "x.json"},
         "loading the level: flat.obj: faces: all 1 triangles are degenerate"},
        {{"generate", "far.obj", "--out", "x.json"},
         "loading the level: far.obj: vertex 3: z = 3e+09 is beyond the coordinate limit"},
        {{"simulate", "--out-dir", "level.obj"}, "--out-dir 'level.obj' is a file, not a folder"},
        {{"generate", "level.obj", "--out", "."}, "cannot write '.': it is a folder"},
        {with(path, {"--from", "1,0,1", "--to", "2,0,2", "--png", "/nonexistent/p.png"}),
         "cannot write '/nonexistent/p.png': the folder '/nonexistent' does not exist"},
    };
    for (const BadCall& call : calls) check_one_line_error(call, dir);
}

TEST_CASE("every output is checked before the work: a bad --png writes no --out") {
    const std::string dir = nl::test::scratch_dir("outputs_first");
    REQUIRE(navlink({"level", "--out", "level.obj"}, dir).exit_code == 0);
    for (const char* command : {"bake", "generate"}) {
        INFO(command);
        const std::string out = std::string("written.") + (std::string(command) == "bake" ? "nlnav" : "json");
        check_one_line_error({{command, "level.obj", "--out", out, "--png", "/nonexistent/v.png"},
                              "cannot write '/nonexistent/v.png': the folder '/nonexistent' does not exist"},
                             dir);
        CHECK_FALSE(std::filesystem::exists(dir + "/" + out));
    }
}

TEST_CASE("generate --plugin loads a link-kind plugin; settings for one not loaded are refused") {
    const std::string dir = nl::test::scratch_dir("cli_plugin");
    // A 2.5 m block on a wide floor: too high to step onto, low enough for the climb plugin.
    nl::test::write_file(dir + "/block.obj",
                         "v -10 0 -10\nv 20 0 -10\nv 20 0 20\nv -10 0 20\n"
                         "v 0 0 0\nv 6 0 0\nv 6 0 10\nv 0 0 10\nv 0 2.5 0\nv 6 2.5 0\nv 6 2.5 10\nv 0 2.5 10\n"
                         "f 1 4 3\nf 1 3 2\n"
                         "f 9 12 11\nf 9 11 10\n"
                         "f 5 6 10\nf 5 10 9\nf 6 7 11\nf 6 11 10\nf 7 8 12\nf 7 12 11\nf 8 5 9\nf 8 9 12\n");
    nl::test::write_file(dir + "/climb.json", R"({"plugins": {"climb": {}}})");
    check_one_line_error({{"generate", "block.obj", "--out", "links.json", "--settings", "climb.json"},
                          "no loaded link-kind plugin provides the kind \"climb\" (loaded: none)"},
                         dir);
    check_one_line_error({{"generate", "block.obj", "--out", "links.json", "--plugin", "missing.so"}, "missing.so"},
                         dir);
    const ProgramRun run = navlink(
        {"generate", "block.obj", "--out", "links.json", "--settings", "climb.json", "--plugin", CLIMB_PLUGIN_PATH},
        dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const auto links = nl::test::parse_json_file(dir + "/links.json").at("links");
    size_t climbs = 0;
    for (const auto& link : links) climbs += link.at("kind") != "jump" && link.at("kind") != "drop";
    CHECK(climbs >= 20);  // four sides of a 6 x 10 m block
}
