#include "headless_script.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "png_export.h"
#include "scene_renderer.h"

namespace nl::picture {
namespace {

constexpr float kFrameTime = 1.0f / 60.0f;
constexpr float kPlayLimit = 120.0f;  // seconds of the agents' walk to the destination at most
constexpr size_t kTileFrames = 3;     // frames shot as streaming changes the tiles, at most

// Writes the session's scene as DIR/frame_NN.png, numbered in order, and says what it shows.
struct FrameShooter {
    ViewerSession& session;
    const ViewSettings& view;
    const std::string& dir;
    int frame = 0;

    void operator()(const std::string& what) {
        session.wait_for_paths();
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%02d.png", frame++);
        write_png(session.scene(), view, dir + name);
        std::printf("%s%s: %s | %s\n", dir.c_str(), name, what.c_str(), session.status().c_str());
    }
};

// Steps the agents in frames of 1/60 s until none is on its way, shooting a frame when the first
// jump and the first drop are half flown, when streaming changes the tiles (the first few times) and
// when every agent has stopped. True if every chosen agent arrived.
bool play_agents(ViewerSession& session, FrameShooter& shoot) {
    bool shot_jump = false, shot_drop = false;
    size_t tile_frames = 0, tile_changes = session.tile_changes();
    float time = 0.0f;
    for (; session.agents_moving() && time < kPlayLimit; time += kFrameTime) {
        session.advance(kFrameTime);
        if (session.tile_changes() != tile_changes && tile_frames < kTileFrames) {
            ++tile_frames;
            shoot("tiles streamed " + change_text(session.last_tile_change()));
        }
        tile_changes = session.tile_changes();
        for (size_t i = 0; i < session.agents().size(); ++i) {
            const nl_agent_info& info = session.crowd().info(i);
            const bool half = info.link_progress >= 0.5f;
            if (!shot_jump && info.state == NL_AGENT_JUMPING && half) {
                shot_jump = true;
                shoot(session.agents()[i].name + " mid-jump");
            } else if (!shot_drop && info.state == NL_AGENT_FALLING && half) {
                shot_drop = true;
                shoot(session.agents()[i].name + " mid-drop");
            }
        }
    }
    shoot("the agents after " + std::to_string(static_cast<int>(time)) + " s");
    bool all_arrived = true;
    for (size_t i = 0; i < session.agents().size(); ++i)
        all_arrived = all_arrived && (!session.selected(i) || session.arrived(i));
    std::printf("agents: %s\n", all_arrived ? "every agent arrived" : "not every agent arrived");
    if (const TileStreamer* tiles = session.streaming() ? session.streamer() : nullptr) {
        const TileStreamer::Counts& c = tiles->counts();
        std::printf(
            "tiles: at most %zu of %zu loaded at once, within %g m of %s; %zu removed (saved first), %zu added "
            "(%zu from saved bytes, %zu built again)\n",
            c.most_loaded, tiles->total(), double(session.stream_radius()), session.followed().c_str(), c.removed,
            c.added_from_bytes + c.built, c.added_from_bytes, c.built);
    }
    return all_arrived;
}

}  // namespace

int run_headless_trip(ViewerSession& session, const ViewSettings& view, const std::string& dir) {
    FrameShooter shoot{session, view, dir};
    shoot((session.all_agents() ? std::string("all agents") : session.followed()) + " to the destination" +
          (session.streaming() ? ", the tiles streamed around " + session.followed() : std::string()));
    return play_agents(session, shoot) ? 0 : 1;
}

int run_headless_script(ViewerSession& session, ViewSettings view, const std::string& dir) {
    int status = 0;
    FrameShooter shoot{session, view, dir};
    // A click where a point of the current scene is drawn (the session's destination or start), or
    // on a polygon of the navmesh: picked through the camera as a mouse click would be. Each pick is
    // logged with the polygon it found; the places drawn there are on the navmesh, so a click that
    // finds no polygon fails.
    auto click_at = [&](SDL_FPoint pixel, bool start, const std::string& what) {
        const auto picked = session.pick(pixel, view);
        if (!picked || picked->polygon == NL_NO_POLYGON) {
            std::printf("scripted click at (%.0f, %.0f) found no navmesh polygon\n", pixel.x, pixel.y);
            status = 1;
            return;
        }
        std::printf("scripted click at (%.0f, %.0f): %s picked (%.2f, %.2f, %.2f) on navmesh polygon %u\n", pixel.x,
                    pixel.y, what.c_str(), picked->point[0], picked->point[1], picked->point[2], picked->polygon);
        if (start)
            session.set_start(picked->point);
        else
            session.set_destination(picked->point);
        shoot(what);
    };
    auto pixel_of = [&](size_t point_index) {
        const Scene scene = session.scene();
        const Camera camera = scene_camera(scene, view);
        return camera.project(scene.points.at(point_index).position);
    };
    // Where the navmesh polygon whose centre is drawn nearest the middle of the map is drawn: any
    // level has one there, whatever its shape (the middle of the picture may be empty).
    auto middle_polygon_pixel = [&]() -> std::optional<SDL_FPoint> {
        const Scene scene = session.scene();
        const Camera camera = scene_camera(scene, view);
        const SDL_FRect map = map_rect(scene, camera);
        const SDL_FPoint middle{map.x + 0.5f * map.w, map.y + 0.5f * map.h};
        std::optional<SDL_FPoint> best;
        float best_distance = 0.0f;
        for (const nl_nav_polygon& polygon : scene.navmesh->polygons) {
            const SDL_FPoint at = camera.project(polygon.centre);
            const float distance = std::hypot(at.x - middle.x, at.y - middle.y);
            if (!best || distance < best_distance) {
                best = at;
                best_distance = distance;
            }
        }
        return best;
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
    // The script's destination is its own pick: an agent that cannot reach it is an outcome, not a
    // failure; one that has a complete path and does not arrive is.
    if (!play_agents(session, shoot) && session.every_path_complete()) status = 1;
    // Clicks, picked through the camera as the mouse's are: on the destination where it is drawn
    // (the pick must find the same place again), on the navmesh in the middle of the map (a new
    // destination), and a right click where the start is drawn (the start stays put). Seen from
    // straight above, a click lands on the same spot of the navmesh, or on a floor drawn above it.
    auto near = [](const ViewerSession::Point& picked, const ViewerSession::Point& placed) {
        return std::hypot(picked[0] - placed[0], picked[2] - placed[2]) < 0.25f && picked[1] > placed[1] - 0.5f;
    };
    if (const auto destination = session.destination()) {
        click_at(pixel_of(1), false, "click on the destination");
        if (!session.destination() || !near(*session.destination(), *destination)) {
            std::printf("the click on the destination picked another place\n");
            status = 1;
        }
    }
    if (const auto middle = middle_polygon_pixel()) click_at(*middle, false, "click in the middle of the map");
    const ViewerSession::Point start = session.start();
    click_at(pixel_of(0), true, "right click on the start");
    if (!near(session.start(), start)) {
        std::printf("the click on the start picked another place\n");
        status = 1;
    }
    return status;
}

}  // namespace nl::picture
