#include "interactive_viewer.h"

#include <SDL2/SDL.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "png_export.h"
#include "scene_renderer.h"

namespace nl::picture {

const char* const kViewerKeys =
    "  left click: destination (the agents walk there)    right click or shift-click: start (they stand there)\n"
    "  1 2 3: walker / short jumper / long jumper    A: all agents at once\n"
    "  L level  N navmesh  B boundary edges  K links  P paths  M agents  G legend  O oblique/top-down\n"
    "  R roofs (cut away above the navmesh, or drawn)  I link numbers  X grid  E tile borders\n"
    "  T tile streaming (a tiled navmesh: only the tiles around the chosen agent loaded)\n"
    "  S: save viewer.png    Q or Escape: quit\n";

namespace {

// Applies a key; returns false to quit.
bool handle_key(SDL_Keycode key, ViewerSession& session, ViewSettings& view) {
    Layers& l = view.layers;
    switch (key) {
        case SDLK_ESCAPE:
        case SDLK_q: return false;
        case SDLK_1: session.select_agent(0); break;
        case SDLK_2: session.select_agent(1); break;
        case SDLK_3: session.select_agent(2); break;
        case SDLK_a: session.toggle_all_agents(); break;
        case SDLK_l: l.level = !l.level; break;
        case SDLK_n: l.navmesh = !l.navmesh; break;
        case SDLK_b: l.boundary = !l.boundary; break;
        case SDLK_k: l.links = !l.links; break;
        case SDLK_p: l.paths = !l.paths; break;
        case SDLK_m: l.agents = !l.agents; break;
        case SDLK_g: l.legend = !l.legend; break;
        case SDLK_o: view.oblique = !view.oblique; break;
        case SDLK_r: l.roofs = !l.roofs; break;
        case SDLK_i: l.link_numbers = !l.link_numbers; break;
        case SDLK_x: l.grid = !l.grid; break;
        case SDLK_e: l.tile_borders = !l.tile_borders; break;
        case SDLK_t: session.set_streaming(!session.streaming()); break;
        case SDLK_s:
            session.wait_for_paths();  // save what was asked for, not a picture mid-planning
            session.update();
            write_png(session.scene(), view, "viewer.png");
            std::printf("wrote viewer.png\n");
            break;
        default: break;
    }
    return true;
}

}  // namespace

int run_interactive_viewer(ViewerSession& session, ViewSettings view) {
    std::unique_ptr<SDL_Window, decltype(&SDL_DestroyWindow)> window(
        SDL_CreateWindow("NavLink viewer", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, view.width, view.height,
                         SDL_WINDOW_RESIZABLE),
        SDL_DestroyWindow);
    if (!window) {
        std::fprintf(stderr, "navlink-viewer: cannot open a window: %s\n", SDL_GetError());
        return 2;
    }
    std::unique_ptr<SDL_Renderer, decltype(&SDL_DestroyRenderer)> renderer(
        SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_PRESENTVSYNC), SDL_DestroyRenderer);
    if (!renderer) renderer.reset(SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_SOFTWARE));
    if (!renderer) {
        std::fprintf(stderr, "navlink-viewer: cannot draw in the window: %s\n", SDL_GetError());
        return 2;
    }
    std::printf("%s", kViewerKeys);
    bool running = true, dirty = true;
    std::string last_status;
    Uint32 last_ticks = SDL_GetTicks();
    while (running) {
        SDL_Event event;
        // Wait briefly for input so an idle viewer does not spin; paths are polled in between, and
        // moving agents are drawn every frame (the renderer waits for the display's refresh).
        const bool busy = session.waiting() || session.agents_moving();
        if (SDL_WaitEventTimeout(&event, busy ? 1 : 50)) {
            do {
                if (event.type == SDL_QUIT) running = false;
                if (event.type == SDL_WINDOWEVENT) dirty = true;
                if (event.type == SDL_KEYDOWN) {
                    running = handle_key(event.key.keysym.sym, session, view) && running;
                    dirty = true;
                }
                if (event.type == SDL_MOUSEBUTTONDOWN) {
                    const SDL_FPoint pixel{static_cast<float>(event.button.x), static_cast<float>(event.button.y)};
                    if (const auto picked = session.pick(pixel, view)) {
                        const bool start = event.button.button == SDL_BUTTON_RIGHT || (SDL_GetModState() & KMOD_SHIFT);
                        if (start)
                            session.set_start(picked->point);
                        else
                            session.set_destination(picked->point);
                        dirty = true;
                    }
                }
            } while (SDL_PollEvent(&event));
        }
        dirty = session.update() || dirty;
        // The agents move in real time; a stall (a dragged window) is not a leap across the level.
        const Uint32 now = SDL_GetTicks();
        const float dt = std::min(0.1f, static_cast<float>(now - last_ticks) / 1000.0f);
        last_ticks = now;
        dirty = session.advance(dt) || dirty;
        if (!dirty) continue;
        SDL_GetRendererOutputSize(renderer.get(), &view.width, &view.height);
        draw_scene(renderer.get(), session.scene(), view);
        SDL_RenderPresent(renderer.get());
        const std::string status = session.status();
        SDL_SetWindowTitle(window.get(), ("NavLink viewer: " + status).c_str());
        if (status != last_status) std::printf("%s\n", status.c_str());
        last_status = status;
        dirty = false;
    }
    return 0;
}

}  // namespace nl::picture
