// The navmesh a sample works on: built from the level by the built-in Recast builder, or handed over
// from an OBJ file of convex polygons (as a host hands over its engine's navmesh).
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

// nl_navmesh_build with the "recast" builder for `body`; `recast_json` (may be empty) is the
// builder's settings object. Without a `carrier`, from every static mesh; with one (a movable mesh),
// from that mesh alone in its own space, and the navmesh rides it. `progress` (optional, with its
// `progress_user`) is told of the build. Throws SampleError.
nl_navmesh_id build_navmesh(nl_world* world, const nl_agent_type& body, const std::string& recast_json,
                            nl_mesh_id carrier = {}, nl_progress_fn* progress = nullptr, void* progress_user = nullptr);

// nl_navmesh_add with the polygons of an OBJ file (each face one polygon, convex seen from above,
// at most NL_MAX_POLYGON_VERTICES corners), made for `body`. Throws SampleError.
nl_navmesh_id add_navmesh_from_obj(nl_world* world, const std::string& path, const nl_agent_type& body);

}  // namespace nl::samples
