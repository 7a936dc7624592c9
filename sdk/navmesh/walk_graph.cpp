#include "navmesh/walk_graph.h"

#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

namespace nl {

WalkGraph::WalkGraph(const NavMesh& navmesh) : navmesh_(navmesh) {
    // Surfaces: a flood through portals from each polygon not yet reached, in polygon order.
    surface_.assign(navmesh.polygon_count(), kNoPolygon);
    std::vector<uint32_t> stack;
    for (uint32_t first = 0; first < navmesh.polygon_count(); ++first) {
        if (surface_[first] != kNoPolygon) continue;
        surface_[first] = first;
        stack.push_back(first);
        while (!stack.empty()) {
            const uint32_t p = stack.back();
            stack.pop_back();
            for (uint32_t k = 0; k < navmesh.corner_count(p); ++k) {
                const uint32_t q = navmesh.neighbour(p, k);
                if (q == kNoPolygon || surface_[q] != kNoPolygon) continue;
                surface_[q] = first;
                stack.push_back(q);
            }
        }
    }
}

float WalkGraph::walk_within(const Vec3& from, uint32_t from_polygon, const Vec3& to, uint32_t to_polygon,
                             float limit) const {
    constexpr float kNone = std::numeric_limits<float>::infinity();
    if (from_polygon >= navmesh_.polygon_count() || to_polygon >= navmesh_.polygon_count()) return kNone;
    if (from_polygon == to_polygon) {
        const float d = (to - from).norm();
        return d <= limit ? d : kNone;
    }
    // States are (polygon, one of its corners): a straight line joins any two corners of a convex
    // polygon, and a walk enters a neighbour at a corner of the portal it shares with it.
    auto state = [](uint32_t polygon, uint32_t vertex) { return (uint64_t(polygon) << 32) | vertex; };
    std::unordered_map<uint64_t, float> best;
    using Entry = std::pair<float, uint64_t>;  // (walked + straight line to the goal, state)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    auto reach = [&](uint32_t polygon, uint32_t v, float walked) {
        const float estimate = walked + (to - navmesh_.vertex(v)).norm();
        if (estimate > limit) return;
        const auto [it, fresh] = best.emplace(state(polygon, v), walked);
        if (!fresh) {
            if (it->second <= walked) return;
            it->second = walked;
        }
        open.emplace(estimate, state(polygon, v));
    };
    for (uint32_t k = 0; k < navmesh_.corner_count(from_polygon); ++k) {
        const uint32_t v = navmesh_.corner(from_polygon, k);
        reach(from_polygon, v, (navmesh_.vertex(v) - from).norm());
    }
    float found = kNone;
    while (!open.empty()) {
        const auto [estimate, s] = open.top();
        open.pop();
        if (estimate >= found) break;  // nothing left can be shorter
        const auto p = static_cast<uint32_t>(s >> 32), v = static_cast<uint32_t>(s);
        const float walked = best[s];
        if (walked + (to - navmesh_.vertex(v)).norm() < estimate) continue;  // a stale entry
        if (p == to_polygon) {
            found = std::min(found, walked + (to - navmesh_.vertex(v)).norm());
            continue;
        }
        const uint32_t corners = navmesh_.corner_count(p);
        for (uint32_t k = 0; k < corners; ++k) {
            const uint32_t w = navmesh_.corner(p, k);
            if (w != v) reach(p, w, walked + (navmesh_.vertex(w) - navmesh_.vertex(v)).norm());
            if (w != v) continue;
            // Across the two edges at v, where they are portals.
            for (const uint32_t edge : {k, (k + corners - 1) % corners}) {
                const uint32_t q = navmesh_.neighbour(p, edge);
                if (q != kNoPolygon) reach(q, v, walked);
            }
        }
    }
    return found <= limit ? found : kNone;
}

}  // namespace nl
