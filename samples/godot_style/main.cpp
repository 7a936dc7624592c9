// navlink-godot-style: a Godot-style scene (a navigation region, a ladder link, four agents) run
// headless through the NavLink C ABI; prints each agent's path, the links it takes and its arrival.
#include <cmath>
#include <cstdio>
#include <string>

#include "agent_reads.h"
#include "arguments.h"
#include "demo_scene.h"
#include "path_plan.h"
#include "sample_error.h"

namespace {

using namespace nl::godot_style;

const char* const kHelp =
    "usage: navlink-godot-style [--seed N] [--remove-ladder-at SECONDS] [--workers N] [--trace]\n"
    "\n"
    "Runs a scripted Godot-style scene headless: the generated default level as a navigation region,\n"
    "a ladder link only climbers may take, and four agents (walker, short jumper, long jumper, climber)\n"
    "sent from the level's start to its goal. Prints paths, links taken and arrivals; exit status 0\n"
    "when every agent arrives within 120 s of scene time.\n"
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
        std::printf("%6.2f s  %-13s takes a %s link%s: gap %.1f m, rise %.1f m, drop %.1f m\n", tree.time(),
                    name.c_str(), nl::samples::segment_name(t.link.kind), t.reversed ? " backwards" : "",
                    t.link.requirements.gap, t.reversed ? t.link.requirements.drop : t.link.requirements.rise,
                    t.reversed ? t.link.requirements.rise : t.link.requirements.drop);
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

void print_states(const DemoScene& scene) {
    nl_world* world = scene.tree->navigation().world();
    for (const NavigationAgent* agent : scene.agents) {
        const nl_agent_info info = nl::samples::read_agent(world, agent->agent());
        const std::vector<nl_path_point> corners = nl::samples::read_corners(world, agent->agent());
        std::printf("%6.2f s  %-13s %-10s at (%.2f, %.2f, %.2f), %.2f m/s", scene.tree->time(), agent->name().c_str(),
                    nl::samples::agent_state_name(info.state), info.position[0], info.position[1], info.position[2],
                    std::hypot(info.velocity[0], info.velocity[2]));
        if (!corners.empty())
            std::printf(", next (%.2f, %.2f, %.2f) of %zu", corners[0].position[0], corners[0].position[1],
                        corners[0].position[2], corners.size());
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const nl::samples::Arguments args("navlink-godot-style", "navlink-godot-style", argc, argv, 1,
                                          {{"seed", true}, {"remove-ladder-at", true}, {"workers", true}, {"trace", false}});
        if (args.wants_help()) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        args.expect_positional(0, "");
        const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
        const long remove_at = args.whole_number("remove-ladder-at", 0, 1000, -1);
        const auto workers = static_cast<int32_t>(args.whole_number("workers", 0, 64, 1));
        DemoScene scene = build_demo_scene(seed, workers);
        const nl_link_generation_report& report = scene.region->generation_report();
        std::printf("scene: region 'Level' (%u jump and %u drop links generated), link 'Ladder', %zu agents\n",
                    report.jump_links, report.drop_links, scene.agents.size());
        for (NavigationAgent* agent : scene.agents) connect_printing(agent, *scene.tree);

        auto all_done = [&] {
            for (NavigationAgent* a : scene.agents)
                if (!a->arrived() && !a->failed()) return false;
            return true;
        };
        const double delta = 1.0 / 60.0;
        if (remove_at >= 0) {
            scene.tree->run_until([] { return false; }, delta, static_cast<double>(remove_at));
            std::printf("%6.2f s  the ladder is taken away\n", scene.tree->time());
            scene.tree->root()->remove_child(scene.ladder);
            scene.ladder = nullptr;
        }
        while (!all_done() && scene.tree->time() < 120.0) {
            scene.tree->run_until(all_done, delta, 1.0);
            if (args.has("trace")) print_states(scene);
        }
        int arrived = 0;
        for (NavigationAgent* a : scene.agents) arrived += a->arrived();
        std::printf("%d of %zu agents arrived in %.1f s of scene time\n", arrived, scene.agents.size(),
                    scene.tree->time());
        return arrived == static_cast<int>(scene.agents.size()) ? 0 : 1;
    } catch (const nl::samples::SampleError& e) {
        std::fprintf(stderr, "navlink-godot-style: %s\n", e.what());
        return 2;
    }
}
