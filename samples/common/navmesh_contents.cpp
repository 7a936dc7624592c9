#include "navmesh_contents.h"

#include "sample_error.h"

namespace nl::samples {

std::vector<nl_link> read_links(const nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    check(nl_navmesh_get_links(world, navmesh, nullptr, 0, &count), "listing the links");
    std::vector<nl_link> links(count, nl_link_init());
    check(nl_navmesh_get_links(world, navmesh, links.data(), count, &count), "listing the links");
    links.resize(count, nl_link_init());
    return links;
}

std::vector<nl_tile_coord> read_tiles(const nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    check(nl_navmesh_get_tiles(world, navmesh, nullptr, 0, &count), "listing the tiles");
    std::vector<nl_tile_coord> tiles(count);
    check(nl_navmesh_get_tiles(world, navmesh, tiles.data(), count, &count), "listing the tiles");
    tiles.resize(count);
    return tiles;
}

NavmeshContents read_navmesh_contents(const nl_world* world, nl_navmesh_id navmesh) {
    NavmeshContents out;
    uint32_t count = 0;
    check(nl_navmesh_get_vertices(world, navmesh, nullptr, 0, &count), "reading the navmesh");
    out.vertices.resize(size_t(count) * 3);
    check(nl_navmesh_get_vertices(world, navmesh, out.vertices.data(), count, &count), "reading the navmesh");

    nl_navmesh_info info{};
    info.size = sizeof info;
    check(nl_navmesh_get_info(world, navmesh, &info), "reading the navmesh");
    out.polygons.resize(info.polygon_count, nl_nav_polygon_init());
    for (uint32_t p = 0; p < info.polygon_count; ++p)
        check(nl_navmesh_get_polygon(world, navmesh, p, &out.polygons[p]), "reading the navmesh");

    check(nl_navmesh_get_boundary_edges(world, navmesh, nullptr, 0, &count), "reading the navmesh outline");
    out.boundary_edges.resize(count);
    check(nl_navmesh_get_boundary_edges(world, navmesh, out.boundary_edges.data(), count, &count),
          "reading the navmesh outline");
    out.links = read_links(world, navmesh);
    if (info.tile_width > 0.0f) {
        out.tile_width = info.tile_width;
        out.tile_origin[0] = info.tile_origin[0];
        out.tile_origin[1] = info.tile_origin[1];
        out.tiles = read_tiles(world, navmesh);
    }
    return out;
}

}  // namespace nl::samples
