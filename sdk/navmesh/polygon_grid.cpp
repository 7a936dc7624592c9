#include "navmesh/polygon_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace nl {
namespace {

// A polygon goes into the finest level in whose cells it spans at most kSpan cells across (so it is
// listed in at most (kSpan + 1)^2 cells), and each level's cells are kSpan times as wide as the
// finer one's. With 4, every polygon of a Recast navmesh (up to about 4 times the median size) is in
// the finest level, so a query visits the cells of one grid, as before the levels existed; only
// polygons far larger than the rest (a floor spanning a kilometre among 10 cm ones) go up.
constexpr int kSpan = 4;

// Clamped before the conversion: a search box far larger than the grid must not overflow an int.
int clamp_cell(double cell, int count) {
    return static_cast<int>(std::clamp(std::floor(cell), 0.0, double(count - 1)));
}

float extent_of(const Aabb& b) { return std::max(b.max.x() - b.min.x(), b.max.z() - b.min.z()); }

}  // namespace

int PolygonGrid::Level::cell_x(float x, float origin) const {
    return clamp_cell((double(x) - origin) * inverse_cell, columns);
}

int PolygonGrid::Level::cell_z(float z, float origin) const {
    return clamp_cell((double(z) - origin) * inverse_cell, rows);
}

void PolygonGrid::build(const std::vector<Aabb>& bounds, const Aabb& all) {
    const size_t count = bounds.size();
    origin_x_ = all.min.x();
    origin_z_ = all.min.z();
    const double width = std::max(1e-3, double(all.max.x()) - all.min.x());
    const double depth = std::max(1e-3, double(all.max.z()) - all.min.z());

    // The finest cells are as wide as the median polygon (a few huge polygons do not coarsen them, as
    // they would a mean), but never so fine that there are more than about 4 per polygon.
    double base = 1e-3;
    if (count > 0) {
        std::vector<float> extents(count);
        for (size_t p = 0; p < count; ++p) extents[p] = extent_of(bounds[p]);
        std::nth_element(extents.begin(), extents.begin() + count / 2, extents.end());
        base = std::max(base, double(extents[count / 2]));
    }
    const double max_cells = 4.0 * double(count) + 16.0;
    auto cells_for = [&](double cell) { return std::ceil(width / cell) * std::ceil(depth / cell); };
    base = std::max(base, std::sqrt(width * depth / max_cells));
    while (cells_for(base) > max_cells) base *= 1.25;  // a long, thin navmesh: the ceilings count too

    // Each polygon's level: the finest in which it spans at most kSpan cells.
    std::vector<uint8_t> level_of(count);
    int finest_unused = 0;
    for (size_t p = 0; p < count; ++p) {
        const double extent = extent_of(bounds[p]);
        int k = 0;
        for (double span = kSpan * base; span < extent; span *= kSpan) ++k;
        level_of[p] = static_cast<uint8_t>(k);
        finest_unused = std::max(finest_unused, k + 1);
    }
    // Grids for the levels that hold polygons, finest first.
    std::vector<int> grid_of(size_t(finest_unused), -1);
    for (const uint8_t k : level_of) grid_of[k] = 0;
    levels_.clear();
    double total_cells = 0.0;
    for (int k = 0; k < finest_unused; ++k) {
        if (grid_of[size_t(k)] < 0) continue;
        const double cell = base * std::pow(double(kSpan), k);
        const double cells = cells_for(cell);
        if (total_cells + cells >= double(std::numeric_limits<uint32_t>::max()))
            fail(ErrorCode::OutOfMemory, "the navmesh's point-location grid would need ", total_cells + cells,
                 " cells");
        grid_of[size_t(k)] = static_cast<int>(levels_.size());
        levels_.push_back(Level{1.0 / cell, static_cast<int>(std::ceil(width / cell)),
                                static_cast<int>(std::ceil(depth / cell)), static_cast<uint32_t>(total_cells)});
        total_cells += cells;
    }

    // Counting sort into compressed rows: two passes, no per-cell vectors.
    auto for_cells = [&](size_t p, auto&& fn) {
        const Level& level = levels_[size_t(grid_of[level_of[p]])];
        const Aabb& b = bounds[p];
        const int x0 = level.cell_x(b.min.x(), origin_x_), x1 = level.cell_x(b.max.x(), origin_x_);
        const int z0 = level.cell_z(b.min.z(), origin_z_), z1 = level.cell_z(b.max.z(), origin_z_);
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) fn(level.first_cell + size_t(z) * size_t(level.columns) + size_t(x));
    };
    cell_start_.assign(size_t(total_cells) + 1, 0);
    for (size_t p = 0; p < count; ++p)
        for_cells(p, [&](size_t c) { ++cell_start_[c + 1]; });  // a cell lists a polygon once
    uint64_t entries = 0;
    for (uint32_t& start : cell_start_) {
        entries += start;
        if (entries > std::numeric_limits<uint32_t>::max())
            fail(ErrorCode::OutOfMemory, "the navmesh's point-location grid would need more than 2^32 entries");
        start = static_cast<uint32_t>(entries);
    }
    cell_polygons_.resize(cell_start_.back());
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t p = 0; p < count; ++p)
        for_cells(p, [&](size_t c) { cell_polygons_[fill[c]++] = static_cast<uint32_t>(p); });
}

void PolygonGrid::visit(const Vec3& lo, const Vec3& hi, const std::vector<Aabb>& bounds,
                        FunctionRef<void(uint32_t)> fn) const {
    for (const Level& level : levels_) {
        const int x0 = level.cell_x(lo.x(), origin_x_), x1 = level.cell_x(hi.x(), origin_x_);
        const int z0 = level.cell_z(lo.z(), origin_z_), z1 = level.cell_z(hi.z(), origin_z_);
        for (int z = z0; z <= z1; ++z) {
            for (int x = x0; x <= x1; ++x) {
                const size_t c = level.first_cell + size_t(z) * size_t(level.columns) + size_t(x);
                for (uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
                    const uint32_t p = cell_polygons_[i];
                    const Aabb& b = bounds[p];
                    if (b.max.x() < lo.x() || b.min.x() > hi.x() || b.max.z() < lo.z() || b.min.z() > hi.z()) continue;
                    // A polygon in several visited cells is reported from the first of them only
                    // (its own first cell, or the box's first column or row: the cell it is listed in
                    // lies at or past its first).
                    if ((x != x0 && level.cell_x(b.min.x(), origin_x_) != x) ||
                        (z != z0 && level.cell_z(b.min.z(), origin_z_) != z))
                        continue;
                    fn(p);
                }
            }
        }
    }
}

}  // namespace nl
