// Level::triangles_to_build_in_columns: the triangles a build of some tiles reads, found through
// Embree's point queries over the static scene, so that building or hashing one tile of a 4 km world
// reads the few hundred triangles around it rather than copying ten million.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "level/level.h"
#include "level/near_triangles.h"

namespace nl {
namespace {

struct ColumnsQuery {
    const NearTriangles* near;
    const std::vector<uint8_t>* built;  // by geometry id: a static mesh builds read
    const Columns* columns;
    std::vector<std::pair<unsigned, unsigned>> found;  // geometry id, triangle
};

bool on_triangle(RTCPointQueryFunctionArguments* args) {
    auto& q = *static_cast<ColumnsQuery*>(args->userPtr);
    if (args->geomID >= q.built->size() || !(*q.built)[args->geomID]) return false;
    const auto [vertices, indices] = q.near->statics[args->geomID];
    const unsigned* t = indices + 3 * size_t(args->primID);
    if (q.columns->met_by(vertex_at(vertices, t[0]), vertex_at(vertices, t[1]), vertex_at(vertices, t[2])))
        q.found.push_back({args->geomID, args->primID});
    return false;
}

// The triangles of `all` that meet `columns`, with only the vertices they use.
BuildTriangles only_in_columns(const BuildTriangles& all, const Columns& columns) {
    BuildTriangles out;
    std::vector<uint32_t> renumbered(all.mesh.vertices.size(), UINT32_MAX);
    const auto& v = all.mesh.vertices;
    for (size_t k = 0; k < all.mesh_starts.size(); ++k) {
        bool started = false;
        for (size_t i = all.mesh_starts[k].first; i < all.mesh_end(k); ++i) {
            const Triangle& t = all.mesh.triangles[i];
            if (!columns.met_by(v[t[0]], v[t[1]], v[t[2]])) continue;
            if (!started) out.mesh_starts.push_back({all.mesh_starts[k].mesh, out.mesh.triangles.size()});
            started = true;
            Triangle kept;
            for (int c = 0; c < 3; ++c) {
                if (renumbered[t[c]] == UINT32_MAX) {
                    renumbered[t[c]] = uint32_t(out.mesh.vertices.size());
                    out.mesh.vertices.push_back(v[t[c]]);
                }
                kept[c] = renumbered[t[c]];
            }
            out.mesh.triangles.push_back(kept);
            out.areas.push_back(all.areas[i]);
        }
    }
    return out;
}

}  // namespace

BuildTriangles Level::triangles_to_build_in_columns(Handle carrier, const Columns& columns, Aabb& out_bounds) const {
    if (!std::isfinite(columns.min_x) || !std::isfinite(columns.min_z) || !std::isfinite(columns.max_x) ||
        !std::isfinite(columns.max_z) || columns.min_x > columns.max_x || columns.min_z > columns.max_z)
        fail(ErrorCode::InvalidArgument, "the columns [", columns.min_x, ", ", columns.max_x, "] x [", columns.min_z,
             ", ", columns.max_z, "] are not finite or have min > max");
    out_bounds = Aabb{};
    if (carrier != Handle{}) {
        // A carrier's mesh, in its own space: one mesh, read whole.
        const BuildTriangles all = triangles_to_build(carrier);
        for (const Vec3& p : all.mesh.vertices) out_bounds.grow(p);
        return only_in_columns(all, columns);
    }
    const auto lock = lock_committed();
    std::vector<uint8_t> built(static_geometry_owner_.size(), 0);
    meshes_.for_each([&](Handle, const Mesh& m) {
        if (!read_by_static_builds(m.flags)) return;
        out_bounds.grow(m.world_bounds.min);
        out_bounds.grow(m.world_bounds.max);
        built[m.geometry_id] = 1;
    });
    BuildTriangles out;
    // The part of the columns the level reaches: a sphere around it finds every triangle that meets them.
    const double lo_x = std::max(columns.min_x, double(out_bounds.min.x())),
                 hi_x = std::min(columns.max_x, double(out_bounds.max.x())),
                 lo_z = std::max(columns.min_z, double(out_bounds.min.z())),
                 hi_z = std::min(columns.max_z, double(out_bounds.max.z()));
    if (out_bounds.empty() || lo_x > hi_x || lo_z > hi_z) return out;
    const Vec3 lo(float(lo_x), out_bounds.min.y(), float(lo_z)), hi(float(hi_x), out_bounds.max.y(), float(hi_z));
    const Vec3 centre = 0.5f * (lo + hi);
    const NearTriangles near = near_triangles();
    ColumnsQuery q{&near, &built, &columns, {}};
    RTCPointQuery query;
    query.x = centre.x();
    query.y = centre.y();
    query.z = centre.z();
    // Padded for rounding: a triangle the sphere leaves out is a triangle lost to a tile.
    query.radius = 0.5f * (hi - lo).norm() * 1.001f + 1e-3f + 1e-6f * centre.cwiseAbs().maxCoeff();
    query.time = 0.0f;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(static_scene_, &query, &context, &on_triangle, &q);
    // In the order triangles_to_build gives them (Embree finds them in its own, some more than once).
    std::sort(q.found.begin(), q.found.end());
    q.found.erase(std::unique(q.found.begin(), q.found.end()), q.found.end());
    meshes_.for_each([&](Handle h, const Mesh& m) {
        if (!read_by_static_builds(m.flags)) return;
        auto first = std::lower_bound(q.found.begin(), q.found.end(), std::make_pair(m.geometry_id, 0u));
        if (first == q.found.end() || first->first != m.geometry_id) return;
        out.mesh_starts.push_back({h, out.mesh.triangles.size()});
        const auto [vertices, indices] = near.statics[m.geometry_id];
        const bool mirrored = m.transform.linear().determinant() < 0.0f;
        const auto last = std::find_if(first, q.found.end(), [&](const auto& f) { return f.first != m.geometry_id; });
        // The vertices the triangles use, each once, in the mesh's order.
        std::vector<uint32_t> used;
        for (auto f = first; f != last; ++f)
            for (uint32_t corner : m.object.triangles[f->second]) used.push_back(corner);
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        const auto base = uint32_t(out.mesh.vertices.size());
        for (uint32_t corner : used) out.mesh.vertices.push_back(vertex_at(vertices, corner));
        auto index_of = [&](uint32_t corner) {
            return base + uint32_t(std::lower_bound(used.begin(), used.end(), corner) - used.begin());
        };
        for (; first != last; ++first) {
            const Triangle t = wound_as_placed(m.object.triangles[first->second], mirrored);
            out.mesh.triangles.push_back({index_of(t[0]), index_of(t[1]), index_of(t[2])});
            out.areas.push_back(build_area(m.flags, m.area));
        }
    });
    return out;
}

}  // namespace nl
