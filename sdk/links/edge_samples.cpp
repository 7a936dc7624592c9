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
    if (planned > kMaxEdgeSamples)
        fail(ErrorCode::InvalidArgument, "sample_spacing ", s.sample_spacing, " m would give ", planned,
             " take-off samples along this navmesh's boundary (at most ", kMaxEdgeSamples, "): raise it");

    std::vector<uint32_t> short_edges;
    for (uint32_t i = 0; i < edges.size(); ++i) {
        const BoundaryEdge& e = edges[i];
        Vec3 outward;
        if (!horizontal_outward(e, outward)) {
            ++out.dropped_edges;
            continue;
        }
        const float length = (e.end - e.start).norm();
        if (length < s.min_edge_length) {
            short_edges.push_back(i);
            continue;
        }
        const auto count = std::max(1u, static_cast<uint32_t>(std::lround(length / s.sample_spacing)));
        for (uint32_t k = 0; k < count; ++k) {
            const float t = (k + 0.5f) / count;
            out.samples.push_back(EdgeSample{e.start + t * (e.end - e.start), outward, e.normal, e.polygon, i});
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
