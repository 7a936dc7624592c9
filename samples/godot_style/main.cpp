// navlink-godot-style: a Godot-style scene (a navigation region, a ladder link, four agents; or with
// --platforms, moving platforms and their passengers) run headless through the NavLink C ABI; prints
// each agent's path, the links it takes and its arrival.
#include <cmath>
#include <cstdio>
#include <string>

#include "world_agents.h"
#include "arguments.h"
#include "demo_scene.h"
#include "path_plan.h"
#include "platforms_scene.h"
#include "sample_error.h"

namespace {

using namespace nl::godot_style;

const char* const kHelp =
    "usage: navlink-godot-style [--seed N] [--remove-ladder-at SECONDS] [--workers N] [--trace] [--platforms]\n"
    "\n"
    "Runs a scripted Godot-style scene headless: the generated default level as a navigation region,\n"
    "a ladder link only climbers may take, and four agents (walker, short jumper, long jumper, climber)\n"
    "sent from the level's start to its goal. Prints paths, links taken and arrivals; exit status 0\n"
    "when every agent arrives within 120 s of scene time.\n"
    "\n"
    "--platforms plays the moving-platforms scene instead: beside the default level, a shuttle across a\n"
    "chasm, a turning disc and a lift to an upper floor, each a MovingPlatform node that moves its mesh\n"
    "every physics frame (nl_mesh_set_transform) by its timetable, and four NavigationAgents riding\n"
    "them to their own targets: they wait at the gangways for the platforms, ride, and get off.\n"
    "\n"
    "NavLink moves the agents at each frame's sync point (nl_world_step) on --workers N threads\n"
    "(default 1); the scene plays the same on any number. --trace prints every agent's state once a\n"
    "second of scene time.\n";

void connect_printing(NavigationAgent* agent, const SceneTree& tree) {
    const std::string name = agent->name();
    agent->path_ready.connect([name, &tree](const std::vector<nl_path_point>& corners) {
        std::printf("%6.2f s  %-13s path ready: %zu corners, %s\n", tree.time(), name.c_str(), corners.size(),
                    nl::samples::describe_links(nl::samples::count_links(corners)).c_str());
    });
    agent->link_reached.connect([name, &tree](const TakenLink& t) {
        std::printf("%6.2f s  %-13s takes a %s link%s: gap %.1f m, rise %.1f m, drop %.1f m", tree.time(), name.c_str(),
                    nl::samples::segment_name(t.link.kind), t.reversed ? " backwards" : "", t.link.requirements.gap,
                    t.reversed ? t.link.requirements.drop : t.link.requirements.rise,
                    t.reversed ? t.link.requirements.rise : t.link.requirements.drop);
        if (t.waited > 0.0) std::printf(", after waiting %.1f s", t.waited);
        std::printf("\n");
    });
    agent->target_reached.connect([agent, &tree] {
        const Vec3& p = agent->position();
        std::printf("%6.2f s  %-13s arrived at (%.1f, %.1f, %.1f) after %.1f m\n", tree.time(), agent->name().c_str(),
                    p[0], p[1], p[2], agent->distance_travelled());
    });
    agent->navigation_failed.connect([name, &tree](nl_agent_reason reason) {
        std::printf("%6.2f s  %-13s cannot get there: %s\n", tree.time(), name.c_str(),
                    nl::samples::agent_reason_name(reason));
    });
}

void print_states(SceneTree& tree, const std::vector<NavigationAgent*>& agents) {
    nl_world* world = tree.navigation().world();
    for (const NavigationAgent* agent : agents) {
        const nl_agent_info info = nl::samples::read_agent(world, agent->agent());
        const std::vector<nl_path_point> corners = nl::samples::read_corners(world, agent->agent());
        std::printf("%6.2f s  %-13s %-10s at (%.2f, %.2f, %.2f), %.2f m/s", tree.time(), agent->name().c_str(),
                    nl::samples::agent_state_name(info.state), info.position[0], info.position[1], info.position[2],
                    std::hypot(info.velocity[0], info.velocity[2]));
        if (!corners.empty())
            std::printf(", next (%.2f, %.2f, %.2f) of %zu", corners[0].position[0], corners[0].position[1],
                        corners[0].position[2], corners.size());
        std::printf("\n");
    }
}

constexpr double kDelta = 1.0 / 60.0;

// Runs the scene on until every agent has arrived or failed (120 s of scene time at most); returns
// the exit status.
int play(SceneTree& tree, const std::vector<NavigationAgent*>& agents, bool trace) {
    auto all_done = [&] {
        for (NavigationAgent* a : agents)
            if (!a->arrived() && !a->failed()) return false;
        return true;
    };
    while (!all_done() && tree.time() < 120.0) {
        tree.run_until(all_done, kDelta, 1.0);
        if (trace) print_states(tree, agents);
    }
    int arrived = 0;
    for (NavigationAgent* a : agents) arrived += a->arrived();
    std::printf("%d of %zu agents arrived in %.1f s of scene time\n", arrived, agents.size(), tree.time());
    return arrived == static_cast<int>(agents.size()) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const nl::samples::Arguments args(
            "navlink-godot-style", "navlink-godot-style", argc, argv, 1,
            {{"seed", true}, {"remove-ladder-at", true}, {"workers", true}, {"trace", false}, {"platforms", false}});
        if (args.wants_help()) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        args.expect_positional(0, "");
        const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
        const long remove_at = args.whole_number("remove-ladder-at", 0, 1000, -1);
        const auto workers = static_cast<int32_t>(args.whole_number("workers", 0, 64, 1));
        if (args.has("platforms")) {
            if (remove_at >= 0) throw nl::samples::SampleError("--remove-ladder-at: the platforms scene has no ladder");
            PlatformsScene scene = build_platforms_scene(seed, workers);
            const nl_link_generation_report& report = scene.region->generation_report();
            std::printf("scene: region 'Level' (%u jump and %u drop links generated), platforms", report.jump_links,
                        report.drop_links);
            for (const MovingPlatform* p : scene.platforms)
                std::printf(" '%s' (%zu gangways)", p->name().c_str(), p->platform().gangways.size());
            std::printf(", %zu agents\n", scene.agents.size());
            for (NavigationAgent* agent : scene.agents) connect_printing(agent, *scene.tree);
            return play(*scene.tree, scene.agents, args.has("trace"));
        }
        DemoScene scene = build_demo_scene(seed, workers);
        const nl_link_generation_report& report = scene.region->generation_report();
        std::printf("scene: region 'Level' (%u jump and %u drop links generated), link 'Ladder', %zu agents\n",
                    report.jump_links, report.drop_links, scene.agents.size());
        for (NavigationAgent* agent : scene.agents) connect_printing(agent, *scene.tree);
        if (remove_at >= 0) {
            scene.tree->run_until([] { return false; }, kDelta, static_cast<double>(remove_at));
            std::printf("%6.2f s  the ladder is taken away\n", scene.tree->time());
            scene.tree->root()->remove_child(scene.ladder);
            scene.ladder = nullptr;
        }
        return play(*scene.tree, scene.agents, args.has("trace"));
    } catch (const nl::samples::SampleError& e) {
        std::fprintf(stderr, "navlink-godot-style: %s\n", e.what());
        return 2;
    }
}
