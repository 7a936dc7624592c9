// Baked navmesh files through the C ABI: nl_navmesh_save / _file, nl_navmesh_load / _file and
// nl_navmesh_file_describe over io/navmesh_file.
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "io/file_bytes.h"
#include "io/navmesh_file.h"
#include "level/level_hash.h"
#include "mapping.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::require;
using nl::capi::to_handle;

namespace {

constexpr uint32_t kKnownLoadFlags = NL_NAVMESH_LOAD_SAME_LEVEL;

std::vector<uint8_t> saved_file(const nl::World& w, nl_navmesh_id navmesh) {
    const nl::NavMeshRegistry::Saved saved = w.navmeshes().saved(to_handle(navmesh));
    std::vector<nl::Link> links;
    for (const nl::StoredLink& l : *saved.links) {
        // The file holds the navmesh as it is now: a link off its loaded tiles would not load back.
        if (l.link.start_polygon == nl::kNoPolygon || l.link.end_polygon == nl::kNoPolygon)
            fail(ErrorCode::InvalidArgument, "link {", l.id.index1 & nl::kHandleSlotMask, ", ", l.id.revision,
                 "} has an end on a tile that is not loaded: save with every tile its links reach loaded (or "
                 "remove the link)");
        links.push_back(l.link);
    }
    return nl::write_navmesh_file(*saved.navmesh, links, saved.made_for, saved.rides_carrier);
}

nl::NavMeshFile read_file(const void* data, size_t size) {
    if (size > 0) require(data, "data");
    return nl::read_navmesh_file(static_cast<const uint8_t*>(data), size);
}

nl_navmesh_id load(nl::World& w, const nl::NavMeshFile& file, const nl_navmesh_load_def* given) {
    const nl_navmesh_load_def def = given ? nl::capi::read_growable(*given, nl_default_navmesh_load_def(),
                                                                    nl::capi::kFirstSize<nl_navmesh_load_def>, "def")
                                          : nl_default_navmesh_load_def();
    if (def.flags & ~kKnownLoadFlags)
        fail(ErrorCode::InvalidArgument, "def->flags has unknown bits 0x", std::hex, def.flags & ~kKnownLoadFlags);
    const nl::Handle carrier = nl::capi::to_handle(def.carrier);
    if ((def.flags & NL_NAVMESH_LOAD_SAME_LEVEL) && file.made_for.level_hash != 0) {
        const uint64_t now = nl::level_hash(w.level().triangles_to_build(carrier));
        if (now != file.made_for.level_hash)
            fail(ErrorCode::InvalidArgument, "the level is not the one the file was baked from (its hash is ", std::hex,
                 now, ", the file's ", file.made_for.level_hash,
                 "): bake it again, or load it without NL_NAVMESH_LOAD_SAME_LEVEL");
    }
    return nl::capi::to_id<nl_navmesh_id>(nl::naming_fields("def->", [&] { return w.load_navmesh(file, carrier); }));
}

}  // namespace

extern "C" {

NL_API nl_status nl_navmesh_save(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity,
                                 size_t* out_size) {
    return guarded("nl_navmesh_save", world, [&] {
        const nl::World& w = deref(world);
        require(out_size, "out_size");
        if (!buffer && capacity > 0) fail(ErrorCode::InvalidArgument, "buffer is null but capacity is ", capacity);
        const std::vector<uint8_t> file = saved_file(w, navmesh);
        *out_size = file.size();
        if (!buffer) return;
        if (file.size() > capacity)
            fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", file.size(), " bytes are needed");
        std::memcpy(buffer, file.data(), file.size());
    });
}

NL_API nl_status nl_navmesh_save_file(const nl_world* world, nl_navmesh_id navmesh, const char* path) {
    return guarded("nl_navmesh_save_file", world, [&] {
        const nl::World& w = deref(world);
        require(path, "path");
        const std::vector<uint8_t> file = saved_file(w, navmesh);
        nl::write_file_bytes(path, std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
    });
}

NL_API nl_status nl_navmesh_save_tile(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile, void* buffer,
                                      size_t capacity, size_t* out_size) {
    return guarded("nl_navmesh_save_tile", world, [&] {
        const nl::World& w = deref(world);
        require(out_size, "out_size");
        if (!buffer && capacity > 0) fail(ErrorCode::InvalidArgument, "buffer is null but capacity is ", capacity);
        const std::vector<uint8_t> file = w.save_tile(to_handle(navmesh), nl::TileCoord{tile.x, tile.z});
        *out_size = file.size();
        if (!buffer) return;
        if (file.size() > capacity)
            fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", file.size(), " bytes are needed");
        std::memcpy(buffer, file.data(), file.size());
    });
}

NL_API nl_status nl_navmesh_save_tile_file(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile,
                                           const char* path) {
    return guarded("nl_navmesh_save_tile_file", world, [&] {
        const nl::World& w = deref(world);
        require(path, "path");
        const std::vector<uint8_t> file = w.save_tile(to_handle(navmesh), nl::TileCoord{tile.x, tile.z});
        nl::write_file_bytes(path, std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
    });
}

NL_API nl_status nl_navmesh_add_tile_bytes(nl_world* world, nl_navmesh_id navmesh, const void* data, size_t size) {
    return guarded("nl_navmesh_add_tile_bytes", world,
                   [&] { deref(world).add_tile_file(to_handle(navmesh), read_file(data, size)); });
}

NL_API nl_status nl_navmesh_add_tile_file(nl_world* world, nl_navmesh_id navmesh, const char* path) {
    return guarded("nl_navmesh_add_tile_file", world, [&] {
        nl::World& w = deref(world);
        require(path, "path");
        const std::string bytes = nl::read_navmesh_file_bytes(path);
        try {
            w.add_tile_file(to_handle(navmesh), read_file(bytes.data(), bytes.size()));
        } catch (const nl::Error& e) {
            throw nl::Error(e.code(), nl::concat(path, ": ", e.what()));  // which file, for a host adding many
        }
    });
}

NL_API nl_status nl_navmesh_get_tile_hash(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile,
                                          uint64_t* out_hash) {
    return guarded("nl_navmesh_get_tile_hash", world, [&] {
        require(out_hash, "out_hash");
        *out_hash = deref(world).tile_content_hash(to_handle(navmesh), nl::TileCoord{tile.x, tile.z});
    });
}

NL_API nl_navmesh_load_def nl_default_navmesh_load_def(void) {
    nl_navmesh_load_def def;
    std::memset(&def, 0, sizeof def);
    def.size = sizeof def;
    return def;
}

NL_API nl_status nl_navmesh_load(nl_world* world, const void* data, size_t size, const nl_navmesh_load_def* def,
                                 nl_navmesh_id* out_id) {
    return guarded("nl_navmesh_load", world, [&] {
        nl::World& w = deref(world);
        require(out_id, "out_id");
        *out_id = load(w, read_file(data, size), def);
    });
}

NL_API nl_status nl_navmesh_load_file(nl_world* world, const char* path, const nl_navmesh_load_def* def,
                                      nl_navmesh_id* out_id) {
    return guarded("nl_navmesh_load_file", world, [&] {
        nl::World& w = deref(world);
        require(path, "path");
        require(out_id, "out_id");
        const std::string bytes = nl::read_navmesh_file_bytes(path);
        try {
            *out_id = load(w, read_file(bytes.data(), bytes.size()), def);
        } catch (const nl::Error& e) {
            throw nl::Error(e.code(), nl::concat(path, ": ", e.what()));  // which file, for a host loading several
        }
    });
}

NL_API nl_status nl_navmesh_file_describe(const void* data, size_t size, nl_navmesh_file_info* out_info,
                                          char* made_for_json, size_t capacity, size_t* out_length) {
    return guarded("nl_navmesh_file_describe", nullptr, [&] {
        if (made_for_json && !out_length)
            fail(ErrorCode::InvalidArgument, "made_for_json is given but out_length is null");
        if (!made_for_json && capacity > 0)
            fail(ErrorCode::InvalidArgument, "made_for_json is null but capacity is ", capacity);
        if (out_info && out_info->size < nl::capi::kFirstSize<nl_navmesh_file_info>)
            fail(ErrorCode::InvalidArgument, "out_info->size is ", out_info->size, " (must be at least ",
                 nl::capi::kFirstSize<nl_navmesh_file_info>, ")");
        const nl::NavMeshFile file = read_file(data, size);
        const std::string json = nl::made_for_json(file);
        if (out_length) *out_length = json.size();  // also when the buffer is too small: the two-call pattern
        if (made_for_json && json.size() >= capacity)
            fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", json.size() + 1, " bytes are needed");
        if (out_info) {
            nl_navmesh_file_info info;
            std::memset(&info, 0, sizeof info);
            info.version = file.version;
            info.file_size = size;
            info.agent_type = nl::capi::to_c(file.navmesh.agent_type);
            info.vertex_count = static_cast<uint32_t>(file.navmesh.vertices.size());
            info.polygon_count = static_cast<uint32_t>(file.navmesh.polygon_sizes.size());
            info.detail_triangle_count = static_cast<uint32_t>(file.navmesh.detail_indices.size() / 3);
            info.link_count = static_cast<uint32_t>(file.links.size());
            for (const nl::Link& l : file.links) info.generated_link_count += l.generated;
            info.rides_carrier = file.rides_carrier;
            info.quantum = file.quantum;
            info.level_hash = file.made_for.level_hash;
            if (file.is_tile) {
                const nl::TileLayout& t = file.navmesh.tiles;
                info.is_tile = 1;
                info.content_hash = file.content_hash;
                info.tile = nl_tile_coord{t.tiles.front().x, t.tiles.front().z};
                info.tile_width = t.grid.tile_width;
                info.tile_origin_x = t.grid.origin_x;
                info.tile_origin_z = t.grid.origin_z;
            }
            nl::capi::write_growable(out_info, info, nl::capi::kFirstSize<nl_navmesh_file_info>, "out_info");
        }
        if (made_for_json) std::memcpy(made_for_json, json.c_str(), json.size() + 1);
    });
}

}  // extern "C"
