#include "world.h"

#include "sample_error.h"

namespace nl::samples {

World::World(int32_t path_workers, int32_t workers) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    def.path_worker_count = path_workers;
    check(nl_world_create(&def, &world_), "creating the NavLink world");
}

World::~World() { nl_world_destroy(world_); }

void World::load_plugin(const std::string& path) {
    nl_plugin_id plugin{};
    check(nl_plugin_load(world_, path.c_str(), &plugin), "loading the plugin '" + path + "'");
}

}  // namespace nl::samples
