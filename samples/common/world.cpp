#include "world.h"

#include "sample_error.h"

#include <cstdio>

namespace nl::samples {
namespace {

// NavLink's warnings (a navmesh built on meshes that look wound clockwise, a navmesh repaired) go to
// stderr as they happen; its errors come back as statuses, which the samples report themselves.
void print_warning(void*, nl_log_level level, nl_status, const char* message) {
    if (level == NL_LOG_WARNING) std::fprintf(stderr, "warning: %s\n", message);
}

}  // namespace

World::World(int32_t path_workers, int32_t workers) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    def.path_worker_count = path_workers;
    def.log_fn = print_warning;
    def.log_level = NL_LOG_WARNING;
    check(nl_world_create(&def, &world_), "creating the NavLink world");
}

World::~World() { nl_world_destroy(world_); }

void World::load_plugin(const std::string& path) {
    nl_plugin_id plugin{};
    check(nl_plugin_load(world_, path.c_str(), &plugin), "loading the plugin '" + path + "'");
}

}  // namespace nl::samples
