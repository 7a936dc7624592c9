// libFuzzer target: tiles' files through nl_navmesh_file_describe, nl_navmesh_add_tile_bytes (into a
// tiled navmesh missing some of its tiles) and nl_navmesh_load. The checksum is made right before
// unless the input's reserved header byte 31 is odd, as fuzz_navmesh_file does. A tile that is added
// must save again and be removed again, leaving the navmesh with the tiles it had.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_support.h"

namespace {

uint32_t tile_count(nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    if (NL_FAILED(nl_navmesh_get_tiles(world, navmesh, nullptr, 0, &count))) __builtin_trap();
    return count;
}

// The seeds' navmesh with every other tile removed: the seeds of those add, the others are loaded.
nl_navmesh_id fixture(nl_world* world) {
    static const nl_navmesh_id navmesh = [world] {
        nl_navmesh_id id{};
        if (!nl::fuzz::add_tile_fixture(world, id)) std::abort();
        nl_tile_coord tiles[64];
        uint32_t count = 0;
        if (NL_FAILED(nl_navmesh_get_tiles(world, id, tiles, 64, &count))) std::abort();
        for (uint32_t i = 1; i < count; i += 2)
            if (NL_FAILED(nl_navmesh_remove_tile(world, id, tiles[i]))) std::abort();
        return id;
    }();
    return navmesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    const nl_navmesh_id navmesh = fixture(world);
    std::vector<uint8_t> file(data, data + size);
    nl::fuzz::fix_checksum(file);
    nl_navmesh_file_info info;
    std::memset(&info, 0, sizeof info);
    info.size = sizeof info;
    nl_status status = nl_navmesh_file_describe(file.data(), file.size(), &info, nullptr, 0, nullptr);
    nl::fuzz::require_reasoned(status);

    const uint32_t before = tile_count(world, navmesh);
    status = nl_navmesh_add_tile_bytes(world, navmesh, file.data(), file.size());
    nl::fuzz::require_reasoned(status);
    if (NL_SUCCEEDED(status)) {
        if (!info.is_tile || tile_count(world, navmesh) != before + 1) __builtin_trap();
        size_t saved = 0;
        if (NL_FAILED(nl_navmesh_save_tile(world, navmesh, info.tile, nullptr, 0, &saved))) __builtin_trap();
        std::vector<uint8_t> again(saved);
        if (NL_FAILED(nl_navmesh_save_tile(world, navmesh, info.tile, again.data(), again.size(), &saved)))
            __builtin_trap();
        if (NL_FAILED(nl_navmesh_remove_tile(world, navmesh, info.tile))) __builtin_trap();
    }
    if (tile_count(world, navmesh) != before) __builtin_trap();

    nl_navmesh_id loaded{};
    status = nl_navmesh_load(world, file.data(), file.size(), nullptr, &loaded);
    nl::fuzz::require_reasoned(status);
    if (NL_SUCCEEDED(status) && NL_FAILED(nl_navmesh_remove(world, loaded))) __builtin_trap();
    return 0;
}
