// What every fuzz target shares: one world per process, and the rule every refusal must keep.
#pragma once

#include <navlink/navlink.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <zlib.h>

namespace nl::fuzz {

// One world for the whole run, with one worker: inputs run one after the other and nothing depends
// on thread timing, so a crash replays from its input alone.
inline nl_world* shared_world() {
    static nl_world* const world = [] {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        nl_world* created = nullptr;
        if (NL_FAILED(nl_world_create(&def, &created))) std::abort();
        return created;
    }();
    return world;
}

// Bad input is refused as bad input: a failure always says why, and never with INTERNAL_ERROR,
// which the library keeps for its own bugs. Traps otherwise, so libFuzzer saves the input.
inline void require_reasoned(nl_status status) {
    if (NL_SUCCEEDED(status)) return;
    if ((status & NL_STATUS_INTERNAL_ERROR) != 0 || std::strlen(nl_get_last_error_message()) == 0) __builtin_trap();
}

// Makes the checksum of a navmesh file's contents right, unless the input's reserved header byte 31 is
// odd: so a fuzzer reaches every section's reader behind the checksum, and the checksum's own refusal.
inline void fix_checksum(std::vector<uint8_t>& file) {
    constexpr size_t kHeaderBytes = 32;
    if (file.size() < kHeaderBytes || (file[31] & 1u)) return;
    const uLong crc = crc32_z(crc32_z(0L, Z_NULL, 0), file.data() + kHeaderBytes, file.size() - kHeaderBytes);
    for (int i = 0; i < 4; ++i) file[24 + i] = static_cast<uint8_t>(crc >> (8 * i));
}

// Two 4 m pads 1 m apart (a gap to jump) in the world's level. False on a failure.
inline bool add_two_pads(nl_world* world) {
    bool ok = true;
    for (float x0 : {0.0f, 5.0f}) {
        const float x1 = x0 + 4.0f;
        const float v[] = {x0, 0, 0, x0, 0, 4, x1, 0, 4, x1, 0, 0};
        const uint32_t quad[] = {0, 1, 2, 0, 2, 3};
        nl_mesh_def mesh = nl_default_mesh_def();
        mesh.vertices = v;
        mesh.vertex_count = 4;
        mesh.indices = quad;
        mesh.triangle_count = 2;
        nl_mesh_id id{};
        ok = ok && NL_SUCCEEDED(nl_mesh_add(world, &mesh, &id));
    }
    return ok;
}

// The two pads and a navmesh of them in tiles of 16 cells of 0.25 m (4 m) with their links: the
// tile_file target's navmesh and its seeds' source. False on a failure.
inline bool add_tile_fixture(nl_world* world, nl_navmesh_id& navmesh) {
    bool ok = add_two_pads(world);
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.settings_json = R"({"cell_size": 0.25, "tile_size": 16})";
    build.settings_json_length = std::strlen(build.settings_json);
    ok = ok && NL_SUCCEEDED(nl_navmesh_build(world, &build, &navmesh));
    const nl_link_settings settings = nl_default_link_settings();
    return ok && NL_SUCCEEDED(nl_navmesh_generate_links(world, navmesh, &settings, nullptr, nullptr, nullptr));
}

}  // namespace nl::fuzz
