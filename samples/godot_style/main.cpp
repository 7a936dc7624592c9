// navlink-godot-style: a Godot-style scene (a navigation region, a ladder link, four agents) run
// headless through the NavLink C ABI; prints each agent's path, the links it takes and its arrival.
#include <cstdio>
#include <string>

#include "arguments.h"
#include "demo_scene.h"
#include "path_plan.h"
#include "sample_error.h"

namespace {

using namespace nl::godot_style;

const char* const kHelp =
    "usage: navlink-godot-style [--seed N] [--remove-ladder-at SECONDS] [--path-workers N]\n"
    "\n"
    "Runs a scripted Godot-style scene headless: the generated default level as a navigation region,\n"
    "a ladder link only climbers may take, and four agents (walker, short jumper, long jumper, climber)\n"
    "sent from the level's start to its goal. Prints paths, links taken and arrivals; exit status 0\n"
    "when every agent arrives within 120 s of scene time.\n"
    "\n"
    "Paths are planned at each frame's sync point on the scene's thread, so runs are identical and fast;\n"
    "--path-workers N plans them on N NavLink threads instead, with frames paced in real time.\n";

void connect_printing(NavigationAgent* agent, const SceneTree& tree) {
    const std::string name = agent->name();
    agent->path_ready.connect([name, &tree](const nl::samples::PlannedPath& p) {
        std::printf("%6.2f s  %-13s path ready: %.1f m, %s\n", tree.time(), name.c_str(), p.result.length,
                    nl::samples::describe_links(nl::samples::count_links(p)).c_str());
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
    agent->navigation_failed.connect([name, &tree](nl_path_outcome outcome) {
        std::printf("%6.2f s  %-13s cannot get there: %s\n", tree.time(), name.c_str(),
                    nl::samples::outcome_name(outcome));
    });
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const nl::samples::Arguments args("navlink-godot-style", "navlink-godot-style", argc, argv, 1,
                                          {{"seed", true}, {"remove-ladder-at", true}, {"path-workers", true}});
        if (args.wants_help()) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        args.expect_positional(0, "");
        const auto seed = static_cast<uint32_t>(args.whole_number("seed", 0, 4294967295L, 1));
        const long remove_at = args.whole_number("remove-ladder-at", 0, 1000, -1);
        const auto workers = static_cast<int32_t>(args.whole_number("path-workers", 0, 64, 0));
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
        scene.tree->run_until(all_done, delta, 120.0);
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
