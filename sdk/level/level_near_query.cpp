// The level's queries of what is near a box: Level::boxes_empty (does any triangle touch it?) and
// Level::bodies_clear (is a swept body apart from every triangle?). Embree's point queries gather
// the triangles near each box (near_triangles.h); exact tests decide each one.
#include <algorithm>

#include "level/level.h"
#include "level/near_triangles.h"

namespace nl {

NearTriangles Level::near_triangles() const {
    NearTriangles near;
    near.static_scene = static_scene_;
    near.statics.resize(static_geometry_owner_.size());
    meshes_.for_each([&](Handle, const Mesh& m) {
        if (!m.own_scene) {
            near.statics[m.geometry_id] = NearTriangles::StaticBuffers{
                static_cast<const float*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_VERTEX, 0)),
                static_cast<const unsigned*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_INDEX, 0))};
            return;
        }
        const Transform inverse = m.transform.inverse(Eigen::Affine);
        near.movables.push_back(
            NearTriangles::Movable{m.own_scene, &m.object, &m.transform, inverse, inverse.linear().norm(), m.world_bounds});
    });
    return near;
}

void Level::boxes_empty(const OrientedBox* boxes, uint32_t count, uint8_t* out_empty) const {
    const auto lock = lock_committed();
    const NearTriangles near = near_triangles();
    tasks_.parallel_for(count, 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const OrientedBox& box = boxes[i];
            const bool touched =
                near.visit_near(box, [&](const Vec3& a, const Vec3& b, const Vec3& c) { return triangle_overlaps_box(a, b, c, box); });
            out_empty[i] = touched ? 0 : 1;
        }
    });
}

void Level::bodies_clear(const BodyStretch* stretches, uint32_t count, const float* radii, uint32_t radius_count,
                         uint8_t* out_cleared) const {
    const auto lock = lock_committed();
    const NearTriangles near = near_triangles();
    tasks_.parallel_for(count, 16, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const BodyStretch& s = stretches[i];
            const double margin = body_margin(s.body.from.cwiseAbs().cwiseMax(s.body.to.cwiseAbs()));
            uint32_t cleared = radius_count;
            // Bodies of the radii are nested: a triangle apart from one is apart from the narrower ones.
            near.visit_near(s.bounds, [&](const Vec3& a, const Vec3& b, const Vec3& c) {
                if (!triangle_overlaps_box(a, b, c, s.bounds)) return false;
                const std::array<Vec3, 3> triangle{a, b, c};
                SweptCylinder body = s.body;
                while (cleared > 0) {
                    body.radius = radii[cleared - 1];
                    if (proven_apart(body, triangle, margin)) break;
                    --cleared;
                }
                return cleared == 0;
            });
            out_cleared[i] = static_cast<uint8_t>(cleared);
        }
    });
}

}  // namespace nl
