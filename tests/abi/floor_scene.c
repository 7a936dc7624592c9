/* The floor of floor_scene.h. */
#include "floor_scene.h"
#include "scene.h"

#include <math.h>
#include <string.h>

const float k_floor_vertices[12] = {
    -10.0f, 1.0f, -10.0f, /* 0 */
    -10.0f, 1.0f, 10.0f,  /* 1 */
    10.0f,  1.0f, 10.0f,  /* 2 */
    10.0f,  1.0f, -10.0f, /* 3 */
};
const uint32_t k_floor_indices[6] = {0, 1, 2, 0, 2, 3};

const float k_identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

void translation(float m[16], float x, float y, float z) {
    memcpy(m, k_identity, sizeof k_identity);
    m[12] = x;
    m[13] = y;
    m[14] = z;
}

nl_mesh_def floor_def(void) { return mesh_def_of(k_floor_vertices, 4, k_floor_indices, 2); }

uint32_t mesh_count(const nl_world* world) {
    uint32_t count = 0xdeadbeefu;
    nl_world_get_meshes(world, NULL, 0, &count);
    return count;
}

int same_id(nl_mesh_id a, nl_mesh_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

nl_ray down_ray(float x, float z, float from_y, float max_distance) {
    nl_ray r;
    r.origin[0] = x;
    r.origin[1] = from_y;
    r.origin[2] = z;
    r.direction[0] = 0.0f;
    r.direction[1] = -1.0f;
    r.direction[2] = 0.0f;
    r.max_distance = max_distance;
    return r;
}

nl_ray_hit cast_down(nl_world* world, float x, float z) {
    const nl_ray r = down_ray(x, z, 5.0f, INFINITY);
    nl_ray_hit h = nl_ray_hit_init();
    if (NL_FAILED(nl_world_cast_rays(world, &r, 1, &h))) memset(&h, 0, sizeof h);
    return h;
}

nl_segment segment(float x0, float y0, float z0, float x1, float y1, float z1) {
    nl_segment s;
    s.from[0] = x0, s.from[1] = y0, s.from[2] = z0;
    s.to[0] = x1, s.to[1] = y1, s.to[2] = z1;
    return s;
}
