#include "shortest_path_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <tuple>

#include "path/link_filter.h"
#include "path/portal.h"

namespace nl::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kOnEdge = 1e-7;     // metres: a point this close to a polygon's edge is on it
constexpr double kInOpening = 1e-6;  // metres: a crossing this close to an opening's end is in it

double cross(double ox, double oz, double ax, double az, double bx, double bz) {
    return (ax - ox) * (bz - oz) - (az - oz) * (bx - ox);
}

PathQuery thin_body(const NavMesh& navmesh) {
    PathQuery query;
    query.capabilities.radius = navmesh.agent().radius;
    return query;
}

}  // namespace

ShortestPathReference::ShortestPathReference(const NavMesh& navmesh) : navmesh_(navmesh) {
    build(thin_body(navmesh), {}, false);
}

ShortestPathReference::ShortestPathReference(const NavMesh& navmesh, const PathQuery& query, const LinkSnapshot& links,
                                             bool every_vertex)
    : navmesh_(navmesh) {
    build(query, links, every_vertex);
}

ShortestPathReference::ShortestPathReference(const PathGraph& graph, const PathQuery& query, bool every_vertex)
    : navmesh_(graph.navmesh()) {
    build(query, *graph.links_ptr(), every_vertex);
}

void ShortestPathReference::build(const PathQuery& query, const LinkSnapshot& links, bool every_vertex) {
    const NavMesh& mesh = navmesh_;
    const uint32_t polygons = mesh.polygon_count();
    margin_ = std::max(0.0f, query.capabilities.radius - mesh.agent().radius);

    // Polygons seen from above, which are open to the body, and the walking rate.
    first_.assign(polygons + 1, 0);
    open_.assign(polygons, 0);
    box_.assign(4 * size_t(polygons), 0.0);
    bool rate_known = false;
    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t n = mesh.corner_count(p);
        first_[p + 1] = first_[p] + n;
        double* box = &box_[4 * size_t(p)];
        box[0] = box[1] = kInfinity;
        box[2] = box[3] = -kInfinity;
        for (uint32_t k = 0; k < n; ++k) {
            const Vec3& v = mesh.vertex(mesh.corner(p, k));
            flat_.push_back({double(v.x()), double(v.z())});
            box[0] = std::min(box[0], double(v.x()));
            box[1] = std::min(box[1], double(v.z()));
            box[2] = std::max(box[2], double(v.x()));
            box[3] = std::max(box[3], double(v.z()));
        }
        const float cost = query.area_cost(mesh.area(p));
        if (!(cost > 0.0f)) continue;
        open_[p] = 1;
        if (rate_known && double(cost) != walk_rate_)
            throw std::invalid_argument("ShortestPathReference: the open areas must cost the body the same");
        walk_rate_ = cost;
        rate_known = true;
    }

    // Each edge's opening to the body.
    openings_.assign(first_[polygons], Opening{});
    for (uint32_t p = 0; p < polygons; ++p) {
        for (uint32_t k = 0; k < mesh.corner_count(p); ++k) {
            const uint32_t q = mesh.neighbour(p, k);
            Opening& o = openings_[first_[p] + k];
            PortalSpan span;
            if (!open_[p] || q == kNoPolygon || !open_[q] || !portal_span(mesh, p, k, margin_, span)) continue;
            o.open = true;
            o.left_point = span.left;
            o.right_point = span.right;
            o.left = {double(span.left.x()), double(span.left.z())};
            o.right = {double(span.right.x()), double(span.right.z())};
        }
    }

    // Bend points: with no margin the reflex corners of the walls (the outline, edges to excluded
    // polygons); with a margin the ends portal_span moved (outline ends of open portals, narrowed)
    // and the vertices off the outline where a wall (a closed portal, an edge to an excluded polygon)
    // ends; or every vertex and narrowed end.
    std::vector<Vec3> bends;
    std::vector<double> angle(mesh.vertex_count(), 0.0);  // filled round each vertex by open polygons
    std::vector<uint8_t> wall_end(mesh.vertex_count(), 0);
    for (uint32_t p = 0; p < polygons; ++p) {
        if (!open_[p]) continue;
        const uint32_t n = mesh.corner_count(p);
        for (uint32_t k = 0; k < n; ++k) {
            const Flat v = corner_at(p, k), before = corner_at(p, (k + n - 1) % n), after = corner_at(p, (k + 1) % n);
            const double a1 = std::atan2(before.z - v.z, before.x - v.x), a2 = std::atan2(after.z - v.z, after.x - v.x);
            double a = std::fabs(a1 - a2);
            angle[mesh.corner(p, k)] += a > kPi ? 2 * kPi - a : a;
            if (!openings_[first_[p] + k].open) wall_end[mesh.corner(p, k)] = wall_end[mesh.corner(p, (k + 1) % n)] = 1;
        }
    }
    for (uint32_t v = 0; v < mesh.vertex_count(); ++v) {
        if (every_vertex) {
            bends.push_back(mesh.vertex(v));
        } else if (margin_ <= 0.0f) {
            if (wall_end[v] && angle[v] > kPi + 1e-6) bends.push_back(mesh.vertex(v));
        } else if (wall_end[v] && !mesh.on_outline(v)) {
            bends.push_back(mesh.vertex(v));
        }
    }
    if (margin_ > 0.0f) {
        for (uint32_t p = 0; p < polygons; ++p) {
            for (uint32_t k = 0; k < mesh.corner_count(p); ++k) {
                const Opening& o = openings_[first_[p] + k];
                if (!o.open) continue;
                const uint32_t n = mesh.corner_count(p);
                if (mesh.on_outline(mesh.corner(p, k))) bends.push_back(o.left_point);
                if (mesh.on_outline(mesh.corner(p, (k + 1) % n))) bends.push_back(o.right_point);
            }
        }
    }
    // The narrowed ends are floats of portal_span's: the same point from either side of its portal.
    std::sort(bends.begin(), bends.end(), [](const Vec3& a, const Vec3& b) {
        return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
    });
    bends.erase(std::unique(bends.begin(), bends.end(), [](const Vec3& a, const Vec3& b) { return a == b; }),
                bends.end());
    for (const Vec3& b : bends) {
        for (Node& node : nodes_at(b)) nodes_.push_back(std::move(node));
    }

    // Links: each direction the body can take becomes a take-off node, a landing node and an edge.
    cheapest_rate_ = walk_rate_;
    std::vector<uint32_t> floor;
    for (const StoredLink& stored : links) {
        const Link& link = stored.link;
        if (!link.enabled || link.crosses() || link.start_polygon >= polygons || link.end_polygon >= polygons) continue;
        for (const bool reversed : {false, true}) {
            if (reversed && !link.bidirectional) continue;
            if (!can_take(link, reversed, query.capabilities)) continue;
            const uint32_t from_polygon = reversed ? link.end_polygon : link.start_polygon;
            const uint32_t to_polygon = reversed ? link.start_polygon : link.end_polygon;
            if (!open_[from_polygon] || !open_[to_polygon]) continue;
            const Vec3& from = reversed ? link.end : link.start;
            const Vec3& to = reversed ? link.start : link.end;
            // The group of polygons at the point that holds the link's own polygon.
            auto node_in = [&](const Vec3& point, uint32_t polygon) {
                Node node{point, {double(point.x()), double(point.z())}, {polygon}};
                on_floor(point, floor);
                if (std::find(floor.begin(), floor.end(), polygon) != floor.end()) {
                    for (std::vector<uint32_t>& group : groups(node.at, floor)) {
                        if (std::find(group.begin(), group.end(), polygon) != group.end())
                            node.polygons = std::move(group);
                    }
                }
                nodes_.push_back(std::move(node));
                return uint32_t(nodes_.size() - 1);
            };
            LinkEdge edge;
            edge.takeoff = node_in(from, from_polygon);
            edge.landing = node_in(to, to_polygon);
            const double dx = double(to.x()) - from.x(), dy = double(to.y()) - from.y(), dz = double(to.z()) - from.z();
            const double chord = std::sqrt(dx * dx + dy * dy + dz * dz);
            edge.cost = chord * link.cost_modifier + query.link_cost;
            cheapest_rate_ = std::min(cheapest_rate_, double(link.cost_modifier));
            link_edges_.push_back(edge);
        }
    }
    // The estimate stays below any route's cost: links cost at least their x-z chord times their modifier.
    cheapest_rate_ = query.link_cost < 0.0f ? 0.0 : std::max(0.0, cheapest_rate_);
    links_from_.assign(nodes_.size(), {});
    for (uint32_t e = 0; e < link_edges_.size(); ++e) links_from_[link_edges_[e].takeoff].push_back(e);
    sees_.assign(nodes_.size() * nodes_.size(), -1);
}

void ShortestPathReference::containing(const Flat& q, const std::vector<uint32_t>* among,
                                       std::vector<uint32_t>& out) const {
    out.clear();
    const uint32_t count = among ? uint32_t(among->size()) : navmesh_.polygon_count();
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t p = among ? (*among)[i] : i;
        if (!open_[p]) continue;
        const double* box = &box_[4 * size_t(p)];
        if (q.x < box[0] - kOnEdge || q.z < box[1] - kOnEdge || q.x > box[2] + kOnEdge || q.z > box[3] + kOnEdge)
            continue;
        const uint32_t n = first_[p + 1] - first_[p];
        bool in = true;
        for (uint32_t k = 0; k < n && in; ++k) {
            const Flat a = corner_at(p, k), b = corner_at(p, (k + 1) % n);
            // Counter-clockwise seen from above (x right, z up): the inside is where the cross product
            // is <= 0 in this orientation (the navmesh's own rule, navmesh.cpp's over_polygon).
            in = -cross(a.x, a.z, b.x, b.z, q.x, q.z) >= -kOnEdge * std::hypot(b.x - a.x, b.z - a.z);
        }
        if (in) out.push_back(p);
    }
}

void ShortestPathReference::on_floor(const Vec3& point, std::vector<uint32_t>& out) const {
    std::vector<uint32_t> below_or_above;
    containing({double(point.x()), double(point.z())}, nullptr, below_or_above);
    out.clear();
    for (const uint32_t p : below_or_above) {
        if (std::fabs(navmesh_.surface_height(p, point.x(), point.z()) - point.y()) <= navmesh_.agent().max_climb)
            out.push_back(p);
    }
}

bool ShortestPathReference::crosses_at(uint32_t p, uint32_t k, const Flat& x) const {
    const Opening& o = openings_[first_[p] + k];
    if (!o.open) return false;
    const double ex = o.right.x - o.left.x, ez = o.right.z - o.left.z, width = std::hypot(ex, ez);
    if (width <= 0.0) return std::hypot(x.x - o.left.x, x.z - o.left.z) <= kInOpening;
    const double along = ((x.x - o.left.x) * ex + (x.z - o.left.z) * ez) / width;
    return along >= -kInOpening && along <= width + kInOpening;
}

void ShortestPathReference::reached_from(const std::vector<uint32_t>& before, const std::vector<uint32_t>& after,
                                         const std::vector<uint32_t>& at_x, const Flat& x,
                                         std::vector<uint32_t>& out) const {
    // Through the polygons round x, across shared edges whose openings hold x: round a corner where
    // polygons meet, never across a corner where two touch alone, never onto another floor.
    std::vector<uint32_t> reached(before), frontier(before);
    out.clear();
    while (!frontier.empty()) {
        const uint32_t p = frontier.back();
        frontier.pop_back();
        if (std::find(after.begin(), after.end(), p) != after.end() &&
            std::find(out.begin(), out.end(), p) == out.end())
            out.push_back(p);
        for (uint32_t k = 0; k < navmesh_.corner_count(p); ++k) {
            const uint32_t q = navmesh_.neighbour(p, k);
            if (q == kNoPolygon || std::find(at_x.begin(), at_x.end(), q) == at_x.end() ||
                std::find(reached.begin(), reached.end(), q) != reached.end() || !crosses_at(p, k, x))
                continue;
            reached.push_back(q);
            frontier.push_back(q);
        }
    }
}

std::vector<std::vector<uint32_t>> ShortestPathReference::groups(const Flat& x,
                                                                 const std::vector<uint32_t>& polygons) const {
    std::vector<std::vector<uint32_t>> out;
    std::vector<uint32_t> left(polygons), group;
    while (!left.empty()) {
        reached_from({left.front()}, left, polygons, x, group);
        std::sort(group.begin(), group.end());
        for (const uint32_t p : group) left.erase(std::find(left.begin(), left.end(), p));
        out.push_back(group);
    }
    return out;
}

std::vector<ShortestPathReference::Node> ShortestPathReference::nodes_at(const Vec3& point) const {
    std::vector<uint32_t> floor;
    on_floor(point, floor);
    std::vector<Node> out;
    const Flat at{double(point.x()), double(point.z())};
    for (std::vector<uint32_t>& group : groups(at, floor)) out.push_back(Node{point, at, std::move(group)});
    return out;
}

bool ShortestPathReference::walk_joins(const Flat& a, const std::vector<uint32_t>& from, const Flat& b,
                                       const std::vector<uint32_t>& to) const {
    if (from.empty() || to.empty()) return false;
    const double dx = b.x - a.x, dz = b.z - a.z, length2 = dx * dx + dz * dz, length = std::sqrt(length2);
    // The open polygons the segment comes near (their boxes within kOnEdge of it): only their edges
    // cut it and only they can hold its pieces.
    std::vector<uint32_t> near;
    const double lo_x = std::min(a.x, b.x) - kOnEdge, hi_x = std::max(a.x, b.x) + kOnEdge;
    const double lo_z = std::min(a.z, b.z) - kOnEdge, hi_z = std::max(a.z, b.z) + kOnEdge;
    for (uint32_t p = 0; p < navmesh_.polygon_count(); ++p) {
        if (!open_[p]) continue;
        const double* box = &box_[4 * size_t(p)];
        if (box[0] > hi_x || box[2] < lo_x || box[1] > hi_z || box[3] < lo_z) continue;
        if (length > 0.0) {
            // Entirely on one side of the segment's line: apart.
            int below = 0, above = 0;
            for (const double cx : {box[0], box[2]}) {
                for (const double cz : {box[1], box[3]}) {
                    const double side = cross(a.x, a.z, b.x, b.z, cx, cz) / length;
                    below += side < -kOnEdge;
                    above += side > kOnEdge;
                }
            }
            if (below == 4 || above == 4) continue;
        }
        near.push_back(p);
    }
    std::vector<uint32_t> current(from), here, at_cut, next;
    if (length2 == 0.0) {
        containing(a, &near, at_cut);
        reached_from(current, to, at_cut, a, next);
        return !next.empty();
    }
    // Every place the segment meets a polygon edge splits it; each piece between lies in one polygon
    // (or two, along a shared edge), which its middle tells. Along an edge's line, the edge's ends and
    // its opening's ends split it.
    std::vector<double> cuts{0.0, 1.0};
    for (const uint32_t p : near) {
        const uint32_t n = first_[p + 1] - first_[p];
        for (uint32_t k = 0; k < n; ++k) {
            const Flat c = corner_at(p, k), d = corner_at(p, (k + 1) % n);
            const double ex = d.x - c.x, ez = d.z - c.z;
            const double denominator = dx * ez - dz * ex;
            const double wx = c.x - a.x, wz = c.z - a.z;
            if (std::fabs(denominator) < 1e-12 * std::sqrt(length2 * (ex * ex + ez * ez))) {
                if (std::fabs(wx * dz - wz * dx) > 1e-9 * length) continue;
                const Opening& o = openings_[first_[p] + k];
                for (const Flat& e : {c, d}) cuts.push_back(((e.x - a.x) * dx + (e.z - a.z) * dz) / length2);
                if (o.open) {
                    for (const Flat& e : {o.left, o.right})
                        cuts.push_back(((e.x - a.x) * dx + (e.z - a.z) * dz) / length2);
                }
                continue;
            }
            const double t = (wx * ez - wz * ex) / denominator, s = (wx * dz - wz * dx) / denominator;
            if (s >= -1e-9 && s <= 1 + 1e-9) cuts.push_back(t);
        }
    }
    // The walk goes piece by piece from the polygons it is in to those of the next piece it reaches
    // at their cut point (reached_from), ending in one of `to`.
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t0 = std::clamp(cuts[i], 0.0, 1.0), t1 = std::clamp(cuts[i + 1], 0.0, 1.0);
        if (t1 - t0 < 1e-12) continue;
        const double middle = 0.5 * (t0 + t1);
        const Flat cut{a.x + t0 * dx, a.z + t0 * dz};
        containing({a.x + middle * dx, a.z + middle * dz}, &near, here);
        containing(cut, &near, at_cut);
        reached_from(current, here, at_cut, cut, next);
        if (next.empty()) return false;
        current.swap(next);
    }
    containing(b, &near, at_cut);
    reached_from(current, to, at_cut, b, next);
    return !next.empty();
}

bool ShortestPathReference::nodes_see(uint32_t i, uint32_t j) const {
    int8_t& known = sees_[size_t(i) * nodes_.size() + j];
    if (known < 0) known = walk_joins(nodes_[i].at, nodes_[i].polygons, nodes_[j].at, nodes_[j].polygons) ? 1 : 0;
    return known == 1;
}

bool ShortestPathReference::walkable(const Vec3& from, const Vec3& to) const {
    std::vector<uint32_t> end;
    on_floor(to, end);
    for (const Node& start : nodes_at(from)) {
        if (walk_joins(start.at, start.polygons, {double(to.x()), double(to.z())}, end)) return true;
    }
    return false;
}

std::optional<double> ShortestPathReference::length(const Vec3& start, const Vec3& goal,
                                                    std::vector<Vec3>* bends) const {
    if (bends) bends->clear();
    // Nodes: the graph's [0, n), then the start's groups, then the goal's.
    const std::vector<Node> starts = nodes_at(start), goals = nodes_at(goal);
    const uint32_t n = uint32_t(nodes_.size()), first_goal = n + uint32_t(starts.size());
    const uint32_t total = first_goal + uint32_t(goals.size());
    auto node = [&](uint32_t i) -> const Node& {
        return i < n ? nodes_[i] : i < first_goal ? starts[i - n] : goals[i - first_goal];
    };
    const Flat goal_at{double(goal.x()), double(goal.z())};
    auto distance = [](const Flat& a, const Flat& b) { return std::hypot(b.x - a.x, b.z - a.z); };
    auto estimate = [&](uint32_t i) { return cheapest_rate_ * distance(node(i).at, goal_at); };

    // A* with lazily checked walks: an entry whose walk is not yet known to be allowed (from the
    // start, to the goal) is checked when it comes first; a walk's cost is exact when it is allowed,
    // so the first allowed entry of a node is its cheapest.
    struct Entry {
        double f, g;
        uint32_t node, parent;
        bool checked;
        bool operator>(const Entry& o) const { return f > o.f; }
    };
    constexpr uint32_t kNone = 0xffffffffu;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    std::vector<double> best(total, kInfinity);
    std::vector<uint32_t> parent(total, kNone);
    std::vector<uint8_t> done(total, 0);
    for (uint32_t s = n; s < first_goal; ++s) {
        best[s] = 0.0;
        open.push({estimate(s), 0.0, s, kNone, true});
    }
    uint32_t reached = kNone;
    while (!open.empty()) {
        const Entry e = open.top();
        open.pop();
        if (done[e.node]) continue;
        if (!e.checked &&
            !walk_joins(node(e.parent).at, node(e.parent).polygons, node(e.node).at, node(e.node).polygons))
            continue;
        done[e.node] = 1;
        best[e.node] = e.g;
        parent[e.node] = e.parent;
        if (e.node >= first_goal) {
            reached = e.node;
            break;
        }
        const Node& from = node(e.node);
        if (e.node < n) {
            for (const uint32_t l : links_from_[e.node]) {
                const LinkEdge& edge = link_edges_[l];
                const double g = e.g + edge.cost;
                if (done[edge.landing] || g >= best[edge.landing]) continue;
                best[edge.landing] = g;
                open.push({g + estimate(edge.landing), g, edge.landing, e.node, true});
            }
        }
        for (uint32_t j = 0; j < n; ++j) {
            if (done[j] || j == e.node) continue;
            const double g = e.g + walk_rate_ * distance(from.at, nodes_[j].at);
            if (g >= best[j]) continue;
            if (e.node >= n) {
                open.push({g + estimate(j), g, j, e.node, false});
            } else if (nodes_see(e.node, j)) {
                best[j] = g;
                open.push({g + estimate(j), g, j, e.node, true});
            }
        }
        for (uint32_t j = first_goal; j < total; ++j) {
            const double g = e.g + walk_rate_ * distance(from.at, node(j).at);
            if (g < best[j]) open.push({g, g, j, e.node, false});
        }
    }
    if (reached == kNone) return std::nullopt;
    if (bends) {
        for (uint32_t i = parent[reached]; i != kNone && i < n; i = parent[i]) bends->push_back(nodes_[i].point);
        std::reverse(bends->begin(), bends->end());
    }
    return best[reached];
}

double xz_length(const PathResult& result) {
    double length = 0.0;
    for (size_t i = 1; i < result.points.size(); ++i) {
        const Vec3 d = result.points[i].position - result.points[i - 1].position;
        length += std::hypot(double(d.x()), double(d.z()));
    }
    return length;
}

}  // namespace nl::test
