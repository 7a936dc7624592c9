#include "level/winding_check.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nl {
namespace {

constexpr float kDegrees = 3.14159265358979f / 180.0f;
constexpr float kLeastColumnSpacing = 0.1f;  // m

// One surface of the mesh met by a column: its height and which way it faces (+1 a floor as given,
// -1 a floor turned over, 0 too steep either way).
struct Crossing {
    float y;
    int8_t floor;
};

}  // namespace

WindingEstimate estimate_winding(const TriangleMesh& mesh, size_t first, size_t count, float max_slope_degrees,
                                 float height) {
    WindingEstimate out;
    if (count == 0) return out;
    float min_x = INFINITY, min_z = INFINITY, max_x = -INFINITY, max_z = -INFINITY;
    for (size_t t = first; t < first + count; ++t)
        for (const uint32_t v : mesh.triangles[t]) {
            const Vec3& p = mesh.vertices[v];
            min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
            min_z = std::min(min_z, p.z()), max_z = std::max(max_z, p.z());
        }
    const float spacing =
        std::max(kLeastColumnSpacing, std::max(max_x - min_x, max_z - min_z) / float(kWindingColumns));
    const uint32_t nx = uint32_t(std::floor((max_x - min_x) / spacing)) + 1,
                   nz = uint32_t(std::floor((max_z - min_z) / spacing)) + 1;
    const float walkable = walkable_normal_y(max_slope_degrees);
    // Where a triangle meets a column, in two passes (count, then fill) into one array in triangle
    // order: a vector per column was most of the estimate's time.
    std::vector<uint32_t> first_crossing(size_t(nx) * nz + 1, 0);
    std::vector<Crossing> crossings;
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<uint32_t> next;
        if (pass == 1) {
            for (size_t j = 1; j < first_crossing.size(); ++j) first_crossing[j] += first_crossing[j - 1];
            crossings.resize(first_crossing.back());
            next.assign(first_crossing.begin(), first_crossing.end() - 1);
        }
        for (size_t t = first; t < first + count; ++t) {
            const Vec3& a = mesh.vertices[mesh.triangles[t][0]];
            const Vec3& b = mesh.vertices[mesh.triangles[t][1]];
            const Vec3& c = mesh.vertices[mesh.triangles[t][2]];
            const Vec3 normal = (b - a).cross(c - a);
            const float length = normal.norm();
            // Seen from above (twice its signed area): a wall has none and no column meets it.
            const float area = normal.y();
            if (!(length > 0.0f) || area == 0.0f) continue;
            const int8_t floor = normal.y() >= walkable * length ? 1 : -normal.y() >= walkable * length ? -1 : 0;
            const float lo_x = std::min({a.x(), b.x(), c.x()}), hi_x = std::max({a.x(), b.x(), c.x()});
            const float lo_z = std::min({a.z(), b.z(), c.z()}), hi_z = std::max({a.z(), b.z(), c.z()});
            const uint32_t i0 = uint32_t(std::max(0.0f, std::ceil((lo_x - min_x) / spacing - 0.5f)));
            const uint32_t k0 = uint32_t(std::max(0.0f, std::ceil((lo_z - min_z) / spacing - 0.5f)));
            for (uint32_t i = i0; i < nx; ++i) {
                const float x = min_x + (float(i) + 0.5f) * spacing;
                if (x > hi_x) break;
                for (uint32_t k = k0; k < nz; ++k) {
                    const float z = min_z + (float(k) + 0.5f) * spacing;
                    if (z > hi_z) break;
                    // Barycentric weights seen from above (the signed areas of the sub-triangles).
                    const float u = (b.z() - c.z()) * (x - c.x()) + (c.x() - b.x()) * (z - c.z());
                    const float v = (c.z() - a.z()) * (x - c.x()) + (a.x() - c.x()) * (z - c.z());
                    const float whole = (b.z() - c.z()) * (a.x() - c.x()) + (c.x() - b.x()) * (a.z() - c.z());
                    const float s = whole < 0.0f ? -1.0f : 1.0f;
                    const float w = whole - u - v;
                    if (s * u < 0.0f || s * v < 0.0f || s * w < 0.0f) continue;
                    const size_t column = size_t(i) * nz + k;
                    if (pass == 0) {
                        ++first_crossing[column + 1];
                    } else {
                        crossings[next[column]++] = {(u * a.y() + v * b.y() + w * c.y()) / whole, floor};
                    }
                }
            }
        }
    }
    const float cell = spacing * spacing;
    for (size_t c = 0; c + 1 < first_crossing.size(); ++c) {
        const auto column = crossings.begin() + first_crossing[c];
        const size_t size = first_crossing[c + 1] - first_crossing[c];
        std::sort(column, column + size, [](const Crossing& p, const Crossing& q) { return p.y < q.y; });
        for (size_t j = 0; j < size; ++j) {
            // Free above it up to the next surface of the mesh (one a hair above is the same surface,
            // met twice on a shared edge).
            size_t above = j + 1;
            while (above < size && column[above].y - column[j].y < 1e-3f) ++above;
            if (above < size && column[above].y - column[j].y < height) continue;
            if (column[j].floor > 0) out.floor_as_given += cell;
            if (column[j].floor < 0) out.floor_turned_over += cell;
            j = above - 1;  // the rest met on this height are the same surface
        }
    }
    return out;
}

float walkable_normal_y(float max_slope_degrees) { return std::cos(max_slope_degrees * kDegrees); }

bool looks_turned_over(const WindingEstimate& estimate) {
    return estimate.floor_turned_over > 2.0f * estimate.floor_as_given &&
           estimate.floor_turned_over > estimate.floor_as_given + 1.0f;
}

}  // namespace nl
