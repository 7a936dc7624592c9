#include "canvas.h"

#include <cmath>

// stb_easy_font: a tiny vector bitmap font as quads, header-only, from Debian's libstb-dev. Its
// functions are static; the unused ones are fine.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace nl::picture {
namespace {

SDL_Vertex vertex(SDL_FPoint p, Rgba c) { return SDL_Vertex{p, SDL_Color{c.r, c.g, c.b, c.a}, SDL_FPoint{0, 0}}; }

}  // namespace

Canvas::Canvas(SDL_Renderer* renderer) : renderer_(renderer) {
    SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
}

void Canvas::clear(Rgba c) {
    SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a);
    SDL_RenderClear(renderer_);
}

void Canvas::triangle(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, Rgba color) {
    const SDL_Vertex v[3] = {vertex(a, color), vertex(b, color), vertex(c, color)};
    SDL_RenderGeometry(renderer_, nullptr, v, 3, nullptr, 0);
}

void Canvas::convex_polygon(const std::vector<SDL_FPoint>& corners, Rgba color) {
    if (corners.size() < 3) return;
    std::vector<SDL_Vertex> v;
    v.reserve((corners.size() - 2) * 3);
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
        v.push_back(vertex(corners[0], color));
        v.push_back(vertex(corners[k], color));
        v.push_back(vertex(corners[k + 1], color));
    }
    SDL_RenderGeometry(renderer_, nullptr, v.data(), static_cast<int>(v.size()), nullptr, 0);
}

void Canvas::line(SDL_FPoint a, SDL_FPoint b, float width, Rgba color) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 1e-4f) return;
    const float nx = -dy / length * 0.5f * width, ny = dx / length * 0.5f * width;
    const SDL_FPoint q[4] = {{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
    const SDL_Vertex v[6] = {vertex(q[0], color), vertex(q[1], color), vertex(q[2], color),
                             vertex(q[0], color), vertex(q[2], color), vertex(q[3], color)};
    SDL_RenderGeometry(renderer_, nullptr, v, 6, nullptr, 0);
}

void Canvas::polyline(const std::vector<SDL_FPoint>& points, float width, Rgba color) {
    for (size_t i = 1; i < points.size(); ++i) line(points[i - 1], points[i], width, color);
    // Round the joints so thick lines do not crack at corners.
    if (width > 2.5f)
        for (size_t i = 1; i + 1 < points.size(); ++i) dot(points[i], 0.5f * width, color);
}

void Canvas::dot(SDL_FPoint centre, float radius, Rgba color) {
    const int sides = 12;
    std::vector<SDL_FPoint> ring;
    for (int i = 0; i < sides; ++i) {
        const float t = 2.0f * static_cast<float>(M_PI) * static_cast<float>(i) / sides;
        ring.push_back({centre.x + radius * std::cos(t), centre.y + radius * std::sin(t)});
    }
    convex_polygon(ring, color);
}

void Canvas::arrow_head(SDL_FPoint from, SDL_FPoint tip, float size, Rgba color) {
    const float dx = tip.x - from.x, dy = tip.y - from.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 1e-4f) return;
    const float ux = dx / length, uy = dy / length;
    const SDL_FPoint back{tip.x - ux * size, tip.y - uy * size};
    triangle(tip, {back.x - uy * size * 0.5f, back.y + ux * size * 0.5f},
             {back.x + uy * size * 0.5f, back.y - ux * size * 0.5f}, color);
}

void Canvas::rectangle(const SDL_FRect& rect, Rgba c) {
    SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a);
    SDL_RenderFillRectF(renderer_, &rect);
}

void Canvas::text(SDL_FPoint at, const std::string& text, float scale, Rgba color) {
    thread_local static char buffer[65536];  // 270 bytes per character at most: long lines are cut, not overrun
    std::string copy = text;
    const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer, sizeof buffer);
    SDL_SetRenderDrawColor(renderer_, color.r, color.g, color.b, color.a);
    for (int q = 0; q < quads; ++q) {
        // Each quad: 4 vertices of 16 bytes (x, y, z floats and a colour); corners 0 and 2 are opposite.
        const float* v0 = reinterpret_cast<const float*>(buffer + q * 64);
        const float* v2 = reinterpret_cast<const float*>(buffer + q * 64 + 32);
        const SDL_FRect r{at.x + v0[0] * scale, at.y + v0[1] * scale, (v2[0] - v0[0]) * scale, (v2[1] - v0[1]) * scale};
        SDL_RenderFillRectF(renderer_, &r);
    }
}

float Canvas::text_width(const std::string& text, float scale) {
    std::string copy = text;
    return static_cast<float>(stb_easy_font_width(copy.data())) * scale;
}

}  // namespace nl::picture
