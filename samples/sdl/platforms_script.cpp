#include "platforms_script.h"

#include <cstdio>
#include <set>
#include <vector>

#include "world_agents.h"
#include "png_export.h"
#include "sample_error.h"

namespace nl::picture {
namespace {

constexpr float kFrameTime = 1.0f / 60.0f;
constexpr float kPlayLimit = 90.0f;  // seconds: the passengers arrive in about 22

// What passenger `i` is doing with a platform now, in words, or "" when it is nothing worth a frame.
std::string moment(const ViewerSession& session, size_t i) {
    const nl_agent_info& info = session.crowd().info(i);
    const auto gangway = samples::find_gangway(session.platforms(), info.link);
    if (!gangway) return "";
    const samples::PlatformLayout& platform = *gangway->platform->layout;
    const std::string& who = session.agents()[i].name;
    if (samples::in_the_air(info.state)) {
        if (gangway->gangway->onto || info.link_progress < 0.5f) return "";
        return who + (info.state == NL_AGENT_JUMPING ? " jumps" : " walks") + " off the " + platform.name;
    }
    if (info.state != NL_AGENT_WAITING) return "";
    nl_link link = nl_link_init();
    samples::check(nl_link_get(session.world(), info.link, &link), "reading a gangway");
    if (link.holds) return "";  // waiting for its landing to clear, not for the platform
    if (gangway->gangway->onto) return who + " waits for the " + platform.name;
    // On board, waiting at the way off while the platform takes it there.
    const samples::Timetable& timetable = platform.timetable;
    const float along = timetable.progress(session.time());
    if (!timetable.turns() && !timetable.docked(session.time()) && along > 0.45f && along < 0.55f)
        return who + " rides the " + platform.name + " half-way";
    return who + " waits on the " + platform.name + " for its way off";
}

}  // namespace

int run_platforms_script(ViewerSession& session, ViewSettings view, const std::string& dir) {
    int frame = 0;
    auto shoot = [&](const std::string& what) {
        const Scene scene = session.scene();
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%02d.png", frame++);
        write_png(scene, view, dir + name);
        std::string where;
        for (const ScenePlatform& platform : scene.platforms) where += (where.empty() ? "" : "; ") + platform.label;
        std::printf("%s%s: %s | %s | %s\n", dir.c_str(), name, what.c_str(), session.status().c_str(), where.c_str());
    };

    shoot("the passengers on the apron, the platforms where their timetables start");
    std::set<std::string> shown;
    float time = 0.0f;
    for (; session.agents_moving() && time < kPlayLimit; time += kFrameTime) {
        session.advance(kFrameTime);
        std::string what;
        for (size_t i = 0; i < session.agents().size(); ++i) {
            // Each moment once, by whoever comes to it first.
            const std::string now = moment(session, i);
            if (now.empty() || !shown.insert(now.substr(session.agents()[i].name.size())).second) continue;
            what += (what.empty() ? "" : "; ") + now;
        }
        if (!what.empty()) shoot(what);
    }
    shoot("the passengers after " + std::to_string(static_cast<int>(time)) + " s");
    bool all_arrived = true;
    for (size_t i = 0; i < session.agents().size(); ++i)
        all_arrived = all_arrived && session.crowd().info(i).state == NL_AGENT_ARRIVED;
    std::printf("agents: %s\n", all_arrived ? "every agent arrived" : "not every agent arrived");
    return all_arrived ? 0 : 1;
}

}  // namespace nl::picture
