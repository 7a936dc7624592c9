#include "crowd_scenarios.h"

#include <cmath>

namespace nl::test {
namespace {

// Adds the rectangle [x0, x1] x [z0, z1] at y = 0, counter-clockwise seen from above.
void add_rectangle(NavMeshInput& in, float x0, float x1, float z0, float z1) {
    for (const auto& [x, z] : {std::pair{x0, z0}, {x0, z1}, {x1, z1}, {x1, z0}}) {
        in.indices.push_back(uint32_t(in.vertices.size()));
        in.vertices.emplace_back(x, 0.0f, z);
    }
    in.polygon_sizes.push_back(4);
}

NavMeshInput body(float radius) {
    NavMeshInput in;
    in.agent.radius = radius;
    in.agent.height = 2.0f;
    return in;
}

}  // namespace

NavMeshInput open_floor(float half, float radius) {
    NavMeshInput in = body(radius);
    add_rectangle(in, -half + radius, half - radius, -half + radius, half - radius);
    return in;
}

NavMeshInput rooms_with_door(float half, float door, float wall, float radius) {
    NavMeshInput in = body(radius);
    const float side = half - radius, face = wall / 2 + radius, gap = door / 2 - radius;
    // Each room in three strips, the middle one as wide as the door, so that the door's ends are
    // corners the strips share with it.
    for (const float sign : {-1.0f, 1.0f}) {
        const float near = sign * face, far = sign * side;
        const float x0 = std::min(near, far), x1 = std::max(near, far);
        add_rectangle(in, x0, x1, -side, -gap);
        add_rectangle(in, x0, x1, -gap, gap);
        add_rectangle(in, x0, x1, gap, side);
    }
    add_rectangle(in, -face, face, -gap, gap);
    return in;
}

CrowdScenario one_point(int count, float distance, bool quarter) {
    CrowdScenario s;
    s.name = count == 2 ? (quarter ? "one point, 2 at 90 degrees" : "one point, 2 head-on") : "one point, " + std::to_string(count) + " in a ring";
    s.navmesh = open_floor(distance + 4.0f, s.radius);
    for (int k = 0; k < count; ++k) {
        const float angle = (count == 2 && quarter) ? float(k) * float(M_PI) / 2 : 2.0f * float(M_PI) * float(k) / float(count);
        s.agents.push_back({Vec3(distance * std::cos(angle), 0.0f, distance * std::sin(angle)), Vec3::Zero()});
    }
    s.seconds = 10.0f + float(count);
    return s;
}

CrowdScenario door_counterflow(int per_side, float door, bool both_ways) {
    CrowdScenario s;
    s.name = std::string(both_ways ? "door counterflow, " : "door one way, ") + std::to_string(per_side) + " per side";
    const float half = 12.0f;
    s.navmesh = rooms_with_door(half, door, 0.4f, s.radius);
    // Rows of up to five, 1.5 m apart, from 3 m off the wall; sent to the mirror place beyond it.
    for (int side = 0; side < (both_ways ? 2 : 1); ++side) {
        const float sign = side == 0 ? -1.0f : 1.0f;
        for (int k = 0; k < per_side; ++k) {
            const float x = sign * (3.0f + 1.5f * float(k / 5)), z = 1.5f * float(k % 5 - 2);
            s.agents.push_back({Vec3(x, 0.0f, z), Vec3(-x, 0.0f, z)});
        }
    }
    s.seconds = 20.0f + 4.0f * float(per_side);
    return s;
}

}  // namespace nl::test
