#include "camera.h"

#include <algorithm>
#include <cmath>

namespace nl::picture {

Camera::Camera(const float lo[3], const float hi[3], const SDL_FRect& area, float pitch_degrees) {
    const float pitch = pitch_degrees * static_cast<float>(M_PI) / 180.0f;
    sin_ = std::sin(pitch);
    cos_ = std::fabs(std::cos(pitch)) < 1e-6f ? 0.0f : std::cos(pitch);
    for (int k = 0; k < 3; ++k) centre_[k] = 0.5f * (lo[k] + hi[k]);
    // The projected box: x spans its width; the picture's vertical spans z sin + y cos.
    const float width = std::max(hi[0] - lo[0], 1e-3f);
    const float height = std::max((hi[2] - lo[2]) * sin_ + (hi[1] - lo[1]) * cos_, 1e-3f);
    scale_ = std::min(area.w / width, area.h / height);
    screen_centre_ = {area.x + 0.5f * area.w, area.y + 0.5f * area.h};
}

SDL_FPoint Camera::project(const float p[3]) const {
    const float dx = p[0] - centre_[0], dy = p[1] - centre_[1], dz = p[2] - centre_[2];
    return {screen_centre_.x + dx * scale_, screen_centre_.y + (dz * sin_ - dy * cos_) * scale_};
}

void Camera::view_direction(float out[3]) const {
    out[0] = 0.0f;
    out[1] = -sin_;
    out[2] = -cos_;
}

void Camera::unproject(SDL_FPoint pixel, float out[3]) const {
    // On the plane through the centre perpendicular to the view: x from the column, and the row
    // along the picture's "down" direction (0, -cos, sin).
    const float u = (pixel.x - screen_centre_.x) / scale_;
    const float v = (pixel.y - screen_centre_.y) / scale_;
    out[0] = centre_[0] + u;
    out[1] = centre_[1] - v * cos_;
    out[2] = centre_[2] + v * sin_;
}

}  // namespace nl::picture
