// libFuzzer target: links JSON through nl_navmesh_load_links_json, on an 8 m x 8 m navmesh. What
// loads must save and load again: a file the library writes is one it reads.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cell_navmesh.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    static const nl_navmesh_id navmesh = [&] {
        const nl::test::CellNavmesh cells(std::vector<std::string>(8, "........"), 0.4f);
        nl_navmesh_id id{};
        if (NL_FAILED(nl_navmesh_add(world, &cells.def, &id))) __builtin_trap();
        return id;
    }();
    uint32_t count = 0;
    const nl_status status =
        nl_navmesh_load_links_json(world, navmesh, reinterpret_cast<const char*>(data), size, 0, &count);
    nl::fuzz::require_reasoned(status);
    if (NL_FAILED(status)) return 0;

    size_t length = 0;
    if (NL_FAILED(nl_navmesh_save_links_json(world, navmesh, nullptr, 0, &length))) __builtin_trap();
    std::string saved(length + 1, '\0');
    if (NL_FAILED(nl_navmesh_save_links_json(world, navmesh, saved.data(), saved.size(), &length))) __builtin_trap();
    uint32_t reloaded = 0;
    if (NL_FAILED(nl_navmesh_load_links_json(world, navmesh, saved.data(), length, 0, &reloaded)) || reloaded != count)
        __builtin_trap();
    return 0;
}
