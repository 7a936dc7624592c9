// Agents stepped until each has arrived or failed, as a host sees them through the C ABI (nl_agent_*):
// each take-off, wait and arrival printed as it happens, the track each really took, and a table of
// how it went. Platforms the host moves, if any, go where their timetables have them before each
// step, and name their gangways in what is printed.
#pragma once

#include <navlink/navlink.h>

#include <optional>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "moving_platforms.h"
#include "path_plan.h"
#include "scene.h"

namespace nl::cli {

class Simulation {
public:
    // `platforms` (borrowed; none when null) are moved before every step.
    explicit Simulation(nl_world* world, const std::vector<samples::MovingPlatform>* platforms = nullptr);

    // Adds an agent standing at `start` of `navmesh` and sends it to `destination`; one on a platform
    // (`destination_rides`) moves with it. Throws SampleError.
    void add_agent(const samples::AgentProfile& profile, nl_navmesh_id navmesh, const float start[3],
                   const float destination[3], bool destination_rides = false);

    // Steps every `dt` seconds until every agent has arrived or failed, or `seconds` have passed.
    void run(double dt, double seconds);

    // Outcome, time, place, distance to the destination, metres travelled, links taken, replans, and
    // how long it waited at take-offs.
    void print_table() const;
    // The track each agent took, in its colour, labelled with its time and its links.
    std::vector<picture::PathLayer> tracks() const;
    // Where each agent's destination is now (one on a platform has moved with it).
    std::vector<picture::ScenePoint> destinations(const std::vector<std::string>& labels) const;
    bool all_arrived() const;
    // Seconds stepped so far.
    double elapsed() const { return static_cast<double>(steps_) * dt_; }

private:
    // One agent's run: its track, the links it took, its waits, its end.
    struct AgentRun {
        samples::AgentProfile profile;
        nl_agent_id id{};
        float destination[3] = {};
        bool destination_rides = false;
        std::vector<nl_path_point> track;
        float last_position[3] = {};  // at the last step, for the distance travelled
        float travelled = 0.0f;
        samples::LinkCounts links_taken;  // as flown: a drop climbed back up is a jump
        int replans = 0;
        nl_link_id waiting_for{};       // the take-off it stands at, waiting; null when it is not
        float waited_there = 0.0f;      // seconds, at that take-off
        float waited = 0.0f;            // seconds, at every take-off
        std::optional<float> ended_at;  // seconds into the run
        bool arrived = false;
        nl_agent_reason failure = NL_AGENT_REASON_NONE;
    };

    void read_events(float time);
    void read_agents(float time, float dt, bool on_interval);
    void report_take_off(AgentRun& run, nl_link_id link, float time);
    void report_wait(AgentRun& run, const nl_agent_info& info, float time);
    // How a take-off is told: "jumps", "drops", "walks onto the shuttle", "jumps off the shuttle"...
    std::string link_word(nl_trajectory_kind kind, nl_link_id link) const;
    float seconds_or_now(const AgentRun& run) const;

    nl_world* world_;
    const std::vector<samples::MovingPlatform>* platforms_;
    std::vector<AgentRun> runs_;
    int name_width_ = 13;
    long steps_ = 0;
    double dt_ = 0.0;
};

}  // namespace nl::cli
