#include "legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "drop_runs.h"
#include "island_colors.h"
#include "map_marker.h"
#include "palette.h"
#include "tile_borders.h"

namespace nl::picture {
namespace {

constexpr float kTextScale = 1.6f;
constexpr float kLine = 19.0f;

class LegendWriter {
public:
    LegendWriter(Canvas& canvas, float x, float y) : canvas_(canvas), x_(x), y_(y) {}

    void heading(const std::string& text) {
        y_ += 6.0f;
        canvas_.text({x_, y_}, text, 1.8f, palette::kText);
        y_ += kLine + 2.0f;
    }
    void swatch_line(Rgba color, const std::string& text, bool arrow = false) {
        const SDL_FPoint a{x_, y_ + 6.0f}, b{x_ + 34.0f, y_ + 6.0f};
        canvas_.line(a, b, 6.0f, palette::kShadow);
        canvas_.line(a, b, 3.0f, color);
        if (arrow) canvas_.arrow_head(a, b, 9.0f, color);
        entry(text);
    }
    void swatch_box(Rgba fill, Rgba edge, const std::string& text) {
        canvas_.rectangle({x_, y_, 34.0f, 13.0f}, fill);
        canvas_.line({x_, y_ + 13.0f}, {x_ + 34.0f, y_ + 13.0f}, 2.5f, edge);
        entry(text);
    }
    void swatch_dot(Rgba color, const std::string& text) {
        canvas_.dot({x_ + 17.0f, y_ + 6.0f}, 7.0f, color);
        entry(text);
    }
    void note(const std::string& text) {
        canvas_.text({x_, y_}, text, kTextScale, palette::kDimText);
        y_ += kLine;
    }
    float x() const { return x_; }
    float& y() { return y_; }

private:
    void entry(const std::string& text) {
        canvas_.text({x_ + 44.0f, y_}, text, kTextScale, palette::kText);
        y_ += kLine;
    }
    Canvas& canvas_;
    float x_, y_;
};

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

}  // namespace

float grid_step(float pixels_per_metre) {
    for (float metres : kRoundLengths)
        if (metres * pixels_per_metre >= 64.0f) return metres;
    return kRoundLengths[sizeof kRoundLengths / sizeof kRoundLengths[0] - 1];
}

float grid_height(const Scene& scene) {
    const samples::NavmeshContents* navmesh = scene.level_navmesh();
    if (!navmesh || navmesh->polygons.empty()) return scene.level->info.bounds_min[1];
    std::vector<float> heights;
    for (const nl_nav_polygon& polygon : navmesh->polygons) heights.push_back(polygon.centre[1]);
    std::nth_element(heights.begin(), heights.begin() + static_cast<long>(heights.size() / 2), heights.end());
    return heights[heights.size() / 2];
}

void drawn_heights(const Scene& scene, const HeightSlice* slice, float& lo, float& hi) {
    lo = scene.level->info.bounds_min[1];
    hi = scene.level->info.bounds_max[1];
    if (slice && slice->active()) hi = std::max(lo, std::min(hi, slice->top()));
}

void draw_legend(Canvas& canvas, const Scene& scene, const ViewSettings& view, const Camera& camera,
                 const HeightSlice* slice) {
    const float left = static_cast<float>(view.width) - kLegendWidth;
    canvas.rectangle({left, 0.0f, kLegendWidth, static_cast<float>(view.height)}, palette::kPanel);
    LegendWriter w(canvas, left + 16.0f, 14.0f);

    w.heading("LEVEL");
    float lo, hi;
    drawn_heights(scene, slice, lo, hi);
    for (int i = 0; i < 60; ++i) {
        const float t = static_cast<float>(i) / 59.0f;
        const Rgba a = palette::kLowGround, b = palette::kHighGround;
        const Rgba c{static_cast<uint8_t>(a.r + (b.r - a.r) * t), static_cast<uint8_t>(a.g + (b.g - a.g) * t),
                     static_cast<uint8_t>(a.b + (b.b - a.b) * t), 255};
        canvas.rectangle({w.x() + 4.0f * i, w.y(), 4.0f, 13.0f}, c);
    }
    w.y() += kLine;
    w.note(format("height: y = %.1f m (dark) to %.1f m (light)", lo, hi));
    w.note(std::to_string(scene.level->triangle_count()) + " triangles, " +
           (view.oblique ? "oblique view" : "top-down view"));
    if (slice && slice->active()) w.note(format("roofs cut away: %.1f m above the navmesh", HeightSlice::kClearance));
    if (view.layers.grid) {
        w.note(format("grid: every %g m; x across, z down (labels)", grid_step(camera.pixels_per_metre())));
        if (!camera.top_down()) w.note(format("(the grid lies at y = %.1f m)", grid_height(scene)));
    }

    if (scene.navmesh) {
        w.heading("NAVMESH");
        if (scene.islands) {
            const IslandColors colors = island_colors(*scene.islands);
            w.note(std::to_string(scene.navmesh->polygons.size()) + " polygons; " + islands_text(*scene.islands) + ":");
            const size_t shown = std::min<size_t>(colors.by_size.size(), 4);
            for (size_t rank = 0; rank < shown; ++rank) {
                const uint32_t island = colors.by_size[rank];
                w.swatch_box(colors.color[island], palette::kNavmeshEdge,
                             "island " + std::to_string(island) + ": " + std::to_string(colors.polygons[island]) +
                                 (colors.polygons[island] == 1 ? " polygon" : " polygons"));
            }
            if (colors.by_size.size() > shown)
                w.note("... " + std::to_string(colors.by_size.size() - shown) + " more (colours repeat after 8)");
            w.note("it walks and takes links within an island");
        } else {
            w.swatch_box(palette::kNavmeshFill, palette::kNavmeshEdge,
                         std::to_string(scene.navmesh->polygons.size()) + " walkable polygons");
        }
        w.swatch_line(palette::kBoundary, std::to_string(scene.navmesh->boundary_edges.size()) + " boundary edges");
        if (scene.navmesh->tiled() && view.layers.tile_borders)
            w.swatch_line(palette::kTileBorder, tile_borders_text(*scene.navmesh));
        for (size_t from = 0; from < scene.streaming.size();) {  // a note a line, each line ending '\n'
            const size_t end = std::min(scene.streaming.find('\n', from), scene.streaming.size());
            w.note(scene.streaming.substr(from, end - from));
            from = end + 1;
        }

        uint32_t counts[4] = {0, 0, 0, 0};
        uint32_t one_way = 0;
        for (const nl_link& l : scene.navmesh->links) {
            const int kind = l.kind == NL_LINK_JUMP ? 0 : l.kind == NL_LINK_DROP ? 1 : l.kind == NL_LINK_MANUAL ? 2 : 3;
            ++counts[kind];
            one_way += !l.bidirectional;
        }
        w.heading("LINKS (" + std::to_string(scene.navmesh->links.size()) + ")");
        w.swatch_line(palette::kJump, "jump: " + std::to_string(counts[0]));
        w.swatch_line(palette::kDrop, "drops: " + drop_summary(scene.navmesh->links), true);
        w.swatch_line(palette::kManual, "manual: " + std::to_string(counts[2]));
        w.swatch_line(palette::kPlugin, "plugin kinds: " + std::to_string(counts[3]));
        w.note("arrow: one way (" + std::to_string(one_way) + "); dots: both ends");
        w.note("drops along a ledge: a line, one arrow");
        if (view.layers.link_numbers) w.note("numbers: as in LINKS.json and navlink path");
    }

    if (!scene.platforms.empty()) {
        w.heading("PLATFORMS (" + std::to_string(scene.platforms.size()) + ")");
        for (const ScenePlatform& platform : scene.platforms)
            w.swatch_box(palette::kPlatform, palette::kBoundary, platform.label);
        w.note("faded link: a gangway that does not hold now");
    }

    if (!scene.paths.empty()) {
        w.heading("PATHS");
        for (const PathLayer& path : scene.paths) w.swatch_line(path.color, path.label);
        w.note("dots on a path: where it takes a link");
    }
    if (view.layers.agents && !scene.agents.empty()) {
        w.heading("AGENTS");
        for (const SceneAgent& a : scene.agents) w.swatch_dot(a.color, a.label + (a.in_air ? " (in the air)" : ""));
        w.note("a line behind each: its track; white: the flight");
    }
    if (!scene.points.empty()) {
        w.heading("POINTS");
        bool any_off_map = false;
        for (const ScenePoint& p : scene.points) {
            bool off_map = false;
            point_marker(scene, camera, p.position, &off_map);
            any_off_map = any_off_map || off_map;
            w.swatch_dot(off_map ? palette::kOffMap : p.color,
                         p.label + format(" (%.1f, %.1f", p.position[0], p.position[1]) +
                             format(", %.1f)", p.position[2]) + (off_map ? " off the map" : ""));
        }
        if (any_off_map) w.note("off the map: at the edge, the arrow its way");
    }

    // A scale bar of a round length near 120 pixels.
    const float ppm = camera.pixels_per_metre();
    float metres = 1.0f;
    for (float candidate : kRoundLengths)
        if (candidate * ppm <= 160.0f) metres = candidate;
    w.heading("SCALE");
    const float y = w.y() + 6.0f;
    canvas.line({w.x(), y}, {w.x() + metres * ppm, y}, 3.0f, palette::kText);
    canvas.line({w.x(), y - 6.0f}, {w.x(), y + 6.0f}, 2.0f, palette::kText);
    canvas.line({w.x() + metres * ppm, y - 6.0f}, {w.x() + metres * ppm, y + 6.0f}, 2.0f, palette::kText);
    canvas.text({w.x() + metres * ppm + 10.0f, y - 6.0f}, format("%.0f m", metres), kTextScale, palette::kText);
    w.y() += kLine;
    if (!camera.top_down()) w.note("(along x; depth is foreshortened)");
}

}  // namespace nl::picture
