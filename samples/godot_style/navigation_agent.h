// An agent that navigates, as Godot's NavigationAgent3D with its body: it has capabilities (how far
// it jumps, how deep it drops, its abilities), asks the navigation server for a path to its target,
// and follows it frame by frame, taking jumps along their arcs and dropping off ledges. Before it
// takes a link it checks the link still exists; if not, it plans again from where it stands.
#pragma once

#include <navlink/navlink.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "node.h"
#include "path_plan.h"
#include "godot_signal.h"
#include "traversal.h"

namespace nl::godot_style {

class NavigationRegion;

// A link the agent took, as it was when the agent took it.
struct TakenLink {
    nl_link link = nl_link_init();        // the link's record (kind, ends, requirements)
    uint8_t reversed;    // taken from its end to its start
    nl_segment_kind as;  // how it was travelled (a drop climbed back up is a jump)
    float apex_height;   // the path point's apex height
    float peak_height;   // the highest the body actually went
};

class NavigationAgent : public Node {
public:
    NavigationAgent(std::string name, NavigationRegion& region, samples::AgentProfile profile, Vec3 position,
                    Body body = {});

    void set_target_position(const Vec3& target);

    Signal<const samples::PlannedPath&> path_ready;  // a path arrived and is being followed
    Signal<const TakenLink&> link_reached;           // about to take a link
    Signal<> target_reached;                         // at the end of a complete path
    Signal<nl_path_outcome> navigation_failed;       // no complete path to the target

    const samples::AgentProfile& profile() const { return profile_; }
    const Vec3& position() const { return position_; }
    bool arrived() const { return arrived_; }
    bool failed() const { return failed_; }
    double arrival_time() const { return arrival_time_; }
    const std::vector<TakenLink>& taken_links() const { return taken_; }
    double distance_travelled() const { return travelled_; }
    int paths_requested() const { return paths_requested_; }

protected:
    void ready() override;
    void process(double delta) override;
    void exit_tree() override;

private:
    void request_path();
    void on_path(nl_path_ticket ticket, nl_path_outcome outcome);
    void begin_segment();  // at path_.points[segment_]: validate and record a link, set up the motion

    NavigationRegion& region_;
    samples::AgentProfile profile_;
    Body body_;
    Vec3 position_;
    std::optional<Vec3> target_;
    nl_path_ticket ticket_{};                                // the request in flight, if any
    std::shared_ptr<int> alive_ = std::make_shared<int>(0);  // deferred results skip a freed agent
    samples::PlannedPath path_;
    size_t segment_ = 0;  // index of the point the current segment starts at
    std::optional<SegmentMotion> motion_;
    double segment_time_ = 0.0;
    float segment_peak_ = 0.0f;
    bool following_ = false, arrived_ = false, failed_ = false;
    double arrival_time_ = 0.0, travelled_ = 0.0, clock_ = 0.0;
    int paths_requested_ = 0;
    std::vector<TakenLink> taken_;
};

}  // namespace nl::godot_style
