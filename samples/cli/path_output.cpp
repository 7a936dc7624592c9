#include "path_output.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "route_text.h"
#include "sample_error.h"

namespace nl::cli {
namespace {

nlohmann::json xyz(const float p[3]) { return nlohmann::json::array({p[0], p[1], p[2]}); }

float distance(const float a[3], const float b[3]) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// "the start (x, y, z) is off the navmesh: ..." with where the navmesh is nearest.
void print_off_navmesh(std::FILE* out, const char* end, const char* option, const float given[3],
                       const std::optional<samples::NearestOnNavmesh>& nearest) {
    std::fprintf(out, "  the %s (%.2f, %.2f, %.2f) is off the navmesh: ", end, given[0], given[1], given[2]);
    if (nearest)
        std::fprintf(out,
                     "the nearest navmesh point is (%.2f, %.2f, %.2f), %.2f m away; move %s there or widen --search\n",
                     nearest->point[0], nearest->point[1], nearest->point[2], nearest->distance, option);
    else
        std::fprintf(out, "no navmesh within 1 km of it\n");
}

// Why a path falls short, with the link's index in LINKS.json; a navmesh without links is walked
// alone unless --links gives them.
void print_shortfall(std::FILE* out, const AskedPath& asked, const std::vector<nl_link>& links) {
    if (!asked.shortfall || asked.shortfall->reason == NL_PATH_SHORTFALL_NONE) return;
    std::fprintf(out, "  why: %s", asked.shortfall->text);
    if (asked.shortfall->reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY)
        std::fprintf(out, " (link #%ld; --agent sets the body's capabilities)",
                     link_index(links, asked.shortfall->link));
    if (asked.shortfall->reason == NL_PATH_SHORTFALL_NO_LINKS) std::fprintf(out, " (--links LINKS.json)");
    std::fprintf(out, "\n");
}

nlohmann::json nearest_json(const std::optional<samples::NearestOnNavmesh>& nearest) {
    if (!nearest) return nullptr;
    return {{"point", xyz(nearest->point)}, {"distance", nearest->distance}};
}

}  // namespace

AskedPath asked_path(nl_world* world, nl_navmesh_id navmesh, const samples::PlannedPath& path, const float from[3],
                     const float to[3], const float search_half_extents[3], const nl_agent_capabilities& agent) {
    AskedPath asked{};
    nl_navmesh_info info = nl_navmesh_info_init();
    samples::check(nl_navmesh_get_info(world, navmesh, &info), "reading the navmesh");
    asked.body_radius = agent.radius;
    asked.navmesh_radius = info.agent_type.radius;
    if (path.result.outcome == NL_PATH_PARTIAL || path.result.outcome == NL_PATH_NO_PATH) {
        const nl_path_request_def request = samples::path_request(navmesh, from, to, agent, search_half_extents);
        nl_path_shortfall shortfall = nl_path_shortfall_init();
        samples::check(nl_path_explain(world, &request, &shortfall), "explaining the path");
        asked.shortfall = shortfall;
    }
    for (int k = 0; k < 3; ++k) {
        asked.from[k] = from[k];
        asked.to[k] = to[k];
    }
    if (path.result.outcome == NL_PATH_START_OFF_NAVMESH)
        asked.nearest_start = samples::nearest_on_navmesh(world, navmesh, from, search_half_extents);
    if (path.result.outcome == NL_PATH_GOAL_OFF_NAVMESH)
        asked.nearest_goal = samples::nearest_on_navmesh(world, navmesh, to, search_half_extents);
    return asked;
}

long link_index(const std::vector<nl_link>& links, nl_link_id link) {
    for (size_t i = 0; i < links.size(); ++i)
        if (links[i].id.index1 == link.index1 && links[i].id.revision == link.revision) return static_cast<long>(i);
    return -1;
}

void print_path_text(std::FILE* out, const samples::PlannedPath& path, const std::vector<nl_link>& links,
                     const AskedPath& asked) {
    const nl_path_result& r = path.result;
    std::fprintf(out, "path: %s, %.2f m walked, %s (%u polygons searched)\n", samples::outcome_name(r.outcome),
                 r.length, samples::describe_links(samples::count_links(path)).c_str(), r.nodes_visited);
    if (asked.body_radius > asked.navmesh_radius)
        std::fprintf(
            out, "  the body (radius %.2f m) is wider than the navmesh's (%.2f m): it keeps %.2f m more from walls\n",
            asked.body_radius, asked.navmesh_radius, asked.body_radius - asked.navmesh_radius);
    if (r.outcome == NL_PATH_START_OFF_NAVMESH)
        print_off_navmesh(out, "start", "--from", asked.from, asked.nearest_start);
    if (r.outcome == NL_PATH_GOAL_OFF_NAVMESH) print_off_navmesh(out, "goal", "--to", asked.to, asked.nearest_goal);
    print_shortfall(out, asked, links);
    if (path.points.empty()) return;
    const bool arrives = r.outcome == NL_PATH_COMPLETE;
    std::fprintf(out, "  from (%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f) on the navmesh\n", r.start[0], r.start[1],
                 r.start[2], r.goal[0], r.goal[1], r.goal[2]);
    std::fprintf(out, "  %3s  %-28s %-6s %-6s %8s\n", "#", "point", "then", "link", "straight");
    const auto segments = samples::path_segments(path);
    for (size_t i = 0; i < path.points.size(); ++i) {
        const nl_path_point& p = path.points[i];
        char position[64];
        std::snprintf(position, sizeof position, "(%.2f, %.2f, %.2f)", p.position[0], p.position[1], p.position[2]);
        if (i + 1 == path.points.size()) {
            std::fprintf(out, "  %3zu  %-28s %-6s\n", i, position, arrives ? "arrive" : "end");
            break;
        }
        char link[32] = "";
        if (p.segment != NL_SEGMENT_WALK)
            std::snprintf(link, sizeof link, "#%ld%s", link_index(links, p.link), p.reversed ? " rev" : "");
        std::fprintf(out, "  %3zu  %-28s %-6s %-6s %8.2f\n", i, position, samples::segment_name(p.segment), link,
                     segments[i].length);
    }
    // The legs in one line, consecutive walking merged (a walker's eleven corners are one walk).
    std::fprintf(out, "  route: %s\n", route_text(path).c_str());
    if (!arrives)
        std::fprintf(out, "  %s: it ends %.2f m from the goal (%.2f, %.2f, %.2f)\n", samples::outcome_name(r.outcome),
                     distance(path.points.back().position, asked.to), asked.to[0], asked.to[1], asked.to[2]);
}

std::string path_json(const samples::PlannedPath& path, const std::vector<nl_link>& links, const AskedPath& asked) {
    const nl_path_result& r = path.result;
    nlohmann::json out;
    out["outcome"] = samples::outcome_name(r.outcome);
    out["from"] = xyz(asked.from);
    out["to"] = xyz(asked.to);
    if (!path.points.empty()) out["ends_from_goal"] = distance(path.points.back().position, asked.to);
    if (r.outcome == NL_PATH_START_OFF_NAVMESH) out["nearest_start"] = nearest_json(asked.nearest_start);
    if (r.outcome == NL_PATH_GOAL_OFF_NAVMESH) out["nearest_goal"] = nearest_json(asked.nearest_goal);
    if (asked.shortfall && asked.shortfall->reason != NL_PATH_SHORTFALL_NONE) {
        out["why"] = asked.shortfall->text;
        if (asked.shortfall->reason == NL_PATH_SHORTFALL_LINK_BEYOND_BODY)
            out["why_link"] = link_index(links, asked.shortfall->link);
    }
    out["length"] = r.length;  // walked, along the surface
    float straight = 0.0f;
    for (const samples::PathSegment& segment : samples::path_segments(path)) straight += segment.length;
    out["straight_length"] = straight;
    out["cost"] = r.cost;
    out["links_used"] = r.links_used;
    out["nodes_visited"] = r.nodes_visited;
    out["start"] = xyz(r.start);
    out["goal"] = xyz(r.goal);
    nlohmann::json points = nlohmann::json::array();
    for (const nl_path_point& p : path.points) {
        nlohmann::json point;
        point["position"] = xyz(p.position);
        point["polygon"] = p.polygon;
        points.push_back(point);
    }
    out["points"] = points;
    nlohmann::json segments = nlohmann::json::array();
    for (const samples::PathSegment& s : samples::path_segments(path)) {
        nlohmann::json segment;
        segment["kind"] = samples::segment_name(s.kind);
        segment["from"] = xyz(s.from->position);
        segment["to"] = xyz(s.to->position);
        segment["length"] = s.length;
        if (s.kind != NL_SEGMENT_WALK) {
            segment["link"] = link_index(links, s.from->link);
            segment["reversed"] = s.from->reversed != 0;
            segment["apex"] = xyz(s.from->apex);
        }
        segments.push_back(segment);
    }
    out["segments"] = segments;
    return out.dump(1) + "\n";
}

}  // namespace nl::cli
