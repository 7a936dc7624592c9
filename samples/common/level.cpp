#include "level.h"

#include "obj_reader.h"
#include "sample_error.h"

namespace nl::samples {
namespace {

void read_info(nl_world* world, Level& level) {
    level.info.size = sizeof level.info;
    check(nl_mesh_get_info(world, level.mesh, &level.info), "reading the level's size");
}

}  // namespace

Level load_level_file(nl_world* world, const std::string& path, bool for_drawing, const LevelFrame& frame) {
    Level level;
    level.name = path;
    nl_mesh_def def = nl_default_mesh_def();
    def.flags = frame.flags;
    def.metres_per_unit = frame.metres_per_unit;
    def.up_axis = frame.up_axis;
    check(nl_mesh_add_obj_file(world, path.c_str(), &def, &level.mesh), "loading the level");
    if (for_drawing) {
        const ObjPolygons obj = read_obj_file(path);
        level.positions = obj.positions;
        level.triangles = obj.fan_triangles();
        const float scale = frame.metres_per_unit > 0.0f ? frame.metres_per_unit : 1.0f;
        for (size_t i = 0; i + 2 < level.positions.size(); i += 3) {
            float* p = &level.positions[i];
            const float y = p[1], z = p[2];
            if (frame.up_axis == NL_UP_AXIS_Z) p[1] = z, p[2] = -y;
            for (int k = 0; k < 3; ++k) p[k] *= scale;
        }
    }
    read_info(world, level);
    return level;
}

Level add_generated_level(nl_world* world, const levelgen::GeneratedLevel& generated, const std::string& name) {
    Level level;
    level.name = name;
    level.positions = generated.positions;
    level.triangles = generated.indices;
    level.markers = generated.markers;
    nl_mesh_def def = nl_default_mesh_def();
    def.vertices = level.positions.data();
    def.vertex_count = generated.vertex_count();
    def.indices = level.triangles.data();
    def.triangle_count = generated.triangle_count();
    check(nl_mesh_add(world, &def, &level.mesh), "registering the generated level");
    read_info(world, level);
    return level;
}

}  // namespace nl::samples
