// Agents::step: a short driver of named phases, each in agent order or parallel over agents with each
// agent writing only its own state (agents.h says why the result is the same for any thread count).
#include <algorithm>
#include <cmath>
#include <mutex>

#include "agents/agent_motion.h"
#include "agents/agent_state.h"
#include "agents/agents.h"
#include "agents/crowd.h"
#include "agents/flight_check.h"
#include "agents/giving_way.h"
#include "agents/overlaps.h"
#include "agents/path_upkeep.h"
#include "agents/route.h"
#include "links/link_placement.h"
#include "path/link_filter.h"
#include "path/path_planner.h"

namespace nl {
namespace {

constexpr float kSameEnd = 0.01f;       // a link end within this of where the path has it has not moved
constexpr float kMissedLanding = 2.0f;  // how far from a moving surface a flight may end and still land on it

AgentState state_of(MotionKind kind) {
    switch (kind) {
        case MotionKind::Arc: return AgentState::Jumping;
        case MotionKind::Fall: return AgentState::Falling;
        case MotionKind::Line: break;
    }
    return AgentState::Traversing;
}

}  // namespace

// What the phases of one step share.
struct Agents::Step {
    float dt;
    const NavMeshRegistry& navmeshes;
    const Level& level;
    TaskSystem& tasks;
    StepNavMeshes table;  // each navmesh's graph and pose at this moment, looked up once
    std::vector<std::shared_ptr<const PathGraph>> current;  // each agent's navmesh's graph (null: failed)
    // The bodies that share a space (the world, or one moving surface): one crowd each.
    std::vector<uint32_t> space_of, index_in_space;
    std::vector<CrowdSnapshot> crowds;
    // A move that cannot finish (only a first allocation of a thread's avoidance scratch can fail)
    // leaves that agent where it was; the others move, the step ends whole and then says so.
    std::vector<uint8_t> unmoved;

    // The graph of `navmesh` at this moment (null: removed), looked up once per step.
    std::shared_ptr<const PathGraph> graph_of(Handle navmesh) {
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
    }
};

void Agents::step(float dt, const NavMeshRegistry& navmeshes, const Level& level, TaskSystem& tasks) {
    if (!(dt >= 0.0f) || !std::isfinite(dt))
        fail_field(ErrorCode::InvalidArgument, "dt is ", dt, " (must be finite and >= 0)");
    if (dt == 0.0f) return;  // does nothing: the last step's events stay too
    std::unique_lock lock(mutex_);
    events_.clear();
    if (agents_.empty()) {
        motions_.remember(level.movable_meshes(), dt);
        return;
    }
    Step s{dt, navmeshes, level, tasks, {}, {}, {}, {}, {}, {}};
    check_against_world(s);
    plan_asked_paths(s);
    move(s);
    separate(s);
    land_cross_flights(s);
    take_off(s);

    motions_.remember(level.movable_meshes(), dt);
    for (const Agent& a : agents_) events_.insert(events_.end(), a.step_events.begin(), a.step_events.end());
    const size_t stuck = static_cast<size_t>(std::count(s.unmoved.begin(), s.unmoved.end(), uint8_t{1}));
    if (stuck > 0)
        fail(ErrorCode::OutOfMemory, stuck, " agents could not move in this step (out of memory); the others did");
}

// 1. (serial) Each agent against the world as it is now: its navmesh still there, its path's links
// still as planned; else it asks for a new path (or fails, its navmesh gone).
void Agents::check_against_world(Step& s) {
    s.current.assign(agents_.size(), nullptr);
    LinkLookup links;
    for (size_t i = 0; i < agents_.size(); ++i) {
        Agent& a = agents_[i];
        a.step_events.clear();
        a.step_events.reserve(8);  // a step emits a few per agent: the parallel move never allocates for them
        if (a.state == AgentState::Failed) {
            // One that failed for another reason says so too: its NO_PATH no longer says why it stands.
            const std::shared_ptr<const PathGraph> graph = s.graph_of(a.def.navmesh);
            if (a.reason != AgentReason::NavMeshRemoved && !graph) a.fail(AgentReason::NavMeshRemoved);
            if (graph && (a.stands_on != graph->navmesh_ptr() || a.awaiting_tile)) stand_on_navmesh_now(a, *graph);
            continue;
        }
        s.current[i] = s.graph_of(a.def.navmesh);
        if (!s.current[i]) {
            a.motion.reset();
            a.fail(AgentReason::NavMeshRemoved);
            continue;
        }
        if ((a.stands_on != s.current[i]->navmesh_ptr() || a.awaiting_tile) &&
            !stand_on_navmesh_now(a, *s.current[i])) {
            s.current[i] = nullptr;  // on no tile: it stands where it is, outside every phase, till one holds it
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
        } else if (a.graph && a.graph != s.current[i] && !a.wants_path && a.state != AgentState::Arrived) {
            // Tiles changed under its handle: a path over tiles that stayed as they were is kept, on the
            // new navmesh, and its links checked there; any other is planned again.
            const bool carried = a.graph->navmesh_ptr() != s.current[i]->navmesh_ptr() &&
                                 carry_path_over(a, a.graph->navmesh(), s.current[i]->navmesh());
            const PathUpkeep upkeep = check_path(a, *s.current[i], links, carried);
            if (upkeep.verdict == PathUpkeep::Holds) {
                a.graph = s.current[i];
            } else if (upkeep.verdict == PathUpkeep::LinkGone) {
                a.ask_path(AgentReason::LinkGone, next_path_order_);
                a.emit(AgentEventKind::Replanned, AgentReason::LinkGone, upkeep.link);
            } else {
                // Another navmesh under the same handle: stand where it is on the new one, plan anew.
                const NavPoint here = s.current[i]->navmesh().find_nearest(a.position, Vec3(2.0f, 2.0f, 2.0f));
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
}

// Its navmesh changed under its handle (tiles added or removed): its polygons are found again on the
// new one. One in the air lands on the nearest polygon to its landing point; one on the ground stands
// where it is, unless no tile holds that place any more: then it waits there, out of the step, until one
// does (false), and plans again when it does.
bool Agents::stand_on_navmesh_now(Agent& a, const PathGraph& now) {
    const NavMesh& navmesh = now.navmesh();
    if (a.motion) {
        // Its polygons stay indices of this navmesh until it lands; then it is placed on the ground as
        // any other (stands_on still differs): on the surface, or waiting if no tile holds it.
        const NavPoint landing = navmesh.find_nearest_anywhere(a.motion->to(), Vec3(0.5f, 1.0f, 0.5f));
        a.landing_polygon = a.polygon = landing.polygon;
        a.stands_on.reset();
        return true;
    }
    NavPoint here;
    if (navmesh.tiles().holds_point(a.position.x(), a.position.z()))
        here = navmesh.find_nearest(a.position, Vec3(2.0f, 2.0f, 2.0f));
    if (!here.found) {
        a.stands_on = now.navmesh_ptr();  // not the old one's memory: awaiting_tile brings it back here
        if (a.state == AgentState::Failed) {
            a.awaiting_tile = true;  // stands on nothing: no phase moves it
            a.polygon = kNoPolygon;
        } else if (!a.awaiting_tile) {
            a.awaiting_tile = true;
            a.path.clear();
            a.graph.reset();
            a.wants_path = false;
            a.at_takeoff = false;
            a.velocity = Vec3::Zero();
            a.polygon = kNoPolygon;
            a.state = AgentState::Waiting;
            a.reason = AgentReason::TileUnloaded;
            a.emit(AgentEventKind::Waiting, AgentReason::TileUnloaded);
        }
        return false;
    }
    a.put_on_surface(here.point);
    a.polygon = here.polygon;
    a.stands_on = now.navmesh_ptr();
    if (a.awaiting_tile) {
        a.awaiting_tile = false;
        if (a.state == AgentState::Failed) {
            // Still failed: a host's new destination or capabilities send it on.
        } else if (a.has_destination) {
            a.ask_path(AgentReason::WorldChanged, next_path_order_);
            a.emit(AgentEventKind::Replanned, AgentReason::WorldChanged);
        } else {
            a.state = AgentState::Idle;
        }
    }
    return true;
}

// 2. The paths asked for, at most max_paths_per_step, planned in parallel on the navmeshes as they are
// now.
void Agents::plan_asked_paths(Step& s) {
    std::vector<uint32_t> asking;
    for (uint32_t i = 0; i < agents_.size(); ++i) {
        const Agent& a = agents_[i];
        if (a.wants_path && !a.motion && a.state != AgentState::Failed && !a.awaiting_tile) asking.push_back(i);
    }
    // Agents with no path to walk meanwhile (a new destination, a link gone at the take-off) first,
    // then the oldest request.
    std::sort(asking.begin(), asking.end(), [&](uint32_t x, uint32_t y) {
        const Agent &a = agents_[x], &b = agents_[y];
        const bool a_stands = a.path.empty() || a.at_takeoff || a.state == AgentState::Waiting;
        const bool b_stands = b.path.empty() || b.at_takeoff || b.state == AgentState::Waiting;
        return a_stands != b_stands ? a_stands : a.path_order < b.path_order;
    });
    if (asking.size() > settings_.max_paths_per_step) {
        // Their turn comes in a later step; meanwhile one with a path walks on (it takes no link).
        for (size_t k = settings_.max_paths_per_step; k < asking.size(); ++k) {
            Agent& a = agents_[asking[k]];
            if (a.path.empty()) a.state = AgentState::Waiting;
        }
        asking.resize(settings_.max_paths_per_step);
    }
    std::vector<PathQuery> queries(asking.size());
    std::vector<PathResult> results(asking.size());
    bool routes = false;  // some agent may need to leave its navmesh: every navmesh is looked at
    for (size_t k = 0; k < asking.size(); ++k) {
        const Agent& a = agents_[asking[k]];
        PathQuery& q = queries[k];
        q.start = a.position;
        q.goal = a.destination;
        q.capabilities = a.def.capabilities;
        q.accept_partial = true;
        routes = routes || a.destination_navmesh != a.def.navmesh;
    }
    for (size_t t = 0; t < s.table.all().size() && !routes; ++t)
        routes = s.table.all()[t].graph && s.table.all()[t].graph->has_cross_links();
    // Every navmesh, then: routes may cross any of them.
    if (routes)
        for (Handle h : s.navmeshes.handles()) s.graph_of(h);
    s.tasks.parallel_for(static_cast<uint32_t>(asking.size()), 1, [&](uint32_t begin, uint32_t end) {
        for (uint32_t k = begin; k < end; ++k) {
            const Agent& a = agents_[asking[k]];
            try {
                const bool here = a.destination_navmesh == a.def.navmesh;
                if (here) plan_path_in_carrier_space(*s.current[asking[k]], queries[k], nullptr, results[k]);
                if (!routes || (here && results[k].outcome == PathOutcome::Complete)) continue;
                // Off this navmesh and back, or onto another: over cross links that hold now, else
                // over one that will (the agent waits for it at its take-off: a ferry).
                RouteQuery route{a.def.navmesh, a.position,         a.destination_navmesh,
                                 a.destination, a.def.capabilities, false};
                PathResult leg;
                bool found = plan_route(s.table, route, leg);
                if (!found) {
                    route.through_waiting = true;
                    found = plan_route(s.table, route, leg);
                }
                if (found)
                    results[k] = std::move(leg);
                else if (!here)
                    results[k].outcome = PathOutcome::NoPath;
            } catch (...) {
                results[k].outcome = PathOutcome::Failed;
            }
        }
    });
    for (size_t k = 0; k < asking.size(); ++k) {
        Agent& a = agents_[asking[k]];
        PathResult& r = results[k];
        a.wants_path = false;
        a.at_takeoff = false;
        a.link = Handle{};
        if (r.outcome != PathOutcome::Complete && r.outcome != PathOutcome::Partial) {
            a.fail(AgentReason::NoPath);
            continue;
        }
        a.graph = s.current[asking[k]];
        a.path = std::move(r.points);
        // A path that starts on a take-off (the agent stands on it) heads for that take-off first.
        a.next = a.path.size() > 1 && a.path[0].segment == kSegmentWalk ? 1 : 0;
        a.partial = r.outcome == PathOutcome::Partial;
        // One giving way stands aside until its time is up (decide_giving_way), on its new path too.
        a.state = a.giving_way > 0.0f ? AgentState::Waiting : AgentState::Walking;
        forget_progress(a);
        // A new way to go counts afresh toward giving up; one planned because the crowd pushed it
        // off its path is the same way, held up by the same crowd.
        if (a.plan_reason != AgentReason::OffPath) forget_patience(a);
        a.reason = a.plan_reason;
        a.emit(AgentEventKind::PathReady, a.plan_reason);
    }
}

// 3. (parallel) Everybody as they are now, for the move: one crowd per space the bodies share (the
// world, or one moving surface), in the order the spaces first appear; each agent steers, avoids the
// others and moves over the surface, or flies its link.
void Agents::move(Step& s) {
    const size_t n = agents_.size();
    std::vector<const CarrierFrame*> spaces;
    s.space_of.assign(n, 0);
    s.index_in_space.assign(n, 0);
    std::vector<std::vector<const Agent*>> members;
    for (uint32_t i = 0; i < n; ++i) {
        const CarrierFrame* frame = agents_[i].frame.get();
        const auto found = std::find(spaces.begin(), spaces.end(), frame);
        s.space_of[i] = static_cast<uint32_t>(found - spaces.begin());
        if (found == spaces.end()) {
            spaces.push_back(frame);
            members.emplace_back();
        }
        s.index_in_space[i] = static_cast<uint32_t>(members[s.space_of[i]].size());
        members[s.space_of[i]].push_back(&agents_[i]);
    }
    s.crowds = std::vector<CrowdSnapshot>(spaces.size());  // built in place: a grid refers to its positions
    for (size_t k = 0; k < spaces.size(); ++k) snapshot_crowd(members[k], s.crowds[k]);
    // A move that cannot finish (only a first allocation of a thread's avoidance scratch can fail)
    // leaves that agent where it was; the others move, the step ends whole and then says so.
    s.unmoved.assign(n, 0);
    s.tasks.parallel_for(static_cast<uint32_t>(n), 64, [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            Agent& a = agents_[i];
            if (a.state == AgentState::Failed || !s.current[i]) continue;
            try {
                move_agent(a, s.index_in_space[i], s.dt, s.current[i]->navmesh(), s.crowds[s.space_of[i]]);
            } catch (...) {
                s.unmoved[i] = 1;
            }
        }
    });
}

// 4. (parallel) Bodies on the ground that overlap after the move are pushed apart, walkers, arrived,
// waiting and failed bodies alike, space by space (overlaps.h); then (serial) who gives way.
void Agents::separate(Step& s) {
    std::vector<std::vector<OverlapBody>> spaces(s.crowds.size());
    for (size_t i = 0; i < agents_.size(); ++i) {
        Agent& a = agents_[i];
        if (a.motion || a.landing_navmesh != Handle{} || a.awaiting_tile) continue;
        const std::shared_ptr<const PathGraph> graph = s.current[i] ? s.current[i] : s.graph_of(a.def.navmesh);
        if (!graph) continue;  // its navmesh was removed: it stands nowhere
        // One at a take-off holds its place (it takes off from there); a walker gives one share, a
        // standing body kStandingGives.
        const float give = a.at_takeoff ? 0.0f : a.state == AgentState::Walking ? 1.0f : kStandingGives;
        spaces[s.space_of[i]].push_back({&a, &graph->navmesh(), give});  // graph: in s.table
    }
    for (const std::vector<OverlapBody>& bodies : spaces) resolve_overlaps(bodies, s.dt, s.tasks);
    decide_giving_way(agents_, s.space_of, s.index_in_space, s.crowds, s.dt);
}

// (serial) Landed over a cross link: onto the landing navmesh, in its space, and on from there.
void Agents::land_cross_flights(Step& s) {
    for (size_t i = 0; i < agents_.size(); ++i) {
        Agent& a = agents_[i];
        if (a.motion || a.landing_navmesh == Handle{} || a.state == AgentState::Failed) continue;
        // Found by a ray down: the surface under the body, if a navmesh for its body rides it (the
        // aim was off and it came down on another platform), else the link's landing navmesh.
        Handle onto = a.landing_navmesh;
        const Ray down{a.position + Vec3(0.0f, 0.5f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 3.0f};
        RayHit hit;
        s.level.cast_rays(&down, 1, &hit);
        const std::shared_ptr<const PathGraph> planned = s.graph_of(a.landing_navmesh);
        if (hit.hit && planned) {
            const Handle under = s.navmeshes.riding(hit.mesh, planned->navmesh().agent());
            if (under != Handle{}) onto = under;
        }
        land_across(a, onto, s.graph_of(onto), s.table);
    }
}

// 6. (serial, in agent order) Take-offs: the link checked as it is now, and its landing clear.
void Agents::take_off(Step& s) {
    std::vector<uint32_t> flying;  // only bodies in the air can hold a landing
    for (uint32_t j = 0; j < agents_.size(); ++j)
        if (agents_[j].motion) flying.push_back(j);
    for (size_t i = 0; i < agents_.size(); ++i) {
        Agent& a = agents_[i];
        if (!a.at_takeoff || a.motion) continue;
        if (a.wants_path) {
            a.state = AgentState::Waiting;  // its new path may not take this link: it waits for it
            continue;
        }
        const PathPoint& point = a.path[a.next];
        Link link;
        bool usable = false;
        try {
            const auto [navmesh, stored] = s.navmeshes.link(point.link);
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
            usable = (motion.from() - point.position).norm() < kSameEnd &&
                     (motion.to() - a.path[a.next + 1].position).norm() < kSameEnd;
        // A cross link whose landing navmesh was removed meanwhile leads nowhere, nor a link parked
        // with an end on a tile not loaded: plan again.
        if (usable && link.crosses() && !s.graph_of(link.landing_navmesh)) usable = false;
        if (usable && (link.start_polygon == kNoPolygon || link.end_polygon == kNoPolygon)) usable = false;
        if (!usable) {
            a.at_takeoff = false;
            a.link = Handle{};
            a.state = AgentState::Waiting;
            a.ask_path(AgentReason::LinkGone, next_path_order_);
            a.emit(AgentEventKind::Replanned, AgentReason::LinkGone, point.link);
            continue;
        }
        if (usable && link.crosses()) {
            if (!s.table.holds(a.def.navmesh, link)) {
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
            if (!take_off_across(a, link, point.link, body, s.table, s.level)) {
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
            const Agent& b = agents_[flying[k]];
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
        a.position = motion.from();  // it stopped within kStopReach of it: in the air it is on the curve
        a.velocity = Vec3::Zero();
        a.motion_time = 0.0f;
        a.link = point.link;
        a.landing_polygon = point.reversed ? link.start_polygon : link.end_polygon;
        a.state = state_of(motion.kind());
        a.emit(AgentEventKind::LinkStarted, AgentReason::None, point.link);
        flying.push_back(static_cast<uint32_t>(i));
    }
}

bool Agents::take_off_across(Agent& a, const Link& link, Handle id, const BodyMotion& body, const StepNavMeshes& table,
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
                           (from.pose.carrier_point(to.pose.world_point(link.end)) - link.placed_end).norm() < kSameEnd;
    if (!flight_is_clear(motion, a.def.capabilities.radius, a.def.height, level,
                         motions_.motions(level.movable_meshes()), as_proven))
        return false;
    a.velocity = Vec3::Zero();
    a.frame.reset();  // in the air over no surface: world space until it lands
    a.at_takeoff = false;
    a.motion = motion;
    a.position = motion.from();
    a.motion_time = 0.0f;
    a.link = id;
    a.landing_navmesh = link.landing_navmesh;
    a.landing_polygon = link.end_polygon;
    a.state = state_of(a.motion->kind());
    a.emit(AgentEventKind::LinkStarted, AgentReason::None, id);
    return true;
}

void Agents::land_across(Agent& a, Handle navmesh, const std::shared_ptr<const PathGraph>& graph,
                         const StepNavMeshes& table) {
    a.landing_navmesh = Handle{};
    if (!graph) {
        a.fail(AgentReason::NavMeshRemoved);
        return;
    }
    const CarrierPose pose = table.find(navmesh)->pose;
    const Vec3 feet = pose.carrier_point(a.position);
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
    a.stands_on = graph->navmesh_ptr();
    a.path.clear();
    a.graph.reset();
    a.next = 0;
    if (a.has_destination) {
        a.state = AgentState::Waiting;
        a.ask_path(AgentReason::None, next_path_order_);
    }
}

}  // namespace nl
