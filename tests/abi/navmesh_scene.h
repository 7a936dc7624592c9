/*
 * The navmeshes the navmesh, build and plugin cases stand on, and the checks every navmesh must pass.
 * Strict C11 through the C ABI only.
 *
 * The grid most cases use is a 2 x 2 grid of 1 m squares at y = 0.5, x and z in [-1, 1]: nine
 * vertices, vertex r * 3 + c at (-1 + c, 0.5, -1 + r), and four quads wound counter-clockwise seen
 * from above (normal +Y). The polygon of the quadrant x in [0, 1], z in [-1, 0] is "quadrant 1", and
 * so on: quadrant = 2 * (z > 0) + (x > 0). Expectations are found by position (a polygon's centre, an
 * edge's ends), never by the order the library happens to store things in.
 */
#ifndef NAVLINK_ABI_NAVMESH_SCENE_H
#define NAVLINK_ABI_NAVMESH_SCENE_H

#include <navlink/navlink.h>

#define GRID_Y 0.5f

extern const float k_grid_vertices[27];
/* Counter-clockwise seen from above: (x0, z0) -> (x0, z1) -> (x1, z1) -> (x1, z0). */
extern const uint32_t k_grid_quads[16];
extern const uint8_t k_quad_counts[4];

/* The grid with polygon_vertex_counts: four quads. */
nl_navmesh_def grid_def(void);

/* Which quadrant of the grid a point (seen from above) lies in; the point must not be on x = 0 or z = 0. */
int quadrant_of(float x, float z);

/* Counts of the world's navmeshes and plugins (0xdeadbeef if the call failed). */
uint32_t navmesh_count(const nl_world* world);
uint32_t plugin_count(const nl_world* world);

int same_navmesh(nl_navmesh_id a, nl_navmesh_id b);
int same_plugin(nl_plugin_id a, nl_plugin_id b);
int same_agent(nl_agent_type a, nl_agent_type b);

/* The navmesh's info (all zero if the call failed). */
nl_navmesh_info navmesh_info(const nl_world* world, nl_navmesh_id id);
/* What a saved file of the navmesh says it was made for (nl_navmesh_file_describe's JSON), in a
   static buffer ("" and a failed check if saving or describing failed). */
const char* navmesh_made_for(const nl_world* world, nl_navmesh_id id);
/* The navmesh's vertices in a malloc'ed array (3 floats each); NULL on failure. */
float* navmesh_vertices(const nl_world* world, nl_navmesh_id id, uint32_t* out_count);
/* The navmesh's boundary edges in a malloc'ed array; NULL on failure. */
nl_boundary_edge* navmesh_edges(const nl_world* world, nl_navmesh_id id, uint32_t* out_count);

float dot3(const float* a, const float* b);
float length3(const float* a);
int near3(const float* a, float x, float y, float z, float tol);
int equal3(const float* a, const float* b);
/* Twice the signed area of a polygon seen from above; positive when counter-clockwise with +Y up. */
float area_from_above(const float* xyz, const nl_nav_polygon* p);

/* Structure every navmesh must have, whatever made it: corners in range and counter-clockwise from
   above, unit upward normals, symmetric neighbours (across the same two vertices), portal and boundary
   counts that agree with the polygons, and boundary edges that are the polygons' unconnected edges with
   unit outward directions square to the edge and away from the polygon. Returns the number of
   problems (each one also a failed check). */
int check_navmesh_structure(const nl_world* world, nl_navmesh_id id, const char* label);

/* The grid's own answers: 9 vertices where the grid has them, `polygons` polygons (4 quads or 8
   triangles) covering the four quadrants, the outline of 8 unit edges with outward pointing straight
   away from the square, area ids by quadrant (`areas` NULL: all 0). */
void check_grid_navmesh(const nl_world* world, nl_navmesh_id id, uint32_t polygons, const uint8_t* areas,
                        const char* label);

/* Registers a box 20 m x 1 m x 20 m, its top at y = 1 (a checked nl_mesh_add). */
nl_mesh_id add_floor_box(nl_world* world);

/* The warnings a world logged, joined (each on its own line). */
typedef struct warnings {
    char text[4096];
    int count;
} warnings;

/* A world of 2 workers whose log's warnings go into `heard` (cleared first). */
nl_world* make_listening_world(warnings* heard);

/* One refused nl_navmesh_build: `detail` naming `needle`, nothing added, out_id untouched. */
#define CHECK_BUILD_FAILS(world, def, detail, needle) \
    check_build_fails((world), (def), (detail), (needle), __FILE__, __LINE__)
void check_build_fails(nl_world* world, const nl_navmesh_build_def* def, nl_status detail, const char* needle,
                       const char* file, int line);

/* The plugin's description (all zero if the call failed). */
nl_plugin_description describe(const nl_world* world, nl_plugin_id id);

#endif /* NAVLINK_ABI_NAVMESH_SCENE_H */
