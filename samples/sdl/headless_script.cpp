#include "headless_script.h"

#include <cmath>
#include <cstdio>

#include "png_export.h"
#include "scene_renderer.h"

namespace nl::picture {

int run_headless_script(ViewerSession& session, ViewSettings view, const std::string& dir) {
    int status = 0;
    int frame = 0;
    auto shoot = [&](const std::string& what) {
        session.wait_for_paths();
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%02d.png", frame++);
        write_png(session.scene(), view, dir + name);
        std::printf("%s%s: %s | %s\n", dir.c_str(), name, what.c_str(), session.status().c_str());
    };
    // A click where a point of the current scene is drawn (the session's destination or start), or
    // at a fraction of the map: picked through the camera as a mouse click would be.
    auto click_at = [&](SDL_FPoint pixel, bool start, const std::string& what) {
        const auto point = session.pick(pixel, view);
        if (!point) {
            std::printf("scripted click at (%.0f, %.0f) found no surface\n", pixel.x, pixel.y);
            status = 1;
            return;
        }
        if (start) session.set_start(*point);
        else session.set_destination(*point);
        shoot(what);
    };
    auto pixel_of = [&](size_t point_index) {
        const Scene scene = session.scene();
        const Camera camera = scene_camera(scene, view);
        return camera.project(scene.points.at(point_index).position);
    };

    shoot("all agents to the destination");
    for (size_t i = 0; i < session.agents().size(); ++i) {
        session.select_agent(i);  // key 1, 2, 3
        shoot("agent " + session.agents()[i].name);
    }
    view.layers.links = false;    // key K
    view.layers.navmesh = false;  // key N
    shoot("links and navmesh hidden");
    view.layers.links = view.layers.navmesh = true;
    view.oblique = true;          // key O
    session.toggle_all_agents();  // key A
    shoot("oblique view, all agents");
    view.oblique = false;
    // Clicks, picked through the camera as the mouse's are: on the destination where it is drawn
    // (the pick must find the same place again), in the middle of the map (a new destination), and
    // a right click where the start is drawn (the start stays put).
    // Seen from straight above, a click lands on the same spot (the surface it finds may be a
    // little above a navmesh point, or a roof over it).
    auto near = [](const ViewerSession::Point& a, const ViewerSession::Point& b) {
        return std::hypot(a[0] - b[0], a[2] - b[2]) < 0.25f;
    };
    if (const auto destination = session.destination()) {
        click_at(pixel_of(1), false, "click on the destination");
        if (!session.destination() || !near(*session.destination(), *destination)) {
            std::printf("the click on the destination picked another place\n");
            status = 1;
        }
    }
    click_at({0.35f * static_cast<float>(view.width), 0.5f * static_cast<float>(view.height)}, false,
             "click in the middle of the map");
    const ViewerSession::Point start = session.start();
    click_at(pixel_of(0), true, "right click on the start");
    if (!near(session.start(), start)) {
        std::printf("the click on the start picked another place\n");
        status = 1;
    }
    return status;
}

}  // namespace nl::picture
