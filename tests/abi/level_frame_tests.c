/*
 * A level as engines give it (issue 33): vertices in another unit than metres or with z up, said at
 * registration (nl_mesh_def.metres_per_unit, up_axis) and brought into NavLink's metres with y up; not
 * said, a navmesh build that finds the level's size against its agent's, or its floors, suggest them
 * succeeds and says so in the log and in nl_navmesh_info.build_warnings. Strict C11 through the C ABI.
 *
 * The level is a closed room seen from inside, 9 x 9 m and 4 m tall (x and z in [0, 9]): its floor
 * faces up, its ceiling down, its walls in. Given with z up, NavLink's (x, y, z) is (x, -z, y) in the
 * numbers; read with y up those numbers make its wall at z = 9 a floor of 9 x 4 m under the wall at
 * z = 0, 36 m2 against the room's 81.
 */
#include <math.h>
#include <string.h>

#include "abi_test.h"
#include "navmesh_scene.h"

/* `units` numbers a metre; with `z_up`, given z up. */
static nl_status add_room(nl_world* world, float units, int z_up, float metres_per_unit, uint32_t up_axis,
                          nl_mesh_id* out) {
    static const float corners[8][3] = {{0, 0, 0}, {9, 0, 0}, {9, 0, 9}, {0, 0, 9},
                                        {0, 4, 0}, {9, 4, 0}, {9, 4, 9}, {0, 4, 9}};
    /* A crate's faces (out) wound the other way: in. */
    static const uint32_t inward[36] = {4, 6, 7, 4, 5, 6, /* ceiling, down */ 0,
                                        2, 1, 0, 3, 2, /* floor, up */
                                        0, 5, 4, 0, 1, 5, 1,
                                        6, 5, 1, 2, 6, 2, 7,
                                        6, 2, 3, 7, 3, 4, 7,
                                        3, 0, 4};
    float v[24];
    int i;
    nl_mesh_def def = nl_default_mesh_def();
    for (i = 0; i < 8; ++i) {
        v[3 * i] = units * corners[i][0];
        v[3 * i + 1] = units * (z_up ? -corners[i][2] : corners[i][1]);
        v[3 * i + 2] = units * (z_up ? corners[i][1] : corners[i][2]);
    }
    def.vertices = v;
    def.vertex_count = 8;
    def.indices = inward;
    def.triangle_count = 12;
    def.metres_per_unit = metres_per_unit;
    def.up_axis = up_axis;
    return nl_mesh_add(world, &def, out);
}

/* The room's floor is walkable at its middle, 0.0 m up. */
static int walkable_at_middle(nl_world* world, nl_navmesh_id navmesh) {
    const float p[3] = {4.5f, 0.0f, 4.5f}, half[3] = {0.5f, 0.5f, 0.5f};
    nl_nav_point hit;
    return NL_SUCCEEDED(nl_navmesh_find_nearest(world, navmesh, p, 1, half, &hit)) && hit.found &&
           fabsf(hit.point[1]) < 0.3f;
}

static nl_navmesh_id build_coarse(nl_world* world) {
    /* Cells of 1 m: the room read in centimetres is 900 m wide. */
    static const char coarse[] = "{\"cell_size\": 1.0, \"cell_height\": 0.5}";
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id id = {0u, 0u};
    def.settings_json = coarse;
    def.settings_json_length = strlen(coarse);
    CHECK_OK(nl_navmesh_build(world, &def, &id));
    return id;
}

/* The room as it is in metres with y up: built with the defaults, walked on at its middle, nothing
   warned of in the build or the log. Destroys `world`. */
static void expect_the_room(nl_world* world, const warnings* heard) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh = {0u, 0u};
    CHECK_OK(nl_navmesh_build(world, &def, &navmesh));
    CHECK(walkable_at_middle(world, navmesh));
    CHECK(navmesh_info(world, navmesh).build_warnings == 0);
    CHECK_THAT(heard->count == 0, heard->text);
    nl_world_destroy(world);
}

static void centimetres(void) {
    warnings heard;
    nl_mesh_id room;
    nl_mesh_info mesh = nl_mesh_info_init();
    nl_world* world = make_listening_world(&heard);
    nl_navmesh_info info;
    /* Not said: walls 400 m tall for a body of 2 m. */
    CHECK_OK(add_room(world, 100.0f, 0, 0.0f, NL_UP_AXIS_NOT_SAID, &room));
    info = navmesh_info(world, build_coarse(world));
    CHECK(info.build_warnings == NL_BUILD_WARNING_UNITS);
    CHECK(heard.count == 1);
    CHECK_THAT(strstr(heard.text, "the level's walls are 400 m tall") != NULL, heard.text);
    CHECK(strstr(heard.text, "nl_mesh_def.metres_per_unit (0.01 for centimetres") != NULL);
    nl_world_destroy(world);

    /* Said: brought to metres, and nothing to warn of. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 100.0f, 0, 0.01f, NL_UP_AXIS_NOT_SAID, &room));
    CHECK_OK(nl_mesh_get_info(world, room, &mesh));
    CHECK(mesh.metres_per_unit == 0.01f && mesh.up_axis == NL_UP_AXIS_NOT_SAID);
    CHECK(near3(mesh.bounds_max, 9.0f, 4.0f, 9.0f, 1e-4f));
    expect_the_room(world, &heard);

    /* Metres said: the host knows best, nothing is said. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 100.0f, 0, 1.0f, NL_UP_AXIS_NOT_SAID, &room));
    CHECK(navmesh_info(world, build_coarse(world)).build_warnings == 0);
    CHECK(heard.count == 0);
    nl_world_destroy(world);
}

static void too_small(void) {
    /* The room in kilometres' numbers (0.009 across) for a body 2 m tall: nothing to stand on, and the
       build's failure is preceded by the warning that says why. */
    warnings heard;
    nl_mesh_id room;
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh = {0u, 0u};
    nl_world* world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 0.001f, 0, 0.0f, NL_UP_AXIS_NOT_SAID, &room));
    CHECK(nl_navmesh_build(world, &def, &navmesh) == (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    CHECK_THAT(strstr(heard.text, "the whole level is 0.009 m across, less than two agents are tall") != NULL,
               heard.text);
    nl_world_destroy(world);
    /* Said in kilometres, it is the room. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 0.001f, 0, 1000.0f, NL_UP_AXIS_NOT_SAID, &room));
    expect_the_room(world, &heard);
}

static void z_up(void) {
    warnings heard;
    nl_mesh_id room;
    nl_mesh_info mesh = nl_mesh_info_init();
    nl_navmesh_info info;
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    nl_navmesh_id navmesh = {0u, 0u};
    nl_world* world = make_listening_world(&heard);
    /* Not said: read with y up the room stands on its side, and the build says so. */
    CHECK_OK(add_room(world, 1.0f, 1, 0.0f, NL_UP_AXIS_NOT_SAID, &room));
    CHECK_OK(nl_navmesh_build(world, &def, &navmesh));
    info = navmesh_info(world, navmesh);
    CHECK(info.build_warnings == NL_BUILD_WARNING_Z_UP);
    CHECK(!walkable_at_middle(world, navmesh));
    CHECK_THAT(strstr(heard.text, "with z up it would hold 81 m2 of floor for this agent, with y up 36 m2") != NULL,
               heard.text);
    CHECK(strstr(heard.text, "NL_UP_AXIS_Z") != NULL);
    nl_world_destroy(world);

    /* Said: turned to y up when registered, the room's floor is walked on. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 1.0f, 1, 0.0f, NL_UP_AXIS_Z, &room));
    CHECK_OK(nl_mesh_get_info(world, room, &mesh));
    CHECK(mesh.up_axis == NL_UP_AXIS_Z);
    CHECK(near3(mesh.bounds_min, 0.0f, 0.0f, 0.0f, 1e-5f) && near3(mesh.bounds_max, 9.0f, 4.0f, 9.0f, 1e-5f));
    expect_the_room(world, &heard);

    /* Centimetres and z up together (an exporter's numbers): the same room. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 100.0f, 1, 0.01f, NL_UP_AXIS_Z, &room));
    CHECK_OK(nl_mesh_get_info(world, room, &mesh));
    CHECK(near3(mesh.bounds_max, 9.0f, 4.0f, 9.0f, 1e-4f));
    expect_the_room(world, &heard);

    /* Y up said: a level that only looks z up is the host's to know; nothing is said. */
    world = make_listening_world(&heard);
    CHECK_OK(add_room(world, 1.0f, 1, 0.0f, NL_UP_AXIS_Y, &room));
    CHECK_OK(nl_navmesh_build(world, &def, &navmesh));
    CHECK(navmesh_info(world, navmesh).build_warnings == 0);
    CHECK(heard.count == 0);
    nl_world_destroy(world);
}

static void bad_frames(void) {
    nl_world* world = make_world(1);
    nl_mesh_id room = {0u, 0u};
    const float bad_units[] = {-1.0f, 1e-7f, 2e6f, NAN, INFINITY};
    size_t i;
    for (i = 0; i < sizeof bad_units / sizeof bad_units[0]; ++i) {
        CHECK(add_room(world, 1.0f, 0, bad_units[i], NL_UP_AXIS_NOT_SAID, &room) ==
              (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
        CHECK_THAT(strstr(nl_get_last_error_message(), "def->metres_per_unit is") != NULL, nl_get_last_error_message());
    }
    CHECK(add_room(world, 1.0f, 0, 0.0f, 3u, &room) == (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK_THAT(strstr(nl_get_last_error_message(), "def->up_axis is 3") != NULL, nl_get_last_error_message());
    CHECK(room.index1 == 0u);
    {
        /* A scale that takes the level past the coordinate limit is refused too. */
        const float far = 0.5f * NL_COORDINATE_LIMIT;
        CHECK(add_room(world, far, 0, 1e6f, NL_UP_AXIS_NOT_SAID, &room) ==
              (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    }
    {
        uint32_t count = 1u;
        CHECK_OK(nl_world_get_meshes(world, NULL, 0, &count));
        CHECK(count == 0u);
    }
    nl_world_destroy(world);
}

ABI_SECTION(level_frame, ABI_CASE(centimetres), ABI_CASE(too_small), ABI_CASE(z_up), ABI_CASE(bad_frames));
