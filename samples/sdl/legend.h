// The legend panel on the right of a picture: what each colour means, how many links of each kind,
// the agents' paths, the height ramp and a scale bar.
#pragma once

#include "camera.h"
#include "canvas.h"
#include "height_slice.h"
#include "scene.h"

namespace nl::picture {

constexpr float kLegendWidth = 430.0f;
constexpr float kLegendMinHeight = 720.0f;  // tall enough for four islands, three paths and two points

// Round lengths in metres, for the scale bar and the grid's step.
constexpr float kRoundLengths[] = {1.0f, 2.0f, 5.0f, 10.0f, 20.0f, 50.0f, 100.0f, 200.0f, 500.0f, 1000.0f};

// Metres between grid lines: the shortest round length at least 64 pixels long.
float grid_step(float pixels_per_metre);

// The height the grid lies at (seen from an angle, it matters): the navmesh's median polygon height
// (the whole navmesh's, while tiles of it are streamed out), or without a navmesh the level's lowest.
float grid_height(const Scene& scene);

// The heights the level's colour ramp spans (dark to light): the level's, up to the slice's top
// cut when roofs are cut away.
void drawn_heights(const Scene& scene, const HeightSlice* slice, float& lo, float& hi);

// `slice`: the roofs cut away, if any.
void draw_legend(Canvas& canvas, const Scene& scene, const ViewSettings& view, const Camera& camera,
                 const HeightSlice* slice);

}  // namespace nl::picture
