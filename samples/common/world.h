// Owns one nl_world for the lifetime of a sample program (RAII over nl_world_create/destroy).
#pragma once

#include <navlink/navlink.h>

#include <string>

namespace nl::samples {

class World {
public:
    // `path_workers`: threads that plan queued path requests (NL_WORKERS_AUTO or a count; 0 means
    // the program runs the queue itself with nl_path_process). `workers`: threads of batch work and
    // agent steps (NL_WORKERS_AUTO or a count; 0 or 1: the calling thread only).
    explicit World(int32_t path_workers = NL_WORKERS_AUTO, int32_t workers = NL_WORKERS_AUTO);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    nl_world* get() const { return world_; }

    // Loads the plugin library at `path` (nl_plugin_load); throws SampleError naming it.
    void load_plugin(const std::string& path);

private:
    nl_world* world_ = nullptr;
};

}  // namespace nl::samples
