#include "path_plan.h"

#include <algorithm>
#include <cmath>

#include "sample_error.h"

namespace nl::samples {

nl_path_request_def path_request(nl_navmesh_id navmesh, const float start[3], const float goal[3],
                                 const nl_agent_capabilities& agent, const float* search_half_extents) {
    nl_path_request_def def = nl_default_path_request_def();
    def.navmesh = navmesh;
    for (int k = 0; k < 3; ++k) {
        def.start[k] = start[k];
        def.goal[k] = goal[k];
        if (search_half_extents) def.search_half_extents[k] = search_half_extents[k];
    }
    def.capabilities = agent;
    return def;
}

std::optional<NearestOnNavmesh> nearest_on_navmesh(const nl_world* world, nl_navmesh_id navmesh, const float point[3],
                                                   const float half_extents[3]) {
    nl_nav_point found{};
    if (NL_FAILED(nl_navmesh_find_nearest(world, navmesh, point, 1, half_extents, &found))) return std::nullopt;
    if (!found.found && !found.beyond_box) return std::nullopt;  // a navmesh without polygons
    NearestOnNavmesh nearest{};
    std::copy(found.point, found.point + 3, nearest.point);
    nearest.distance = found.distance;
    return nearest;
}

PlannedPath find_path(nl_world* world, nl_navmesh_id navmesh, const float start[3], const float goal[3],
                      const nl_agent_capabilities& agent, const float* search_half_extents) {
    const nl_path_request_def def = path_request(navmesh, start, goal, agent, search_half_extents);
    PlannedPath path;
    path.result.size = sizeof path.result;
    path.points.resize(256, nl_path_point_init());
    uint32_t count = 0;
    nl_status status = nl_path_find(world, &def, &path.result, path.points.data(), 256, &count);
    if (NL_FAILED(status) && (status & NL_STATUS_BUFFER_TOO_SMALL)) {
        path.points.resize(count, nl_path_point_init());  // a long path: plan again with room for all of it
        status = nl_path_find(world, &def, &path.result, path.points.data(), count, &count);
    }
    check(status, "planning the path");
    path.points.resize(count, nl_path_point_init());
    return path;
}

PlannedPath queued_result(const nl_world* world, nl_path_ticket ticket) {
    PlannedPath path;
    path.result.size = sizeof path.result;
    path.points.resize(256, nl_path_point_init());
    uint32_t count = 0;
    nl_status status = nl_path_get_result(world, ticket, &path.result, path.points.data(), 256, &count);
    if (NL_FAILED(status) && (status & NL_STATUS_BUFFER_TOO_SMALL)) {
        path.points.resize(count, nl_path_point_init());
        status = nl_path_get_result(world, ticket, &path.result, path.points.data(), count, &count);
    }
    check(status, "reading a path result");
    path.points.resize(count, nl_path_point_init());
    return path;
}

std::vector<PathSegment> path_segments(const PlannedPath& path) {
    std::vector<PathSegment> out;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) {
        const nl_path_point& a = path.points[i];
        const nl_path_point& b = path.points[i + 1];
        const float dx = b.position[0] - a.position[0], dy = b.position[1] - a.position[1],
                    dz = b.position[2] - a.position[2];
        out.push_back({a.segment, &a, &b, std::sqrt(dx * dx + dy * dy + dz * dz)});
    }
    return out;
}

const char* outcome_name(nl_path_outcome outcome) {
    switch (outcome) {
        case NL_PATH_PENDING: return "pending";
        case NL_PATH_COMPLETE: return "complete";
        case NL_PATH_PARTIAL: return "partial";
        case NL_PATH_NO_PATH: return "no path";
        case NL_PATH_START_OFF_NAVMESH: return "start off navmesh";
        case NL_PATH_GOAL_OFF_NAVMESH: return "goal off navmesh";
        case NL_PATH_CANCELLED: return "cancelled";
        case NL_PATH_FAILED: return "failed";
        default: return "unknown";
    }
}

const char* segment_name(nl_segment_kind kind) {
    if (kind == NL_SEGMENT_WALK) return "walk";
    if (kind == NL_LINK_JUMP) return "jump";
    if (kind == NL_LINK_DROP) return "drop";
    if (kind == NL_LINK_MANUAL) return "manual";
    return "plugin";
}

LinkCounts count_links(const PlannedPath& path) { return count_links(path.points); }

void count_link(LinkCounts& counts, nl_segment_kind kind) {
    if (kind == NL_LINK_JUMP)
        ++counts.jumps;
    else if (kind == NL_LINK_DROP)
        ++counts.drops;
    else if (kind == NL_LINK_MANUAL)
        ++counts.manual;
    else if (kind != NL_SEGMENT_WALK)
        ++counts.plugin;
}

LinkCounts count_links(const std::vector<nl_path_point>& points) {
    LinkCounts counts;
    // Every point, the last too: a path ends walking, but an agent's corners on its way over a
    // platform end at the take-off of the cross link that leaves their navmesh.
    for (const nl_path_point& point : points) count_link(counts, point.segment);
    return counts;
}

std::string describe_links(const LinkCounts& c) {
    std::string out;
    auto add = [&out](uint32_t n, const char* one, const char* many) {
        if (n == 0) return;
        if (!out.empty()) out += ", ";
        out += std::to_string(n) + " " + (n == 1 ? one : many);
    };
    add(c.jumps, "jump", "jumps");
    add(c.drops, "drop", "drops");
    add(c.manual, "manual link", "manual links");
    add(c.plugin, "plugin link", "plugin links");
    return out.empty() ? "no links" : out;
}

}  // namespace nl::samples
