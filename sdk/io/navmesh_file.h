// The baked navmesh file: a navmesh, its links and what they were made for, compact and checked.
//
// Little-endian. A 32-byte header: the magic bytes 89 'N' 'L' 'N' 'A' 'V' 0D 0A, the format version
// (u32), the section count (u32), the file's bytes (u64), the CRC-32 of every byte after the header
// (u32) and flags (u32; 1: the rest is deflated by zlib, its inflated size in its first 8 bytes).
// Then sections, each a tag (4 ASCII bytes), 4 reserved bytes, its payload's bytes (u64) and the
// payload: MADE (the agent type and what it was made with), GEOM (the polygons and their detail)
// and LINK (the links); a tile's file (write_tile_file) has a TILE section after them: the grid, the
// tile's place, its content hash, its weld tolerance and each link's start and end tiles. A reader skips
// sections it does not know.
//
// Coordinates are fixed point: whole quanta of the navmesh grid (2^-10 m, navmesh_grid.h, stated in
// GEOM) from the navmesh's lowest corner. Navmeshes keep every coordinate on that grid, so the file
// holds them exactly: a loaded navmesh is the saved one, bit for bit, and answers every query alike.
// Each axis of the vertices takes the fewest bytes its extent needs (2 up to 64 m, 3 up to 16 km);
// polygon corners the fewest the vertex count needs; detail triangles a byte per corner where a
// polygon's detail vertices lie within 256 of each other; link points a variable-length offset.
// Adjacency and outline are not stored: the loader builds them again from the shared corners, as
// nl_navmesh_add does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "links/link.h"
#include "navmesh/provenance.h"
#include "navmesh/navmesh_builder.h"

namespace nl {

constexpr uint32_t kNavMeshFileVersion = 1;
constexpr size_t kNavMeshFileHeaderBytes = 32;
// The largest file read_navmesh_file_bytes reads: 4 GiB (a navmesh of some 100 million polygons);
// a header that says more is refused before anything is read past it.
constexpr uint64_t kNavMeshFileMaxBytes = uint64_t(4) << 30;

struct NavMeshFile {
    NavMeshInput navmesh;     // weld_tolerance 0: the saved vertices are welded already
    std::vector<Link> links;  // in the order they were saved; their polygons as saved
    NavMeshProvenance made_for;
    bool rides_carrier = false;  // the coordinates are in the space of the mesh it rode
    uint32_t version = 0;
    float quantum = 0.0f;  // metres (2^-10)
    std::string writer;    // the NavLink version that wrote it
    // A tile's file: `navmesh` is one tile of a tiled navmesh (navmesh.tiles: its grid and place), the
    // links are those it owns (their polygons not saved: kNoPolygon), each with its start and end tiles.
    bool is_tile = false;
    uint64_t content_hash = 0;  // of everything the tile was made from (a tile's file only)
};

// The file for `navmesh` and its `links` (none may be a cross link: InvalidArgument).
std::vector<uint8_t> write_navmesh_file(const NavMesh& navmesh, const std::vector<Link>& links,
                                        const NavMeshProvenance& made_for, bool rides_carrier);

// The file of one tile of a tiled navmesh: `tile` as it was built or handed over (its place in
// tile.tiles), the links it owns (link_tiles.h; their start_tile and end_tile set, no cross link), and
// the hash of what it was made from. InvalidArgument for a link without its tiles.
std::vector<uint8_t> write_tile_file(const NavMeshInput& tile, const std::vector<Link>& links,
                                     const NavMeshProvenance& made_for, uint64_t content_hash);

// Reads a file written by write_navmesh_file or write_tile_file, checking everything but what building it checks
// (build_navmesh) and placing its links (place_saved_link). Throws VersionMismatch (not a navmesh
// file, or a newer version) or Parse (truncated, corrupted: the section and what is wrong named).
// Whatever the file says, allocates no more than a fixed multiple of what its bytes inflate to
// (deflate's limit: 1032 times `size`).
NavMeshFile read_navmesh_file(const uint8_t* data, size_t size);

// The file at `path`, read no further than its header says it goes (file_bytes.h), and never more than
// kNavMeshFileMaxBytes: a device is refused (Io), a stream that goes on past its end or a header that
// says more than that too (Parse); the bytes are for read_navmesh_file.
std::string read_navmesh_file_bytes(const std::string& path);

// What the file was made for, as a JSON object: {"builder", "builder_settings", "link_settings",
// "level_hash" (16 hex digits), "writer"}; settings are objects (null when not recorded).
std::string made_for_json(const NavMeshFile& file);

// The CRC-32 a file's header holds for the bytes after it (for tools that patch a file on purpose).
uint32_t navmesh_file_checksum(const uint8_t* data, size_t size);

}  // namespace nl
