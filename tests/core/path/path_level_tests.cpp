// Paths on procedural levels built from boxes, through the core world: the navmesh by the Recast
// builder, links by the generator, then each agent's path. Each level has one feature an
// agent's body decides about: a gap, a ledge, a narrow corridor.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core_world.h"
#include "path/path_planner.h"
#include "shared_levels.h"

using nl::levelgen::Box;

namespace {

struct LevelWithLinks {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    nl::Handle navmesh;
    std::vector<nl::Link> links;

    explicit LevelWithLinks(const std::vector<Box>& boxes, float agent_radius = 0.6f) {
        nl::levelgen::GeneratedLevel level;
        for (const Box& b : boxes) level.add_box(b);
        nl::test::add_level(*world, level);
        nl::AgentType agent;
        agent.radius = agent_radius;
        navmesh = nl::test::build_recast_navmesh(*world, agent);
        world->generate_links(navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
        for (const nl::StoredLink& l : nl::test::links_of(*world, navmesh)) links.push_back(l.link);
    }

    struct Path {
        nl::PathResult result;
        const std::vector<nl::PathPoint>& points() const { return result.points; }

        uint32_t segments_of(nl::LinkKind kind) const {
            uint32_t n = 0;
            for (size_t i = 0; i + 1 < points().size(); ++i) n += points()[i].segment == uint32_t(kind);
            return n;
        }
        bool passes(float min_x, float max_x, float min_z, float max_z) const {
            for (const nl::PathPoint& p : points())
                if (p.position[0] >= min_x && p.position[0] <= max_x && p.position[2] >= min_z &&
                    p.position[2] <= max_z)
                    return true;
            return false;
        }
        std::string describe() const {
            std::string s = "outcome " + std::to_string(uint32_t(result.outcome)) + ", length " +
                            std::to_string(result.length) + ":";
            for (const nl::PathPoint& p : points())
                s += " (" + std::to_string(p.position[0]) + ", " + std::to_string(p.position[1]) + ", " +
                     std::to_string(p.position[2]) + ")" +
                     (p.segment ? " then link kind " + std::to_string(p.segment) : "");
            return s;
        }
    };

    Path plan(const float* from, const float* to, const nl::AgentCapabilities& agent) const {
        nl::PathQuery query;
        query.start = nl::Vec3(from[0], from[1], from[2]);
        query.goal = nl::Vec3(to[0], to[1], to[2]);
        query.capabilities = agent;
        query.accept_partial = false;
        Path path;
        const auto graph = world->navmeshes().path_graph(navmesh);
        nl::plan_path(*graph, query, nullptr, path.result);
        REQUIRE(path.result.outcome != nl::PathOutcome::Failed);
        return path;
    }
    // The stored link a path point takes.
    nl::Link link(nl::Handle id) const {
        const auto links = world->navmeshes().links(navmesh);
        for (const nl::StoredLink& l : *links)
            if (l.id == id) return l.link;
        FAIL("no link {", id.index1, ", ", id.revision, "}");
        return {};
    }
};

nl::AgentCapabilities walker() { return nl::AgentCapabilities{}; }

// Whether (x, z) of `point` lies over some polygon, seen from above, give or take a centimetre.
// Heights are left out: a straight path segment runs above or below a rolling floor.
bool over_navmesh(const nl::NavMesh& mesh, const float* point) {
    const nl::Vec3 p(point[0], point[1], point[2]);
    for (uint32_t polygon = 0; polygon < mesh.polygon_count(); ++polygon) {
        const nl::Vec3 q = mesh.closest_point_on_polygon(polygon, p);
        if (std::hypot(q.x() - p.x(), q.z() - p.z()) < 0.01f) return true;
    }
    return false;
}

// Bit for bit the same point (what memcmp of two nl_path_points says).
bool same_point(const nl::PathPoint& a, const nl::PathPoint& b) {
    return std::memcmp(a.position.data(), b.position.data(), sizeof(float) * 3) == 0 &&
           std::memcmp(a.apex.data(), b.apex.data(), sizeof(float) * 3) == 0 && a.polygon == b.polygon &&
           a.segment == b.segment && a.link == b.link && a.reversed == b.reversed;
}

nl::AgentCapabilities jumper(float distance, float height, float drop) {
    nl::AgentCapabilities a;
    a.max_jump_distance = distance;
    a.max_jump_height = height;
    a.max_drop_height = drop;
    return a;
}

}  // namespace

TEST_CASE("a runner jumps the gap; a walker, or a jumper too short for it, goes round by the stairs") {
    // Platform A (top 0) and B (top 1.2) 2 m apart over a pit; round the back a bridge at 0 joins A
    // and a flight of stairs up to B.
    std::vector<Box> boxes = {
        {{0, -1, 0}, {10, 0, 10}},        // A
        {{12, 0.2f, 0}, {22, 1.2f, 10}},  // B
        {{0, -1, 20}, {22, 0, 23}},       // the bridge
        {{0, -1, 10}, {3, 0, 20}},        // A to the bridge
        {{-5, -31, -5}, {27, -30, 28}},   // the pit's floor, beyond any drop
    };
    for (int step = 0; step < 4; ++step) {
        const float z1 = 20.0f - 2.5f * step, top = 0.3f * (step + 1);
        boxes.push_back({{19, -1, z1 - 2.5f}, {22, top, z1}});
    }
    LevelWithLinks level(boxes);
    uint32_t jumps = 0;
    for (const nl::Link& l : level.links)
        jumps += l.kind == nl::LinkKind::Jump && l.start[0] < 12.5f && l.end[0] > 9.5f;
    REQUIRE(jumps > 0);

    const float from[3] = {5, 0, 5}, to[3] = {17, 1.2f, 5};
    const auto runner = level.plan(from, to, jumper(3.5f, 1.5f, 2.0f));
    INFO("runner: ", runner.describe());
    REQUIRE(runner.result.outcome == nl::PathOutcome::Complete);
    CHECK(runner.result.links_used == 1);
    CHECK(runner.segments_of(nl::LinkKind::Jump) == 1);
    CHECK(runner.result.length < 16.0f);
    for (size_t i = 0; i < runner.points().size(); ++i) {
        if (runner.points()[i].segment != uint32_t(nl::LinkKind::Jump)) continue;
        const nl::Link link = level.link(runner.points()[i].link);
        CHECK(link.kind == nl::LinkKind::Jump);
        CHECK(runner.points()[i].apex[1] > runner.points()[i + 1].position[1]);  // the arc tops the higher end
    }

    for (const nl::AgentCapabilities& agent : {walker(), jumper(1.0f, 1.5f, 2.0f)}) {
        const auto round = level.plan(from, to, agent);
        INFO("round: ", round.describe());
        REQUIRE(round.result.outcome == nl::PathOutcome::Complete);
        CHECK(round.result.links_used == 0);
        CHECK(round.passes(0, 22, 20, 23));  // over the bridge
        CHECK(round.result.length > 35.0f);
    }
}

TEST_CASE("only an agent that may drop takes the ledge; the others walk down the stairs") {
    // A 3 m tower on open ground, with stairs down its east side.
    std::vector<Box> boxes = {{{-12, -1, -10}, {30, 0, 20}}, {{0, 0, 0}, {10, 3, 10}}};
    for (int step = 0; step < 9; ++step) boxes.push_back({{10.0f + step, 0, 0}, {11.0f + step, 2.7f - 0.3f * step, 3}});
    LevelWithLinks level(boxes);
    uint32_t drops = 0;
    for (const nl::Link& l : level.links) drops += l.kind == nl::LinkKind::Drop;
    REQUIRE(drops > 0);

    const float top[3] = {2, 3, 5}, ground[3] = {-6, 0, 5};
    const auto dropper = level.plan(top, ground, jumper(0.0f, 0.0f, 3.5f));
    INFO("dropper: ", dropper.describe());
    REQUIRE(dropper.result.outcome == nl::PathOutcome::Complete);
    CHECK(dropper.segments_of(nl::LinkKind::Drop) == 1);
    CHECK(dropper.result.length < 12.0f);

    for (const nl::AgentCapabilities& agent : {walker(), jumper(4.0f, 1.5f, 0.0f)}) {
        const auto stairs = level.plan(top, ground, agent);
        INFO("no drop: ", stairs.describe());
        REQUIRE(stairs.result.outcome == nl::PathOutcome::Complete);
        CHECK(stairs.result.links_used == 0);
        CHECK(stairs.passes(10, 19, 0, 3));
        CHECK(stairs.result.length > 20.0f);
    }

    // A body good for 2.5 m may step off the stairs part of the way down, never off the tower.
    const auto partway = level.plan(top, ground, jumper(0.0f, 0.0f, 2.5f));
    INFO("2.5 m: ", partway.describe());
    REQUIRE(partway.result.outcome == nl::PathOutcome::Complete);
    for (size_t i = 0; i + 1 < partway.points().size(); ++i) {
        if (partway.points()[i].segment == nl::kSegmentWalk) continue;
        const nl::Link link = level.link(partway.points()[i].link);
        CHECK(link.requirements.drop <= 2.5f);
        CHECK(partway.points()[i].position[1] - partway.points()[i + 1].position[1] < 2.6f);
    }

    // Nobody climbs the 3 m drop back up: it is one way; a jumper may hop onto the stairs (up a low
    // drop that is a jump back, reported as a jump).
    const auto up = level.plan(ground, top, jumper(4.0f, 1.5f, 3.5f));
    INFO("up: ", up.describe());
    REQUIRE(up.result.outcome == nl::PathOutcome::Complete);
    for (size_t i = 0; i + 1 < up.points().size(); ++i) {
        if (up.points()[i].segment == nl::kSegmentWalk) continue;
        CHECK(up.points()[i].segment == uint32_t(nl::LinkKind::Jump));
        CHECK(up.points()[i + 1].position[1] - up.points()[i].position[1] <= 1.6f);
    }
}

TEST_CASE("one navmesh serves two agent sizes: the wide one avoids the narrow corridor") {
    // Two rooms over a pit, joined by a 1.2 m corridor and by a 4 m way round; the navmesh is built
    // for a 0.3 m radius.
    const std::vector<Box> boxes = {
        {{0, -1, 0}, {10, 0, 10}},      {{0, -1, 20}, {10, 0, 30}}, {{4.4f, -1, 10}, {5.6f, 0, 20}},
        {{14, -1, 0}, {18, 0, 30}},     {{10, -1, 0}, {14, 0, 4}},  {{10, -1, 26}, {14, 0, 30}},
        {{-5, -31, -5}, {23, -30, 35}},
    };
    LevelWithLinks level(boxes, 0.3f);
    const float from[3] = {3, 0, 7}, to[3] = {3, 0, 23};
    nl::AgentCapabilities slim = walker();
    slim.radius = 0.3f;
    const auto narrow = level.plan(from, to, slim);
    INFO("slim: ", narrow.describe());
    REQUIRE(narrow.result.outcome == nl::PathOutcome::Complete);
    CHECK_FALSE(narrow.passes(10, 20, 0, 30));
    CHECK(narrow.result.length < 20.0f);

    nl::AgentCapabilities wide = walker();
    wide.radius = 0.6f;
    const auto round = level.plan(from, to, wide);
    INFO("wide: ", round.describe());
    REQUIRE(round.result.outcome == nl::PathOutcome::Complete);
    CHECK(round.passes(14, 18, 0, 30));
    CHECK(round.result.length > 30.0f);
}

TEST_CASE("on every shared level, paths stay on the navmesh, end where asked, and do not depend on the thread") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty() && nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir());
    for (const auto& path : levels) {
        const auto world = nl::test::make_world(1, 2);
        nl::test::add_obj_file(*world, path);
        const nl::Handle navmesh = nl::test::build_recast_navmesh(*world);
        const auto navmesh_ptr = world->navmeshes().navmesh(navmesh);

        std::mt19937 rng(5);
        // A random point of a random polygon (a random mix of its corners), a little above it.
        auto random_point = [&]() {
            const uint32_t polygon = uint32_t(rng() % navmesh_ptr->polygon_count());
            float total = 0.0f;
            nl::Vec3 mix = nl::Vec3::Zero();
            for (uint32_t c = 0; c < navmesh_ptr->corner_count(polygon); ++c) {
                const float w = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
                total += w;
                mix += w * navmesh_ptr->vertex(navmesh_ptr->corner(polygon, c));
            }
            nl::Vec3 out = mix / total;
            out.y() += 0.3f;
            return out;
        };
        constexpr int kPairs = 150;
        std::vector<nl::PathQuery> queries(kPairs);
        std::vector<nl::Handle> tickets(kPairs);
        for (int i = 0; i < kPairs; ++i) {
            queries[i].start = random_point();
            queries[i].goal = random_point();
            tickets[i] = world->paths().submit(world->navmeshes().path_graph(navmesh), queries[i], nullptr);
        }
        int complete = 0;
        for (int i = 0; i < kPairs; ++i) {
            INFO(path.stem().string(), " pair ", i);
            nl::PathResult sync;
            const auto graph = world->navmeshes().path_graph(navmesh);
            nl::plan_path(*graph, queries[i], nullptr, sync);
            REQUIRE(sync.outcome != nl::PathOutcome::Failed);
            const std::vector<nl::PathPoint>& points = sync.points;
            const size_t count = points.size();

            // The queued answer, planned on a worker, is the same.
            nl::PathOutcome outcome = nl::PathOutcome::Pending;
            for (int spins = 0; outcome == nl::PathOutcome::Pending && spins < 100000; ++spins) {
                outcome = world->paths().poll(tickets[i]);
                if (outcome == nl::PathOutcome::Pending) std::this_thread::sleep_for(std::chrono::microseconds(100));
            }
            nl::PathResult queued;
            REQUIRE(world->paths().read(tickets[i], [&](const nl::PathResult& r) { queued = r; }));
            world->paths().release(tickets[i]);
            CHECK(queued.outcome == sync.outcome);
            REQUIRE(queued.points.size() == count);
            for (size_t k = 0; k < count; ++k) CHECK(same_point(queued.points[k], points[k]));

            if (sync.outcome != nl::PathOutcome::Complete) continue;
            ++complete;
            REQUIRE(count >= 1);
            for (int k = 0; k < 3; ++k) {
                CHECK(points.front().position[k] == sync.start[k]);
                CHECK(points.back().position[k] == sync.goal[k]);
            }
            const float straight =
                std::sqrt(std::pow(sync.goal[0] - sync.start[0], 2.0f) + std::pow(sync.goal[1] - sync.start[1], 2.0f) +
                          std::pow(sync.goal[2] - sync.start[2], 2.0f));
            CHECK(sync.length >= straight - 1e-3f);
            // Walked segments run over the navmesh: points along them lie over some polygon.
            for (size_t k = 0; k + 1 < count; ++k) {
                CHECK(points[k].segment == nl::kSegmentWalk);  // no links on these navmeshes
                for (float t : {0.25f, 0.5f, 0.75f}) {
                    float probe[3];
                    for (int a = 0; a < 3; ++a)
                        probe[a] = points[k].position[a] + t * (points[k + 1].position[a] - points[k].position[a]);
                    CHECK_MESSAGE(over_navmesh(*navmesh_ptr, probe), "segment ", k, " leaves the navmesh at (",
                                  probe[0], ", ", probe[1], ", ", probe[2], ")");
                }
            }
        }
        MESSAGE(path.stem().string(), ": ", complete, " of ", kPairs, " random pairs complete");
        CHECK(complete > 0);
    }
}
