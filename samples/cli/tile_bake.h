// A world baked in tiles (navlink bake --tile-size): one tile's file per loaded tile (nl_navmesh_save_tile)
// and an index, index.json, in one folder:
//
//   {"format": "navlink-tiles", "version": 1, "tile_width": 19.2, "tile_origin": [x, z],
//    "tiles": [{"x": 0, "z": 0, "file": "tile_0_0.nltile", "hash": "16 hex digits"}, ...]}
//
// A bake into a folder that holds a bake keeps every tile whose content hash it holds already.
#pragma once

#include <navlink/navlink.h>

#include <cstdint>
#include <string>
#include <vector>

namespace nl::cli {

struct TileBakeEntry {
    nl_tile_coord tile;
    std::string file;  // in the folder
    uint64_t hash = 0;
};

struct TileBakeIndex {
    float tile_width = 0.0f;
    float tile_origin[2] = {0.0f, 0.0f};
    std::vector<TileBakeEntry> tiles;  // row order
};

// Whether `path` is a folder holding a tile bake's index.
bool is_tile_bake(const std::string& path);
// The index of the bake in `folder`. Throws SampleError naming what is wrong.
TileBakeIndex read_tile_bake(const std::string& folder);

struct TileBakeWritten {
    size_t written = 0, kept = 0, removed = 0;  // tiles written, kept (same hash), stale files removed
    uint64_t bytes = 0;                         // of the tiles' files written
};
// Writes every loaded tile of a tiled navmesh and the index into `folder` (made if needed), keeping
// the files of tiles whose hash the folder's index holds. Throws SampleError.
TileBakeWritten write_tile_bake(nl_world* world, nl_navmesh_id navmesh, const std::string& folder);

// Loads the bake in `folder`: its first tile as a navmesh, the others added to it. Throws SampleError.
nl_navmesh_id load_tile_bake(nl_world* world, const std::string& folder);

}  // namespace nl::cli
