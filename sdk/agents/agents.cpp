#include "agents/agents.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <shared_mutex>

#include "agents/agent_motion.h"
#include "agents/agent_state.h"
#include "agents/flight_check.h"
#include "agents/path_upkeep.h"
#include "agents/route.h"
#include "links/link_placement.h"
#include "path/link_filter.h"
#include "path/path_planner.h"

namespace nl {
namespace {

constexpr float kSameEnd = 0.01f;  // a link end within this of where the path has it has not moved
constexpr float kMissedLanding = 2.0f;  // how far from a moving surface a flight may end and still land on it

void check_positive(float value, const char* field) {
    if (!(value > 0.0f) || !std::isfinite(value)) fail_field(ErrorCode::InvalidArgument, field, " is ", value, " (must be finite and > 0)");
}
void check_amount(float value, const char* field) {
    if (!(value >= 0.0f) || !std::isfinite(value))
        fail_field(ErrorCode::InvalidArgument, field, " is ", value, " (must be finite and >= 0)");
}
void check_capabilities(const AgentCapabilities& c) {
    check_amount(c.max_jump_distance, "capabilities.max_jump_distance");
    check_amount(c.max_jump_height, "capabilities.max_jump_height");
    check_amount(c.max_drop_height, "capabilities.max_drop_height");
    check_amount(c.radius, "capabilities.radius");
}
void check_point(const Vec3& p, const char* field) {
    if (!within_coordinate_limit(p)) fail_field(ErrorCode::InvalidArgument, field, " is not finite or beyond the coordinate limit");
}

AgentState state_of(MotionKind kind) {
    switch (kind) {
        case MotionKind::Arc: return AgentState::Jumping;
        case MotionKind::Fall: return AgentState::Falling;
        case MotionKind::Line: break;
    }
    return AgentState::Traversing;
}

}  // namespace

Agents::Agents(uint32_t handle_tag, AgentsSettings settings) : settings_(settings), ids_(handle_tag, HandleKind::Agent) {}
Agents::~Agents() = default;

AgentBody& Agents::find(Handle agent) {
    uint32_t* index = ids_.find(agent);
    if (!index) fail_stale("agent", agent);
    return agents_[*index];
}
const AgentBody& Agents::find(Handle agent) const { return const_cast<Agents*>(this)->find(agent); }

uint32_t Agents::locate(const NavMesh& navmesh, const SurfacePose& pose, const Vec3& world_point, float radius,
                        const char* field, Vec3& on_navmesh) const {
    // Over the navmesh, or within the body's radius of its edge (half a metre at least), and within
    // 2 m above or below it; farther is refused, saying how far the nearest navmesh is.
    const float across = std::max(0.5f, radius);
    const Vec3 point = pose.surface_point(world_point);
    const NavPoint near = navmesh.find_nearest(point, pose.surface_extents(Vec3(across, 2.0f, across)));
    if (near.found) {
        on_navmesh = near.point;
        return near.polygon;
    }
    const NavPoint far = navmesh.find_nearest(point, Vec3(25.0f, 25.0f, 25.0f));
    if (far.found)
        fail_field(ErrorCode::NotFound, field, " is not on the navmesh: the nearest navmesh point is ", far.distance,
                   " m away (within ", across, " m across and 2 m up or down is on it)");
    fail_field(ErrorCode::NotFound, field, " is not on the navmesh (nothing within 25 m)");
}

std::shared_ptr<const NavMesh> Agents::navmesh_of(const NavMeshRegistry& navmeshes, Handle agent, float& radius,
                                                  SurfacePose& pose) const {
    Handle navmesh;
    {
        std::shared_lock lock(mutex_);
        const AgentBody& a = find(agent);
        navmesh = a.def.navmesh;
        radius = a.def.capabilities.radius;
        pose = pose_of(a.frame);
    }
    try {
        return navmeshes.navmesh(navmesh);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::InvalidHandle) throw;
        fail(ErrorCode::InvalidHandle, "the agent's navmesh {", navmesh.index1, ", ", navmesh.generation,
             "} was removed: the agent cannot go anywhere (it fails at the next step; remove it)");
    }
}

bool Agents::locate_across(const NavMeshRegistry& navmeshes, Handle own, const Vec3& point, float radius, Vec3& on_navmesh,
                           Handle& navmesh, std::shared_ptr<const SurfaceFrame>& frame) const {
    // The navmeshes cross links join to the agent's, nearest hop first (either way: a platform the
    // agent can ride away from its own navmesh and back).
    std::vector<std::pair<Handle, Handle>> joins;
    for (Handle h : navmeshes.handles()) {
        try {
            const auto links = navmeshes.links(h);  // held: an edit on another thread may publish the next
            for (const StoredLink& s : *links)
                if (s.link.crosses()) joins.emplace_back(h, s.link.landing_navmesh);
        } catch (const Error& e) {
            if (e.code() != ErrorCode::InvalidHandle) throw;  // removed meanwhile
        }
    }
    std::vector<Handle> seen{own};
    for (size_t next = 0; next < seen.size(); ++next) {
        for (const auto& [a, b] : joins) {
            const Handle other = a == seen[next] ? b : b == seen[next] ? a : Handle{};
            if (other == Handle{} || std::find(seen.begin(), seen.end(), other) != seen.end()) continue;
            seen.push_back(other);
            try {
                const std::shared_ptr<const NavMesh> mesh = navmeshes.navmesh(other);
                std::shared_ptr<const SurfaceFrame> other_frame = navmeshes.frame(other);
                locate(*mesh, pose_of(other_frame), point, radius, "point", on_navmesh);
                navmesh = other;
                frame = std::move(other_frame);
                return true;
            } catch (const Error& e) {
                if (e.code() != ErrorCode::NotFound && e.code() != ErrorCode::InvalidHandle) throw;
            }
        }
    }
    return false;
}

Handle Agents::add(const NavMeshRegistry& navmeshes, const AgentDef& def) {
    check_capabilities(def.capabilities);
    check_positive(def.height, "height");
    check_positive(def.max_speed, "max_speed");
    check_positive(def.max_acceleration, "max_acceleration");
    check_positive(def.gravity, "gravity");
    check_amount(def.takeoff_speed, "takeoff_speed");
    check_point(def.position, "position");
    const std::shared_ptr<const NavMesh> navmesh = navmeshes.navmesh(def.navmesh);
    AgentBody body;
    body.def = def;
    body.frame = navmeshes.frame(def.navmesh);
    body.polygon = locate(*navmesh, pose_of(body.frame), def.position, def.capabilities.radius, "position", body.position);
    std::unique_lock lock(mutex_);
    // Nothing may throw once the id is taken. Grown geometrically: adding n agents one by one
    // copies O(n) bodies in all, not O(n^2).
    if (agents_.size() == agents_.capacity()) agents_.reserve(std::max<size_t>(16, 2 * agents_.capacity()));
    const Handle id = ids_.insert(static_cast<uint32_t>(agents_.size()));
    body.id = id;
    agents_.push_back(std::move(body));
    return id;
}

void Agents::remove(Handle agent) {
    std::unique_lock lock(mutex_);
    uint32_t* slot = ids_.find(agent);
    if (!slot) fail_stale("agent", agent);
    const uint32_t at = *slot;
    ids_.erase(agent);
    if (at + 1 != agents_.size()) {
        agents_[at] = std::move(agents_.back());
        *ids_.find(agents_[at].id) = at;
    }
    agents_.pop_back();
}

bool Agents::contains(Handle agent) const {
    std::shared_lock lock(mutex_);
    return ids_.find(agent) != nullptr;
}

void Agents::set_destination(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& destination, const char* field) {
    check_point(destination, field);
    float radius;
    SurfacePose pose;
    const std::shared_ptr<const NavMesh> mesh = navmesh_of(navmeshes, agent, radius, pose);
    Handle own;
    {
        std::shared_lock lock(mutex_);
        own = find(agent).def.navmesh;
    }
    Vec3 on_navmesh;
    Handle there = own;
    std::shared_ptr<const SurfaceFrame> there_frame = navmeshes.frame(own);
    // Located on the surface now, and kept there: it moves with the surface until the agent arrives.
    try {
        locate(*mesh, pose, destination, radius, field, on_navmesh);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::NotFound) throw;
        if (!locate_across(navmeshes, own, destination, radius, on_navmesh, there, there_frame)) throw;
    }
    std::unique_lock lock(mutex_);
    AgentBody& a = find(agent);
    a.has_destination = true;
    a.destination = on_navmesh;
    a.destination_navmesh = there;
    a.destination_frame = std::move(there_frame);
    if (!a.motion) {
        // The old path leads elsewhere: walking on along it while the new one waits its turn would end
        // in an arrival (or failure) at the old destination.
        a.path.clear();
        a.at_takeoff = false;
        a.link = Handle{};
        a.state = AgentState::Waiting;
    }
    a.reason = AgentReason::None;
    a.ask_path(AgentReason::DestinationSet, next_path_order_);
}

void Agents::stop(Handle agent) {
    std::unique_lock lock(mutex_);
    AgentBody& a = find(agent);
    a.has_destination = false;
    a.wants_path = false;
    a.at_takeoff = false;
    a.path.clear();
    a.graph.reset();
    if (!a.motion) a.link = Handle{};
    // One whose navmesh was removed stays failed: it has nowhere to stand (and would fail again,
    // with a second event, at the next step).
    const bool stranded = a.state == AgentState::Failed && a.reason == AgentReason::NavMeshRemoved;
    if (!a.motion && !stranded) {
        a.state = AgentState::Idle;
        a.velocity = Vec3::Zero();
    }
}

void Agents::teleport(const NavMeshRegistry& navmeshes, Handle agent, const Vec3& position, const char* field) {
    check_point(position, field);
    float radius;
    SurfacePose pose;
    const std::shared_ptr<const NavMesh> mesh = navmesh_of(navmeshes, agent, radius, pose);
    Vec3 on_navmesh;
    const uint32_t polygon = locate(*mesh, pose, position, radius, field, on_navmesh);
    std::unique_lock lock(mutex_);
    AgentBody& a = find(agent);
    if (a.motion) fail(ErrorCode::InvalidArgument, "the agent is taking a link (teleport it after it lands)");
    a.put_on_surface(on_navmesh);
    a.polygon = polygon;
    a.velocity = Vec3::Zero();
    a.at_takeoff = false;
    a.link = Handle{};
    a.path.clear();
    if (a.has_destination && a.state != AgentState::Failed) {
        a.state = AgentState::Waiting;
        a.ask_path(AgentReason::OffPath, next_path_order_);
    }
}

void Agents::set_capabilities(Handle agent, const AgentCapabilities& capabilities) {
    check_capabilities(capabilities);
    std::unique_lock lock(mutex_);
    AgentBody& a = find(agent);
    a.def.capabilities = capabilities;
    // A body that could not reach its destination may now (one whose navmesh was removed may not).
    const bool stranded = a.state == AgentState::Failed && a.reason == AgentReason::NavMeshRemoved;
    if (a.has_destination && a.state != AgentState::Arrived && !stranded) {
        if (a.state == AgentState::Failed) a.state = AgentState::Waiting;
        a.ask_path(AgentReason::CapabilitiesChanged, next_path_order_);
    }
}

void Agents::set_speed(Handle agent, float max_speed, float max_acceleration) {
    check_positive(max_speed, "max_speed");
    check_positive(max_acceleration, "max_acceleration");
    std::unique_lock lock(mutex_);
    AgentBody& a = find(agent);
    a.def.max_speed = max_speed;
    a.def.max_acceleration = max_acceleration;
}

uint32_t Agents::count() const {
    std::shared_lock lock(mutex_);
    return static_cast<uint32_t>(agents_.size());
}

void Agents::step(float dt, const NavMeshRegistry& navmeshes, const Level& level, TaskSystem& tasks) {
    if (!(dt >= 0.0f) || !std::isfinite(dt)) fail_field(ErrorCode::InvalidArgument, "dt is ", dt, " (must be finite and >= 0)");
    if (dt == 0.0f) return;  // does nothing: the last step's events stay too
    std::unique_lock lock(mutex_);
    events_.clear();
    if (agents_.empty()) {
        motions_.remember(level.movable_meshes(), dt);
        return;
    }

    // 1. The world as it is now: each navmesh's graph, looked up once.
    StepNavMeshes table;  // each navmesh's graph and pose at this moment, looked up once
    auto graph_of = [&](Handle navmesh) -> std::shared_ptr<const PathGraph> {
        if (const StepNavMesh* known = table.find(navmesh)) return known->graph;
        std::shared_ptr<const PathGraph> graph;
        if (navmeshes.contains(navmesh)) {
            try {
                graph = navmeshes.path_graph(navmesh);
            } catch (const Error& e) {
                if (e.code() != ErrorCode::InvalidHandle) throw;  // removed since: no graph
            }
        }
        table.add(navmesh, graph);
        return graph;
    };
    std::vector<std::shared_ptr<const PathGraph>> current(agents_.size());
    LinkLookup links;
    for (size_t i = 0; i < agents_.size(); ++i) {
        AgentBody& a = agents_[i];
        a.step_events.clear();
        a.step_events.reserve(8);  // a step emits a few per agent: the parallel move never allocates for them
        if (a.state == AgentState::Failed) {
            // One that failed for another reason says so too: its NO_PATH no longer says why it stands.
            if (a.reason != AgentReason::NavMeshRemoved && !navmeshes.contains(a.def.navmesh))
                a.fail(AgentReason::NavMeshRemoved);
            continue;
        }
        current[i] = graph_of(a.def.navmesh);
        if (!current[i]) {
            a.motion.reset();
            a.fail(AgentReason::NavMeshRemoved);
            continue;
        }
        if (a.motion) continue;  // in the air: it lands first
        if (a.off_path) {
            a.off_path = false;
            // Once per request: one waiting its turn walks on, off its path, step after step.
            if (!a.wants_path) {
                a.ask_path(AgentReason::OffPath, next_path_order_);
                a.emit(AgentEventKind::Replanned, AgentReason::OffPath);
            }
        } else if (a.graph && a.graph != current[i] && !a.wants_path && a.state != AgentState::Arrived) {
            const PathUpkeep upkeep = check_path(a, *current[i], links);
            if (upkeep.verdict == PathUpkeep::Holds) {
                a.graph = current[i];
            } else if (upkeep.verdict == PathUpkeep::LinkGone) {
                a.ask_path(AgentReason::LinkGone, next_path_order_);
                a.emit(AgentEventKind::Replanned, AgentReason::LinkGone, upkeep.link);
            } else {
                // Another navmesh under the same handle: stand where it is on the new one, plan anew.
                const NavPoint here = current[i]->navmesh().find_nearest(a.position, Vec3(2.0f, 2.0f, 2.0f));
                if (!here.found) {
                    a.fail(AgentReason::NavMeshRemoved);
                    continue;
                }
                a.put_on_surface(here.point);
                a.polygon = here.polygon;
                a.path.clear();
                a.graph.reset();
                a.at_takeoff = false;
                a.state = AgentState::Waiting;
                a.ask_path(AgentReason::WorldChanged, next_path_order_);
                a.emit(AgentEventKind::Replanned, AgentReason::WorldChanged);
            }
        }
    }

    // 2. The paths asked for, at most max_paths_per_step, planned in parallel.
    std::vector<uint32_t> asking;
    for (uint32_t i = 0; i < agents_.size(); ++i) {
        const AgentBody& a = agents_[i];
        if (a.wants_path && !a.motion && a.state != AgentState::Failed) asking.push_back(i);
    }
    // Agents with no path to walk meanwhile (a new destination, a link gone at the take-off) first,
    // then the oldest request.
    std::sort(asking.begin(), asking.end(), [&](uint32_t x, uint32_t y) {
        const AgentBody &a = agents_[x], &b = agents_[y];
        const bool a_stands = a.path.empty() || a.at_takeoff || a.state == AgentState::Waiting;
        const bool b_stands = b.path.empty() || b.at_takeoff || b.state == AgentState::Waiting;
        return a_stands != b_stands ? a_stands : a.path_order < b.path_order;
    });
    if (asking.size() > settings_.max_paths_per_step) {
        // Their turn comes in a later step; meanwhile one with a path walks on (it takes no link).
        for (size_t k = settings_.max_paths_per_step; k < asking.size(); ++k) {
            AgentBody& a = agents_[asking[k]];
            if (a.path.empty()) a.state = AgentState::Waiting;
        }
        asking.resize(settings_.max_paths_per_step);
    }
    std::vector<PathQuery> queries(asking.size());
    std::vector<PathResult> results(asking.size());
    bool routes = false;  // some agent may need to leave its navmesh: every navmesh is looked at
    for (size_t k = 0; k < asking.size(); ++k) {
        const AgentBody& a = agents_[asking[k]];
        PathQuery& q = queries[k];
        q.start = a.position;
        q.goal = a.destination;
        q.agent = a.def.capabilities;
        q.accept_partial = true;
        routes = routes || a.destination_navmesh != a.def.navmesh;
    }
    for (size_t t = 0; t < table.all().size() && !routes; ++t)
        routes = table.all()[t].graph && table.all()[t].graph->has_cross_links();
    // Every navmesh, then: routes may cross any of them.
    if (routes)
        for (Handle h : navmeshes.handles()) graph_of(h);
    tasks.parallel_for(static_cast<uint32_t>(asking.size()), 1, [&](uint32_t begin, uint32_t end) {
        for (uint32_t k = begin; k < end; ++k) {
            const AgentBody& a = agents_[asking[k]];
            try {
                const bool here = a.destination_navmesh == a.def.navmesh;
                if (here) plan_path_in_surface_space(*current[asking[k]], queries[k], nullptr, results[k]);
                if (!routes || (here && results[k].outcome == PathOutcome::Complete)) continue;
                // Off this navmesh and back, or onto another: over cross links that hold now, else
                // over one that will (the agent waits for it at its take-off: a ferry).
                RouteQuery route{a.def.navmesh, a.position, a.destination_navmesh, a.destination, a.def.capabilities, false};
                PathResult leg;
                bool found = plan_route(table, route, leg);
                if (!found) {
                    route.through_waiting = true;
                    found = plan_route(table, route, leg);
                }
                if (found) results[k] = std::move(leg);
                else if (!here) results[k].outcome = PathOutcome::NoPath;
            } catch (...) {
                results[k].outcome = PathOutcome::Failed;
            }
        }
    });
    for (size_t k = 0; k < asking.size(); ++k) {
        AgentBody& a = agents_[asking[k]];
        PathResult& r = results[k];
        a.wants_path = false;
        a.at_takeoff = false;
        a.link = Handle{};
        if (r.outcome != PathOutcome::Complete && r.outcome != PathOutcome::Partial) {
            a.fail(AgentReason::NoPath);
            continue;
        }
        a.graph = current[asking[k]];
        a.path = std::move(r.points);
        // A path that starts on a take-off (the agent stands on it) heads for that take-off first.
        a.next = a.path.size() > 1 && a.path[0].segment == kSegmentWalk ? 1 : 0;
        a.partial = r.outcome == PathOutcome::Partial;
        a.state = AgentState::Walking;
        a.reason = a.plan_reason;
        a.emit(AgentEventKind::PathReady, a.plan_reason);
    }

    // 3. Everybody as they are now, for the parallel move: one crowd per space the bodies share (the
    // world, or one moving surface), in the order the spaces first appear.
    const size_t n = agents_.size();
    std::vector<const SurfaceFrame*> spaces;
    std::vector<uint32_t> space_of(n), index_in_space(n);
    std::vector<std::vector<const AgentBody*>> members;
    for (uint32_t i = 0; i < n; ++i) {
        const SurfaceFrame* frame = agents_[i].frame.get();
        const auto found = std::find(spaces.begin(), spaces.end(), frame);
        space_of[i] = static_cast<uint32_t>(found - spaces.begin());
        if (found == spaces.end()) {
            spaces.push_back(frame);
            members.emplace_back();
        }
        index_in_space[i] = static_cast<uint32_t>(members[space_of[i]].size());
        members[space_of[i]].push_back(&agents_[i]);
    }
    std::vector<CrowdSnapshot> crowds(spaces.size());  // built in place: a grid refers to its positions
    for (size_t s = 0; s < spaces.size(); ++s) snapshot_crowd(members[s], crowds[s]);
    // A move that cannot finish (only a first allocation of a thread's avoidance scratch can fail)
    // leaves that agent where it was; the others move, the step ends whole and then says so.
    std::vector<uint8_t> unmoved(n, 0);
    tasks.parallel_for(static_cast<uint32_t>(n), 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            AgentBody& a = agents_[i];
            if (a.state == AgentState::Failed || !current[i]) continue;
            try {
                move_agent(a, index_in_space[i], dt, current[i]->navmesh(), crowds[space_of[i]]);
            } catch (...) {
                unmoved[i] = 1;
            }
        }
    });

    // Landed over a cross link: onto the landing navmesh, in its space, and on from there.
    for (size_t i = 0; i < n; ++i) {
        AgentBody& a = agents_[i];
        if (a.motion || a.landing_navmesh == Handle{} || a.state == AgentState::Failed) continue;
        // Found by a ray down: the surface under the body, if a navmesh for its body rides it (the
        // aim was off and it came down on another platform), else the link's landing navmesh.
        Handle onto = a.landing_navmesh;
        const Ray down{a.position + Vec3(0.0f, 0.5f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 3.0f};
        RayHit hit;
        level.cast_rays(&down, 1, &hit);
        const std::shared_ptr<const PathGraph> planned = graph_of(a.landing_navmesh);
        if (hit.hit && planned) {
            const Handle under = navmeshes.riding(hit.mesh, planned->navmesh().agent());
            if (under != Handle{}) onto = under;
        }
        land_across(a, onto, graph_of(onto), table);
    }

    // 4. Take-offs, in agent order: the link checked as it is now, and its landing clear.
    std::vector<uint32_t> flying;  // only bodies in the air can hold a landing
    for (uint32_t j = 0; j < n; ++j)
        if (agents_[j].motion) flying.push_back(j);
    for (size_t i = 0; i < n; ++i) {
        AgentBody& a = agents_[i];
        if (!a.at_takeoff || a.motion) continue;
        if (a.wants_path) {
            a.state = AgentState::Waiting;  // its new path may not take this link: it waits for it
            continue;
        }
        const PathPoint& point = a.path[a.next];
        Link link;
        bool usable = false;
        try {
            const auto [navmesh, stored] = navmeshes.link(point.link);
            link = stored;
            usable = navmesh == a.def.navmesh && link.enabled && (!point.reversed || link.bidirectional) &&
                     can_take(link, point.reversed, a.def.capabilities);
        } catch (const Error& e) {
            if (e.code() != ErrorCode::InvalidHandle) throw;
        }
        const BodyMotion body{a.def.max_speed, a.def.gravity, a.def.takeoff_speed};
        const LinkMotion motion(link, point.reversed, body);
        // Moved since the path was planned (by another thread, after this step's upkeep): the path's
        // take-off and landing are not the link's any more.
        if (usable && a.next + 1 < a.path.size())
            usable = (motion.from() - point.position).norm() < kSameEnd && (motion.to() - a.path[a.next + 1].position).norm() < kSameEnd;
        // A cross link whose landing navmesh was removed meanwhile leads nowhere: plan again.
        if (usable && link.crosses() && !graph_of(link.landing_navmesh)) usable = false;
        if (!usable) {
            a.at_takeoff = false;
            a.link = Handle{};
            a.state = AgentState::Waiting;
            a.ask_path(AgentReason::LinkGone, next_path_order_);
            a.emit(AgentEventKind::Replanned, AgentReason::LinkGone, point.link);
            continue;
        }
        if (usable && link.crosses()) {
            if (!table.holds(a.def.navmesh, link)) {
                // Its other end is not where it was placed (the platform is away): wait for it here.
                a.state = AgentState::Waiting;
                a.link = point.link;
                continue;
            }
            bool busy = false;
            for (uint32_t j : flying) busy = busy || agents_[j].link == point.link;
            if (busy) {
                a.state = AgentState::Waiting;
                a.link = point.link;
                continue;
            }
            if (!take_off_across(a, link, point.link, body, table, level)) {
                a.state = AgentState::Waiting;  // its aim would meet the level: it waits for a clear one
                a.link = point.link;
                continue;
            }
            flying.push_back(static_cast<uint32_t>(i));
            continue;
        }
        // One body on a landing at a time: wait while another flies to it, or flies this very link
        // (either way: two bodies never cross in the air). Bodies standing there do not stop it (one
        // that stays would hold it forever, two at both ends of a link would wait for each other):
        // after the landing the bodies are pushed apart as anywhere else.
        const Vec3 landing = motion.to();
        bool busy = false;
        for (size_t k = 0; k < flying.size() && !busy; ++k) {
            const AgentBody& b = agents_[flying[k]];
            const float reach = a.def.capabilities.radius + b.def.capabilities.radius;
            const Vec3 there = b.motion->to();
            busy = b.link == point.link ||
                   (b.frame == a.frame && std::hypot(there.x() - landing.x(), there.z() - landing.z()) < reach &&
                    std::fabs(there.y() - landing.y()) < std::max(a.def.height, b.def.height));
        }
        if (busy) {
            a.state = AgentState::Waiting;
            a.link = point.link;
            continue;
        }
        a.at_takeoff = false;
        a.motion = motion;
        a.motion_time = 0.0f;
        a.link = point.link;
        a.landing_polygon = point.reversed ? link.start_polygon : link.end_polygon;
        a.state = state_of(motion.kind());
        a.emit(AgentEventKind::LinkStarted, AgentReason::None, point.link);
        flying.push_back(static_cast<uint32_t>(i));
    }

    motions_.remember(level.movable_meshes(), dt);
    for (const AgentBody& a : agents_) events_.insert(events_.end(), a.step_events.begin(), a.step_events.end());
    const size_t stuck = static_cast<size_t>(std::count(unmoved.begin(), unmoved.end(), uint8_t{1}));
    if (stuck > 0) fail(ErrorCode::OutOfMemory, stuck, " agents could not move in this step (out of memory); the others did");
}

bool Agents::take_off_across(AgentBody& a, const Link& link, Handle id, const BodyMotion& body, const StepNavMeshes& table,
                             const Level& level) {
    const StepNavMesh& from = *table.find(a.def.navmesh);
    const StepNavMesh& to = *table.find(link.landing_navmesh);
    Link flight = link_in_world(link, from.pose, to.pose);
    // Aimed where the landing point will be after the flight; the time of a flight to there differs
    // from the first guess's by the little the aim moved, so one correction is enough.
    const MeshMotion landing =
        to.graph->frame() ? motions_.motion(MovableMesh{to.graph->frame()->mesh(), to.pose.to_world()}) : MeshMotion{};
    const Vec3 aim = flight.end;
    flight.end = landing.after(LinkMotion(flight, false, body).duration()) * link.end;
    flight.end = landing.after(LinkMotion(flight, false, body).duration()) * link.end;
    const LinkMotion motion(flight, false, body);
    // Off the placed arc (the surface moves, or stands elsewhere within the link's tolerance), the
    // generator's proof does not cover it; nor does it cover meshes that move near it since.
    const bool as_proven = (flight.end - aim).norm() < kSameEnd &&
                           (from.pose.surface_point(to.pose.world_point(link.end)) - link.placed_end).norm() < kSameEnd;
    if (!flight_is_clear(motion, a.def.capabilities.radius, a.def.height, level,
                         motions_.motions(level.movable_meshes()), as_proven))
        return false;
    a.position = from.pose.world_point(a.position);
    a.velocity = Vec3::Zero();
    a.frame.reset();  // in the air over no surface: world space until it lands
    a.at_takeoff = false;
    a.motion = motion;
    a.motion_time = 0.0f;
    a.link = id;
    a.landing_navmesh = link.landing_navmesh;
    a.landing_polygon = link.end_polygon;
    a.state = state_of(a.motion->kind());
    a.emit(AgentEventKind::LinkStarted, AgentReason::None, id);
    return true;
}

void Agents::land_across(AgentBody& a, Handle navmesh, const std::shared_ptr<const PathGraph>& graph,
                         const StepNavMeshes& table) {
    a.landing_navmesh = Handle{};
    if (!graph) {
        a.fail(AgentReason::NavMeshRemoved);
        return;
    }
    const SurfacePose pose = table.find(navmesh)->pose;
    const Vec3 feet = pose.surface_point(a.position);
    const float across = std::max(0.5f, a.def.capabilities.radius);
    NavPoint on = graph->navmesh().find_nearest(feet, Vec3(across, 2.0f, across));
    // The surface changed its motion during the flight (a platform that left as the body jumped):
    // the flight was aimed by its motion at take-off, so the body lands on its nearest point.
    if (!on.found) on = graph->navmesh().find_nearest(feet, Vec3(kMissedLanding, 2.0f, kMissedLanding));
    if (!on.found) {
        a.fail(AgentReason::LinkGone);
        return;
    }
    a.def.navmesh = navmesh;
    a.frame = graph->frame();
    a.put_on_surface(on.point);
    a.landing_offset = feet.y() - on.point.y();
    a.walked_since_landing = 0.0f;
    a.polygon = on.polygon;
    a.path.clear();
    a.graph.reset();
    a.next = 0;
    if (a.has_destination) {
        a.state = AgentState::Waiting;
        a.ask_path(AgentReason::None, next_path_order_);
    }
}

namespace {

// What a host reads, in the world: on a moving surface, at the surface's pose of this moment (the
// velocity is the body's own, turned with the surface, without the surface's motion).
AgentInfo info_of(const AgentBody& a) {
    const SurfacePose pose = pose_of(a.frame);
    AgentInfo info;
    info.id = a.id;
    info.state = a.state;
    info.reason = a.reason;
    info.position = pose.world_point(a.position);
    info.velocity = pose.world_vector(a.velocity);
    info.polygon = a.polygon;
    info.link = a.link;
    info.link_progress = a.motion ? std::clamp(a.motion_time / a.motion->duration(), 0.0f, 1.0f) : 0.0f;
    info.destination = pose_of(a.destination_frame).world_point(a.destination);
    info.has_destination = a.has_destination;
    info.corners_ahead = a.path.empty() ? 0u : static_cast<uint32_t>(a.path.size() - a.next);
    info.user_data = a.def.user_data;
    info.navmesh = a.def.navmesh;
    info.surface = a.frame ? a.frame->mesh() : Handle{};
    info.surface_position = a.position;
    return info;
}

}  // namespace

AgentInfo Agents::info(Handle agent) const {
    std::shared_lock lock(mutex_);
    return info_of(find(agent));
}

std::vector<AgentInfo> Agents::infos() const {
    std::shared_lock lock(mutex_);
    std::vector<AgentInfo> out;
    out.reserve(agents_.size());
    for (const AgentBody& a : agents_) out.push_back(info_of(a));
    return out;
}

std::vector<PathPoint> Agents::corners(Handle agent) const {
    std::shared_lock lock(mutex_);
    const AgentBody& a = find(agent);
    if (a.path.empty()) return {};
    std::vector<PathPoint> out(a.path.begin() + a.next, a.path.end());
    const SurfacePose pose = pose_of(a.frame);
    for (PathPoint& p : out) {
        p.position = pose.world_point(p.surface_position);
        p.apex = pose.world_point(p.apex);
    }
    return out;
}

Agents::Flight Agents::flight(Handle agent) const {
    std::shared_lock lock(mutex_);
    const AgentBody& a = find(agent);
    if (!a.motion) return {};
    return Flight{a.motion, a.link, a.motion_time, pose_of(a.frame)};
}

std::vector<AgentEvent> Agents::events() const {
    std::shared_lock lock(mutex_);
    return events_;
}

}  // namespace nl
