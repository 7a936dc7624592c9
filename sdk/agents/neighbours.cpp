#include "agents/neighbours.h"

#include <algorithm>
#include <cmath>

namespace nl {

void NeighbourGrid::build(const std::vector<Vec3>& positions, const std::vector<uint8_t>& grounded, float cell) {
    positions_ = &positions;
    cell_ = std::max(cell, 0.1f);
    float lo_x = 0.0f, lo_z = 0.0f, hi_x = 0.0f, hi_z = 0.0f;
    bool any = false;
    for (size_t i = 0; i < positions.size(); ++i) {
        if (!grounded[i]) continue;
        const Vec3& p = positions[i];
        if (!any) lo_x = hi_x = p.x(), lo_z = hi_z = p.z(), any = true;
        lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
        lo_z = std::min(lo_z, p.z()), hi_z = std::max(hi_z, p.z());
    }
    origin_x_ = lo_x;
    origin_z_ = lo_z;
    // Bounded: a crowd spread over kilometres gets coarser cells, not millions of them.
    const double width = double(hi_x) - lo_x, depth = double(hi_z) - lo_z;
    while ((width / cell_ + 1.0) * (depth / cell_ + 1.0) > 4.0 * double(positions.size()) + 64.0) cell_ *= 2.0f;
    columns_ = any ? int(width / cell_) + 1 : 0;
    rows_ = any ? int(depth / cell_) + 1 : 0;
    cell_start_.assign(size_t(columns_) * rows_ + 1, 0u);
    auto cell_of = [&](const Vec3& p) {
        const int cx = std::clamp(int((p.x() - origin_x_) / cell_), 0, columns_ - 1);
        const int cz = std::clamp(int((p.z() - origin_z_) / cell_), 0, rows_ - 1);
        return size_t(cz) * columns_ + cx;
    };
    for (size_t i = 0; i < positions.size(); ++i)
        if (grounded[i]) ++cell_start_[cell_of(positions[i]) + 1];
    for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    members_.assign(cell_start_.back(), 0u);
    std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t i = 0; i < positions.size(); ++i)
        if (grounded[i]) members_[fill[cell_of(positions[i])]++] = static_cast<uint32_t>(i);
}

void NeighbourGrid::visit(const Vec3& p, float range, FunctionRef<void(uint32_t)> visit) const {
    if (columns_ == 0) return;
    const int x0 = std::clamp(int(std::floor((p.x() - range - origin_x_) / cell_)), 0, columns_ - 1);
    const int x1 = std::clamp(int(std::floor((p.x() + range - origin_x_) / cell_)), 0, columns_ - 1);
    const int z0 = std::clamp(int(std::floor((p.z() - range - origin_z_) / cell_)), 0, rows_ - 1);
    const int z1 = std::clamp(int(std::floor((p.z() + range - origin_z_) / cell_)), 0, rows_ - 1);
    const float range2 = range * range;
    for (int z = z0; z <= z1; ++z) {
        for (int x = x0; x <= x1; ++x) {
            const size_t c = size_t(z) * columns_ + x;
            for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
                const uint32_t j = members_[k];
                const Vec3& q = (*positions_)[j];
                const float dx = q.x() - p.x(), dz = q.z() - p.z();
                if (dx * dx + dz * dz <= range2) visit(j);
            }
        }
    }
}

size_t NeighbourGrid::nearest(const Vec3& p, float range, uint32_t self, uint32_t* out, size_t most) const {
    constexpr size_t kMost = 16;
    most = std::min(most, kMost);
    if (columns_ == 0 || most == 0) return 0;
    std::pair<float, uint32_t> best[kMost];  // (squared distance, index), ascending
    size_t count = 0;
    const float range2 = range * range;
    auto consider = [&](int x, int z) {
        const size_t c = size_t(z) * columns_ + x;
        for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
            const uint32_t j = members_[k];
            if (j == self) continue;
            const Vec3& q = (*positions_)[j];
            const float dx = q.x() - p.x(), dz = q.z() - p.z();
            const std::pair<float, uint32_t> candidate{dx * dx + dz * dz, j};
            if (candidate.first > range2) continue;
            if (count == most && !(candidate < best[most - 1])) continue;
            size_t at = count < most ? count++ : most - 1;
            for (; at > 0 && candidate < best[at - 1]; --at) best[at] = best[at - 1];
            best[at] = candidate;
        }
    };
    const int x0 = std::clamp(int(std::floor((p.x() - range - origin_x_) / cell_)), 0, columns_ - 1);
    const int x1 = std::clamp(int(std::floor((p.x() + range - origin_x_) / cell_)), 0, columns_ - 1);
    const int z0 = std::clamp(int(std::floor((p.z() - range - origin_z_) / cell_)), 0, rows_ - 1);
    const int z1 = std::clamp(int(std::floor((p.z() + range - origin_z_) / cell_)), 0, rows_ - 1);
    const int cx = std::clamp(int(std::floor((p.x() - origin_x_) / cell_)), x0, x1);
    const int cz = std::clamp(int(std::floor((p.z() - origin_z_) / cell_)), z0, z1);
    const int rings = std::max(std::max(cx - x0, x1 - cx), std::max(cz - z0, z1 - cz));
    // A cell r + 1 rings out is at least r cells away from p along one axis (p in its cell, or beyond
    // the grid on the far side); the slack covers the rounding of cell indices.
    const float slack = 1e-3f + 1e-6f * (std::fabs(p.x() - origin_x_) + std::fabs(p.z() - origin_z_));
    for (int r = 0; r <= rings; ++r) {
        for (int z = std::max(cz - r, z0); z <= std::min(cz + r, z1); ++z) {
            if (z == cz - r || z == cz + r) {
                for (int x = std::max(cx - r, x0); x <= std::min(cx + r, x1); ++x) consider(x, z);
            } else {
                if (cx - r >= x0) consider(cx - r, z);
                if (cx + r <= x1) consider(cx + r, z);
            }
        }
        const float clear = float(r) * cell_ - slack;  // every agent not yet seen is farther than this
        if (count == most && clear > 0.0f && best[most - 1].first < clear * clear) break;
    }
    for (size_t k = 0; k < count; ++k) out[k] = best[k].second;
    return count;
}

}  // namespace nl
