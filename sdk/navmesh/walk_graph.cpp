#include "navmesh/walk_graph.h"

#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

namespace nl {

WalkGraph::WalkGraph(const NavMesh& mesh) : mesh_(mesh), first_polygon_(mesh.vertex_count() + 1, 0) {
    for (uint32_t p = 0; p < mesh.polygon_count(); ++p)
        for (uint32_t k = 0; k < mesh.corner_count(p); ++k) ++first_polygon_[mesh.corner(p, k) + 1];
    for (size_t v = 1; v < first_polygon_.size(); ++v) first_polygon_[v] += first_polygon_[v - 1];
    polygons_.resize(first_polygon_.back());
    std::vector<uint32_t> fill(first_polygon_.begin(), first_polygon_.end() - 1);
    for (uint32_t p = 0; p < mesh.polygon_count(); ++p)
        for (uint32_t k = 0; k < mesh.corner_count(p); ++k) polygons_[fill[mesh.corner(p, k)]++] = p;

    // Surfaces: a flood through portals from each polygon not yet reached, in polygon order.
    surface_.assign(mesh.polygon_count(), kNoPolygon);
    std::vector<uint32_t> stack;
    for (uint32_t first = 0; first < mesh.polygon_count(); ++first) {
        if (surface_[first] != kNoPolygon) continue;
        surface_[first] = first;
        stack.push_back(first);
        while (!stack.empty()) {
            const uint32_t p = stack.back();
            stack.pop_back();
            for (uint32_t k = 0; k < mesh.corner_count(p); ++k) {
                const uint32_t q = mesh.neighbour(p, k);
                if (q == kNoPolygon || surface_[q] != kNoPolygon) continue;
                surface_[q] = first;
                stack.push_back(q);
            }
        }
    }
}

float WalkGraph::walk_within(const Vec3& from, uint32_t from_polygon, const Vec3& to, uint32_t to_polygon, float limit) const {
    constexpr float kNone = std::numeric_limits<float>::infinity();
    if (from_polygon >= mesh_.polygon_count() || to_polygon >= mesh_.polygon_count()) return kNone;
    if (from_polygon == to_polygon) {
        const float d = (to - from).norm();
        return d <= limit ? d : kNone;
    }
    // Nodes are vertices; the goal is reached from any corner of its polygon.
    std::unordered_map<uint32_t, float> best;
    using Entry = std::pair<float, uint32_t>;  // (walked + straight line to the goal, vertex)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    auto reach = [&](uint32_t v, float walked) {
        const float estimate = walked + (to - mesh_.vertex(v)).norm();
        if (estimate > limit) return;
        const auto [it, fresh] = best.emplace(v, walked);
        if (!fresh) {
            if (it->second <= walked) return;
            it->second = walked;
        }
        open.emplace(estimate, v);
    };
    for (uint32_t k = 0; k < mesh_.corner_count(from_polygon); ++k) {
        const uint32_t v = mesh_.corner(from_polygon, k);
        reach(v, (mesh_.vertex(v) - from).norm());
    }
    float found = kNone;
    while (!open.empty()) {
        const auto [estimate, v] = open.top();
        open.pop();
        if (estimate >= found) break;  // nothing left can be shorter
        const float walked = best[v];
        if (walked + (to - mesh_.vertex(v)).norm() < estimate) continue;  // a stale entry
        for (uint32_t i = first_polygon_[v]; i < first_polygon_[v + 1]; ++i) {
            const uint32_t p = polygons_[i];
            if (p == to_polygon) found = std::min(found, walked + (to - mesh_.vertex(v)).norm());
            for (uint32_t k = 0; k < mesh_.corner_count(p); ++k) {
                const uint32_t w = mesh_.corner(p, k);
                if (w != v) reach(w, walked + (mesh_.vertex(w) - mesh_.vertex(v)).norm());
            }
        }
    }
    return found <= limit ? found : kNone;
}

}  // namespace nl
