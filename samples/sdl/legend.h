// The legend panel on the right of a picture: what each colour means, how many links of each kind,
// the agents' paths, the height ramp and a scale bar.
#pragma once

#include "camera.h"
#include "canvas.h"
#include "scene.h"

namespace nl::picture {

constexpr float kLegendWidth = 430.0f;
constexpr float kLegendMinHeight = 560.0f;  // tall enough for three paths and two points

void draw_legend(Canvas& canvas, const Scene& scene, const ViewSettings& view, const Camera& camera);

}  // namespace nl::picture
