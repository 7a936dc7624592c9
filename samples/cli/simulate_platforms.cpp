// navlink simulate --platforms: passengers ride the platforms beside the default level (a shuttle
// across a chasm, a turning disc, a lift to an upper floor), which the host moves by their timetables
// every step; prints each take-off, wait and arrival, and draws the tracks and the platforms.
#include <cstdio>
#include <string>
#include <vector>

#include "moving_platforms.h"
#include "navigable_level.h"
#include "navmesh_contents.h"
#include "picture_export.h"
#include "platform_picture.h"
#include "platforms_level.h"
#include "simulate_scenes.h"
#include "simulation.h"

namespace nl::cli {
namespace {

void print_scene(const samples::PlatformsLevel& scene) {
    for (const samples::PlatformLayout& platform : scene.platforms) {
        std::printf("  %-7s %s every %.0f s; gangways:", platform.name.c_str(),
                    platform.timetable.turns() ? "turns once" : "goes and comes back", platform.timetable.cycle());
        for (size_t i = 0; i < platform.gangways.size(); ++i)
            std::printf("%s %s (placed at %.0f s)", i ? "," : "", platform.gangways[i].name.c_str(),
                        platform.gangways[i].placed_at);
        std::printf("\n");
    }
    for (const samples::Passenger& p : scene.passengers)
        std::printf("  %s goes from (%.1f, %.1f, %.1f) to (%.1f, %.1f, %.1f), %s\n", p.profile.name.c_str(), p.start[0],
                    p.start[1], p.start[2], p.destination[0], p.destination[1], p.destination[2],
                    p.destination_name.c_str());
}

}  // namespace

int simulate_platforms(const SimulateOptions& options) {
    const samples::PlatformsLevel scene = samples::generate_platforms_level(options.seed);
    const std::string seed = std::to_string(options.seed);
    const nl_agent_type body = scene.passengers.front().profile.body;
    NavigableLevel level(scene.level, "generated default level (seed " + seed + ") with moving platforms", body, "");
    // Links are generated against what stands still: the platforms come after, so that no link is
    // proved against a platform that then moves away.
    const nl_link_generation_report report = level.generate_links(nl_default_link_settings());
    const std::vector<samples::MovingPlatform> platforms =
        samples::add_moving_platforms(level.world(), level.navmesh(), scene.platforms, body, 0.0);

    std::printf("NavLink simulate --platforms: %s, %u jumps and %u drops generated\n", level.level().name.c_str(),
                report.jump_links, report.drop_links);
    print_scene(scene);
    std::printf("  stepped every %.1f ms, the platforms moved before each step\n\n", options.dt * 1000.0);

    Simulation simulation(level.world(), &platforms);
    std::vector<std::string> destination_names;
    for (const samples::Passenger& p : scene.passengers) {
        simulation.add_agent(p.profile, level.navmesh(), p.start.data(), p.destination.data(), p.destination_rides);
        destination_names.push_back(p.destination_name);
    }
    simulation.run(options.dt, options.seconds);
    simulation.print_table();

    PictureRequest request;
    request.path = options.out_dir + "/platforms.png";
    request.oblique = options.oblique;
    request.title =
        "navlink simulate --platforms: the tracks of passengers riding a shuttle, a disc and a lift (seed " + seed +
        ")";
    write_picture(level.level(), samples::read_navmesh_contents(level.world(), level.navmesh()), simulation.tracks(),
                  request, simulation.destinations(destination_names),
                  picture::scene_platforms(level.world(), platforms, simulation.elapsed()));
    std::printf("\nwrote %s\n", request.path.c_str());
    return simulation.all_arrived() ? 0 : 1;
}

}  // namespace nl::cli
