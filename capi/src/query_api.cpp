// Queries on a navmesh for one body: reachability, the surface raycast and slide, random points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "mapping.h"
#include "navmesh/random_points.h"
#include "navmesh/surface_walk.h"
#include "path/reachability.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::Vec3;
using nl::capi::copy_point;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;

namespace {

static_assert(NL_NO_ISLAND == nl::ReachabilityMap::kNoIsland, "header and core disagree");

struct Filter {
    nl::AgentCapabilities capabilities;
    std::vector<float> area_costs;
    std::array<uint64_t, 4> excluded;

    bool excludes_any() const { return (excluded[0] | excluded[1] | excluded[2] | excluded[3]) != 0; }
    bool may_enter(const nl::NavMesh& mesh, uint32_t p) const {
        return !nl::ReachabilityClass::area_excluded(excluded, mesh.area(p));
    }
};

// `name` is the filter's argument name ("filter", "def->filter").
Filter read_filter(const nl_query_filter* given, const std::string& name) {
    if (!given) {  // the default walker: nothing to check
        static const Filter defaults{nl::capi::read_capabilities(nl_default_agent_capabilities(), ""), {}, {}};
        return defaults;
    }
    const nl_query_filter filter =
        nl::capi::read_growable(*given, nl_default_query_filter(), nl::capi::kFirstSize<nl_query_filter>, name.c_str());
    const std::string prefix = name + "->";
    Filter body;
    body.capabilities = nl::capi::read_capabilities(filter.capabilities, prefix.c_str());
    body.area_costs = nl::capi::read_area_costs(filter.area_costs, filter.area_cost_count, prefix.c_str());
    body.excluded = nl::ReachabilityClass::excluded_areas_of(body.area_costs);
    return body;
}

// The navmesh and its links now (the map is built for these), and the body's map.
std::shared_ptr<const nl::PathGraph> graph_of(const nl::World& world, nl_navmesh_id navmesh) {
    return world.navmeshes().path_graph(to_handle(navmesh));
}
std::shared_ptr<const nl::ReachabilityMap> map_of(const nl::PathGraph& graph, const Filter& body) {
    return graph.reachability(body.capabilities, body.area_costs);
}

void check_polygon(const nl::NavMesh& mesh, uint32_t polygon, const char* name) {
    if (polygon >= mesh.polygon_count())
        fail(ErrorCode::InvalidArgument, name, " is ", polygon, " but the navmesh has ", mesh.polygon_count(),
             " polygons");
}

// A walk's start: in the navmesh's space, over its polygon. `prefix` parts name the struct the
// fields are in ("rays[", 3, "]."), or nothing for a walk's own arguments; spelt out on failure only.
template <typename... Prefix>
Vec3 read_start(const nl::NavMesh& mesh, const nl::CarrierPose& pose, uint32_t polygon, const float* start,
                const Prefix&... prefix) {
    if (polygon >= mesh.polygon_count())
        fail(ErrorCode::InvalidArgument, prefix..., "start_polygon is ", polygon, " but the navmesh has ",
             mesh.polygon_count(), " polygons");
    if (!start) fail(ErrorCode::InvalidArgument, prefix..., "start is null");
    const Vec3 local = pose.carrier_point(nl::capi::read_position(start, prefix..., "start"));
    if (mesh.over_polygon(polygon, local.x(), local.z())) return local;
    const Vec3 on = mesh.closest_point_on_polygon(polygon, local);
    const float dx = on.x() - local.x(), dz = on.z() - local.z();
    constexpr float kOverTolerance = 1e-3f;
    if (dx * dx + dz * dz > kOverTolerance * kOverTolerance)
        fail(ErrorCode::InvalidArgument, prefix..., "start is not over ", prefix..., "start_polygon ", polygon, " (",
             std::sqrt(dx * dx + dz * dz), " m from it, seen from above)");
    return local;
}

// Checked before a walk writes anything.
void check_polygons_output(const uint32_t* out, uint32_t capacity) {
    if (!out && capacity > 0) fail(ErrorCode::InvalidArgument, "out_polygons is null but capacity is ", capacity);
}

// Writes a slide's polygons: as many as fit, the count of all of them.
void write_polygons(const std::vector<uint32_t>& polygons, uint32_t* out, uint32_t capacity, uint32_t* out_count) {
    const uint32_t written = out ? static_cast<uint32_t>(std::min<size_t>(capacity, polygons.size())) : 0;
    std::copy(polygons.begin(), polygons.begin() + written, out);
    if (out_count) *out_count = static_cast<uint32_t>(polygons.size());
    if (out && written < polygons.size())
        fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but the walk visited ", polygons.size(),
             " polygons");
}

}  // namespace

extern "C" {

NL_API nl_query_filter nl_default_query_filter(void) {
    nl_query_filter filter{};
    filter.size = sizeof(nl_query_filter);
    filter.capabilities = nl_default_agent_capabilities();
    return filter;
}

NL_API nl_random_points_def nl_default_random_points_def(void) {
    nl_random_points_def def{};
    def.size = sizeof(nl_random_points_def);
    def.reachable_from = NL_NO_POLYGON;
    def.seed = 1;
    return def;
}

NL_API nl_status nl_navmesh_can_reach(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                      const uint32_t* from_polygons, const uint32_t* to_polygons, uint32_t count,
                                      uint8_t* out_reachable) {
    return guarded("nl_navmesh_can_reach", world, [&] {
        const nl::World& w = deref(world);
        const Filter body = read_filter(filter, "filter");
        const auto graph = graph_of(w, navmesh);
        const uint32_t polygons = graph->navmesh().polygon_count();
        if (count == 0) return;
        require(from_polygons, "from_polygons");
        require(to_polygons, "to_polygons");
        require(out_reachable, "out_reachable");
        for (uint32_t i = 0; i < count; ++i) {
            const bool from_bad = from_polygons[i] >= polygons;
            if (from_bad || to_polygons[i] >= polygons)
                fail(ErrorCode::InvalidArgument, from_bad ? "from_polygons[" : "to_polygons[", i, "] is ",
                     from_bad ? from_polygons[i] : to_polygons[i], " but the navmesh has ", polygons, " polygons");
        }
        const auto map = map_of(*graph, body);
        for (uint32_t i = 0; i < count; ++i) out_reachable[i] = map->reaches(from_polygons[i], to_polygons[i]) ? 1 : 0;
    });
}

NL_API nl_status nl_navmesh_get_reachable_polygons(const nl_world* world, nl_navmesh_id navmesh,
                                                   const nl_query_filter* filter, uint32_t from_polygon,
                                                   uint32_t* out_polygons, uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_reachable_polygons", world, [&] {
        const nl::World& w = deref(world);
        const Filter body = read_filter(filter, "filter");
        const auto graph = graph_of(w, navmesh);
        check_polygon(graph->navmesh(), from_polygon, "from_polygon");
        std::vector<uint32_t> reached;
        map_of(*graph, body)->reachable_polygons(from_polygon, reached);
        nl::capi::list_into(reached, out_polygons, capacity, out_count, "out_polygons", [](uint32_t p) { return p; });
    });
}

NL_API nl_status nl_navmesh_get_islands(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                        uint32_t* out_islands, uint32_t capacity, uint32_t* out_count,
                                        uint32_t* out_island_count) {
    return guarded("nl_navmesh_get_islands", world, [&] {
        const nl::World& w = deref(world);
        const Filter body = read_filter(filter, "filter");
        const auto graph = graph_of(w, navmesh);
        const auto map = map_of(*graph, body);
        const uint32_t polygons = graph->navmesh().polygon_count();
        if (out_island_count) *out_island_count = map->island_count();  // also when the polygons do not fit
        nl::capi::list_into(polygons, out_islands, capacity, out_count, "out_islands", [&] {
            for (uint32_t p = 0; p < polygons; ++p) out_islands[p] = map->island(p);
        });
    });
}

NL_API nl_status nl_navmesh_raycast(const nl_world* world, nl_navmesh_id navmesh, const nl_query_filter* filter,
                                    const nl_navmesh_ray* rays, uint32_t count, nl_navmesh_raycast_hit* out_hits,
                                    uint32_t* out_polygons, uint32_t polygons_per_ray) {
    return guarded("nl_navmesh_raycast", world, [&] {
        const nl::World& w = deref(world);
        const Filter body = read_filter(filter, "filter");
        const nl::NavMeshRegistry::Placed placed = w.navmeshes().placed(to_handle(navmesh));
        const nl::NavMesh& mesh = *placed.navmesh;
        const nl::CarrierPose pose = nl::pose_of(placed.frame);
        if (count == 0) return;
        require(rays, "rays");
        require(out_hits, "out_hits");
        if (!out_polygons && polygons_per_ray > 0)
            fail(ErrorCode::InvalidArgument, "out_polygons is null but polygons_per_ray is ", polygons_per_ray);
        const nl::capi::ElementWriter<nl_navmesh_raycast_hit> hits(
            out_hits, nl::capi::kFirstSize<nl_navmesh_raycast_hit>, "out_hits");
        // Every ray is checked before any is walked: a refused batch writes nothing.
        thread_local std::vector<std::pair<Vec3, Vec3>> ends;
        ends.resize(count);
        for (uint32_t i = 0; i < count; ++i) {
            ends[i].first = read_start(mesh, pose, rays[i].start_polygon, rays[i].start, "rays[", i, "].");
            ends[i].second = pose.carrier_point(nl::capi::read_position(rays[i].end, "rays[", i, "].end"));
        }
        const auto passable_fn = [&](uint32_t p) { return body.may_enter(mesh, p); };
        const nl::PolygonFilter passable(passable_fn);
        // The workers read this thread's checked ends: `ends` named inside them would be their own.
        const std::vector<std::pair<Vec3, Vec3>>& checked = ends;
        w.tasks().parallel_for(count, 64, [&](uint32_t begin, uint32_t end) {
            thread_local std::vector<uint32_t> crossed;
            nl::SurfaceWalkOptions options;
            options.passable = body.excludes_any() ? &passable : nullptr;
            options.max_polygons = mesh.polygon_count() + 1;
            options.polygons = &crossed;
            for (uint32_t i = begin; i < end; ++i) {
                const nl::SurfaceRayHit hit =
                    nl::raycast_surface(mesh, rays[i].start_polygon, checked[i].first, checked[i].second, options);
                nl_navmesh_raycast_hit c{};
                c.hit = hit.hit ? 1 : 0;
                c.t = hit.t;
                copy_point(c.point, pose.world_point(hit.point));
                copy_point(c.wall_normal, pose.world_vector(hit.wall_normal));
                c.end_polygon = hit.end_polygon;
                c.polygon_count = static_cast<uint32_t>(crossed.size());
                hits.write(i, c);
                if (polygons_per_ray > 0)
                    std::copy_n(crossed.begin(), std::min<size_t>(crossed.size(), polygons_per_ray),
                                out_polygons + size_t(i) * polygons_per_ray);
            }
        });
    });
}

NL_API nl_status nl_navmesh_move_along_surface(const nl_world* world, nl_navmesh_id navmesh,
                                               const nl_query_filter* filter, uint32_t start_polygon,
                                               const float* start, const float* target, nl_nav_point* out_point,
                                               uint32_t* out_polygons, uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_move_along_surface", world, [&] {
        const nl::World& w = deref(world);
        const Filter body = read_filter(filter, "filter");
        const nl::NavMeshRegistry::Placed placed = w.navmeshes().placed(to_handle(navmesh));
        const nl::NavMesh* mesh = placed.navmesh.get();
        const nl::CarrierPose pose = nl::pose_of(placed.frame);
        const Vec3 from = read_start(*mesh, pose, start_polygon, start);
        require(target, "target");
        const Vec3 to = pose.carrier_point(nl::capi::read_position(target, "target"));
        require(out_point, "out_point");
        check_polygons_output(out_polygons, capacity);

        thread_local std::vector<uint32_t> visited;
        const auto passable_fn = [&](uint32_t p) { return body.may_enter(*mesh, p); };
        const nl::PolygonFilter passable(passable_fn);
        nl::SurfaceWalkOptions options;
        options.passable = body.excludes_any() ? &passable : nullptr;
        options.max_polygons = mesh->polygon_count();
        options.polygons = &visited;
        const nl::SurfaceMove moved = nl::move_along_surface(*mesh, start_polygon, from, to, options);
        *out_point =
            nl::capi::to_c(nl::NavPoint{true, moved.position, (moved.position - to).norm(), moved.polygon}, pose);
        write_polygons(visited, out_polygons, capacity, out_count);
    });
}

NL_API nl_status nl_navmesh_random_points(const nl_world* world, nl_navmesh_id navmesh, const nl_random_points_def* def,
                                          nl_nav_point* out_points, uint32_t count, uint32_t* out_found) {
    return guarded("nl_navmesh_random_points", world, [&] {
        const nl::World& w = deref(world);
        require(def, "def");
        const nl_random_points_def d = nl::capi::read_growable(*def, nl_default_random_points_def(),
                                                               nl::capi::kFirstSize<nl_random_points_def>, "def");
        const Filter body = read_filter(d.filter, "def->filter");
        const auto graph = graph_of(w, navmesh);
        const nl::NavMesh* mesh = &graph->navmesh();
        const nl::CarrierPose pose = nl::pose_of(graph->frame());  // the graph's own navmesh and frame
        nl::RandomPointsRequest request;
        request.centre = pose.carrier_point(nl::capi::read_position(d.centre, "def->centre"));
        request.radius = nl::capi::read_amount(d.radius, "def->radius");
        if (request.radius > nl::kCoordinateLimit)
            fail(ErrorCode::InvalidArgument, "def->radius is beyond the coordinate limit");
        request.seed = d.seed;
        std::shared_ptr<const nl::ReachabilityMap> map;
        if (d.reachable_from != NL_NO_POLYGON) {
            check_polygon(*mesh, d.reachable_from, "def->reachable_from");
            map = map_of(*graph, body);
        }
        require(out_found, "out_found");
        if (count > 0) require(out_points, "out_points");
        *out_found = 0;
        if (count == 0) return;
        std::vector<uint8_t> reached_islands;  // one walk of the island graph for every polygon asked about
        if (map) map->reachable_islands(d.reachable_from, reached_islands);
        const auto allowed_fn = [&](uint32_t p) {
            if (!body.may_enter(*mesh, p)) return false;
            if (!map || p == d.reachable_from) return true;
            const uint32_t island = map->island(p);
            return island != nl::ReachabilityMap::kNoIsland && reached_islands[island] != 0;
        };
        const nl::PolygonFilter allowed(allowed_fn);
        thread_local std::vector<nl::NavPoint> points;
        points.resize(count);
        const uint32_t found = nl::random_points(*mesh, request, &allowed, count, points.data());
        for (uint32_t i = 0; i < count; ++i)
            out_points[i] = i < found ? nl::capi::to_c(points[i], pose) : nl_nav_point{};
        for (uint32_t i = found; i < count; ++i) out_points[i].polygon = NL_NO_POLYGON;
        *out_found = found;
    });
}

}  // extern "C"
