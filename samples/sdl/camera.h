// World to picture: a parallel projection looking down from the +z side at `pitch` degrees below the
// horizon (90: straight down, x to the right and z down the picture), scaled to fit the level's
// bounds in the picture's drawing area.
#pragma once

#include <SDL2/SDL.h>

namespace nl::picture {

class Camera {
public:
    // Fits the box [lo, hi] into `area` (pixels), keeping proportions.
    Camera(const float lo[3], const float hi[3], const SDL_FRect& area, float pitch_degrees);

    SDL_FPoint project(const float p[3]) const;
    // Larger is nearer the viewer: draw in increasing order (painter's algorithm).
    float nearness(const float p[3]) const { return p[1] * sin_ + p[2] * cos_; }
    // The view direction (unit, from the eye into the scene).
    void view_direction(float out[3]) const;
    // A point on the plane through the level's centre that projects to `pixel`: with view_direction,
    // the ray behind a pixel (to find what was clicked).
    void unproject(SDL_FPoint pixel, float out[3]) const;
    float pixels_per_metre() const { return scale_; }
    bool top_down() const { return cos_ < 1e-3f; }

private:
    float sin_, cos_, scale_;
    float centre_[3];
    SDL_FPoint screen_centre_;
};

}  // namespace nl::picture
