#include "path/any_angle_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <limits>
#include <vector>

#include "path/link_filter.h"
#include "path/portal.h"
#include "path/search_costs.h"
#include "os/compiler.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr uint32_t kNoNode = 0xffffffffu;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Seen from above, in double: the search compares which side of a line points lie on, and float's
// rounding would let a walk slip past a corner or lose the one through a vertex.
struct Flat {
    double x, z;
};
Flat flat(const Vec3& v) { return {v.x(), v.z()}; }
Flat operator-(Flat a, Flat b) { return {a.x - b.x, a.z - b.z}; }
Flat operator+(Flat a, Flat b) { return {a.x + b.x, a.z + b.z}; }
Flat operator*(double s, Flat a) { return {s * a.x, s * a.z}; }
double cross(Flat a, Flat b) { return a.x * b.z - a.z * b.x; }
double distance(Flat a, Flat b) {
    const double dx = a.x - b.x, dz = a.z - b.z;
    return std::sqrt(dx * dx + dz * dz);
}

// Walks from `root` in straight lines through the interval [a, b] of an edge into `polygon` (a toward
// the polygon's first corner of that edge); or, for a node without an edge (the start, a link's
// landing), from `root` inside `polygon` to anywhere in it.
struct IntervalNode {
    Flat root, a, b;
    double g;          // cost from the start to the root
    uint32_t root_id;  // the root's turning id (below), for pruning
    uint32_t polygon;
    uint32_t edge;            // the polygon's edge the interval is on; kNoNode for a node without edge
    uint32_t entry;           // CorridorStep::entry into `polygon`
    uint32_t parent;          // node index; kNoNode for the start
    uint32_t a_turn, b_turn;  // turning ids of a and b when a walk may bend there, else kNoNode
};

struct OpenEntry {
    double f;
    uint32_t node;
    bool operator>(const OpenEntry& other) const { return f > other.f; }
};

// Turning ids name the points a walk may bend at or start from, for the cheapest cost found to each:
// the navmesh's vertices, then where links land (two per link, one per direction), then the start,
// held in an array; then the narrowed ends of portals (two per polygon edge, only for a wider body),
// held in a table (an array would take two entries per edge for every search thread).
struct TurningIds {
    uint32_t landing_base, start, narrowed_base;
    TurningIds(const NavMesh& navmesh, size_t links)
        : landing_base(navmesh.vertex_count()),
          start(landing_base + 2 * static_cast<uint32_t>(links)),
          narrowed_base(start + 1) {}
    uint32_t dense_count() const { return narrowed_base; }
};

// How a walk reached a turning point: from its root, across the edge into the polygon it bent in
// (NavMesh::edge_index; kNoNode for the start and links' landings).
struct Arrival {
    Flat from{0.0, 0.0};
    uint32_t entry = kNoNode;
};

// Costs by key, with the arrival of the cheapest, open addressing with epoch stamps: a search clears
// it in constant time (an unordered_map's clear walks its buckets).
class CostTable {
public:
    struct Entry {
        double g;
        Arrival arrival;
    };

    void clear() {
        if (++epoch_ == 0) {
            for (Slot& slot : slots_) slot.epoch = 0;
            epoch_ = 1;
        }
        used_ = 0;
    }
    // The cost kept for `key` and its arrival, or null.
    const Entry* find(uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (size_t i = hash(key);; i = (i + 1) & (slots_.size() - 1)) {
            const Slot& slot = slots_[i];
            if (slot.epoch != epoch_) return nullptr;
            if (slot.key == key) return &slot.entry;
        }
    }
    // Keeps g and its arrival for `key` if it has none or a dearer one.
    void lower(uint64_t key, double g, const Arrival& arrival = {}) {
        if (2 * (used_ + 1) > slots_.size()) grow();
        for (size_t i = hash(key);; i = (i + 1) & (slots_.size() - 1)) {
            Slot& slot = slots_[i];
            if (slot.epoch != epoch_) {
                slot = Slot{key, Entry{g, arrival}, epoch_};
                ++used_;
                return;
            }
            if (slot.key != key) continue;
            if (g < slot.entry.g) slot.entry = Entry{g, arrival};
            return;
        }
    }

private:
    struct Slot {
        uint64_t key;
        Entry entry;
        uint32_t epoch;
    };
    size_t hash(uint64_t key) const { return size_t((key * 0x9e3779b97f4a7c15ull) >> 32) & (slots_.size() - 1); }
    void grow() {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(std::max<size_t>(64, 2 * old.size()), Slot{0, Entry{0.0, {}}, 0});
        const uint32_t current = epoch_;
        epoch_ = 1;
        used_ = 0;
        for (const Slot& slot : old)
            if (slot.epoch == current) lower(slot.key, slot.entry.g, slot.entry.arrival);
    }

public:
    // Frees the table's room when it holds more than `bytes` (kept between searches otherwise).
    void trim(size_t bytes) {
        if (slots_.size() * sizeof(Slot) <= bytes) return;
        std::vector<Slot>().swap(slots_);
        epoch_ = 1;
        used_ = 0;
    }

private:
    std::vector<Slot> slots_;
    uint32_t epoch_ = 1;
    size_t used_ = 0;
};

// Frees a vector's room when it holds more than `bytes`.
template <typename T>
void trim(std::vector<T>& v, size_t bytes) {
    if (v.capacity() * sizeof(T) > bytes) std::vector<T>().swap(v);
}

struct ShortestScratch {
    std::vector<IntervalNode> nodes;
    std::vector<OpenEntry> open;
    std::vector<double> best;  // per dense turning id, valid where best_epoch is current
    std::vector<uint32_t> best_epoch;
    std::vector<Arrival> best_arrival;  // per dense turning id: how the walk at its best cost came
    CostTable best_narrowed;            // per narrowed end's turning id
    std::vector<uint32_t> polygon_epoch;
    // The cheapest cost at which a root on a polygon's edge saw all of the polygon, per (root,
    // polygon): round a vertex the sweep from polygon to polygon would otherwise go on circling.
    CostTable whole_views;
    // Arrivals at a turning point as cheap as its best but across another edge than the best's, per
    // (turning id, edge): a corner shared by several polygons is bent at from each.
    CostTable tied_arrivals;
    std::vector<uint32_t> pending;
    uint32_t epoch = 0;

    // What a search grows (its intervals, open list, tables) stays for the next search on the thread
    // up to kKeptBytes each; beyond, it is freed when the search ends. A thread that once searched
    // across a whole world kept that room for good: 37 MB of intervals on a path worker of a 0.5 km
    // world (massif), some 3 GB over the path workers of a 4 km world streaming tiles.
    static constexpr size_t kKeptBytes = size_t(8) << 20;
    void trim() {
        nl::trim(nodes, kKeptBytes);
        nl::trim(open, kKeptBytes);
        nl::trim(pending, kKeptBytes);
        whole_views.trim(kKeptBytes);
        tied_arrivals.trim(kKeptBytes);
        best_narrowed.trim(kKeptBytes);
    }

    uint32_t begin(uint32_t turning_ids, uint32_t polygons) {
        nodes.clear();
        open.clear();
        pending.clear();
        whole_views.clear();
        tied_arrivals.clear();
        best_narrowed.clear();
        if (best.size() < turning_ids) {
            best.resize(turning_ids), best_epoch.resize(turning_ids, 0);
            best_arrival.resize(turning_ids);
        }
        if (polygon_epoch.size() < polygons) polygon_epoch.resize(polygons, 0);
        if (++epoch == 0) {
            std::fill(best_epoch.begin(), best_epoch.end(), 0);
            std::fill(polygon_epoch.begin(), polygon_epoch.end(), 0);
            epoch = 1;
        }
        return epoch;
    }
};

ShortestScratch& shortest_scratch() {
    thread_local ShortestScratch scratch;
    return scratch;
}

// Narrows [lo, hi] to where s0 + t (s1 - s0) <= 0. False when nothing is left.
inline NL_ALWAYS_INLINE bool keep_nonpositive(double s0, double s1, double& lo, double& hi) {
    if (s0 <= 0.0 && s1 <= 0.0) return lo <= hi;
    if (s0 > 0.0 && s1 > 0.0) return false;
    const double t = s0 / (s0 - s1);
    if (s0 > 0.0)
        lo = std::max(lo, t);
    else
        hi = std::min(hi, t);
    return lo <= hi;
}

// The shortest walk from `root` through the segment [a, b] to `goal`, seen from above: straight when
// the line crosses the segment (after mirroring a goal on the root's side, which the walk must come
// back to), else round the nearer end. `straight` is the distance from root to goal.
double estimate_through(Flat root, Flat a, Flat b, Flat goal, double straight) {
    const Flat along = b - a;
    const double root_side = cross(along, root - a), goal_side = cross(along, goal - a);
    const double length2 = along.x * along.x + along.z * along.z;
    if (length2 == 0.0) return distance(root, a) + distance(a, goal);
    if (root_side == 0.0) return straight;  // on the edge's line: a bound is enough
    const bool mirrored = (root_side > 0.0) == (goal_side > 0.0);
    if (mirrored) {
        // Mirror the goal across the edge's line.
        const double t = ((goal - a).x * along.x + (goal - a).z * along.z) / length2;
        const Flat foot = a + t * along;
        goal = foot + (-1.0) * (goal - foot);
    }
    const Flat direction = goal - root;
    const double denominator = cross(along, direction);
    if (denominator != 0.0) {
        // The length through the edge's line is convex in where it crosses, least where the
        // straight line does: beyond an end, the walk bends at that end.
        const double u = cross(root - a, direction) / denominator;
        if (u < 0.0) return distance(root, a) + distance(a, goal);
        if (u > 1.0) return distance(root, b) + distance(b, goal);
        return mirrored ? distance(root, goal) : straight;
    }
    return std::min(distance(root, a) + distance(a, goal), distance(root, b) + distance(b, goal));
}

class ShortestSearch {
public:
    ShortestSearch(const PathGraph& graph, const PathQuery& query, const NavPoint& goal, float walk_cost,
                   ShortestScratch& scratch, CorridorSearch& result)
        : graph_(graph),
          mesh_(graph.navmesh()),
          query_(query),
          goal_(goal),
          goal_flat_(flat(goal.point)),
          rate_(walk_cost),
          h_scale_(cheapest_link_rate(graph, query, walk_cost)),
          margin_(std::max(0.0f, query.capabilities.radius - graph.navmesh().agent().radius)),
          ids_(mesh_, graph.links_ptr()->size()),
          links_beat_walking_(h_scale_ < rate_),
          keeps_out_(
              std::any_of(query.area_costs.begin(), query.area_costs.end(), [](float cost) { return cost <= 0.0f; })),
          scratch_(scratch),
          epoch_(scratch.begin(ids_.dense_count(), mesh_.polygon_count())),
          result_(result) {}

    void add_start(const NavPoint& start) {
        improve(ids_.start, 0.0);
        generate(IntervalNode{flat(start.point),
                              {},
                              {},
                              0.0,
                              ids_.start,
                              start.polygon,
                              kNoNode,
                              CorridorStep::kStart,
                              kNoNode,
                              kNoNode,
                              kNoNode});
        flush(false);
    }

    // Runs until the goal's cost is the least in the open list.
    void run(const std::atomic<bool>* cancel) {
        uint32_t expansions = 0;
        std::vector<OpenEntry>& open = scratch_.open;
        uint32_t index = kNoNode;  // the node to expand next when it skipped the open list
        for (;;) {
            if (index == kNoNode) {
                if (open.empty() || open.front().f >= best_goal_) break;
                std::pop_heap(open.begin(), open.end(), std::greater<OpenEntry>());
                index = open.back().node;
                open.pop_back();
                if (stale(index)) {
                    index = kNoNode;
                    continue;
                }
            }
            if ((++expansions & (kCancelCheckExpansions - 1)) == 0 && cancel &&
                cancel->load(std::memory_order_relaxed)) {
                result_.cancelled = true;
                return;
            }
            expand(index);
            if (result_.out_of_nodes || result_.gave_up) {
                flush(false);  // a goal reached on the way still counts
                break;
            }
            // A walk with one way on goes on at once (Polyanya's intermediate nodes): its cost
            // only grows, and the open list need not hold it.
            if (pending_.size() == 1) {
                const IntervalNode& next = scratch_.nodes[pending_[0]];
                if (next.edge != kNoNode && next.polygon != goal_.polygon) {
                    index = pending_[0];
                    pending_.clear();
                    continue;
                }
            }
            index = flush(true);
        }
        // Out of nodes with a walk found: a complete path, though perhaps not the shortest.
        result_.reached_goal = goal_parent_ != kNoNode && !result_.gave_up;
    }

    uint32_t node_count() const { return static_cast<uint32_t>(scratch_.nodes.size()); }

    void write_corridor() {
        result_.cost = static_cast<float>(best_goal_);
        const std::vector<IntervalNode>& nodes = scratch_.nodes;
        for (uint32_t i = goal_parent_, guard = 0; i != kNoNode; i = nodes[i].parent) {
            if (++guard > nodes.size())
                fail(ErrorCode::Internal, "exact path search: corridor does not lead back to the start");
            result_.steps.push_back(CorridorStep{nodes[i].polygon, nodes[i].entry});
        }
        std::reverse(result_.steps.begin(), result_.steps.end());
    }

private:
    // Tolerances relative to the costs: two routes of equal length to a corner must both go on (each
    // bends round it to its own side), one longer by rounding must not double the work.
    static constexpr double kRelativeSlack = 1e-9;

    static bool worse(double g, double best) { return g > best * (1.0 + kRelativeSlack) + kRelativeSlack; }
    static bool cheaper(double g, double best) { return g < best * (1.0 - kRelativeSlack) - kRelativeSlack; }
    static uint64_t tie_key(uint32_t id, uint32_t entry) { return (uint64_t(id) << 32) | entry; }

    // The best cost kept for a turning id and the first arrival at it; false when there is none.
    bool best_of(uint32_t id, double& best, const Arrival*& first) const {
        if (id >= ids_.narrowed_base) {
            const CostTable::Entry* entry = scratch_.best_narrowed.find(id);
            if (!entry) return false;
            best = entry->g, first = &entry->arrival;
            return true;
        }
        if (scratch_.best_epoch[id] != epoch_) return false;
        best = scratch_.best[id], first = &scratch_.best_arrival[id];
        return true;
    }
    bool worse_than_best(uint32_t id, double g) const {
        double best;
        const Arrival* first;
        return best_of(id, best, first) && worse(g, best);
    }
    bool landed_no_cheaper(uint32_t id, double g) const {
        double best;
        const Arrival* first;
        return best_of(id, best, first) && !cheaper(g, best);
    }
    // Records g for the turning id unless it was reached more cheaply; false then.
    // `arrival`: how the walk that bends there came (nothing for the start and links' landings).
    bool improve(uint32_t id, double g, const Arrival& arrival = {}) {
        double best;
        const Arrival* first;
        if (best_of(id, best, first)) {
            if (worse(g, best)) return false;
            if (!cheaper(g, best)) {
                // As cheap: kept when it came across another edge than the first.
                if (arrival.entry != kNoNode && arrival.entry != first->entry)
                    scratch_.tied_arrivals.lower(tie_key(id, arrival.entry), g, arrival);
                return true;
            }
        }
        if (id >= ids_.narrowed_base) {
            scratch_.best_narrowed.lower(id, g, arrival);
        } else {
            scratch_.best[id] = g;
            scratch_.best_arrival[id] = arrival;
            scratch_.best_epoch[id] = epoch_;
        }
        return true;
    }
    // Whether a walk arriving as `now` may bend at turning point `at` (turning id `id`) at cost g: not
    // when the point was reached more cheaply another way, nor when a walk already bent there as
    // cheaply, across the same edge, coming the same way (its root on the same ray into the point,
    // within rounding: pillars on one grid line put them so). That one's bent views are the same, on
    // the same side of the ray; left to go on, each such corner in a row would double the nodes after it.
    bool may_bend(uint32_t id, double g, const Arrival& now, Flat at) const {
        double best;
        const Arrival* same;
        if (!best_of(id, best, same)) return true;
        if (worse(g, best)) return false;
        if (cheaper(g, best)) return true;
        if (same->entry != now.entry) {
            const CostTable::Entry* tied = scratch_.tied_arrivals.find(tie_key(id, now.entry));
            if (!tied || cheaper(g, tied->g)) return true;
            same = &tied->arrival;
        }
        const Flat u = at - same->from, v = at - now.from;
        const double along = u.x * v.x + u.z * v.z, across = cross(u, v);
        return !(along > 0.0 && across * across <= kSameRay * (u.x * u.x + u.z * u.z) * (v.x * v.x + v.z * v.z));
    }
    static constexpr double kSameRay = 1e-18;  // squared sine of the angle between rays taken as one

    // A new node, pushed on the open list by flush() unless expanded at once.
    void generate(const IntervalNode& node) {
        uint32_t& seen = scratch_.polygon_epoch[node.polygon];
        if (seen != epoch_) {
            if (query_.max_nodes != 0 && result_.nodes_visited >= query_.max_nodes) {
                result_.out_of_nodes = true;
                return;
            }
            seen = epoch_;
            ++result_.nodes_visited;
        }
        // A few nodes per polygon is the rule (intervals seen from a root or two), some hundred where
        // many routes tie exactly (cell maps with links and a wide body: 100 per polygon); far more
        // means views going round in circles where the navmesh folds over itself seen from above.
        if (scratch_.nodes.size() > kNodesPerPolygon * size_t(result_.nodes_visited) + kNodesAtLeast) {
            result_.gave_up = true;
            return;
        }
        scratch_.nodes.push_back(node);
        pending_.push_back(static_cast<uint32_t>(scratch_.nodes.size() - 1));
    }
    static constexpr size_t kNodesPerPolygon = 256, kNodesAtLeast = 65536;

    // Whether the node's root was reached more cheaply since it was made.
    bool stale(uint32_t index) const { return worse_than_best(scratch_.nodes[index].root_id, scratch_.nodes[index].g); }

    // Puts the nodes just generated on the open list. With `may_keep`, the cheapest of them is kept
    // off it and returned when it would be the next out of it anyway (the walk straight on toward
    // the goal, most often); otherwise kNoNode.
    uint32_t flush(bool may_keep) {
        uint32_t kept = kNoNode;
        double kept_f = kInfinity;
        for (const uint32_t index : pending_) {
            const IntervalNode& node = scratch_.nodes[index];
            if (node.polygon == goal_.polygon) {
                // The goal's cost through this node, at once: the best found so far bounds what the
                // open list need hold.
                View view;
                if (view_of(node, view)) {
                    const double cost = cost_to(view, goal_flat_);
                    if (cost < best_goal_) best_goal_ = cost, goal_parent_ = index;
                }
                // Walking on from the goal's polygon and back costs more than walking to the goal
                // in it (convex) unless some link is cheaper per metre than walking.
                if (!links_beat_walking_) continue;
            }
            // Siblings share their root: its straight distance to the goal once.
            if (node.root.x != straight_root_.x || node.root.z != straight_root_.z)
                straight_root_ = node.root, straight_ = distance(node.root, goal_flat_);
            if (node.g + straight_ * h_scale_ >= best_goal_) continue;  // no estimate is below the straight line's
            const double h =
                node.edge == kNoNode ? straight_ : estimate_through(node.root, node.a, node.b, goal_flat_, straight_);
            const double f = node.g + h * h_scale_;
            if (f >= best_goal_) continue;  // never expanded: the goal is already as cheap
            if (may_keep && f < kept_f) {
                if (kept != kNoNode) push(kept_f, kept);
                kept = index, kept_f = f;
            } else {
                push(f, index);
            }
        }
        pending_.clear();
        // A sibling in the goal's polygon may have priced the goal below it since; its root may
        // have been reached more cheaply (both for good: costs only fall).
        if (kept == kNoNode || kept_f >= best_goal_ || stale(kept)) return kNoNode;
        if (!scratch_.open.empty() && scratch_.open.front().f < kept_f) {
            push(kept_f, kept);
            return kNoNode;
        }
        return kept;
    }

    void push(double f, uint32_t index) {
        scratch_.open.push_back(OpenEntry{f, index});
        std::push_heap(scratch_.open.begin(), scratch_.open.end(), std::greater<OpenEntry>());
    }

    // The turning id of an end of polygon p's edge k's opening (the end at corner k, or at k + 1),
    // or kNoNode when no walk bends there.
    uint32_t turning_id(uint32_t p, uint32_t k, bool far_end) const {
        const uint32_t n = mesh_.corner_count(p);
        const uint32_t v = mesh_.corner(p, far_end ? (k + 1 == n ? 0 : k + 1) : k);
        if (margin_ > 0.0f && mesh_.on_outline(v))
            return ids_.narrowed_base + 2 * mesh_.edge_index(p, k) + (far_end ? 1 : 0);
        return graph_.may_bend_at(v, margin_ > 0.0f) ? v : kNoNode;
    }

    // Which walks from a node's root reach points of its polygon: straight through the interval, or
    // bending at one of its ends when the walk may bend there.
    struct View {
        Flat root, a, b;
        double scale = 0.0;  // the sign of the side tests; 0: every point of the polygon is in view
        double g = 0.0, g_a = kInfinity, g_b = kInfinity;  // costs to the root and to the ends
        uint32_t a_turn = kNoNode, b_turn = kNoNode;

        // Positive: beyond the ray through b (bending at b); negative: beyond the ray through a.
        double beyond_b(Flat x) const { return cross(b - root, x - root) * scale; }
        double beyond_a(Flat x) const { return -cross(a - root, x - root) * scale; }
    };

    double cost_to(const View& view, Flat target) const {
        if (view.scale != 0.0) {
            if (view.beyond_b(target) > 0.0) return view.g_b + rate_ * distance(view.b, target);
            if (view.beyond_a(target) > 0.0) return view.g_a + rate_ * distance(view.a, target);
        }
        return view.g + rate_ * distance(view.root, target);
    }

    // The walks from a node's root into its polygon; false when none goes through its interval (a
    // root on the entry edge's line away from the interval).
    bool view_of(const IntervalNode& node, View& view) const {
        if (node.edge == kNoNode) {
            view = View{node.root, node.a, node.b};
            view.g = node.g;
            return true;
        }
        const uint32_t p = node.polygon, corners = mesh_.corner_count(p), entry = node.edge;
        return view_of(node, flat(mesh_.vertex(mesh_.corner(p, entry))),
                       flat(mesh_.vertex(mesh_.corner(p, entry + 1 == corners ? 0 : entry + 1))), view);
    }
    // The same for a node with an entry edge from `first` to `second`.
    bool view_of(const IntervalNode& node, Flat first, Flat second, View& view) const {
        view = View{node.root, node.a, node.b};
        view.g = node.g;
        const Flat along = second - first;
        const double side = cross(first - node.root, along);
        const Flat to_root = node.root - first;
        const double size2 = (to_root.x * to_root.x + to_root.z * to_root.z) * (along.x * along.x + along.z * along.z);
        // A root lies beyond the entry edge, on the side away from this polygon (polygons lie on the
        // negative side of their edges), or on the edge's line.
        if (side > 0.0 && side * side > 1e-24 * size2) {
            view.scale = 1.0;
            if (node.a_turn != kNoNode)
                view.g_a = node.g + rate_ * distance(node.root, node.a), view.a_turn = node.a_turn;
            if (node.b_turn != kNoNode)
                view.g_b = node.g + rate_ * distance(node.root, node.b), view.b_turn = node.b_turn;
            const Arrival arrival{node.root, mesh_.edge_index(node.polygon, node.edge)};
            if (view.a_turn != kNoNode && !may_bend(view.a_turn, view.g_a, arrival, node.a)) view.g_a = kInfinity;
            if (view.b_turn != kNoNode && !may_bend(view.b_turn, view.g_b, arrival, node.b)) view.g_b = kInfinity;
            return true;
        }
        // The root on the entry edge's line: a corner of this polygon the walk bends at, or a start or
        // a landing located on the edge itself, from which all of it is in view; a root elsewhere on
        // the line sees nothing through. A point located on an edge lies on it within the rounding of
        // its coordinates, on either side: one that far on this polygon's side counts as on the line
        // (else the view from it would be the cone behind it, and the walk would bend at the edge's
        // ends: a start on a portal took the long way round).
        const Flat ab = node.b - node.a;
        const double t = std::clamp(((node.root - node.a).x * ab.x + (node.root - node.a).z * ab.z) /
                                        std::max(ab.x * ab.x + ab.z * ab.z, 1e-300),
                                    0.0, 1.0);
        const double rounding = 4.0 * std::numeric_limits<float>::epsilon() *
                                std::max({1.0, std::fabs(node.root.x), std::fabs(node.root.z)});
        return distance(node.a + t * ab, node.root) <= 1e-6 * (1.0 + std::sqrt(std::sqrt(size2))) + rounding;
    }

    void expand(uint32_t index) {
        const uint32_t p = scratch_.nodes[index].polygon;
        const uint32_t corners = mesh_.corner_count(p);
        // Room for every successor first: `node` stays where it is while they are added.
        const size_t most = scratch_.nodes.size() + 3 * corners + size_t(graph_.exits_end(p) - graph_.exits_begin(p));
        if (scratch_.nodes.capacity() < most) scratch_.nodes.reserve(std::max(most, 2 * scratch_.nodes.capacity()));
        const IntervalNode& node = scratch_.nodes[index];
        const uint32_t entry = node.edge;

        // Each corner's place once: two edges share it.
        Flat at[kMaxPolygonVertices];
        for (uint32_t k = 0; k < corners; ++k) at[k] = flat(mesh_.vertex(mesh_.corner(p, k)));
        View view;
        if (entry == kNoNode ? !view_of(node, view)
                             : !view_of(node, at[entry], at[entry + 1 == corners ? 0 : entry + 1], view))
            return;
        if (entry != kNoNode && view.scale == 0.0) {
            // Round a vertex the sweep from polygon to polygon would otherwise go on circling.
            const uint64_t view_key = (uint64_t(node.root_id) << 32) | p;
            const CostTable::Entry* seen = scratch_.whole_views.find(view_key);
            if (seen && seen->g <= node.g) return;
            scratch_.whole_views.lower(view_key, node.g);
        }

        for (const LinkExit* exit = graph_.exits_begin(p); exit != graph_.exits_end(p); ++exit)
            take_link(index, view, *exit);

        // Two edges share each corner: its sides once.
        double b_side[kMaxPolygonVertices], a_side[kMaxPolygonVertices];
        if (view.scale != 0.0) {
            for (uint32_t k = 0; k < corners; ++k) b_side[k] = view.beyond_b(at[k]), a_side[k] = view.beyond_a(at[k]);
        }
        bool bent_a = false, bent_b = false;
        for (uint32_t k = 0; k < corners; ++k) {
            if (k == entry) continue;
            const uint32_t q = mesh_.neighbour(p, k);
            if (q == kNoPolygon || (keeps_out_ && query_.area_cost(mesh_.area(q)) <= 0.0f)) continue;
            if (graph_.dead_end(p, q, goal_.polygon)) continue;
            const uint32_t next = k + 1 == corners ? 0 : k + 1;
            Flat near_end = at[k], far_end = at[next];  // the opening's ends at corners k and k + 1
            double b0 = b_side[k], b1 = b_side[next], a0 = a_side[k], a1 = a_side[next];
            if (margin_ > 0.0f && (mesh_.on_outline(mesh_.corner(p, k)) || mesh_.on_outline(mesh_.corner(p, next)))) {
                PortalSpan span;
                if (!portal_span(mesh_, p, k, margin_, span)) continue;
                near_end = flat(span.left), far_end = flat(span.right);
                if (view.scale != 0.0) {
                    b0 = view.beyond_b(near_end), b1 = view.beyond_b(far_end);
                    a0 = view.beyond_a(near_end), a1 = view.beyond_a(far_end);
                }
            }
            Successor successor{index, p, k, q, near_end, far_end};
            if (view.scale == 0.0) {
                add(successor, view.root, node.root_id, view.g, 0.0, 1.0);
                continue;
            }
            double lo = 0.0, hi = 1.0;
            if (keep_nonpositive(b0, b1, lo, hi) && keep_nonpositive(a0, a1, lo, hi))
                add(successor, view.root, node.root_id, view.g, lo, hi);
            lo = 0.0, hi = 1.0;
            if (view.g_b < kInfinity && keep_nonpositive(-b0, -b1, lo, hi)) {
                add(successor, view.b, view.b_turn, view.g_b, lo, hi);
                bent_b = true;
            }
            lo = 0.0, hi = 1.0;
            if (view.g_a < kInfinity && keep_nonpositive(-a0, -a1, lo, hi)) {
                add(successor, view.a, view.a_turn, view.g_a, lo, hi);
                bent_a = true;
            }
        }
        if (!bent_a && !bent_b) return;
        const Arrival arrival{node.root, mesh_.edge_index(p, entry)};
        if (bent_a) improve(view.a_turn, view.g_a, arrival);
        if (bent_b) improve(view.b_turn, view.g_b, arrival);
    }

    // One edge of an expanded polygon, the part [lo, hi] of its opening in view from a root.
    struct Successor {
        uint32_t parent, p, k, q;
        Flat near_end, far_end;
    };

    void add(const Successor& s, Flat root, uint32_t root_id, double g, double lo, double hi) {
        // An interval that reaches an end of the opening within rounding ends there, where the walk
        // may bend: a ray along a wall through a corner stops a hair short of it (dungeon: a walk
        // down a straight wall could not turn at its end, and lost the way on).
        constexpr double kSnap = 1e-9;
        if (hi >= 1.0 - kSnap) hi = 1.0;
        if (lo <= kSnap) lo = 0.0;
        if (lo > hi) lo = hi;
        const Flat along = s.far_end - s.near_end;
        // A single point: a walk through a corner of the edge. It goes on into the neighbour only when
        // it leaves this polygon there: round a vertex, polygon after polygon would pass it on.
        if (lo == hi && !leaves_across(s, root, s.near_end + lo * along)) return;
        // In the next polygon the edge runs the other way: its first corner is this one's k + 1.
        const uint8_t twin = graph_.twin_edge(s.p, s.k);
        if (twin == PathGraph::kNoTwin) return;
        generate(IntervalNode{root, s.near_end + hi * along, s.near_end + lo * along, g, root_id, s.q, twin, s.k,
                              s.parent, hi >= 1.0 ? turning_id(s.p, s.k, true) : kNoNode,
                              lo <= 0.0 ? turning_id(s.p, s.k, false) : kNoNode});
    }

    // Whether the line from `root` through `point` (on the edge of s) goes on beyond the edge, away
    // from the polygon it crosses. The navmesh's polygons wind one way (NavMeshBuilder turns them
    // to face up): each lies on the negative side of its edges, corner k to k + 1.
    static bool leaves_across(const Successor& s, Flat root, Flat point) {
        return cross(s.far_end - s.near_end, point - root) > 0.0;
    }

    void take_link(uint32_t index, const View& view, const LinkExit& exit) {
        const Link& link = graph_.link(exit.link).link;
        const bool reversed = exit.reversed != 0;
        if (!can_take(link, reversed, query_.capabilities)) return;
        const uint32_t q = reversed ? link.start_polygon : link.end_polygon;
        if (query_.area_cost(mesh_.area(q)) <= 0.0f) return;
        const Vec3& from = reversed ? link.end : link.start;
        const Vec3& to = reversed ? link.start : link.end;
        const double walked = cost_to(view, flat(from));
        if (walked == kInfinity) return;
        const double g = walked + double((to - from).norm()) * link.cost_modifier + query_.link_cost;
        const uint32_t id = ids_.landing_base + 2 * exit.link + (reversed ? 1u : 0u);
        // A landing reached again at no lower cost sees its polygon as it did: nothing new.
        if (landed_no_cheaper(id, g) || !improve(id, g)) return;
        const uint32_t entry = CorridorStep::kLinkBit | exit.link | (reversed ? CorridorStep::kReversedBit : 0u);
        generate(IntervalNode{flat(to), {}, {}, g, id, q, kNoNode, entry, index, kNoNode, kNoNode});
    }

    const PathGraph& graph_;
    const NavMesh& mesh_;
    const PathQuery& query_;
    const NavPoint& goal_;
    const Flat goal_flat_;
    const double rate_;
    const double h_scale_;
    const float margin_;
    const TurningIds ids_;
    const bool links_beat_walking_;  // some link the body takes costs less per metre than walking
    const bool keeps_out_;           // some area costs the body 0: it keeps out of those polygons
    ShortestScratch& scratch_;
    const uint32_t epoch_;
    CorridorSearch& result_;
    std::vector<uint32_t>& pending_ = scratch_.pending;  // generated by the expansion under way
    Flat straight_root_{kInfinity, kInfinity};           // the last root flush() measured to the goal, and how far
    double straight_ = kInfinity;
    double best_goal_ = kInfinity;
    uint32_t goal_parent_ = kNoNode;
};

}  // namespace

void find_shortest_corridor(const PathGraph& graph, const PathQuery& query, const NavPoint& start, const NavPoint& goal,
                            float walk_cost, const std::atomic<bool>* cancel, CorridorSearch& result) {
    result.steps.clear();
    result.reached_goal = result.out_of_nodes = result.cancelled = result.gave_up = false;
    result.nodes_visited = 0;
    result.cost = 0.0f;
    ShortestScratch& scratch = shortest_scratch();
    ShortestSearch search(graph, query, goal, walk_cost, scratch, result);
    search.add_start(start);
    search.run(cancel);
    result.search_nodes = search.node_count();
    if (!result.cancelled && result.reached_goal) search.write_corridor();
    scratch.trim();
}

}  // namespace nl
