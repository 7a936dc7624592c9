#include "platform_picture.h"

#include <cmath>
#include <cstdio>

#include "navmesh_contents.h"
#include "sample_error.h"

namespace nl::picture {
namespace {

// "shuttle at (4.0, -3.7, 19.2), moving", or for one that turns in place, "disc turned 123 deg".
std::string label(const samples::MovingPlatform& platform, const float transform[16], double time) {
    const samples::Timetable& timetable = platform.layout->timetable;
    char text[96];
    if (timetable.turns()) {
        double degrees = std::atan2(transform[8], transform[0]) * 180.0 / M_PI;
        if (degrees < 0.0) degrees += 360.0;
        std::snprintf(text, sizeof text, "%s turned %.0f deg", platform.layout->name.c_str(), degrees);
    } else {
        std::snprintf(text, sizeof text, "%s at (%.1f, %.1f, %.1f), %s", platform.layout->name.c_str(), transform[12],
                      transform[13], transform[14], timetable.docked(time) ? "docked" : "moving");
    }
    return text;
}

}  // namespace

std::vector<ScenePlatform> scene_platforms(const nl_world* world, const std::vector<samples::MovingPlatform>& platforms,
                                           double time) {
    std::vector<ScenePlatform> out;
    for (const samples::MovingPlatform& platform : platforms) {
        nl_mesh_info info{};
        info.size = sizeof info;
        samples::check(nl_mesh_get_info(world, platform.mesh, &info),
                       "reading where the " + platform.layout->name + " is");
        const float* m = info.transform;  // column-major
        ScenePlatform drawn;
        drawn.label = label(platform, m, time);
        const std::vector<float>& own = platform.layout->body.positions;
        for (size_t i = 0; i + 2 < own.size(); i += 3)
            for (int k = 0; k < 3; ++k)
                drawn.positions.push_back(m[k] * own[i] + m[4 + k] * own[i + 1] + m[8 + k] * own[i + 2] + m[12 + k]);
        drawn.triangles = platform.layout->body.indices;
        drawn.navmesh = samples::read_navmesh_contents(world, platform.navmesh);
        out.push_back(std::move(drawn));
    }
    return out;
}

}  // namespace nl::picture
