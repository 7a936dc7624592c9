#include "png_export.h"

#include <SDL2/SDL.h>
#include <stb/stb_image_write.h>

#include <memory>

#include "sample_error.h"
#include "scene_renderer.h"

namespace nl::picture {

void write_png(const Scene& scene, const ViewSettings& requested, const std::string& path) {
    ViewSettings view = requested;
    if (view.height <= 0) view.height = fitted_height(scene, view);
    // RGBA32 is bytes R, G, B, A in memory on any machine: what stbi_write_png expects.
    std::unique_ptr<SDL_Surface, decltype(&SDL_FreeSurface)> surface(
        SDL_CreateRGBSurfaceWithFormat(0, view.width, view.height, 32, SDL_PIXELFORMAT_RGBA32), SDL_FreeSurface);
    if (!surface) throw samples::SampleError(std::string("cannot make a picture surface: ") + SDL_GetError());
    std::unique_ptr<SDL_Renderer, decltype(&SDL_DestroyRenderer)> renderer(SDL_CreateSoftwareRenderer(surface.get()),
                                                                           SDL_DestroyRenderer);
    if (!renderer) throw samples::SampleError(std::string("cannot make a software renderer: ") + SDL_GetError());
    draw_scene(renderer.get(), scene, view);
    SDL_RenderFlush(renderer.get());  // SDL batches drawing: make sure it reached the pixels
    if (!stbi_write_png(path.c_str(), view.width, view.height, 4, surface->pixels, surface->pitch))
        throw samples::SampleError("cannot write '" + path + "'");
}

}  // namespace nl::picture
