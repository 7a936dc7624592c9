/* A program outside the project that does what a game does with an installed NavLink: two platforms
 * 1.5 m apart, a navmesh built by the built-in Recast builder, jump links generated against the
 * level with Embree, and a path from one platform to the other that only a jumper can take. It
 * exercises every dependency the library links, so a static link that left one out fails here.
 * Valid C and C++: path_consumer.cpp compiles this same file as C++. Exit code 0 on success. */
#include <navlink/navlink.h>

#include <stdio.h>

static int failed(const char* what) {
    fprintf(stderr, "path consumer: %s failed: %s\n", what, nl_get_last_error_message());
    return 1;
}

/* Two 8 x 8 m platforms at the same height, x in [0, 8] and [9.5, 17.5]. */
static const float platform_vertices[] = {
    0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 8.0f, 8.0f,  0.0f, 8.0f, 8.0f,  0.0f, 0.0f,
    9.5f, 0.0f, 0.0f, 9.5f, 0.0f, 8.0f, 17.5f, 0.0f, 8.0f, 17.5f, 0.0f, 0.0f,
};
/* Counter-clockwise seen from above: the faces point up. */
static const uint32_t platform_indices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};

static int find_path(nl_world* world) {
    nl_mesh_def mesh_def = nl_default_mesh_def();
    nl_navmesh_build_def build_def = nl_default_navmesh_build_def();
    nl_path_request_def request = nl_default_path_request_def();
    nl_path_result result = nl_path_result_init();
    nl_mesh_id mesh;
    nl_navmesh_id navmesh;
    uint32_t point_count = 0;

    mesh_def.vertices = platform_vertices;
    mesh_def.vertex_count = 8;
    mesh_def.indices = platform_indices;
    mesh_def.triangle_count = 4;
    if (NL_FAILED(nl_mesh_add(world, &mesh_def, &mesh))) return failed("nl_mesh_add");
    if (NL_FAILED(nl_navmesh_build(world, &build_def, &navmesh))) return failed("nl_navmesh_build");
    if (NL_FAILED(nl_navmesh_generate_links(world, navmesh, NULL, NULL, NULL, NULL)))
        return failed("nl_navmesh_generate_links");

    request.navmesh = navmesh;
    request.start[0] = 3.0f;
    request.start[2] = 4.0f;
    request.goal[0] = 14.0f;
    request.goal[2] = 4.0f;
    request.capabilities.max_jump_distance = 3.0f;
    request.capabilities.max_jump_height = 1.0f;
    request.capabilities.max_drop_height = 1.0f;
    request.accept_partial = 0;
    if (NL_FAILED(nl_path_find(world, &request, &result, NULL, 0, &point_count))) return failed("nl_path_find");
    if (result.outcome != NL_PATH_COMPLETE || result.links_used != 1) {
        fprintf(stderr, "path consumer: expected a complete path over one jump, got outcome %u with %u links\n",
                (unsigned)result.outcome, (unsigned)result.links_used);
        return 1;
    }
    printf("path over %u link, %.1f m, %u points\n", (unsigned)result.links_used, (double)result.length,
           (unsigned)point_count);
    return 0;
}

int main(void) {
    nl_world_def world_def = nl_default_world_def();
    nl_world* world = NULL;
    int rc;

    world_def.worker_count = 1;
    if (NL_FAILED(nl_world_create(&world_def, &world))) return failed("nl_world_create");
    rc = find_path(world);
    nl_world_destroy(world);
    return rc;
}
