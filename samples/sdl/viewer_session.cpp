#include "viewer_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "demo_setup.h"
#include "island_colors.h"
#include "link_files.h"
#include "navmesh_setup.h"
#include "palette.h"
#include "platform_picture.h"
#include "sample_error.h"
#include "scene_renderer.h"
#include "world_agents.h"

namespace nl::picture {

ViewerSession::ViewerSession(const ViewerOptions& options) : agents_(samples::demo_agents()) {
    levelgen::GeneratedLevel generated;
    const std::string seed = std::to_string(options.seed);
    if (options.level_path) {
        level_ = samples::load_level_file(world_.get(), *options.level_path, true);
    } else if (options.platforms) {
        platforms_level_.emplace(samples::generate_platforms_level(options.seed));
        level_ = samples::add_generated_level(world_.get(), platforms_level_->level,
                                              "generated default level (seed " + seed + ") with moving platforms");
        agents_.clear();
        for (const samples::Passenger& p : platforms_level_->passengers) agents_.push_back(p.profile);
    } else {
        generated = levelgen::generate_default_level(options.seed);
        level_ = samples::add_generated_level(world_.get(), generated, "generated default level (seed " + seed + ")");
    }
    navmesh_ = samples::build_navmesh(world_.get(), agents_[0].body, options.settings.recast_json);
    if (options.links_path) {
        samples::load_links_file(world_.get(), navmesh_, *options.links_path);
    } else {
        samples::check(
            nl_navmesh_generate_links(world_.get(), navmesh_, &options.settings.links, nullptr, nullptr, nullptr),
            "generating links");
    }
    contents_ = samples::read_navmesh_contents(world_.get(), navmesh_);
    paths_.resize(agents_.size());
    routes_.resize(agents_.size());
    current_ = agents_.size() - 1;
    if (options.agent) {
        current_ = *options.agent % agents_.size();
        all_agents_ = false;
    }
    stream_radius_ = options.stream_radius;
    read_islands();
    if (platforms_level_) {
        add_passengers();
        return;
    }

    // Start at the level's start marker, or in the middle of the first polygon.
    if (const levelgen::Marker* m = generated.marker("start")) {
        start_ = {m->position[0], m->position[1], m->position[2]};
    } else if (!contents_.polygons.empty()) {
        const float* c = contents_.polygons[0].centre;
        start_ = {c[0], c[1], c[2]};
    }
    crowd_.emplace(world_.get(), navmesh_, agents_, std::vector<Point>(agents_.size(), start_));
    // Every tile is loaded now: the ones streaming brings back.
    if (contents_.tiled()) streamer_.emplace(world_.get(), navmesh_, options.settings.recast_json, agents_[0].body);
    // Send the agents to the level's goal marker, or to the polygon farthest from the start.
    if (const levelgen::Marker* m = generated.marker("goal")) {
        set_destination({m->position[0], m->position[1], m->position[2]});
    } else if (!contents_.polygons.empty()) {
        const nl_nav_polygon* farthest = &contents_.polygons[0];
        auto distance2 = [this](const float* c) {
            return (c[0] - start_[0]) * (c[0] - start_[0]) + (c[2] - start_[2]) * (c[2] - start_[2]);
        };
        for (const nl_nav_polygon& p : contents_.polygons)
            if (distance2(p.centre) > distance2(farthest->centre)) farthest = &p;
        set_destination({farthest->centre[0], farthest->centre[1], farthest->centre[2]});
    }
}

// The platforms come after the links: these are generated against what stands still. Each
// passenger stands at its own start and is sent to its own destination; the session's start is the
// first one's (a right click puts the agents chosen there).
void ViewerSession::add_passengers() {
    platforms_ =
        samples::add_moving_platforms(world_.get(), navmesh_, platforms_level_->platforms, agents_[0].body, time_);
    std::vector<Point> starts;
    for (const samples::Passenger& p : platforms_level_->passengers) starts.push_back(p.start);
    start_ = starts.front();
    crowd_.emplace(world_.get(), navmesh_, agents_, starts);
    for (size_t i = 0; i < agents_.size(); ++i) crowd_->send(i, platforms_level_->passengers[i].destination);
    contents_.links = samples::read_links(world_.get(), navmesh_);  // with the gangways onto the platforms
    read_islands();
}

ViewerSession::~ViewerSession() { cancel_pending(); }

namespace {

// Where the ray origin + t direction (t in [0, max_t]) meets triangle a b c from either side: t, or
// a negative number (Moller-Trumbore).
float ray_triangle(const float origin[3], const float direction[3], float max_t, const float* a, const float* b,
                   const float* c) {
    const float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const float p[3] = {direction[1] * e2[2] - direction[2] * e2[1], direction[2] * e2[0] - direction[0] * e2[2],
                        direction[0] * e2[1] - direction[1] * e2[0]};
    const float det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (std::fabs(det) < 1e-12f) return -1.0f;
    const float inv = 1.0f / det;
    const float s[3] = {origin[0] - a[0], origin[1] - a[1], origin[2] - a[2]};
    const float u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    if (u < 0.0f || u > 1.0f) return -1.0f;
    const float q[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const float v = (direction[0] * q[0] + direction[1] * q[1] + direction[2] * q[2]) * inv;
    if (v < 0.0f || u + v > 1.0f) return -1.0f;
    const float t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    return t >= 0.0f && t <= max_t ? t : -1.0f;
}

}  // namespace

std::optional<ViewerSession::Picked> ViewerSession::pick(SDL_FPoint pixel, const ViewSettings& view) const {
    const Camera camera = scene_camera(scene(), view);
    float on_plane[3], direction[3];
    camera.unproject(pixel, on_plane);
    camera.view_direction(direction);
    // From well in front of the level, along the view, to well behind it.
    const float* lo = level_.info.bounds_min;
    const float* hi = level_.info.bounds_max;
    float reach = 0.0f;
    for (int k = 0; k < 3; ++k) reach += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    reach = std::sqrt(reach) + 10.0f;
    float origin[3];
    for (int k = 0; k < 3; ++k) origin[k] = on_plane[k] - direction[k] * reach;

    // The navmesh polygons first: the nearest one the ray meets (a polygon is convex: a fan).
    float nearest = -1.0f;
    uint32_t polygon = NL_NO_POLYGON;
    for (uint32_t p = 0; p < contents_.polygons.size(); ++p) {
        const nl_nav_polygon& poly = contents_.polygons[p];
        const float* first = &contents_.vertices[3 * size_t(poly.vertices[0])];
        for (uint32_t k = 1; k + 1 < poly.vertex_count; ++k) {
            const float t =
                ray_triangle(origin, direction, 2.0f * reach, first, &contents_.vertices[3 * size_t(poly.vertices[k])],
                             &contents_.vertices[3 * size_t(poly.vertices[k + 1])]);
            if (t >= 0.0f && (nearest < 0.0f || t < nearest)) {
                nearest = t;
                polygon = p;
            }
        }
    }
    if (polygon != NL_NO_POLYGON)
        return Picked{{origin[0] + direction[0] * nearest, origin[1] + direction[1] * nearest,
                       origin[2] + direction[2] * nearest},
                      polygon};

    nl_ray ray{};
    for (int k = 0; k < 3; ++k) {
        ray.origin[k] = origin[k];
        ray.direction[k] = direction[k];
    }
    ray.max_distance = 2.0f * reach;
    nl_ray_hit hit = nl_ray_hit_init();
    // Picking only reads the level; a failure (a point beyond the coordinate limit) is a miss.
    if (NL_FAILED(nl_world_cast_rays(world_.get(), &ray, 1, &hit)) || !hit.hit) return std::nullopt;
    return Picked{{hit.point[0], hit.point[1], hit.point[2]}, NL_NO_POLYGON};
}

template <typename Visit>
void ViewerSession::for_selected(Visit visit) {
    for (size_t i = 0; i < agents_.size(); ++i)
        if (all_agents_ || i == current_) visit(i);
}

template <typename Change>
void ViewerSession::with_every_tile(Change change) {
    if (!streaming_) {
        change();
        return;
    }
    // Path requests made now plan over every tile (a request reads the navmesh of the moment).
    if (!streamer_->load_all().empty()) read_navmesh();
    change();
    whole_ = contents_;
    plan_routes();
    stream();
}

bool ViewerSession::set_start(const Point& start) {
    bool all = true;
    with_every_tile([&] {
        start_ = start;
        for_selected([&](size_t i) { all = crowd_->teleport(i, start) && all; });
        request_paths();
    });
    return all;
}

bool ViewerSession::set_destination(const Point& destination) {
    bool all = true;
    with_every_tile([&] {
        destination_ = destination;
        for_selected([&](size_t i) { all = crowd_->send(i, destination) && all; });
        request_paths();
    });
    return all;
}

void ViewerSession::read_islands() {
    islands_ = picture::read_islands(world_.get(), navmesh_, agents_[current_].capabilities, agents_[current_].name);
}

void ViewerSession::select_agent(size_t index) {
    with_every_tile([&] {
        current_ = index % agents_.size();
        all_agents_ = false;
        request_paths();
    });
    read_islands();
}

void ViewerSession::toggle_all_agents() {
    with_every_tile([&] {
        all_agents_ = !all_agents_;
        request_paths();
    });
}

void ViewerSession::read_navmesh() {
    contents_ = samples::read_navmesh_contents(world_.get(), navmesh_);
    read_islands();
}

std::string ViewerSession::followed() const { return all_agents_ ? "the agents" : "the " + agents_[current_].name; }

bool ViewerSession::set_streaming(bool on) {
    if (on == streaming_) return true;
    if (!streamer_) {
        std::printf("tile streaming: %s\n", platforms_.empty()
                                                ? "the navmesh is not tiled (build it in tiles: --tile-size N)"
                                                : "not with the moving platforms");
        return false;
    }
    streaming_ = on;
    if (on) {
        whole_ = contents_;
        std::printf("tile streaming on: the tiles within %g m of %s stay loaded, of %zu tiles of %g m\n",
                    double(stream_radius_), followed().c_str(), streamer_->total(), double(streamer_->tile_width()));
        plan_routes();
        stream();
        return true;
    }
    if (!streamer_->load_all().empty()) read_navmesh();
    // Sent along their way by waypoints: now to the destination itself.
    for (size_t i = 0; i < agents_.size(); ++i)
        if (routes_[i] && !routes_[i]->done) crowd_->redirect(i, routes_[i]->destination);
    routes_.assign(agents_.size(), std::nullopt);
    std::printf("tile streaming off: every tile loaded (%zu)\n", streamer_->total());
    return true;
}

void ViewerSession::plan_routes() {
    std::vector<bool> en_route(agents_.size(), false);
    for (size_t i = 0; i < agents_.size(); ++i) en_route[i] = routes_[i] && !routes_[i]->done;
    routes_.assign(agents_.size(), std::nullopt);
    if (!destination_) return;
    for_selected([&](size_t i) {
        const nl_agent_info& info = crowd_->info(i);
        const bool stopped = info.state == NL_AGENT_ARRIVED || info.state == NL_AGENT_FAILED;
        if (!info.has_destination || (stopped && !en_route[i])) return;
        samples::PlannedPath path =
            samples::find_path(world_.get(), navmesh_, info.position, destination_->data(), agents_[i].capabilities);
        if (path.result.outcome != NL_PATH_COMPLETE && path.result.outcome != NL_PATH_PARTIAL) return;
        StreamedRoute route;
        route.points = std::move(path.points);
        route.destination = *destination_;
        route.partial = path.result.outcome == NL_PATH_PARTIAL;
        routes_[i] = std::move(route);
    });
}

bool ViewerSession::stream() {
    std::vector<TileStreamer::Point> centres;
    for_selected([&](size_t i) {
        const float* p = crowd_->info(i).position;
        centres.push_back({p[0], p[1], p[2]});
    });
    const TileStreamer::Change change = streamer_->follow(centres, stream_radius_);
    if (!change.empty()) {
        read_navmesh();
        ++tile_changes_;
        last_tile_change_ = change;
        std::printf("%7.2f s  tiles %s: %zu of %zu loaded\n", double(crowd_->time()), change_text(change).c_str(),
                    streamer_->loaded_count(), streamer_->total());
    }
    steer_along_routes();
    return !change.empty();
}

// Each chosen agent on a route: to the farthest point of it the loaded tiles hold, a little inside
// them (so that the tiles beyond come within range before it gets there), and to the destination
// once they hold the rest of the way.
void ViewerSession::steer_along_routes() {
    const float margin = std::min(1.0f, 0.25f * stream_radius_);
    for (size_t i = 0; i < agents_.size(); ++i) {
        if (!routes_[i] || routes_[i]->done) continue;
        StreamedRoute& route = *routes_[i];
        const nl_agent_info& info = crowd_->info(i);
        if (samples::in_the_air(info.state)) continue;  // it lands first
        const bool stopped = info.state == NL_AGENT_ARRIVED || info.state == NL_AGENT_IDLE ||
                             info.state == NL_AGENT_FAILED ||
                             (info.state == NL_AGENT_WAITING && info.reason == NL_AGENT_REASON_TILE_UNLOADED);
        advance_on_route(route, info.position);
        const std::optional<Waypoint> waypoint = waypoint_on_route(route, *streamer_, margin);
        if (waypoint && waypoint->final) {
            // The destination itself, or where a route that falls short of it ends (the agent goes as
            // near as it can) when the tiles loaded do not hold the destination.
            const float* d = route.destination.data();
            const float* end = route.points.back().position;
            crowd_->redirect(i, streamer_->holds(d[0], d[2], 0.0f) ? route.destination : Point{end[0], end[1], end[2]});
            route.done = true;
            continue;
        }
        const bool further =
            waypoint && (!route.waypoint || std::hypot((*route.waypoint)[0] - waypoint->point[0],
                                                       (*route.waypoint)[1] - waypoint->point[1],
                                                       (*route.waypoint)[2] - waypoint->point[2]) > 0.5f);
        if (further) {
            // Tried once per place: a waypoint refused (said on stdout) is not tried again each frame.
            crowd_->redirect(i, waypoint->point);
            route.waypoint = waypoint->point;
        } else if (stopped) {
            std::printf("%s: the tiles loaded hold no more of its way\n", agents_[i].name.c_str());
            route.done = true;
        }
    }
}

bool ViewerSession::arrived(size_t index) const {
    return crowd_->info(index).state == NL_AGENT_ARRIVED && !(routes_[index] && routes_[index]->partial);
}

bool ViewerSession::agents_moving() const {
    if (crowd_->moving()) return true;
    for (const auto& route : routes_)
        if (route && !route->done) return true;
    return false;
}

void ViewerSession::cancel_pending() {
    for (const Pending& p : pending_) nl_path_release(world_.get(), p.ticket);  // cancels it if unfinished
    pending_.clear();
}

bool ViewerSession::advance(float dt) {
    if (platforms_.empty()) {
        const bool moved = crowd_->step(dt);
        return (streaming_ && stream()) || moved;
    }
    time_ += dt;
    samples::move_platforms(world_.get(), platforms_, time_);
    // The gangways onto the platforms are links of the ground: their ends have moved with them.
    contents_.links = samples::read_links(world_.get(), navmesh_);
    read_islands();  // a gangway holds or not as its platform comes and goes
    crowd_->step(dt, true);
    return true;
}

void ViewerSession::request_paths() {
    cancel_pending();
    for (auto& path : paths_) path.reset();
    // A path request plans within one navmesh: routes over the platforms are the agents' own.
    if (!destination_ || !platforms_.empty()) return;
    for_selected([&](size_t i) {
        const nl_path_request_def def =
            samples::path_request(navmesh_, start_.data(), destination_->data(), agents_[i].capabilities);
        nl_path_ticket ticket{};
        samples::check(nl_path_request(world_.get(), &def, &ticket), "requesting a path");
        pending_.push_back({i, ticket});
    });
}

bool ViewerSession::update() {
    bool changed = false;
    for (size_t k = 0; k < pending_.size();) {
        nl_path_outcome outcome = NL_PATH_PENDING;
        samples::check(nl_path_poll(world_.get(), pending_[k].ticket, &outcome), "polling a path");
        if (outcome == NL_PATH_PENDING) {
            ++k;
            continue;
        }
        paths_[pending_[k].agent] = samples::queued_result(world_.get(), pending_[k].ticket);
        nl_path_release(world_.get(), pending_[k].ticket);
        pending_.erase(pending_.begin() + static_cast<long>(k));
        changed = true;
    }
    return changed;
}

void ViewerSession::wait_for_paths() {
    while (waiting()) {
        samples::check(nl_path_process(world_.get(), nullptr, nullptr), "running the path queue");
        update();
    }
}

Scene ViewerSession::scene() const {
    Scene scene;
    scene.level = &level_;
    scene.navmesh = &contents_;
    if (streaming_) scene.whole_navmesh = &whole_;
    scene.islands = &islands_;
    scene.title = level_.name + "  |  agent: " + (all_agents_ ? std::string("all") : agents_[current_].name);
    if (streaming_) {
        char text[128];
        std::snprintf(text, sizeof text, "streaming: %zu of %zu tiles loaded,\n(those within %g m of %s)",
                      streamer_->loaded_count(), streamer_->total(), double(stream_radius_), followed().c_str());
        scene.streaming = text;
    }
    for (size_t i = 0; i < agents_.size(); ++i) {
        if (!paths_[i]) continue;
        const samples::PlannedPath& p = *paths_[i];
        char label[112];
        std::snprintf(label, sizeof label, "%s: %.1f m, %s%s%s", agents_[i].name.c_str(), p.result.length,
                      samples::describe_links(samples::count_links(p)).c_str(),
                      p.result.outcome == NL_PATH_COMPLETE ? "" : "; ",
                      p.result.outcome == NL_PATH_COMPLETE ? "" : samples::outcome_name(p.result.outcome));
        scene.paths.push_back({label, palette::agent(i), p.points});
    }
    scene.agents = crowd_->scene_agents();
    scene.platforms = scene_platforms(world_.get(), platforms_, time_);
    if (platforms_level_ && !destination_) {
        // Where each passenger goes (a place on a platform has moved with it), not one start.
        for (size_t i = 0; i < agents_.size(); ++i) {
            const nl_agent_info& info = crowd_->info(i);
            if (info.has_destination)
                scene.points.push_back({platforms_level_->passengers[i].destination_name,
                                        {info.destination[0], info.destination[1], info.destination[2]},
                                        palette::kText});
        }
        return scene;
    }
    scene.points.push_back({"start", {start_[0], start_[1], start_[2]}, palette::kText});
    if (destination_)
        scene.points.push_back(
            {"destination", {(*destination_)[0], (*destination_)[1], (*destination_)[2]}, palette::kText});
    return scene;
}

bool ViewerSession::every_path_complete() const {
    for (size_t i = 0; i < agents_.size(); ++i)
        if ((all_agents_ || i == current_) && (!paths_[i] || paths_[i]->result.outcome != NL_PATH_COMPLETE))
            return false;
    return true;
}

std::optional<ViewerSession::Point> ViewerSession::destination() const { return destination_; }

std::string ViewerSession::status() const {
    std::string out = all_agents_ ? "all agents" : agents_[current_].name;
    for (size_t i = 0; i < agents_.size(); ++i) {
        if (!paths_[i]) continue;
        char text[96];
        std::snprintf(text, sizeof text, "; %s %s %.1f m", agents_[i].name.c_str(),
                      samples::outcome_name(paths_[i]->result.outcome), paths_[i]->result.length);
        out += text;
    }
    if (waiting()) out += "; planning...";
    if (streaming_)
        out += "; tiles " + std::to_string(streamer_->loaded_count()) + "/" + std::to_string(streamer_->total());
    const std::string moving = crowd_->status();
    if (!moving.empty()) out += "; " + moving;
    return out;
}

}  // namespace nl::picture
