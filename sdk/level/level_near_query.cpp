// The level's queries of what is near a box: Level::boxes_empty (does any triangle touch it?) and
// Level::bodies_clear (is a swept body apart from every triangle?). Embree's point queries gather
// the triangles near each box (near_triangles.h); exact tests decide each one.
#include <algorithm>
#include <atomic>

#include "level/level.h"
#include "level/near_triangles.h"

namespace nl {

NearTriangles Level::near_triangles() const {
    NearTriangles near;
    near.static_scene = static_scene_;
    near.statics.resize(static_geometry_owner_.size());
    meshes_.for_each([&](Handle h, const Mesh& m) {
        if (!m.own_scene) {
            near.statics[m.geometry_id] = NearTriangles::StaticBuffers{
                static_cast<const float*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_VERTEX, 0)),
                static_cast<const unsigned*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_INDEX, 0))};
            return;
        }
        NearTriangles::Movable movable;
        movable.mesh = h;
        movable.scene = m.own_scene;
        movable.object = &m.object;
        movable.object_bounds = m.object_bounds;
        movable.place(m.transform);
        movable.world_bounds = m.world_bounds;  // exact, where place() bounds the object's box
        near.movables.push_back(movable);
    });
    return near;
}

void NearTriangles::Movable::place(const Transform& transform) {
    to_world = transform;
    to_object = transform.inverse(Eigen::Affine);
    stretch = to_object.linear().norm();
    world_bounds = transformed_box(object_bounds, transform);
}

std::vector<NearTriangles::Movable> NearTriangles::placed(const MeshPlacement* placements, uint32_t count) const {
    std::vector<Movable> out = movables;
    for (uint32_t i = 0; i < count; ++i)
        for (Movable& m : out)
            if (m.mesh == placements[i].mesh) m.place(placements[i].transform);
    return out;
}

void Level::boxes_empty(const OrientedBox* boxes, uint32_t count, uint8_t* out_empty) const {
    const auto lock = lock_committed();
    const NearTriangles near = near_triangles();
    tasks_.parallel_for(count, 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const OrientedBox& box = boxes[i];
            const bool touched = near.visit_near(
                box, [&](const Vec3& a, const Vec3& b, const Vec3& c) { return triangle_overlaps_box(a, b, c, box); });
            out_empty[i] = touched ? 0 : 1;
        }
    });
}

void Level::bodies_clear(const BodyStretch* stretches, uint32_t count, const float* radii, uint32_t radius_count,
                         uint8_t* out_cleared) const {
    std::vector<BodyGroup> singles(count);
    for (uint32_t i = 0; i < count; ++i) singles[i] = BodyGroup{stretches[i].bounds, i, 1};
    bodies_clear(singles.data(), count, stretches, radii, radius_count, out_cleared);
}

uint64_t Level::bodies_clear(const BodyGroup* groups, uint32_t group_count, const BodyStretch* stretches,
                             const float* radii, uint32_t radius_count, uint8_t* out_cleared) const {
    const auto lock = lock_committed();
    const NearTriangles near = near_triangles();
    std::atomic<uint64_t> tested{0};
    tasks_.parallel_for(group_count, 8, [&](uint32_t begin, uint32_t end) {
        std::vector<std::array<Vec3, 3>> inside;  // the triangles in the group's box
        uint64_t tested_here = 0;
        for (uint32_t g = begin; g < end; ++g) {
            const BodyGroup& group = groups[g];
            inside.clear();
            const auto gather = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
                if (triangle_overlaps_box(a, b, c, group.bounds)) inside.push_back({a, b, c});
                return false;
            };
            if (group.placed_count == 0)
                near.visit_near(group.bounds, gather);
            else
                near.visit_near(group.bounds, near.placed(group.placed, group.placed_count), gather);
            for (uint32_t i = group.first; i < group.first + group.count; ++i) {
                const BodyStretch& s = stretches[i];
                const double margin = body_margin(s.body.from.cwiseAbs().cwiseMax(s.body.to.cwiseAbs()));
                uint32_t cleared = radius_count;
                bool met = false;
                // Bodies of the radii are nested: a triangle apart from one is apart from the narrower ones.
                for (const auto& triangle : inside) {
                    if (!triangle_overlaps_box(triangle[0], triangle[1], triangle[2], s.bounds)) continue;
                    met = true;
                    SweptCylinder body = s.body;
                    while (cleared > 0) {
                        body.radius = radii[cleared - 1];
                        if (proven_apart(body, triangle, margin)) break;
                        --cleared;
                    }
                    if (cleared == 0) break;
                }
                tested_here += met;
                out_cleared[i] = static_cast<uint8_t>(cleared);
            }
        }
        tested.fetch_add(tested_here, std::memory_order_relaxed);
    });
    return tested.load();
}

}  // namespace nl
