/*
 * Settings of the built-in Recast navmesh builder (builder name "recast"), with Recast's usual
 * defaults (those of RecastDemo's solo mesh). Pass a filled struct as nl_navmesh_build_def.settings,
 * or the same fields as JSON in settings_json: keys as the field names below (but `size` and
 * `reserved`), "partition" also as "watershed", "monotone" or "layers", the filters as booleans.
 *
 * Recast's own limits, refused with INVALID_ARGUMENT naming the setting to change: agent height at
 * most 255 cell heights, radius at most 127 cell sizes, a solo mesh's level at most 65,535 cells per
 * side, 2^27 cells in all and 2^24 walkable cells (a tiled build, tile_size > 0, has no limit on the
 * level's width: each tile is a Recast build of its own), and at most 8,191 cell heights tall.
 */
#ifndef NAVLINK_RECAST_H
#define NAVLINK_RECAST_H

#include "navlink/navlink.h"

#ifdef __cplusplus
extern "C" {
#endif

/** How Recast partitions the walkable area into regions. */
#define NL_RECAST_PARTITION_WATERSHED 0u /**< Best polygons; slowest (the default). */
#define NL_RECAST_PARTITION_MONOTONE 1u  /**< Fastest; long thin polygons. */
#define NL_RECAST_PARTITION_LAYERS 2u    /**< Between the two; good for tiles. */

typedef struct nl_recast_settings {
    uint32_t size;                    /**< sizeof(nl_recast_settings); set by nl_default_recast_settings(). */
    float cell_size;                  /**< Voxel width, metres (0.3). */
    float cell_height;                /**< Voxel height, metres (0.2). */
    float region_min_size;            /**< Smallest region kept, in cells per side (8). */
    float region_merge_size;          /**< Regions smaller than this merge with neighbours, cells per side (20). */
    float edge_max_length;            /**< Longest polygon edge along walls, metres (12); 0 = no limit. */
    float edge_max_error;             /**< Contour simplification error, cells (1.3). */
    uint32_t vertices_per_polygon;    /**< 3..6 (6). */
    float detail_sample_distance;     /**< Detail mesh sample spacing, cells (6); 0 <= value < 0.9: no
                                           samples inside polygons (the outline only). */
    float detail_sample_max_error;    /**< Detail mesh height error, cells of cell_height (1). */
    uint32_t partition;               /**< NL_RECAST_PARTITION_* (watershed). */
    uint8_t filter_low_hanging_obstacles;     /**< 1 (default): walk over obstacles lower than max_climb. */
    uint8_t filter_ledge_spans;               /**< 1 (default): no walkable spans at ledges. */
    uint8_t filter_walkable_low_height_spans; /**< 1 (default): no spans with less headroom than height. */
    uint8_t reserved;                         /**< Set to 0; ignored. */
    uint32_t tile_size;               /**< Tile side in cells: 0 (default) builds one solo mesh; 16..4096
                                           builds square tiles (Recast's tiled pipeline, as RecastDemo's
                                           Sample_TileMesh) in parallel on the world's task system and
                                           joins them into one navmesh (nl_navmesh_def.tile_width):
                                           levels of any width, the same navmesh for any thread count.
                                           Added in 0.3. */
    uint32_t tile_border;             /**< Cells of level each tile is voxelised with beyond its sides, so
                                           that erosion and regions see its neighbours: 0 (default) is
                                           the agent's radius in cells + 3, as RecastDemo; otherwise
                                           at least the radius in cells + 1 and at most tile_size.
                                           Added in 0.3. */
} nl_recast_settings;

/** Recast's usual defaults. Thread-safe; never fails. */
NL_API nl_recast_settings nl_default_recast_settings(void);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_RECAST_H */
