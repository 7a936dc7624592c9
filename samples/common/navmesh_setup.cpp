#include "navmesh_setup.h"

#include "obj_reader.h"
#include "sample_error.h"

namespace nl::samples {

nl_navmesh_id build_navmesh(nl_world* world, const nl_agent_type& body, const std::string& recast_json,
                            nl_mesh_id carrier, nl_progress_fn* progress, void* progress_user) {
    nl_navmesh_build_def def = nl_default_navmesh_build_def();
    def.agent_type = body;
    def.carrier = carrier;
    def.progress = progress;
    def.progress_user = progress_user;
    if (!recast_json.empty()) {
        def.settings_json = recast_json.data();
        def.settings_json_length = recast_json.size();
    }
    nl_navmesh_id navmesh{};
    check(nl_navmesh_build(world, &def, &navmesh), "building the navmesh");
    return navmesh;
}

nl_navmesh_id add_navmesh_from_obj(nl_world* world, const std::string& path, const nl_agent_type& body) {
    const ObjPolygons obj = read_obj_file(path, NL_MAX_POLYGON_VERTICES);
    nl_navmesh_def def = nl_default_navmesh_def();
    def.vertices = obj.positions.data();
    def.vertex_count = obj.vertex_count();
    def.indices = obj.indices.data();
    def.polygon_vertex_counts = obj.corner_counts.data();
    def.polygon_count = obj.polygon_count();
    def.agent_type = body;
    nl_navmesh_id navmesh{};
    check(nl_navmesh_add(world, &def, &navmesh), "adding the navmesh from '" + path + "'");
    return navmesh;
}

}  // namespace nl::samples
