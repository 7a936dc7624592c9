#include "world/world.h"

#include <string>

namespace nl {

World::World(WorldSettings settings)
    : handle_tag_(HandleTag::acquire()),
      logger_(std::move(settings.logger)),
      tasks_(settings.tasks ? std::move(settings.tasks) : make_tbb_task_system(settings.worker_count)),
      level_(std::make_unique<Level>(*tasks_, handle_tag_.value())),
      navmeshes_(handle_tag_.value()),
      plugins_(handle_tag_.value()),
      paths_(handle_tag_.value(), settings.path_worker_count),
      agents_(handle_tag_.value(), settings.agents) {}

World::~World() { paths_.shutdown(); }

void World::log_repairs(const NavMesh& navmesh) const {
    const NavMeshRepairs& r = navmesh.repairs();
    if (r.flipped_polygons || r.dropped_polygons || r.non_manifold_edges) {
        logger_.log(LogLevel::Warning, concat("repaired the navmesh: ", r.flipped_polygons, " polygons turned to face up, ",
                                              r.dropped_polygons, " degenerate polygons dropped, ", r.non_manifold_edges,
                                              " edges shared by 3+ polygons left unconnected"));
    }
}

Handle World::add_navmesh(const NavMeshInput& input) {
    std::shared_ptr<const NavMesh> navmesh = nl::build_navmesh(input);
    log_repairs(*navmesh);
    return navmeshes_.add(std::move(navmesh));
}

Handle World::build_navmesh(const NavMeshBuildRequest& request) {
    NavMeshBuilder* builder = plugins_.find_navmesh_builder(request.builder);
    if (!builder) {
        std::string loaded;
        for (const std::string& name : plugins_.navmesh_builder_names()) loaded += (loaded.empty() ? "'" : ", '") + name + "'";
        fail(ErrorCode::NotFound, "no navmesh builder named '", request.builder, "' (loaded: ", loaded.empty() ? "none" : loaded,
             ")");
    }
    std::shared_ptr<const NavMesh> navmesh = builder->build(*this, request);
    if (!navmesh) fail(ErrorCode::Internal, "builder '", request.builder, "' succeeded without handing over a navmesh");
    log_repairs(*navmesh);
    return navmeshes_.add(std::move(navmesh));
}

}  // namespace nl
