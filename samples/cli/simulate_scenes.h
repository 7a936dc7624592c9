// The scenes navlink simulate plays: the demo's three bodies across the default level, or passengers
// riding the platforms beside it (--platforms). Each prints its run and writes its picture.
#pragma once

#include <cstdint>
#include <string>

namespace nl::cli {

struct SimulateOptions {
    uint32_t seed = 1;
    std::string out_dir = ".";
    double dt = 1.0 / 60.0;  // seconds per step
    double seconds = 120.0;  // at most
    bool oblique = false;
};

// Each returns the exit status: 0 when every agent arrived, 1 when one did not. Throws SampleError.
int simulate_default_level(const SimulateOptions& options);
int simulate_platforms(const SimulateOptions& options);

}  // namespace nl::cli
