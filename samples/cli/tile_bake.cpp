#include "tile_bake.h"

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <map>

#include "json_text.h"
#include "sample_error.h"
#include "text_file.h"

namespace nl::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kIndexName = "index.json";

std::string hash_text(uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, hash);
    return text;
}

std::string tile_file_name(const nl_tile_coord& t) {
    return "tile_" + std::to_string(t.x) + "_" + std::to_string(t.z) + ".nltile";
}

std::vector<nl_tile_coord> loaded_tiles(nl_world* world, nl_navmesh_id navmesh) {
    uint32_t count = 0;
    samples::check(nl_navmesh_get_tiles(world, navmesh, nullptr, 0, &count), "listing the tiles");
    std::vector<nl_tile_coord> tiles(count);
    samples::check(nl_navmesh_get_tiles(world, navmesh, tiles.data(), count, &count), "listing the tiles");
    return tiles;
}

}  // namespace

bool is_tile_bake(const std::string& path) {
    std::error_code error;
    return fs::is_directory(path, error) && fs::is_regular_file(fs::path(path) / kIndexName, error);
}

TileBakeIndex read_tile_bake(const std::string& folder) {
    const std::string index_path = (fs::path(folder) / kIndexName).string();
    const nlohmann::json j = samples::parse_json_text(samples::read_text_file(index_path), index_path);
    auto bad = [&](const std::string& what) { return samples::SampleError(index_path + ": " + what); };
    if (!j.is_object() || j.value("format", "") != "navlink-tiles")
        throw bad("not a tile bake's index (\"format\" is not \"navlink-tiles\")");
    if (j.value("version", 0) != 1)
        throw bad("version " + j.value("version", nlohmann::json()).dump() + " (this reads 1)");
    TileBakeIndex out;
    try {
        out.tile_width = j.at("tile_width").get<float>();
        out.tile_origin[0] = j.at("tile_origin").at(0).get<float>();
        out.tile_origin[1] = j.at("tile_origin").at(1).get<float>();
        for (const nlohmann::json& t : j.at("tiles")) {
            TileBakeEntry e;
            e.tile = nl_tile_coord{t.at("x").get<int32_t>(), t.at("z").get<int32_t>()};
            e.file = t.at("file").get<std::string>();
            e.hash = std::stoull(t.at("hash").get<std::string>(), nullptr, 16);
            if (e.file.empty() || fs::path(e.file).has_parent_path() || e.file == "." || e.file == "..")
                throw bad("tile (" + std::to_string(e.tile.x) + ", " + std::to_string(e.tile.z) + ")'s file '" +
                          e.file + "' is not a name in the folder");
            out.tiles.push_back(e);
        }
    } catch (const nlohmann::json::exception& e) {
        throw bad(std::string("a field is missing or of the wrong type (") + e.what() + ")");
    } catch (const std::logic_error&) {
        throw bad("a tile's hash is not 16 hex digits");
    }
    if (out.tiles.empty()) throw bad("no tiles");
    return out;
}

TileBakeWritten write_tile_bake(nl_world* world, nl_navmesh_id navmesh, const std::string& folder) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw samples::SampleError(folder + ": cannot make the folder (" + error.message() + ")");
    // What the folder holds already, by tile.
    std::map<std::pair<int32_t, int32_t>, TileBakeEntry> held;
    if (is_tile_bake(folder)) {
        for (const TileBakeEntry& e : read_tile_bake(folder).tiles) held[{e.tile.x, e.tile.z}] = e;
    }
    nl_navmesh_info info = nl_navmesh_info_init();
    samples::check(nl_navmesh_get_info(world, navmesh, &info), "reading the navmesh");
    if (info.tile_count == 0) throw samples::SampleError("the navmesh is not tiled: nothing to bake in tiles");
    TileBakeWritten written;
    nlohmann::json tiles = nlohmann::json::array();
    for (const nl_tile_coord& t : loaded_tiles(world, navmesh)) {
        uint64_t hash = 0;
        samples::check(nl_navmesh_get_tile_hash(world, navmesh, t, &hash), "hashing a tile");
        const std::string name = tile_file_name(t);
        const fs::path path = fs::path(folder) / name;
        const auto before = held.find({t.x, t.z});
        if (before != held.end() && before->second.hash == hash && before->second.file == name &&
            fs::is_regular_file(path, error)) {
            ++written.kept;
        } else {
            samples::check(nl_navmesh_save_tile_file(world, navmesh, t, path.string().c_str()),
                           "writing " + path.string());
            ++written.written;
            written.bytes += fs::file_size(path, error);
        }
        if (before != held.end()) held.erase(before);
        tiles.push_back({{"x", t.x}, {"z", t.z}, {"file", name}, {"hash", hash_text(hash)}});
    }
    for (const auto& [coord, stale] : held) written.removed += fs::remove(fs::path(folder) / stale.file, error);
    const nlohmann::json index = {{"format", "navlink-tiles"},
                                  {"version", 1},
                                  {"tile_width", info.tile_width},
                                  {"tile_origin", {info.tile_origin[0], info.tile_origin[1]}},
                                  {"tiles", tiles}};
    samples::write_text_file((fs::path(folder) / kIndexName).string(), index.dump(1) + "\n");
    return written;
}

nl_navmesh_id load_tile_bake(nl_world* world, const std::string& folder) {
    const TileBakeIndex index = read_tile_bake(folder);
    nl_navmesh_id navmesh{};
    const std::string first = (fs::path(folder) / index.tiles.front().file).string();
    samples::check(nl_navmesh_load_file(world, first.c_str(), nullptr, &navmesh), "loading the first tile");
    for (size_t i = 1; i < index.tiles.size(); ++i) {
        const std::string path = (fs::path(folder) / index.tiles[i].file).string();
        samples::check(nl_navmesh_add_tile_file(world, navmesh, path.c_str()), "adding a tile");
    }
    return navmesh;
}

}  // namespace nl::cli
