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
    CHECK(same_agent(build.agent, agent));
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
    CHECK_MSG(same_agent(info.agent, agent), "%s: info.agent is (%g %g %g %g), the def's (%g %g %g %g)", label,
              info.agent.radius, info.agent.height, info.agent.max_climb, info.agent.max_slope, agent.radius,
              agent.height, agent.max_climb, agent.max_slope);
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
    def.agent = agent;
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
                              strstr(made_for, "\"cell_height\":0.2") && strstr(made_for, "\"partition\":\"watershed\""),
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
    def.agent.radius = -1.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "radius");
    def.agent = agent;
    def.agent.height = 0.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "height");
    def.agent = agent;
    def.agent.max_slope = 90.0f;
    CHECK_BUILD_FAILS(world, &def, NL_STATUS_INVALID_ARGUMENT, "max_slope");
    def.agent = agent;
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

ABI_SECTION(navmesh_build, ABI_CASE(defaults), ABI_CASE(recast));
