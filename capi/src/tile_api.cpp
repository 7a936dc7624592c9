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
        const nl_navmesh_def full =
            nl::capi::read_growable(*def, nl_default_navmesh_def(), nl::capi::kFirstSize<nl_navmesh_def>, "def");
        nl::naming_fields("def->", [&] {
            w.add_tile(to_handle(navmesh), nl::capi::navmesh_input_from_def(*def), to_handle(full.carrier));
        });
    });
}

NL_API nl_status nl_navmesh_remove_tile(nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile) {
    return guarded("nl_navmesh_remove_tile", world, [&] {
        deref(world).remove_tile(to_handle(navmesh), nl::TileCoord{tile.x, tile.z});
    });
}

NL_API nl_status nl_navmesh_build_tiles(nl_world* world, nl_navmesh_id navmesh, const nl_navmesh_build_def* def,
                                        const float* box_min, const float* box_max) {
    return guarded("nl_navmesh_build_tiles", world, [&] {
        nl::World& w = deref(world);
        require(def, "def");
        require(box_min, "box_min");
        require(box_max, "box_max");
        nl::Aabb box;
        box.min = nl::capi::read_position(box_min, "box_min");
        box.max = nl::capi::read_position(box_max, "box_max");
        if (box.min.x() > box.max.x() || box.min.z() > box.max.z())
            nl::fail(nl::ErrorCode::InvalidArgument, "box_min is beyond box_max in x or z");
        nl::naming_fields("def->",
                          [&] { w.build_tiles(to_handle(navmesh), nl::capi::build_request_from_def(*def), box); });
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
