// Registers a procedural level through the C ABI, as a host would: shared by tests that drive
// nl_* functions.
#pragma once

#include <navlink/navlink.h>

#include "level_generator.h"

namespace nl::test {

// Returns the status of nl_mesh_add; `out_id` (optional) receives the mesh.
inline nl_status add_generated_level(nl_world* world, const nl::levelgen::GeneratedLevel& level, uint32_t flags = 0,
                                     const float* transform = nullptr, nl_mesh_id* out_id = nullptr) {
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = level.positions.data();
    def.vertex_count = level.vertex_count();
    def.indices = level.indices.data();
    def.triangle_count = level.triangle_count();
    def.flags = flags;
    def.transform = transform;
    nl_mesh_id id{};
    const nl_status status = nl_mesh_add(world, &def, &id);
    if (out_id) *out_id = id;
    return status;
}

}  // namespace nl::test
