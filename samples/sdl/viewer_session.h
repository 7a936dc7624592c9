// What the viewer shows and edits: a level with its navmesh and links, the demo's three agents, a
// start and a destination, and the paths planned between them through the queued path API
// (nl_path_request, polled every frame), so the window never waits for the planner. The same bodies
// are agents of the world too: a destination sends them, a start puts them there.
// With --platforms, the level has moving platforms beside it, moved by their timetables every frame,
// and the agents are their passengers, each sent where it goes (their routes cross navmeshes, which
// a path request does not: no paths are planned).
// A tiled navmesh (--tile-size, or "tile_size" in --settings) can be streamed around the chosen agent
// (--stream-tiles R, key T): only its tiles within R metres of that agent (of each, with all chosen)
// stay loaded, and it is sent along its way over every tile (tile_streamer.h).
#pragma once

#include <SDL2/SDL.h>
#include <navlink/navlink.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "generation_settings.h"
#include "level.h"
#include "moving_platforms.h"
#include "navmesh_contents.h"
#include "path_plan.h"
#include "scene.h"
#include "tile_streamer.h"
#include "viewer_agents.h"
#include "world.h"

namespace nl::picture {

struct ViewerOptions {
    std::optional<std::string> level_path;  // none: the generated default level
    std::optional<std::string> links_path;  // none: links are generated (the demo's settings)
    uint32_t seed = 1;
    bool platforms = false;                // the generated default level with its moving platforms and passengers
    samples::GenerationSettings settings;  // the links' and the builder's ("recast", with its tile_size)
    std::optional<size_t> agent;           // the only agent chosen and sent (an index of the demo's); none: all
    float stream_radius = 20.0f;           // metres around the chosen agent that tile streaming keeps loaded
    bool stream_tiles = false;             // streaming on from the start (a tiled navmesh only)
};

class ViewerSession {
public:
    using Point = std::array<float, 3>;

    explicit ViewerSession(const ViewerOptions& options);  // throws SampleError
    ~ViewerSession();
    ViewerSession(const ViewerSession&) = delete;
    ViewerSession& operator=(const ViewerSession&) = delete;

    // What a click on a pixel of a view picks: the nearest navmesh polygon the ray through it meets
    // (so a roof over the navmesh, cut away in the picture, is not picked), or where there is none,
    // the level surface the ray meets (`polygon` NL_NO_POLYGON).
    struct Picked {
        Point point;
        uint32_t polygon;
    };
    std::optional<Picked> pick(SDL_FPoint pixel, const ViewSettings& view) const;
    // Each returns false when an agent could not be placed or sent there (said on stdout).
    bool set_start(const Point& start);
    bool set_destination(const Point& destination);
    void select_agent(size_t index);
    void toggle_all_agents();
    bool selected(size_t index) const { return all_agents_ || index == current_; }
    bool all_agents() const { return all_agents_; }

    // Tile streaming (a tiled navmesh only): on, only the tiles within stream_radius() of the chosen
    // agents stay loaded, each frame; off, every tile is loaded again. False (and a line) when the
    // navmesh is not tiled.
    bool set_streaming(bool on);
    bool streaming() const { return streaming_; }
    float stream_radius() const { return stream_radius_; }
    const TileStreamer* streamer() const { return streamer_ ? &*streamer_ : nullptr; }
    // How many times streaming changed the tiles loaded, and the last change.
    size_t tile_changes() const { return tile_changes_; }
    const TileStreamer::Change& last_tile_change() const { return last_tile_change_; }
    // "the long jumper", "the agents"
    std::string followed() const;

    // Takes the paths that finished since the last call; true if any did (draw again).
    bool update();
    // Moves the platforms and steps the agents by `dt` seconds (real time) when one is on its way or
    // a platform carries them; true if anything moved.
    bool advance(float dt);
    // An agent on its way, or one streaming sends further along its way.
    bool agents_moving() const;
    // Whether agent `index` arrived at the destination (not only at the end of a streamed route that
    // falls short of it).
    bool arrived(size_t index) const;
    // Whether every agent shown has a complete planned path to the destination.
    bool every_path_complete() const;
    const ViewerAgents& crowd() const { return *crowd_; }
    bool waiting() const { return !pending_.empty(); }
    // Runs queued requests on this thread until none is left (headless mode).
    void wait_for_paths();

    Scene scene() const;  // borrows this session's level and navmesh
    const std::vector<samples::AgentProfile>& agents() const { return agents_; }
    const std::vector<samples::MovingPlatform>& platforms() const { return platforms_; }
    const nl_world* world() const { return world_.get(); }
    double time() const { return time_; }  // seconds the agents and platforms have moved
    size_t current_agent() const { return current_; }
    const Point& start() const { return start_; }
    std::optional<Point> destination() const;
    // One line about the current state, for the title bar and the console.
    std::string status() const;

private:
    void add_passengers();
    void request_paths();
    template <typename Visit>
    void for_selected(Visit visit);
    void cancel_pending();
    void read_islands();
    // Streaming: the tiles around the chosen agents, then their waypoints; true if the tiles changed.
    bool stream();
    void steer_along_routes();
    // The chosen agents' routes to the destination over every tile (they are loaded).
    void plan_routes();
    // A change the user makes while streaming (a start, a destination, another agent chosen) is
    // made with every tile loaded, the routes planned again, and then the tiles streamed again.
    template <typename Change>
    void with_every_tile(Change change);
    void read_navmesh();

    samples::World world_;
    samples::Level level_;
    nl_navmesh_id navmesh_{};
    samples::NavmeshContents contents_;  // the tiles loaded
    samples::NavmeshContents whole_;     // with every tile, while streaming has some out
    SceneIslands islands_;               // the current agent's, drawn in the navmesh's colours
    std::vector<samples::AgentProfile> agents_;
    size_t current_ = 0;
    bool all_agents_ = true;
    Point start_{};
    std::optional<Point> destination_;
    struct Pending {
        size_t agent;
        nl_path_ticket ticket;
    };
    std::vector<Pending> pending_;
    std::vector<std::optional<samples::PlannedPath>> paths_;  // per agent, for the current destination
    std::optional<ViewerAgents> crowd_;                       // the same bodies as agents, sent to each destination
    std::optional<samples::PlatformsLevel> platforms_level_;  // with platforms: where they go, and who rides
    std::vector<samples::MovingPlatform> platforms_;
    double time_ = 0.0;
    std::optional<TileStreamer> streamer_;  // a tiled navmesh's tiles (none with platforms)
    bool streaming_ = false;
    float stream_radius_ = 20.0f;
    std::vector<std::optional<StreamedRoute>> routes_;  // per agent, while streaming
    size_t tile_changes_ = 0;
    TileStreamer::Change last_tile_change_;
};

}  // namespace nl::picture
