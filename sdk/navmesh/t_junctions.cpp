#include "navmesh/t_junctions.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "navmesh/edge_pairs.h"

namespace nl {
namespace {

// The ends of unmatched edges in square x-z cells, to find those near an edge.
class EndGrid {
public:
    EndGrid(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& ends, float cell) : cell_(cell) {
        for (uint32_t v : ends) cells_[key(cell_of(vertices[v].x()), cell_of(vertices[v].z()))].push_back(v);
    }

    // The ends in the cells the box [lo, hi] (x-z) touches, each once, in vertex order.
    void near(float x0, float z0, float x1, float z1, std::vector<uint32_t>& out) const {
        out.clear();
        for (int64_t cx = cell_of(x0); cx <= cell_of(x1); ++cx)
            for (int64_t cz = cell_of(z0); cz <= cell_of(z1); ++cz) {
                const auto found = cells_.find(key(cx, cz));
                if (found != cells_.end()) out.insert(out.end(), found->second.begin(), found->second.end());
            }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

private:
    int64_t cell_of(float v) const { return static_cast<int64_t>(std::floor(double(v) / cell_)); }
    static uint64_t key(int64_t cx, int64_t cz) { return (uint64_t(cx) << 32) ^ uint64_t(uint32_t(cz)); }

    double cell_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

}  // namespace

JoinedPolygons join_t_junctions(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& first_corner,
                                const std::vector<uint32_t>& corners, const TJunctionTolerance& tolerance,
                                uint32_t max_corners) {
    const uint32_t polygons = static_cast<uint32_t>(first_corner.size() - 1);
    const auto on_border = [&](uint32_t v) {
        return tolerance.on_tile_border && !tolerance.on_tile_border->empty() && (*tolerance.on_tile_border)[v];
    };
    const float widest = std::max(tolerance.anywhere, tolerance.tile_border);
    auto next_corner = [&](uint32_t slot, uint32_t p) {
        return slot + 1 < first_corner[p + 1] ? corners[slot + 1] : corners[first_corner[p]];
    };

    // The unmatched edges: a key met once.
    const std::vector<KeyedEdge> edges = edges_by_vertex_pair(first_corner, corners);
    std::vector<uint8_t> unmatched(corners.size(), 0);
    std::vector<uint32_t> ends;
    double length_sum = 0.0;
    uint32_t unmatched_count = 0;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key) ++j;
        if (j - i == 1) {
            unmatched[edges[i].slot] = 1;
            const uint32_t a = uint32_t(edges[i].key >> 32), b = uint32_t(edges[i].key);
            ends.push_back(a);
            ends.push_back(b);
            length_sum += std::hypot(vertices[a].x() - vertices[b].x(), vertices[a].z() - vertices[b].z());
            ++unmatched_count;
        }
        i = j;
    }

    JoinedPolygons out;
    if (unmatched_count == 0) return out;
    out.moved_corner.resize(corners.size());
    out.first_corner.reserve(first_corner.size());
    out.corners.reserve(corners.size());
    out.first_corner.push_back(0);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    const float cell = std::max(float(length_sum / unmatched_count), 4.0f * widest + 1e-3f);
    const EndGrid grid(vertices, ends, cell);

    // The vertices on one edge, ordered along it.
    std::vector<uint32_t> near;
    std::vector<std::pair<double, uint32_t>> on_edge;
    auto vertices_on = [&](uint32_t a, uint32_t b) {
        on_edge.clear();
        const Vec3& pa = vertices[a];
        const Vec3& pb = vertices[b];
        const double dx = double(pb.x()) - pa.x(), dz = double(pb.z()) - pa.z();
        const double length = std::hypot(dx, dz);
        const bool edge_on_border = on_border(a) && on_border(b);
        const float reach = edge_on_border ? widest : tolerance.anywhere;
        if (reach <= 0.0f || length <= 2.0 * reach) return;
        grid.near(std::min(pa.x(), pb.x()) - reach, std::min(pa.z(), pb.z()) - reach, std::max(pa.x(), pb.x()) + reach,
                  std::max(pa.z(), pb.z()) + reach, near);
        for (uint32_t v : near) {
            if (v == a || v == b) continue;
            const bool across_tiles = edge_on_border && on_border(v);
            const double within = across_tiles ? widest : tolerance.anywhere;
            const double within_height =
                across_tiles ? std::max(tolerance.anywhere, tolerance.tile_border_height) : tolerance.anywhere;
            if (within <= 0.0) continue;
            const Vec3& q = vertices[v];
            const double qx = double(q.x()) - pa.x(), qz = double(q.z()) - pa.z();
            const double along = (qx * dx + qz * dz) / length;  // metres from a
            const double across = std::fabs(qx * dz - qz * dx) / length;
            if (along <= within || along >= length - within || across > within) continue;
            const double t = along / length;
            const double height = pa.y() + t * (double(pb.y()) - pa.y());
            if (std::fabs(q.y() - height) > within_height) continue;
            on_edge.push_back({t, v});
        }
        std::sort(on_edge.begin(), on_edge.end());
    };

    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t start = static_cast<uint32_t>(out.corners.size());
        uint32_t room = max_corners - (first_corner[p + 1] - first_corner[p]);
        for (uint32_t slot = first_corner[p]; slot < first_corner[p + 1]; ++slot) {
            out.moved_corner[slot] = static_cast<uint8_t>(out.corners.size() - start);
            out.corners.push_back(corners[slot]);
            if (!unmatched[slot]) continue;
            vertices_on(corners[slot], next_corner(slot, p));
            if (on_edge.empty()) continue;
            if (on_edge.size() > room) {
                ++out.left_open;
                continue;
            }
            room -= static_cast<uint32_t>(on_edge.size());
            for (const auto& [t, v] : on_edge) out.corners.push_back(v);
            out.inserted += static_cast<uint32_t>(on_edge.size());
        }
        out.first_corner.push_back(static_cast<uint32_t>(out.corners.size()));
    }
    return out;
}

}  // namespace nl
