// The square tiles a tiled navmesh is cut into: a grid on the x-z plane, each tile built on its own
// (Recast's tiled pipeline) and joined to its neighbours along the lines between them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace nl {

// The largest tile index (either way) a navmesh holds: x + 1 never overflows.
constexpr double kMaxTileIndex = double(1 << 30);

struct TileCoord {
    int32_t x = 0;
    int32_t z = 0;
    // Row by row (z, then x): the order tiles are joined in, whatever order they came in.
    friend bool operator<(const TileCoord& a, const TileCoord& b) { return std::tie(a.z, a.x) < std::tie(b.z, b.x); }
    friend bool operator==(const TileCoord& a, const TileCoord& b) { return a.x == b.x && a.z == b.z; }
    friend bool operator!=(const TileCoord& a, const TileCoord& b) { return !(a == b); }
};

struct TileGrid {
    float origin_x = 0.0f;    // x of tile (0, 0)'s lower corner
    float origin_z = 0.0f;    // z of the same
    float tile_width = 0.0f;  // metres; 0: not tiled

    bool tiled() const { return tile_width > 0.0f; }
    // The lines between tiles: tile (x, z) spans [line_x(x), line_x(x + 1)] in x.
    double line_x(int64_t x) const { return double(origin_x) + double(x) * tile_width; }
    double line_z(int64_t z) const { return double(origin_z) + double(z) * tile_width; }
    // The tile (x, z) lies in; on a line between two, the higher one. Saturates far off the grid.
    TileCoord tile_at(float x, float z) const {
        auto index = [&](double v, float origin) {
            const double i = std::floor((v - origin) / tile_width);
            return static_cast<int32_t>(std::clamp(i, -2147483648.0, 2147483647.0));
        };
        return TileCoord{index(x, origin_x), index(z, origin_z)};
    }
    friend bool operator==(const TileGrid& a, const TileGrid& b) {
        return a.origin_x == b.origin_x && a.origin_z == b.origin_z && a.tile_width == b.tile_width;
    }
    friend bool operator!=(const TileGrid& a, const TileGrid& b) { return !(a == b); }
};

// Which tiles a navmesh holds: its grid and the tiles in row order (TileCoord's <). A solo navmesh
// has no grid and no tiles.
struct TileLayout {
    TileGrid grid;
    std::vector<TileCoord> tiles;

    // Whether the tile at `coord` is one of them.
    bool holds(const TileCoord& coord) const { return std::binary_search(tiles.begin(), tiles.end(), coord); }
    // Whether the point (x, z) lies on a tile it holds; true for a solo navmesh (no grid).
    bool holds_point(float x, float z) const { return !grid.tiled() || holds(grid.tile_at(x, z)); }
};

}  // namespace nl
