// libFuzzer target: baked navmesh files through nl_navmesh_file_describe and nl_navmesh_load. The
// checksum is made right before loading unless the input's reserved header byte 31 is odd, so the
// fuzzer reaches every section's reader and the navmesh build and link placement behind them, and
// the checksum's own refusal too. What loads must save and load again to the same counts (a tile's file
// as a tile's file).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_support.h"

namespace {

nl_navmesh_file_info described(const void* data, size_t size, nl_status& status) {
    nl_navmesh_file_info info;
    std::memset(&info, 0, sizeof info);
    info.size = sizeof info;
    size_t length = 0;
    status = nl_navmesh_file_describe(data, size, &info, nullptr, 0, &length);
    if (NL_SUCCEEDED(status)) {
        std::vector<char> json(length + 1);
        if (NL_FAILED(nl_navmesh_file_describe(data, size, nullptr, json.data(), json.size(), &length)))
            __builtin_trap();
    }
    return info;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    std::vector<uint8_t> file(data, data + size);
    nl::fuzz::fix_checksum(file);
    nl_status status;
    const nl_navmesh_file_info info = described(file.data(), file.size(), status);
    nl::fuzz::require_reasoned(status);

    nl_navmesh_id navmesh{};
    status = nl_navmesh_load(world, file.data(), file.size(), nullptr, &navmesh);
    nl::fuzz::require_reasoned(status);
    if (NL_FAILED(status)) return 0;
    if (NL_FAILED(nl_navmesh_file_describe(file.data(), file.size(), nullptr, nullptr, 0, nullptr))) __builtin_trap();

    // A tile's file loads as a tiled navmesh of that tile and saves as a tile's file again (saved whole,
    // it would be refused for its links to tiles not loaded).
    auto save = [&](void* buffer, size_t capacity, size_t* size) {
        return info.is_tile ? nl_navmesh_save_tile(world, navmesh, info.tile, buffer, capacity, size)
                            : nl_navmesh_save(world, navmesh, buffer, capacity, size);
    };
    size_t saved_size = 0;
    if (NL_FAILED(save(nullptr, 0, &saved_size))) __builtin_trap();
    std::vector<uint8_t> saved(saved_size);
    if (NL_FAILED(save(saved.data(), saved.size(), &saved_size))) __builtin_trap();
    nl_navmesh_id again{};
    if (NL_FAILED(nl_navmesh_load(world, saved.data(), saved.size(), nullptr, &again))) __builtin_trap();
    const nl_navmesh_file_info reread = described(saved.data(), saved.size(), status);
    if (NL_FAILED(status) || reread.link_count != info.link_count || reread.polygon_count > info.polygon_count)
        __builtin_trap();
    if (NL_FAILED(nl_navmesh_remove(world, navmesh)) || NL_FAILED(nl_navmesh_remove(world, again))) __builtin_trap();
    return 0;
}
