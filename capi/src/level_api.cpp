#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "io/obj_reader.h"
#include "queries.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;

namespace {

static_assert(NL_COORDINATE_LIMIT == nl::kCoordinateLimit, "header and core disagree on the coordinate limit");
static_assert(NL_MESH_MOVABLE == nl::kMeshMovable && NL_MESH_CLOCKWISE == nl::kMeshClockwise &&
                  NL_MESH_OBSTACLE == nl::kMeshObstacle && NL_MESH_NOT_IN_NAVMESH == nl::kMeshNotInNavMesh &&
                  NL_MESH_MAX_AREA == nl::kMaxMeshArea,
              "header and core disagree on mesh flags");

using nl::capi::to_handle;
using nl::capi::to_id;

nl::Transform read_transform(const float* m) {
    if (!m) return nl::Transform::Identity();
    return nl::validate_transform(Eigen::Map<const Eigen::Matrix4f>(m), "transform");
}

static_assert(NL_UP_AXIS_NOT_SAID == uint32_t(nl::UpAxis::NotSaid) && NL_UP_AXIS_Y == uint32_t(nl::UpAxis::Y) &&
                  NL_UP_AXIS_Z == uint32_t(nl::UpAxis::Z),
              "header and core disagree on up axes");

// The core refuses an axis it does not know, named as any field of the def.
nl::MeshFrame read_frame(const nl_mesh_def& def) { return {def.metres_per_unit, nl::UpAxis(def.up_axis)}; }

nl_mesh_def read_def(const nl_mesh_def& def) {
    return nl::capi::read_growable(def, nl_default_mesh_def(), nl::capi::kFirstSize<nl_mesh_def>, "def");
}

nl::TriangleMesh read_def_geometry(const nl_mesh_def& def) {
    nl::TriangleMesh mesh;
    mesh.vertices = nl::capi::read_vertices(def.vertices, def.vertex_count, def.vertex_stride);
    nl::capi::require_field(def.indices, "indices");
    if (def.triangle_count == 0) nl::fail_field(ErrorCode::InvalidArgument, "triangle_count is 0");
    mesh.triangles.resize(def.triangle_count);
    std::memcpy(mesh.triangles.data(), def.indices, size_t(def.triangle_count) * 3 * sizeof(uint32_t));
    return mesh;
}

// A failure about an OBJ's geometry in the file's own words: "vertex 8" for vertices[7] (its eighth
// `v` line), "faces" for indices; the other fields are the def's. The reader refuses numbers that are
// not finite with their line first; what reaches here is the level's own checks.
std::string obj_words(const std::string& field_message) {
    if (field_message.rfind("indices", 0) == 0) return "faces" + field_message.substr(7);
    if (field_message.rfind("vertices[", 0) != 0) return field_message;
    const size_t close = field_message.find(']');
    if (close == std::string::npos) return field_message;
    const unsigned long index = std::stoul(field_message.substr(9, close - 9));
    const std::string vertex = "vertex " + std::to_string(index + 1);
    // "vertices[1].x = 2e+09 is ..." reads "vertex 2: x = 2e+09 is ...".
    if (field_message.compare(close + 1, 1, ".") == 0) return vertex + ": " + field_message.substr(close + 2);
    return vertex + field_message.substr(close + 1);
}

bool about_geometry(const std::string& field_message) {
    return field_message.rfind("vertices", 0) == 0 || field_message.rfind("indices", 0) == 0 ||
           field_message.rfind("triangle_count", 0) == 0;
}

// `source`: the OBJ file (or "data") the geometry came from, whose name failures about the geometry
// carry instead of the def's field names a host using nl_mesh_add would know; null for nl_mesh_add.
nl_mesh_id add_mesh(nl::World& world, const nl::TriangleMesh& mesh, const nl_mesh_def& def, const char* function,
                    const char* source = nullptr) {
    const nl::Handle h = [&] {
        try {
            if (def.reserved != 0)
                nl::fail_field(ErrorCode::InvalidArgument, "reserved is ", def.reserved, " (must be 0)");
            return world.level().add_mesh(mesh, read_transform(def.transform), def.flags, def.user_data, def.area,
                                          read_frame(def));
        } catch (const nl::Error& e) {
            if (!e.starts_with_field()) throw;
            if (source && about_geometry(e.what()))
                throw nl::Error(e.code(), nl::concat(source, ": ", obj_words(e.what())));
            throw nl::Error(e.code(), nl::concat("def->", e.what()), true);
        }
    }();
    const nl::MeshInfo info = world.level().info(h);
    if (info.degenerate_triangle_count > 0) {
        world.logger().log(nl::LogLevel::Warning, nl::concat(function, ": skipped ", info.degenerate_triangle_count,
                                                             " degenerate triangles of ",
                                                             info.degenerate_triangle_count + info.triangle_count));
    }
    return to_id<nl_mesh_id>(h);
}

// Options of an OBJ load: the def without geometry.
nl_mesh_def obj_options(const nl_mesh_def* in) {
    if (!in) return nl_default_mesh_def();
    const nl_mesh_def def = read_def(*in);
    if (def.vertices || def.indices || def.vertex_count || def.triangle_count)
        fail(ErrorCode::InvalidArgument,
             "def carries geometry; for an OBJ load only flags, transform, user_data, area, metres_per_unit and "
             "up_axis apply");
    return def;
}

// nl_ray_hit's first release with a `size` (0.2): every field up to `reserved`.

nl_ray_hit to_c(const nl::RayHit& hit) {
    nl_ray_hit out{};
    if (!hit.hit) return out;
    out.hit = 1;
    out.distance = hit.distance;
    Eigen::Map<nl::Vec3>(out.point) = hit.point;
    Eigen::Map<nl::Vec3>(out.normal) = hit.normal;
    out.mesh = to_id<nl_mesh_id>(hit.mesh);
    out.triangle = hit.triangle;
    return out;
}

nl::Vec3 read_point(const float* p, const char* array, uint32_t index, const char* field) {
    return nl::capi::read_position(p, array, "[", index, "].", field);
}

// Unit direction of any finite nonzero vector: scaled by its largest component first, so neither
// 1e-30 nor 3e38 underflows or overflows on the way.
nl::Vec3 read_direction(const float* p, uint32_t index) {
    const nl::Vec3 v(p[0], p[1], p[2]);
    if (!v.allFinite()) fail(ErrorCode::InvalidArgument, "rays[", index, "].direction is not finite");
    const float largest = v.cwiseAbs().maxCoeff();
    if (!(largest > 0.0f)) fail(ErrorCode::InvalidArgument, "rays[", index, "].direction is zero");
    return (v / largest).normalized();
}

}  // namespace

namespace nl::capi {

void cast_rays(const World& world, const nl_ray* rays, uint32_t count, nl_ray_hit* out_hits) {
    if (count == 0) return;
    require(rays, "rays");
    require(out_hits, "out_hits");
    std::vector<Ray> batch(count);
    for (uint32_t i = 0; i < count; ++i) {
        const nl_ray& r = rays[i];
        if (!(r.max_distance > 0.0f))
            fail(ErrorCode::InvalidArgument, "rays[", i, "].max_distance is ", r.max_distance, " (must be > 0)");
        batch[i] = Ray{read_point(r.origin, "rays", i, "origin"), read_direction(r.direction, i), r.max_distance};
    }
    const ElementWriter<nl_ray_hit> writer(out_hits, nl::capi::kFirstSize<nl_ray_hit>, "out_hits");
    std::vector<RayHit> hits(count);
    world.level().cast_rays(batch.data(), count, hits.data());
    for (uint32_t i = 0; i < count; ++i) writer.write(i, to_c(hits[i]));
}

void segments_blocked(const World& world, const nl_segment* segments, uint32_t count, uint8_t* out_blocked) {
    if (count == 0) return;
    require(segments, "segments");
    require(out_blocked, "out_blocked");
    std::vector<Segment> batch(count);
    for (uint32_t i = 0; i < count; ++i)
        batch[i] = Segment{read_point(segments[i].from, "segments", i, "from"),
                           read_point(segments[i].to, "segments", i, "to")};
    world.level().segments_blocked(batch.data(), count, out_blocked);
}

}  // namespace nl::capi

extern "C" {

NL_API nl_mesh_def nl_default_mesh_def(void) {
    nl_mesh_def def{};
    def.size = sizeof(nl_mesh_def);
    return def;
}

NL_API nl_status nl_mesh_add(nl_world* world, const nl_mesh_def* def, nl_mesh_id* out_id) {
    return guarded("nl_mesh_add", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        require(out_id, "out_id");
        const nl_mesh_def settings = read_def(*def);
        *out_id = add_mesh(w, nl::naming_fields("def->", [&] { return read_def_geometry(settings); }), settings,
                           "nl_mesh_add");
    });
}

NL_API nl_status nl_mesh_add_obj_file(nl_world* world, const char* path, const nl_mesh_def* def, nl_mesh_id* out_id) {
    return guarded("nl_mesh_add_obj_file", world, [&] {
        nl::World& w = deref(world);
        require(path, "path");
        require(out_id, "out_id");
        const nl_mesh_def options = obj_options(def);
        *out_id = add_mesh(w, nl::read_obj_file(path), options, "nl_mesh_add_obj_file", path);
    });
}

NL_API nl_status nl_mesh_add_obj_memory(nl_world* world, const char* data, size_t length, const nl_mesh_def* def,
                                        nl_mesh_id* out_id) {
    return guarded("nl_mesh_add_obj_memory", world, [&] {
        nl::World& w = deref(world);
        if (length > 0) require(data, "data");
        require(out_id, "out_id");
        const nl_mesh_def options = obj_options(def);
        *out_id = add_mesh(w, nl::read_obj_text(std::string_view(data ? data : "", length)), options,
                           "nl_mesh_add_obj_memory", "data");
    });
}

NL_API nl_status nl_mesh_remove(nl_world* world, nl_mesh_id mesh) {
    return guarded("nl_mesh_remove", world, [&] { deref(world).remove_mesh(to_handle(mesh)); });
}

NL_API nl_status nl_mesh_set_transform(nl_world* world, nl_mesh_id mesh, const float* transform) {
    return guarded("nl_mesh_set_transform", world, [&] {
        nl::World& w = deref(world);
        require(transform, "transform");
        w.set_mesh_transform(to_handle(mesh), read_transform(transform));
    });
}

NL_API int32_t nl_mesh_is_valid(const nl_world* world, nl_mesh_id mesh) {
    int32_t valid = 0;
    guarded("nl_mesh_is_valid", world, [&] { valid = deref(world).level().contains(to_handle(mesh)) ? 1 : 0; });
    return valid;
}

NL_API nl_status nl_mesh_get_info(const nl_world* world, nl_mesh_id mesh, nl_mesh_info* out_info) {
    return guarded("nl_mesh_get_info", world, [&] {
        const nl::World& w = deref(world);
        require(out_info, "out_info");
        const nl::MeshInfo info = w.level().info(to_handle(mesh));
        nl_mesh_info out{};
        out.size = sizeof(nl_mesh_info);
        out.vertex_count = info.vertex_count;
        out.triangle_count = info.triangle_count;
        out.degenerate_triangle_count = info.degenerate_triangle_count;
        out.flags = info.flags;
        out.area = info.area;
        Eigen::Map<Eigen::Matrix4f>(out.transform) = info.transform.matrix();
        Eigen::Map<nl::Vec3>(out.bounds_min) = info.bounds.min;
        Eigen::Map<nl::Vec3>(out.bounds_max) = info.bounds.max;
        out.user_data = info.user_data;
        out.metres_per_unit = info.frame.metres_per_unit;
        out.up_axis = uint32_t(info.frame.up);
        nl::capi::write_growable(out_info, out, nl::capi::kFirstSize<nl_mesh_info>, "out_info");
    });
}

NL_API nl_status nl_world_get_meshes(const nl_world* world, nl_mesh_id* out_ids, uint32_t capacity,
                                     uint32_t* out_count) {
    return guarded("nl_world_get_meshes", world, [&] {
        nl::capi::list_into(deref(world).level().meshes(), out_ids, capacity, out_count, "out_ids", to_id<nl_mesh_id>);
    });
}

NL_API nl_status nl_world_cast_rays(nl_world* world, const nl_ray* rays, uint32_t count, nl_ray_hit* out_hits) {
    return guarded("nl_world_cast_rays", world, [&] { nl::capi::cast_rays(deref(world), rays, count, out_hits); });
}

NL_API nl_status nl_world_segments_blocked(nl_world* world, const nl_segment* segments, uint32_t count,
                                           uint8_t* out_blocked) {
    return guarded("nl_world_segments_blocked", world,
                   [&] { nl::capi::segments_blocked(deref(world), segments, count, out_blocked); });
}

}  // extern "C"
