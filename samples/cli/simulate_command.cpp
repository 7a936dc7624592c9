// navlink simulate: the demo's three bodies as agents (nl_agent_*) on the default level, stepped
// until each has arrived; prints when and where, and draws the tracks they really took.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "agent_reads.h"
#include "arguments.h"
#include "commands.h"
#include "demo_setup.h"
#include "help_text.h"
#include "level_generator.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "palette.h"
#include "path_plan.h"
#include "picture_export.h"
#include "sample_error.h"

namespace nl::cli {
namespace {

// One agent's run as the host sees it through the C ABI: its track, the links it took, its end.
struct AgentRun {
    samples::AgentProfile profile;
    nl_agent_id id{};
    std::vector<nl_path_point> track;
    float last_position[3] = {};  // at the last step, for the distance travelled
    float travelled = 0.0f;
    samples::LinkCounts links_taken;  // as flown: a drop climbed back up is a jump
    int replans = 0;
    std::optional<float> ended_at;  // seconds into the run
    bool arrived = false;
    nl_agent_reason failure = NL_AGENT_REASON_NONE;
    float end_position[3] = {};
};

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

const char* link_word(nl_trajectory_kind kind) {
    switch (kind) {
        case NL_TRAJECTORY_ARC: return "jumps";
        case NL_TRAJECTORY_FALL: return "drops";
        default: return "takes a link";
    }
}

// Counts the link and prints the take-off, read from the trajectory the agent now flies.
void report_take_off(const nl_world* world, AgentRun& run, float time) {
    nl_agent_trajectory trajectory = nl_agent_trajectory_init();
    samples::check(nl_agent_get_trajectory(world, run.id, &trajectory), "reading a trajectory");
    nl_link link = nl_link_init();
    samples::check(nl_link_get(world, trajectory.link, &link), "reading a link");
    // A drop climbed back up is flown as a jump: count what the body did.
    samples::count_link(run.links_taken, trajectory.kind == NL_TRAJECTORY_ARC    ? NL_LINK_JUMP
                                         : trajectory.kind == NL_TRAJECTORY_FALL ? NL_LINK_DROP
                                                                                 : link.kind);
    std::printf("  %6.2f s  %-13s %-12s from (%.1f, %.1f, %.1f) to (%.1f, %.1f, %.1f) in %.2f s\n", time,
                run.profile.name.c_str(), link_word(trajectory.kind), trajectory.from[0], trajectory.from[1],
                trajectory.from[2], trajectory.to[0], trajectory.to[1], trajectory.to[2], trajectory.duration);
}

void read_events(const nl_world* world, std::vector<AgentRun>& runs, float time) {
    for (const nl_agent_event& event : samples::read_agent_events(world)) {
        AgentRun& run = runs.at(event.user_data);
        switch (event.kind) {
            case NL_AGENT_EVENT_LINK_STARTED: report_take_off(world, run, time); break;
            case NL_AGENT_EVENT_REPLANNED: ++run.replans; break;
            case NL_AGENT_EVENT_ARRIVED:
            case NL_AGENT_EVENT_FAILED: {
                const nl_agent_info info = samples::read_agent(world, run.id);
                run.ended_at = time;
                run.arrived = event.kind == NL_AGENT_EVENT_ARRIVED;
                run.failure = event.reason;
                for (int k = 0; k < 3; ++k) run.end_position[k] = info.position[k];
                std::printf("  %6.2f s  %-13s %s at (%.1f, %.1f, %.1f)\n", time, run.profile.name.c_str(),
                            run.arrived ? "arrives" : "fails", info.position[0], info.position[1],
                            info.position[2]);
                break;
            }
            default: break;
        }
    }
}

void record_tracks(const nl_world* world, std::vector<AgentRun>& runs, bool on_interval) {
    for (const nl_agent_info& info : samples::read_agents(world)) {
        AgentRun& run = runs.at(info.user_data);
        run.travelled += distance(run.last_position, info.position);
        for (int k = 0; k < 3; ++k) run.last_position[k] = info.position[k];
        if (on_interval || samples::in_the_air(info.state) || info.state == NL_AGENT_ARRIVED)
            run.track.push_back(track_point(info.position));
    }
}

}  // namespace

int run_simulate(int argc, char** argv) {
    const samples::Arguments args("navlink simulate", "simulate", argc, argv, 2,
                                  {{"seed", true}, {"out-dir", true}, {"oblique", false}, {"hz", true},
                                   {"seconds", true}});
    if (args.wants_help()) {
        std::fputs(kSimulateHelp, stdout);
        return 0;
    }
    args.expect_positional(0, "");
    const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
    const std::string dir = args.value("out-dir").value_or(".");
    const double dt = 1.0 / static_cast<double>(args.whole_number("hz", 2, 1000, 60));
    const auto seconds = static_cast<double>(args.whole_number("seconds", 1, 3600, 120));

    const levelgen::GeneratedLevel generated = levelgen::generate_default_level(seed);
    const std::vector<samples::AgentProfile> profiles = samples::demo_agents();
    NavigableLevel level(generated, "generated default level (seed " + std::to_string(seed) + ")", profiles[0].body,
                         "");
    const nl_link_generation_report report = level.generate_links(nl_default_link_settings());
    nl_world* world = level.world();

    const float* start = generated.marker("start")->position;
    const float* goal = generated.marker("goal")->position;
    std::printf("NavLink simulate: %s, %u jumps and %u drops generated\n", level.level().name.c_str(),
                report.jump_links, report.drop_links);
    std::printf("  three agents leave (%.1f, %.1f, %.1f) for (%.1f, %.1f, %.1f), stepped every %.1f ms\n\n",
                start[0], start[1], start[2], goal[0], goal[1], goal[2], dt * 1000.0);

    std::vector<AgentRun> runs;
    for (size_t i = 0; i < profiles.size(); ++i) {
        AgentRun run;
        run.profile = profiles[i];
        nl_agent_def def = samples::agent_def(profiles[i], level.navmesh(), start);
        def.user_data = i;
        samples::check(nl_agent_add(world, &def, &run.id), "adding an agent");
        samples::check(nl_agent_set_destination(world, run.id, goal), "setting a destination");
        run.track.push_back(track_point(start));
        for (int k = 0; k < 3; ++k) run.last_position[k] = start[k];
        runs.push_back(std::move(run));
    }

    const auto steps_per_track_point = static_cast<long>(std::lround(std::max(1.0, kTrackInterval / dt)));
    long step = 0;
    auto running = [&runs] {
        for (const AgentRun& run : runs)
            if (!run.ended_at) return true;
        return false;
    };
    for (; running() && step * dt < seconds; ++step) {
        samples::check(nl_world_step(world, static_cast<float>(dt)), "stepping the world");
        const auto time = static_cast<float>((step + 1) * dt);
        read_events(world, runs, time);
        record_tracks(world, runs, (step + 1) % steps_per_track_point == 0);
    }

    std::printf("\n%-13s | %-8s %8s  %-22s %9s %9s  %s\n", "agent", "outcome", "time", "where", "to goal",
                "travelled", "links taken");
    std::vector<picture::PathLayer> layers;
    bool all_arrived = true;
    for (size_t i = 0; i < runs.size(); ++i) {
        const AgentRun& run = runs[i];
        const nl_agent_info info = samples::read_agent(world, run.id);
        const std::string outcome = run.arrived ? "arrived"
                                    : run.ended_at ? std::string("failed: ") + samples::agent_reason_name(run.failure)
                                                   : "on its way";
        char where[48];
        std::snprintf(where, sizeof where, "(%.1f, %.1f, %.1f)", info.position[0], info.position[1], info.position[2]);
        const std::string links = samples::describe_links(run.links_taken);
        std::printf("%-13s | %-8s %6.1f s  %-22s %7.2f m %7.1f m  %s, %d replans\n", run.profile.name.c_str(),
                    outcome.c_str(), run.ended_at.value_or(static_cast<float>(step * dt)), where,
                    distance(info.position, goal), run.travelled, links.c_str(), run.replans);
        char label[96];
        std::snprintf(label, sizeof label, "%s: %.1f s, %s", run.profile.name.c_str(),
                      run.ended_at.value_or(static_cast<float>(step * dt)), links.c_str());
        layers.push_back({label, picture::palette::agent(i), run.track});
        all_arrived = all_arrived && run.arrived;
    }

    const samples::NavmeshContents contents = samples::read_navmesh_contents(world, level.navmesh());
    const std::string png_path = dir + "/simulate.png";
    PictureRequest request;
    request.path = png_path;
    request.oblique = args.has("oblique");
    request.title = "navlink simulate: the tracks three agents took (seed " + std::to_string(seed) + ")";
    write_picture(level.level(), contents, layers, request,
                  {{"start", {start[0], start[1], start[2]}, picture::palette::kText},
                   {"goal", {goal[0], goal[1], goal[2]}, picture::palette::kText}});
    std::printf("\nwrote %s\n", png_path.c_str());
    return all_arrived ? 0 : 1;
}

}  // namespace nl::cli
