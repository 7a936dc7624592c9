// navlink-fuzz-seeds OUT_DIR [LEVEL.obj...]: writes the seed inputs that come from real data, too big
// to keep in the repository, into OUT_DIR/<target>/:
//   obj/          pieces of each level (runs of its faces with the vertices they use), with \n, \r\n
//                 and lone \r line endings
//   navmesh_add/  each level's upward-facing triangles as a host navmesh (navmesh_bytes.h), and a
//                 map of quads
//   links_json/   links of every kind saved by nl_navmesh_save_links_json from the navmesh the
//                 links target loads them on
//   navmesh_file/ navmesh files saved by nl_navmesh_save: the links target's navmesh with each
//                 count of those links, a map of quads with areas, and a navmesh the Recast
//                 builder built with generated links; each also with its body inflated (the flag
//                 cleared), so that mutations reach the sections' fields; and two tiles' files
//   tile_file/    every tile's file (nl_navmesh_save_tile) of the tiled navmesh fuzz_support.h's
//                 add_tile_fixture makes, with its links
#include <navlink/navlink.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <zlib.h>

#include "cell_navmesh.h"
#include "fuzz_support.h"
#include "io/obj_reader.h"
#include "navmesh_bytes.h"

namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Faces [first, first + count) of `mesh` as an OBJ text, vertices renumbered, lines ending `eol`.
std::string obj_piece(const nl::TriangleMesh& mesh, size_t first, size_t count, const char* eol) {
    std::map<uint32_t, uint32_t> renumbered;
    std::string vertices, faces;
    for (size_t t = first; t < first + count && t < mesh.triangles.size(); ++t) {
        faces += "f";
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            const auto [it, added] = renumbered.emplace(v, uint32_t(renumbered.size() + 1));
            if (added) {
                const nl::Vec3& p = mesh.vertices[v];
                vertices +=
                    "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + eol;
            }
            faces += " " + std::to_string(it->second);
        }
        faces += eol;
    }
    return vertices + faces;
}

// The level's triangles that face up, as a host navmesh would list them.
std::string upward_triangles(const nl::TriangleMesh& mesh) {
    std::vector<float> vertices;
    std::vector<uint32_t> triangles;
    std::map<uint32_t, uint32_t> renumbered;
    for (const nl::Triangle& t : mesh.triangles) {
        const nl::Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const nl::Vec3 n = (b - a).cross(c - a);
        if (!(n.y() > 0.7f * n.norm())) continue;
        for (int k = 0; k < 3; ++k) {
            const auto [it, added] = renumbered.emplace(t[k], uint32_t(renumbered.size()));
            if (added)
                vertices.insert(vertices.end(),
                                {mesh.vertices[t[k]].x(), mesh.vertices[t[k]].y(), mesh.vertices[t[k]].z()});
            triangles.push_back(it->second);
        }
    }
    return nl::fuzz::triangles_as_bytes(vertices, triangles);
}

// A map of 1 m quads with areas, in the navmesh_add target's format.
std::string quad_map() {
    const nl::test::CellNavmesh cells({"..1.", ".2..", "...."}, 0.4f);
    std::string out;
    auto put = [&](const auto& value) { out.append(reinterpret_cast<const char*>(&value), sizeof value); };
    put(uint8_t{nl::fuzz::kCounts | nl::fuzz::kAreas});
    put(static_cast<uint16_t>(cells.def.vertex_count));
    put(static_cast<uint16_t>(cells.def.polygon_count));
    for (const float f : cells.vertices) put(f);
    for (const uint8_t c : cells.counts) put(c);
    for (const uint32_t i : cells.indices) put(static_cast<uint16_t>(i));
    for (const uint8_t a : cells.areas) put(a);
    return out;
}

// A navmesh file and, when its body is deflated, the same file with its body inflated (flag 0,
// checksum made right): both read the same.
void write_navmesh_file(const fs::path& path, const std::string& file) {
    write(path, file);
    uint32_t flags = 0;
    std::memcpy(&flags, file.data() + 28, 4);
    if (!(flags & 1u) || file.size() < 40) return;
    uint64_t inflated_size = 0;
    std::memcpy(&inflated_size, file.data() + 32, 8);
    std::string body(inflated_size, '\0');
    uLongf got = body.size();
    if (uncompress(reinterpret_cast<Bytef*>(body.data()), &got, reinterpret_cast<const Bytef*>(file.data() + 40),
                   file.size() - 40) != Z_OK)
        return;
    std::string plain = file.substr(0, 32) + body;
    const uint64_t size = plain.size();
    const uint32_t none = 0;
    std::memcpy(plain.data() + 16, &size, 8);
    std::memcpy(plain.data() + 28, &none, 4);
    const uint32_t crc = static_cast<uint32_t>(
        crc32_z(crc32_z(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(plain.data() + 32), plain.size() - 32));
    std::memcpy(plain.data() + 24, &crc, 4);
    write(fs::path(path).replace_extension(".plain.nlnav"), plain);
}

// Saves the navmesh with nl_navmesh_save to `path` (and its inflated twin).
bool save_navmesh_file(nl_world* world, nl_navmesh_id navmesh, const fs::path& path) {
    size_t size = 0;
    if (NL_FAILED(nl_navmesh_save(world, navmesh, nullptr, 0, &size))) return false;
    std::string file(size, '\0');
    if (NL_FAILED(nl_navmesh_save(world, navmesh, file.data(), file.size(), &size))) return false;
    write_navmesh_file(path, file);
    return true;
}

// Links of each kind on the links target's navmesh (an 8 m map of cells), as the library saves them.
bool write_links(const fs::path& dir, const fs::path& file_dir) {
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world))) return false;
    const nl::test::CellNavmesh cells(std::vector<std::string>(8, "........"), 0.4f);
    nl_navmesh_id navmesh{};
    bool ok = NL_SUCCEEDED(nl_navmesh_add(world, &cells.def, &navmesh));
    const nl_link_kind kinds[] = {NL_LINK_JUMP, NL_LINK_DROP, NL_LINK_MANUAL, NL_LINK_FIRST_PLUGIN_KIND + 7};
    for (int i = 0; ok && i < 4; ++i) {
        nl_link_def def = nl_default_link_def();
        def.kind = kinds[i];
        def.start[0] = 0.5f + i, def.start[2] = 0.5f;
        def.end[0] = 7.5f - i, def.end[2] = 6.5f;
        def.bidirectional = uint8_t(i % 2);
        def.user_data = 1000u + uint64_t(i);
        def.requirements.clearance_width = 0.8f;
        nl_link_id id{};
        ok = NL_SUCCEEDED(nl_link_add(world, navmesh, &def, &id));
        size_t length = 0;
        ok = ok && NL_SUCCEEDED(nl_navmesh_save_links_json(world, navmesh, nullptr, 0, &length));
        std::string json(length + 1, '\0');
        ok = ok && NL_SUCCEEDED(nl_navmesh_save_links_json(world, navmesh, json.data(), json.size(), &length));
        if (ok) write(dir / ("links-" + std::to_string(i + 1) + ".json"), json.substr(0, length));
        ok = ok && save_navmesh_file(world, navmesh, file_dir / ("cells-" + std::to_string(i + 1) + ".nlnav"));
    }
    if (!ok) std::fprintf(stderr, "navlink-fuzz-seeds: links: %s\n", nl_get_last_error_message());
    nl_world_destroy(world);
    return ok;
}

// The quad map as a navmesh file (areas, no links).
bool write_quad_file(const fs::path& dir) {
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world))) return false;
    const nl::test::CellNavmesh cells({"..1.", ".2..", "...."}, 0.4f);
    nl_navmesh_id navmesh{};
    const bool ok = NL_SUCCEEDED(nl_navmesh_add(world, &cells.def, &navmesh)) &&
                    save_navmesh_file(world, navmesh, dir / "quad-map.nlnav");
    if (!ok) std::fprintf(stderr, "navlink-fuzz-seeds: navmesh file: %s\n", nl_get_last_error_message());
    nl_world_destroy(world);
    return ok;
}

// Two floors with a 1 m gap, built by the Recast builder with links generated: a file whose MADE
// section records the builder's settings and the link settings.
bool write_built_file(const fs::path& dir) {
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world))) return false;
    bool ok = nl::fuzz::add_two_pads(world);
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    build.settings_json = R"({"cell_size": 0.25})";
    build.settings_json_length = std::strlen(build.settings_json);
    nl_navmesh_id navmesh{};
    ok = ok && NL_SUCCEEDED(nl_navmesh_build(world, &build, &navmesh));
    const nl_link_settings settings = nl_default_link_settings();
    ok = ok && NL_SUCCEEDED(nl_navmesh_generate_links(world, navmesh, &settings, nullptr, nullptr, nullptr));
    ok = ok && save_navmesh_file(world, navmesh, dir / "built-gap.nlnav");
    if (!ok) std::fprintf(stderr, "navlink-fuzz-seeds: built navmesh file: %s\n", nl_get_last_error_message());
    nl_world_destroy(world);
    return ok;
}

// Tiles' files (nl_navmesh_save_tile) of the same two pads in tiles of 16 cells of 0.25 m, with their
// links: the seeds of the tile_file target (whose own navmesh is these tiles) and of navmesh_file.
bool write_tile_files(const fs::path& dir, const fs::path& navmesh_file_dir) {
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(nullptr, &world))) return false;
    nl_navmesh_id navmesh{};
    bool ok = nl::fuzz::add_tile_fixture(world, navmesh);
    uint32_t count = 0;
    nl_tile_coord tiles[64];
    ok = ok && NL_SUCCEEDED(nl_navmesh_get_tiles(world, navmesh, tiles, 64, &count));
    for (uint32_t i = 0; ok && i < count; ++i) {
        size_t size = 0;
        ok = NL_SUCCEEDED(nl_navmesh_save_tile(world, navmesh, tiles[i], nullptr, 0, &size));
        std::string file(size, '\0');
        ok = ok && NL_SUCCEEDED(nl_navmesh_save_tile(world, navmesh, tiles[i], file.data(), size, &size));
        const std::string name = "tile_" + std::to_string(tiles[i].x) + "_" + std::to_string(tiles[i].z) + ".nltile";
        if (ok) write_navmesh_file(dir / name, file);
        if (ok && i < 2) write_navmesh_file(navmesh_file_dir / name, file);
    }
    if (!ok) std::fprintf(stderr, "navlink-fuzz-seeds: tiles' files: %s\n", nl_get_last_error_message());
    nl_world_destroy(world);
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: navlink-fuzz-seeds OUT_DIR [LEVEL.obj...]\n");
        return 2;
    }
    const fs::path out = argv[1];
    for (const char* target : {"obj", "navmesh_add", "links_json", "navmesh_file", "tile_file"})
        fs::create_directories(out / target);
    write(out / "navmesh_add" / "quad-map.bin", quad_map());
    if (!write_links(out / "links_json", out / "navmesh_file") || !write_quad_file(out / "navmesh_file") ||
        !write_built_file(out / "navmesh_file") || !write_tile_files(out / "tile_file", out / "navmesh_file"))
        return 1;
    for (int i = 2; i < argc; ++i) {
        const std::string name = fs::path(argv[i]).stem().string();
        try {
            const nl::TriangleMesh mesh = nl::read_obj_file(argv[i]);
            const size_t step = std::max<size_t>(1, mesh.triangles.size() / 4);
            for (size_t k = 0; k < 4; ++k)
                write(out / "obj" / (name + "-" + std::to_string(k) + ".obj"), obj_piece(mesh, k * step, 48, "\n"));
            write(out / "obj" / (name + "-crlf.obj"), obj_piece(mesh, 0, 24, "\r\n"));
            write(out / "obj" / (name + "-cr.obj"), obj_piece(mesh, 0, 24, "\r"));
            write(out / "navmesh_add" / (name + ".bin"), upward_triangles(mesh));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "navlink-fuzz-seeds: %s: %s\n", argv[i], e.what());
            return 1;
        }
    }
    return 0;
}
