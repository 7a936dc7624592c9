/* A program outside the project that uses an installed NavLink: it creates a world, adds a triangle,
 * casts a ray onto it and prints the version. Exit code 0 on success. */
#include <navlink/navlink.h>

#include <math.h>
#include <stdio.h>

static int fail(const char* what) {
    fprintf(stderr, "consumer: %s failed: %s\n", what, nl_get_last_error_message());
    return 1;
}

int main(void) {
    static const float vertices[] = {-1.0f, 0.0f, -1.0f, -1.0f, 0.0f, 2.0f, 2.0f, 0.0f, -1.0f};
    static const uint32_t indices[] = {0, 1, 2};
    const nl_version version = nl_get_version();
    nl_world_def world_def = nl_default_world_def();
    nl_mesh_def mesh_def = nl_default_mesh_def();
    nl_world* world = NULL;
    nl_mesh_id mesh;
    nl_ray ray = {{0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 10.0f};
    nl_ray_hit hit = nl_ray_hit_init();
    int ok;

    if (version.major != NL_VERSION_MAJOR || version.minor != NL_VERSION_MINOR || version.patch != NL_VERSION_PATCH) {
        fprintf(stderr, "consumer: header %d.%d.%d, library %d.%d.%d\n", NL_VERSION_MAJOR, NL_VERSION_MINOR,
                NL_VERSION_PATCH, (int)version.major, (int)version.minor, (int)version.patch);
        return 1;
    }
    world_def.worker_count = 1;
    if (NL_FAILED(nl_world_create(&world_def, &world))) return fail("nl_world_create");
    mesh_def.vertices = vertices;
    mesh_def.vertex_count = 3;
    mesh_def.indices = indices;
    mesh_def.triangle_count = 1;
    if (NL_FAILED(nl_mesh_add(world, &mesh_def, &mesh))) {
        nl_world_destroy(world);
        return fail("nl_mesh_add");
    }
    if (NL_FAILED(nl_world_cast_rays(world, &ray, 1, &hit))) {
        nl_world_destroy(world);
        return fail("nl_world_cast_rays");
    }
    ok = hit.hit == 1 && fabsf(hit.distance - 2.0f) < 1e-5f && hit.mesh.index1 == mesh.index1 &&
         hit.mesh.revision == mesh.revision && hit.triangle == 0;
    nl_world_destroy(world);
    if (!ok) {
        fprintf(stderr, "consumer: wrong hit (hit %d, distance %g)\n", (int)hit.hit, (double)hit.distance);
        return 1;
    }
    printf("NavLink %d.%d.%d: hit at distance %g\n", (int)version.major, (int)version.minor, (int)version.patch,
           (double)hit.distance);
    return 0;
}
