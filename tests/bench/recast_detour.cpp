#include "recast_detour.h"

#include <DetourNavMeshBuilder.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "io/obj_reader.h"
#include "navmesh_export.h"

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
