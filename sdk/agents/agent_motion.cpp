#include "agents/agent_motion.h"

#include <DetourObstacleAvoidance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "navmesh/surface_walk.h"

namespace nl {
namespace {

constexpr float kCornerReach = 0.15f;  // a corner on the way counts as reached this near (x-z)
constexpr float kStopReach = 0.05f;    // the destination and a take-off are reached this near
// A link's ends lie on the level's floor, the walking height on the navmesh's surface, and the two
// can differ by a Recast cell or two: over this last (and first) stretch the feet ease from one to
// the other, so a body never pops up or down at a take-off or a landing.
constexpr float kHeightEase = 1.0f;
constexpr float kContact = 0.1f;         // bodies this near each other's surface touch
constexpr float kOffPathSlack = 1.0f;    // how far past its radius an agent may be pushed off its path
constexpr size_t kMaxNeighbours = 6;     // as DetourCrowd: the nearest count
constexpr size_t kHemmedIn = 4;          // touching this many of them: a jam (coarser avoidance)
constexpr size_t kSlidesPastAtMost = 2;  // touching at most this many walkers, it slides past them

float distance_xz(const Vec3& a, const Vec3& b) { return std::hypot(a.x() - b.x(), a.z() - b.z()); }

// The distance in x-z from p to the segment ab.
float distance_to_segment_xz(const Vec3& p, const Vec3& a, const Vec3& b) {
    const float dx = b.x() - a.x(), dz = b.z() - a.z();
    const float length2 = dx * dx + dz * dz;
    const float t =
        length2 > 0.0f ? std::clamp(((p.x() - a.x()) * dx + (p.z() - a.z()) * dz) / length2, 0.0f, 1.0f) : 0.0f;
    return std::hypot(a.x() + t * dx - p.x(), a.z() + t * dz - p.z());
}

// DetourCrowd's obstacle avoidance, one query object per thread (it is scratch space; the answer
// depends on its inputs only). DetourCrowd's default parameters: velocity obstacles sampled
// adaptively around the desired velocity.
struct FreeQuery {
    void operator()(dtObstacleAvoidanceQuery* q) const { dtFreeObstacleAvoidanceQuery(q); }
};
dtObstacleAvoidanceQuery& avoidance_query() {
    thread_local std::unique_ptr<dtObstacleAvoidanceQuery, FreeQuery> query;
    if (!query) {
        query.reset(dtAllocObstacleAvoidanceQuery());
        if (!query || !query->init(int(kMaxNeighbours), 1)) throw std::bad_alloc();
    }
    return *query;
}

// DetourCrowd's default sampling (75 velocities), or, for a body hemmed in (touching four or more of
// its six nearest), its low-quality preset (11): in a jam it has nowhere much to go, and a crowd of
// thousands pressed together spent most of a step choosing among velocities that all collide.
dtObstacleAvoidanceParams avoidance_params(bool hemmed_in) {
    dtObstacleAvoidanceParams p{};
    p.velBias = 0.4f;
    p.weightDesVel = 2.0f;
    p.weightCurVel = 0.75f;
    p.weightSide = 0.75f;
    p.weightToi = 2.5f;
    p.horizTime = 2.5f;
    p.gridSize = 33;
    p.adaptiveDivs = hemmed_in ? 5 : 7;
    p.adaptiveRings = 2;
    p.adaptiveDepth = hemmed_in ? 1 : 5;
    return p;
}

// The neighbours an agent steers around: the nearest kMaxNeighbours within its range (nearest first,
// the lower index on a tie, so the answer does not depend on the grid's order).
size_t nearest_neighbours(uint32_t self, const CrowdSnapshot& crowd, float range,
                          std::array<uint32_t, kMaxNeighbours>& out) {
    return crowd.grid.nearest(crowd.positions[self], range, self, out.data(), out.size());
}

void fly(Agent& a, float dt) {
    a.motion_time += dt;
    a.position = a.motion->at(a.motion_time, &a.velocity);
    if (a.motion_time < a.motion->duration()) return;
    // Landed: on the link's end, walking on from the point after the take-off.
    a.position = a.motion->to();
    a.polygon = a.landing_polygon;
    a.velocity = Vec3::Zero();
    const Handle link = a.link;
    a.motion.reset();
    a.link = Handle{};
    a.motion_time = 0.0f;
    // Stopped in the air: it stands where it lands. Sent elsewhere in the air: it waits for that path.
    a.state = !a.has_destination ? AgentState::Idle : a.wants_path ? AgentState::Waiting : AgentState::Walking;
    if (!a.path.empty()) ++a.next;
    a.emit(AgentEventKind::LinkFinished, AgentReason::None, link);
}

// Walkers meeting head-on both keep to their right (seen from above, y up: forward x up), so that
// they pass on opposite sides and a two-way flow forms lanes, instead of both dodging the same way:
// with another walker ahead within kOncomingRange coming the other way, the desired velocity turns
// right by up to kKeepRight radians, the more the nearer it is. (Velocity obstacles alone are
// symmetric: two bodies on one line choose mirror velocities and meet again.)
constexpr float kOncomingRange = 4.0f;  // m
constexpr float kKeepRight = 0.5f;      // rad
Vec3 keep_right(const Agent& a, const Vec3& desired, const CrowdSnapshot& crowd, const uint32_t* near, size_t count) {
    const float speed = desired.norm();
    if (speed <= 0.0f) return desired;
    const Vec3 forward = desired / speed;
    float turn = 0.0f;
    for (size_t k = 0; k < count; ++k) {
        const uint32_t j = near[k];
        if (crowd.makes_room[j]) continue;
        const Vec3 ahead(crowd.positions[j].x() - a.position.x(), 0.0f, crowd.positions[j].z() - a.position.z());
        const float along = ahead.dot(forward), distance = ahead.norm();
        const Vec3& v = crowd.velocities[j];
        const float towards = -(v.x() * forward.x() + v.z() * forward.z());  // its speed against our way
        if (along <= 0.0f || distance > kOncomingRange || towards < 0.5f * std::hypot(v.x(), v.z()) || towards <= 0.0f)
            continue;
        turn = std::max(turn, kKeepRight * (1.0f - distance / kOncomingRange));
    }
    if (turn <= 0.0f) return desired;
    const Vec3 right(forward.z() * -1.0f, 0.0f, forward.x());  // forward x up, for y up: (-z, 0, x)
    const Vec3 turned = forward * std::cos(turn) + right * std::sin(turn);
    return turned * speed;
}

// A walker that touches a body it walks into slides around it, as around a wall's corner, keeping
// to its right: the part of its velocity into the other is taken away, and, when less than half its
// speed is left (head-on), half its speed goes to the right of the contact. Velocity obstacles
// cannot do this: for bodies in contact every velocity toward the other collides at once, and the
// least bad is to stand, so two walkers pressed together in counterflow stood for good. Then no
// contact is pressed into faster than it moves away. Bodies that make room are pushed aside
// instead (overlaps.h); one on its way our way that moves along it (a queue: overtaking it by the
// side jammed a door's mouth), and one that walks away at half our speed or more, are followed, not
// slid past; one our way that stands (stuck) is walked round. Returns whether it touched a body it
// walks into (`desired` changed), else leaves it.
constexpr float kSlideSpeed = 0.5f;  // of its desired speed: head-on, the sidestep to the right
constexpr float kMovesOn = 0.1f;     // of its desired speed: a body our way this fast along it is followed
bool slide_past(const Agent& a, Vec3& desired, const CrowdSnapshot& crowd, const uint32_t* near, size_t count) {
    const float speed = desired.norm();
    if (speed <= 0.0f) return false;
    const float radius = a.def.capabilities.radius;
    // The unit normal from a toward body j, if they touch.
    auto contact = [&](uint32_t j, Vec3& normal) {
        normal = Vec3(crowd.positions[j].x() - a.position.x(), 0.0f, crowd.positions[j].z() - a.position.z());
        const float d = normal.norm();
        if (crowd.makes_room[j] || d >= radius + crowd.radii[j] + kContact || d < 1e-5f) return false;
        normal /= d;
        return true;
    };
    auto away = [&](uint32_t j, const Vec3& normal) {
        return crowd.velocities[j].x() * normal.x() + crowd.velocities[j].z() * normal.z();
    };
    bool slid = false;
    Vec3 normal;
    for (size_t k = 0; k < count; ++k) {
        if (!contact(near[k], normal)) continue;
        const float into = desired.dot(normal);
        // Followed, not slid past: one on its way our way that moves along it (a queue that moves), or
        // one walking off faster than half our speed.
        const bool our_way = crowd.ways[near[k]].dot(desired) > 0.0f &&
                             crowd.velocities[near[k]].dot(desired) > kMovesOn * speed * speed;
        if (into <= 0.0f || our_way || away(near[k], normal) > kSlideSpeed * speed) continue;
        desired -= normal * into;
        if (desired.norm() < kSlideSpeed * speed)
            desired += Vec3(-normal.z(), 0.0f, normal.x()) * (kSlideSpeed * speed);
        slid = true;
    }
    if (!slid) return false;
    if (desired.norm() > speed) desired *= speed / desired.norm();
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t k = 0; k < count; ++k) {
            if (!contact(near[k], normal)) continue;
            const float into = desired.dot(normal) - std::max(0.0f, away(near[k], normal));
            if (into > 0.0f) desired -= normal * into;
        }
    }
    return true;
}

// Hexagonal packing's density: k discs fill a circle about sqrt(k / kPacking) radii wide.
constexpr float kPacking = 0.9069f;

// Whether bodies i and j were sent to one point (CrowdSnapshot::sharing_goal).
bool shares_goal(uint32_t i, uint32_t j, const CrowdSnapshot& crowd) {
    return crowd.sharing_goal[i] > 0 && crowd.sharing_goal[j] > 0 &&
           distance_xz(crowd.goals[i], crowd.goals[j]) < crowd.radii[i] + crowd.radii[j];
}

// Whether a body `distance` from its destination arrives there among the bodies sent to the same
// point: k bodies cannot all stand on it, but they fit in a circle of sqrt((k - 1) / kPacking) radii
// around it (two: one radius each side). Within that circle, a body that touches one that is as near
// to the point or nearer, and was sent there too or has arrived, has come as near as it can.
bool arrived_among_others(const Agent& a, uint32_t self, const Vec3& goal, float distance, const CrowdSnapshot& crowd) {
    const uint16_t sharing = crowd.sharing_goal[self];
    if (sharing < 2) return false;
    const float radius = a.def.capabilities.radius;
    // Avoidance keeps a body from closing the last gap to a standing one: half a radius counts as
    // touching here.
    const float slack = std::max(kContact, 0.5f * radius);
    if (distance > radius * std::sqrt(float(sharing - 1) / kPacking) + slack) return false;
    bool blocked = false;
    crowd.grid.visit(a.position, radius + crowd.max_radius + slack, [&](uint32_t j) {
        if (blocked || j == self) return;
        const float reach = radius + crowd.radii[j] + slack;
        if (distance_xz(crowd.positions[j], a.position) >= reach) return;
        blocked = (shares_goal(self, j, crowd) || crowd.arrived[j]) &&
                  distance_xz(crowd.positions[j], goal) <= distance + slack;
    });
    return blocked;
}

// Slows down to stop `distance` ahead: the speed from which max_acceleration stops in that distance.
float braking_speed(const Agent& a, float distance) {
    return std::sqrt(2.0f * std::max(a.def.max_acceleration, 0.01f) * std::max(distance, 0.0f));
}

void decelerate(Agent& a, float dt) {
    const float speed = a.velocity.norm();
    const float slower = std::max(0.0f, speed - a.def.max_acceleration * dt);
    a.velocity = speed > 0.0f ? Vec3(a.velocity * (slower / speed)) : Vec3(Vec3::Zero());
}

// Giving way: a step back from where it was heading and kStepAside to its right, at half its speed,
// out of the narrow place (docs/agents.md, "Passing in narrow places"). Straight back, the crowd
// behind a body that gave way at a door's mouth pushed it back in: 60 of 100 crossed a 2 m door in
// counterflow in 220 s; stepping back to the right, as keeping right passes, clears the door's lane
// (all 100 by 173 s; 0.35-0.5 rad did alike, 0.65 let 90 through).
constexpr float kStepAside = 0.4f;  // rad
void back_off(Agent& a, float dt, const NavMesh& navmesh) {
    const Vec3& target = a.path[a.next].position;
    const Vec3 back(a.position.x() - target.x(), 0.0f, a.position.z() - target.z());
    const Vec3 right(back.z(), 0.0f, -back.x());  // its right, facing the target
    const Vec3 away = back * std::cos(kStepAside) + right * std::sin(kStepAside);
    const float length = away.norm();
    a.velocity = length > 1e-6f ? Vec3(away * (0.5f * a.def.max_speed / length)) : Vec3(Vec3::Zero());
    const SurfaceMove moved = move_keeping_height(navmesh, a.polygon, a.position, a.position + a.velocity * dt);
    a.walked_since_landing += distance_xz(a.position, moved.position);
    a.position = moved.position;
    a.polygon = moved.polygon;
}

}  // namespace

SurfaceMove move_keeping_height(const NavMesh& navmesh, uint32_t polygon, const Vec3& from, const Vec3& to) {
    SurfaceMove moved = move_along_surface(navmesh, polygon, from, to);
    moved.position.y() += from.y() - navmesh.surface_height(polygon, from.x(), from.z());
    return moved;
}

// The feet's height over (x, z) of the surface point `on_surface`: the surface's, eased from the
// landing's floor over the first kHeightEase walked, and toward the take-off's floor over the last.
float eased_height(const Agent& a, const Vec3& on_surface, const PathPoint& target, float distance) {
    float y = on_surface.y();
    if (a.walked_since_landing < kHeightEase) y += a.landing_offset * (1.0f - a.walked_since_landing / kHeightEase);
    if (target.segment != kSegmentWalk && distance < kHeightEase + kStopReach) {
        const float toward_floor = std::min(1.0f, 1.0f - (distance - kStopReach) / kHeightEase);
        y += toward_floor * (target.position.y() - y);
    }
    return y;
}

void move_agent(Agent& a, uint32_t self, float dt, const NavMesh& navmesh, const CrowdSnapshot& crowd) {
    if (a.motion) {
        fly(a, dt);
        // Landed on the floor: how far that is from the surface it walks on now (one that landed on
        // another navmesh is moved onto it after this phase).
        if (!a.motion && a.landing_navmesh == Handle{}) {
            a.landing_offset = a.position.y() - navmesh.surface_height(a.polygon, a.position.x(), a.position.z());
            a.walked_since_landing = 0.0f;
        }
        return;
    }
    if (a.giving_way > 0.0f && !a.path.empty() && !a.at_takeoff) {
        back_off(a, dt, navmesh);
        return;
    }
    if (a.state != AgentState::Walking || a.at_takeoff || a.path.empty()) {
        decelerate(a, dt);
        a.velocity = Vec3::Zero();  // standing agents do not drift over the surface
        return;
    }

    // The next point to head for: walk corners reached on the way are passed.
    const std::vector<PathPoint>& path = a.path;
    while (a.next + 1 < path.size() && path[a.next].segment == kSegmentWalk &&
           distance_xz(a.position, path[a.next].position) < kCornerReach)
        ++a.next;
    // A corner it can see past is behind it: as Detour's corridor, head straight for the one after,
    // so that no corner must be reached exactly (at a wall's end, avoidance would keep it off).
    if (a.next + 1 < path.size() && path[a.next].segment == kSegmentWalk &&
        straight_walk_clear(navmesh, a.polygon, a.position, path[a.next + 1].position))
        ++a.next;
    const PathPoint& target = path[a.next];
    const bool last = a.next + 1 == path.size();
    const bool takeoff = target.segment != kSegmentWalk;
    const float distance = distance_xz(a.position, target.position);

    // A destination others share, or another body has arrived on, is reached as near as the crowd
    // there lets (docs/agents.md, "Arriving among others").
    bool taken =
        last && !takeoff && crowd.grounded[self] && arrived_among_others(a, self, target.position, distance, crowd);
    if (!taken && last && !takeoff && crowd.grounded[self]) {
        const float radius = a.def.capabilities.radius;
        bool against_crowd = false;
        crowd.grid.visit(a.position, radius + crowd.max_radius + kContact, [&](uint32_t j) {
            // Bodies sent to the same point settle by arrived_among_others' bound instead.
            against_crowd =
                against_crowd || (j != self && crowd.arrived[j] && !shares_goal(self, j, crowd) &&
                                  distance_xz(crowd.positions[j], a.position) < radius + crowd.radii[j] + kContact &&
                                  distance_xz(crowd.positions[j], target.position) < distance);
        });
        if (against_crowd) {
            crowd.grid.visit(target.position, radius + crowd.max_radius, [&](uint32_t j) {
                taken = taken || (j != self && crowd.arrived[j] &&
                                  distance_xz(crowd.positions[j], target.position) < radius + crowd.radii[j]);
            });
        }
    }
    if ((last || takeoff) && (distance < kStopReach || taken)) {
        a.velocity = Vec3::Zero();
        if (takeoff) {
            a.at_takeoff = true;  // the serial phase checks the link and takes off
        } else if (a.partial) {
            a.fail(AgentReason::NoPath);
        } else {
            a.state = AgentState::Arrived;
            a.emit(AgentEventKind::Arrived);
        }
        return;
    }

    // Pushed off the stretch it walks (by other agents): while it still sees the point it heads for
    // (a straight walk over the surface), its path holds from where it stands, as Detour's corridor
    // re-anchors on the polygon it was pushed onto; behind a wall now, it plans again from there.
    const Vec3& from = a.next > 0 ? path[a.next - 1].position : a.position;
    if (distance_to_segment_xz(a.position, from, target.position) > a.def.capabilities.radius + kOffPathSlack &&
        !straight_walk_clear(navmesh, a.polygon, a.position, target.position))
        a.off_path = true;

    // Desired velocity: toward the target at full speed, braking for a stop.
    Vec3 toward(target.position.x() - a.position.x(), 0.0f, target.position.z() - a.position.z());
    float speed = a.def.max_speed;
    if (last || takeoff) speed = std::min(speed, braking_speed(a, distance));
    Vec3 desired = distance > 0.0f ? Vec3(toward * (speed / distance)) : Vec3(Vec3::Zero());
    // Never overshoot the stop within this step.
    if ((last || takeoff) && desired.norm() * dt > distance) desired *= distance / (desired.norm() * dt);

    const float radius = a.def.capabilities.radius;
    // The first at a take-off walks straight onto it; the others make way.
    const bool steers = a.def.avoidance && crowd.grounded[self] && !crowd.first_at_takeoff[self];
    std::array<uint32_t, kMaxNeighbours> near{};
    const size_t count = steers ? nearest_neighbours(self, crowd, std::max(radius * 12.0f, 1.0f), near) : 0;
    if (steers) {
        // Other bodies only: walls are kept by the navmesh itself, eroded by the body's radius, and
        // by the surface move. A body on that eroded edge touches it, and DetourCrowd's sampling
        // takes a touched wall for an immediate collision: bodies rounding a corner would crawl.
        if (count > 0) {
            desired = keep_right(a, desired, crowd, near.data(), count);
            dtObstacleAvoidanceQuery& query = avoidance_query();
            query.reset();
            size_t touching = 0;
            for (size_t k = 0; k < count; ++k) {
                const uint32_t j = near[k];
                // A body standing at its destination, or aside, makes room (overlaps.h): a walker goes
                // its way and pushes it aside, instead of finding a wall of arrived bodies past a door
                // (one sent to the same point stops as it touches it: arrived_among_others).
                if (crowd.makes_room[j]) continue;
                query.addCircle(crowd.positions[j].data(), crowd.radii[j], crowd.velocities[j].data(),
                                crowd.velocities[j].data());
                touching += distance_xz(crowd.positions[j], a.position) < radius + crowd.radii[j] + kContact;
            }
            // Pressed against one or two bodies, it slides past them; hemmed in by more, it has no
            // side to slide to, and the velocity obstacles choose.
            if (touching > kSlidesPastAtMost || !slide_past(a, desired, crowd, near.data(), count)) {
                const dtObstacleAvoidanceParams params = avoidance_params(touching >= kHemmedIn);
                Vec3 chosen = desired;
                query.sampleVelocityAdaptive(a.position.data(), radius, a.def.max_speed, a.velocity.data(),
                                             desired.data(), chosen.data(), &params);
                desired = Vec3(chosen.x(), 0.0f, chosen.z());
            }
        }
    }

    // Accelerate toward it within max_acceleration.
    Vec3 change = desired - a.velocity;
    change.y() = 0.0f;
    const float most = a.def.max_acceleration * dt;
    if (change.norm() > most) change *= most / change.norm();
    a.velocity += change;
    a.velocity.y() = 0.0f;

    const Vec3 before = a.position;
    const SurfaceMove moved = move_along_surface(navmesh, a.polygon, before, before + a.velocity * dt);
    a.position = moved.position;
    a.polygon = moved.polygon;
    a.walked_since_landing += distance_xz(before, moved.position);
    a.position.y() = eased_height(a, moved.position, target, distance_xz(moved.position, target.position));
    if (moved.blocked && dt > 0.0f) {
        // Slid along a wall: keep only the velocity the wall left, never more than the body had.
        const Vec3 went = moved.position - before;
        Vec3 slid(went.x() / dt, 0.0f, went.z() / dt);
        const float had = a.velocity.norm(), speed = slid.norm();
        if (speed > had) slid = speed > 0.0f ? Vec3(slid * (had / speed)) : Vec3(Vec3::Zero());
        a.velocity = slid;
    }
}

}  // namespace nl
