#include "navigation_agent.h"

#include <algorithm>
#include <cmath>

#include "world_agents.h"
#include "navigation_region.h"
#include "sample_error.h"
#include "scene_tree.h"

namespace nl::godot_style {
namespace {

float distance_squared(const float* a, const float* b) {
    float sum = 0.0f;
    for (int k = 0; k < 3; ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
    return sum;
}

nl_segment_kind travelled_as(const nl_agent_trajectory& trajectory, const nl_link& link) {
    switch (trajectory.kind) {
        case NL_TRAJECTORY_ARC: return NL_LINK_JUMP;
        case NL_TRAJECTORY_FALL: return NL_LINK_DROP;
        default: return link.kind;
    }
}

}  // namespace

NavigationAgent::NavigationAgent(std::string name, NavigationRegion& region, samples::AgentProfile profile,
                                 Vec3 position)
    : Node(std::move(name)), region_(region), profile_(std::move(profile)), position_(position) {}

void NavigationAgent::set_target_position(const Vec3& target) {
    target_ = target;
    arrived_ = failed_ = false;
    if (agent_.index1)
        samples::check(nl_agent_set_destination(tree()->navigation().world(), agent_, target.data()),
                       name() + ": setting the target");
}

void NavigationAgent::ready() {
    agent_ = tree()->navigation().add_agent(samples::agent_def(profile_, region_.navmesh(), position_.data()), *this);
    if (target_) set_target_position(*target_);
}

void NavigationAgent::exit_tree() {
    tree()->navigation().remove_agent(agent_);
    agent_ = nl_agent_id{};
}

void NavigationAgent::on_navigation_event(const nl_agent_event& event) {
    nl_world* world = tree()->navigation().world();
    switch (event.kind) {
        case NL_AGENT_EVENT_PATH_READY:
            ++paths_planned_;
            path_ready.emit(samples::read_corners(world, agent_));
            break;
        case NL_AGENT_EVENT_REPLANNED: replan_reasons_.push_back(event.reason); break;
        case NL_AGENT_EVENT_LINK_STARTED: take_off(event.link); break;
        case NL_AGENT_EVENT_LINK_FINISHED: in_air_ = false; break;
        case NL_AGENT_EVENT_ARRIVED:
            arrived_ = true;
            arrival_time_ = tree()->time();
            target_reached.emit();
            break;
        case NL_AGENT_EVENT_FAILED:
            failed_ = true;
            navigation_failed.emit(event.reason);
            break;
        default: break;
    }
}

void NavigationAgent::take_off(nl_link_id link_id) {
    nl_world* world = tree()->navigation().world();
    TakenLink taken;
    nl_agent_trajectory trajectory = nl_agent_trajectory_init();
    samples::check(nl_link_get(world, link_id, &taken.link), name() + ": reading the link it took");
    samples::check(nl_agent_get_trajectory(world, agent_, &trajectory), name() + ": reading its trajectory");
    taken.reversed =
        distance_squared(trajectory.from, taken.link.end) < distance_squared(trajectory.from, taken.link.start);
    taken.as = travelled_as(trajectory, taken.link);
    taken.apex_height = trajectory.apex[1];
    taken.peak_height = std::max(trajectory.from[1], position_[1]);
    taken.waited = waiting_;
    waiting_ = 0.0;
    taken_.push_back(taken);
    in_air_ = true;
    link_reached.emit(taken_.back());
}

void NavigationAgent::process(double delta) {
    const nl_agent_info info = samples::read_agent(tree()->navigation().world(), agent_);
    // Waiting for its path has no link; waiting at a take-off has the link it is to take.
    waiting_ = info.state == NL_AGENT_WAITING && info.link.index1 ? waiting_ + delta : 0.0;
    const Vec3 next{info.position[0], info.position[1], info.position[2]};
    travelled_ += std::sqrt(distance_squared(next.data(), position_.data()));
    position_ = next;
    if (in_air_ && !taken_.empty()) taken_.back().peak_height = std::max(taken_.back().peak_height, position_[1]);
}

}  // namespace nl::godot_style
