// Navmeshes that ride movable meshes (moving surfaces): they follow the mesh's transform with no new
// snapshot, answer in the world where the mesh is now, keep their links and agents in the mesh's own
// space (no drift, however long the mesh turns), and destinations set on them stick to them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <memory>
#include <vector>

#include "core_errors.h"
#include "core_world.h"
#include "generated_mesh.h"
#include "level_generator.h"
#include "links/link_placement.h"
#include "path/path_planner.h"
#include "world/world.h"

namespace {

using nl::AgentState;
using nl::Handle;
using nl::Transform;
using nl::Vec3;

// Where the platform is at time t: turning about its centre at `spin` rad/s and carried along x at
// `drift` m/s, from (20, 5, 0). Each pose is computed from t, never accumulated.
Transform platform_pose(double t, double spin = 0.5, double drift = 0.0) {
    Transform pose = Transform::Identity();
    pose.translate(Vec3(float(20.0 + drift * t), 5.0f, 0.0f));
    pose.rotate(Eigen::AngleAxisf(float(std::fmod(spin * t, 2.0 * M_PI)), Vec3::UnitY()));
    return pose;
}

// An 8 x 8 m platform 0.5 m thick, its top at y = 0 in its own space, movable, with a navmesh of one
// square on its top (given in the platform's space) for bodies of radius 0.3.
struct Platform {
    std::unique_ptr<nl::World> world;
    Handle mesh, navmesh;

    explicit Platform(const Transform& pose = platform_pose(0.0), int workers = 1) {
        nl::WorldSettings settings;
        settings.worker_count = workers;
        world = std::make_unique<nl::World>(std::move(settings));
        nl::levelgen::GeneratedLevel level;
        level.add_box({{-4, -0.5f, -4}, {4, 0, 4}});
        mesh = world->level().add_mesh(nl::test::to_triangle_mesh(level), pose, nl::kMeshMovable, 0);
        nl::NavMeshInput in;
        const float e = 3.7f;
        in.vertices = {{-e, 0, -e}, {-e, 0, e}, {e, 0, e}, {e, 0, -e}};
        in.indices = {0, 1, 2, 3};
        in.polygon_sizes = {4};
        in.agent_type.radius = 0.3f;
        navmesh = world->add_navmesh(in, mesh);
    }

    Handle add_agent(const Vec3& world_position) {
        nl::AgentDef def;
        def.navmesh = navmesh;
        def.position = world_position;
        def.capabilities.radius = 0.3f;
        return world->agents().add(world->navmeshes(), def);
    }
};

float distance(const Vec3& a, const Vec3& b) { return (a - b).norm(); }

// `fn` throws an nl::Error with `code` whose message contains `needle`.
void check_refused(const std::function<void()>& fn, nl::ErrorCode code, const char* needle) {
    std::string message;
    CHECK(nl::test::code_of(fn, &message) == code);
    CHECK_MESSAGE(message.find(needle) != std::string::npos, message);
}

}  // namespace

TEST_CASE("a navmesh on a movable mesh follows its transform: no rebuild, no new snapshot, answers in the world") {
    Platform p;
    const std::shared_ptr<const nl::PathGraph> before = p.world->navmeshes().path_graph(p.navmesh);
    const std::shared_ptr<const nl::NavMesh> polygons = p.world->navmeshes().navmesh(p.navmesh);
    const Transform moved = platform_pose(2.0);  // turned by 1 rad
    p.world->set_mesh_transform(p.mesh, moved);
    CHECK(p.world->navmeshes().path_graph(p.navmesh) == before);
    CHECK(p.world->navmeshes().navmesh(p.navmesh) == polygons);
    CHECK(p.world->level().info(p.mesh).transform.isApprox(moved));

    // A path between two points of the platform, asked in the world where it is now.
    const Vec3 from_local(-2, 0, -2), to_local(2, 0, 1);
    nl::PathQuery q;
    q.start = moved * from_local;
    q.goal = moved * to_local;
    q.capabilities.radius = 0.3f;
    nl::PathResult r;
    nl::plan_path(*before, q, nullptr, r);
    REQUIRE(r.outcome == nl::PathOutcome::Complete);
    REQUIRE(r.points.size() == 2);
    CHECK(distance(r.points.front().position, q.start) < 1e-4f);
    CHECK(distance(r.points.back().position, q.goal) < 1e-4f);
    CHECK(distance(r.points.front().carrier_position, from_local) < 1e-4f);
    CHECK(distance(r.points.back().carrier_position, to_local) < 1e-4f);
    CHECK(distance(r.start, q.start) < 1e-4f);

    // Where the platform's corner was, there is no navmesh now (it turned 1 rad away).
    q.start = platform_pose(0.0) * Vec3(3.5f, 0, 3.5f);
    q.search_half_extents = Vec3(0.2f, 1.0f, 0.2f);
    nl::plan_path(*before, q, nullptr, r);
    CHECK(r.outcome == nl::PathOutcome::StartOffNavMesh);
}

TEST_CASE("a mesh that carries a navmesh takes rigid transforms only, and is not removed from under it") {
    Platform p;
    const Transform placed = p.world->level().info(p.mesh).transform;
    Transform scaled = placed;
    scaled.scale(2.0f);
    check_refused([&] { p.world->set_mesh_transform(p.mesh, scaled); }, nl::ErrorCode::InvalidArgument,
                  "transform is not a rotation and a translation");
    Transform mirrored = placed;
    mirrored.scale(Vec3(-1, 1, 1));
    check_refused([&] { p.world->set_mesh_transform(p.mesh, mirrored); }, nl::ErrorCode::InvalidArgument,
                  "not a rotation");
    CHECK(p.world->level().info(p.mesh).transform.isApprox(placed));  // nothing moved
    const auto frame = p.world->navmeshes().frame(p.navmesh);
    CHECK(frame->moves() == 0);

    check_refused([&] { p.world->remove_mesh(p.mesh); }, nl::ErrorCode::InvalidArgument, "remove the navmesh first");
    CHECK(p.world->level().contains(p.mesh));
    p.world->navmeshes().remove(p.navmesh);
    p.world->remove_mesh(p.mesh);
    CHECK_FALSE(p.world->level().contains(p.mesh));
}

TEST_CASE("a navmesh is placed only on a movable mesh with a rigid transform") {
    Platform p;
    nl::levelgen::GeneratedLevel ground;
    ground.add_box({{-10, -1, -10}, {10, 0, 10}});
    const Handle fixed = p.world->level().add_mesh(nl::test::to_triangle_mesh(ground), Transform::Identity(), 0, 0);
    Transform stretched = Transform::Identity();
    stretched.scale(Vec3(1, 1, 3));
    const Handle squashed =
        p.world->level().add_mesh(nl::test::to_triangle_mesh(ground), stretched, nl::kMeshMovable, 0);
    nl::NavMeshInput in;
    in.vertices = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}};
    in.indices = {0, 1, 2, 3};
    in.polygon_sizes = {4};
    const size_t before = p.world->navmeshes().handles().size();
    check_refused([&] { p.world->add_navmesh(in, fixed); }, nl::ErrorCode::InvalidArgument,
                  "carrier is not a movable mesh");
    check_refused([&] { p.world->add_navmesh(in, squashed); }, nl::ErrorCode::InvalidArgument,
                  "carrier's transform is not a rotation");
    check_refused([&] { p.world->add_navmesh(in, Handle{7, 3}); }, nl::ErrorCode::InvalidHandle, "carrier");
    CHECK(p.world->navmeshes().handles().size() == before);
    // A second navmesh on the same mesh shares its frame: one move places both.
    const Handle second = p.world->add_navmesh(in, p.mesh);
    CHECK(p.world->navmeshes().frame(second) == p.world->navmeshes().frame(p.navmesh));
}

TEST_CASE("links on a moving navmesh are kept in its space and read in the world where it is now") {
    Platform p;
    const Transform pose = platform_pose(1.0);
    p.world->set_mesh_transform(p.mesh, pose);
    nl::Link link;
    link.kind = nl::LinkKind::Manual;
    link.start = pose * Vec3(-3, 0, 0);
    link.end = pose * Vec3(3, 0, 0);
    nl::set_requirements_from_ends(link);
    const Handle id = p.world->add_link(p.navmesh, link);
    CHECK(distance(p.world->navmeshes().link(id).second.start, Vec3(-3, 0, 0)) < 1e-4f);  // stored on the surface
    const Transform later = platform_pose(3.0, 0.5, 2.0);
    p.world->set_mesh_transform(p.mesh, later);
    const nl::Link seen = p.world->link_in_world(id).second;
    CHECK(distance(seen.start, later * Vec3(-3, 0, 0)) < 1e-4f);
    CHECK(distance(seen.end, later * Vec3(3, 0, 0)) < 1e-4f);
    // The generator proves links against the level as it stands: on a moving surface they would hold
    // at one placement only, so it refuses rather than promise that.
    check_refused(
        [&] { p.world->generate_links(p.navmesh, nl::LinkSettings{}, {}, [](float, const char*) { return true; }); },
        nl::ErrorCode::InvalidArgument, "rides a moving mesh");
}

TEST_CASE("an idle agent on a turning platform stays where it stood on it: within 1 mm after 10,000 steps") {
    Platform p;
    const Handle agent = p.add_agent(platform_pose(0.0) * Vec3(2.5f, 0, 1.5f));
    const Vec3 stood = platform_pose(0.0).inverse() * p.world->agents().info(agent).position;
    const double dt = 1.0 / 60.0;
    float worst = 0.0f;
    for (int k = 1; k <= 10000; ++k) {
        const Transform pose = platform_pose(k * dt, 0.7, 0.3);
        p.world->set_mesh_transform(p.mesh, pose);
        p.world->step(float(dt));
        worst = std::max(worst, distance(p.world->agents().info(agent).position, pose * stood));
    }
    MESSAGE("worst distance from where it stood on the platform: " << worst * 1000.0f << " mm");
    CHECK(worst < 0.001f);
    CHECK(p.world->agents().info(agent).state == AgentState::Idle);
}

TEST_CASE("a destination set on a moving surface sticks to it: the agent arrives where it is at arrival") {
    Platform p;
    const Handle agent = p.add_agent(platform_pose(0.0) * Vec3(-3, 0, -3));
    const Vec3 target_local(3, 0, 3);
    // Set at t = 0 where the target is then; the platform turns and travels on meanwhile.
    p.world->agents().set_destination(p.world->navmeshes(), agent, platform_pose(0.0, 0.4, 1.5) * target_local);
    const double dt = 1.0 / 30.0;
    double t = 0.0;
    nl::AgentInfo info;
    for (int k = 0; k < 600; ++k) {
        t += dt;
        p.world->set_mesh_transform(p.mesh, platform_pose(t, 0.4, 1.5));
        p.world->step(float(dt));
        info = p.world->agents().info(agent);
        const Vec3 target_now = platform_pose(t, 0.4, 1.5) * target_local;
        REQUIRE(distance(info.destination, target_now) < 1e-3f);
        if (info.state == AgentState::Arrived) break;
    }
    REQUIRE(info.state == AgentState::Arrived);
    const Vec3 target_now = platform_pose(t, 0.4, 1.5) * target_local;
    MESSAGE("arrived after " << t << " s, " << distance(info.position, target_now) * 100.0f
                             << " cm from the destination "
                             << "(which travelled " << distance(target_now, platform_pose(0.0, 0.4, 1.5) * target_local)
                             << " m meanwhile)");
    CHECK(distance(info.position, target_now) < 0.05f);
    CHECK(distance(target_now, platform_pose(0.0, 0.4, 1.5) * target_local) > 5.0f);
}

TEST_CASE("bodies on a moving surface avoid each other there, and not bodies on the ground below it") {
    Platform p;
    nl::levelgen::GeneratedLevel ground;
    ground.add_box({{10, -2, -10}, {30, -1, 10}});
    p.world->level().add_mesh(nl::test::to_triangle_mesh(ground), Transform::Identity(), 0, 0);
    nl::NavMeshInput in;
    in.vertices = {{10.3f, -1, -9.7f}, {10.3f, -1, 9.7f}, {29.7f, -1, 9.7f}, {29.7f, -1, -9.7f}};
    in.indices = {0, 1, 2, 3};
    in.polygon_sizes = {4};
    in.agent_type.radius = 0.3f;
    const Handle floor = p.world->add_navmesh(in);
    // Two on the platform heading through each other, one on the ground right under one of them.
    const Transform pose = platform_pose(0.0);
    const Handle a = p.add_agent(pose * Vec3(-3, 0, 0));
    const Handle b = p.add_agent(pose * Vec3(3, 0, 0));
    nl::AgentDef def;
    def.navmesh = floor;
    def.position = pose * Vec3(-3, 0, 0) + Vec3(0, -6, 0);
    def.capabilities.radius = 0.3f;
    const Handle below = p.world->agents().add(p.world->navmeshes(), def);
    p.world->agents().set_destination(p.world->navmeshes(), a, pose * Vec3(3, 0, 0));
    p.world->agents().set_destination(p.world->navmeshes(), b, pose * Vec3(-3, 0, 0));
    float closest = 1e9f;
    for (int k = 0; k < 300; ++k) {
        p.world->step(1.0f / 30.0f);
        const Vec3 pa = p.world->agents().info(a).position, pb = p.world->agents().info(b).position;
        closest = std::min(closest, std::hypot(pa.x() - pb.x(), pa.z() - pb.z()));
    }
    CHECK(closest > 0.5f);  // two radii of 0.3 with a little give
    CHECK(p.world->agents().info(a).state == AgentState::Arrived);
    CHECK(p.world->agents().info(b).state == AgentState::Arrived);
    // The one below never moved: a body 6 m above on another surface is not in its way.
    CHECK(distance(p.world->agents().info(below).position, def.position + Vec3(0, 0, 0)) < 1.01f);
    CHECK(p.world->agents().info(below).velocity.norm() == 0.0f);
}

namespace {

// Two 6 x 6 m ledges (tops at y = 0) across a 10 m chasm, x in [0, 6] and [16, 22], one static
// navmesh over both; a 4 x 4 m shuttle (movable, its top at y = 0 in its own space, a navmesh on it)
// that docks at one ledge, crosses, docks at the other and comes back, on a timetable. A link from
// the near ledge onto the shuttle docked there, and one from the shuttle docked at the far ledge onto
// it, each placed while the shuttle stood there: they hold only while it does.
struct Ferry {
    std::unique_ptr<nl::World> world;
    Handle ground, shuttle, ledges, deck, board, leave;

    static constexpr float kNearDock = 8.0f, kFarDock = 14.0f;  // the shuttle's centre, docked flush
    float near_dock = kNearDock, far_dock = kFarDock;
    // Docked 3 s, 4 s across, docked 3 s, 4 s back.
    float shuttle_x(double t) const {
        const double u = std::fmod(t, 14.0);
        if (u < 3.0) return near_dock;
        if (u < 7.0) return float(near_dock + (far_dock - near_dock) * (u - 3.0) / 4.0);
        if (u < 10.0) return far_dock;
        return float(far_dock - (far_dock - near_dock) * (u - 10.0) / 4.0);
    }
    static Transform at(float x) {
        Transform t = Transform::Identity();
        t.translate(Vec3(x, 0, 3));
        return t;
    }

    // `gangways`: the two host links; without them, the docks may stand off the ledges (`near`, `far`)
    // so that the generator finds jumps across the gaps.
    explicit Ferry(bool gangways = true, float near = kNearDock, float far = kFarDock, int workers = 1)
        : near_dock(near), far_dock(far) {
        nl::WorldSettings settings;
        settings.worker_count = workers;
        world = std::make_unique<nl::World>(std::move(settings));
        nl::levelgen::GeneratedLevel level, box;
        level.add_box({{0, -1, 0}, {6, 0, 6}});
        level.add_box({{16, -1, 0}, {22, 0, 6}});
        ground = world->level().add_mesh(nl::test::to_triangle_mesh(level), Transform::Identity(), 0, 0);
        box.add_box({{-2, -0.5f, -2}, {2, 0, 2}});
        shuttle = world->level().add_mesh(nl::test::to_triangle_mesh(box), at(kFarDock), nl::kMeshMovable, 0);
        nl::NavMeshInput both;
        both.vertices = {{0.3f, 0, 0.3f},  {0.3f, 0, 5.7f},  {5.7f, 0, 5.7f},  {5.7f, 0, 0.3f},
                         {16.3f, 0, 0.3f}, {16.3f, 0, 5.7f}, {21.7f, 0, 5.7f}, {21.7f, 0, 0.3f}};
        both.indices = {0, 1, 2, 3, 4, 5, 6, 7};
        both.polygon_sizes = {4, 4};
        both.agent_type.radius = 0.3f;
        ledges = world->add_navmesh(both);
        nl::NavMeshInput top;
        top.vertices = {{-1.7f, 0, -1.7f}, {-1.7f, 0, 1.7f}, {1.7f, 0, 1.7f}, {1.7f, 0, -1.7f}};
        top.indices = {0, 1, 2, 3};
        top.polygon_sizes = {4};
        top.agent_type.radius = 0.3f;
        deck = world->add_navmesh(top, shuttle);
        if (gangways)
            leave = add_cross(deck, Vec3(15.4f, 0, 3), ledges, Vec3(16.6f, 0, 3));  // placed docked at the far ledge
        world->set_mesh_transform(shuttle, at(near_dock));
        if (gangways) board = add_cross(ledges, Vec3(5.6f, 0, 3), deck, Vec3(6.6f, 0, 3));
    }

    Handle add_cross(Handle from, const Vec3& start, Handle to, const Vec3& end) {
        nl::Link link;
        link.kind = nl::LinkKind::Manual;
        link.start = start;
        link.end = end;
        link.landing_navmesh = to;
        link.tolerance = nl::kDefaultCrossTolerance;
        nl::set_requirements_from_ends(link);
        link.requirements.gap = 0.0f;  // a gangway: walked, not jumped
        return world->add_link(from, link);
    }
};

}  // namespace

TEST_CASE(
    "a ferry carries every agent across the chasm: they wait at the take-off, ride, and get off on the far side") {
    Ferry f;
    const Vec3 goal(20, 0, 3);
    std::vector<Handle> agents;
    for (float z : {1.5f, 3.0f, 4.5f}) {
        nl::AgentDef def;
        def.navmesh = f.ledges;
        def.position = Vec3(2, 0, z);
        def.capabilities.radius = 0.3f;
        agents.push_back(f.world->agents().add(f.world->navmeshes(), def));
        f.world->agents().set_destination(f.world->navmeshes(), agents.back(), goal);
    }
    const double dt = 1.0 / 30.0;
    std::vector<int> boarded(agents.size(), 0), left(agents.size(), 0);
    int waited = 0, arrived = 0, inside = 0;
    double t = 4.0;  // the shuttle has just left: the first to reach the dock waits for it
    for (int k = 0; k < 90 * 30 && arrived < int(agents.size()); ++k) {
        t += dt;
        f.world->set_mesh_transform(f.shuttle, Ferry::at(f.shuttle_x(t)));
        f.world->step(float(dt));
        for (const nl::AgentEvent& e : f.world->agents().events()) {
            const size_t i = size_t(std::find(agents.begin(), agents.end(), e.agent) - agents.begin());
            if (e.kind == nl::AgentEventKind::LinkStarted) (e.link == f.board ? boarded : left)[i] += 1;
            if (e.kind == nl::AgentEventKind::Arrived) ++arrived;
            CHECK_MESSAGE(e.kind != nl::AgentEventKind::Failed, "agent ", i, " failed, reason ", int(e.reason));
        }
        // No body inside the level: a segment up its middle from just above its feet meets nothing.
        std::vector<nl::Segment> bodies;
        for (Handle a : agents) {
            const nl::AgentInfo info = f.world->agents().info(a);
            waited += info.state == AgentState::Waiting && info.link == f.board;
            bodies.push_back({info.position + Vec3(0, 0.05f, 0), info.position + Vec3(0, 1.8f, 0)});
        }
        std::vector<uint8_t> blocked(bodies.size());
        f.world->level().segments_blocked(bodies.data(), uint32_t(bodies.size()), blocked.data());
        for (uint8_t b : blocked) inside += b;
    }
    MESSAGE("arrived " << arrived << " of " << agents.size() << " by t = " << t
                       << " s; steps spent waiting at the dock: " << waited);
    CHECK(arrived == int(agents.size()));
    CHECK(waited > 0);  // the ferry was away when the first came: they waited for it
    CHECK(inside == 0);
    for (size_t i = 0; i < agents.size(); ++i) {
        CHECK(boarded[i] >= 1);
        CHECK(left[i] >= 1);
        const nl::AgentInfo info = f.world->agents().info(agents[i]);
        CHECK(info.state == AgentState::Arrived);
        CHECK(distance(info.position, goal) < 1.5f);  // three bodies share the goal: they stand round it
    }
}

TEST_CASE(
    "a jump onto a moving surface aims where the landing will be: the body lands on the link's end on the surface") {
    Ferry f;
    // The shuttle slides along the near ledge's edge (z) at 1.5 m/s while a jumper jumps on from 1.5 m
    // away; the link tolerates the slide, so it holds while the shuttle passes.
    nl::Link jump;
    jump.kind = nl::LinkKind::Jump;
    jump.start = Vec3(5.6f, 0, 3);
    jump.end = Vec3(7.6f, 0, 3);  // on the shuttle docked at the near ledge, 0.4 m from its centre
    jump.landing_navmesh = f.deck;
    jump.tolerance = 5.0f;
    nl::set_requirements_from_ends(jump);
    const Handle link = f.world->add_link(f.ledges, jump);
    const Vec3 end_on_deck = f.world->navmeshes().link(link).second.end;
    nl::AgentDef def;
    def.navmesh = f.ledges;
    def.position = Vec3(4.5f, 0, 3);
    def.capabilities.radius = 0.3f;
    def.capabilities.max_jump_distance = 3.0f;
    def.capabilities.max_jump_height = 1.0f;
    const Handle jumper = f.world->agents().add(f.world->navmeshes(), def);
    f.world->agents().set_destination(f.world->navmeshes(), jumper, Ferry::at(Ferry::kNearDock) * Vec3(1, 0, 1));
    const double dt = 1.0 / 60.0, speed = 1.5;
    auto pose = [&](double t) {
        Transform p = Ferry::at(Ferry::kNearDock);
        p.pretranslate(Vec3(0, 0, float(speed * t - 1.0)));  // passes the take-off about 0.7 s in
        return p;
    };
    bool landed = false;
    for (int k = 1; k < 240 && !landed; ++k) {
        f.world->set_mesh_transform(f.shuttle, pose(k * dt));
        f.world->step(float(dt));
        for (const nl::AgentEvent& e : f.world->agents().events()) {
            if (e.kind != nl::AgentEventKind::LinkFinished) continue;
            landed = true;
            const Vec3 where = f.world->agents().info(jumper).position;
            const Vec3 meant = pose(k * dt) * end_on_deck;
            MESSAGE("landed " << distance(where, meant) * 100.0f << " cm from the link's end on the moving shuttle");
            CHECK(distance(where, meant) < 0.1f);
        }
        CHECK(f.world->agents().info(jumper).state != AgentState::Failed);
    }
    CHECK(landed);
}

TEST_CASE(
    "links between a ledge and a platform are generated for where the platform stands, kept per stop, and ferry "
    "jumpers") {
    // The shuttle docks 1 m off each ledge: a gap a jumper crosses, and the generator proves.
    Ferry f(false, 9.0f, 13.0f);
    nl::LinkSettings settings;
    settings.max_jump_gap = 2.0f;
    auto cross_count = [&](Handle from, Handle to) {
        size_t n = 0;
        const auto links = f.world->navmeshes().links(from);
        for (const nl::StoredLink& s : *links) n += s.link.crosses() && s.link.landing_navmesh == to;
        return n;
    };
    auto holding = [&](Handle from) {
        size_t n = 0;
        const auto links = f.world->navmeshes().links(from);
        for (const nl::StoredLink& s : *links) n += s.link.crosses() && f.world->link_holds(from, s.link);
        return n;
    };
    const nl::LinkGenerationReport near =
        f.world->generate_cross_links(f.ledges, f.deck, settings, 0.25f, nl::test::keep_going);
    const size_t on_near = cross_count(f.ledges, f.deck), off_near = cross_count(f.deck, f.ledges);
    MESSAGE("docked at the near ledge: " << on_near << " links onto the shuttle, " << off_near << " off it ("
                                         << near.jump_links << " jumps, " << near.drop_links << " drops)");
    CHECK(on_near > 0);
    CHECK(off_near > 0);
    CHECK(holding(f.ledges) == on_near);
    const auto ledge_links = f.world->navmeshes().links(f.ledges);
    for (const nl::StoredLink& s : *ledge_links) {
        // Every one from the near ledge's edge to the shuttle's near edge, across the 1 m gap.
        const nl::Link w = f.world->in_world(f.ledges, s.link);
        CHECK(w.start.x() == doctest::Approx(6.0f).epsilon(0.1));
        CHECK(w.end.x() == doctest::Approx(7.0f).epsilon(0.1));
        CHECK(s.link.generated);
    }
    // Again at the same stop: replaced, not doubled.
    f.world->generate_cross_links(f.ledges, f.deck, settings, 0.25f, nl::test::keep_going);
    CHECK(cross_count(f.ledges, f.deck) == on_near);
    // Out in the chasm (3 m from either ledge, beyond a 2 m jump): nothing holds, nothing is found,
    // and the near stop's links stay for when it is back.
    f.world->set_mesh_transform(f.shuttle, Ferry::at(11.0f));
    CHECK(holding(f.ledges) == 0);
    f.world->generate_cross_links(f.ledges, f.deck, settings, 0.25f, nl::test::keep_going);
    CHECK(cross_count(f.ledges, f.deck) == on_near);
    CHECK(cross_count(f.deck, f.ledges) == off_near);
    // At the far stop: links of its own, beside the near stop's.
    f.world->set_mesh_transform(f.shuttle, Ferry::at(13.0f));
    f.world->generate_cross_links(f.ledges, f.deck, settings, 0.25f, nl::test::keep_going);
    CHECK(cross_count(f.deck, f.ledges) > off_near);
    // The ledge's own generation keeps the cross links.
    f.world->generate_links(f.ledges, settings, {}, nl::test::keep_going);
    CHECK(cross_count(f.deck, f.ledges) > off_near);
    CHECK(cross_count(f.ledges, f.deck) >= on_near);

    // Jumpers ride the generated links across.
    const Vec3 goal(20, 0, 3);
    std::vector<Handle> agents;
    for (float z : {2.0f, 4.0f}) {
        nl::AgentDef def;
        def.navmesh = f.ledges;
        def.position = Vec3(2, 0, z);
        def.capabilities.radius = 0.3f;
        def.capabilities.max_jump_distance = 2.0f;
        def.capabilities.max_jump_height = 1.0f;
        def.capabilities.max_drop_height = 1.0f;
        agents.push_back(f.world->agents().add(f.world->navmeshes(), def));
        f.world->agents().set_destination(f.world->navmeshes(), agents.back(), goal);
    }
    const double dt = 1.0 / 30.0;
    int arrived = 0, inside = 0;
    double t = 4.0;
    for (int k = 0; k < 90 * 30 && arrived < int(agents.size()); ++k) {
        t += dt;
        f.world->set_mesh_transform(f.shuttle, Ferry::at(f.shuttle_x(t)));
        f.world->step(float(dt));
        for (const nl::AgentEvent& e : f.world->agents().events()) {
            arrived += e.kind == nl::AgentEventKind::Arrived;
            CHECK_MESSAGE(e.kind != nl::AgentEventKind::Failed, "failed, reason ", int(e.reason));
        }
        std::vector<nl::Segment> bodies;
        for (Handle a : agents) {
            const Vec3 p = f.world->agents().info(a).position;
            bodies.push_back({p + Vec3(0, 0.05f, 0), p + Vec3(0, 1.8f, 0)});
        }
        std::vector<uint8_t> blocked(bodies.size());
        f.world->level().segments_blocked(bodies.data(), uint32_t(bodies.size()), blocked.data());
        for (uint8_t b : blocked) inside += b;
    }
    MESSAGE("jumpers arrived: " << arrived << " of " << agents.size() << " by t = " << t << " s");
    CHECK(arrived == int(agents.size()));
    CHECK(inside == 0);
}

TEST_CASE("an agent put on a platform stands on the platform's navmesh: found by a ray down") {
    Ferry f;
    nl::AgentDef def;
    def.navmesh = f.ledges;  // the host names the ground's navmesh for this body
    def.capabilities.radius = 0.3f;
    def.position = Vec3(8.5f, 0.0f, 3.5f);  // on the shuttle, docked at the near ledge
    const Handle rider = f.world->add_agent(def);
    CHECK(f.world->agents().info(rider).navmesh == f.deck);
    CHECK(f.world->agents().info(rider).carrier == f.shuttle);
    def.position = Vec3(2.0f, 0.0f, 3.0f);  // on the ledge
    CHECK(f.world->agents().info(f.world->add_agent(def)).navmesh == f.ledges);
    // A body the platform's navmesh was not made for stays on the navmesh it was given.
    nl::NavMeshInput wide;
    wide.vertices = {{0.6f, 0, 0.6f}, {0.6f, 0, 5.4f}, {5.4f, 0, 5.4f}, {5.4f, 0, 0.6f}};
    wide.indices = {0, 1, 2, 3};
    wide.polygon_sizes = {4};
    wide.agent_type.radius = 0.6f;
    def.navmesh = f.world->add_navmesh(wide);
    def.position = Vec3(8.5f, 0.0f, 3.5f);
    def.capabilities.radius = 0.6f;
    check_refused([&] { f.world->add_agent(def); }, nl::ErrorCode::NotFound, "position is not on the navmesh");
    // The shuttle carries the rider away.
    f.world->set_mesh_transform(f.shuttle, Ferry::at(11.0f));
    f.world->step(1.0f / 30.0f);
    CHECK(f.world->agents().info(rider).position.x() == doctest::Approx(11.5f).epsilon(0.01));
}

TEST_CASE("removing the platform's navmesh removes the cross links onto it; an agent waiting for it plans again") {
    Ferry f;
    nl::AgentDef def;
    def.navmesh = f.ledges;
    def.capabilities.radius = 0.3f;
    def.position = Vec3(2, 0, 3);
    const Handle agent = f.world->add_agent(def);
    f.world->set_mesh_transform(f.shuttle, Ferry::at(11.0f));  // away: the agent will wait at the dock
    f.world->agents().set_destination(f.world->navmeshes(), agent, Vec3(20, 0, 3));
    for (int k = 0; k < 90 && f.world->agents().info(agent).link != f.board; ++k) f.world->step(1.0f / 30.0f);
    REQUIRE(f.world->agents().info(agent).state == AgentState::Waiting);
    REQUIRE(f.world->agents().info(agent).link == f.board);
    f.world->navmeshes().remove(f.deck);
    CHECK_FALSE(f.world->navmeshes().contains_link(f.board));
    const auto ledge_links = f.world->navmeshes().links(f.ledges);
    for (const nl::StoredLink& s : *ledge_links) CHECK_FALSE(s.link.crosses());
    f.world->step(1.0f / 30.0f);
    f.world->step(1.0f / 30.0f);
    // No way across any more: it went as near as it could and failed, saying why.
    for (int k = 0; k < 60 && f.world->agents().info(agent).state != AgentState::Failed; ++k)
        f.world->step(1.0f / 30.0f);
    CHECK(f.world->agents().info(agent).state == AgentState::Failed);
    CHECK(f.world->agents().info(agent).reason == nl::AgentReason::NoPath);
    f.world->remove_mesh(f.shuttle);  // nothing rides it now
}

TEST_CASE(
    "a body that comes down on another platform than the one it aimed at lands on that platform: found by a ray down") {
    Ferry f;
    // A second shuttle, out of the way, with a navmesh for the same body.
    nl::levelgen::GeneratedLevel box;
    box.add_box({{-2, -0.5f, -2}, {2, 0, 2}});
    const Handle spare =
        f.world->level().add_mesh(nl::test::to_triangle_mesh(box), Ferry::at(30.0f), nl::kMeshMovable, 0);
    nl::NavMeshInput top;
    top.vertices = {{-1.7f, 0, -1.7f}, {-1.7f, 0, 1.7f}, {1.7f, 0, 1.7f}, {1.7f, 0, -1.7f}};
    top.indices = {0, 1, 2, 3};
    top.polygon_sizes = {4};
    top.agent_type.radius = 0.3f;
    const Handle spare_deck = f.world->add_navmesh(top, spare);
    nl::AgentDef def;
    def.navmesh = f.ledges;
    def.capabilities.radius = 0.3f;
    def.position = Vec3(5.0f, 0, 3);
    const Handle walker = f.world->add_agent(def);
    f.world->agents().set_destination(f.world->navmeshes(), walker, Ferry::at(Ferry::kNearDock) * Vec3(1, 0, 0));
    bool swapped = false;
    for (int k = 0; k < 120; ++k) {
        f.world->step(1.0f / 60.0f);
        for (const nl::AgentEvent& e : f.world->agents().events()) {
            if (e.kind != nl::AgentEventKind::LinkStarted || swapped) continue;
            // In the air on the gangway: the shuttle leaves and the spare one takes its place.
            f.world->set_mesh_transform(f.shuttle, Ferry::at(11.0f));
            f.world->set_mesh_transform(spare, Ferry::at(Ferry::kNearDock));
            swapped = true;
        }
    }
    REQUIRE(swapped);
    const nl::AgentInfo info = f.world->agents().info(walker);
    CHECK(info.navmesh == spare_deck);
    CHECK(info.carrier == spare);
    // Its destination is on the shuttle it aimed at, which no link joins to the spare one: it says so.
    CHECK(info.state == AgentState::Failed);
    CHECK(info.reason == nl::AgentReason::NoPath);
}

namespace {

// A jumper at the take-off of a jump onto the shuttle, which comes along +z at 1.5 m/s from 3 m back
// and stops after 2 s where the jump was placed; each step the jumper aims where the shuttle will be
// when it lands (behind the placed end, on the -z side, while the shuttle comes). `furnish` adds to
// the level once (with no pose) and follows the shuttle's pose each step.
struct ApproachRun {
    double took_off = -1.0;
    int inside = 0;  // steps in which the jumper's body met the level
    bool on_deck = false;
};

ApproachRun jump_onto_approaching_shuttle(const std::function<void(Ferry&, const Transform*)>& furnish) {
    Ferry f;
    furnish(f, nullptr);
    nl::Link jump;
    jump.kind = nl::LinkKind::Jump;
    jump.start = Vec3(5.6f, 0, 3);
    jump.end = Vec3(7.6f, 0, 3);
    jump.landing_navmesh = f.deck;
    jump.tolerance = 5.0f;
    nl::set_requirements_from_ends(jump);
    const Handle link = f.world->add_link(f.ledges, jump);
    nl::AgentDef def;
    def.navmesh = f.ledges;
    def.position = Vec3(5.5f, 0, 3);
    def.capabilities.radius = 0.3f;
    def.capabilities.max_jump_distance = 3.0f;
    def.capabilities.max_jump_height = 1.0f;
    const Handle jumper = f.world->add_agent(def);
    f.world->agents().set_destination(f.world->navmeshes(), jumper, Ferry::at(Ferry::kNearDock) * Vec3(1, 0, 0));
    const double dt = 1.0 / 60.0, stop = 2.0;
    ApproachRun out;
    for (int k = 1; k < 360; ++k) {
        Transform p = Ferry::at(Ferry::kNearDock);
        p.pretranslate(Vec3(0, 0, float(1.5 * (std::min(k * dt, stop) - stop))));
        f.world->set_mesh_transform(f.shuttle, p);
        furnish(f, &p);
        f.world->step(float(dt));
        for (const nl::AgentEvent& e : f.world->agents().events())
            if (e.kind == nl::AgentEventKind::LinkStarted && e.link == link && out.took_off < 0.0)
                out.took_off = k * dt;
        // The body (0.3 m wide, 0.3 to 1.8 m above its feet) against the level as it is now.
        const Vec3 at = f.world->agents().info(jumper).position;
        nl::BodyStretch body;
        body.body = nl::SweptCylinder{at, at, 0.3f, 0.3f, 1.8f};
        body.bounds = nl::bounds_of(body.body, 0.01f);
        const float radius = 0.3f;
        uint8_t cleared = 0;
        f.world->level().bodies_clear(&body, 1, &radius, 1, &cleared);
        out.inside += cleared == 0;
    }
    out.on_deck = f.world->agents().info(jumper).navmesh == f.deck;
    return out;
}

}  // namespace

TEST_CASE(
    "a jump aimed where a moving surface will be is swept again: it waits while that flight would meet the level") {
    const ApproachRun open = jump_onto_approaching_shuttle([](Ferry&, const Transform*) {});
    const ApproachRun blocked = jump_onto_approaching_shuttle([](Ferry& f, const Transform* pose) {
        if (pose) return;
        // Beside the placed arc (0.45 m off it: clear for a 0.3 m body), in the way of the arcs
        // aimed at the coming shuttle.
        nl::levelgen::GeneratedLevel level;
        level.add_box({{6.45f, -1.0f, 2.25f}, {6.75f, 3.0f, 2.55f}});
        f.world->level().add_mesh(nl::test::to_triangle_mesh(level), Transform::Identity(), 0, 0);
    });
    MESSAGE("took off at " << open.took_off << " s with nothing in the way, at " << blocked.took_off
                           << " s beside the pole");
    CHECK(open.took_off > 0.0);
    CHECK(blocked.took_off > open.took_off + 0.1);  // it waited while its aimed flight met the pole
    CHECK(open.inside == 0);
    CHECK(blocked.inside == 0);
    CHECK(open.on_deck);
    CHECK(blocked.on_deck);
}

TEST_CASE(
    "a jump onto a moving surface is checked against the level as it will be: a post riding the shuttle holds it "
    "back") {
    // A thin post rides on the shuttle (another movable mesh, moved with it). Seen from the shuttle,
    // a jumper taking off early flies across the deck from its far side, through where the post
    // stands; once the shuttle stops, the post is 1.4 m off the arc. Where the post is at take-off,
    // it is off the flight too: only the level as it will be when the body passes tells.
    Handle pole;
    const ApproachRun open = jump_onto_approaching_shuttle([](Ferry&, const Transform*) {});
    const ApproachRun held = jump_onto_approaching_shuttle([&](Ferry& f, const Transform* pose) {
        if (pose) {
            f.world->set_mesh_transform(pole, *pose);
            return;
        }
        nl::levelgen::GeneratedLevel level;
        level.add_box({{-1.45f, 0.0f, 1.35f}, {-1.35f, 3.0f, 1.45f}});  // on the deck, in its space
        pole = f.world->level().add_mesh(nl::test::to_triangle_mesh(level), Ferry::at(Ferry::kNearDock),
                                         nl::kMeshMovable, 0);
    });
    MESSAGE("took off at " << open.took_off << " s with no post, at " << held.took_off
                           << " s with the post riding the shuttle");
    CHECK(held.took_off > open.took_off + 0.1);  // it waited while its flight would have met the post
    CHECK(held.inside == 0);
    CHECK(held.on_deck);
}
