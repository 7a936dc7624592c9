// What the viewer shows and edits: a level with its navmesh and links, the demo's three agents, a
// start and a destination, and the paths planned between them through the queued path API
// (nl_path_request, polled every frame), so the window never waits for the planner. The same bodies
// are agents of the world too: a destination sends them, a start puts them there.
// With --platforms, the level has moving platforms beside it, moved by their timetables every frame,
// and the agents are their passengers, each sent where it goes (their routes cross navmeshes, which
// a path request does not: no paths are planned).
#pragma once

#include <SDL2/SDL.h>
#include <navlink/navlink.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "level.h"
#include "moving_platforms.h"
#include "navmesh_contents.h"
#include "path_plan.h"
#include "scene.h"
#include "viewer_agents.h"
#include "world.h"

namespace nl::picture {

struct ViewerOptions {
    std::optional<std::string> level_path;  // none: the generated default level
    std::optional<std::string> links_path;  // none: links are generated (the demo's settings)
    uint32_t seed = 1;
    bool platforms = false;  // the generated default level with its moving platforms and passengers
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

    // Takes the paths that finished since the last call; true if any did (draw again).
    bool update();
    // Moves the platforms and steps the agents by `dt` seconds (real time) when one is on its way or
    // a platform carries them; true if anything moved.
    bool advance(float dt);
    bool agents_moving() const { return crowd_->moving(); }
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

    samples::World world_;
    samples::Level level_;
    nl_navmesh_id navmesh_{};
    samples::NavmeshContents contents_;
    SceneIslands islands_;  // the current agent's, drawn in the navmesh's colours
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
};

}  // namespace nl::picture
