#include "navmesh/polygon_grid.h"

#include <algorithm>
#include <cmath>

namespace nl {

void PolygonGrid::build(const std::vector<Aabb>& bounds, const Aabb& all) {
    const auto count = static_cast<uint32_t>(bounds.size());
    // Cells about the size of an average polygon: each cell then lists a handful.
    double mean_extent = 0.0;
    for (const Aabb& b : bounds) mean_extent += std::max(b.max.x() - b.min.x(), b.max.z() - b.min.z());
    mean_extent = count ? mean_extent / count : 1.0;
    const double width = std::max(1e-3f, all.max.x() - all.min.x());
    const double depth = std::max(1e-3f, all.max.z() - all.min.z());
    double cell = std::max(mean_extent, 1e-3);
    // Bound the cell count by the polygon count so empty space costs little memory.
    const double max_cells = 4.0 * count + 16.0;
    if ((width / cell) * (depth / cell) > max_cells) cell = std::sqrt(width * depth / max_cells);
    inverse_cell_ = static_cast<float>(1.0 / cell);
    origin_x_ = all.min.x();
    origin_z_ = all.min.z();
    columns_ = std::max(1, static_cast<int>(std::ceil(width / cell)));
    rows_ = std::max(1, static_cast<int>(std::ceil(depth / cell)));

    // Counting sort into compressed rows: two passes, no per-cell vectors.
    cell_start_.assign(size_t(columns_) * rows_ + 1, 0);
    auto for_cells = [&](const Aabb& b, auto&& fn) {
        const int x0 = cell_x(b.min.x()), x1 = cell_x(b.max.x());
        const int z0 = cell_z(b.min.z()), z1 = cell_z(b.max.z());
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) fn(size_t(z) * columns_ + x);
    };
    for (const Aabb& b : bounds) for_cells(b, [&](size_t c) { ++cell_start_[c + 1]; });
    for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    cell_polygons_.resize(cell_start_.back());
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (uint32_t p = 0; p < count; ++p) for_cells(bounds[p], [&](size_t c) { cell_polygons_[fill[c]++] = p; });
}

namespace {

// Clamped before the conversion: a search box far larger than the grid must not overflow an int.
int clamp_cell(double cell, int count) { return static_cast<int>(std::clamp(std::floor(cell), 0.0, double(count - 1))); }

}  // namespace

int PolygonGrid::cell_x(float x) const { return clamp_cell((double(x) - origin_x_) * inverse_cell_, columns_); }

int PolygonGrid::cell_z(float z) const { return clamp_cell((double(z) - origin_z_) * inverse_cell_, rows_); }

void PolygonGrid::visit(const Vec3& lo, const Vec3& hi, const std::vector<Aabb>& bounds,
                        FunctionRef<void(uint32_t)> fn) const {
    const int x0 = cell_x(lo.x()), x1 = cell_x(hi.x());
    const int z0 = cell_z(lo.z()), z1 = cell_z(hi.z());
    for (int z = z0; z <= z1; ++z) {
        for (int x = x0; x <= x1; ++x) {
            const size_t c = size_t(z) * columns_ + x;
            for (uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
                const uint32_t p = cell_polygons_[i];
                const Aabb& b = bounds[p];
                if (b.max.x() < lo.x() || b.min.x() > hi.x() || b.max.z() < lo.z() || b.min.z() > hi.z()) continue;
                // A polygon spanning several visited cells is reported from the first of them only.
                if (std::max(cell_x(b.min.x()), x0) != x || std::max(cell_z(b.min.z()), z0) != z) continue;
                fn(p);
            }
        }
    }
}

}  // namespace nl
