#include "path/path_shortfall.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "path/link_filter.h"
#include "path/path_planner.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr float kAnyDistance = std::numeric_limits<float>::max();

bool reaches(const PathGraph& graph, const PathQuery& query) {
    PathResult result;
    plan_path(graph, query, nullptr, result);
    return result.outcome == PathOutcome::Complete;
}

PathQuery with_navmesh_width(PathQuery q, float navmesh_radius) {
    q.capabilities.radius = std::min(q.capabilities.radius, navmesh_radius);
    return q;
}

PathQuery with_every_area(PathQuery q) {
    for (float& cost : q.area_costs)
        if (cost == 0.0f) cost = 1.0f;
    return q;
}

PathQuery with_every_link(PathQuery q) {
    q.capabilities.max_jump_distance = q.capabilities.max_jump_height = q.capabilities.max_drop_height = kAnyDistance;
    q.capabilities.abilities = ~uint64_t(0);
    return q;
}

// A body that fits any link's clearance; walking keeps the navmesh's own radius.
PathQuery with_any_width(PathQuery q) {
    q.capabilities.radius = 0.0f;
    return q;
}

const Link* find_link(const PathGraph& graph, Handle id) {
    for (const StoredLink& stored : graph.links())
        if (stored.id == id) return &stored.link;
    return nullptr;
}

// The first link on the path to the goal with every link allowed that the body cannot take, and
// the first of its requirements the body falls short of.
bool name_the_link(const PathGraph& graph, const PathQuery& query, const PathQuery& every_link,
                   PathShortfallReport& out) {
    PathResult result;
    plan_path(graph, every_link, nullptr, result);
    if (result.outcome != PathOutcome::Complete) return false;
    for (const PathPoint& point : result.points) {
        if (point.link == Handle{}) continue;
        const Link* link = find_link(graph, point.link);
        if (!link) continue;
        const LinkShortfall stops = what_stops(*link, point.reversed, query.capabilities);
        if (stops.limit == LinkLimit::None) continue;
        out.why = PathShortfall::LinkBeyondBody;
        out.limit = stops.limit;
        out.needed = stops.needed;
        out.has = stops.has;
        out.missing_abilities = stops.missing_abilities;
        out.link = point.link;
        out.link_kind = link->kind;
        out.reversed = point.reversed;
        out.link_start = point.position;
        return true;
    }
    return false;
}

}  // namespace

PathShortfallReport explain_shortfall(const PathGraph& graph, const PathQuery& query, const PathResult& result) {
    PathShortfallReport out;
    out.navmesh_radius = graph.navmesh().agent().radius;
    if (result.outcome != PathOutcome::Partial && result.outcome != PathOutcome::NoPath) return out;
    if (result.out_of_nodes) {
        out.why = PathShortfall::OutOfNodes;
        return out;
    }
    PathQuery unlimited = query;
    unlimited.max_nodes = 0;
    unlimited.accept_partial = false;
    const float navmesh_radius = out.navmesh_radius;
    const bool wider = query.capabilities.radius > navmesh_radius;
    if (wider && reaches(graph, with_navmesh_width(unlimited, navmesh_radius))) {
        out.why = PathShortfall::BodyTooWide;
        out.needed = query.capabilities.radius;
        out.has = navmesh_radius;
        return out;
    }
    const bool excludes = std::find(query.area_costs.begin(), query.area_costs.end(), 0.0f) != query.area_costs.end();
    if (excludes && reaches(graph, with_every_area(unlimited))) {
        out.why = PathShortfall::AreasExcluded;
        return out;
    }
    if (name_the_link(graph, query, with_every_link(unlimited), out)) return out;
    // Every limit lifted at once: a way that needs more than one of them, or a link too narrow.
    const PathQuery everything = with_any_width(with_every_link(with_every_area(unlimited)));
    if (name_the_link(graph, query, everything, out)) return out;
    if (reaches(graph, everything)) {
        out.why = wider ? PathShortfall::BodyTooWide : PathShortfall::AreasExcluded;
        out.needed = wider ? query.capabilities.radius : 0.0f;
        out.has = wider ? navmesh_radius : 0.0f;
        return out;
    }
    out.why = graph.links().empty() ? PathShortfall::NoLinks : PathShortfall::NotConnected;
    return out;
}

namespace {

// Metres to the centimetre: "2.48", "4".
double cm(float metres) { return std::round(double(metres) * 100.0) / 100.0; }

std::string link_words(const PathShortfallReport& r, LinkKind kind) {
    const char* what = kind == LinkKind::Jump     ? "a jump"
                       : kind == LinkKind::Drop   ? (r.reversed ? "a drop taken back up" : "a drop")
                       : kind == LinkKind::Manual ? "a manual link"
                                                  : "a plugin's link";
    return concat(what, " at (", cm(r.link_start.x()), ", ", cm(r.link_start.y()), ", ", cm(r.link_start.z()),
                  ") would get there");
}

// Passages narrower than its body are not in a navmesh at all: no path search can tell them.
std::string built_for(const PathShortfallReport& r) {
    return concat("built for a body of radius ", cm(r.navmesh_radius), " m, it leaves out passages narrower than ",
                  cm(2.0f * r.navmesh_radius), " m");
}

}  // namespace

std::string describe(const PathShortfallReport& r, const PathQuery& query) {
    switch (r.why) {
        case PathShortfall::None: return {};
        case PathShortfall::OutOfNodes:
            return concat("max_nodes (", query.max_nodes,
                          ") stopped the search before it reached the goal: raise it, or 0 for no limit");
        case PathShortfall::BodyTooWide:
            return concat("the body (radius ", cm(r.needed),
                          " m) is too wide for the passages on the way: a body of the navmesh's radius (", cm(r.has),
                          " m) would get there; build a navmesh for this body");
        case PathShortfall::AreasExcluded:
            return "areas the request keeps the body out of (area_costs 0) stand in the way";
        case PathShortfall::LinkBeyondBody: {
            std::string out = link_words(r, r.link_kind);
            switch (r.limit) {
                case LinkLimit::JumpDistance:
                    return concat(out, ": it needs a jump of ", cm(r.needed), " m across, and the body jumps ",
                                  cm(r.has), " m (max_jump_distance)");
                case LinkLimit::JumpHeight:
                    return concat(out, ": it needs a jump of ", cm(r.needed), " m up, and the body jumps ", cm(r.has),
                                  " m up (max_jump_height)");
                case LinkLimit::DropHeight:
                    return concat(out, ": it needs a drop of ", cm(r.needed), " m, and the body drops ", cm(r.has),
                                  " m (max_drop_height)");
                case LinkLimit::Width:
                    return concat(out, ": it is clear for a body ", cm(r.has), " m wide, and the body is ",
                                  cm(r.needed), " m wide (radius)");
                case LinkLimit::Abilities:
                case LinkLimit::None:
                    return concat(out, ": it needs abilities the body lacks (abilities 0x", std::hex,
                                  r.missing_abilities, ")");
            }
            return out;
        }
        case PathShortfall::NoLinks:
            return concat("the goal is on another island of the navmesh (", built_for(r),
                          "), and the navmesh has no links: generate or load them");
        case PathShortfall::NotConnected:
            return concat("no passage or link leads to the goal, whatever the body could do (", built_for(r), ")");
    }
    return {};
}

}  // namespace nl
