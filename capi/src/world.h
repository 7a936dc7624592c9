// What an nl_world is behind the opaque pointer.
#pragma once

#include <memory>

#include "level/level.h"
#include "navlink/navlink.h"
#include "util/task_system.h"

struct nl_world {
    nl_world_def def;
    std::unique_ptr<nl::TaskSystem> tasks;
    std::unique_ptr<nl::Level> level;
};

namespace nl::capi {

// Throws InvalidArgument for a null world.
inline nl_world& deref(nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world;
}
inline const nl_world& deref(const nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world;
}

}  // namespace nl::capi
