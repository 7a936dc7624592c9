// Level::boxes_empty: Embree point queries gather the triangles near a box, an exact separating-axis
// test decides each one.
#include <algorithm>
#include <cmath>
#include <vector>

#include "level/level.h"

namespace nl {
namespace {

// A static geometry's buffers, as Embree holds them (world space).
struct StaticBuffers {
    const float* vertices = nullptr;
    const unsigned* indices = nullptr;
};

// What the point query callback needs: the box, where the triangles are, and the answer so far.
struct BoxQuery {
    const OrientedBox* box = nullptr;
    const std::vector<StaticBuffers>* statics = nullptr;  // by geomID in the static scene
    const TriangleMesh* object = nullptr;  // or a movable mesh's, in its space, with its transform
    const Transform* transform = nullptr;
    bool overlap = false;
};

bool stop_query(RTCPointQueryFunctionArguments* args, BoxQuery& q) {
    q.overlap = true;
    args->query->radius = 0.0f;  // nothing further can change the answer: shrink the search away
    return true;
}

bool static_triangle_near(RTCPointQueryFunctionArguments* args) {
    auto& q = *static_cast<BoxQuery*>(args->userPtr);
    if (q.overlap) return false;
    const auto [vertices, indices] = (*q.statics)[args->geomID];
    const unsigned* t = indices + 3 * size_t(args->primID);
    if (triangle_overlaps_box(vertex_at(vertices, t[0]), vertex_at(vertices, t[1]), vertex_at(vertices, t[2]), *q.box))
        return stop_query(args, q);
    return false;
}

bool movable_triangle_near(RTCPointQueryFunctionArguments* args) {
    auto& q = *static_cast<BoxQuery*>(args->userPtr);
    if (q.overlap) return false;
    const Triangle& t = q.object->triangles[args->primID];
    const Transform& m = *q.transform;
    if (triangle_overlaps_box(m * q.object->vertices[t[0]], m * q.object->vertices[t[1]], m * q.object->vertices[t[2]], *q.box))
        return stop_query(args, q);
    return false;
}

Aabb world_bounds(const OrientedBox& box) {
    const Vec3 reach = box.axes.cwiseAbs() * box.half_extents;
    Aabb out;
    out.grow(box.center - reach);
    out.grow(box.center + reach);
    return out;
}

bool overlaps(const Aabb& a, const Aabb& b) {
    return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace

void Level::boxes_empty(const OrientedBox* boxes, uint32_t count, uint8_t* out_empty) const {
    const auto lock = lock_committed();
    // Movable meshes are asked in their own space, through a sphere grown by the transform's largest
    // stretch (the Frobenius norm bounds it), and their triangles tested in world space.
    struct Movable {
        const Mesh* mesh;
        Transform to_object;
        float stretch;
    };
    std::vector<Movable> movables;
    std::vector<StaticBuffers> statics(static_geometry_owner_.size());
    meshes_.for_each([&](Handle, const Mesh& m) {
        if (!m.own_scene) {
            statics[m.geometry_id] = StaticBuffers{
                static_cast<const float*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_VERTEX, 0)),
                static_cast<const unsigned*>(rtcGetGeometryBufferData(m.geometry, RTC_BUFFER_TYPE_INDEX, 0))};
            return;
        }
        const Transform inverse = m.transform.inverse(Eigen::Affine);
        movables.push_back(Movable{&m, inverse, inverse.linear().norm()});
    });
    tasks_.parallel_for(count, 64, [&](uint32_t begin, uint32_t end) {
        RTCPointQueryContext context;
        for (uint32_t i = begin; i < end; ++i) {
            const OrientedBox& box = boxes[i];
            BoxQuery q;
            q.box = &box;
            q.statics = &statics;
            RTCPointQuery query;
            query.x = box.center.x();
            query.y = box.center.y();
            query.z = box.center.z();
            query.radius = box.bounding_radius();
            query.time = 0.0f;
            rtcInitPointQueryContext(&context);
            rtcPointQuery(static_scene_, &query, &context, static_triangle_near, &q);
            if (!q.overlap && !movables.empty()) {
                const Aabb reach = world_bounds(box);
                for (const Movable& movable : movables) {
                    if (q.overlap) break;
                    if (!overlaps(reach, movable.mesh->world_bounds)) continue;
                    const Vec3 centre = movable.to_object * box.center;
                    query.x = centre.x();
                    query.y = centre.y();
                    query.z = centre.z();
                    query.radius = box.bounding_radius() * movable.stretch;
                    q.object = &movable.mesh->object;
                    q.transform = &movable.mesh->transform;
                    rtcInitPointQueryContext(&context);
                    rtcPointQuery(movable.mesh->own_scene, &query, &context, movable_triangle_near, &q);
                }
            }
            out_empty[i] = q.overlap ? 0 : 1;
        }
    });
}

}  // namespace nl
