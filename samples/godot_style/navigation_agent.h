// An agent that navigates, as Godot's NavigationAgent3D with its body: a NavLink agent (nl_agent_*)
// with the capabilities of its profile. NavLink moves it: it follows its path, jumps and drops along
// the trajectories the link generator checked, checks each link just before take-off and plans again
// if the link is gone. The node only turns the agent's events into signals and keeps a record of
// what the body did, for the scene's printout and the harness's tests.
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "godot_signal.h"
#include "node.h"

namespace nl::godot_style {

class NavigationRegion;
using Vec3 = std::array<float, 3>;

// A link the agent took, as it was when the agent took off.
struct TakenLink {
    nl_link link = nl_link_init();         // the link's record (kind, ends, requirements)
    uint8_t reversed = 0;                  // taken from its end to its start
    nl_segment_kind as = NL_SEGMENT_WALK;  // how it was travelled (a drop climbed back up is a jump)
    float apex_height = 0.0f;              // the top of the arc the generator checked (jumps)
    float peak_height = 0.0f;              // the highest the body went on it
    double waited = 0.0;                   // seconds it stood at the take-off first: for a platform that
                                           // was away, or for the landing to clear
};

class NavigationAgent : public Node {
public:
    NavigationAgent(std::string name, NavigationRegion& region, samples::AgentProfile profile, Vec3 position);

    void set_target_position(const Vec3& target);

    Signal<const std::vector<nl_path_point>&> path_ready;  // a path was planned: its corners
    Signal<const TakenLink&> link_reached;                 // took off on a link
    Signal<> target_reached;                               // at the target
    Signal<nl_agent_reason> navigation_failed;             // cannot get there, and why

    const samples::AgentProfile& profile() const { return profile_; }
    nl_agent_id agent() const { return agent_; }
    const Vec3& position() const { return position_; }
    bool arrived() const { return arrived_; }
    bool failed() const { return failed_; }
    double arrival_time() const { return arrival_time_; }
    const std::vector<TakenLink>& taken_links() const { return taken_; }
    double distance_travelled() const { return travelled_; }
    int paths_planned() const { return paths_planned_; }
    // Why it planned again, in order (pushed off its path in a crowd, a link gone, ...).
    const std::vector<nl_agent_reason>& replan_reasons() const { return replan_reasons_; }

protected:
    void ready() override;
    void process(double delta) override;
    void exit_tree() override;

private:
    friend class NavigationServer;
    void on_navigation_event(const nl_agent_event& event);
    void take_off(nl_link_id link);

    NavigationRegion& region_;
    samples::AgentProfile profile_;
    Vec3 position_;
    std::optional<Vec3> target_;
    nl_agent_id agent_{};
    bool in_air_ = false, arrived_ = false, failed_ = false;
    double arrival_time_ = 0.0, travelled_ = 0.0;
    double waiting_ = 0.0;  // seconds at the take-off it waits at now
    int paths_planned_ = 0;
    std::vector<TakenLink> taken_;
    std::vector<nl_agent_reason> replan_reasons_;
};

}  // namespace nl::godot_style
