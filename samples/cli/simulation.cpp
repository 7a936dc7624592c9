#include "simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "world_agents.h"
#include "palette.h"
#include "sample_error.h"

namespace nl::cli {
namespace {

// A track point every this many seconds on the ground; every step in the air, so arcs stay round.
constexpr float kTrackInterval = 0.25f;

nl_path_point track_point(const float position[3]) {
    nl_path_point point = nl_path_point_init();
    for (int k = 0; k < 3; ++k) point.position[k] = point.apex[k] = position[k];
    point.segment = NL_SEGMENT_WALK;
    return point;
}

float distance(const float a[3], const float b[3]) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

nl_link read_link(const nl_world* world, nl_link_id id) {
    nl_link link = nl_link_init();
    samples::check(nl_link_get(world, id, &link), "reading a link");
    return link;
}

}  // namespace

Simulation::Simulation(nl_world* world, const std::vector<samples::MovingPlatform>* platforms)
    : world_(world), platforms_(platforms) {}

void Simulation::add_agent(const samples::AgentProfile& profile, nl_navmesh_id navmesh, const float start[3],
                           const float destination[3], bool destination_rides) {
    AgentRun run;
    run.profile = profile;
    nl_agent_def def = samples::agent_def(profile, navmesh, start);
    def.user_data = runs_.size();
    samples::check(nl_agent_add(world_, &def, &run.id), "adding " + profile.name);
    samples::check(nl_agent_set_destination(world_, run.id, destination), "sending " + profile.name);
    for (int k = 0; k < 3; ++k) run.destination[k] = destination[k];
    run.destination_rides = destination_rides;
    run.track.push_back(track_point(start));
    for (int k = 0; k < 3; ++k) run.last_position[k] = start[k];
    name_width_ = std::max(name_width_, static_cast<int>(profile.name.size()));
    runs_.push_back(std::move(run));
}

std::string Simulation::link_word(nl_trajectory_kind kind, nl_link_id link) const {
    const auto gangway = platforms_ ? samples::find_gangway(*platforms_, link) : std::nullopt;
    std::string word = kind == NL_TRAJECTORY_ARC    ? "jumps"
                       : kind == NL_TRAJECTORY_FALL ? "drops"
                       : gangway                    ? "walks"
                                                    : "takes a link";
    if (gangway) word += (gangway->gangway->onto ? " onto the " : " off the ") + gangway->platform->layout->name;
    return word;
}

// Counts the link and prints the take-off, read from the trajectory the agent now flies.
void Simulation::report_take_off(AgentRun& run, nl_link_id link_id, float time) {
    nl_agent_trajectory trajectory = nl_agent_trajectory_init();
    samples::check(nl_agent_get_trajectory(world_, run.id, &trajectory), "reading a trajectory");
    const nl_link link = read_link(world_, link_id);
    // A drop climbed back up is flown as a jump: count what the body did.
    samples::count_link(run.links_taken, trajectory.kind == NL_TRAJECTORY_ARC    ? NL_LINK_JUMP
                                         : trajectory.kind == NL_TRAJECTORY_FALL ? NL_LINK_DROP
                                                                                 : link.kind);
    std::printf("  %6.2f s  %-*s %-12s from (%.1f, %.1f, %.1f) to (%.1f, %.1f, %.1f) in %.2f s", time, name_width_,
                run.profile.name.c_str(), link_word(trajectory.kind, link_id).c_str(), trajectory.from[0],
                trajectory.from[1], trajectory.from[2], trajectory.to[0], trajectory.to[1], trajectory.to[2],
                trajectory.duration);
    if (samples::same_link(run.waiting_for, link_id)) std::printf(", after waiting %.1f s", run.waited_there);
    std::printf("\n");
    run.waiting_for = nl_link_id{};
}

// Prints the start of a wait at a take-off: for a platform that is away, or for the landing to clear.
void Simulation::report_wait(AgentRun& run, const nl_agent_info& info, float time) {
    const nl_link link = read_link(world_, info.link);
    const auto gangway = platforms_ ? samples::find_gangway(*platforms_, info.link) : std::nullopt;
    std::string what = "for its landing to clear";
    if (gangway && !link.holds) {
        const std::string& platform = gangway->platform->layout->name;
        what = gangway->gangway->onto ? "for the " + platform : "on the " + platform + " for its way off";
    }
    std::printf("  %6.2f s  %-*s waits %s at (%.1f, %.1f, %.1f)\n", time, name_width_, run.profile.name.c_str(),
                what.c_str(), info.position[0], info.position[1], info.position[2]);
    run.waiting_for = info.link;
    run.waited_there = 0.0f;
}

void Simulation::read_events(float time) {
    for (const nl_agent_event& event : samples::read_agent_events(world_)) {
        AgentRun& run = runs_.at(event.user_data);
        switch (event.kind) {
            case NL_AGENT_EVENT_LINK_STARTED: report_take_off(run, event.link, time); break;
            case NL_AGENT_EVENT_REPLANNED: ++run.replans; break;
            case NL_AGENT_EVENT_ARRIVED:
            case NL_AGENT_EVENT_FAILED: {
                const nl_agent_info info = samples::read_agent(world_, run.id);
                run.ended_at = time;
                run.arrived = event.kind == NL_AGENT_EVENT_ARRIVED;
                run.failure = event.reason;
                std::printf("  %6.2f s  %-*s %s at (%.1f, %.1f, %.1f)\n", time, name_width_, run.profile.name.c_str(),
                            run.arrived ? "arrives" : "fails", info.position[0], info.position[1], info.position[2]);
                break;
            }
            default: break;
        }
    }
}

void Simulation::read_agents(float time, float dt, bool on_interval) {
    for (const nl_agent_info& info : samples::read_agents(world_)) {
        AgentRun& run = runs_.at(info.user_data);
        run.travelled += distance(run.last_position, info.position);
        for (int k = 0; k < 3; ++k) run.last_position[k] = info.position[k];
        if (on_interval || samples::in_the_air(info.state) || info.state == NL_AGENT_ARRIVED)
            run.track.push_back(track_point(info.position));
        // Waiting for its path has no link; waiting at a take-off has the link it is to take.
        if (info.state == NL_AGENT_WAITING && info.link.index1) {
            if (!samples::same_link(run.waiting_for, info.link)) report_wait(run, info, time);
            run.waited_there += dt;
            run.waited += dt;
        } else if (!samples::in_the_air(info.state)) {
            run.waiting_for = nl_link_id{};  // it went another way
        }
    }
}

void Simulation::run(double dt, double seconds) {
    dt_ = dt;
    const auto steps_per_track_point = static_cast<long>(std::lround(std::max(1.0, kTrackInterval / dt)));
    auto running = [this] {
        for (const AgentRun& run : runs_)
            if (!run.ended_at) return true;
        return false;
    };
    for (; running() && steps_ * dt < seconds; ++steps_) {
        const double time = (steps_ + 1) * dt;
        // The platforms stand where they are at the end of the step: the step carries the riders
        // there and aims the flights onto them at where they will be.
        if (platforms_) samples::move_platforms(world_, *platforms_, time);
        samples::check(nl_world_step(world_, static_cast<float>(dt)), "stepping the world");
        read_events(static_cast<float>(time));
        read_agents(static_cast<float>(time), static_cast<float>(dt), (steps_ + 1) % steps_per_track_point == 0);
    }
}

float Simulation::seconds_or_now(const AgentRun& run) const {
    return run.ended_at.value_or(static_cast<float>(elapsed()));
}

void Simulation::print_table() const {
    std::printf("\n%-*s | %-8s %8s  %-22s %9s %9s  %s\n", name_width_, "agent", "outcome", "time", "where", "to goal",
                "travelled", "links taken");
    for (const AgentRun& run : runs_) {
        const nl_agent_info info = samples::read_agent(world_, run.id);
        const std::string outcome = run.arrived    ? "arrived"
                                    : run.ended_at ? std::string("failed: ") + samples::agent_reason_name(run.failure)
                                                   : "on its way";
        char where[48];
        std::snprintf(where, sizeof where, "(%.1f, %.1f, %.1f)", info.position[0], info.position[1], info.position[2]);
        // A destination on a platform has moved with it: the agent's own record says where it is now.
        const float* destination = run.destination_rides && info.has_destination ? info.destination : run.destination;
        std::printf("%-*s | %-8s %6.1f s  %-22s %7.2f m %7.1f m  %s, %d replans", name_width_, run.profile.name.c_str(),
                    outcome.c_str(), seconds_or_now(run), where, distance(info.position, destination), run.travelled,
                    samples::describe_links(run.links_taken).c_str(), run.replans);
        if (run.waited > 0.0f) std::printf(", waited %.1f s", run.waited);
        std::printf("\n");
    }
}

std::vector<picture::PathLayer> Simulation::tracks() const {
    std::vector<picture::PathLayer> layers;
    for (size_t i = 0; i < runs_.size(); ++i) {
        const AgentRun& run = runs_[i];
        char label[96];
        std::snprintf(label, sizeof label, "%s: %.1f s, %s", run.profile.name.c_str(), seconds_or_now(run),
                      samples::describe_links(run.links_taken).c_str());
        layers.push_back({label, picture::palette::agent(i), run.track});
    }
    return layers;
}

std::vector<picture::ScenePoint> Simulation::destinations(const std::vector<std::string>& labels) const {
    std::vector<picture::ScenePoint> points;
    for (size_t i = 0; i < runs_.size() && i < labels.size(); ++i) {
        const AgentRun& run = runs_[i];
        const nl_agent_info info = samples::read_agent(world_, run.id);
        const float* at = run.destination_rides && info.has_destination ? info.destination : run.destination;
        points.push_back({labels[i], {at[0], at[1], at[2]}, picture::palette::kText});
    }
    return points;
}

bool Simulation::all_arrived() const {
    for (const AgentRun& run : runs_)
        if (!run.arrived) return false;
    return true;
}

}  // namespace nl::cli
