// World's baked tiles: a tile and the links it owns to a tile's file and back, and the content hash
// that says what it was made from (a bake skips a tile whose hash it holds).
#include <cmath>

#include "io/link_json.h"
#include "io/navmesh_file.h"
#include "level/level_hash.h"
#include "links/link_placement.h"
#include "links/tile_links.h"
#include "world/world.h"

namespace nl {

uint64_t World::tile_content_hash(Handle navmesh, TileCoord coord) const {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    const TileGrid& grid = mesh->tiles().grid;
    if (!grid.tiled()) fail(ErrorCode::InvalidArgument, "the navmesh is not tiled");
    if (std::fabs(double(coord.x)) > kMaxTileIndex || std::fabs(double(coord.z)) > kMaxTileIndex)
        fail(ErrorCode::InvalidArgument, "tile (", coord.x, ", ", coord.z,
             ") is beyond the grid's tiles (indices within 2^30 either way)");
    const NavMeshProvenance made_for = navmeshes_.made_for(navmesh);
    LinkSettings links;
    if (!made_for.links.settings.empty()) apply_settings_json(made_for.links.settings, links);
    // The tile's links see the tiles within link reach of it; each of those was built from the
    // triangles within its border, which is never wider than a tile.
    const double reach =
        (made_for.links.settings.empty() ? 0.0 : double(tile_link_reach(links))) + 2.0 * double(grid.tile_width);
    const Columns columns{grid.line_x(coord.x) - reach, grid.line_z(coord.z) - reach,
                          grid.line_x(int64_t(coord.x) + 1) + reach, grid.line_z(int64_t(coord.z) + 1) + reach};
    Aabb level_bounds;
    const uint64_t triangles = level_hash(level_->triangles_to_build_in_columns(Handle{}, columns, level_bounds));
    Fnv1a64 h;
    h.word(static_cast<uint32_t>(triangles >> 32));
    h.word(static_cast<uint32_t>(triangles));
    for (const std::string& text :
         {made_for.builder, made_for.builder_settings, made_for.links.settings, made_for.links.plugins})
        h.text(text);
    const AgentType& body = mesh->agent();
    for (float v :
         {body.radius, body.height, body.max_climb, body.max_slope, grid.origin_x, grid.origin_z, grid.tile_width})
        h.number(v);
    h.word(static_cast<uint32_t>(coord.x));
    h.word(static_cast<uint32_t>(coord.z));
    return h.value();
}

std::vector<uint8_t> World::save_tile(Handle navmesh, TileCoord coord) const {
    const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
    if (!mesh->tiles().grid.tiled())
        fail(ErrorCode::InvalidArgument, "the navmesh is not tiled: save it whole (nl_navmesh_save)");
    if (navmeshes_.frame(navmesh))
        fail(ErrorCode::InvalidArgument,
             "the navmesh rides a moving mesh: its tiles are not baked one by one (save it whole)");
    const NavMeshRegistry::SavedTile saved = navmeshes_.saved_tile(navmesh, coord);
    return write_tile_file(*saved.tile, saved.links, saved.made_for, tile_content_hash(navmesh, coord));
}

void World::add_tile_file(Handle navmesh, const NavMeshFile& file) {
    if (!file.is_tile)
        fail(ErrorCode::InvalidArgument, "the file holds a whole navmesh, not a tile (load it as a navmesh)");
    {
        const std::shared_ptr<const NavMesh> mesh = navmeshes_.navmesh(navmesh);
        if (!mesh->tiles().grid.tiled())
            fail(ErrorCode::InvalidArgument, "the navmesh is not tiled: a tile's file is added to a tiled one");
    }
    const NavMeshProvenance ours = navmeshes_.made_for(navmesh);
    const NavMeshProvenance& theirs = file.made_for;
    if (ours.builder != theirs.builder || ours.builder_settings != theirs.builder_settings ||
        ours.links.settings != theirs.links.settings || ours.links.plugins != theirs.links.plugins)
        fail(ErrorCode::InvalidArgument, "the tile was made with ",
             ours.builder != theirs.builder                     ? "another builder"
             : ours.builder_settings != theirs.builder_settings ? "other builder settings"
                                                                : "other link settings",
             " than the navmesh's tiles: bake them together");
    try {
        // Its own polygons and the links within it checked first; a link to another tile waits, parked,
        // for that tile.
        const std::shared_ptr<const NavMesh> alone = nl::build_navmesh(file.navmesh);
        const TileCoord at = file.navmesh.tiles.tiles.front();
        std::vector<Link> links = file.links;
        for (size_t i = 0; i < links.size(); ++i) {  // each starts on the file's tile (read_navmesh_file)
            if (links[i].end_tile == at)
                naming_fields(concat("links[", i, "].").c_str(), [&] { place_saved_link(*alone, links[i]); });
        }
        const TileLinks given{{at}, std::move(links)};
        insert_tile(navmesh, file.navmesh, &given);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidArgument) throw;
        // A refusal about a tile def's field (add_tile's words) is about the file's tile here.
        std::string why = e.what();
        if (e.starts_with_field() && why.find(": ") != std::string::npos) why = why.substr(why.find(": ") + 2);
        throw Error(e.code(), concat("the file's tile: ", why));
    }
}

}  // namespace nl
