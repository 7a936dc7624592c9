#include "scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "canvas.h"
#include "legend.h"
#include "link_shape.h"
#include "palette.h"

namespace nl::picture {
namespace {

constexpr float kTitleHeight = 34.0f;
constexpr float kMargin = 16.0f;
constexpr float kObliquePitch = 55.0f;

SDL_FRect map_area(const ViewSettings& view) {
    const float legend = view.layers.legend ? kLegendWidth : 0.0f;
    return {kMargin, kTitleHeight + kMargin, static_cast<float>(view.width) - legend - 2 * kMargin,
            static_cast<float>(view.height) - kTitleHeight - 2 * kMargin};
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

// Cuts a triangle in four until its edges are shorter than `max_edge` metres, so that depth
// sorting by the centre works for big floors next to small walls.
void subdivide(const Point3& a, const Point3& b, const Point3& c, float max_edge, int depth,
               std::vector<std::array<Point3, 3>>& out) {
    auto dist2 = [](const Point3& p, const Point3& q) {
        return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
    };
    const float longest = std::max({dist2(a, b), dist2(b, c), dist2(c, a)});
    if (depth == 0 || longest <= max_edge * max_edge) {
        out.push_back({a, b, c});
        return;
    }
    auto mid = [](const Point3& p, const Point3& q) {
        return Point3{0.5f * (p[0] + q[0]), 0.5f * (p[1] + q[1]), 0.5f * (p[2] + q[2])};
    };
    const Point3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    subdivide(a, ab, ca, max_edge, depth - 1, out);
    subdivide(ab, b, bc, max_edge, depth - 1, out);
    subdivide(ca, bc, c, max_edge, depth - 1, out);
    subdivide(ab, bc, ca, max_edge, depth - 1, out);
}

// Triangles (x y z per vertex in `positions`, 3 indices each) lit from above, each piece coloured by
// `color_at` for its mean height.
template <typename ColorAt>
void collect_triangles(const std::vector<float>& positions, const std::vector<uint32_t>& triangles,
                       const Camera& camera, ColorAt color_at, std::vector<Surface>& out) {
    float view[3];
    camera.view_direction(view);
    const float light[3] = {0.3f, 0.88f, 0.37f};  // from above, a little from the south-east
    const float max_edge = camera.top_down() ? 1e9f : 2.0f;
    std::vector<std::array<Point3, 3>> pieces;
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
        pieces.clear();
        subdivide(p[0], p[1], p[2], max_edge, 6, pieces);
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

void collect_level(const Scene& scene, const Camera& camera, std::vector<Surface>& out) {
    const samples::Level& level = *scene.level;
    const float lo = level.info.bounds_min[1], hi = level.info.bounds_max[1];
    collect_triangles(level.positions, level.triangles, camera, [lo, hi](float y) {
        return mix(palette::kLowGround, palette::kHighGround, hi > lo ? (y - lo) / (hi - lo) : 0.5f);
    }, out);
}

// Platforms in one colour whatever their height, so that they stand out from the level they cross.
void collect_platforms(const Scene& scene, const Camera& camera, std::vector<Surface>& out) {
    for (const ScenePlatform& platform : scene.platforms)
        collect_triangles(platform.positions, platform.triangles, camera, [](float) { return palette::kPlatform; },
                          out);
}

void collect_navmesh(const samples::NavmeshContents& nav, const Camera& camera, const Layers& layers,
                     std::vector<Surface>& out) {
    if (layers.navmesh) {
        for (const nl_nav_polygon& polygon : nav.polygons) {
            Surface s;
            s.kind = Surface::NavPolygon;
            s.color = palette::kNavmeshFill;
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
        if (s.corners.size() == 3) canvas.triangle(s.corners[0], s.corners[1], s.corners[2], s.color);
        else canvas.convex_polygon(s.corners, s.color);
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

void draw_links(Canvas& canvas, const Camera& camera, const samples::NavmeshContents& nav, bool behind_paths) {
    // Drops first, jumps over them: there are fewer jumps and they cross gaps drops only fall into.
    // Under paths the links step back (thinner, fainter) so the routes read first.
    const float width = behind_paths ? 1.5f : 2.0f;
    const uint8_t alpha = behind_paths ? 150 : 255;
    for (nl_link_kind pass : {NL_LINK_DROP, NL_LINK_FIRST_PLUGIN_KIND, NL_LINK_MANUAL, NL_LINK_JUMP}) {
        for (const nl_link& link : nav.links) {
            const bool plugin = link.kind >= NL_LINK_FIRST_PLUGIN_KIND;
            if (plugin ? pass != NL_LINK_FIRST_PLUGIN_KIND : link.kind != pass) continue;
            const auto curve = projected(camera, traversal_curve(link.kind, link.start, link.end, link.apex));
            Rgba color = palette::link_kind(link.kind);
            // A disabled link steps back, and so does a cross link that does not hold now (its
            // platform is away: its end is drawn where the platform has taken it).
            if (!link.enabled || !link.holds) color = mix(color, palette::kBackground, 0.6f);
            color.a = alpha;
            Rgba shadow = palette::kShadow;
            shadow.a = static_cast<uint8_t>(shadow.a * alpha / 255);
            canvas.polyline(curve, width + 2.0f, shadow);
            canvas.polyline(curve, width, color);
            canvas.dot(curve.front(), width + 1.0f, color);
            if (link.bidirectional) canvas.dot(curve.back(), width + 1.0f, color);
            else canvas.arrow_head(curve[curve.size() - 3], curve.back(), 4.0f + 3.0f * width, color);
        }
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

void draw_points(Canvas& canvas, const Camera& camera, const Scene& scene) {
    for (const ScenePoint& point : scene.points) {
        const SDL_FPoint at = camera.project(point.position);
        canvas.dot(at, 10.0f, palette::kShadow);
        canvas.dot(at, 7.0f, point.color);
        canvas.text({at.x + 12.0f, at.y - 8.0f}, point.label, 2.0f, palette::kShadow);
        canvas.text({at.x + 11.0f, at.y - 9.0f}, point.label, 2.0f, palette::kText);
    }
}

SDL_FPoint projected_point(const Camera& camera, const std::array<float, 3>& p) { return camera.project(p.data()); }

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

    std::vector<Surface> surfaces;
    if (view.layers.level) {
        collect_level(scene, camera, surfaces);
        collect_platforms(scene, camera, surfaces);
    }
    if (scene.navmesh) collect_navmesh(*scene.navmesh, camera, view.layers, surfaces);
    for (const ScenePlatform& platform : scene.platforms)
        collect_navmesh(platform.navmesh, camera, view.layers, surfaces);
    draw_surfaces(canvas, surfaces);
    if (view.layers.links) {
        const bool behind_paths = view.layers.paths && !scene.paths.empty();
        if (scene.navmesh) draw_links(canvas, camera, *scene.navmesh, behind_paths);
        for (const ScenePlatform& platform : scene.platforms)
            draw_links(canvas, camera, platform.navmesh, behind_paths);
    }
    if (view.layers.paths) draw_paths(canvas, camera, scene);
    draw_points(canvas, camera, scene);
    if (view.layers.agents) draw_agents(canvas, camera, scene);

    canvas.text({kMargin, 10.0f}, scene.title, 2.0f, palette::kText);
    if (view.layers.legend) draw_legend(canvas, scene, view, camera);
}

}  // namespace nl::picture
