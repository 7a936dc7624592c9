// Renders a scene off screen (SDL's software renderer on a surface; no window and no video driver
// needed, so it works headless) and writes it as a PNG with stb_image_write.
#pragma once

#include <string>

#include "scene.h"

namespace nl::picture {

// A view height of 0 or less fits the picture to the level (fitted_height).
// Throws nl::samples::SampleError naming the file when it cannot be written.
void write_png(const Scene& scene, const ViewSettings& view, const std::string& path);

}  // namespace nl::picture
