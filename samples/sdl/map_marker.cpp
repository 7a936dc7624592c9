#include "map_marker.h"

#include <algorithm>

namespace nl::picture {

SDL_FRect map_rect(const Scene& scene, const Camera& camera) {
    const float* lo = scene.level->info.bounds_min;
    const float* hi = scene.level->info.bounds_max;
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (int corner = 0; corner < 8; ++corner) {
        const float p[3] = {corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1], corner & 4 ? hi[2] : lo[2]};
        const SDL_FPoint q = camera.project(p);
        x0 = std::min(x0, q.x);
        y0 = std::min(y0, q.y);
        x1 = std::max(x1, q.x);
        y1 = std::max(y1, q.y);
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

SDL_FPoint point_marker(const Scene& scene, const Camera& camera, const float p[3], bool* off_map) {
    const SDL_FPoint at = camera.project(p);
    const SDL_FRect map = map_rect(scene, camera);
    const bool off =
        at.x < map.x - 1.0f || at.x > map.x + map.w + 1.0f || at.y < map.y - 1.0f || at.y > map.y + map.h + 1.0f;
    if (off_map) *off_map = off;
    if (!off) return at;
    const float inset = kOffMapInset;
    return {std::clamp(at.x, map.x + inset, std::max(map.x + inset, map.x + map.w - inset)),
            std::clamp(at.y, map.y + inset, std::max(map.y + inset, map.y + map.h - inset))};
}

}  // namespace nl::picture
