/*
 * Building navmeshes (navlink.h, recast.h): nl_navmesh_build with the built-in Recast builder on the box
 * of navmesh_scene.h, its defaults, settings by struct and JSON, and refusals.
 */
#include "abi_test.h"
#include "navmesh_scene.h"
#include "scene.h"

#include <navlink/recast.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void defaults(void) {
    const nl_agent_type agent = nl_default_agent_type();
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    const nl_recast_settings recast = nl_default_recast_settings();

    CHECK(build.size == sizeof(nl_navmesh_build_def));
    CHECK_THAT(build.builder == NULL || strcmp(build.builder, "recast") == 0,
               "nl_default_navmesh_build_def: builder \"recast\" (or NULL, which means it)");
    CHECK(same_agent(build.agent_type, agent));
    CHECK(build.settings == NULL && build.settings_json == NULL && build.settings_json_length == 0);

    CHECK(recast.size == sizeof(nl_recast_settings));
    CHECK(recast.cell_size == 0.3f);
    CHECK(recast.cell_height == 0.2f);
    CHECK(recast.region_min_size == 8.0f);
    CHECK(recast.region_merge_size == 20.0f);
    CHECK(recast.edge_max_length == 12.0f);
    CHECK(recast.edge_max_error == 1.3f);
    CHECK(recast.vertices_per_polygon == 6);
    CHECK(recast.detail_sample_distance == 6.0f);
    CHECK(recast.detail_sample_max_error == 1.0f);
    CHECK(recast.partition == NL_RECAST_PARTITION_WATERSHED);
    CHECK(recast.filter_low_hanging_obstacles == 1 && recast.filter_ledge_spans == 1 &&
          recast.filter_walkable_low_height_spans == 1);
    CHECK(recast.reserved == 0);
}

/* A built navmesh of the box: on its top (Recast's sits up to two cell heights above the floor, as the
   header says: from 1 to 1 + 2 * cell_height), inside it, and well-formed. */
static void check_box_navmesh(const nl_world* world, nl_navmesh_id id, nl_agent_type agent, float cell_height,
                              const char* label) {
    const float top = 1.0f, highest = top + 2.0f * cell_height + 1e-3f;
    const nl_navmesh_info info = navmesh_info(world, id);
    const float point[3] = {1.0f, 3.0f, -2.0f}, half[3] = {2.0f, 4.0f, 2.0f};
    nl_nav_point nearest;
    CHECK_MSG(info.polygon_count > 0 && info.vertex_count >= 3 && info.boundary_edge_count >= 3,
              "%s: %u polygons, %u vertices, %u boundary edges", label, (unsigned)info.polygon_count,
              (unsigned)info.vertex_count, (unsigned)info.boundary_edge_count);
    CHECK_MSG(same_agent(info.agent_type, agent), "%s: info.agent is (%g %g %g %g), the def's (%g %g %g %g)", label,
              info.agent_type.radius, info.agent_type.height, info.agent_type.max_climb, info.agent_type.max_slope,
              agent.radius, agent.height, agent.max_climb, agent.max_slope);
    /* On the top, inside the box, reaching near its edges (less the agent's radius). */
    CHECK_MSG(info.bounds_min[0] >= -10.0f && info.bounds_max[0] <= 10.0f && info.bounds_min[2] >= -10.0f &&
                  info.bounds_max[2] <= 10.0f && info.bounds_min[0] < -8.0f && info.bounds_max[0] > 8.0f &&
                  info.bounds_min[2] < -8.0f && info.bounds_max[2] > 8.0f,
              "%s: bounds x %g..%g, z %g..%g", label, info.bounds_min[0], info.bounds_max[0], info.bounds_min[2],
              info.bounds_max[2]);
    CHECK_MSG(info.bounds_min[1] >= top - 1e-3f && info.bounds_max[1] <= highest,
              "%s: bounds y %g..%g, the top is at %g (%g with two cell heights)", label, info.bounds_min[1],
              info.bounds_max[1], top, highest);
    CHECK_OK(nl_navmesh_find_nearest(world, id, point, 1, half, &nearest));
    CHECK_MSG(nearest.found == 1 && nearest.polygon < info.polygon_count && nearest.point[1] >= top - 1e-3f &&
                  nearest.point[1] <= highest && fabsf(nearest.point[0] - 1.0f) <= 1e-3f &&
                  fabsf(nearest.point[2] + 2.0f) <= 1e-3f,
              "%s: the point over the box's middle finds (%g %g %g) on polygon %u", label, nearest.point[0],
              nearest.point[1], nearest.point[2], (unsigned)nearest.polygon);
    check_navmesh_structure(world, id, label);
}

static void recast(void) {
    nl_world* world = make_world(2);
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id id = {0u, 0u}, second = {0u, 0u};
    nl_agent_type agent;

    /* An empty world: nothing to walk on is a failure, not an empty navmesh. */
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "walkable");
    /* Only a wall: nothing flat enough. */
    {
        static const float wall[] = {0, 0, 0, 0, 3, 0, 0, 3, 5, 0, 0, 5};
        static const uint32_t quad[] = {0, 1, 2, 0, 2, 3};
        nl_mesh_def mesh = nl_default_mesh_def();
        nl_mesh_id wall_id = {0u, 0u};
        mesh.vertices = wall;
        mesh.vertex_count = 4;
        mesh.indices = quad;
        mesh.triangle_count = 2;
        CHECK_OK(nl_mesh_add(world, &mesh, &wall_id));
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "walkable");
        CHECK_OK(nl_mesh_remove(world, wall_id));
    }

    add_floor_box(world);
    agent.radius = 0.5f;
    agent.height = 1.8f;
    agent.max_climb = 0.4f;
    agent.max_slope = 40.0f;
    def.agent_type = agent;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK(nl_navmesh_is_valid(world, id) == 1);
    CHECK(navmesh_count(world) == 1);
    check_box_navmesh(world, id, agent, 0.2f, "recast, defaults");

    /* builder NULL means "recast". */
    def.builder = NULL;
    CHECK_OK(nl_navmesh_build(world, &def, &second));
    CHECK(!same_navmesh(id, second));
    check_box_navmesh(world, second, agent, 0.2f, "recast, builder NULL");
    def.builder = "recast";

    /* Settings as JSON, and as a struct. */
    {
        static const char json[] = "{\"cell_size\": 0.2}";
        static const char json_more[] =
            "{\"cell_height\": 0.1, \"partition\": \"monotone\", \"vertices_per_polygon\": 3}";
        nl_recast_settings settings = nl_default_recast_settings();
        nl_navmesh_info info;
        def.settings_json = json;
        def.settings_json_length = strlen(json);
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.2f, "recast, cell_size 0.2 (JSON)");
        def.settings_json = json_more;
        def.settings_json_length = strlen(json_more);
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.1f, "recast, monotone triangles (JSON)");
        {
            /* vertices_per_polygon 3: every polygon a triangle. */
            uint32_t p, triangles = 1;
            info = navmesh_info(world, id);
            for (p = 0; p < info.polygon_count; ++p) {
                nl_nav_polygon poly = nl_nav_polygon_init();
                if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &poly)) || poly.vertex_count != 3) triangles = 0;
            }
            CHECK_THAT(triangles, "settings_json vertices_per_polygon 3 gives triangles only");
        }
        def.settings_json = NULL;
        def.settings_json_length = 0;
        settings.cell_size = 0.25f;
        def.settings = &settings;
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        check_box_navmesh(world, id, agent, 0.2f, "recast, cell_size 0.25 (struct)");

        /* Struct and JSON together: the JSON is applied over the struct. */
        {
            static const char triangles_json[] = "{\"vertices_per_polygon\": 3}";
            uint32_t p, triangles = 1;
            def.settings_json = triangles_json;
            def.settings_json_length = strlen(triangles_json);
            CHECK_OK(nl_navmesh_build(world, &def, &id));
            check_box_navmesh(world, id, agent, 0.2f, "recast, struct and JSON");
            info = navmesh_info(world, id);
            for (p = 0; p < info.polygon_count; ++p) {
                nl_nav_polygon poly = nl_nav_polygon_init();
                if (NL_FAILED(nl_navmesh_get_polygon(world, id, p, &poly)) || poly.vertex_count != 3) triangles = 0;
            }
            CHECK_THAT(triangles, "settings_json vertices_per_polygon 3 applies over a struct's 6");
            /* What it was built with is recorded whole: the struct's, the JSON's, the defaults. */
            {
                const char* made_for = navmesh_made_for(world, id);
                CHECK_MSG(strstr(made_for, "\"cell_size\":0.25") && strstr(made_for, "\"vertices_per_polygon\":3") &&
                              strstr(made_for, "\"cell_height\":0.2") &&
                              strstr(made_for, "\"partition\":\"watershed\""),
                          "the recorded settings: %s", made_for);
            }
            /* An empty string is not a JSON object. */
            def.settings_json = "";
            def.settings_json_length = 0;
            CHECK_BUILD_FAILS(world, &def, NL_STATUS_PARSE_ERROR, "settings_json");
            def.settings_json = NULL;
        }

        /* Refused settings, each naming what is wrong. */
        settings.size = 0;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "size");
        settings = nl_default_recast_settings();
        settings.cell_size = 0.0f;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        settings = nl_default_recast_settings();
        settings.vertices_per_polygon = 7;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "vertices_per_polygon");
        def.settings = NULL;
    }
    {
        static const char negative[] = "{\"cell_size\": -1}";
        static const char malformed[] = "{bad json";
        static const char unknown[] = "{\"cell_size\": 0.3, \"cel_height\": 0.2}";
        static const char not_object[] = "[0.3]";
        static const char wrong_type[] = "{\"cell_size\": \"big\"}";
        def.settings_json = negative;
        def.settings_json_length = strlen(negative);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        def.settings_json = malformed;
        def.settings_json_length = strlen(malformed);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_PARSE_ERROR, "settings_json");
        def.settings_json = unknown;
        def.settings_json_length = strlen(unknown);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cel_height");
        {
            /* Valid JSON, but a navmesh 1e18 m high: the settings' fault (INVALID_ARGUMENT), not the builder's. */
            static const char huge_cell[] = "{\"cell_height\": 1.1e18}";
            def.settings_json = huge_cell;
            def.settings_json_length = strlen(huge_cell);
            CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_height");
        }
        def.settings_json = not_object;
        def.settings_json_length = strlen(not_object);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "settings_json");
        def.settings_json = wrong_type;
        def.settings_json_length = strlen(wrong_type);
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "cell_size");
        /* The JSON is `settings_json_length` bytes: what follows is not read. */
        def.settings_json = "{\"cell_size\": 0.3}{{{";
        def.settings_json_length = 18;
        CHECK_OK(nl_navmesh_build(world, &def, &id));
        def.settings_json = NULL;
        def.settings_json_length = 3;
        CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "settings_json");
        def.settings_json_length = 0;
    }

    /* No such builder: NOT_FOUND, listing the builders there are. */
    def.builder = "nope";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "'recast'");
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "nope");
    def.builder = "";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "'recast'");
    def.builder = "recast";

    /* A bad agent, a bad def. */
    def.agent_type.radius = -1.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "radius");
    def.agent_type = agent;
    def.agent_type.height = 0.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "height");
    def.agent_type = agent;
    def.agent_type.max_slope = 90.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "max_slope");
    def.agent_type = agent;
    def.size = 0;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "size");
    def.size = sizeof def;
    {
        const uint32_t before = navmesh_count(world);
        nl_navmesh_id out = {77u, 77u};
        CHECK_INVALID(nl_navmesh_build(NULL, &def, &out), "world");
        CHECK_INVALID(nl_navmesh_build(world, NULL, &out), "def");
        CHECK_INVALID(nl_navmesh_build(world, &def, NULL), "out_id");
        CHECK(out.index1 == 77u && navmesh_count(world) == before);
    }
    nl_world_destroy(world);
}

/* ---------------------------------------------------------------------------------------------
 * What a build takes from the level: winding, mesh roles, areas; and its progress
 * ------------------------------------------------------------------------------------------- */

/* Registers a horizontal quad x in [x0, x1], z in [z0, z1] at height y, its front up (counter-
   clockwise seen from above) or, with `front_down`, wound the other way. */
static nl_mesh_id add_quad(nl_world* world, float x0, float z0, float x1, float z1, float y, int front_down,
                           uint32_t flags, uint32_t area, const float* transform) {
    const float v[12] = {x0, y, z0, x0, y, z1, x1, y, z1, x1, y, z0};
    static const uint32_t up[6] = {0, 1, 2, 0, 2, 3}, down[6] = {0, 2, 1, 0, 3, 2};
    nl_mesh_def def = nl_default_mesh_def();
    nl_mesh_id id = {0u, 0u};
    def.vertices = v;
    def.vertex_count = 4;
    def.indices = front_down ? down : up;
    def.triangle_count = 2;
    def.flags = flags;
    def.area = area;
    def.transform = transform;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    return id;
}

/* A closed crate: x and z in [x0, x0 + side], y in [0, height], every face out. */
static nl_mesh_id add_crate(nl_world* world, float x0, float z0, float side, float height, uint32_t flags) {
    const float x1 = x0 + side, z1 = z0 + side;
    const float v[24] = {x0, 0,      z0, x1, 0,      z0, x1, 0,      z1, x0, 0,      z1,
                         x0, height, z0, x1, height, z0, x1, height, z1, x0, height, z1};
    static const uint32_t t[36] = {4, 7, 6, 4, 6, 5, /* top, up */ 0,
                                   1, 2, 0, 2, 3, /* bottom, down */
                                   0, 4, 5, 0, 5, 1, 1,
                                   5, 6, 1, 6, 2, 2, 6,
                                   7, 2, 7, 3, 3, 7, 4,
                                   3, 4, 0};
    nl_mesh_def def = nl_default_mesh_def();
    nl_mesh_id id = {0u, 0u};
    def.vertices = v;
    def.vertex_count = 8;
    def.indices = t;
    def.triangle_count = 12;
    def.flags = flags;
    CHECK_OK(nl_mesh_add(world, &def, &id));
    return id;
}

/* The navmesh polygon within (0.4, 0.3, 0.4) of (x, y, z), or -1; its area into *area. */
static int polygon_at(const nl_world* world, nl_navmesh_id navmesh, float x, float y, float z, uint32_t* area) {
    const float p[3] = {x, y, z}, half[3] = {0.4f, 0.3f, 0.4f};
    nl_nav_point hit;
    nl_nav_polygon polygon = nl_nav_polygon_init();
    if (NL_FAILED(nl_navmesh_find_nearest(world, navmesh, p, 1, half, &hit)) || !hit.found) return -1;
    if (area && NL_SUCCEEDED(nl_navmesh_get_polygon(world, navmesh, hit.polygon, &polygon))) *area = polygon.area;
    return (int)hit.polygon;
}

static nl_navmesh_id build(nl_world* world) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id id = {0u, 0u};
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    return id;
}

/* A level whose big floor is wound clockwise and not flagged, beside a small platform wound right:
   the build succeeds on the platform, and says the floor looks turned over (the log, the navmesh's
   info); flagged NL_MESH_CLOCKWISE, nothing is said. */
static void turned_over_warning(void) {
    warnings heard;
    nl_navmesh_info info = nl_navmesh_info_init();
    nl_world* world = make_listening_world(&heard);
    add_quad(world, -20, -20, 20, 20, 0, 1, 0, 0, NULL);
    add_quad(world, 30, 0, 34, 4, 0, 0, 0, 0, NULL);
    CHECK_OK(nl_navmesh_get_info(world, build(world), &info));
    CHECK(info.turned_over_mesh_count == 1);
    CHECK(heard.count == 1);
    CHECK(strstr(heard.text, "1 mesh that looks wound clockwise") != NULL);
    CHECK(strstr(heard.text, "turned over, it would hold 1600 m2 of floor for this agent, as given 0 m2") != NULL);
    CHECK(strstr(heard.text, "NL_MESH_CLOCKWISE") != NULL);
    nl_world_destroy(world);

    world = make_listening_world(&heard);
    add_quad(world, -20, -20, 20, 20, 0, 1, NL_MESH_CLOCKWISE, 0, NULL);
    add_quad(world, 30, 0, 34, 4, 0, 0, 0, 0, NULL);
    info = nl_navmesh_info_init();
    CHECK_OK(nl_navmesh_get_info(world, build(world), &info));
    CHECK(info.turned_over_mesh_count == 0);
    CHECK(heard.count == 0);
    nl_world_destroy(world);
}

static void winding(void) {
    static const float mirror_x[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_mesh_info info = nl_mesh_info_init();
    nl_world* world = make_world(2);
    /* Wound clockwise (fronts down): nothing to walk on, and the message says why and what to set. */
    nl_mesh_id floor = add_quad(world, -10, -10, 10, 10, 0, 1, 0, 0, NULL);
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND,
                      "2 of the level's 2 triangles would be flat enough turned over");
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_NOT_FOUND, "NL_MESH_CLOCKWISE");
    CHECK_OK(nl_mesh_remove(world, floor));
    /* The same triangles flagged clockwise are turned over and walked on; the flag is kept. */
    floor = add_quad(world, -10, -10, 10, 10, 0, 1, NL_MESH_CLOCKWISE, 0, NULL);
    CHECK_OK(nl_mesh_get_info(world, floor, &info));
    CHECK(info.flags == NL_MESH_CLOCKWISE);
    CHECK(polygon_at(world, build(world), 0, 0, 0, NULL) >= 0);
    CHECK_OK(nl_mesh_remove(world, floor));
    /* A mirroring transform keeps the mesh's front up: a counter-clockwise floor mirrored in x stays walkable. */
    nl_world_destroy(world);
    world = make_world(2);
    add_quad(world, 0, -10, 20, 10, 0, 0, 0, 0, mirror_x);
    CHECK(polygon_at(world, build(world), -10, 0, 0, NULL) >= 0);
    nl_world_destroy(world);
}

static void mesh_roles(void) {
    static const float down[3] = {0, -1, 0};
    nl_world* world = make_world(2);
    nl_mesh_id crate, ceiling;
    nl_navmesh_id navmesh;
    nl_ray ray;
    nl_ray_hit hit = nl_ray_hit_init();
    nl_mesh_info info = nl_mesh_info_init();
    add_quad(world, -10, -10, 10, 10, 0, 0, 0, 0, NULL);

    /* A crate's top is walkable as any floor; flagged NL_MESH_OBSTACLE it only blocks. */
    crate = add_crate(world, 3, 3, 4, 1, 0);
    navmesh = build(world);
    CHECK_THAT(polygon_at(world, navmesh, 5, 1, 5, NULL) >= 0, "an ordinary crate's top is walkable");
    CHECK_OK(nl_mesh_remove(world, crate));
    crate = add_crate(world, 3, 3, 4, 1, NL_MESH_OBSTACLE);
    CHECK_OK(nl_mesh_get_info(world, crate, &info));
    CHECK(info.flags == NL_MESH_OBSTACLE);
    navmesh = build(world);
    CHECK_THAT(polygon_at(world, navmesh, 5, 1, 5, NULL) < 0, "an obstacle's top is not walked on");
    CHECK_THAT(polygon_at(world, navmesh, 5, 0, 5, NULL) < 0, "the floor under an obstacle is blocked");
    CHECK_THAT(polygon_at(world, navmesh, -5, 0, 5, NULL) >= 0, "the floor beside it is walkable");

    /* A slab 1 m over the floor leaves no headroom under it; left out of navmesh builds it leaves
       the floor walkable, and rays still meet it. */
    ceiling = add_quad(world, -8, -8, -2, -2, 1.0f, 1, 0, 0, NULL);
    CHECK_THAT(polygon_at(world, build(world), -5, 0, -5, NULL) < 0, "no headroom under the slab");
    CHECK_OK(nl_mesh_remove(world, ceiling));
    ceiling = add_quad(world, -8, -8, -2, -2, 1.0f, 1, NL_MESH_NOT_IN_NAVMESH, 0, NULL);
    CHECK_THAT(polygon_at(world, build(world), -5, 0, -5, NULL) >= 0, "a slab left out of builds leaves the floor");
    ray.origin[0] = -5;
    ray.origin[1] = 5;
    ray.origin[2] = -5;
    memcpy(ray.direction, down, sizeof down);
    ray.max_distance = 10;
    CHECK_OK(nl_world_cast_rays(world, &ray, 1, &hit));
    CHECK_MSG(hit.hit == 1 && hit.mesh.index1 == ceiling.index1 && fabsf(hit.point[1] - 1.0f) < 1e-4f,
              "a ray down onto the left-out slab hits it (hit %d at y %g)", (int)hit.hit, hit.point[1]);
    nl_world_destroy(world);
}

static void mesh_areas(void) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_mesh_info info = nl_mesh_info_init();
    nl_world* world = make_world(2);
    nl_navmesh_id navmesh;
    nl_mesh_id east;
    uint32_t area = 99;
    add_quad(world, -10, -10, 0, 10, 0, 0, 0, 0, NULL);
    east = add_quad(world, 0, -10, 10, 10, 0, 0, 0, 5, NULL);
    CHECK_OK(nl_mesh_get_info(world, east, &info));
    CHECK(info.area == 5u);
    navmesh = build(world);
    CHECK(polygon_at(world, navmesh, 5, 0, 0, &area) >= 0 && area == 5u);
    area = 99;
    CHECK(polygon_at(world, navmesh, -5, 0, 0, &area) >= 0 && area == 0u);
    /* Recast keeps 6 bits of area: 62 is the builder's last. */
    CHECK_OK(nl_mesh_remove(world, east));
    east = add_quad(world, 0, -10, 10, 10, 0, 0, 0, 62, NULL);
    CHECK(polygon_at(world, build(world), 5, 0, 0, &area) >= 0 && area == 62u);
    CHECK_OK(nl_mesh_remove(world, east));
    add_quad(world, 0, -10, 10, 10, 0, 0, 0, 63, NULL);
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "areas 0..62");
    nl_world_destroy(world);
}

typedef struct progress_log {
    int calls;
    float fractions[256];
    int rasterising;       /* calls in the stage "rasterising the level" */
    const char* cancel_at; /* stop when this stage is reported */
} progress_log;

static int32_t log_progress(void* user, float fraction, const char* stage) {
    progress_log* log = (progress_log*)user;
    if (log->calls < 256) log->fractions[log->calls] = fraction;
    ++log->calls;
    if (strcmp(stage, "rasterising the level") == 0) ++log->rasterising;
    return !(log->cancel_at && strcmp(stage, log->cancel_at) == 0);
}

static void build_progress(void) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_world* world = make_world(2);
    progress_log log;
    nl_navmesh_id id = {0u, 0u};
    int i, ordered = 1;
    add_floor_box(world);
    memset(&log, 0, sizeof log);
    def.progress = log_progress;
    def.progress_user = &log;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK_MSG(log.calls >= 10 && log.calls <= 256, "%d progress calls", log.calls);
    for (i = 1; i < log.calls && i < 256; ++i) ordered = ordered && log.fractions[i] >= log.fractions[i - 1];
    CHECK_THAT(ordered, "progress never goes back");
    CHECK(log.fractions[0] == 0.0f && log.fractions[log.calls - 1] == 1.0f);
    CHECK(log.rasterising >= 1);

    /* Cancelled while rasterising: CANCELLED, nothing added, and the builder stopped there. */
    memset(&log, 0, sizeof log);
    log.cancel_at = "rasterising the level";
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_CANCELLED, "cancelled");
    CHECK(navmesh_count(world) == 1u);
    CHECK_MSG(log.rasterising == 1, "the build went on after its cancel: %d rasterising reports", log.rasterising);
    nl_world_destroy(world);
}

/* A progress callback that adds a mesh to the level in the middle of the build. */
typedef struct level_changer {
    nl_world* world;
    nl_mesh_id added;
} level_changer;

static int32_t add_mesh_mid_build(void* user, float fraction, const char* stage) {
    level_changer* c = (level_changer*)user;
    (void)fraction;
    if (c->added.index1 == 0 && strcmp(stage, "marking walkable triangles") == 0)
        c->added = add_quad(c->world, 20, 20, 24, 24, 0, 0, 0, 0, NULL);
    return 1;
}

/* The level hash a navmesh records is of the level it was built from, even when the level changes
   while it is built: loading it with NL_NAVMESH_LOAD_SAME_LEVEL matches that level, not the later one. */
static void level_hash_of_the_built_level(void) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_load_def load = nl_default_navmesh_load_def();
    nl_world* world = make_world(2);
    level_changer changer;
    nl_navmesh_id id = {0u, 0u}, loaded = {0u, 0u};
    static unsigned char file[1 << 16];
    size_t size = 0;
    add_floor_box(world);
    memset(&changer, 0, sizeof changer);
    changer.world = world;
    def.progress = add_mesh_mid_build;
    def.progress_user = &changer;
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    CHECK_THAT(changer.added.index1 != 0, "the progress callback added a mesh during the build");
    CHECK_OK(nl_navmesh_save(world, id, file, sizeof file, &size));
    load.flags = NL_NAVMESH_LOAD_SAME_LEVEL;
    CHECK_FAIL(nl_navmesh_load(world, file, size, &load, &loaded), NL_STATUS_INVALID_ARGUMENT, "not the one");
    CHECK_OK(nl_mesh_remove(world, changer.added));
    CHECK_OK(nl_navmesh_load(world, file, size, &load, &loaded));
    nl_world_destroy(world);
}

ABI_SECTION(navmesh_build, ABI_CASE(defaults), ABI_CASE(recast), ABI_CASE(winding), ABI_CASE(turned_over_warning),
            ABI_CASE(mesh_roles), ABI_CASE(mesh_areas), ABI_CASE(build_progress),
            ABI_CASE(level_hash_of_the_built_level));
