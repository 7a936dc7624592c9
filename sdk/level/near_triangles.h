// What the level's box and body queries share (private to sdk/level): the triangles near a box,
// gathered by Embree point queries, in world space. Static meshes are asked in the static scene;
// movable ones in their own space, through a sphere grown by the transform's largest stretch (the
// Frobenius norm of the inverse's linear part bounds it), their triangles brought to world space.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "level/geometry.h"
#include "level/oriented_box.h"

namespace nl {

class NearTriangles {
public:
    struct StaticBuffers {  // a static geometry's buffers, as Embree holds them (world space)
        const float* vertices = nullptr;
        const unsigned* indices = nullptr;
    };
    struct Movable {
        RTCScene scene = nullptr;
        const TriangleMesh* object = nullptr;  // object-space vertices
        const Transform* to_world = nullptr;
        Transform to_object;
        float stretch = 1.0f;
        Aabb world_bounds;
    };

    RTCScene static_scene = nullptr;
    std::vector<StaticBuffers> statics;  // by geometry id in the static scene
    std::vector<Movable> movables;

    // Calls visit(a, b, c) with world-space corners for the triangles Embree finds near `box`
    // (every one that touches it, and some that do not), until visit returns true; returns whether
    // one did. Safe to call from several tasks at once while the level's shared lock is held.
    template <typename Visit>
    bool visit_near(const OrientedBox& box, Visit&& visit) const;

private:
    template <typename Visit>
    struct Query {
        const NearTriangles* near;
        Visit* visit;
        const Movable* movable = nullptr;  // null while the static scene is asked
        bool stopped = false;
    };

    template <typename Visit>
    static bool on_triangle(RTCPointQueryFunctionArguments* args);
};

template <typename Visit>
bool NearTriangles::on_triangle(RTCPointQueryFunctionArguments* args) {
    auto& q = *static_cast<Query<Visit>*>(args->userPtr);
    if (q.stopped) return false;
    bool stop;
    if (!q.movable) {
        const auto [vertices, indices] = q.near->statics[args->geomID];
        const unsigned* t = indices + 3 * size_t(args->primID);
        stop = (*q.visit)(vertex_at(vertices, t[0]), vertex_at(vertices, t[1]), vertex_at(vertices, t[2]));
    } else {
        const Triangle& t = q.movable->object->triangles[args->primID];
        const Transform& m = *q.movable->to_world;
        const auto& v = q.movable->object->vertices;
        stop = (*q.visit)(m * v[t[0]], m * v[t[1]], m * v[t[2]]);
    }
    if (!stop) return false;
    q.stopped = true;
    args->query->radius = 0.0f;  // nothing further can change the answer: shrink the search away
    return true;
}

template <typename Visit>
bool NearTriangles::visit_near(const OrientedBox& box, Visit&& visit) const {
    using V = std::remove_reference_t<Visit>;
    Query<V> q{this, &visit};
    RTCPointQueryContext context;
    RTCPointQuery query;
    query.x = box.center.x();
    query.y = box.center.y();
    query.z = box.center.z();
    query.radius = box.bounding_radius();
    query.time = 0.0f;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(static_scene, &query, &context, &on_triangle<V>, &q);
    if (q.stopped || movables.empty()) return q.stopped;
    const Vec3 reach = box.axes.cwiseAbs() * box.half_extents;
    const Aabb bounds{box.center - reach, box.center + reach};
    for (const Movable& movable : movables) {
        if ((bounds.max.array() < movable.world_bounds.min.array()).any() ||
            (movable.world_bounds.max.array() < bounds.min.array()).any())
            continue;
        const Vec3 centre = movable.to_object * box.center;
        query.x = centre.x();
        query.y = centre.y();
        query.z = centre.z();
        query.radius = box.bounding_radius() * movable.stretch;
        q.movable = &movable;
        rtcInitPointQueryContext(&context);
        rtcPointQuery(movable.scene, &query, &context, &on_triangle<V>, &q);
        if (q.stopped) return true;
    }
    return false;
}

}  // namespace nl
