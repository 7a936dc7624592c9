// What the level's box and body queries share (private to sdk/level): the triangles near a box,
// gathered by Embree point queries, in world space. Static meshes are asked in the static scene;
// movable ones in their own space, through a sphere grown by the transform's largest stretch (the
// Frobenius norm of the inverse's linear part bounds it), their triangles brought to world space.
#pragma once

#include <embree3/rtcore.h>

#include <utility>
#include <vector>

#include "level/geometry.h"
#include "level/oriented_box.h"
#include "util/handle.h"

namespace nl {

struct MeshPlacement;

class NearTriangles {
public:
    struct StaticBuffers {  // a static geometry's buffers, as Embree holds them (world space)
        const float* vertices = nullptr;
        const unsigned* indices = nullptr;
    };
    struct Movable {
        Handle mesh;
        RTCScene scene = nullptr;
        const TriangleMesh* object = nullptr;  // object-space vertices
        Aabb object_bounds;
        Transform to_world;
        Transform to_object;
        float stretch = 1.0f;
        Aabb world_bounds;

        // The mesh placed by `to_world` instead.
        void place(const Transform& to_world);
    };

    RTCScene static_scene = nullptr;
    std::vector<StaticBuffers> statics;  // by geometry id in the static scene
    std::vector<Movable> movables;

    // Calls visit(a, b, c) with world-space corners for the triangles Embree finds near `box`
    // (every one that touches it, and some that do not), until visit returns true; returns whether
    // one did. Safe to call from several tasks at once while the level's shared lock is held.
    template <typename Visit>
    bool visit_near(const OrientedBox& box, Visit&& visit) const {
        return visit_near(box, movables, std::forward<Visit>(visit));
    }
    // The same, with the movable meshes placed as `placed` says (from placed()).
    template <typename Visit>
    bool visit_near(const OrientedBox& box, const std::vector<Movable>& placed, Visit&& visit) const;

    // The movable meshes with those that `placements` names placed there.
    std::vector<Movable> placed(const MeshPlacement* placements, uint32_t count) const;

private:
    template <typename Visit>
    struct Query {
        const NearTriangles* near;
        Visit* visit;
        Aabb reach;                        // the box's world bounds: a triangle outside them is skipped
        const Movable* movable = nullptr;  // null while the static scene is asked
        bool stopped = false;
    };

    // Whether the triangle's bounds miss `reach` (cheap, and most of the triangles a sphere gathers
    // around a long box do: the floor under a body, a wall beside it).
    static bool outside(const Aabb& reach, const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
        return (hi.array() < reach.min.array()).any() || (reach.max.array() < lo.array()).any();
    }

    template <typename Visit>
    static bool on_triangle(RTCPointQueryFunctionArguments* args);
};

template <typename Visit>
bool NearTriangles::on_triangle(RTCPointQueryFunctionArguments* args) {
    auto& q = *static_cast<Query<Visit>*>(args->userPtr);
    if (q.stopped) return false;
    Vec3 a, b, c;
    if (!q.movable) {
        const auto [vertices, indices] = q.near->statics[args->geomID];
        const unsigned* t = indices + 3 * size_t(args->primID);
        a = vertex_at(vertices, t[0]), b = vertex_at(vertices, t[1]), c = vertex_at(vertices, t[2]);
    } else {
        const Triangle& t = q.movable->object->triangles[args->primID];
        const Transform& m = q.movable->to_world;
        const auto& v = q.movable->object->vertices;
        a = m * v[t[0]], b = m * v[t[1]], c = m * v[t[2]];
    }
    if (outside(q.reach, a, b, c)) return false;
    const bool stop = (*q.visit)(a, b, c);
    if (!stop) return false;
    q.stopped = true;
    args->query->radius = 0.0f;  // nothing further can change the answer: shrink the search away
    return true;
}

template <typename Visit>
bool NearTriangles::visit_near(const OrientedBox& box, const std::vector<Movable>& placed, Visit&& visit) const {
    using V = std::remove_reference_t<Visit>;
    const Vec3 extent = box.axes.cwiseAbs() * box.half_extents;
    // Padded as the exact tests pad: bounds only ever skip what those would call apart.
    const Vec3 pad = Vec3::Constant(0.05f + 1e-6f * box.center.cwiseAbs().maxCoeff());
    Query<V> q{this, &visit, Aabb{box.center - extent - pad, box.center + extent + pad}};
    RTCPointQueryContext context;
    RTCPointQuery query;
    query.x = box.center.x();
    query.y = box.center.y();
    query.z = box.center.z();
    query.radius = box.bounding_radius();
    query.time = 0.0f;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(static_scene, &query, &context, &on_triangle<V>, &q);
    if (q.stopped || placed.empty()) return q.stopped;
    for (const Movable& movable : placed) {
        if ((q.reach.max.array() < movable.world_bounds.min.array()).any() ||
            (movable.world_bounds.max.array() < q.reach.min.array()).any())
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
