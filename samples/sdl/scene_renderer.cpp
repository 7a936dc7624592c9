#include "scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "canvas.h"
#include "drop_runs.h"
#include "height_slice.h"
#include "island_colors.h"
#include "legend.h"
#include "link_shape.h"
#include "palette.h"
#include "tile_borders.h"

namespace nl::picture {
namespace {

constexpr float kTitleHeight = 34.0f;
constexpr float kMargin = 16.0f;
constexpr float kLabelColumn = 52.0f;  // left of the map: the grid's z labels
constexpr float kLabelRow = 18.0f;     // above the map: the grid's x labels
constexpr float kLabelScale = 1.4f;
constexpr float kObliquePitch = 55.0f;

SDL_FRect map_area(const ViewSettings& view) {
    const float legend = view.layers.legend ? kLegendWidth : 0.0f;
    const float left = kMargin + kLabelColumn, top = kTitleHeight + kMargin + kLabelRow;
    return {left, top, static_cast<float>(view.width) - legend - left - kMargin,
            static_cast<float>(view.height) - top - kMargin};
}

Rgba mix(Rgba a, Rgba b, float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    auto m = [t](uint8_t x, uint8_t y) { return static_cast<uint8_t>(std::lround(x + (y - x) * t)); };
    return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a)};
}

Rgba shaded(Rgba c, float light) {
    auto s = [light](uint8_t x) { return static_cast<uint8_t>(std::clamp(x * light, 0.0f, 255.0f)); };
    return {s(c.r), s(c.g), s(c.b), c.a};
}

// One thing to paint in depth order: a level triangle, a navmesh polygon or an outline edge.
struct Surface {
    float nearness;
    enum Kind { LevelTriangle, NavPolygon, Outline } kind;
    std::vector<SDL_FPoint> corners;
    Rgba color;
};

float longest_edge_squared(const Point3& a, const Point3& b, const Point3& c) {
    auto dist2 = [](const Point3& p, const Point3& q) {
        return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
    };
    return std::max({dist2(a, b), dist2(b, c), dist2(c, a)});
}

enum class Piece { Keep, Drop, Split };

// Cuts triangle a b c in four at its edges' midpoints for as long as `judge(a, b, c, last)` says
// Split (`last` once `depth` cuts are made: it must then keep or drop), and keeps the pieces it
// says Keep.
template <typename Judge>
void split_triangle(const Point3& a, const Point3& b, const Point3& c, int depth, const Judge& judge,
                    std::vector<std::array<Point3, 3>>& out) {
    const Piece piece = judge(a, b, c, depth == 0);
    if (piece != Piece::Split) {
        if (piece == Piece::Keep) out.push_back({a, b, c});
        return;
    }
    auto mid = [](const Point3& p, const Point3& q) {
        return Point3{0.5f * (p[0] + q[0]), 0.5f * (p[1] + q[1]), 0.5f * (p[2] + q[2])};
    };
    const Point3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    split_triangle(a, ab, ca, depth - 1, judge, out);
    split_triangle(ab, b, bc, depth - 1, judge, out);
    split_triangle(ca, bc, c, depth - 1, judge, out);
    split_triangle(ab, bc, ca, depth - 1, judge, out);
}

// Cuts a triangle in four until its edges are shorter than `max_edge` metres, so that depth
// sorting by the centre works for big floors next to small walls.
void subdivide(const Point3& a, const Point3& b, const Point3& c, float max_edge, int depth,
               std::vector<std::array<Point3, 3>>& out) {
    split_triangle(
        a, b, c, depth,
        [max_edge](const Point3& p, const Point3& q, const Point3& r, bool last) {
            return last || longest_edge_squared(p, q, r) <= max_edge * max_edge ? Piece::Keep : Piece::Split;
        },
        out);
}

// The parts of triangle a b c not above the slice's cut (all of it without a slice): a triangle the
// cut crosses is cut in four until its pieces are as small as the slice's cells.
void below_cut(const Point3& a, const Point3& b, const Point3& c, const HeightSlice* slice, int depth,
               std::vector<std::array<Point3, 3>>& out) {
    if (!slice || !slice->active()) {
        out.push_back({a, b, c});
        return;
    }
    split_triangle(
        a, b, c, depth,
        [slice](const Point3& p, const Point3& q, const Point3& r, bool last) {
            const Point3 centre{(p[0] + q[0] + r[0]) / 3.0f, (p[1] + q[1] + r[1]) / 3.0f, (p[2] + q[2] + r[2]) / 3.0f};
            const int above =
                slice->above(p.data()) + slice->above(q.data()) + slice->above(r.data()) + slice->above(centre.data());
            if (above == 0) return Piece::Keep;
            if (above == 4 || last || longest_edge_squared(p, q, r) <= slice->cell_size() * slice->cell_size())
                return slice->above(centre.data()) ? Piece::Drop : Piece::Keep;
            return Piece::Split;
        },
        out);
}

// Triangles (x y z per vertex in `positions`, 3 indices each) lit from above, each piece coloured by
// `color_at` for its mean height; with a slice, only what is below its cut.
template <typename ColorAt>
void collect_triangles(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                       const Camera& camera, ColorAt color_at, const HeightSlice* slice, std::vector<Surface>& out) {
    float view[3];
    camera.view_direction(view);
    const float light[3] = {0.3f, 0.88f, 0.37f};  // from above, a little from the south-east
    const float max_edge = camera.top_down() ? 1e9f : 2.0f;
    std::vector<std::array<Point3, 3>> kept, pieces;
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        Point3 p[3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) p[i][k] = positions[3 * size_t(triangles[t + i]) + k];
        const float e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const float e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length < 1e-12f) continue;
        for (float& c : n) c /= length;
        // Front faces only: a ceiling seen from above is its back, so enclosed levels (tunnels,
        // rooms) show their floors; and walls seen edge-on from straight above are left out.
        const float facing = -(n[0] * view[0] + n[1] * view[1] + n[2] * view[2]);
        if (facing < 0.02f) continue;
        const float lambert = std::max(0.0f, n[0] * light[0] + n[1] * light[1] + n[2] * light[2]);
        kept.clear();
        below_cut(p[0], p[1], p[2], slice, 10, kept);
        for (const auto& part : kept) {
            pieces.clear();
            subdivide(part[0], part[1], part[2], max_edge, 6, pieces);
            for (const auto& piece : pieces) {
                const float mean_y = (piece[0][1] + piece[1][1] + piece[2][1]) / 3.0f;
                Surface s;
                s.kind = Surface::LevelTriangle;
                s.color = shaded(color_at(mean_y), 0.35f + 0.65f * lambert);
                s.nearness = 0.0f;
                for (const Point3& q : piece) {
                    s.corners.push_back(camera.project(q.data()));
                    s.nearness += camera.nearness(q.data()) / 3.0f;
                }
                out.push_back(std::move(s));
            }
        }
    }
}

void collect_level(const Scene& scene, const Camera& camera, const HeightSlice* slice, std::vector<Surface>& out) {
    const samples::Level& level = *scene.level;
    float lo, hi;
    drawn_heights(scene, slice, lo, hi);
    collect_triangles(
        level.positions, level.triangles, camera,
        [lo, hi](float y) {
            return mix(palette::kLowGround, palette::kHighGround, hi > lo ? (y - lo) / (hi - lo) : 0.5f);
        },
        slice, out);
}

// Platforms in one colour whatever their height, so that they stand out from the level they cross.
void collect_platforms(const Scene& scene, const Camera& camera, std::vector<Surface>& out) {
    for (const ScenePlatform& platform : scene.platforms)
        collect_triangles(
            platform.positions, platform.triangles, camera, [](float) { return palette::kPlatform; }, nullptr, out);
}

// A navmesh's polygons (coloured by island when `islands` is given), and its outline.
void collect_navmesh(const samples::NavmeshContents& nav, const SceneIslands* islands, const Camera& camera,
                     const Layers& layers, std::vector<Surface>& out) {
    if (layers.navmesh) {
        const IslandColors colors = islands ? island_colors(*islands) : IslandColors{};
        for (uint32_t p = 0; p < nav.polygons.size(); ++p) {
            const nl_nav_polygon& polygon = nav.polygons[p];
            Surface s;
            s.kind = Surface::NavPolygon;
            s.color = islands ? colors.of_polygon(*islands, p) : palette::kNavmeshFill;
            s.nearness = -1e30f;
            for (uint32_t k = 0; k < polygon.vertex_count; ++k) {
                const float* v = &nav.vertices[3 * size_t(polygon.vertices[k])];
                s.corners.push_back(camera.project(v));
                s.nearness = std::max(s.nearness, camera.nearness(v));
            }
            s.nearness += 0.05f;  // just above the surface it lies on
            out.push_back(std::move(s));
        }
    }
    if (layers.boundary) {
        for (const nl_boundary_edge& edge : nav.boundary_edges) {
            Surface s;
            s.kind = Surface::Outline;
            s.color = palette::kBoundary;
            s.corners = {camera.project(edge.start), camera.project(edge.end)};
            s.nearness = std::max(camera.nearness(edge.start), camera.nearness(edge.end)) + 0.06f;
            out.push_back(std::move(s));
        }
    }
}

void draw_surfaces(Canvas& canvas, std::vector<Surface>& surfaces) {
    std::stable_sort(surfaces.begin(), surfaces.end(),
                     [](const Surface& a, const Surface& b) { return a.nearness < b.nearness; });
    for (const Surface& s : surfaces) {
        if (s.kind == Surface::Outline) {
            canvas.line(s.corners[0], s.corners[1], 2.5f, s.color);
            continue;
        }
        if (s.corners.size() == 3)
            canvas.triangle(s.corners[0], s.corners[1], s.corners[2], s.color);
        else
            canvas.convex_polygon(s.corners, s.color);
        if (s.kind == Surface::NavPolygon) {
            std::vector<SDL_FPoint> ring = s.corners;
            ring.push_back(ring.front());
            canvas.polyline(ring, 1.0f, palette::kNavmeshEdge);
        }
    }
}

std::vector<SDL_FPoint> projected(const Camera& camera, const std::vector<Point3>& curve) {
    std::vector<SDL_FPoint> out;
    out.reserve(curve.size());
    for (const Point3& p : curve) out.push_back(camera.project(p.data()));
    return out;
}

// One link's curve, with a dot at each end it may be entered from and an arrow head at the end of a
// one-way link (`arrow` false: a dot at its start only, as a drop of a run drawn by another's arrow).
void draw_link(Canvas& canvas, const Camera& camera, const nl_link& link, float width, uint8_t alpha) {
    const auto curve = projected(camera, traversal_curve(link.kind, link.start, link.end, link.apex));
    Rgba color = palette::link_kind(link.kind);
    // A disabled link steps back, and so does a cross link that does not hold now (its platform
    // is away: its end is drawn where the platform has taken it).
    if (!link.enabled || !link.holds) color = mix(color, palette::kBackground, 0.6f);
    color.a = alpha;
    Rgba shadow = palette::kShadow;
    shadow.a = static_cast<uint8_t>(shadow.a * alpha / 255);
    canvas.polyline(curve, width + 2.0f, shadow);
    canvas.polyline(curve, width, color);
    canvas.dot(curve.front(), width + 1.0f, color);
    if (link.bidirectional)
        canvas.dot(curve.back(), width + 1.0f, color);
    else
        canvas.arrow_head(curve[curve.size() - 3], curve.back(), 4.0f + 3.0f * width, color);
}

// A run of drops along one ledge: a line through their take-offs, and one arrow.
void draw_drop_run(Canvas& canvas, const Camera& camera, const std::vector<nl_link>& links, const DropRun& run,
                   float width, uint8_t alpha) {
    if (run.links.size() > 1) {
        std::vector<SDL_FPoint> ledge;
        for (uint32_t i : run.links) ledge.push_back(camera.project(links[i].start));
        Rgba color = palette::kDrop;
        if (!links[run.arrow].enabled || !links[run.arrow].holds) color = mix(color, palette::kBackground, 0.6f);
        color.a = alpha;
        Rgba shadow = palette::kShadow;
        shadow.a = static_cast<uint8_t>(shadow.a * alpha / 255);
        canvas.polyline(ledge, width + 3.0f, shadow);
        canvas.polyline(ledge, width + 1.0f, color);
    }
    draw_link(canvas, camera, links[run.arrow], width, alpha);
}

// Where a link's number goes: a drop's at its take-off (drops of a run share one curve), any
// other's half-way along its curve.
SDL_FPoint number_place(const Camera& camera, const nl_link& link) {
    if (link.kind == NL_LINK_DROP) return camera.project(link.start);
    const auto curve = traversal_curve(link.kind, link.start, link.end, link.apex);
    return camera.project(curve[curve.size() / 2].data());
}

void draw_links(Canvas& canvas, const Camera& camera, const samples::NavmeshContents& nav, bool behind_paths,
                bool numbers) {
    // Drops first (one arrow per ledge run), jumps over them: there are fewer jumps and they cross
    // gaps drops only fall into. Under paths the links step back (thinner, fainter) so the routes
    // read first.
    const float width = behind_paths ? 1.5f : 2.0f;
    const uint8_t alpha = behind_paths ? 150 : 255;
    for (const DropRun& run : drop_runs(nav.links)) draw_drop_run(canvas, camera, nav.links, run, width, alpha);
    for (nl_link_kind pass : {NL_LINK_DROP, NL_LINK_FIRST_PLUGIN_KIND, NL_LINK_MANUAL, NL_LINK_JUMP}) {
        for (const nl_link& link : nav.links) {
            const bool plugin = link.kind >= NL_LINK_FIRST_PLUGIN_KIND;
            if (plugin ? pass != NL_LINK_FIRST_PLUGIN_KIND : link.kind != pass) continue;
            if (link.kind == NL_LINK_DROP && !link.bidirectional) continue;  // in a run, above
            draw_link(canvas, camera, link, width, alpha);
        }
    }
    if (!numbers) return;
    // The index in the navmesh's link list: the link's place in LINKS.json and its #N in navlink path.
    // Links from one place (a fan of drops) stack their numbers downwards.
    std::vector<SDL_FPoint> anchors;
    for (size_t i = 0; i < nav.links.size(); ++i) {
        SDL_FPoint at = number_place(camera, nav.links[i]);
        int below = 0;
        for (const SDL_FPoint& other : anchors) below += std::hypot(other.x - at.x, other.y - at.y) < 3.0f;
        anchors.push_back(at);
        at.y += 11.0f * static_cast<float>(below);
        const std::string text = std::to_string(i);
        const float w = Canvas::text_width(text, 1.3f);
        canvas.rectangle({at.x + 3.0f, at.y - 12.0f, w + 3.0f, 10.0f}, palette::kShadow);
        canvas.text({at.x + 4.5f, at.y - 11.0f}, text, 1.3f, palette::link_kind(nav.links[i].kind));
    }
}

void draw_paths(Canvas& canvas, const Camera& camera, const Scene& scene) {
    for (const PathLayer& path : scene.paths) {
        std::vector<SDL_FPoint> line;
        for (size_t i = 0; i + 1 < path.points.size(); ++i) {
            const nl_path_point& p = path.points[i];
            const nl_path_point& q = path.points[i + 1];
            const auto piece = projected(camera, traversal_curve(p.segment, p.position, q.position, p.apex));
            line.insert(line.end(), line.empty() ? piece.begin() : piece.begin() + 1, piece.end());
        }
        canvas.polyline(line, 9.0f, palette::kShadow);
        canvas.polyline(line, 5.0f, path.color);
        for (size_t i = 0; i + 1 < path.points.size(); ++i)
            if (path.points[i].segment != NL_SEGMENT_WALK)
                canvas.dot(camera.project(path.points[i].position), 5.0f, path.color);  // where a link starts
    }
}

// A label beside a marker at `at`, on the side where it stays inside `room`.
void marker_label(Canvas& canvas, SDL_FPoint at, const std::string& label, const SDL_FRect& room) {
    const float w = Canvas::text_width(label, 2.0f);
    const float x = at.x + 12.0f + w <= room.x + room.w ? at.x + 11.0f : at.x - 11.0f - w;
    const float y = std::clamp(at.y - 9.0f, room.y, room.y + room.h - 14.0f);
    canvas.text({x + 1.0f, y + 1.0f}, label, 2.0f, palette::kShadow);
    canvas.text({x, y}, label, 2.0f, palette::kText);
}

// Each point where it is; a point off the map at the map's edge, a pink arrow pointing its way.
void draw_points(Canvas& canvas, const Camera& camera, const Scene& scene) {
    const SDL_FRect room = map_rect(scene, camera);
    for (const ScenePoint& point : scene.points) {
        bool off_map = false;
        const SDL_FPoint at = point_marker(scene, camera, point.position, &off_map);
        if (!off_map) {
            canvas.dot(at, 10.0f, palette::kShadow);
            canvas.dot(at, 7.0f, point.color);
            marker_label(canvas, at, point.label, room);
            continue;
        }
        const SDL_FPoint real = camera.project(point.position);
        const float dx = real.x - at.x, dy = real.y - at.y, length = std::max(std::hypot(dx, dy), 1e-3f);
        const SDL_FPoint tip{at.x + dx / length * kOffMapArrow, at.y + dy / length * kOffMapArrow};
        canvas.arrow_head(at, tip, kOffMapArrow + 2.0f, palette::kShadow);
        canvas.dot(at, 10.0f, palette::kShadow);
        canvas.arrow_head(at, tip, kOffMapArrow, palette::kOffMap);
        canvas.dot(at, 7.0f, palette::kOffMap);
        marker_label(canvas, at, point.label + ": off the map", room);
    }
}

std::string metres_label(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(value == 0.0f ? 0.0f : value));
    return text;
}

// Lines every grid step of x and z, labelled at the map's top (x) and left (z) edges, so a point's
// coordinates can be read off the picture. Seen from an angle they lie at grid_height.
void draw_grid(Canvas& canvas, const Camera& camera, const Scene& scene) {
    const float* lo = scene.level->info.bounds_min;
    const float* hi = scene.level->info.bounds_max;
    const float step = grid_step(camera.pixels_per_metre());
    const float y = grid_height(scene);
    for (float x = std::ceil(lo[0] / step) * step; x <= hi[0] + 1e-3f; x += step) {
        const float a[3] = {x, y, lo[2]}, b[3] = {x, y, hi[2]};
        const SDL_FPoint top = camera.project(a);
        canvas.line(top, camera.project(b), 1.0f, palette::kGrid);
        const std::string text = metres_label(x);
        canvas.text({top.x - 0.5f * Canvas::text_width(text, kLabelScale), top.y - kLabelRow + 2.0f}, text, kLabelScale,
                    palette::kGridLabel);
    }
    for (float z = std::ceil(lo[2] / step) * step; z <= hi[2] + 1e-3f; z += step) {
        const float a[3] = {lo[0], y, z}, b[3] = {hi[0], y, z};
        const SDL_FPoint left = camera.project(a);
        canvas.line(left, camera.project(b), 1.0f, palette::kGrid);
        const std::string text = metres_label(z);
        canvas.text({left.x - 6.0f - Canvas::text_width(text, kLabelScale), left.y - 4.0f}, text, kLabelScale,
                    palette::kGridLabel);
    }
    // The axes' names in the corner: x across (labels along the top), z down (along the left).
    const float corner[3] = {lo[0], y, lo[2]};
    const SDL_FPoint c = camera.project(corner);
    canvas.text({c.x - kLabelColumn + 2.0f, c.y - kLabelRow + 2.0f}, "x>", kLabelScale, palette::kText);
    canvas.text({c.x - kLabelColumn + 2.0f, c.y + 10.0f}, "z", kLabelScale, palette::kText);
    canvas.arrow_head({c.x - kLabelColumn + 5.0f, c.y + 20.0f}, {c.x - kLabelColumn + 5.0f, c.y + 30.0f}, 7.0f,
                      palette::kText);
}

SDL_FPoint projected_point(const Camera& camera, const std::array<float, 3>& p) { return camera.project(p.data()); }

// A tiled navmesh's loaded tiles: each square outlined thin along the tile lines (seen from an angle,
// at the grid's height), and the navmesh's edges on those lines over it at their own heights.
void draw_tile_borders(Canvas& canvas, const Camera& camera, const Scene& scene, const samples::NavmeshContents& nav) {
    const TileBorders borders =
        tile_borders(nav, grid_height(scene), scene.level->info.bounds_min, scene.level->info.bounds_max);
    for (const auto& side : borders.squares)
        canvas.line(projected_point(camera, side[0]), projected_point(camera, side[1]), 1.0f, palette::kTileSquare);
    for (const auto& seam : borders.seams)
        canvas.line(projected_point(camera, seam[0]), projected_point(camera, seam[1]), 2.0f, palette::kTileBorder);
}

void draw_agents(Canvas& canvas, const Camera& camera, const Scene& scene) {
    for (const SceneAgent& agent : scene.agents) {
        std::vector<SDL_FPoint> track;
        for (const auto& p : agent.track) track.push_back(projected_point(camera, p));
        Rgba faint = agent.color;
        faint.a = 150;
        if (track.size() > 1) canvas.polyline(track, 2.0f, faint);
        if (agent.trajectory.size() > 1) {  // the rest of the flight, as the generator checked it
            std::vector<SDL_FPoint> curve;
            for (const auto& p : agent.trajectory) curve.push_back(projected_point(camera, p));
            canvas.polyline(curve, 4.0f, palette::kShadow);
            canvas.polyline(curve, 2.0f, palette::kText);
        }
        const SDL_FPoint at = camera.project(agent.position);
        const float body = std::max(4.0f, agent.radius * camera.pixels_per_metre());
        canvas.dot(at, body + 3.0f, agent.in_air ? palette::kText : palette::kShadow);
        canvas.dot(at, body, agent.color);
    }
}

}  // namespace

int fitted_height(const Scene& scene, const ViewSettings& view) {
    // The map at the width available, with its proportions, but never shorter than the legend.
    ViewSettings tall = view;
    tall.height = 100000;
    const SDL_FRect area = map_area(tall);
    const float* lo = scene.level->info.bounds_min;
    const float* hi = scene.level->info.bounds_max;
    const float pitch = (view.oblique ? kObliquePitch : 90.0f) * static_cast<float>(M_PI) / 180.0f;
    const float width = std::max(hi[0] - lo[0], 1e-3f);
    const float depth = (hi[2] - lo[2]) * std::sin(pitch) + (hi[1] - lo[1]) * std::fabs(std::cos(pitch));
    const float map_height = area.w * depth / width;
    const float needed = kTitleHeight + 2 * kMargin + map_height;
    return static_cast<int>(
        std::ceil(std::clamp(needed, view.layers.legend ? kLegendMinHeight : 200.0f, 4.0f * view.width)));
}

Camera scene_camera(const Scene& scene, const ViewSettings& view) {
    return Camera(scene.level->info.bounds_min, scene.level->info.bounds_max, map_area(view),
                  view.oblique ? kObliquePitch : 90.0f);
}

void draw_scene(SDL_Renderer* renderer, const Scene& scene, const ViewSettings& view) {
    Canvas canvas(renderer);
    canvas.clear(palette::kBackground);
    const Camera camera = scene_camera(scene, view);

    // Roofs cut away: level surfaces above the navmesh under them (height_slice.h).
    const std::optional<HeightSlice> slice = scene.level_navmesh() && !view.layers.roofs
                                                 ? std::optional<HeightSlice>(std::in_place, *scene.level_navmesh())
                                                 : std::nullopt;
    std::vector<Surface> surfaces;
    if (view.layers.level) {
        collect_level(scene, camera, slice ? &*slice : nullptr, surfaces);
        collect_platforms(scene, camera, surfaces);
    }
    if (scene.navmesh) collect_navmesh(*scene.navmesh, scene.islands, camera, view.layers, surfaces);
    for (const ScenePlatform& platform : scene.platforms)
        collect_navmesh(platform.navmesh, nullptr, camera, view.layers, surfaces);
    draw_surfaces(canvas, surfaces);
    if (view.layers.grid) draw_grid(canvas, camera, scene);
    if (view.layers.tile_borders && scene.navmesh && scene.navmesh->tiled())
        draw_tile_borders(canvas, camera, scene, *scene.navmesh);
    if (view.layers.links) {
        const bool behind_paths = view.layers.paths && !scene.paths.empty();
        if (scene.navmesh) draw_links(canvas, camera, *scene.navmesh, behind_paths, view.layers.link_numbers);
        for (const ScenePlatform& platform : scene.platforms)
            draw_links(canvas, camera, platform.navmesh, behind_paths, false);
    }
    if (view.layers.paths) draw_paths(canvas, camera, scene);
    draw_points(canvas, camera, scene);
    if (view.layers.agents) draw_agents(canvas, camera, scene);

    canvas.text({kMargin, 10.0f}, scene.title, 2.0f, palette::kText);
    if (view.layers.legend) draw_legend(canvas, scene, view, camera, slice ? &*slice : nullptr);
}

}  // namespace nl::picture
