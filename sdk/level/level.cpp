#include "level/level.h"

#include <algorithm>
#include <mutex>

#include "util/error.h"

namespace nl {
namespace {

void set_instance_transform(RTCGeometry instance, const Transform& t) {
    const Eigen::Matrix4f m = t.matrix();  // column-major, as Embree's FLOAT4X4_COLUMN_MAJOR
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, m.data());
    rtcCommitGeometry(instance);
}

Aabb bounds_of(const TriangleMesh& mesh, const Transform& t) {
    Aabb box;
    for (const Vec3& v : mesh.vertices) box.grow(t * v);
    return box;
}

// The vertices brought from the host's units and up axis into NavLink's frame; empty when they are
// in it already.
TriangleMesh in_navlink_frame(const TriangleMesh& given, const MeshFrame& frame) {
    if (!(frame.metres_per_unit == 0.0f ||
          (frame.metres_per_unit >= kLeastMetresPerUnit && frame.metres_per_unit <= kMostMetresPerUnit)))
        fail_field(ErrorCode::InvalidArgument, "metres_per_unit is ", frame.metres_per_unit,
                   " (0 for metres not said, or ", kLeastMetresPerUnit, " to ", kMostMetresPerUnit,
                   ": 0.01 for centimetres, 0.0254 for inches)");
    if (frame.up != UpAxis::NotSaid && frame.up != UpAxis::Y && frame.up != UpAxis::Z)
        fail_field(ErrorCode::InvalidArgument, "up_axis is ", uint32_t(frame.up),
                   " (NL_UP_AXIS_NOT_SAID, NL_UP_AXIS_Y or NL_UP_AXIS_Z)");
    if (frame.identity()) return {};
    const float scale = frame.metres_per_unit == 0.0f ? 1.0f : frame.metres_per_unit;
    TriangleMesh out;
    out.triangles = given.triangles;
    out.vertices.reserve(given.vertices.size());
    for (const Vec3& v : given.vertices)
        out.vertices.push_back(scale * (frame.up == UpAxis::Z ? Vec3(v.x(), v.z(), -v.y()) : v));
    return out;
}

template <typename Owner>
void store_owner(std::vector<Owner>& table, unsigned id, Owner owner) {
    if (table.size() <= id) table.resize(id + 1);
    table[id] = owner;
}

}  // namespace

Level::Level(TaskSystem& tasks, uint32_t handle_tag) : tasks_(tasks), meshes_(handle_tag, HandleKind::Mesh) {
    device_ = rtcNewDevice(nullptr);
    // Each Embree device takes one of the process's thread-local keys (1,024 on glibc): past about a
    // thousand worlds, or when memory runs out, there is none for another.
    if (!device_)
        fail(ErrorCode::OutOfMemory, "Embree could not create another device (error ", rtcGetDeviceError(nullptr),
             "): about 1,000 worlds can exist at once, each device taking one of the process's thread-local keys");
    top_ = rtcNewScene(device_);
    static_scene_ = rtcNewScene(device_);
    // Robust traversal: link clearance tests must not leak through cracks between triangles.
    rtcSetSceneFlags(static_scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneFlags(top_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_LOW);

    RTCGeometry group = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(group, static_scene_);
    set_instance_transform(group, Transform::Identity());
    static_instance_ = rtcAttachGeometry(top_, group);
    rtcReleaseGeometry(group);  // the top scene keeps it alive
    store_owner(instance_owner_, static_instance_, InstanceOwner{true, {}});
    static_dirty_ = true;
    check_embree("creating the scene");
}

Level::~Level() {
    meshes_.for_each([](Handle, const Mesh& m) {
        rtcReleaseGeometry(m.geometry);
        if (m.instance) rtcReleaseGeometry(m.instance);
        if (m.own_scene) rtcReleaseScene(m.own_scene);
    });
    rtcReleaseScene(top_);
    rtcReleaseScene(static_scene_);
    rtcReleaseDevice(device_);
}

namespace {

void check_embree_error(RTCError e, const char* what) {
    if (e == RTC_ERROR_NONE) return;
    if (e == RTC_ERROR_OUT_OF_MEMORY) fail(ErrorCode::OutOfMemory, "out of memory while ", what);
    fail(ErrorCode::Internal, "Embree error ", static_cast<int>(e), " while ", what);
}

}  // namespace

void Level::check_embree(const char* what) const { check_embree_error(rtcGetDeviceError(device_), what); }

void Level::commit(RTCScene scene, bool exclusive, const char* what) const {
    RTCError error = RTC_ERROR_NONE;
    auto build = [&] {
        rtcCommitScene(scene);
        error = rtcGetDeviceError(device_);
    };
    if (exclusive)
        tasks_.execute_exclusive(build);
    else
        tasks_.execute(build);
    check_embree_error(error, what);
}

namespace {

void check_placement(const Aabb& world_bounds) {
    if (!within_coordinate_limit(world_bounds.min) || !within_coordinate_limit(world_bounds.max))
        fail(ErrorCode::InvalidArgument, "the transform places the mesh beyond the coordinate limit of +-",
             kCoordinateLimit, " m");
}

}  // namespace

Handle Level::add_mesh(const TriangleMesh& given, const Transform& transform, uint32_t flags, uint64_t user_data,
                       uint32_t area, const MeshFrame& frame) {
    if (flags & ~kMeshKnownFlags)
        fail_field(ErrorCode::InvalidArgument, "flags has unknown bits 0x", std::hex, flags & ~kMeshKnownFlags);
    if ((flags & kMeshObstacle) && (flags & kMeshNotInNavMesh))
        fail_field(ErrorCode::InvalidArgument,
                   "flags has both NL_MESH_OBSTACLE and NL_MESH_NOT_IN_NAVMESH: an obstacle is part of navmesh builds");
    if (area > kMaxMeshArea) fail_field(ErrorCode::InvalidArgument, "area is ", area, " (at most ", kMaxMeshArea, ")");
    const TriangleMesh framed = in_navlink_frame(given, frame);
    const TriangleMesh& input = frame.identity() ? given : framed;
    ValidatedTriangles valid = validate_mesh(input);

    Mesh mesh;
    mesh.object.vertices = input.vertices;
    mesh.object.triangles = std::move(valid.kept);
    if (flags & kMeshClockwise)
        for (Triangle& t : mesh.object.triangles) std::swap(t[1], t[2]);
    mesh.input_index = std::move(valid.input_index);
    mesh.degenerate_count = valid.degenerate_count;
    mesh.flags = flags;
    mesh.area = static_cast<uint8_t>(area);
    mesh.user_data = user_data;
    mesh.frame = frame;
    mesh.transform = transform;
    mesh.object_bounds = bounds_of(mesh.object, Transform::Identity());
    mesh.world_bounds = bounds_of(mesh.object, transform);
    check_placement(mesh.world_bounds);

    try {
        if (flags & kMeshMovable) prepare_movable(mesh);
    } catch (...) {
        detach(mesh);
        throw;
    }
    const auto lock = lock_exclusive();
    try {
        if (flags & kMeshMovable)
            attach_movable(mesh);
        else
            upload_static(mesh);
        check_embree("registering a mesh");
    } catch (...) {
        detach(mesh);
        throw;
    }
    const Handle h = meshes_.insert(std::move(mesh));
    Mesh& stored = *meshes_.find(h);
    if (stored.flags & kMeshMovable)
        store_owner(instance_owner_, stored.instance_id, InstanceOwner{false, h});
    else
        store_owner(static_geometry_owner_, stored.geometry_id, h);
    return h;
}

void Level::upload_static(Mesh& mesh) {
    // Static meshes are stored in world space, so traversal needs no instance transform for them.
    const auto vertex_count = mesh.object.vertices.size();
    const auto triangle_count = mesh.object.triangles.size();
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g) check_embree("creating a triangle geometry");
    mesh.geometry = g;
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertex_count));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangle_count));
    if (!vb || !ib) check_embree("allocating mesh buffers");
    for (size_t i = 0; i < vertex_count; ++i) {
        Eigen::Map<Vec3>(vb + 3 * i) = mesh.transform * mesh.object.vertices[i];
    }
    std::copy_n(mesh.object.triangles.front().data(), 3 * triangle_count, ib);
    rtcCommitGeometry(g);
    mesh.geometry_id = rtcAttachGeometry(static_scene_, g);
    static_dirty_ = true;
}

void Level::prepare_movable(Mesh& mesh) {
    mesh.own_scene = rtcNewScene(device_);
    rtcSetSceneFlags(mesh.own_scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!mesh.own_scene || !g) check_embree("creating a movable mesh");
    mesh.geometry = g;
    const auto vertex_count = mesh.object.vertices.size();
    const auto triangle_count = mesh.object.triangles.size();
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertex_count));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangle_count));
    if (!vb || !ib) check_embree("allocating mesh buffers");
    std::copy_n(mesh.object.vertices.front().data(), 3 * vertex_count, vb);
    std::copy_n(mesh.object.triangles.front().data(), 3 * triangle_count, ib);
    rtcCommitGeometry(g);
    mesh.geometry_id = rtcAttachGeometry(mesh.own_scene, g);
    check_embree("registering a movable mesh");
    commit(mesh.own_scene, false, "building a movable mesh");
}

void Level::attach_movable(Mesh& mesh) {
    mesh.instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    if (!mesh.instance) check_embree("creating an instance");
    rtcSetGeometryInstancedScene(mesh.instance, mesh.own_scene);
    set_instance_transform(mesh.instance, mesh.transform);
    mesh.normal_to_world = normal_matrix(mesh.transform);
    mesh.instance_id = rtcAttachGeometry(top_, mesh.instance);
    top_dirty_ = true;
}

void Level::detach(Mesh& mesh) {
    if (mesh.instance) {
        if (mesh.instance_id != RTC_INVALID_GEOMETRY_ID) rtcDetachGeometry(top_, mesh.instance_id);
        rtcReleaseGeometry(mesh.instance);
        top_dirty_ = true;
    } else if (mesh.geometry && mesh.geometry_id != RTC_INVALID_GEOMETRY_ID) {
        rtcDetachGeometry(static_scene_, mesh.geometry_id);
        static_dirty_ = true;
    }
    if (mesh.geometry) rtcReleaseGeometry(mesh.geometry);
    if (mesh.own_scene) rtcReleaseScene(mesh.own_scene);
    mesh.geometry = mesh.instance = nullptr;
    mesh.own_scene = nullptr;
}

void Level::remove_mesh(Handle h) {
    const auto lock = lock_exclusive();
    Mesh* mesh = meshes_.find(h);
    if (!mesh) fail_stale("mesh", h);
    detach(*mesh);
    meshes_.erase(h);
}

void Level::set_transform(Handle h, const Transform& transform) {
    // The bounds go over every vertex: under the shared lock, so that ray queries and the navmesh
    // riding the mesh are not held up for it (a mesh's own vertices never change once added).
    Aabb bounds;
    {
        const auto shared = lock_shared();
        const Mesh* mesh = meshes_.find(h);
        if (!mesh) fail_stale("mesh", h);
        bounds = bounds_of(mesh->object, transform);
    }
    check_placement(bounds);
    const auto lock = lock_exclusive();
    Mesh* mesh = meshes_.find(h);
    if (!mesh) fail_stale("mesh", h);  // removed meanwhile
    mesh->transform = transform;
    mesh->world_bounds = bounds;
    if (mesh->instance) {
        mesh->normal_to_world = normal_matrix(transform);
        set_instance_transform(mesh->instance, transform);
        top_dirty_ = true;
    } else {
        auto* vb = static_cast<float*>(rtcGetGeometryBufferData(mesh->geometry, RTC_BUFFER_TYPE_VERTEX, 0));
        for (size_t i = 0; i < mesh->object.vertices.size(); ++i) {
            Eigen::Map<Vec3>(vb + 3 * i) = transform * mesh->object.vertices[i];
        }
        rtcUpdateGeometryBuffer(mesh->geometry, RTC_BUFFER_TYPE_VERTEX, 0);
        rtcCommitGeometry(mesh->geometry);
        static_dirty_ = true;
    }
    check_embree("moving a mesh");
}

bool Level::contains(Handle h) const {
    const auto lock = lock_shared();
    return meshes_.find(h) != nullptr;
}

MeshInfo Level::info(Handle h) const {
    const auto lock = lock_shared();
    const Mesh* mesh = meshes_.find(h);
    if (!mesh) fail_stale("mesh", h);
    MeshInfo out;
    out.vertex_count = static_cast<uint32_t>(mesh->object.vertices.size());
    out.triangle_count = static_cast<uint32_t>(mesh->object.triangles.size());
    out.degenerate_triangle_count = mesh->degenerate_count;
    out.flags = mesh->flags;
    out.area = mesh->area;
    out.transform = mesh->transform;
    out.bounds = mesh->world_bounds;
    out.user_data = mesh->user_data;
    out.frame = mesh->frame;
    return out;
}

std::vector<MovableMesh> Level::movable_meshes() const {
    const auto lock = lock_shared();
    std::vector<MovableMesh> out;
    meshes_.for_each([&](Handle h, const Mesh& m) {
        if (!m.own_scene) return;
        const Aabb& b = m.object_bounds;
        float reach = 0.0f;  // the farthest corner of its object bounds, mapped to the world
        for (float x : {b.min.x(), b.max.x()})
            for (float y : {b.min.y(), b.max.y()})
                for (float z : {b.min.z(), b.max.z()})
                    reach = std::max(reach, (m.transform.linear() * Vec3(x, y, z)).norm());
        out.push_back(MovableMesh{h, m.transform, reach});
    });
    return out;
}

std::vector<Handle> Level::meshes() const {
    const auto lock = lock_shared();
    std::vector<Handle> out;
    out.reserve(meshes_.size());
    meshes_.for_each([&](Handle h, const Mesh&) { out.push_back(h); });
    return out;
}

namespace {

// A mirroring transform (negative determinant) would turn every triangle over in world space; its
// corners are taken the other way round so each keeps the front it has in its own space, as engines
// keep a mirrored object's front faces.
void append_in_world(const TriangleMesh& object, const Transform& transform, TriangleMesh& out) {
    const auto base = static_cast<uint32_t>(out.vertices.size());
    const bool mirrored = transform.linear().determinant() < 0.0f;
    for (const Vec3& v : object.vertices) out.vertices.push_back(transform * v);
    for (const Triangle& t : object.triangles) {
        const Triangle placed = wound_as_placed(t, mirrored);
        out.triangles.push_back({placed[0] + base, placed[1] + base, placed[2] + base});
    }
}

void append_for_build(Handle mesh, const TriangleMesh& object, const Transform& transform, uint8_t area,
                      BuildTriangles& out) {
    out.mesh_starts.push_back({mesh, out.mesh.triangles.size()});
    append_in_world(object, transform, out.mesh);
    out.areas.resize(out.mesh.triangles.size(), area);
}

}  // namespace

TriangleMesh Level::world_triangles() const {
    const auto lock = lock_shared();
    TriangleMesh out;
    meshes_.for_each([&](Handle, const Mesh& m) { append_in_world(m.object, m.transform, out); });
    return out;
}

BuildTriangles Level::triangles_to_build(Handle carrier) const {
    const auto lock = lock_shared();
    BuildTriangles out;
    if (carrier != Handle{}) {
        const Mesh* m = meshes_.find(carrier);
        if (!m) fail_stale("mesh", carrier);
        if (!(m->flags & kMeshMovable))
            fail(ErrorCode::InvalidArgument,
                 "the carrier mesh is not movable (NL_MESH_MOVABLE): a static mesh's floor is "
                 "part of the level's navmesh");
        if (m->flags & kMeshNotInNavMesh)
            fail(ErrorCode::InvalidArgument, "the carrier mesh is left out of navmesh builds (NL_MESH_NOT_IN_NAVMESH)");
        append_for_build(carrier, m->object, Transform::Identity(), build_area(m->flags, m->area), out);
        return out;
    }
    meshes_.for_each([&](Handle handle, const Mesh& m) {
        if (read_by_static_builds(m.flags))
            append_for_build(handle, m.object, m.transform, build_area(m.flags, m.area), out);
    });
    return out;
}

void Level::static_triangles(const RayHit* hits, uint32_t count, std::optional<std::array<Vec3, 3>>* out) const {
    const auto lock = lock_shared();
    tasks_.parallel_for(count, 512, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            out[i].reset();
            const Mesh* mesh = hits[i].hit ? meshes_.find(hits[i].mesh) : nullptr;
            if (!mesh || mesh->own_scene || hits[i].primitive >= mesh->object.triangles.size()) continue;
            // Embree's own buffer: the world-space corners it intersects.
            const auto* vertices =
                static_cast<const float*>(rtcGetGeometryBufferData(mesh->geometry, RTC_BUFFER_TYPE_VERTEX, 0));
            const Triangle& t = mesh->object.triangles[hits[i].primitive];
            out[i] =
                std::array<Vec3, 3>{vertex_at(vertices, t[0]), vertex_at(vertices, t[1]), vertex_at(vertices, t[2])};
        }
    });
}

namespace {

void refuse_inside_task() {
    if (TaskSystem::inside_task())
        fail(ErrorCode::Internal,
             "the level was called from inside a parallel task (it must be called by the calling thread)");
}

}  // namespace

std::shared_lock<SharedMutex> Level::lock_shared() const {
    refuse_inside_task();
    return std::shared_lock<SharedMutex>(mutex_);
}

std::unique_lock<SharedMutex> Level::lock_exclusive() const {
    refuse_inside_task();
    return std::unique_lock<SharedMutex>(mutex_);
}

std::shared_lock<SharedMutex> Level::lock_committed() const {
    for (;;) {
        std::shared_lock shared = lock_shared();
        if (!static_dirty_ && !top_dirty_) return shared;
        shared.unlock();
        const auto exclusive = lock_exclusive();
        if (static_dirty_) {
            commit(static_scene_, true, "building the scene");
            rtcCommitGeometry(rtcGetGeometry(top_, static_instance_));
            check_embree("building the scene");
            static_dirty_ = false;
            top_dirty_ = true;
        }
        if (top_dirty_) {
            commit(top_, true, "building the scene");
            top_dirty_ = false;
        }
    }
}

RayHit Level::resolve_hit(const RTCRayHit& rh, const Ray& ray) const {
    RayHit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    const InstanceOwner& owner = instance_owner_[rh.hit.instID[0]];
    const Handle h = owner.is_static_group ? static_geometry_owner_[rh.hit.geomID] : owner.mesh;
    const Mesh& mesh = *meshes_.find(h);
    Vec3 normal(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    if (!owner.is_static_group) normal = mesh.normal_to_world * normal;
    hit.hit = true;
    hit.distance = rh.ray.tfar + 0.0f;  // a ray starting on a surface reports +0, not -0
    hit.point = ray.origin + ray.direction * rh.ray.tfar;
    hit.normal = normal.normalized();
    hit.mesh = h;
    hit.triangle = mesh.input_index.empty() ? rh.hit.primID : mesh.input_index[rh.hit.primID];
    hit.primitive = rh.hit.primID;
    return hit;
}

namespace {

RTCRayHit ray_hit_query(const Vec3& origin, const Vec3& direction, float tfar, uint32_t id) {
    RTCRayHit rh;
    rh.ray.org_x = origin.x();
    rh.ray.org_y = origin.y();
    rh.ray.org_z = origin.z();
    rh.ray.dir_x = direction.x();
    rh.ray.dir_y = direction.y();
    rh.ray.dir_z = direction.z();
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = tfar;
    rh.ray.time = 0.0f;
    rh.ray.mask = ~0u;
    rh.ray.id = id;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace

template <typename Each>
void Level::batch(uint32_t count, Each&& each) const {
    const auto lock = lock_committed();
    tasks_.parallel_for(count, 512, [&](uint32_t begin, uint32_t end) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (uint32_t i = begin; i < end; ++i) each(i, context);
    });
}

void Level::cast_rays(const Ray* rays, uint32_t count, RayHit* out) const {
    batch(count, [&](uint32_t i, RTCIntersectContext& context) {
        RTCRayHit rh = ray_hit_query(rays[i].origin, rays[i].direction, rays[i].max_distance, i);
        rtcIntersect1(top_, &context, &rh);
        out[i] = resolve_hit(rh, rays[i]);
    });
}

void Level::segments_first_hit(const Segment* segments, uint32_t count, RayHit* out) const {
    batch(count, [&](uint32_t i, RTCIntersectContext& context) {
        const Vec3 delta = segments[i].to - segments[i].from;
        out[i] = RayHit{};
        if (delta.squaredNorm() == 0.0f) return;  // as segments_blocked: never blocked
        RTCRayHit rh = ray_hit_query(segments[i].from, delta, 1.0f, i);
        rtcIntersect1(top_, &context, &rh);
        out[i] = resolve_hit(rh, Ray{segments[i].from, delta, 1.0f});
        if (out[i].hit) out[i].distance = rh.ray.tfar * delta.norm();
    });
}

void Level::segments_blocked(const Segment* segments, uint32_t count, uint8_t* out_blocked) const {
    batch(count, [&](uint32_t i, RTCIntersectContext& context) {
        const Vec3 delta = segments[i].to - segments[i].from;
        out_blocked[i] = 0;
        if (delta.squaredNorm() == 0.0f) return;
        RTCRay ray = ray_hit_query(segments[i].from, delta, 1.0f, i).ray;
        rtcOccluded1(top_, &context, &ray);
        // Embree marks an occluded ray by setting tfar to -inf.
        out_blocked[i] = ray.tfar < 0.0f ? 1 : 0;
    });
}

}  // namespace nl
