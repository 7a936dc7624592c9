#include "height_slice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nl::picture {
namespace {

constexpr float kNone = -std::numeric_limits<float>::infinity();
constexpr int kMaxCells = 1 << 20;  // a 1024 x 1024 grid at most: cells grow on huge levels

// Distance seen from above from (x, z) to the polygon (0 inside it; corners in order, convex).
float distance_xz(const std::vector<std::array<float, 2>>& corners, float x, float z) {
    bool inside = true;
    float nearest = std::numeric_limits<float>::max();
    float side_sign = 0.0f;
    for (size_t k = 0; k < corners.size(); ++k) {
        const auto& a = corners[k];
        const auto& b = corners[(k + 1) % corners.size()];
        const float ex = b[0] - a[0], ez = b[1] - a[1];
        const float cross = ex * (z - a[1]) - ez * (x - a[0]);
        if (cross != 0.0f) {
            if (side_sign == 0.0f)
                side_sign = cross > 0 ? 1.0f : -1.0f;
            else if ((cross > 0 ? 1.0f : -1.0f) != side_sign)
                inside = false;
        }
        const float length2 = ex * ex + ez * ez;
        const float t = length2 > 0.0f ? std::clamp(((x - a[0]) * ex + (z - a[1]) * ez) / length2, 0.0f, 1.0f) : 0.0f;
        nearest = std::min(nearest, std::hypot(x - a[0] - t * ex, z - a[1] - t * ez));
    }
    return inside ? 0.0f : nearest;
}

}  // namespace

HeightSlice::HeightSlice(const samples::NavmeshContents& nav) {
    if (nav.polygons.empty()) return;
    float lo[2] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    float hi[2] = {-lo[0], -lo[1]};
    float top = kNone;
    for (size_t v = 0; v + 2 < nav.vertices.size(); v += 3) {
        lo[0] = std::min(lo[0], nav.vertices[v]);
        hi[0] = std::max(hi[0], nav.vertices[v]);
        lo[1] = std::min(lo[1], nav.vertices[v + 2]);
        hi[1] = std::max(hi[1], nav.vertices[v + 2]);
        top = std::max(top, nav.vertices[v + 1]);
    }
    fallback_ = top + kClearance;
    origin_[0] = lo[0] - kReach;
    origin_[1] = lo[1] - kReach;
    const float width = hi[0] - lo[0] + 2 * kReach, depth = hi[1] - lo[1] + 2 * kReach;
    cell_ = std::max(0.25f, std::sqrt(width * depth / kMaxCells));
    columns_ = static_cast<int>(std::ceil(width / cell_)) + 1;
    rows_ = static_cast<int>(std::ceil(depth / cell_)) + 1;
    cut_.assign(size_t(columns_) * size_t(rows_), kNone);

    std::vector<std::array<float, 2>> corners;
    for (const nl_nav_polygon& polygon : nav.polygons) {
        corners.clear();
        float low = std::numeric_limits<float>::max(), high = kNone;
        float box_lo[2] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
        float box_hi[2] = {-box_lo[0], -box_lo[1]};
        for (uint32_t k = 0; k < polygon.vertex_count; ++k) {
            const float* v = &nav.vertices[3 * size_t(polygon.vertices[k])];
            corners.push_back({v[0], v[2]});
            low = std::min(low, v[1]);
            high = std::max(high, v[1]);
            box_lo[0] = std::min(box_lo[0], v[0]);
            box_hi[0] = std::max(box_hi[0], v[0]);
            box_lo[1] = std::min(box_lo[1], v[2]);
            box_hi[1] = std::max(box_hi[1], v[2]);
        }
        const int c0 = std::max(0, static_cast<int>(std::floor((box_lo[0] - kReach - origin_[0]) / cell_)));
        const int c1 = std::min(columns_ - 1, static_cast<int>(std::floor((box_hi[0] + kReach - origin_[0]) / cell_)));
        const int r0 = std::max(0, static_cast<int>(std::floor((box_lo[1] - kReach - origin_[1]) / cell_)));
        const int r1 = std::min(rows_ - 1, static_cast<int>(std::floor((box_hi[1] + kReach - origin_[1]) / cell_)));
        const float* n = polygon.normal;
        const float* c = polygon.centre;
        for (int r = r0; r <= r1; ++r) {
            for (int col = c0; col <= c1; ++col) {
                const float x = origin_[0] + (static_cast<float>(col) + 0.5f) * cell_;
                const float z = origin_[1] + (static_cast<float>(r) + 0.5f) * cell_;
                // A cell counts when any of it is within reach: its centre within reach plus half its diagonal.
                if (distance_xz(corners, x, z) > kReach + 0.71f * cell_) continue;
                // The polygon's plane there, kept within its corners' heights.
                const float y = n[1] > 1e-3f ? c[1] - (n[0] * (x - c[0]) + n[2] * (z - c[2])) / n[1] : high;
                float& cut = cut_[size_t(r) * size_t(columns_) + size_t(col)];
                cut = std::max(cut, std::clamp(y, low, high) + kClearance);
            }
        }
    }
}

float HeightSlice::cut_at(float x, float z) const {
    const int col = static_cast<int>(std::floor((x - origin_[0]) / cell_));
    const int row = static_cast<int>(std::floor((z - origin_[1]) / cell_));
    if (col < 0 || row < 0 || col >= columns_ || row >= rows_) return fallback_;
    const float cut = cut_[size_t(row) * size_t(columns_) + size_t(col)];
    return cut == kNone ? fallback_ : cut;
}

}  // namespace nl::picture
