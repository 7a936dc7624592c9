/*
 * navlink/navmesh_file.h: Baked navmesh files: a navmesh and its links in one checked file.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_NAVMESH_FILE_H
#define NAVLINK_NAVMESH_FILE_H

#include "navlink/links.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Baked navmesh files: a navmesh, its links and what they were made for in one compact, checked
 * binary file (docs/baking.md), saved in an editor or build step and loaded at run time with no
 * Recast build. Navmeshes keep their coordinates on a grid of 1/1024 m, so a file holds them exactly:
 * a loaded navmesh answers every query as the saved one did.
 * ------------------------------------------------------------------------------------------- */

/** Writes the navmesh, its links (generated and manual, in the order nl_navmesh_get_links lists them)
 *  and what they were made for (agent type, builder and its settings, the level's hash, the link
 *  generation settings) as a navmesh file into `buffer` (caller-owned, `capacity` bytes). `*out_size`
 *  always receives the file's size; a NULL buffer only measures (two-call pattern).
 *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (nothing written), INVALID_HANDLE,
 *  INVALID_ARGUMENT (out_size NULL; buffer NULL with a capacity; a navmesh with cross links: a file
 *  holds one navmesh's own links; a tiled navmesh with a link whose end's tile is not loaded: the file
 *  holds the tiles loaded, and the link would not load back). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh to save.
 *  @param[out,opt] buffer  Receives the file, or NULL to measure only.
 *  @param[in] capacity  The bytes `buffer` has room for.
 *  @param[out] out_size  Receives the file's size. */
NL_API nl_status nl_navmesh_save(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity,
                                 size_t* out_size);

/** The same, written to the file at `path` (NUL-terminated, borrowed): whole or not at all (written
 *  beside it, then renamed over it). A symbolic link at `path` stays: the file it leads to (through
 *  any chain of links) is written. Returns SUCCESS, or a failure as nl_navmesh_save, or IO_ERROR
 *  (cannot write; the reason named; also a path that is, or leads to, a directory, a device, a socket
 *  or a pipe: left as it was). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh to save.
 *  @param[in] path  The file to write. */
NL_API nl_status nl_navmesh_save_file(const nl_world* world, nl_navmesh_id navmesh, const char* path);

/** Writes one tile of a tiled navmesh as a tile's file (a navmesh file with a TILE section, docs/tiles.md,
 *  "Baked tiles"): the tile's polygons as built or added, the generated links it owns (those that start
 *  on it, wherever they end), what it was made for, and its content hash (nl_navmesh_get_tile_hash).
 *  Host links are not in it (nl_navmesh_save saves a whole navmesh with them). Load the first tile of
 *  a world with nl_navmesh_load (a tiled navmesh of that tile) and the others with
 *  nl_navmesh_add_tile_bytes, in any order: the navmesh and links are those the tiles were saved from,
 *  bit for bit. `*out_size` always receives the file's size; a NULL buffer only measures.
 *  Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (nothing written), NOT_FOUND (no tile loaded
 *  there), INVALID_HANDLE, INVALID_ARGUMENT (out_size NULL; buffer NULL with a capacity; a navmesh that
 *  is not tiled, or rides a movable mesh: save it whole). Thread-safe. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] tile  The tile to save.
 *  @param[out,opt] buffer  Receives the file, or NULL to measure only.
 *  @param[in] capacity  The bytes `buffer` has room for.
 *  @param[out] out_size  Receives the file's size. */
NL_API nl_status nl_navmesh_save_tile(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile, void* buffer,
                                      size_t capacity, size_t* out_size);

/** The same, written to the file at `path` (NUL-terminated, borrowed) as nl_navmesh_save_file writes.
 *  Also IO_ERROR. Thread-safe. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] tile  The tile to save.
 *  @param[in] path  The file to write. */
NL_API nl_status nl_navmesh_save_tile_file(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile,
                                           const char* path);

/** Adds the tile a tile's file holds (`data`, `size` bytes, borrowed) to a tiled navmesh, with its
 *  links, as nl_navmesh_add_tile adds a tile (one step for paths and agents); no link is generated: a
 *  link to a tile not loaded waits, out of every path, until that tile is added, and the links of the
 *  loaded tiles that land on this one come into use. Returns SUCCESS, or a failure with VERSION_MISMATCH
 *  or PARSE_ERROR (as nl_navmesh_load), INVALID_ARGUMENT (null data with a size; a whole navmesh's file;
 *  a tile of another grid or agent type, or made with another builder, builder settings or link
 *  settings than the navmesh; a tile already loaded there; polygons or links that do not fit, named),
 *  INVALID_HANDLE, OUT_OF_MEMORY; nothing changed on a failure. Thread-safe; waits for a link
 *  generation of the navmesh running meanwhile. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] data  The tile's file, `size` bytes.
 *  @param[in] size  The bytes of `data`. */
NL_API nl_status nl_navmesh_add_tile_bytes(nl_world* world, nl_navmesh_id navmesh, const void* data, size_t size);

/** The same, from the file at `path` (NUL-terminated, borrowed), read as nl_navmesh_load_file reads.
 *  Also NOT_FOUND (no such file), IO_ERROR. Thread-safe. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] path  The tile's file. */
NL_API nl_status nl_navmesh_add_tile_file(nl_world* world, nl_navmesh_id navmesh, const char* path);

/** The content hash of the tile at `tile` of a tiled navmesh's grid (loaded or not), from what the world
 *  holds now: the level's triangles in the columns the tile, its links and its neighbours' borders reach,
 *  the builder and its settings, the link settings and the body. A bake keeps a tile's file by it and
 *  skips a tile whose hash it holds; a tile's file records the hash it was saved with. Never 0.
 *  Returns SUCCESS, or a failure with INVALID_HANDLE, INVALID_ARGUMENT (out_hash NULL; a navmesh that
 *  is not tiled). Thread-safe. Added in 0.3.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The tiled navmesh.
 *  @param[in] tile  The tile.
 *  @param[out] out_hash  Receives the hash. */
NL_API nl_status nl_navmesh_get_tile_hash(const nl_world* world, nl_navmesh_id navmesh, nl_tile_coord tile,
                                          uint64_t* out_hash);

/** Refuse a file baked from other level geometry than the world holds now (see nl_navmesh_load_def). */
#define NL_NAVMESH_LOAD_SAME_LEVEL 0x1u

/** How to load a navmesh file. Get one from nl_default_navmesh_load_def(). */
typedef struct nl_navmesh_load_def {
    uint32_t size;       /**< sizeof(nl_navmesh_load_def). */
    nl_mesh_id carrier;  /**< For a file whose navmesh rode a movable mesh (nl_navmesh_file_info.rides_carrier):
                              the movable mesh it rides now. The null id otherwise. */
    uint32_t flags;      /**< NL_NAVMESH_LOAD_SAME_LEVEL: compare the hash of the level it was baked from
                              with the world's (its static meshes, or the carrier in its own space)
                              and refuse a mismatch. 0: load it whatever the level. */
} nl_navmesh_load_def;

/** The null carrier and no flags. Thread-safe; never fails. */
NL_API nl_navmesh_load_def nl_default_navmesh_load_def(void);

/** Adds the navmesh and its links held in a navmesh file (`data`, `size` bytes, borrowed), as
 *  nl_navmesh_add and nl_link_add would, with new ids (links in the file's order); what it was made
 *  for travels with it (nl_navmesh_save writes it again). A tile's file (nl_navmesh_save_tile) makes a
 *  tiled navmesh of that one tile: add the others with nl_navmesh_add_tile_bytes. `def` may be NULL
 *  (the defaults).
 *  Nothing in the world changes unless everything loads. Whatever the file says, the loader allocates
 *  no more than a fixed multiple of what its bytes inflate to (deflate's limit: 1032 times `size`).
 *  Returns SUCCESS, or a failure with VERSION_MISMATCH (not a NavLink navmesh file, or a newer format
 *  version), PARSE_ERROR (truncated or corrupted: the section and what is wrong named), INVALID_ARGUMENT
 *  (null data with a size, null out_id, bad def size or flags, a carrier for a file that rode none or
 *  none for one that did, NL_NAVMESH_LOAD_SAME_LEVEL and the level differs, polygons or links that do
 *  not fit, named as "links[3].start"), INVALID_HANDLE (the carrier), OUT_OF_MEMORY. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] data  The file's bytes, `size` of them.
 *  @param[in] size  The bytes of `data`.
 *  @param[in,opt] def  How to load it, or NULL for the defaults.
 *  @param[out] out_id  Receives the navmesh's id. */
NL_API nl_status nl_navmesh_load(nl_world* world, const void* data, size_t size, const nl_navmesh_load_def* def,
                                 nl_navmesh_id* out_id);

/** The same, from the file at `path` (NUL-terminated, borrowed): a regular file or a pipe, read no
 *  further than its header says the file goes. Also NOT_FOUND (no such file), IO_ERROR (cannot read
 *  it; a directory, a device or a socket), PARSE_ERROR (a pipe that goes on past the file's end).
 *  Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] path  The file to read.
 *  @param[in,opt] def  How to load it, or NULL for the defaults.
 *  @param[out] out_id  Receives the navmesh's id. */
NL_API nl_status nl_navmesh_load_file(nl_world* world, const char* path, const nl_navmesh_load_def* def,
                                      nl_navmesh_id* out_id);

/** What a navmesh file holds and was made for (nl_navmesh_file_describe). */
typedef struct nl_navmesh_file_info {
    uint32_t size;                  /**< sizeof(nl_navmesh_file_info); set by the caller. */
    uint32_t version;               /**< The file's format version. */
    uint64_t file_size;             /**< Bytes. */
    nl_agent_type agent_type;       /**< The body the navmesh was made for. */
    uint32_t vertex_count;
    uint32_t polygon_count;
    uint32_t detail_triangle_count; /**< 0: no height detail. */
    uint32_t link_count;
    uint32_t generated_link_count;  /**< Of link_count, made by link generation. */
    uint32_t rides_carrier;         /**< 1: its coordinates are in the space of a movable mesh it rode. */
    float quantum;                  /**< Metres per step of its fixed-point coordinates (1/1024). */
    uint32_t reserved;
    uint64_t level_hash;            /**< Of the level triangles it was built from; 0: handed over by the host. */
    /* A tile's file (nl_navmesh_save_tile); all 0 for a whole navmesh's. Added in 0.3. */
    uint64_t content_hash;          /**< Of everything the tile was made from (nl_navmesh_get_tile_hash). */
    nl_tile_coord tile;             /**< The tile's place in its grid. */
    float tile_width;               /**< Metres; 0: a whole navmesh's file. */
    float tile_origin_x;            /**< The grid's origin (nl_navmesh_info.tile_origin). */
    float tile_origin_z;
    uint32_t is_tile;               /**< 1: a tile's file. */
} nl_navmesh_file_info;

/** Reads a navmesh file (`data`, `size` bytes, borrowed) without loading it: fills `out_info`
 *  (optional) and writes what it was made for as a JSON object into `made_for_json` (optional,
 *  caller-owned, `capacity` bytes, NUL-terminated; `*out_length`, when given, always receives its
 *  length without the NUL; a NULL buffer only measures): {"builder": name or null, "builder_settings":
 *  object or null (complete when the builder recorded what it used, as "recast" does, else as
 *  given), "link_settings": object or null, "link_plugins": {kind name: {"plugin", "version",
 *  "settings"}} for each link-kind plugin that ran, or null, "level_hash": "16 hex digits",
 *  "writer": version}.
 *  Returns SUCCESS, or a failure as nl_navmesh_load reading the file (VERSION_MISMATCH, PARSE_ERROR),
 *  BUFFER_TOO_SMALL, INVALID_ARGUMENT (null data with a size; a buffer without out_length; bad info
 *  size). Thread-safe; needs no world (failures reach no log callback).
 *  @param[in] data  The file's bytes, `size` of them.
 *  @param[in] size  The bytes of `data`.
 *  @param[out,opt] out_info  Receives what the file holds, or NULL.
 *  @param[out,opt] made_for_json  Receives what it was made for, or NULL.
 *  @param[in] capacity  The bytes `made_for_json` has room for.
 *  @param[out,opt] out_length  Receives the JSON's length, or NULL when `made_for_json` is. */
NL_API nl_status nl_navmesh_file_describe(const void* data, size_t size, nl_navmesh_file_info* out_info,
                                          char* made_for_json, size_t capacity, size_t* out_length);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_NAVMESH_FILE_H */
