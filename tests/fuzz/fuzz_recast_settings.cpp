// libFuzzer target: the Recast builder's settings JSON through nl_navmesh_build, on a level of an
// 8 m x 8 m floor with a 1 m step on it. Settings whose grid would have more than 100,000 cells are
// only read, not built: such a build is slow by design (Recast allocates the grid whole), and a
// fuzzer that times out on it finds nothing.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "build_failure.h"
#include "fuzz_support.h"
#include "recast_settings.h"

namespace {

constexpr float kLevelSide = 8.0f;
constexpr double kMaxBuiltCells = 100000.0;

void add_level(nl_world* world) {
    // The floor, then a 2 m x 2 m block 1 m high, as 2 + 10 triangles facing out.
    static const float vertices[] = {0, 0, 0, kLevelSide, 0, 0, kLevelSide, 0, kLevelSide, 0, 0, kLevelSide,
                                     3, 0, 3, 5,          0, 3, 5,          0, 5,          3, 0, 5,
                                     3, 1, 3, 5,          1, 3, 5,          1, 5,          3, 1, 5};
    static const uint32_t indices[] = {0, 2, 1,  0, 3,  2, 8, 10, 9,  8, 11, 10, 4, 5, 9, 4, 9, 8,
                                       5, 6, 10, 5, 10, 9, 6, 7,  11, 6, 11, 10, 7, 4, 8, 7, 8, 11};
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = vertices;
    def.vertex_count = sizeof vertices / sizeof(float) / 3;
    def.indices = indices;
    def.triangle_count = sizeof indices / sizeof(uint32_t) / 3;
    nl_mesh_id mesh{};
    if (NL_FAILED(nl_mesh_add(world, &def, &mesh))) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    static const bool level_added = (add_level(world), true);
    (void)level_added;
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.settings_json = reinterpret_cast<const char*>(data);
    def.settings_json_length = size;
    try {
        const nl_recast_settings s = nl::recast::resolve_settings(def);
        if (std::pow(double(kLevelSide) / s.cell_size, 2.0) > kMaxBuiltCells || s.cell_height < 0.01f) return 0;
    } catch (const nl::recast::BuildFailure&) {
        // Refused: the build below refuses it the same way, through the C ABI's checks.
    }
    nl_navmesh_id navmesh{};
    const nl_status status = nl_navmesh_build(world, &def, &navmesh);
    nl::fuzz::require_reasoned(status);
    if (NL_SUCCEEDED(status)) nl_navmesh_remove(world, navmesh);
    return 0;
}
