// The demo's three bodies as agents of the viewer's world (nl_agent_*): sent where the user clicks,
// stepped in real time, drawn where they stand or fly with the track behind them.
#pragma once

#include <navlink/navlink.h>

#include <array>
#include <string>
#include <vector>

#include "agent_profile.h"
#include "scene.h"

namespace nl::picture {

class ViewerAgents {
public:
    using Point = std::array<float, 3>;

    // Adds one agent per profile at its start (`starts[i]`) of `navmesh`. Throws SampleError.
    ViewerAgents(nl_world* world, nl_navmesh_id navmesh, const std::vector<samples::AgentProfile>& profiles,
                 const std::vector<Point>& starts);

    // Sends agent `index` to `destination`; false (and a line on stdout) when it is off the navmesh.
    bool send(size_t index, const Point& destination);
    // The same on its way (a waypoint of a longer way): its track goes on.
    bool redirect(size_t index, const Point& destination);
    // Puts agent `index` at `position` and forgets its track; false (and a line) off the navmesh.
    bool teleport(size_t index, const Point& position);
    // Advances the world by `dt` seconds when an agent is on its way, or always when `surfaces_move`
    // (platforms carry the agents standing on them); true if one moved. Prints each take-off,
    // arrival and failure.
    bool step(float dt, bool surfaces_move = false);
    // Whether an agent is on its way (one waiting on a tile that was unloaded is not: stepping the
    // world does not bring it on, loading its tile does).
    bool moving() const;
    const nl_agent_info& info(size_t index) const { return infos_.at(index); }
    float time() const { return time_; }  // seconds stepped

    // Where each agent is, its track, and in the air the trajectory it flies.
    std::vector<SceneAgent> scene_agents() const;
    // "long jumper jumping 40%, walker walking" (the agents not standing still).
    std::string status() const;

private:
    // After a send or teleport: a line and false when it was refused, else a fresh track.
    bool moved(size_t index, nl_status status, const char* what);
    void read_back();

    nl_world* world_;
    std::vector<samples::AgentProfile> profiles_;
    std::vector<nl_agent_id> ids_;
    std::vector<nl_agent_info> infos_;
    std::vector<std::vector<Point>> tracks_;
    float time_ = 0.0f;
};

}  // namespace nl::picture
