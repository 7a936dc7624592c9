// What an nl_world is behind the opaque pointer: the core world, nothing else. Everything a world
// holds lives in nl::World (sdk/world/world.h); this layer maps C structs and ids to it and back.
#pragma once

#include <memory>

#include "navlink/navlink.h"
#include "util/error.h"
#include "world/world.h"

struct nl_world {
    std::unique_ptr<nl::World> core;
};

namespace nl::capi {

// The core world; throws InvalidArgument for a null world.
inline nl::World& deref(nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world->core;
}
inline const nl::World& deref(const nl_world* world) {
    if (!world) throw Error(ErrorCode::InvalidArgument, "world is null");
    return *world->core;
}

}  // namespace nl::capi
