#include "crowd_scenarios.h"

#include <algorithm>
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
    in.agent_type.radius = radius;
    in.agent_type.height = 2.0f;
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
    s.name = count == 2 ? (quarter ? "one point, 2 at 90 degrees" : "one point, 2 head-on")
                        : "one point, " + std::to_string(count) + " in a ring";
    const float half = distance + 4.0f;
    s.navmesh = open_floor(half, s.radius);
    s.boxes = {{Vec3(-half, -1.0f, -half), Vec3(half, 0.0f, half)}};
    for (int k = 0; k < count; ++k) {
        const float angle =
            (count == 2 && quarter) ? float(k) * float(M_PI) / 2 : 2.0f * float(M_PI) * float(k) / float(count);
        s.agents.push_back({Vec3(distance * std::cos(angle), 0.0f, distance * std::sin(angle)), Vec3::Zero()});
    }
    s.seconds = 10.0f + float(count);
    return s;
}

CrowdScenario door_counterflow(int per_side, float door, bool both_ways, float radius) {
    CrowdScenario s;
    s.name = std::string(both_ways ? "door counterflow, " : "door one way, ") + std::to_string(per_side) + " per side";
    s.radius = radius;
    // Rows of up to five bodies spaced 2.5 radii, from 3 m off the wall; each sent to the mirror place.
    const float spacing = 2.5f * radius;
    const float half = std::max(12.0f, 5.0f + spacing * float((per_side + 4) / 5));  // room for the rows
    const float wall = 0.4f;
    s.navmesh = rooms_with_door(half, door, wall, s.radius);
    s.boxes = {{Vec3(-half, -1.0f, -half), Vec3(half, 0.0f, half)},
               {Vec3(-wall / 2, 0.0f, -half), Vec3(wall / 2, 2.5f, -door / 2)},
               {Vec3(-wall / 2, 0.0f, door / 2), Vec3(wall / 2, 2.5f, half)}};
    for (int side = 0; side < (both_ways ? 2 : 1); ++side) {
        const float sign = side == 0 ? -1.0f : 1.0f;
        for (int k = 0; k < per_side; ++k) {
            const float x = sign * (3.0f + spacing * float(k / 5)), z = spacing * float(k % 5 - 2);
            s.agents.push_back({Vec3(x, 0.0f, z), Vec3(-x, 0.0f, z)});
        }
    }
    s.seconds = 20.0f + 4.0f * float(per_side);
    return s;
}

CrowdScenario corridor(int per_end, float width, bool crossing) {
    CrowdScenario s;
    s.name = std::string(crossing ? "corridors crossing at 90 degrees, " : "corridor counterflow, ") +
             std::to_string(per_end) + " per end, " + std::to_string(int(width * 10) / 10) + "." +
             std::to_string(int(width * 10) % 10) + " m wide";
    const float half_length = 15.0f, half_width = width / 2, r = s.radius;
    // The floor: a strip along x (and one along z), raised over nothing: its edges bound it.
    s.boxes = {{Vec3(-half_length, -1.0f, -half_width), Vec3(half_length, 0.0f, half_width)}};
    if (crossing) s.boxes.push_back({Vec3(-half_width, -1.0f, -half_length), Vec3(half_width, 0.0f, half_length)});
    const float in = half_width - r, end = half_length - r;
    if (!crossing) {
        add_rectangle(s.navmesh, -end, end, -in, in);
    } else {
        // The crossing square, and four arms that each share one of its sides.
        add_rectangle(s.navmesh, -in, in, -in, in);
        add_rectangle(s.navmesh, -end, -in, -in, in);
        add_rectangle(s.navmesh, in, end, -in, in);
        add_rectangle(s.navmesh, -in, in, -end, -in);
        add_rectangle(s.navmesh, -in, in, in, end);
    }
    s.navmesh.agent_type.radius = r;
    s.navmesh.agent_type.height = 2.0f;
    const float spacing = 2.5f * r, first = half_length - 1.5f;
    const int across = std::max(1, int((width - 2 * r) / spacing) + 1);
    for (int end = 0; end < 2; ++end) {
        const float sign = end == 0 ? -1.0f : 1.0f;
        for (int k = 0; k < per_end; ++k) {
            const float along = sign * (first - spacing * float(k / across));
            const float side =
                across > 1 ? -half_width + r + (width - 2 * r) * float(k % across) / float(across - 1) : 0.0f;
            s.agents.push_back({Vec3(along, 0.0f, side), Vec3(-along, 0.0f, side)});
            if (crossing) s.agents.push_back({Vec3(side, 0.0f, along), Vec3(side, 0.0f, -along)});
        }
    }
    s.seconds = 30.0f + 2.0f * float(s.agents.size());
    return s;
}

}  // namespace nl::test
