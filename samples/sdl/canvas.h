// Drawing primitives over an SDL_Renderer that SDL2 lacks: filled triangles and polygons with
// per-vertex colour, lines of any width, dots, arrow heads, and text in stb_easy_font's small
// built-in bitmap font (no font file, no SDL_ttf).
#pragma once

#include <SDL2/SDL.h>

#include <string>
#include <vector>

#include "scene.h"

namespace nl::picture {

class Canvas {
public:
    explicit Canvas(SDL_Renderer* renderer);

    void clear(Rgba color);
    void triangle(SDL_FPoint a, SDL_FPoint b, SDL_FPoint c, Rgba color);
    void convex_polygon(const std::vector<SDL_FPoint>& corners, Rgba color);
    void line(SDL_FPoint a, SDL_FPoint b, float width, Rgba color);
    void polyline(const std::vector<SDL_FPoint>& points, float width, Rgba color);
    void dot(SDL_FPoint centre, float radius, Rgba color);
    // A filled arrow head at `tip`, pointing from `from` towards `tip`.
    void arrow_head(SDL_FPoint from, SDL_FPoint tip, float size, Rgba color);
    void rectangle(const SDL_FRect& rect, Rgba color);
    // Text with its top-left corner at `at`; `scale` multiplies the font's 6-pixel line height.
    void text(SDL_FPoint at, const std::string& text, float scale, Rgba color);
    static float text_width(const std::string& text, float scale);

    SDL_Renderer* renderer() const { return renderer_; }

private:
    SDL_Renderer* renderer_;
};

}  // namespace nl::picture
