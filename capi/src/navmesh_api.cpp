#include <cstddef>
#include <cmath>
#include <cstring>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "mapping.h"
#include "navmesh/navmesh_builder.h"
#include "queries.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;

namespace {

static_assert(NL_BUILD_WARNING_CLOCKWISE == nl::kWarnedClockwise && NL_BUILD_WARNING_UNITS == nl::kWarnedUnits &&
                  NL_BUILD_WARNING_Z_UP == nl::kWarnedZUp,
              "header and core disagree on build warnings");

constexpr uint32_t kMaxCorners = NL_MAX_POLYGON_VERTICES;
static_assert(NL_MAX_POLYGON_VERTICES == nl::kMaxPolygonVertices, "header and core disagree");
static_assert(NL_NO_POLYGON == nl::kNoPolygon, "header and core disagree");

using nl::capi::to_handle;
using nl::capi::copy_point;
using nl::capi::to_id;

using nl::capi::to_c;

}  // namespace

namespace nl::capi {

AgentType to_core(const nl_agent_type& a) { return AgentType{a.radius, a.height, a.max_climb, a.max_slope}; }
nl_agent_type to_c(const AgentType& a) { return nl_agent_type{a.radius, a.height, a.max_climb, a.max_slope}; }

nl_nav_point to_c(const NavPoint& p, const CarrierPose& pose) {
    nl_nav_point r{};
    r.found = p.found ? 1 : 0;
    r.polygon = p.polygon;
    r.distance = p.distance;
    if (p.found) copy_point(r.point, pose.world_point(p.point));
    return r;
}

NavMeshInput navmesh_input_from_def(const nl_navmesh_def& given) {
    const nl_navmesh_def def =
        read_growable(given, nl_default_navmesh_def(), nl::capi::kFirstSize<nl_navmesh_def>, "def");
    NavMeshInput in;
    in.vertices = read_vertices(def.vertices, def.vertex_count, def.vertex_stride);
    require_field(def.indices, "indices");
    if (def.polygon_count == 0) fail_field(ErrorCode::InvalidArgument, "polygon_count is 0");
    size_t index_count = size_t(def.polygon_count) * 3;
    if (def.polygon_vertex_counts) {
        in.polygon_sizes.assign(def.polygon_vertex_counts, def.polygon_vertex_counts + def.polygon_count);
        index_count = 0;
        // Checked before they size the read of the indices.
        for (size_t p = 0; p < in.polygon_sizes.size(); ++p) {
            const uint32_t n = in.polygon_sizes[p];
            if (n < 3 || n > kMaxCorners)
                fail_field(ErrorCode::InvalidArgument, "polygon_vertex_counts[", p, "] = ", n, " (must be 3..",
                           kMaxCorners, ")");
            index_count += n;
        }
    }
    in.indices.assign(def.indices, def.indices + index_count);
    if (def.areas) in.areas.assign(def.areas, def.areas + def.polygon_count);
    in.weld_tolerance = def.weld_tolerance;
    in.agent_type = to_core(def.agent_type);
    if (def.tile_width != 0.0f) {
        // Checked here, where the field's name is known; the builder checks the grid again.
        if (!(std::isfinite(def.tile_width) && def.tile_width > 0.0f))
            fail_field(ErrorCode::InvalidArgument, "tile_width is ", def.tile_width,
                       " (must be > 0, or 0: not a tile)");
        if (!std::isfinite(def.tile_origin_x) || !std::isfinite(def.tile_origin_z))
            fail_field(ErrorCode::InvalidArgument, "tile_origin_x and tile_origin_z must be finite");
        in.tiles.grid = TileGrid{def.tile_origin_x, def.tile_origin_z, def.tile_width};
        in.tiles.tiles.push_back(TileCoord{def.tile_x, def.tile_z});
    }

    const bool any_detail = def.detail_vertices || def.detail_triangles || def.detail_triangle_starts ||
                            def.detail_vertex_count || def.detail_triangle_count;
    if (any_detail) {
        require_field(def.detail_vertices, "detail_vertices");
        require_field(def.detail_triangles, "detail_triangles");
        require_field(def.detail_triangle_starts, "detail_triangle_starts");
        if (def.detail_vertex_count == 0 || def.detail_triangle_count == 0)
            fail_field(ErrorCode::InvalidArgument,
                       "detail_vertex_count and detail_triangle_count must be > 0 with detail");
        in.detail_starts.assign(def.detail_triangle_starts, def.detail_triangle_starts + def.polygon_count + 1);
        in.detail_vertices.resize(def.detail_vertex_count);
        for (uint32_t i = 0; i < def.detail_vertex_count; ++i)
            in.detail_vertices[i] = Eigen::Map<const Vec3>(def.detail_vertices + 3 * size_t(i));
        in.detail_indices.assign(def.detail_triangles, def.detail_triangles + size_t(def.detail_triangle_count) * 3);
    }
    return in;
}

void navmesh_get_info(const World& world, nl_navmesh_id navmesh, nl_navmesh_info* out_info) {
    const auto mesh = world.navmeshes().navmesh(to_handle(navmesh));
    const auto frame = world.navmeshes().frame(to_handle(navmesh));
    const nl::CarrierPose pose = nl::pose_of(frame);
    require(out_info, "out_info");
    nl_navmesh_info info{};
    info.size = sizeof info;
    info.vertex_count = mesh->vertex_count();
    info.polygon_count = mesh->polygon_count();
    info.portal_count = mesh->portal_count();
    info.boundary_edge_count = mesh->boundary_edge_count();
    info.welded_vertex_count = mesh->repairs().welded_vertices;
    info.flipped_polygon_count = mesh->repairs().flipped_polygons;
    info.dropped_polygon_count = mesh->repairs().dropped_polygons;
    info.non_manifold_edge_count = mesh->repairs().non_manifold_edges;
    info.t_junction_corner_count = mesh->repairs().t_junction_corners;
    info.unjoined_t_junction_count = mesh->repairs().t_junctions_left;
    info.tile_count = static_cast<uint32_t>(mesh->tiles().tiles.size());
    info.tile_width = mesh->tiles().grid.tile_width;
    info.tile_origin[0] = mesh->tiles().grid.origin_x;
    info.tile_origin[1] = mesh->tiles().grid.origin_z;
    info.agent_type = to_c(mesh->agent());
    const nl::Aabb bounds = pose.world_box(mesh->bounds());
    copy_point(info.bounds_min, bounds.min);
    copy_point(info.bounds_max, bounds.max);
    if (frame) info.carrier = to_id<nl_mesh_id>(frame->mesh());
    const nl::NavMeshProvenance made_for = world.navmeshes().made_for(to_handle(navmesh));
    info.turned_over_mesh_count = static_cast<uint32_t>(made_for.turned_over_meshes.size());
    info.build_warnings = made_for.warnings;
    write_growable(out_info, info, nl::capi::kFirstSize<nl_navmesh_info>, "out_info");
}

void navmesh_get_boundary_edges(const World& world, nl_navmesh_id navmesh, nl_boundary_edge* out_edges,
                                uint32_t capacity, uint32_t* out_count) {
    const auto mesh = world.navmeshes().navmesh(to_handle(navmesh));
    const nl::CarrierPose pose = world.navmesh_pose(to_handle(navmesh));
    list_into(mesh->boundary_edges(), out_edges, capacity, out_count, "out_edges", [&](const BoundaryEdge& e) {
        nl_boundary_edge out{};
        copy_point(out.start, pose.world_point(e.start));
        copy_point(out.end, pose.world_point(e.end));
        copy_point(out.outward, pose.world_vector(e.outward));
        copy_point(out.normal, pose.world_vector(e.normal));
        out.polygon = e.polygon;
        out.edge = e.edge;
        return out;
    });
}

void navmesh_find_nearest(const World& world, nl_navmesh_id navmesh, const float* points, uint32_t count,
                          const float* half_extents, nl_nav_point* out) {
    const auto mesh = world.navmeshes().navmesh(to_handle(navmesh));
    const nl::CarrierPose pose = world.navmesh_pose(to_handle(navmesh));
    require(half_extents, "half_extents");
    const Vec3 extents(half_extents[0], half_extents[1], half_extents[2]);
    if (!(extents.array() > 0.0f).all() || !within_coordinate_limit(extents))
        fail(ErrorCode::InvalidArgument, "half_extents must be positive and finite");
    if (count == 0) return;
    require(points, "points");
    require(out, "out");
    for (uint32_t i = 0; i < count; ++i) {
        if (!within_coordinate_limit(Eigen::Map<const Vec3>(points + 3 * size_t(i))))
            fail(ErrorCode::InvalidArgument, "points[", i, "] is not finite or beyond the coordinate limit");
    }
    world.tasks().parallel_for(count, 256, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const Vec3 point = pose.carrier_point(Eigen::Map<const Vec3>(points + 3 * size_t(i)));
            const NavPoint p = mesh->find_nearest(point, pose.carrier_extents(extents));
            out[i] = to_c(p, pose);
            if (p.found) continue;
            // Why nothing was found: where the navmesh is, beyond the box.
            const NavPoint beyond = mesh->find_nearest_anywhere(point, pose.carrier_extents(extents));
            if (!beyond.found) continue;
            out[i].beyond_box = 1;
            out[i].distance = beyond.distance;
            copy_point(out[i].point, pose.world_point(beyond.point));
        }
    });
}

}  // namespace nl::capi

extern "C" {

NL_API nl_agent_type nl_default_agent_type(void) { return to_c(nl::AgentType{}); }

NL_API nl_navmesh_def nl_default_navmesh_def(void) {
    nl_navmesh_def def{};
    def.size = sizeof(nl_navmesh_def);
    def.weld_tolerance = 0.001f;
    def.agent_type = nl_default_agent_type();
    return def;
}

NL_API nl_status nl_navmesh_add(nl_world* world, const nl_navmesh_def* def, nl_navmesh_id* out_id) {
    return guarded("nl_navmesh_add", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        require(out_id, "out_id");
        const nl_navmesh_def full =
            nl::capi::read_growable(*def, nl_default_navmesh_def(), nl::capi::kFirstSize<nl_navmesh_def>, "def");
        *out_id = to_id<nl_navmesh_id>(nl::naming_fields(
            "def->", [&] { return w.add_navmesh(nl::capi::navmesh_input_from_def(*def), to_handle(full.carrier)); }));
    });
}

NL_API nl_status nl_navmesh_remove(nl_world* world, nl_navmesh_id navmesh) {
    return guarded("nl_navmesh_remove", world, [&] { deref(world).navmeshes().remove(to_handle(navmesh)); });
}

NL_API int32_t nl_navmesh_is_valid(const nl_world* world, nl_navmesh_id navmesh) {
    int32_t valid = 0;
    guarded("nl_navmesh_is_valid", world,
            [&] { valid = deref(world).navmeshes().contains(to_handle(navmesh)) ? 1 : 0; });
    return valid;
}

NL_API nl_status nl_navmesh_get_info(const nl_world* world, nl_navmesh_id navmesh, nl_navmesh_info* out_info) {
    return guarded("nl_navmesh_get_info", world, [&] { nl::capi::navmesh_get_info(deref(world), navmesh, out_info); });
}

NL_API nl_status nl_navmesh_get_vertices(const nl_world* world, nl_navmesh_id navmesh, float* out_xyz,
                                         uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_vertices", world, [&] {
        const auto mesh = deref(world).navmeshes().navmesh(to_handle(navmesh));
        const nl::CarrierPose pose = deref(world).navmesh_pose(to_handle(navmesh));
        nl::capi::list_into(mesh->vertex_count(), out_xyz, capacity, out_count, "out_xyz", [&] {
            for (uint32_t i = 0; i < mesh->vertex_count(); ++i)
                copy_point(out_xyz + 3 * size_t(i), pose.world_point(mesh->vertex(i)));
        });
    });
}

NL_API nl_status nl_navmesh_get_polygon(const nl_world* world, nl_navmesh_id navmesh, uint32_t polygon,
                                        nl_nav_polygon* out_polygon) {
    return guarded("nl_navmesh_get_polygon", world, [&] {
        const auto mesh = deref(world).navmeshes().navmesh(to_handle(navmesh));
        const nl::CarrierPose pose = deref(world).navmesh_pose(to_handle(navmesh));
        require(out_polygon, "out_polygon");
        if (polygon >= mesh->polygon_count())
            fail(ErrorCode::InvalidArgument, "polygon ", polygon,
                 " is out of range (polygon_count = ", mesh->polygon_count(), ")");
        nl_nav_polygon out{};
        out.size = sizeof out;
        out.vertex_count = mesh->corner_count(polygon);
        for (uint32_t k = 0; k < out.vertex_count; ++k) {
            out.vertices[k] = mesh->corner(polygon, k);
            out.neighbours[k] = mesh->neighbour(polygon, k);
        }
        for (uint32_t k = out.vertex_count; k < NL_MAX_POLYGON_VERTICES; ++k) out.neighbours[k] = NL_NO_POLYGON;
        out.area = mesh->area(polygon);
        copy_point(out.normal, pose.world_vector(mesh->normal(polygon)));
        copy_point(out.centre, pose.world_point(mesh->centre(polygon)));
        nl::capi::write_growable(out_polygon, out, nl::capi::kFirstSize<nl_nav_polygon>, "out_polygon");
    });
}

NL_API nl_status nl_navmesh_get_boundary_edges(const nl_world* world, nl_navmesh_id navmesh,
                                               nl_boundary_edge* out_edges, uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_boundary_edges", world, [&] {
        nl::capi::navmesh_get_boundary_edges(deref(world), navmesh, out_edges, capacity, out_count);
    });
}

NL_API nl_status nl_navmesh_find_nearest(const nl_world* world, nl_navmesh_id navmesh, const float* points,
                                         uint32_t count, const float* half_extents, nl_nav_point* out) {
    return guarded("nl_navmesh_find_nearest", world,
                   [&] { nl::capi::navmesh_find_nearest(deref(world), navmesh, points, count, half_extents, out); });
}

NL_API nl_status nl_world_get_navmeshes(const nl_world* world, nl_navmesh_id* out_ids, uint32_t capacity,
                                        uint32_t* out_count) {
    return guarded("nl_world_get_navmeshes", world, [&] {
        nl::capi::list_into(deref(world).navmeshes().handles(), out_ids, capacity, out_count, "out_ids",
                            to_id<nl_navmesh_id>);
    });
}

}  // extern "C"
