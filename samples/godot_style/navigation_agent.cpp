#include "navigation_agent.h"

#include <algorithm>
#include <cmath>

#include "navigation_region.h"
#include "sample_error.h"
#include "scene_tree.h"

namespace nl::godot_style {

NavigationAgent::NavigationAgent(std::string name, NavigationRegion& region, samples::AgentProfile profile,
                                 Vec3 position, Body body)
    : Node(std::move(name)), region_(region), profile_(std::move(profile)), body_(body), position_(position) {}

void NavigationAgent::set_target_position(const Vec3& target) {
    target_ = target;
    arrived_ = failed_ = false;
    if (tree()) request_path();
}

void NavigationAgent::ready() {
    if (target_) request_path();
}

void NavigationAgent::exit_tree() {
    if (ticket_.index1) nl_path_release(tree()->navigation().world(), ticket_);  // cancels it if unfinished
    ticket_ = nl_path_ticket{};
}

void NavigationAgent::request_path() {
    nl_world* world = tree()->navigation().world();
    if (ticket_.index1) nl_path_release(world, ticket_);  // a newer target replaces the old request
    following_ = false;
    motion_.reset();
    const nl_path_request_def def =
        samples::path_request(region_.navmesh(), position_.data(), target_->data(), profile_.capabilities);
    std::weak_ptr<int> alive = alive_;
    ticket_ = tree()->navigation().query_path(def, [this, alive](nl_path_ticket ticket, nl_path_outcome outcome) {
        if (!alive.expired()) on_path(ticket, outcome);
    });
    ++paths_requested_;
}

void NavigationAgent::on_path(nl_path_ticket ticket, nl_path_outcome outcome) {
    nl_world* world = tree()->navigation().world();
    if (ticket.index1 != ticket_.index1 || ticket.generation != ticket_.generation) return;  // superseded
    if (outcome == NL_PATH_COMPLETE) path_ = samples::queued_result(world, ticket);
    nl_path_release(world, ticket);
    ticket_ = nl_path_ticket{};
    if (outcome != NL_PATH_COMPLETE) {
        failed_ = true;
        navigation_failed.emit(outcome);
        return;
    }
    segment_ = 0;
    following_ = true;
    path_ready.emit(path_);
    begin_segment();
}

void NavigationAgent::begin_segment() {
    if (segment_ + 1 >= path_.points.size()) {
        following_ = false;
        arrived_ = true;
        arrival_time_ = clock_;
        target_reached.emit();
        return;
    }
    const nl_path_point& from = path_.points[segment_];
    if (from.segment != NL_SEGMENT_WALK) {
        nl_link link = nl_link_init();
        if (NL_FAILED(nl_link_get(tree()->navigation().world(), from.link, &link))) {
            request_path();  // the link is gone (a NavigationLink left the tree): plan again from here
            return;
        }
        taken_.push_back({link, from.reversed, from.segment, from.apex[1], 0.0f});
        link_reached.emit(taken_.back());
    }
    motion_.emplace(from, path_.points[segment_ + 1], body_);
    segment_time_ = 0.0;
    segment_peak_ = position_[1];
}

void NavigationAgent::process(double delta) {
    clock_ += delta;
    double left = delta;
    // A fast body can finish several short segments in one frame.
    while (following_ && motion_ && left > 0.0) {
        const double step = std::min(left, motion_->duration() - segment_time_);
        segment_time_ += step;
        left -= step;
        const Vec3 next = motion_->position_at(segment_time_);
        travelled_ += std::sqrt((next[0] - position_[0]) * (next[0] - position_[0]) +
                                (next[1] - position_[1]) * (next[1] - position_[1]) +
                                (next[2] - position_[2]) * (next[2] - position_[2]));
        position_ = next;
        segment_peak_ = std::max(segment_peak_, position_[1]);
        if (segment_time_ < motion_->duration()) break;
        if (path_.points[segment_].segment != NL_SEGMENT_WALK && !taken_.empty())
            taken_.back().peak_height = segment_peak_;
        ++segment_;
        motion_.reset();
        begin_segment();
    }
}

}  // namespace nl::godot_style
