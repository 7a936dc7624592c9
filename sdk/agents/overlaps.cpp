#include "agents/overlaps.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "agents/agent_motion.h"
#include "agents/neighbours.h"

namespace nl {
namespace {

// Rounds of pushing: each halves most overlaps. DetourCrowd runs four; six kept a crowd pressed
// against a door's walls within 2-3 cm (four left 6 cm in ten-a-side counterflow), and eight keep
// it so since walkers slide past each other (six let 24 closing on one point sink 5.5 cm).
constexpr int kRounds = 8;
// Past them, rounds go on while any overlap deeper than kSettled is left, up to kMostRounds: a crowd
// pressed many deep against a door (seventy a side) sank 11 cm after eight.
constexpr int kMostRounds = 16;
constexpr float kSettled = 0.02f;  // m
// The contacts a body is pushed by: its nearest, found once per step from where the move left them
// (a round moves bodies by millimetres to centimetres: the same bodies stay nearest).
constexpr size_t kContacts = 8;
constexpr float kReachSlack = 0.1f;  // m: bodies this much apart may touch after the first rounds

}  // namespace

void resolve_overlaps(const std::vector<OverlapBody>& bodies, float dt, TaskSystem& tasks) {
    const size_t n = bodies.size();
    if (n < 2) return;
    std::vector<Vec3> positions(n), next(n);
    std::vector<uint32_t> polygons(n);
    std::vector<uint8_t> everyone(n, 1);
    float widest = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        positions[i] = bodies[i].agent->position;
        polygons[i] = bodies[i].agent->polygon;
        widest = std::max(widest, bodies[i].agent->def.capabilities.radius);
    }
    NeighbourGrid grid;
    grid.build(positions, everyone, std::max(widest * 3.0f, 0.5f));
    std::vector<std::array<uint32_t, kContacts>> contacts(n);
    std::vector<uint8_t> contact_count(n, 0);
    tasks.parallel_for(static_cast<uint32_t>(n), 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const float reach = bodies[i].agent->def.capabilities.radius + widest + kReachSlack;
            contact_count[i] =
                static_cast<uint8_t>(grid.nearest(positions[i], reach, i, contacts[i].data(), kContacts));
        }
    });
    if (std::all_of(contact_count.begin(), contact_count.end(), [](uint8_t c) { return c == 0; })) return;

    std::vector<float> deepest(n, 0.0f);  // each body's deepest overlap as a round found it
    // The bodies a round pushes: all of them for kRounds; past them, those still in an overlap and
    // their contacts (the rest neither push nor are pushed: a dense crowd's later rounds are cheap).
    std::vector<uint32_t> active(n);
    for (uint32_t i = 0; i < n; ++i) active[i] = i;
    std::vector<uint8_t> in_active(n, 0);
    next = positions;
    for (int round = 0; round < kMostRounds && !active.empty(); ++round) {
        tasks.parallel_for(static_cast<uint32_t>(active.size()), 64, [&](uint32_t begin, uint32_t end) {
            for (uint32_t slot = begin; slot < end; ++slot) {
                const uint32_t i = active[slot];
                const Agent& a = *bodies[i].agent;
                Vec3 push = Vec3::Zero();
                deepest[i] = 0.0f;
                for (uint8_t k = 0; k < contact_count[i]; ++k) {
                    const uint32_t j = contacts[i][k];
                    const Agent& b = *bodies[j].agent;
                    const Vec3 d(positions[i].x() - positions[j].x(), 0.0f, positions[i].z() - positions[j].z());
                    const float gap = d.norm(), reach = a.def.capabilities.radius + b.def.capabilities.radius;
                    if (gap >= reach) continue;
                    // On floors apart (one world space holds every floor of a level): no contact.
                    if (std::fabs(positions[i].y() - positions[j].y()) > std::max(a.def.height, b.def.height)) continue;
                    const float gives = bodies[i].give + bodies[j].give;
                    if (gives <= 0.0f) continue;  // both hold their places
                    deepest[i] = std::max(deepest[i], reach - gap);
                    // Exactly on top of each other: apart along x, the lower index to the left.
                    const Vec3 away = gap > 1e-6f ? Vec3(d / gap) : Vec3(i < j ? -1.0f : 1.0f, 0.0f, 0.0f);
                    push += away * ((reach - gap) * bodies[i].give / gives);
                }
                next[i] = positions[i];
                if (push.squaredNorm() == 0.0f) continue;
                // In x-z only: the feet's height is set once, after the rounds.
                SurfaceWalkOptions flat;
                flat.surface_height = false;
                const SurfaceMove moved =
                    move_along_surface(*bodies[i].navmesh, polygons[i], positions[i], positions[i] + push, flat);
                next[i] = moved.position;
                polygons[i] = moved.polygon;
            }
        });
        for (const uint32_t i : active) positions[i] = next[i];
        if (round + 1 < kRounds) continue;
        // Serial, in index order: the next round's bodies are the same for any thread count.
        float worst = 0.0f;
        for (const uint32_t i : active) worst = std::max(worst, deepest[i]);
        if (worst < kSettled) break;
        std::vector<uint32_t> still;
        for (const uint32_t i : active) {
            if (deepest[i] < kSettled) continue;
            if (!in_active[i]) in_active[i] = 1, still.push_back(i);
            for (uint8_t k = 0; k < contact_count[i]; ++k)
                if (!in_active[contacts[i][k]]) in_active[contacts[i][k]] = 1, still.push_back(contacts[i][k]);
        }
        for (const uint32_t i : still) in_active[i] = 0;
        std::sort(still.begin(), still.end());
        active.swap(still);
    }
    for (size_t i = 0; i < n; ++i) {
        Agent& a = *bodies[i].agent;
        const Vec3 moved(positions[i].x() - a.position.x(), 0.0f, positions[i].z() - a.position.z());
        // Pushed over the surface, its feet keep their height over it (eased near a take-off or a
        // landing), as move_keeping_height does for one move.
        if (moved.x() != 0.0f || moved.z() != 0.0f) {
            const NavMesh& navmesh = *bodies[i].navmesh;
            positions[i].y() = a.position.y() - navmesh.surface_height(a.polygon, a.position.x(), a.position.z()) +
                               navmesh.surface_height(polygons[i], positions[i].x(), positions[i].z());
        }
        a.walked_since_landing += moved.norm();
        a.position = positions[i];
        a.polygon = polygons[i];
        // A walker keeps only the velocity its contacts left it (as position-based dynamics update
        // velocities): pressed on by others, it stops pressing into them, or the next step's move
        // would sink it back as deep (a ring closing on its centre presses every body sideways, and
        // no push along the ring undoes that).
        if (a.state != AgentState::Walking || dt <= 0.0f) continue;
        a.velocity += moved / dt;
        const float speed = a.velocity.norm();
        if (speed > a.def.max_speed) a.velocity *= a.def.max_speed / speed;
    }
}

}  // namespace nl
