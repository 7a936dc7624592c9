// Draws a Scene with any SDL_Renderer: a window's (the interactive viewer) or a software renderer on
// a surface (PNG files). Surfaces are drawn back to front (painter's algorithm, large triangles cut
// up first), links and paths on top, then the legend.
#pragma once

#include <SDL2/SDL.h>

#include "camera.h"
#include "map_marker.h"
#include "scene.h"

namespace nl::picture {

// The camera a view of the scene uses: to draw it, and to turn a click back into a point.
Camera scene_camera(const Scene& scene, const ViewSettings& view);

// The picture height that fits the level at `view.width` (and the legend), for pictures whose
// proportions are free (PNG files); a window keeps its own size.
int fitted_height(const Scene& scene, const ViewSettings& view);

void draw_scene(SDL_Renderer* renderer, const Scene& scene, const ViewSettings& view);

}  // namespace nl::picture
