#include "viewer_agents.h"

#include <cmath>
#include <cstdio>

#include "world_agents.h"
#include "link_shape.h"
#include "palette.h"
#include "sample_error.h"

namespace nl::picture {
namespace {

// A track point when the agent has moved this far on the ground (every step in the air).
constexpr float kTrackSpacing = 0.2f;
constexpr size_t kTrackLimit = 4000;

bool on_its_way(nl_agent_state state) {
    return state == NL_AGENT_WALKING || state == NL_AGENT_WAITING || samples::in_the_air(state);
}

bool parked_on_unloaded_tile(const nl_agent_info& info) {
    return info.state == NL_AGENT_WAITING && info.reason == NL_AGENT_REASON_TILE_UNLOADED;
}

// The curve the agent flies, as the library describes it to a host that animates the body.
std::vector<Point3> flight_curve(const nl_agent_trajectory& t) {
    switch (t.kind) {
        case NL_TRAJECTORY_ARC: return traversal_curve(NL_LINK_JUMP, t.from, t.to, t.apex);
        case NL_TRAJECTORY_FALL: {
            std::vector<Point3> curve;
            for (const auto& p : t.points) curve.push_back({p[0], p[1], p[2]});
            return curve;
        }
        case NL_TRAJECTORY_LINE: return {{t.from[0], t.from[1], t.from[2]}, {t.to[0], t.to[1], t.to[2]}};
        default: return {};
    }
}

}  // namespace

ViewerAgents::ViewerAgents(nl_world* world, nl_navmesh_id navmesh, const std::vector<samples::AgentProfile>& profiles,
                           const std::vector<Point>& starts)
    : world_(world), profiles_(profiles), tracks_(profiles.size()) {
    for (size_t i = 0; i < profiles_.size(); ++i) {
        nl_agent_def def = samples::agent_def(profiles_[i], navmesh, starts.at(i).data());
        def.user_data = i;
        nl_agent_id id{};
        samples::check(nl_agent_add(world_, &def, &id), "adding an agent");
        ids_.push_back(id);
    }
    read_back();
}

bool ViewerAgents::send(size_t index, const Point& destination) {
    return moved(index, nl_agent_set_destination(world_, ids_.at(index), destination.data()), "go there");
}

bool ViewerAgents::redirect(size_t index, const Point& destination) {
    if (NL_FAILED(nl_agent_set_destination(world_, ids_.at(index), destination.data()))) {
        std::printf("%s cannot go there: %s\n", profiles_[index].name.c_str(), nl_get_last_error_message());
        return false;
    }
    read_back();
    return true;
}

bool ViewerAgents::teleport(size_t index, const Point& position) {
    return moved(index, nl_agent_teleport(world_, ids_.at(index), position.data()), "stand there");
}

bool ViewerAgents::moved(size_t index, nl_status status, const char* what) {
    if (NL_FAILED(status)) {
        std::printf("%s cannot %s: %s\n", profiles_[index].name.c_str(), what, nl_get_last_error_message());
        return false;
    }
    tracks_[index].clear();
    read_back();
    return true;
}

bool ViewerAgents::moving() const {
    for (const nl_agent_info& info : infos_)
        if (on_its_way(info.state) && !parked_on_unloaded_tile(info)) return true;
    return false;
}

bool ViewerAgents::step(float dt, bool surfaces_move) {
    if (!moving() && !surfaces_move) return false;
    samples::check(nl_world_step(world_, dt), "stepping the agents");
    time_ += dt;
    read_back();
    for (const nl_agent_event& event : samples::read_agent_events(world_)) {
        const size_t i = event.user_data;
        const float* p = infos_.at(i).position;
        if (event.kind == NL_AGENT_EVENT_LINK_STARTED || event.kind == NL_AGENT_EVENT_ARRIVED ||
            event.kind == NL_AGENT_EVENT_FAILED)
            std::printf("%7.2f s  %s %s%s%s at (%.1f, %.1f, %.1f)\n", time_, profiles_[i].name.c_str(),
                        samples::agent_event_name(event.kind), event.kind == NL_AGENT_EVENT_FAILED ? ": " : "",
                        event.kind == NL_AGENT_EVENT_FAILED ? samples::agent_reason_name(event.reason) : "", p[0], p[1],
                        p[2]);
    }
    return true;
}

void ViewerAgents::read_back() {
    infos_ = samples::read_agents(world_);
    for (const nl_agent_info& info : infos_) {
        std::vector<Point>& track = tracks_.at(info.user_data);
        const Point here{info.position[0], info.position[1], info.position[2]};
        const bool far = track.empty() || std::hypot(here[0] - track.back()[0], here[1] - track.back()[1],
                                                     here[2] - track.back()[2]) >= kTrackSpacing;
        if ((far || samples::in_the_air(info.state)) && track.size() < kTrackLimit) track.push_back(here);
    }
}

std::vector<SceneAgent> ViewerAgents::scene_agents() const {
    std::vector<SceneAgent> out;
    for (const nl_agent_info& info : infos_) {
        const size_t i = info.user_data;
        SceneAgent a;
        a.label = profiles_[i].name;
        a.color = palette::agent(i);
        for (int k = 0; k < 3; ++k) a.position[k] = info.position[k];
        a.radius = profiles_[i].capabilities.radius;
        a.in_air = samples::in_the_air(info.state);
        a.track = tracks_[i];
        if (a.in_air) {
            nl_agent_trajectory trajectory = nl_agent_trajectory_init();
            samples::check(nl_agent_get_trajectory(world_, ids_[i], &trajectory), "reading a trajectory");
            a.trajectory = flight_curve(trajectory);
        }
        out.push_back(std::move(a));
    }
    return out;
}

std::string ViewerAgents::status() const {
    std::string out;
    for (const nl_agent_info& info : infos_) {
        if (!on_its_way(info.state) && info.state != NL_AGENT_FAILED) continue;
        char text[96];
        if (parked_on_unloaded_tile(info))
            std::snprintf(text, sizeof text, "%s waiting for its tile", profiles_[info.user_data].name.c_str());
        else if (samples::in_the_air(info.state))
            std::snprintf(text, sizeof text, "%s %s %.0f%%", profiles_[info.user_data].name.c_str(),
                          samples::agent_state_name(info.state), 100.0f * info.link_progress);
        else
            std::snprintf(text, sizeof text, "%s %s", profiles_[info.user_data].name.c_str(),
                          samples::agent_state_name(info.state));
        out += (out.empty() ? "" : ", ") + std::string(text);
    }
    return out;
}

}  // namespace nl::picture
