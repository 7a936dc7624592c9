// The pictures as a user reads them, checked pixel by pixel at places computed with the pictures' own
// camera (samples/sdl): roofs cut away above the navmesh, a start off the map marked at its edge, the
// drop arrows counted, link numbers where the links are, a tiled navmesh's tile borders; and the
// viewer's clicks in a level with a roof, which pick the navmesh polygon under the cursor, its script
// on every shared level, and its tiles streamed around an agent walking across a tiled level.
#include <navlink/navlink.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "cli_fixture.h"
#include "level.h"
#include "navmesh_contents.h"
#include "navmesh_setup.h"
#include "palette.h"
#include "scene_renderer.h"
#include "shared_levels.h"
#include "tile_borders.h"
#include "world.h"

using nl::test::navlink;
using nl::test::ProgramRun;
using nlohmann::json;

namespace {

using Color = std::array<int, 3>;

struct Png {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;

    explicit Png(const std::string& path) {
        int channels = 0;
        uint8_t* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
        REQUIRE_MESSAGE(data != nullptr, path);
        rgba.assign(data, data + size_t(width) * size_t(height) * 4);
        stbi_image_free(data);
    }
    Color at(int x, int y) const {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        const uint8_t* p = &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
        return {p[0], p[1], p[2]};
    }
    Color at(SDL_FPoint p) const { return at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))); }
    // The median of each channel over the 5 x 5 pixels around `p`: a thin line or a letter over one
    // pixel does not change it.
    Color median(SDL_FPoint p) const {
        Color out{};
        for (int c = 0; c < 3; ++c) {
            std::vector<int> values;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    values.push_back(at(static_cast<int>(p.x) + dx, static_cast<int>(p.y) + dy)[c]);
            std::nth_element(values.begin(), values.begin() + 12, values.end());
            out[c] = values[12];
        }
        return out;
    }
};

int difference(const Color& a, const Color& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

std::string text(const Color& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// A level as the CLI loads it and the camera of its PNG pictures (1600 pixels wide, as tall as the
// level needs): where a point of the level is drawn.
struct PictureCamera {
    nl::samples::World world;
    nl::samples::Level level;
    nl::picture::Scene scene;
    nl::picture::ViewSettings view;

    explicit PictureCamera(const std::string& obj) : level(nl::samples::load_level_file(world.get(), obj, false)) {
        scene.level = &level;
        view.height = nl::picture::fitted_height(scene, view);
    }
    nl::picture::Camera camera() const { return nl::picture::scene_camera(scene, view); }
    SDL_FPoint pixel(const float p[3]) const { return camera().project(p); }
};

std::string dungeon() { return (nl::test::levels_dir() / "dungeon.obj").string(); }

bool has_dungeon() {
    if (std::filesystem::exists(dungeon())) return true;
    if (nl::test::levels_required()) FAIL("no dungeon.obj in " << nl::test::levels_dir());
    MESSAGE("no dungeon.obj in " << nl::test::levels_dir() << ": skipped");
    return false;
}

// Whether the level has a surface above `p` (a roof or a ceiling, seen from either side), more than
// `clearance` up.
bool roofed(nl_world* world, const float p[3], float clearance) {
    nl_ray ray{};
    for (int k = 0; k < 3; ++k) ray.origin[k] = p[k];
    ray.origin[1] += clearance;
    ray.direction[1] = 1.0f;
    ray.max_distance = 1000.0f;
    nl_ray_hit hit = nl_ray_hit_init();
    REQUIRE(nl_world_cast_rays(world, &ray, 1, &hit) == NL_STATUS_SUCCESS);
    return hit.hit;
}

// The height of the topmost surface at (x, z) that faces up: what a picture straight down shows
// there when it draws every surface (a ceiling seen from above is its back, not drawn).
float top_surface(nl_world* world, float x, float z, float above) {
    nl_ray ray{};
    ray.origin[0] = x;
    ray.origin[1] = above;
    ray.origin[2] = z;
    ray.direction[1] = -1.0f;
    ray.max_distance = 2000.0f;
    for (int i = 0; i < 100; ++i) {
        nl_ray_hit hit = nl_ray_hit_init();
        REQUIRE(nl_world_cast_rays(world, &ray, 1, &hit) == NL_STATUS_SUCCESS);
        if (!hit.hit) return -1e30f;
        if (hit.normal[1] > 0.02f) return hit.point[1];
        ray.origin[1] = hit.point[1] - 1e-3f;
    }
    return -1e30f;
}

bool flat(const nl_nav_polygon& p) { return p.normal[1] > 0.995f; }

}  // namespace

TEST_CASE("pictures cut roofs away: the floor under dungeon's roof is drawn as open floor at its height") {
    if (!has_dungeon()) return;
    const std::string dir = nl::test::scratch_dir("picture_roofs");
    const ProgramRun cut = navlink({"generate", dungeon(), "--out", "links.json", "--png", "cut.png"}, dir);
    REQUIRE_MESSAGE(cut.exit_code == 0, cut.err);
    const ProgramRun whole =
        navlink({"generate", dungeon(), "--out", "links.json", "--png", "whole.png", "--roofs"}, dir);
    REQUIRE_MESSAGE(whole.exit_code == 0, whole.err);
    const Png cut_png(dir + "/cut.png"), whole_png(dir + "/whole.png");

    // The CLI's navmesh, built here the same way: flat polygons under a roof, each beside an open
    // one at the same height it walks to (so of the same island, drawn in the same colour).
    PictureCamera picture(dungeon());
    const nl_navmesh_id navmesh = nl::samples::build_navmesh(picture.world.get(), nl_default_agent_type(), "");
    const nl::samples::NavmeshContents nav = nl::samples::read_navmesh_contents(picture.world.get(), navmesh);
    REQUIRE(cut_png.width == 1600);
    REQUIRE(cut_png.height == picture.view.height);
    const float above = picture.level.info.bounds_max[1] + 1.0f;
    auto top = [&](const nl_nav_polygon& p) {
        return top_surface(picture.world.get(), p.centre[0], p.centre[2], above);
    };
    size_t pairs = 0, matching = 0, roof_shown_before = 0;
    for (uint32_t p = 0; p < nav.polygons.size(); ++p) {
        const nl_nav_polygon& under = nav.polygons[p];
        if (!flat(under) || top(under) < under.centre[1] + 2.5f) continue;
        for (uint32_t k = 0; k < under.vertex_count; ++k) {
            const uint32_t n = under.neighbours[k];
            if (n == NL_NO_POLYGON) continue;
            const nl_nav_polygon& open = nav.polygons[n];
            if (!flat(open) || std::fabs(open.centre[1] - under.centre[1]) > 0.1f ||
                std::fabs(top(open) - open.centre[1]) > 0.5f)
                continue;
            const Color under_cut = cut_png.median(picture.pixel(under.centre));
            const Color open_cut = cut_png.median(picture.pixel(open.centre));
            const Color under_whole = whole_png.median(picture.pixel(under.centre));
            const Color open_whole = whole_png.median(picture.pixel(open.centre));
            INFO("polygon " << p << " under a roof " << text(under_cut) << ", open neighbour " << n << " "
                            << text(open_cut) << "; with roofs " << text(under_whole) << ", " << text(open_whole));
            ++pairs;
            matching += difference(under_cut, open_cut) <= 12;
            roof_shown_before += difference(under_whole, open_whole) > 12;
            break;
        }
    }
    MESSAGE(pairs << " roofed polygons beside open ones: " << matching << " drawn as their open neighbour, "
                  << roof_shown_before << " drawn unlike it with --roofs");
    REQUIRE(pairs >= 3);
    CHECK(matching >= pairs * 3 / 4);
    CHECK(roof_shown_before >= pairs * 3 / 4);  // with --roofs, the roof hides the floor there
}

TEST_CASE("a start off the map is marked at the map's edge, its arrow pointing its way") {
    const std::string dir = nl::test::scratch_dir("picture_off_map");
    REQUIRE(navlink({"level", "--out", "level.obj"}, dir).exit_code == 0);
    const ProgramRun run =
        navlink({"path", "level.obj", "--from", "500,0,500", "--to", "4,0,3", "--png", "p.png"}, dir);
    CHECK_MESSAGE(run.exit_code == 1, run.err);  // the start is off the navmesh
    const Png png(dir + "/p.png");
    PictureCamera picture(dir + "/level.obj");
    const nl::picture::Camera camera = picture.camera();
    const float from[3] = {500.0f, 0.0f, 500.0f}, to[3] = {4.0f, 0.0f, 3.0f};
    bool off = false;
    const SDL_FPoint marker = nl::picture::point_marker(picture.scene, camera, from, &off);
    REQUIRE(off);
    const SDL_FRect map = nl::picture::map_rect(picture.scene, camera);
    // South-east of the level: in the map's bottom right corner.
    CHECK(marker.x == doctest::Approx(map.x + map.w - nl::picture::kOffMapInset));
    CHECK(marker.y == doctest::Approx(map.y + map.h - nl::picture::kOffMapInset));
    const nl::picture::Rgba pink = nl::picture::palette::kOffMap;
    const Color expected{pink.r, pink.g, pink.b};
    INFO("marker at " << marker.x << ", " << marker.y << ": " << text(png.at(marker)));
    CHECK(difference(png.at(marker), expected) <= 3);
    // The arrow points at the start: towards the bottom right, past the marker's dot.
    CHECK(difference(png.at({marker.x + 9.5f, marker.y + 9.5f}), expected) <= 3);
    // The goal is on the map: drawn where it is, in the points' colour.
    bool goal_off = true;
    const SDL_FPoint goal = nl::picture::point_marker(picture.scene, camera, to, &goal_off);
    CHECK_FALSE(goal_off);
    CHECK(difference(png.at(goal), {235, 235, 235}) <= 3);
    CHECK(run.out.find("wrote p.png") != std::string::npos);
}

TEST_CASE("navlink demo draws one arrow per ledge run of drops, and says how many") {
    const std::string dir = nl::test::scratch_dir("picture_drops");
    const ProgramRun run = navlink({"demo"}, dir);
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const json links = nl::test::parse_json_file(dir + "/demo.links.json");
    const size_t drops = nl::test::count_kinds(links).drop;
    std::smatch m;
    REQUIRE_MESSAGE(
        std::regex_search(run.out, m, std::regex(R"(drops: (\d+) \((\d+) arrows\); (\d+) islands? for the walker)")),
        run.out);
    CHECK(std::stoul(m[1]) == drops);
    const unsigned long arrows = std::stoul(m[2]);
    MESSAGE(drops << " drops drawn as " << arrows << " arrows; " << m[3] << " islands for the walker");
    CHECK(drops > 30);             // the default level's ledges
    CHECK(arrows >= 4);            // every ledge keeps an arrow...
    CHECK(arrows * 3 <= drops);    // ...and a ledge's row of drops is one
    CHECK(std::stoul(m[3]) >= 2);  // the walker cannot cross the gaps: the platforms are islands
}

TEST_CASE("--link-numbers draws each link's number beside it, and only there") {
    const std::string dir = nl::test::scratch_dir("picture_link_numbers");
    REQUIRE(navlink({"level", "--out", "level.obj"}, dir).exit_code == 0);
    REQUIRE(navlink({"generate", "level.obj", "--out", "links.json", "--png", "plain.png"}, dir).exit_code == 0);
    const ProgramRun numbered =
        navlink({"generate", "level.obj", "--out", "links.json", "--png", "numbers.png", "--link-numbers"}, dir);
    REQUIRE_MESSAGE(numbered.exit_code == 0, numbered.err);
    CHECK(navlink({"generate", "--help"}, dir).out.find("--link-numbers") != std::string::npos);
    CHECK(navlink({"path", "--help"}, dir).out.find("--link-numbers") != std::string::npos);
    CHECK(navlink({"demo", "--help"}, dir).out.find("--link-numbers") != std::string::npos);

    const Png plain(dir + "/plain.png"), numbers(dir + "/numbers.png");
    REQUIRE(plain.width == numbers.width);
    REQUIRE(plain.height == numbers.height);
    PictureCamera picture(dir + "/level.obj");
    const nl::picture::Camera camera = picture.camera();
    const SDL_FRect map = nl::picture::map_rect(picture.scene, camera);
    // Where the links are drawn: their ends and apex.
    std::vector<SDL_FPoint> link_points;
    const json links = nl::test::parse_json_file(dir + "/links.json");
    for (const auto& l : links.at("links"))
        for (const char* key : {"start", "end", "apex"}) {
            const float p[3] = {l.at(key).at(0).get<float>(), l.at(key).at(1).get<float>(),
                                l.at(key).at(2).get<float>()};
            link_points.push_back(camera.project(p));
        }
    size_t changed = 0, near_a_link = 0;
    for (int y = static_cast<int>(map.y); y < static_cast<int>(map.y + map.h); ++y)
        for (int x = static_cast<int>(map.x); x < static_cast<int>(map.x + map.w); ++x) {
            if (difference(plain.at(x, y), numbers.at(x, y)) == 0) continue;
            ++changed;
            for (const SDL_FPoint& p : link_points)
                if (std::hypot(p.x - static_cast<float>(x), p.y - static_cast<float>(y)) < 40.0f) {
                    ++near_a_link;
                    break;
                }
        }
    MESSAGE(changed << " pixels of the map changed by the numbers, " << near_a_link << " within 40 px of a link");
    CHECK(changed > 500);
    CHECK(near_a_link == changed);
}

TEST_CASE("the viewer's clicks in dungeon pick the navmesh polygon under the cursor, not the roof over it") {
    if (!has_dungeon()) return;
    const std::string dir = nl::test::scratch_dir("viewer_dungeon");
    const ProgramRun run = nl::test::run_program({NAVLINK_VIEWER_PATH, dungeon(), "--headless", "--frames", dir}, dir);
    INFO(run.out << run.err);
    CHECK(run.exit_code == 0);
    nl::samples::World world;
    nl::samples::load_level_file(world.get(), dungeon(), false);
    const nl_navmesh_id navmesh = nl::samples::build_navmesh(world.get(), nl_default_agent_type(), "");
    const std::regex picked(R"(: (.*) picked \(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\) on navmesh polygon (\d+))");
    size_t clicks = 0, under_roof = 0;
    for (std::sregex_iterator it(run.out.begin(), run.out.end(), picked), end; it != end; ++it) {
        const float p[3] = {std::stof((*it)[2]), std::stof((*it)[3]), std::stof((*it)[4])};
        INFO((*it)[0]);
        // On the navmesh: its nearest point is the picked one, on the polygon the log names.
        const float box[3] = {0.5f, 0.5f, 0.5f};
        nl_nav_point nearest{};
        REQUIRE(nl_navmesh_find_nearest(world.get(), navmesh, p, 1, box, &nearest) == NL_STATUS_SUCCESS);
        CHECK(nearest.found);
        CHECK(nearest.distance < 0.05f);
        CHECK(nearest.polygon == std::stoul((*it)[5]));
        under_roof += roofed(world.get(), p, 2.5f);
        ++clicks;
    }
    MESSAGE(clicks << " clicks, " << under_roof << " under a roof");
    CHECK(clicks == 3);
    CHECK(under_roof >= 1);  // a click the roof used to take
}

TEST_CASE("the viewer's headless script runs on every shared level") {
    const auto levels = nl::test::shared_levels_or_skip();
    if (levels.empty()) return;
    for (const auto& level : levels) {
        const std::string name = level.stem().string();
        INFO(name);
        const std::string dir = nl::test::scratch_dir("viewer_" + name);
        const ProgramRun run =
            nl::test::run_program({NAVLINK_VIEWER_PATH, level.string(), "--headless", "--frames", dir}, dir);
        INFO(run.out << run.err);
        CHECK(run.exit_code == 0);
        CHECK(run.out.find("right click on the start picked") != std::string::npos);
        CHECK(nl::test::is_png(dir + "/frame_00.png", 1600));
    }
}

TEST_CASE("a tiled navmesh's picture draws the borders of its tiles over it; a solo navmesh's draws none") {
    const std::string dir = nl::test::scratch_dir("picture_tiles");
    REQUIRE(navlink({"level", "--out", "level.obj"}, dir).exit_code == 0);
    nl::test::write_file(dir + "/tiles.json", R"({"recast": {"tile_size": 32}})");
    const ProgramRun tiled = navlink(
        {"generate", "level.obj", "--settings", "tiles.json", "--out", "tiled.json", "--png", "tiled.png"}, dir);
    REQUIRE_MESSAGE(tiled.exit_code == 0, tiled.err);
    const ProgramRun solo = navlink({"generate", "level.obj", "--out", "solo.json", "--png", "solo.png"}, dir);
    REQUIRE_MESSAGE(solo.exit_code == 0, solo.err);
    const Png tiled_png(dir + "/tiled.png"), solo_png(dir + "/solo.png");

    // The CLI's tiled navmesh, built here the same way: where its tiles meet, its edges lie on the
    // lines between them.
    PictureCamera picture(dir + "/level.obj");
    const nl_navmesh_id navmesh =
        nl::samples::build_navmesh(picture.world.get(), nl_default_agent_type(), R"({"tile_size": 32})");
    const nl::samples::NavmeshContents nav = nl::samples::read_navmesh_contents(picture.world.get(), navmesh);
    REQUIRE(nav.tiled());
    CHECK(nav.tile_width == doctest::Approx(32 * 0.3f));
    REQUIRE(nav.tiles.size() > 4);
    REQUIRE(tiled_png.height == picture.view.height);
    const nl::picture::TileBorders borders = nl::picture::tile_borders(
        nav, picture.level.info.bounds_min[1], picture.level.info.bounds_min, picture.level.info.bounds_max);
    CHECK(nl::picture::tile_borders_text(nav) ==
          "tile borders (" + std::to_string(nav.tiles.size()) + " tiles of 9.6 m)");
    const nl::picture::Rgba blue = nl::picture::palette::kTileBorder;
    const Color border{blue.r, blue.g, blue.b};
    size_t seams = 0, drawn = 0, drawn_solo = 0;
    for (const auto& seam : borders.seams) {
        if (std::hypot(seam[1][0] - seam[0][0], seam[1][2] - seam[0][2]) < 1.0f) continue;
        const float middle[3] = {0.5f * (seam[0][0] + seam[1][0]), 0.5f * (seam[0][1] + seam[1][1]),
                                 0.5f * (seam[0][2] + seam[1][2])};
        const SDL_FPoint at = picture.pixel(middle);
        INFO("seam at (" << middle[0] << ", " << middle[2] << "): tiled " << text(tiled_png.at(at)) << ", solo "
                         << text(solo_png.at(at)));
        ++seams;
        drawn += difference(tiled_png.at(at), border) <= 40;
        drawn_solo += difference(solo_png.at(at), border) <= 40;
    }
    MESSAGE(seams << " navmesh edges along tile lines: " << drawn << " drawn in the tile borders' colour, "
                  << drawn_solo << " so in the solo navmesh's picture");
    REQUIRE(seams >= 8);
    CHECK(drawn >= seams * 3 / 4);  // a link drawn over a border hides it
    CHECK(drawn_solo == 0);
}

TEST_CASE("the viewer streams the tiles around an agent walking across a tiled level: it arrives, few tiles loaded") {
    const std::string dir = nl::test::scratch_dir("viewer_stream_tiles");
    const ProgramRun run = nl::test::run_program({NAVLINK_VIEWER_PATH, "--headless", "--tile-size", "32",
                                                  "--stream-tiles", "6", "--agent", "3", "--frames", dir},
                                                 dir);
    INFO(run.out << run.err);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("\nagents: every agent arrived") != std::string::npos);
    std::smatch m;
    REQUIRE(std::regex_search(run.out, m,
                              std::regex(R"(tiles: at most (\d+) of (\d+) loaded at once, within 6 m of the long )"
                                         R"(jumper; (\d+) removed \(saved first\), (\d+) added \((\d+) from saved )"
                                         R"(bytes, (\d+) built again\))")));
    const unsigned long most = std::stoul(m[1]), total = std::stoul(m[2]), removed = std::stoul(m[3]),
                        added = std::stoul(m[4]), from_bytes = std::stoul(m[5]);
    CHECK(total >= 12);            // the generated level in tiles of 9.6 m
    CHECK(most < total);           // never every tile at once
    CHECK(most * 3 <= total * 2);  // ... nor nearly
    CHECK(from_bytes == added);    // each came back as it was saved, with its links
    // Along the way, after the first step (at 0 s the tiles out of range go): each change a line
    // with the tiles loaded then, never more than the most.
    const std::regex change(R"(\n +([0-9.]+) s  tiles ([-+(), 0-9]+): (\d+) of (\d+) loaded)");
    size_t came = 0, went = 0;
    for (std::sregex_iterator it(run.out.begin(), run.out.end(), change), end; it != end; ++it) {
        CHECK(std::stoul((*it)[3]) <= most);
        CHECK(std::stoul((*it)[4]) == total);
        if (std::stof((*it)[1]) <= 0.0f) continue;
        const std::string tiles = (*it)[2];
        came += std::count(tiles.begin(), tiles.end(), '+');
        went += std::count(tiles.begin(), tiles.end(), '-');
    }
    MESSAGE("at most " << most << " of " << total << " tiles loaded; " << removed << " removed, " << added
                       << " added; on the way " << came << " came in and " << went << " went out");
    CHECK(came > 2);
    CHECK(went > 2);
    CHECK(came == added);
    // The frames show the tiles coming in; the last is a PNG.
    CHECK(run.out.find("frame_01.png: tiles streamed +(") != std::string::npos);
    CHECK(nl::test::is_png(dir + "/frame_01.png", 1600));
}
