// libFuzzer target: the link generator's JSON inputs. The first byte chooses which: even, the link
// settings (nl_link_settings_from_json); odd, the link-kind plugins' settings, which
// nl_navmesh_generate_links checks before any work (accepted ones then generate a 2 m x 2 m navmesh).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cell_navmesh.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    nl_world* world = nl::fuzz::shared_world();
    const char* json = reinterpret_cast<const char*>(data + 1);
    nl_link_settings settings = nl_default_link_settings();
    if (data[0] % 2 == 0) {
        nl::fuzz::require_reasoned(nl_link_settings_from_json(json, size - 1, &settings));
        return 0;
    }
    static const nl_navmesh_id navmesh = [&] {
        const nl::test::CellNavmesh cells({"..", ".."}, 0.4f);
        nl_navmesh_id id{};
        if (NL_FAILED(nl_navmesh_add(world, &cells.def, &id))) __builtin_trap();
        return id;
    }();
    settings.plugin_settings_json = json;
    settings.plugin_settings_json_length = size - 1;
    nl::fuzz::require_reasoned(nl_navmesh_generate_links(world, navmesh, &settings, nullptr, nullptr, nullptr));
    return 0;
}
