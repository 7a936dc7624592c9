#include "recast_detour.h"

#include <DetourNavMeshBuilder.h>

#include <Recast.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/obj_reader.h"
#include "navmesh_export.h"
#include "recast_memory.h"
#include "recast_pipeline.h"

namespace nl::bench {

RecastLevel build_recast_level(const std::string& name, const std::vector<float>& vertices,
                               const std::vector<uint32_t>& indices, float radius, float cell_size) {
    nl::recast::LevelTriangles triangles;
    triangles.vertices = vertices;
    triangles.indices = indices;
    triangles.areas.assign(indices.size() / 3, 0);
    const nl_plugin_host no_host{};  // size 0: Recast's log goes nowhere, nobody asks for progress
    nl::recast::HostLogContext context(no_host);
    RecastLevel level;
    level.name = name;
    if (radius > 0.0f) level.agent.radius = radius;
    if (cell_size > 0.0f) level.settings.cell_size = cell_size;
    level.solo = nl::recast::build_solo_mesh(context, triangles, level.settings, level.agent,
                                             nl::recast::BuildProgress(no_host));
    return level;
}

RecastLevel build_recast_level_from_obj(const char* path) {
    const nl::TriangleMesh mesh = nl::read_obj_file(path);
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    for (const nl::Vec3& v : mesh.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    for (const nl::Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    return build_recast_level(std::filesystem::path(path).stem().string(), vertices, indices);
}

dtPolyRef DetourMesh::ref(uint32_t index) const {
    return mesh->getPolyRefBase(static_cast<const dtNavMesh*>(mesh)->getTile(0)) | index;
}

bool build_detour(RecastLevel& level, DetourMesh& out) {
    rcPolyMesh& pm = *level.solo.polygons;
    const rcPolyMeshDetail& dm = *level.solo.detail;
    for (int i = 0; i < pm.npolys; ++i) pm.flags[i] = 1;
    dtNavMeshCreateParams params{};
    params.verts = pm.verts;
    params.vertCount = pm.nverts;
    params.polys = pm.polys;
    params.polyAreas = pm.areas;
    params.polyFlags = pm.flags;
    params.polyCount = pm.npolys;
    params.nvp = pm.nvp;
    params.detailMeshes = dm.meshes;
    params.detailVerts = dm.verts;
    params.detailVertsCount = dm.nverts;
    params.detailTris = dm.tris;
    params.detailTriCount = dm.ntris;
    params.walkableHeight = level.agent.height;
    params.walkableRadius = level.agent.radius;
    params.walkableClimb = level.agent.max_climb;
    rcVcopy(params.bmin, pm.bmin);
    rcVcopy(params.bmax, pm.bmax);
    params.cs = level.settings.cell_size;
    params.ch = level.settings.cell_height;
    params.buildBvTree = true;
    unsigned char* data = nullptr;
    if (!dtCreateNavMeshData(&params, &data, &out.bytes)) return false;
    if (dtStatusFailed(out.mesh->init(data, out.bytes, DT_TILE_FREE_DATA))) {
        dtFree(data);
        return false;
    }
    return dtStatusSucceed(out.query->init(out.mesh, 2048));  // RecastDemo's node pool
}

bool add_navlink_navmesh(nl_world* world, const RecastLevel& level, nl_navmesh_id* out_navmesh,
                         uint32_t* out_polygons) {
    const nl::recast::NavMeshExport exported(*level.solo.polygons, *level.solo.detail);
    const nl_navmesh_def def = exported.def(level.agent);
    if (NL_FAILED(nl_navmesh_add(world, &def, out_navmesh))) {
        std::fprintf(stderr, "%s: nl_navmesh_add: %s\n", level.name.c_str(), nl_get_last_error_message());
        return false;
    }
    *out_polygons = exported.polygon_count();
    if (*out_polygons != uint32_t(level.solo.polygons->npolys)) {
        std::fprintf(stderr, "%s: NavLink kept %u polygons of Recast's %d\n", level.name.c_str(), *out_polygons,
                     level.solo.polygons->npolys);
        return false;
    }
    return true;
}

TiledLevel plan_tiled_level(const std::string& name, const std::vector<float>& vertices,
                            const std::vector<uint32_t>& indices, const nl_recast_settings& settings,
                            const nl_agent_type& agent) {
    TiledLevel level;
    level.name = name;
    level.settings = settings;
    level.agent = agent;
    level.vertices = vertices;
    level.indices.assign(indices.begin(), indices.end());
    // The bounds of the vertices the triangles use (NavLink's builder sees those alone).
    for (int axis = 0; axis < 3; ++axis) level.bmin[axis] = INFINITY, level.bmax[axis] = -INFINITY;
    for (const uint32_t i : indices)
        for (int axis = 0; axis < 3; ++axis) {
            level.bmin[axis] = std::min(level.bmin[axis], vertices[3 * size_t(i) + axis]);
            level.bmax[axis] = std::max(level.bmax[axis], vertices[3 * size_t(i) + axis]);
        }
    level.origin_x = level.bmin[0];
    level.origin_z = level.bmin[2];
    level.tile_width = double(settings.tile_size) * settings.cell_size;
    const int radius_cells = int(std::ceil(double(agent.radius) / settings.cell_size));
    level.border = settings.tile_border ? int(settings.tile_border) : radius_cells + 3;
    level.tiles_x = int(std::max(1.0, std::ceil((double(level.bmax[0]) - level.bmin[0]) / level.tile_width)));
    level.tiles_z = int(std::max(1.0, std::ceil((double(level.bmax[2]) - level.bmin[2]) / level.tile_width)));
    return level;
}

void bin_triangles(TiledLevel& level) {
    const double pad = double(level.border) * level.settings.cell_size;
    auto range = [&](float lo, float hi, double origin, int tiles, int& a, int& b) {
        a = int(std::clamp(std::floor((double(lo) - origin - pad) / level.tile_width), 0.0, double(tiles)));
        b = int(std::clamp(std::floor((double(hi) - origin + pad) / level.tile_width), -1.0, double(tiles - 1)));
    };
    const size_t triangles = level.indices.size() / 3;
    std::vector<int> boxes(4 * triangles);  // x0 x1 z0 z1 per triangle: counted, then filled
    level.first.assign(size_t(level.tile_count()) + 1, 0);
    for (size_t t = 0; t < triangles; ++t) {
        float lo_x = INFINITY, hi_x = -INFINITY, lo_z = INFINITY, hi_z = -INFINITY;
        for (int k = 0; k < 3; ++k) {
            const float* v = &level.vertices[3 * size_t(level.indices[3 * t + k])];
            lo_x = std::min(lo_x, v[0]), hi_x = std::max(hi_x, v[0]);
            lo_z = std::min(lo_z, v[2]), hi_z = std::max(hi_z, v[2]);
        }
        int* box = &boxes[4 * t];
        range(lo_x, hi_x, level.origin_x, level.tiles_x, box[0], box[1]);
        range(lo_z, hi_z, level.origin_z, level.tiles_z, box[2], box[3]);
        for (int z = box[2]; z <= box[3]; ++z)
            for (int x = box[0]; x <= box[1]; ++x) ++level.first[size_t(z) * level.tiles_x + x + 1];
    }
    for (size_t t = 1; t < level.first.size(); ++t) level.first[t] += level.first[t - 1];
    level.triangles.resize(3 * level.first.back());
    std::vector<size_t> next(level.first.begin(), level.first.end() - 1);
    for (size_t t = 0; t < triangles; ++t) {
        const int* box = &boxes[4 * t];
        for (int z = box[2]; z <= box[3]; ++z)
            for (int x = box[0]; x <= box[1]; ++x) {
                int* to = &level.triangles[3 * next[size_t(z) * level.tiles_x + x]++];
                std::copy_n(&level.indices[3 * t], 3, to);
            }
    }
}

namespace {

void require_recast(bool ok, const char* step) {
    if (!ok) throw std::runtime_error(std::string("Recast step ") + step + " failed");
}

}  // namespace

DetourTile build_detour_tile(const TiledLevel& level, int x, int z) {
    DetourTile out;
    out.x = x;
    out.z = z;
    const size_t tile = size_t(z) * level.tiles_x + x;
    const size_t first = level.first[tile];
    const int count = int(level.first[tile + 1] - first);
    if (count == 0) return out;
    const nl_recast_settings& s = level.settings;
    const int size = int(s.tile_size);
    const double pad = double(level.border) * s.cell_size;
    const float lo[3] = {float(level.origin_x + x * level.tile_width - pad), level.bmin[1],
                         float(level.origin_z + z * level.tile_width - pad)};
    const float hi[3] = {float(level.origin_x + (x + 1) * level.tile_width + pad), level.bmax[1],
                         float(level.origin_z + (z + 1) * level.tile_width + pad)};
    rcConfig cfg = nl::recast::make_config(s, level.agent, lo, hi);
    cfg.tileSize = size;
    cfg.borderSize = level.border;
    cfg.width = cfg.height = size + 2 * level.border;
    rcContext ctx(false);

    // Voxelise the tile's triangles, those steep enough not walkable.
    const float* verts = level.vertices.data();
    const int nverts = int(level.vertices.size() / 3);
    const int* tris = &level.triangles[3 * first];
    nl::recast::HeightfieldPtr solid(rcAllocHeightfield());
    require_recast(
        solid && rcCreateHeightfield(&ctx, *solid, cfg.width, cfg.height, cfg.bmin, cfg.bmax, cfg.cs, cfg.ch),
        "rcCreateHeightfield");
    std::vector<unsigned char> areas(size_t(count), RC_NULL_AREA);
    rcMarkWalkableTriangles(&ctx, cfg.walkableSlopeAngle, verts, nverts, tris, count, areas.data());
    require_recast(rcRasterizeTriangles(&ctx, verts, nverts, tris, areas.data(), count, *solid, cfg.walkableClimb),
                   "rcRasterizeTriangles");
    if (s.filter_low_hanging_obstacles) rcFilterLowHangingWalkableObstacles(&ctx, cfg.walkableClimb, *solid);
    if (s.filter_ledge_spans) rcFilterLedgeSpans(&ctx, cfg.walkableHeight, cfg.walkableClimb, *solid);
    if (s.filter_walkable_low_height_spans) rcFilterWalkableLowHeightSpans(&ctx, cfg.walkableHeight, *solid);

    // Compact, erode by the radius, partition (the border cells are the neighbours').
    nl::recast::CompactHeightfieldPtr chf(rcAllocCompactHeightfield());
    require_recast(chf && rcBuildCompactHeightfield(&ctx, cfg.walkableHeight, cfg.walkableClimb, *solid, *chf),
                   "rcBuildCompactHeightfield");
    solid.reset();
    require_recast(rcErodeWalkableArea(&ctx, cfg.walkableRadius, *chf), "rcErodeWalkableArea");
    if (s.partition == NL_RECAST_PARTITION_MONOTONE) {
        require_recast(rcBuildRegionsMonotone(&ctx, *chf, cfg.borderSize, cfg.minRegionArea, cfg.mergeRegionArea),
                       "rcBuildRegionsMonotone");
    } else if (s.partition == NL_RECAST_PARTITION_LAYERS) {
        require_recast(rcBuildLayerRegions(&ctx, *chf, cfg.borderSize, cfg.minRegionArea), "rcBuildLayerRegions");
    } else {
        require_recast(rcBuildDistanceField(&ctx, *chf), "rcBuildDistanceField");
        require_recast(rcBuildRegions(&ctx, *chf, cfg.borderSize, cfg.minRegionArea, cfg.mergeRegionArea),
                       "rcBuildRegions");
    }

    // Contours, polygons, detail.
    nl::recast::ContourSetPtr cset(rcAllocContourSet());
    require_recast(cset && rcBuildContours(&ctx, *chf, cfg.maxSimplificationError, cfg.maxEdgeLen, *cset),
                   "rcBuildContours");
    if (cset->nconts == 0) return out;
    nl::recast::PolyMeshPtr pm(rcAllocPolyMesh());
    require_recast(pm && rcBuildPolyMesh(&ctx, *cset, cfg.maxVertsPerPoly, *pm), "rcBuildPolyMesh");
    cset.reset();
    if (pm->npolys == 0) return out;
    nl::recast::PolyMeshDetailPtr dm(rcAllocPolyMeshDetail());
    require_recast(dm && rcBuildPolyMeshDetail(&ctx, *pm, *chf, cfg.detailSampleDist, cfg.detailSampleMaxError, *dm),
                   "rcBuildPolyMeshDetail");
    chf.reset();
    if (pm->nverts >= 0xffff) throw std::runtime_error("a tile has more than 65,535 vertices");

    for (int i = 0; i < pm->npolys; ++i) pm->flags[i] = 1;
    dtNavMeshCreateParams params{};
    params.verts = pm->verts;
    params.vertCount = pm->nverts;
    params.polys = pm->polys;
    params.polyAreas = pm->areas;
    params.polyFlags = pm->flags;
    params.polyCount = pm->npolys;
    params.nvp = pm->nvp;
    params.detailMeshes = dm->meshes;
    params.detailVerts = dm->verts;
    params.detailVertsCount = dm->nverts;
    params.detailTris = dm->tris;
    params.detailTriCount = dm->ntris;
    params.walkableHeight = level.agent.height;
    params.walkableRadius = level.agent.radius;
    params.walkableClimb = level.agent.max_climb;
    params.tileX = x;
    params.tileY = z;
    params.tileLayer = 0;
    rcVcopy(params.bmin, pm->bmin);
    rcVcopy(params.bmax, pm->bmax);
    params.cs = cfg.cs;
    params.ch = cfg.ch;
    params.buildBvTree = true;
    if (!dtCreateNavMeshData(&params, &out.data, &out.bytes)) throw std::runtime_error("dtCreateNavMeshData failed");
    out.polygons = pm->npolys;
    return out;
}

DetourTiles::~DetourTiles() {
    for (DetourTile& tile : tiles) dtFree(tile.data);
}

size_t DetourTiles::data_bytes() const {
    size_t bytes = 0;
    for (const DetourTile& tile : tiles) bytes += size_t(tile.bytes);
    return bytes;
}

int DetourTiles::polygon_count() const {
    int polygons = 0;
    for (const DetourTile& tile : tiles) polygons += tile.polygons;
    return polygons;
}

namespace {

// Bits to tell apart n things (0 for one).
int bits_for(long long n) {
    int bits = 0;
    while ((1LL << bits) < n) ++bits;
    return bits;
}

}  // namespace

bool build_detour_tiles(const TiledLevel& level, DetourTiles& out, int max_nodes) {
    int most_polygons = 1;
    for (int z = 0; z < level.tiles_z; ++z)
        for (int x = 0; x < level.tiles_x; ++x) {
            const DetourTile tile = build_detour_tile(level, x, z);
            if (!tile.data) continue;
            out.tiles.push_back(tile);
            most_polygons = std::max(most_polygons, tile.polygons);
        }
    if (out.tiles.empty()) {
        std::fprintf(stderr, "%s: no tile has a walkable surface\n", level.name.c_str());
        return false;
    }
    // Debian's Detour has 32-bit refs: tile, polygon and at least 10 salt bits.
    out.tile_bits = bits_for(level.tile_count());
    const int poly_bits = bits_for(most_polygons);
    if (out.tile_bits + poly_bits > 22) {
        std::fprintf(stderr,
                     "%s: %d tiles of up to %d polygons need %d + %d ref bits; 32-bit Detour refs have 22 (raise "
                     "--tile-size)\n",
                     level.name.c_str(), level.tile_count(), most_polygons, out.tile_bits, poly_bits);
        return false;
    }
    out.poly_bits = 22 - out.tile_bits;
    dtNavMeshParams params{};
    params.orig[0] = float(level.origin_x);
    params.orig[1] = level.bmin[1];
    params.orig[2] = float(level.origin_z);
    params.tileWidth = params.tileHeight = float(level.tile_width);
    params.maxTiles = 1 << out.tile_bits;
    params.maxPolys = 1 << out.poly_bits;
    if (dtStatusFailed(out.navmesh.mesh->init(&params))) {
        std::fprintf(stderr, "%s: dtNavMesh::init failed\n", level.name.c_str());
        return false;
    }
    for (const DetourTile& tile : out.tiles)
        if (dtStatusFailed(out.navmesh.mesh->addTile(tile.data, tile.bytes, 0, 0, nullptr))) {
            std::fprintf(stderr, "%s: Detour refused tile (%d, %d)\n", level.name.c_str(), tile.x, tile.z);
            return false;
        }
    out.navmesh.bytes = int(std::min<size_t>(out.data_bytes(), 0x7fffffff));
    return dtStatusSucceed(out.navmesh.query->init(out.navmesh.mesh, max_nodes));
}

void random_point_in_detour_polygon(const dtMeshTile& tile, int polygon, std::mt19937& rng, float out[3]) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const dtPoly& poly = tile.polys[polygon];
    std::uniform_int_distribution<int> fan(1, poly.vertCount - 2);
    const int k = fan(rng);
    float u = unit(rng), v = unit(rng);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    const float* a = &tile.verts[3 * poly.verts[0]];
    const float* b = &tile.verts[3 * poly.verts[k]];
    const float* c = &tile.verts[3 * poly.verts[k + 1]];
    for (int axis = 0; axis < 3; ++axis) out[axis] = (1.0f - u - v) * a[axis] + u * b[axis] + v * c[axis];
    out[1] += 0.5f;
}

void random_point_in_polygon(const rcPolyMesh& pm, int polygon, std::mt19937& rng, float out[3]) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const unsigned short* poly = &pm.polys[size_t(polygon) * 2 * pm.nvp];
    int n = 0;
    while (n < pm.nvp && poly[n] != RC_MESH_NULL_IDX) ++n;
    std::uniform_int_distribution<int> fan(1, n - 2);
    const int k = fan(rng);
    float u = unit(rng), v = unit(rng);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    const unsigned short* a = &pm.verts[3 * poly[0]];
    const unsigned short* b = &pm.verts[3 * poly[k]];
    const unsigned short* c = &pm.verts[3 * poly[k + 1]];
    for (int axis = 0; axis < 3; ++axis) {
        const float cell = axis == 1 ? pm.ch : pm.cs;
        const float w = (1.0f - u - v) * a[axis] + u * b[axis] + v * c[axis];
        out[axis] = pm.bmin[axis] + w * cell;
    }
    out[1] += 0.5f;
}

void random_point(const rcPolyMesh& pm, std::mt19937& rng, float out[3]) {
    std::uniform_int_distribution<int> pick(0, pm.npolys - 1);
    random_point_in_polygon(pm, pick(rng), rng, out);
}

std::vector<int> largest_connected_polygons(const rcPolyMesh& pm) {
    std::vector<int> part(pm.npolys, -1);
    std::vector<int> sizes, stack;
    for (int seed = 0; seed < pm.npolys; ++seed) {
        if (part[seed] >= 0) continue;
        const int id = int(sizes.size());
        sizes.push_back(0);
        part[seed] = id;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            ++sizes[id];
            const unsigned short* poly = &pm.polys[size_t(p) * 2 * pm.nvp];
            for (int j = 0; j < pm.nvp && poly[j] != RC_MESH_NULL_IDX; ++j) {
                const unsigned short next = poly[pm.nvp + j];
                if (next == RC_MESH_NULL_IDX || (next & 0x8000) || part[next] >= 0)
                    continue;  // no neighbour, or a tile portal
                part[next] = id;
                stack.push_back(next);
            }
        }
    }
    const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    std::vector<int> out;
    for (int p = 0; p < pm.npolys; ++p)
        if (part[p] == largest) out.push_back(p);
    return out;
}

}  // namespace nl::bench
