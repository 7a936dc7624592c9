// Where things are marked on the map of a picture: the map's rectangle, and a point's marker, kept
// inside the map for a point off it. The scene and the legend both mark points.
#pragma once

#include <SDL2/SDL.h>

#include "camera.h"
#include "scene.h"

namespace nl::picture {

// The map's rectangle in a picture: the level's bounding box as the camera shows it.
SDL_FRect map_rect(const Scene& scene, const Camera& camera);

// Where point `p` is marked: where it is, or, for a point off the map (`*off_map` set, if given),
// kOffMapInset pixels inside the map's edge nearest it, with an arrow of kOffMapArrow pixels
// pointing its way.
constexpr float kOffMapInset = 14.0f;
constexpr float kOffMapArrow = 18.0f;
SDL_FPoint point_marker(const Scene& scene, const Camera& camera, const float p[3], bool* off_map = nullptr);

}  // namespace nl::picture
