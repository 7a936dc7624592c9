#include "links/edge_samples.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "util/error.h"

namespace nl {
namespace {

bool horizontal_outward(const BoundaryEdge& e, Vec3& out) {
    out = Vec3(e.outward.x(), 0.0f, e.outward.z());
    const float length = out.norm();
    if (!(length >= 1e-3f)) return false;  // a vertical polygon's edge has no outside (or a NaN one)
    out /= length;
    return true;
}

// The vertex indices of a boundary edge (corner order of its polygon).
std::pair<uint32_t, uint32_t> vertices_of(const NavMesh& m, const BoundaryEdge& e) {
    return {m.corner(e.polygon, e.edge), m.corner(e.polygon, (e.edge + 1) % m.corner_count(e.polygon))};
}

// Whether a vertex lies on a line between tiles.
bool on_tile_line(const TileGrid& grid, const Vec3& v) {
    if (!grid.tiled()) return false;
    const auto on_line = [&](float c, float origin) {
        const double k = (double(c) - origin) / grid.tile_width;
        return std::fabs(k - std::round(k)) * grid.tile_width <= 1e-3;
    };
    return on_line(v.x(), grid.origin_x) || on_line(v.z(), grid.origin_z);
}

// A tiled navmesh's boundary is cut where it crosses a line between tiles: the pieces of one straight
// outline are joined again into one edge (`run`, the pieces in order), so that a ledge is sampled and
// ranked as the solo navmesh's is, whatever the tile size. On a solo navmesh every run is one edge.
struct Run {
    std::vector<uint32_t> pieces;
    Vec3 start, end;
    float length() const { return (end - start).norm(); }
};

std::vector<Run> straight_runs(const NavMesh& m, const std::vector<BoundaryEdge>& edges) {
    const TileGrid& grid = m.tiles().grid;
    std::vector<uint32_t> next(edges.size(), UINT32_MAX), previous(edges.size(), UINT32_MAX);
    if (grid.tiled()) {
        std::unordered_map<uint32_t, std::vector<uint32_t>> starting_at;
        for (uint32_t i = 0; i < edges.size(); ++i) starting_at[vertices_of(m, edges[i]).first].push_back(i);
        for (uint32_t i = 0; i < edges.size(); ++i) {
            const uint32_t joint = vertices_of(m, edges[i]).second;
            const auto found = starting_at.find(joint);
            if (found == starting_at.end() || found->second.size() != 1 || !on_tile_line(grid, m.vertex(joint)))
                continue;
            const uint32_t j = found->second.front();
            const Vec3 a = (edges[i].end - edges[i].start).normalized(),
                       b = (edges[j].end - edges[j].start).normalized();
            if (j == i || a.dot(b) < 0.9999f || edges[i].outward.dot(edges[j].outward) < 0.9999f) continue;
            next[i] = j;
            previous[j] = i;
        }
    }
    std::vector<Run> runs;
    std::vector<uint8_t> taken(edges.size(), 0);
    for (uint32_t i = 0; i < edges.size(); ++i) {
        if (previous[i] != UINT32_MAX || taken[i]) continue;
        Run run;
        for (uint32_t e = i; e != UINT32_MAX && !taken[e]; e = next[e]) {
            taken[e] = 1;
            run.pieces.push_back(e);
        }
        run.start = edges[run.pieces.front()].start;
        run.end = edges[run.pieces.back()].end;
        runs.push_back(std::move(run));
    }
    for (uint32_t i = 0; i < edges.size(); ++i)  // a ring of pieces (never straight: none in practice)
        if (!taken[i]) runs.push_back(Run{{i}, edges[i].start, edges[i].end});
    return runs;
}

// The piece of `run` that the point `t` of the way along it lies on.
uint32_t piece_at(const Run& run, const std::vector<BoundaryEdge>& edges, float t) {
    float along = t * run.length();
    for (uint32_t piece : run.pieces) {
        along -= (edges[piece].end - edges[piece].start).norm();
        if (along <= 0.0f) return piece;
    }
    return run.pieces.back();
}

}  // namespace

EdgeSampling sample_edges(const NavMesh& navmesh, const LinkSettings& s) {
    EdgeSampling out;
    const std::vector<BoundaryEdge> edges = navmesh.boundary_edges();
    out.edges = static_cast<uint32_t>(edges.size());

    // Counted before anything is allocated: a huge navmesh with a fine spacing is refused, not a
    // generation that runs out of memory or overflows its counts.
    double planned = 0.0;
    for (const BoundaryEdge& e : edges)
        planned += std::max(1.0, std::round(double((e.end - e.start).norm()) / s.sample_spacing));
    const std::vector<Run> runs = straight_runs(navmesh, edges);
    if (planned > kMaxEdgeSamples)
        fail(ErrorCode::InvalidArgument, "sample_spacing ", s.sample_spacing, " m would give ", planned,
             " take-off samples along this navmesh's boundary (at most ", kMaxEdgeSamples, "): raise it");

    std::vector<uint32_t> short_edges;
    for (const Run& run : runs) {
        const uint32_t i = run.pieces.front();  // the run's edge, as ranking knows it
        Vec3 outward;
        if (!horizontal_outward(edges[i], outward)) {
            out.dropped_edges += static_cast<uint32_t>(run.pieces.size());
            continue;
        }
        const float length = run.length();
        if (length < s.min_edge_length) {
            short_edges.insert(short_edges.end(), run.pieces.begin(), run.pieces.end());
            continue;
        }
        const auto count = std::max(1u, static_cast<uint32_t>(std::lround(length / s.sample_spacing)));
        for (uint32_t k = 0; k < count; ++k) {
            const float t = (k + 0.5f) / count;
            const BoundaryEdge& on = edges[piece_at(run, edges, t)];
            out.samples.push_back(EdgeSample{run.start + t * (run.end - run.start), outward, on.normal, on.polygon, i});
        }
    }

    // Chains of short edges: boundary edges meet at shared vertices, at most two per vertex on a
    // manifold outline. Walk each chain from an end (or anywhere, for a closed ring).
    std::unordered_map<uint32_t, std::vector<uint32_t>> at_vertex;
    for (uint32_t i : short_edges) {
        const auto [a, b] = vertices_of(navmesh, edges[i]);
        at_vertex[a].push_back(i);
        at_vertex[b].push_back(i);
    }
    std::unordered_map<uint32_t, bool> visited;
    auto neighbours = [&](uint32_t i) {
        std::vector<uint32_t> n;
        const auto [a, b] = vertices_of(navmesh, edges[i]);
        for (uint32_t v : {a, b})
            for (uint32_t j : at_vertex[v])
                if (j != i) n.push_back(j);
        return n;
    };
    auto emit_group = [&](const std::vector<uint32_t>& group) {
        if (group.size() < s.min_group_size) {
            out.dropped_edges += static_cast<uint32_t>(group.size());
            return;
        }
        Vec3 average = Vec3::Zero();
        for (uint32_t i : group) {
            Vec3 o;
            horizontal_outward(edges[i], o);
            average += o;
        }
        if (average.norm() < 1e-3f) {  // a group facing every way (a small island) has no direction
            out.dropped_edges += static_cast<uint32_t>(group.size());
            return;
        }
        average.normalize();
        uint32_t best = group.front();
        float best_dot = -2.0f;
        for (uint32_t i : group) {
            Vec3 o;
            horizontal_outward(edges[i], o);
            if (o.dot(average) > best_dot) {
                best_dot = o.dot(average);
                best = i;
            }
        }
        const BoundaryEdge& e = edges[best];
        out.samples.push_back(EdgeSample{0.5f * (e.start + e.end), average, e.normal, e.polygon, best});
        ++out.groups;
    };
    std::sort(short_edges.begin(), short_edges.end());
    for (int pass = 0; pass < 2; ++pass) {
        // First pass starts at chain ends (edges with fewer than two short neighbours); the second
        // picks up closed rings.
        for (uint32_t start : short_edges) {
            if (visited[start] || (pass == 0 && neighbours(start).size() >= 2)) continue;
            std::vector<uint32_t> chain;
            for (uint32_t current = start;;) {
                visited[current] = true;
                chain.push_back(current);
                uint32_t next = UINT32_MAX;
                for (uint32_t j : neighbours(current))
                    if (!visited[j]) next = std::min(next, j);
                if (next == UINT32_MAX) break;
                current = next;
            }
            for (size_t first = 0; first < chain.size(); first += s.max_group_size) {
                const size_t last = std::min(chain.size(), first + s.max_group_size);
                emit_group(std::vector<uint32_t>(chain.begin() + first, chain.begin() + last));
            }
        }
    }
    return out;
}

}  // namespace nl
