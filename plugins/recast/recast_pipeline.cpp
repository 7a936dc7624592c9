#include "recast_pipeline.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "build_failure.h"

namespace nl::recast {
namespace {

// Recast's limits: polygon-mesh vertices are unsigned short grid coordinates, rcErodeWalkableArea
// compares distances in an unsigned char holding twice the radius, compact spans keep at most 255
// cells of headroom, and the span array of the grid is allocated whole.
constexpr double kMaxGridSide = 65535.0;
constexpr double kMaxGridCells = double(1 << 27);
constexpr int kMaxErodeRadius = 127;
constexpr int kMaxWalkableHeight = 255;
// rcCompactCell keeps its first span's index in 24 bits: past this many walkable spans the compact
// heightfield's cells wrap around to earlier spans. Watershed regions then come out empty ("no
// walkable surface" for a 1.24 km floor at 0.3 m cells) and monotone ones silently drop part of it.
constexpr int kMaxCompactSpans = (1 << 24) - 1;
constexpr float kNoDetailSampling = 1e30f;

// A level too large for its cells is most often a level in centimetres read as metres: said with the
// remedy for each.
std::string units_hint(const float* bmin, const float* bmax) {
    std::ostringstream out;
    out << "; the level is " << std::lround(bmax[0] - bmin[0]) << " x " << std::lround(bmax[2] - bmin[2]) << " m and "
        << std::lround(bmax[1] - bmin[1])
        << " m tall: if that is not its size in metres, register its meshes with nl_mesh_def.metres_per_unit "
           "(0.01 for centimetres)";
    return out.str();
}

std::string describe(const nl_agent_type& a) {
    std::ostringstream out;
    out << "agent radius " << a.radius << " m, height " << a.height << " m, max climb " << a.max_climb
        << " m, max slope " << a.max_slope << " degrees";
    return out.str();
}

// Fails naming `step` when a Recast step returned false; Recast's own "Out of memory" becomes
// OUT_OF_MEMORY, anything else INTERNAL_ERROR.
void require_step(bool ok, const char* step, const HostLogContext& context) {
    if (ok) return;
    const std::string& why = context.last_error();
    const bool out_of_memory =
        why.find("Out of memory") != std::string::npos || why.find("out of memory") != std::string::npos;
    fail(out_of_memory ? NL_STATUS_OUT_OF_MEMORY : NL_STATUS_INTERNAL_ERROR, "Recast step ", step, " failed",
         why.empty() ? "" : ": ", why);
}

// How many triangles rcRasterizeTriangles takes between two progress reports: a few milliseconds.
constexpr int kRasterizeChunk = 1 << 16;

}  // namespace

void no_walkable_surface(const nl_agent_type& agent, const std::string& why) {
    fail(NL_STATUS_NOT_FOUND, "no walkable surface for ", describe(agent), ": ", why);
}

std::vector<unsigned char> walkable_areas(HostLogContext& ctx, const LevelTriangles& level, const rcConfig& cfg,
                                          const nl_agent_type& agent) {
    const int nverts = level.vertex_count();
    const int ntris = level.triangle_count();
    const int* tris = reinterpret_cast<const int*>(level.indices.data());
    for (int i = 0; i < ntris; ++i) {
        const unsigned area = level.areas[size_t(i)];
        if (area != NL_BUILD_AREA_OBSTACLE && area > kMaxRecastArea)
            fail(NL_STATUS_INVALID_ARGUMENT, "a mesh has area ", area, "; the Recast builder carries areas 0..",
                 kMaxRecastArea, " (Recast keeps 6 bits of area)");
    }
    std::vector<unsigned char> areas(static_cast<size_t>(ntris), RC_NULL_AREA);
    rcMarkWalkableTriangles(&ctx, cfg.walkableSlopeAngle, level.vertices.data(), nverts, tris, ntris, areas.data());
    bool any = false, any_flat = false;
    for (size_t i = 0; i < areas.size(); ++i) {
        if (areas[i] == RC_NULL_AREA) continue;
        any_flat = true;
        const bool obstacle = level.areas[i] == NL_BUILD_AREA_OBSTACLE;
        areas[i] = obstacle ? RC_NULL_AREA : static_cast<unsigned char>(level.areas[i] + 1);
        any = any || !obstacle;
    }
    if (any) return areas;
    if (any_flat)
        no_walkable_surface(agent, "every triangle flatter than max slope is an obstacle's (NL_MESH_OBSTACLE)");

    std::vector<int> turned(level.indices.begin(), level.indices.end());
    for (size_t t = 0; t < turned.size(); t += 3) std::swap(turned[t + 1], turned[t + 2]);
    std::vector<unsigned char> turned_areas(static_cast<size_t>(ntris), RC_NULL_AREA);
    rcMarkWalkableTriangles(&ctx, cfg.walkableSlopeAngle, level.vertices.data(), nverts, turned.data(), ntris,
                            turned_areas.data());
    size_t would_be = 0;
    for (size_t i = 0; i < turned_areas.size(); ++i)
        would_be += turned_areas[i] != RC_NULL_AREA && level.areas[i] != NL_BUILD_AREA_OBSTACLE;
    if (would_be > 0)
        no_walkable_surface(agent, std::to_string(would_be) + " of the level's " + std::to_string(ntris) +
                                       " triangles would be flat enough turned over: their fronts face down. A "
                                       "triangle's front is the side its corners run counter-clockwise from; register "
                                       "meshes wound clockwise (Godot's) with NL_MESH_CLOCKWISE");
    no_walkable_surface(agent, "no triangle of the level is flatter than max slope");
}

namespace {

template <typename T, typename Ptr = std::unique_ptr<T, RecastDeleter>>
Ptr require_allocated(T* p, const char* what) {
    if (!p) fail(NL_STATUS_OUT_OF_MEMORY, "out of memory allocating Recast's ", what);
    return Ptr(p);
}

}  // namespace

rcConfig make_config(const nl_recast_settings& s, const nl_agent_type& agent, const float* bmin, const float* bmax) {
    rcConfig cfg;
    std::memset(&cfg, 0, sizeof cfg);
    cfg.cs = s.cell_size;
    cfg.ch = s.cell_height;
    cfg.walkableSlopeAngle = agent.max_slope;

    const double height_cells = std::ceil(double(agent.height) / cfg.ch);
    if (height_cells > kMaxWalkableHeight)
        fail(NL_STATUS_INVALID_ARGUMENT, "agent_type.height of ", agent.height, " m is ", height_cells,
             " cells of cell_height ", cfg.ch, " m; Recast handles at most ", kMaxWalkableHeight,
             " (raise cell_height)");
    cfg.walkableHeight = static_cast<int>(height_cells);
    // A climb beyond the heightfield's height is no different from one of its full height.
    cfg.walkableClimb =
        static_cast<int>(std::min(std::floor(double(agent.max_climb) / cfg.ch), double(RC_SPAN_MAX_HEIGHT)));
    const double radius_cells = std::ceil(double(agent.radius) / cfg.cs);
    if (radius_cells > kMaxErodeRadius)
        fail(NL_STATUS_INVALID_ARGUMENT, "agent_type.radius of ", agent.radius, " m is ", radius_cells,
             " cells of cell_size ", cfg.cs, " m; Recast erodes at most ", kMaxErodeRadius, " (raise cell_size)");
    cfg.walkableRadius = static_cast<int>(radius_cells);

    cfg.maxEdgeLen = static_cast<int>(std::min(double(s.edge_max_length) / cfg.cs, double(INT_MAX)));
    cfg.maxSimplificationError = s.edge_max_error;
    cfg.minRegionArea = static_cast<int>(rcSqr(s.region_min_size));
    cfg.mergeRegionArea = static_cast<int>(rcSqr(s.region_merge_size));
    cfg.maxVertsPerPoly = static_cast<int>(s.vertices_per_polygon);
    // RecastDemo passes 0 to disable sampling, but Recast's buildPolyDetail then leaves the polygon's
    // hull empty and triangulateHull reads garbage (recastnavigation issue #650, still in Debian's
    // 1.5.1+git20210215: a crash). A distance longer than any edge does what 0 means: the outline
    // only, each edge in one piece, no interior samples.
    cfg.detailSampleDist = s.detail_sample_distance < 0.9f ? kNoDetailSampling : cfg.cs * s.detail_sample_distance;
    cfg.detailSampleMaxError = cfg.ch * s.detail_sample_max_error;

    rcVcopy(cfg.bmin, bmin);
    rcVcopy(cfg.bmax, bmax);
    const double width = (double(bmax[0]) - bmin[0]) / cfg.cs + 0.5;
    const double depth = (double(bmax[2]) - bmin[2]) / cfg.cs + 0.5;
    if (width > kMaxGridSide || depth > kMaxGridSide || width * depth > kMaxGridCells)
        fail(NL_STATUS_INVALID_ARGUMENT, "cell_size ", cfg.cs, " m makes a grid of ", std::floor(width), " x ",
             std::floor(depth), " cells over the level; Recast's solo mesh takes at most ", kMaxGridSide,
             " per side and ", kMaxGridCells, " in all (raise cell_size, or build in tiles: tile_size)",
             units_hint(bmin, bmax));
    const double layers = (double(bmax[1]) - bmin[1]) / cfg.ch;
    if (layers > RC_SPAN_MAX_HEIGHT)
        fail(NL_STATUS_INVALID_ARGUMENT, "cell_height ", cfg.ch, " m makes the level ", std::ceil(layers),
             " cells tall; Recast's heightfield holds at most ", RC_SPAN_MAX_HEIGHT, " (raise cell_height)",
             units_hint(bmin, bmax));
    // The navmesh's vertices lie on the grid, up to two cells above the highest voxel (Recast rounds
    // voxel tops up): all of it must stay within the coordinate limit the navmesh is held to, or a
    // cell of 1e18 m makes a navmesh nl_navmesh_add refuses.
    const double top = double(bmin[1]) + (std::ceil(layers) + 2.0) * cfg.ch;
    if (!(top <= NL_COORDINATE_LIMIT))
        fail(NL_STATUS_INVALID_ARGUMENT, "cell_height ", cfg.ch, " m puts the navmesh up to ", top,
             " m high, beyond the coordinate limit of ", NL_COORDINATE_LIMIT, " m (lower cell_height)");
    const double far = std::max(double(bmin[0]) + (std::ceil(width) + 1.0) * cfg.cs,
                                double(bmin[2]) + (std::ceil(depth) + 1.0) * cfg.cs);
    if (!(far <= NL_COORDINATE_LIMIT))
        fail(NL_STATUS_INVALID_ARGUMENT, "cell_size ", cfg.cs, " m puts the navmesh's grid out to ", far,
             " m, beyond the coordinate limit of ", NL_COORDINATE_LIMIT, " m (lower cell_size)");
    rcCalcGridSize(cfg.bmin, cfg.bmax, cfg.cs, &cfg.width, &cfg.height);
    return cfg;
}

RecastPolygons build_polygons(HostLogContext& ctx, const LevelTriangles& level, const int* tris,
                              const unsigned char* areas, int ntris, const rcConfig& cfg, const nl_recast_settings& s,
                              const nl_agent_type& agent, const BuildProgress* progress) {
    auto report = [&](float fraction, const char* stage) {
        if (progress) progress->report(fraction, stage);
    };
    const float* verts = level.vertices.data();
    const int nverts = level.vertex_count();
    if (cfg.width < 1 || cfg.height < 1) no_walkable_surface(agent, "the level is narrower than one cell");

    // Voxelise, in chunks so that the progress moves and a cancel is prompt on a large level.
    HeightfieldPtr solid = require_allocated(rcAllocHeightfield(), "heightfield");
    require_step(rcCreateHeightfield(&ctx, *solid, cfg.width, cfg.height, cfg.bmin, cfg.bmax, cfg.cs, cfg.ch),
                 "rcCreateHeightfield", ctx);
    for (int first = 0; first < ntris; first += kRasterizeChunk) {
        report(0.05f + 0.45f * float(first) / float(ntris), "rasterising the level");
        const int count = std::min(kRasterizeChunk, ntris - first);
        require_step(rcRasterizeTriangles(&ctx, verts, nverts, tris + 3 * size_t(first), areas + first, count, *solid,
                                          cfg.walkableClimb),
                     "rcRasterizeTriangles", ctx);
    }
    report(0.5f, "filtering spans");

    // Remove spans no agent could stand on, as configured.
    if (s.filter_low_hanging_obstacles) rcFilterLowHangingWalkableObstacles(&ctx, cfg.walkableClimb, *solid);
    if (s.filter_ledge_spans) rcFilterLedgeSpans(&ctx, cfg.walkableHeight, cfg.walkableClimb, *solid);
    if (s.filter_walkable_low_height_spans) rcFilterWalkableLowHeightSpans(&ctx, cfg.walkableHeight, *solid);

    const int walkable_spans = rcGetHeightFieldSpanCount(&ctx, *solid);
    if (walkable_spans > kMaxCompactSpans) {
        const double finer = std::sqrt(double(walkable_spans) / kMaxCompactSpans);
        fail(NL_STATUS_INVALID_ARGUMENT, "the level has ", walkable_spans, " walkable cells of cell_size ", cfg.cs,
             " m; Recast's compact heightfield indexes at most ", kMaxCompactSpans,
             " (24 bits): raise cell_size to at least ", std::ceil(cfg.cs * finer * 1000.0) / 1000.0,
             " m, or build in tiles (tile_size)", units_hint(cfg.bmin, cfg.bmax));
    }

    // Compact the walkable spans, keep the agent's radius from walls.
    report(0.55f, "compacting the heightfield");
    CompactHeightfieldPtr chf = require_allocated(rcAllocCompactHeightfield(), "compact heightfield");
    require_step(rcBuildCompactHeightfield(&ctx, cfg.walkableHeight, cfg.walkableClimb, *solid, *chf),
                 "rcBuildCompactHeightfield", ctx);
    solid.reset();
    if (chf->spanCount == 0) no_walkable_surface(agent, "no walkable span has the agent's headroom");
    report(0.6f, "eroding by the agent's radius");
    require_step(rcErodeWalkableArea(&ctx, cfg.walkableRadius, *chf), "rcErodeWalkableArea", ctx);
    report(0.65f, "partitioning into regions");

    // Partition into regions; a tile's border cells belong to its neighbours.
    switch (s.partition) {
        case NL_RECAST_PARTITION_MONOTONE:
            require_step(rcBuildRegionsMonotone(&ctx, *chf, cfg.borderSize, cfg.minRegionArea, cfg.mergeRegionArea),
                         "rcBuildRegionsMonotone", ctx);
            break;
        case NL_RECAST_PARTITION_LAYERS:
            require_step(rcBuildLayerRegions(&ctx, *chf, cfg.borderSize, cfg.minRegionArea), "rcBuildLayerRegions",
                         ctx);
            break;
        default:
            require_step(rcBuildDistanceField(&ctx, *chf), "rcBuildDistanceField", ctx);
            require_step(rcBuildRegions(&ctx, *chf, cfg.borderSize, cfg.minRegionArea, cfg.mergeRegionArea),
                         "rcBuildRegions", ctx);
            break;
    }

    // Trace and simplify the region outlines.
    report(0.8f, "tracing contours");
    ContourSetPtr cset = require_allocated(rcAllocContourSet(), "contour set");
    require_step(rcBuildContours(&ctx, *chf, cfg.maxSimplificationError, cfg.maxEdgeLen, *cset), "rcBuildContours",
                 ctx);
    if (cset->nconts == 0)
        no_walkable_surface(agent, "every walkable region was eroded by the radius or smaller than region_min_size");

    // Convex polygons, and the detail triangles with the surface's real heights.
    report(0.85f, "building polygons");
    RecastPolygons out;
    out.polygons = require_allocated(rcAllocPolyMesh(), "polygon mesh");
    require_step(rcBuildPolyMesh(&ctx, *cset, cfg.maxVertsPerPoly, *out.polygons), "rcBuildPolyMesh", ctx);
    cset.reset();
    if (out.polygons->npolys == 0)
        no_walkable_surface(agent, "Recast made no polygon from the walkable regions' outlines");
    report(0.9f, "building the detail mesh");
    out.detail = require_allocated(rcAllocPolyMeshDetail(), "detail mesh");
    require_step(
        rcBuildPolyMeshDetail(&ctx, *out.polygons, *chf, cfg.detailSampleDist, cfg.detailSampleMaxError, *out.detail),
        "rcBuildPolyMeshDetail", ctx);
    return out;
}

}  // namespace nl::recast
