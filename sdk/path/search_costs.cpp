#include "path/search_costs.h"

#include <algorithm>
#include <utility>

#include "path/link_filter.h"

namespace nl {

float heuristic_scale(const PathGraph& graph, const PathQuery& query) {
    float scale = 1.0f;  // areas the costs do not list cost 1
    for (float cost : query.area_costs) {
        if (cost > 0.0f) scale = std::min(scale, cost);
    }
    return cheapest_link_rate(graph, query, scale);
}

float cheapest_link_rate(const PathGraph& graph, const PathQuery& query, float at_most) {
    float rate = at_most;
    if (graph.cheapest_link_per_metre() >= rate) return rate;
    for (const StoredLink& stored : graph.links()) {
        const Link& l = stored.link;
        if (l.enabled && l.cost_modifier < rate &&
            (can_take(l, false, query.capabilities) || (l.bidirectional && can_take(l, true, query.capabilities))))
            rate = l.cost_modifier;
    }
    return rate;
}

namespace {

// The least and the most cost per metre of the navmesh's areas the body may enter (areas it keeps
// out of are obstacles, not rates); both 0 when it may enter none.
std::pair<float, float> walk_cost_range(const PathGraph& graph, const PathQuery& query) {
    if (query.area_costs.empty()) return {1.0f, 1.0f};
    float least = 0.0f, most = 0.0f;
    const std::array<uint64_t, 4>& present = graph.areas_present();
    for (uint32_t area = 0; area < 256; ++area) {
        if (((present[area >> 6] >> (area & 63)) & 1u) == 0) continue;
        const float cost = query.area_cost(static_cast<uint8_t>(area));
        if (cost <= 0.0f) continue;
        least = least == 0.0f ? cost : std::min(least, cost);
        most = std::max(most, cost);
    }
    return {least, most};
}

}  // namespace

float uniform_walk_cost(const PathGraph& graph, const PathQuery& query) {
    const auto [least, most] = walk_cost_range(graph, query);
    if (least == 0.0f) return 1.0f;
    return least == most ? least : 0.0f;
}

float cheapest_walk_cost(const PathGraph& graph, const PathQuery& query) {
    const float least = walk_cost_range(graph, query).first;
    return least == 0.0f ? 1.0f : least;
}

}  // namespace nl
