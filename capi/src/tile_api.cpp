// The tiles of a tiled navmesh, in and out at run time: mapped onto World::add_tile / remove_tile.
#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "mapping.h"
#include "world.h"

using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;

extern "C" {

NL_API nl_status nl_navmesh_add_tile(nl_world* world, nl_navmesh_id navmesh, const nl_navmesh_def* def) {
    return guarded("nl_navmesh_add_tile", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        nl::naming_fields("def->", [&] { w.add_tile(to_handle(navmesh), nl::capi::navmesh_input_from_def(*def)); });
    });
}

NL_API nl_status nl_navmesh_remove_tile(nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile) {
    return guarded("nl_navmesh_remove_tile", world, [&] {
        deref(world).remove_tile(to_handle(navmesh), nl::TileCoord{tile.x, tile.z});
    });
}

NL_API nl_status nl_navmesh_get_tiles(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord* out_tiles,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("nl_navmesh_get_tiles", world, [&] {
        const auto mesh = deref(world).navmeshes().navmesh(to_handle(navmesh));
        nl::capi::list_into(mesh->tiles().tiles, out_tiles, capacity, out_count, "out_tiles",
                            [](const nl::TileCoord& t) {
                                return nl_tile_coord{t.x, t.z};
                            });
    });
}

}  // extern "C"
