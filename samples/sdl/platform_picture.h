// The moving platforms as a picture shows them: each one's triangles where its mesh stands now (the
// transform the world holds for it) and its navmesh with the gangways off it, read back in the
// world, labelled with where it is.
#pragma once

#include <navlink/navlink.h>

#include <vector>

#include "moving_platforms.h"
#include "scene.h"

namespace nl::picture {

// `time` is the platforms' timetable time, to say whether each is docked. Throws SampleError.
std::vector<ScenePlatform> scene_platforms(const nl_world* world, const std::vector<samples::MovingPlatform>& platforms,
                                           double time);

}  // namespace nl::picture
