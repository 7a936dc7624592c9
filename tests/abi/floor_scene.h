/*
 * The floor the world, level and ray cases stand on, and the rays and segments they cast at it.
 * Strict C11 through the C ABI only.
 *
 * Scenes are built so that every expectation is exact: a floor at y = 1 spanning x, z in [-10, 10],
 * wound counter-clockwise seen from above (normal +Y).
 */
#ifndef NAVLINK_ABI_FLOOR_SCENE_H
#define NAVLINK_ABI_FLOOR_SCENE_H

#include <navlink/navlink.h>

/* The floor's corners. Counter-clockwise seen from above: (v1 - v0) x (v2 - v0) points to +Y. Triangle 0
 * holds the points with z > x, triangle 1 those with z < x. */
extern const float k_floor_vertices[12];
extern const uint32_t k_floor_indices[6];

extern const float k_identity[16];

/* The floor as an OBJ file: a quad, counter-clockwise from above, at y = 1. */
#define FLOOR_QUAD_OBJ                                   \
    "# a quad, counter-clockwise from above, at y = 1\n" \
    "o floor\n"                                          \
    "v -10 1 -10\n"                                      \
    "v -10 1 10\n"                                       \
    "v 10 1 10\n"                                        \
    "v 10 1 -10\n"                                       \
    "vn 0 1 0\n"                                         \
    "usemtl none\n"                                      \
    "f 1 2 3 4\n"

/* The identity moved by (x, y, z). */
void translation(float m[16], float x, float y, float z);

nl_mesh_def floor_def(void);

/* The world's mesh count (0xdeadbeef if the call failed). */
uint32_t mesh_count(const nl_world* world);

/* 1 if two mesh ids are equal. */
int same_id(nl_mesh_id a, nl_mesh_id b);

/* A ray straight down from (x, from_y, z). */
nl_ray down_ray(float x, float z, float from_y, float max_distance);

/* Casts one ray straight down from (x, 5, z); returns the hit (hit = 0 on a miss or an error). */
nl_ray_hit cast_down(nl_world* world, float x, float z);

nl_segment segment(float x0, float y0, float z0, float x1, float y1, float z1);

#endif /* NAVLINK_ABI_FLOOR_SCENE_H */
