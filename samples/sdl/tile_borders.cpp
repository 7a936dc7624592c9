#include "tile_borders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

namespace nl::picture {
namespace {

// How far a corner may be from a tile line and still lie on it: navmesh coordinates are kept on a
// grid of 1/1024 m, tile lines may fall between its steps.
constexpr float kOnLine = 2e-3f;

// The index of the tile line through `value` (lines at origin + i * width), or false when it is on none.
bool line_through(float value, float origin, float width, long long& index) {
    const double steps = (double(value) - double(origin)) / double(width);
    index = std::llround(steps);
    return std::fabs(double(value) - (double(origin) + double(index) * double(width))) <= kOnLine;
}

}  // namespace

TileBorders tile_borders(const samples::NavmeshContents& nav, float height, const float lo[3], const float hi[3]) {
    TileBorders out;
    if (!nav.tiled()) return out;
    const float w = nav.tile_width, x0 = nav.tile_origin[0], z0 = nav.tile_origin[1];
    auto x_of = [&](long long i) { return static_cast<float>(double(x0) + double(i) * double(w)); };
    auto z_of = [&](long long i) { return static_cast<float>(double(z0) + double(i) * double(w)); };
    // Each side once: (along x or along z, the line's index, the cell along it).
    std::set<std::tuple<int, long long, long long>> sides;
    for (const nl_tile_coord& t : nav.tiles) {
        sides.insert({0, t.z, t.x});        // along x, at the tile's lower z
        sides.insert({0, t.z + 1LL, t.x});  // ... its upper z
        sides.insert({1, t.x, t.z});        // along z, at its lower x
        sides.insert({1, t.x + 1LL, t.z});  // ... its upper x
    }
    for (const auto& [along_z, line, cell] : sides) {
        // The side on its line, from `cell` to the next, within the level's box.
        const int across = along_z ? 0 : 2, along = along_z ? 2 : 0;
        const float at = along_z ? x_of(line) : z_of(line);
        const float from = std::max(along_z ? z_of(cell) : x_of(cell), lo[along]);
        const float to = std::min(along_z ? z_of(cell + 1) : x_of(cell + 1), hi[along]);
        if (at < lo[across] - kOnLine || at > hi[across] + kOnLine || to <= from) continue;
        Point3 a{}, b{};
        a[1] = b[1] = height;
        a[across] = b[across] = at;
        a[along] = from;
        b[along] = to;
        out.squares.push_back({a, b});
    }
    for (const nl_nav_polygon& polygon : nav.polygons) {
        for (uint32_t k = 0; k < polygon.vertex_count; ++k) {
            const float* a = &nav.vertices[3 * size_t(polygon.vertices[k])];
            const float* b = &nav.vertices[3 * size_t(polygon.vertices[(k + 1) % polygon.vertex_count])];
            long long la = 0, lb = 0;
            const bool on_x_line = line_through(a[0], x0, w, la) && line_through(b[0], x0, w, lb) && la == lb;
            const bool on_z_line =
                !on_x_line && line_through(a[2], z0, w, la) && line_through(b[2], z0, w, lb) && la == lb;
            if ((on_x_line || on_z_line) && std::hypot(b[0] - a[0], b[2] - a[2]) > kOnLine)
                out.seams.push_back({Point3{a[0], a[1], a[2]}, Point3{b[0], b[1], b[2]}});
        }
    }
    return out;
}

std::string tile_borders_text(const samples::NavmeshContents& nav) {
    if (!nav.tiled()) return "";
    char text[96];
    std::snprintf(text, sizeof text, "tile borders (%zu %s of %g m)", nav.tiles.size(),
                  nav.tiles.size() == 1 ? "tile" : "tiles", std::round(double(nav.tile_width) * 100.0) / 100.0);
    return text;
}

}  // namespace nl::picture
