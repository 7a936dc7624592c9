// The level: the host's collision geometry in Embree, answering batched ray and occlusion queries.
//
// Two-level scene: the top scene holds only instances. All static meshes share one child scene behind
// an identity instance; each movable mesh has a child scene of its own, so moving it changes one
// instance transform and the top level is refit over a handful of instances, not rebuilt over every
// triangle.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <optional>
#include <mutex>
#include <shared_mutex>
#include <vector>

#include "level/geometry.h"
#include "level/mesh_validation.h"
#include "level/oriented_box.h"
#include "level/swept_body.h"
#include "util/handle.h"
#include "os/shared_mutex.h"
#include "util/task_system.h"

namespace nl {

enum MeshFlags : uint32_t {
    kMeshMovable = 1u << 0,
    // Front faces wound clockwise seen from their front (Godot's convention): the triangles are
    // turned over when the mesh is added, so every stored triangle is counter-clockwise.
    kMeshClockwise = 1u << 1,
    // In navmesh builds only as something that blocks: never walked on, whatever its slope.
    kMeshObstacle = 1u << 2,
    // Left out of navmesh builds; rays and link checks still meet it.
    kMeshNotInNavMesh = 1u << 3,
    kMeshKnownFlags = kMeshMovable | kMeshClockwise | kMeshObstacle | kMeshNotInNavMesh,
};

// The area a navmesh builder gives a mesh's walkable triangles: 0..kMaxMeshArea (kObstacleArea
// marks an obstacle's triangles in a builder's input).
constexpr uint32_t kMaxMeshArea = kObstacleArea - 1u;
// Whether a static build reads a mesh of these flags (Level::triangles_to_build): not a movable one
// (a navmesh over it would stay behind when it moves), not one left out of navmesh builds.
inline bool read_by_static_builds(uint32_t flags) { return !(flags & (kMeshMovable | kMeshNotInNavMesh)); }
// What a builder's input says of a mesh's triangles: its area, or kObstacleArea for an obstacle's.
inline uint8_t build_area(uint32_t flags, uint8_t area) { return (flags & kMeshObstacle) ? kObstacleArea : area; }

// The frame a host's vertices are given in; NavLink's own is metres with y up. Vertices are brought
// into it when a mesh is registered, before its transform (which, as every other position, is in
// NavLink's frame).
enum class UpAxis : uint32_t { NotSaid, Y, Z };  // not said: y, and a navmesh build says when z looks up
struct MeshFrame {
    // Metres per unit of the vertices; 0 = not said (metres, and a navmesh build says when the level's
    // size suggests other units), 1 = metres said.
    float metres_per_unit = 0.0f;
    // Z: the vertices have z up (Blender's, Unreal's, 3ds Max's own frame): (x, y, z) becomes
    // (x, z, -y), a rotation, so fronts stay fronts.
    UpAxis up = UpAxis::NotSaid;
    bool identity() const { return (metres_per_unit == 0.0f || metres_per_unit == 1.0f) && up != UpAxis::Z; }
};
// Least and most metres per unit taken: from micrometres to kilometres and beyond.
constexpr float kLeastMetresPerUnit = 1e-6f, kMostMetresPerUnit = 1e6f;

struct MeshInfo {
    uint32_t vertex_count = 0;
    uint32_t triangle_count = 0;
    uint32_t degenerate_triangle_count = 0;
    uint32_t flags = 0;
    uint8_t area = 0;
    Transform transform = Transform::Identity();
    Aabb bounds;
    uint64_t user_data = 0;
    MeshFrame frame;
};

// Direction must be unit length; max_distance > 0 (may be infinite).
struct Ray {
    Vec3 origin;
    Vec3 direction;
    float max_distance;
};

struct RayHit {
    bool hit = false;
    float distance = 0.0f;
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::Zero();
    Handle mesh;
    uint32_t triangle = 0;   // index in the mesh's input triangles
    uint32_t primitive = 0;  // index in the mesh's kept triangles (Level::static_triangles)
};

struct Segment {
    Vec3 from;
    Vec3 to;
};

// A straight stretch of a path swept by the agent's body, for Level::bodies_clear: the body (its
// radius is given per query) and a box that holds it at the widest radius asked.
struct BodyStretch {
    SweptCylinder body;
    OrientedBox bounds;
};

// Where a movable mesh will be at a moment to come, for the body queries of that moment.
struct MeshPlacement {
    Handle mesh;
    Transform transform = Transform::Identity();
};

// Stretches [first, first + count) of a bodies_clear batch that one box holds (a straight run of a
// path): the level is asked once for the triangles in that box, and each stretch is tested against
// those. With `placed`, the stretches are of a moment to come: the movable meshes it names are
// tested where it places them, the others where they are (a placement of a removed or static mesh
// is ignored).
struct BodyGroup {
    OrientedBox bounds;
    uint32_t first = 0, count = 0;
    const MeshPlacement* placed = nullptr;  // borrowed, `placed_count` entries
    uint32_t placed_count = 0;
};

// A movable mesh where it is now, and how far its farthest point is from its origin (world metres):
// a bound on how fast its points move when it turns.
struct MovableMesh {
    Handle mesh;
    Transform transform = Transform::Identity();
    float reach = 0.0f;
};

class NearTriangles;

// Thread-safe: queries run at once under a shared lock, edits take it exclusively. Every method is
// called by the thread that called into NavLink, never from inside a parallel_for body (TaskSystem's
// contract; it throws Internal otherwise): a body waiting for the lock while the lock's holder waits
// for the body's arena would hang.
class Level {
public:
    // Handles this level issues carry `handle_tag`, so handles of another level (world) are refused.
    explicit Level(TaskSystem& tasks, uint32_t handle_tag = 0);
    ~Level();
    Level(const Level&) = delete;
    Level& operator=(const Level&) = delete;

    // Edits: each validates first and changes nothing when it throws (a bad field is named as
    // validate_mesh names it).
    // kMeshClockwise turns the triangles over; `area` (at most kMaxMeshArea) is what navmesh builds
    // give its walkable triangles; `frame` says the units and up axis of the vertices.
    Handle add_mesh(const TriangleMesh& mesh, const Transform& transform, uint32_t flags, uint64_t user_data,
                    uint32_t area = 0, const MeshFrame& frame = {});
    void remove_mesh(Handle mesh);
    void set_transform(Handle mesh, const Transform& transform);

    bool contains(Handle mesh) const;
    MeshInfo info(Handle mesh) const;
    std::vector<Handle> meshes() const;
    // Every movable mesh, where it is now: one consistent reading under the level's lock.
    std::vector<MovableMesh> movable_meshes() const;

    // World-space triangles of every mesh under its current transform (for reference checks).
    TriangleMesh world_triangles() const;
    // What a navmesh builder builds on: with a null `surface`, every static mesh in world space but
    // those left out of navmesh builds (a movable mesh is left out too: a navmesh over it would stay
    // behind when it moves); else the movable mesh `surface` alone, in its own space. Each triangle
    // carries its mesh's area, or kObstacleArea for an obstacle's. Throws InvalidHandle, or
    // InvalidArgument for a surface that is not movable or is left out of navmesh builds.
    BuildTriangles triangles_to_build(Handle carrier) const;
    // What triangles_to_build gives, only the triangles that meet `columns` (in the same order, each
    // with its area, with only the vertices they use), found through Embree's point queries rather
    // than by reading the level: what a build or a content hash of some tiles reads. `out_bounds`:
    // the bounds of every vertex triangles_to_build gives (what places a tile grid's heights).
    BuildTriangles triangles_to_build_in_columns(Handle carrier, const Columns& columns, Aabb& out_bounds) const;
    // For each hit, the corners of its triangle (RayHit::mesh, RayHit::primitive) if it is a static
    // mesh's, in world space, exactly as Embree tests them; nothing for a miss, a movable mesh (Embree
    // tests those in their own space) or a mesh removed since the hit. Parallel over the batch.
    void static_triangles(const RayHit* hits, uint32_t count, std::optional<std::array<Vec3, 3>>* out) const;

    // Batched queries, parallel over the task system; out spans must have rays.size() entries.
    void cast_rays(const Ray* rays, uint32_t count, RayHit* out) const;
    void segments_blocked(const Segment* segments, uint32_t count, uint8_t* out_blocked) const;
    // The first hit along each segment, cast exactly as segments_blocked casts it (so a hit here is a
    // blocked segment there); distances in metres from `from`.
    void segments_first_hit(const Segment* segments, uint32_t count, RayHit* out) const;
    // out_empty[i] = 1 when no triangle shares a point with boxes[i]: then no segment inside the box
    // is blocked, and the caller need not cast them (pad the box for rounding). Exact per triangle;
    // Embree's point queries find the triangles near each box.
    void boxes_empty(const OrientedBox* boxes, uint32_t count, uint8_t* out_empty) const;
    // out_cleared[i] = how many of `radii` (ascending), counted from the first, give a body along
    // stretches[i] that is proven apart from every triangle of the level (swept_body.h: exact, with a
    // margin; touching is a hit). 0: even the narrowest body touches something. Triangles outside
    // the stretch's bounds are not looked at, so the bounds must hold the widest body.
    void bodies_clear(const BodyStretch* stretches, uint32_t count, const float* radii, uint32_t radius_count,
                      uint8_t* out_cleared) const;
    // The same, the stretches in groups: each group's box must hold its stretches' boxes. Answers
    // what bodies_clear answers, with one gathering of triangles per group; returns how many
    // stretches met a triangle in their box (and were tested exactly).
    uint64_t bodies_clear(const BodyGroup* groups, uint32_t group_count, const BodyStretch* stretches,
                          const float* radii, uint32_t radius_count, uint8_t* out_cleared) const;

private:
    struct Mesh {
        TriangleMesh object;                // object-space vertices, kept triangles
        std::vector<uint32_t> input_index;  // kept triangle -> input triangle; empty = identity
        uint32_t degenerate_count = 0;
        uint32_t flags = 0;
        uint8_t area = 0;
        uint64_t user_data = 0;
        MeshFrame frame;
        Transform transform = Transform::Identity();
        Eigen::Matrix3f normal_to_world = Eigen::Matrix3f::Identity();  // movable meshes only
        Aabb object_bounds;
        Aabb world_bounds;
        RTCGeometry geometry = nullptr;  // triangles, in static_scene_ or own_scene
        unsigned geometry_id = RTC_INVALID_GEOMETRY_ID;
        RTCScene own_scene = nullptr;    // movable only
        RTCGeometry instance = nullptr;  // movable only
        unsigned instance_id = RTC_INVALID_GEOMETRY_ID;
    };
    struct InstanceOwner {
        bool is_static_group = false;
        Handle mesh;  // for movable meshes
    };

    void upload_static(Mesh& mesh);
    // Builds a movable mesh's own scene and BVH; needs no lock, so queries keep running meanwhile.
    void prepare_movable(Mesh& mesh);
    void attach_movable(Mesh& mesh);
    void detach(Mesh& mesh);
    // The level's lock, refused inside a parallel_for body.
    std::shared_lock<SharedMutex> lock_shared() const;
    std::unique_lock<SharedMutex> lock_exclusive() const;
    // Takes a shared lock on a committed scene; commits pending edits first.
    std::shared_lock<SharedMutex> lock_committed() const;
    void check_embree(const char* what) const;
    // Commits a scene through the task system (exclusively: under the level's exclusive lock), and
    // checks Embree's error where the commit ran: Embree keeps errors per thread.
    void commit(RTCScene scene, bool exclusive, const char* what) const;
    // Where the triangles are, for the near queries; under the shared lock.
    NearTriangles near_triangles() const;
    RayHit resolve_hit(const RTCRayHit& rh, const Ray& ray) const;
    // Calls each(i, context) for every i in [0, count) on the workers, over the committed scene.
    template <typename Each>
    void batch(uint32_t count, Each&& each) const;

    TaskSystem& tasks_;
    RTCDevice device_ = nullptr;
    RTCScene top_ = nullptr;
    RTCScene static_scene_ = nullptr;
    unsigned static_instance_ = RTC_INVALID_GEOMETRY_ID;

    SlotMap<Mesh> meshes_;
    std::vector<Handle> static_geometry_owner_;  // by geomID in static_scene_
    std::vector<InstanceOwner> instance_owner_;  // by geomID in top_

    mutable SharedMutex mutex_{"the level"};
    mutable bool static_dirty_ = false;
    mutable bool top_dirty_ = true;
};

}  // namespace nl
