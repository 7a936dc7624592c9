// libFuzzer target: a host navmesh through nl_navmesh_add, decoded from the bytes (navmesh_bytes.h).
// A navmesh that is accepted must locate points as the brute-force search does: near its first
// vertices, with small, medium and huge search boxes.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "host_input.h"
#include "navmesh_bytes.h"
#include "world.h"

namespace {

void check_point_location(const nl::NavMesh& mesh) {
    const nl::Vec3 boxes[] = {nl::Vec3(0.5f, 1.0f, 0.5f), nl::Vec3(2.0f, 4.0f, 2.0f), nl::Vec3(1e4f, 1e4f, 1e4f)};
    for (uint32_t v = 0; v < mesh.vertex_count() && v < 16; ++v) {
        const nl::Vec3 point = mesh.vertex(v) + nl::Vec3(0.25f, 0.5f, -0.25f);
        // The huge box visits every polygon: once is enough.
        for (size_t b = 0; b < (v == 0 ? 3 : 2); ++b) {
            const nl::NavPoint fast = mesh.find_nearest(point, boxes[b]), slow = mesh.find_nearest_brute_force(point, boxes[b]);
            if (fast.found != slow.found || fast.polygon != slow.polygon || !(fast.point == slow.point)) __builtin_trap();
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    const nl::fuzz::NavmeshBytes input(data, size);
    nl_navmesh_id navmesh{};
    const nl_status status = nl_navmesh_add(world, &input.def, &navmesh);
    nl::fuzz::require_reasoned(status);
    if (NL_FAILED(status)) return 0;
    check_point_location(*world->core->navmeshes().navmesh(nl::capi::to_handle(navmesh)));
    nl_navmesh_remove(world, navmesh);
    return 0;
}
