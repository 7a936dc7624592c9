// Paths on procedural levels built from boxes, through the C ABI as a host would: the navmesh by
// the Recast builder, links by the generator, then each agent's path. Each level has one feature an
// agent's body decides about: a gap, a ledge, a narrow corridor.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "generated_level_c.h"
#include "shared_levels.h"
#include "world.h"

using nl::levelgen::Box;

namespace {

struct LevelWithLinks {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    std::vector<nl_link> links;

    explicit LevelWithLinks(const std::vector<Box>& boxes, float agent_radius = 0.6f) {
        nl::levelgen::GeneratedLevel level;
        for (const Box& b : boxes) level.add_box(b);
        nl_world_def def = nl_default_world_def();
        def.worker_count = 2;
        def.path_worker_count = 0;
        REQUIRE(nl_world_create(&def, &world) == NL_STATUS_SUCCESS);
        REQUIRE(nl::test::add_generated_level(world, level) == NL_STATUS_SUCCESS);
        nl_navmesh_build_def build = nl_default_navmesh_build_def();
        build.agent.radius = agent_radius;
        REQUIRE_MESSAGE(nl_navmesh_build(world, &build, &navmesh) == NL_STATUS_SUCCESS, nl_get_last_error_message());
        REQUIRE(nl_navmesh_generate_links(world, navmesh, nullptr, nullptr, nullptr, nullptr) == NL_STATUS_SUCCESS);
        uint32_t count = 0;
        nl_navmesh_get_links(world, navmesh, nullptr, 0, &count);
        links.resize(count, nl_link_init());
        nl_navmesh_get_links(world, navmesh, links.data(), count, &count);
    }
    ~LevelWithLinks() { nl_world_destroy(world); }
    LevelWithLinks(const LevelWithLinks&) = delete;
    LevelWithLinks& operator=(const LevelWithLinks&) = delete;

    struct Path {
        nl_path_result result{};
        std::vector<nl_path_point> points;

        uint32_t segments_of(nl_segment_kind kind) const {
            uint32_t n = 0;
            for (size_t i = 0; i + 1 < points.size(); ++i) n += points[i].segment == kind;
            return n;
        }
        bool passes(float min_x, float max_x, float min_z, float max_z) const {
            for (const nl_path_point& p : points)
                if (p.position[0] >= min_x && p.position[0] <= max_x && p.position[2] >= min_z && p.position[2] <= max_z)
                    return true;
            return false;
        }
        std::string describe() const {
            std::string s = "outcome " + std::to_string(result.outcome) + ", length " + std::to_string(result.length) + ":";
            for (const nl_path_point& p : points)
                s += " (" + std::to_string(p.position[0]) + ", " + std::to_string(p.position[1]) + ", " +
                     std::to_string(p.position[2]) + ")" + (p.segment ? " then link kind " + std::to_string(p.segment) : "");
            return s;
        }
    };

    Path plan(const float* from, const float* to, const nl_agent_capabilities& agent) const {
        nl_path_request_def def = nl_default_path_request_def();
        def.navmesh = navmesh;
        for (int i = 0; i < 3; ++i) def.start[i] = from[i], def.goal[i] = to[i];
        def.agent = agent;
        def.accept_partial = 0;
        Path path;
        path.result.size = sizeof path.result;
        path.points.resize(256, nl_path_point_init());
        uint32_t count = 0;
        REQUIRE(nl_path_find(world, &def, &path.result, path.points.data(), 256, &count) == NL_STATUS_SUCCESS);
        path.points.resize(count, nl_path_point_init());
        return path;
    }
};

nl_agent_capabilities walker() { return nl_default_agent_capabilities(); }

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

nl_agent_capabilities jumper(float distance, float height, float drop) {
    nl_agent_capabilities a = nl_default_agent_capabilities();
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
        {{0, -1, 0}, {10, 0, 10}},     // A
        {{12, 0.2f, 0}, {22, 1.2f, 10}},  // B
        {{0, -1, 20}, {22, 0, 23}},    // the bridge
        {{0, -1, 10}, {3, 0, 20}},     // A to the bridge
        {{-5, -31, -5}, {27, -30, 28}},  // the pit's floor, beyond any drop
    };
    for (int step = 0; step < 4; ++step) {
        const float z1 = 20.0f - 2.5f * step, top = 0.3f * (step + 1);
        boxes.push_back({{19, -1, z1 - 2.5f}, {22, top, z1}});
    }
    LevelWithLinks level(boxes);
    uint32_t jumps = 0;
    for (const nl_link& l : level.links) jumps += l.kind == NL_LINK_JUMP && l.start[0] < 12.5f && l.end[0] > 9.5f;
    REQUIRE(jumps > 0);

    const float from[3] = {5, 0, 5}, to[3] = {17, 1.2f, 5};
    const auto runner = level.plan(from, to, jumper(3.5f, 1.5f, 2.0f));
    INFO("runner: ", runner.describe());
    REQUIRE(runner.result.outcome == NL_PATH_COMPLETE);
    CHECK(runner.result.links_used == 1);
    CHECK(runner.segments_of(NL_LINK_JUMP) == 1);
    CHECK(runner.result.length < 16.0f);
    for (size_t i = 0; i < runner.points.size(); ++i) {
        if (runner.points[i].segment != NL_LINK_JUMP) continue;
        nl_link link = nl_link_init();
        REQUIRE(nl_link_get(level.world, runner.points[i].link, &link) == NL_STATUS_SUCCESS);
        CHECK(link.kind == NL_LINK_JUMP);
        CHECK(runner.points[i].apex[1] > runner.points[i + 1].position[1]);  // the arc tops the higher end
    }

    for (const nl_agent_capabilities& agent : {walker(), jumper(1.0f, 1.5f, 2.0f)}) {
        const auto round = level.plan(from, to, agent);
        INFO("round: ", round.describe());
        REQUIRE(round.result.outcome == NL_PATH_COMPLETE);
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
    for (const nl_link& l : level.links) drops += l.kind == NL_LINK_DROP;
    REQUIRE(drops > 0);

    const float top[3] = {2, 3, 5}, ground[3] = {-6, 0, 5};
    const auto dropper = level.plan(top, ground, jumper(0.0f, 0.0f, 3.5f));
    INFO("dropper: ", dropper.describe());
    REQUIRE(dropper.result.outcome == NL_PATH_COMPLETE);
    CHECK(dropper.segments_of(NL_LINK_DROP) == 1);
    CHECK(dropper.result.length < 12.0f);

    for (const nl_agent_capabilities& agent : {walker(), jumper(4.0f, 1.5f, 0.0f)}) {
        const auto stairs = level.plan(top, ground, agent);
        INFO("no drop: ", stairs.describe());
        REQUIRE(stairs.result.outcome == NL_PATH_COMPLETE);
        CHECK(stairs.result.links_used == 0);
        CHECK(stairs.passes(10, 19, 0, 3));
        CHECK(stairs.result.length > 20.0f);
    }

    // A body good for 2.5 m may step off the stairs part of the way down, never off the tower.
    const auto partway = level.plan(top, ground, jumper(0.0f, 0.0f, 2.5f));
    INFO("2.5 m: ", partway.describe());
    REQUIRE(partway.result.outcome == NL_PATH_COMPLETE);
    for (size_t i = 0; i + 1 < partway.points.size(); ++i) {
        if (partway.points[i].segment == NL_SEGMENT_WALK) continue;
        nl_link link = nl_link_init();
        REQUIRE(nl_link_get(level.world, partway.points[i].link, &link) == NL_STATUS_SUCCESS);
        CHECK(link.requirements.drop <= 2.5f);
        CHECK(partway.points[i].position[1] - partway.points[i + 1].position[1] < 2.6f);
    }

    // Nobody climbs the 3 m drop back up: it is one way; a jumper may hop onto the stairs (up a low
    // drop that is a jump back, reported as a jump).
    const auto up = level.plan(ground, top, jumper(4.0f, 1.5f, 3.5f));
    INFO("up: ", up.describe());
    REQUIRE(up.result.outcome == NL_PATH_COMPLETE);
    for (size_t i = 0; i + 1 < up.points.size(); ++i) {
        if (up.points[i].segment == NL_SEGMENT_WALK) continue;
        CHECK(up.points[i].segment == NL_LINK_JUMP);
        CHECK(up.points[i + 1].position[1] - up.points[i].position[1] <= 1.6f);
    }
}

TEST_CASE("one navmesh serves two agent sizes: the wide one avoids the narrow corridor") {
    // Two rooms over a pit, joined by a 1.2 m corridor and by a 4 m way round; the navmesh is built
    // for a 0.3 m radius.
    const std::vector<Box> boxes = {
        {{0, -1, 0}, {10, 0, 10}},       {{0, -1, 20}, {10, 0, 30}}, {{4.4f, -1, 10}, {5.6f, 0, 20}},
        {{14, -1, 0}, {18, 0, 30}},      {{10, -1, 0}, {14, 0, 4}},  {{10, -1, 26}, {14, 0, 30}},
        {{-5, -31, -5}, {23, -30, 35}},
    };
    LevelWithLinks level(boxes, 0.3f);
    const float from[3] = {3, 0, 7}, to[3] = {3, 0, 23};
    nl_agent_capabilities slim = walker();
    slim.radius = 0.3f;
    const auto narrow = level.plan(from, to, slim);
    INFO("slim: ", narrow.describe());
    REQUIRE(narrow.result.outcome == NL_PATH_COMPLETE);
    CHECK_FALSE(narrow.passes(10, 20, 0, 30));
    CHECK(narrow.result.length < 20.0f);

    nl_agent_capabilities wide = walker();
    wide.radius = 0.6f;
    const auto round = level.plan(from, to, wide);
    INFO("wide: ", round.describe());
    REQUIRE(round.result.outcome == NL_PATH_COMPLETE);
    CHECK(round.passes(14, 18, 0, 30));
    CHECK(round.result.length > 30.0f);
}

TEST_CASE("on every shared level, paths stay on the navmesh, end where asked, and do not depend on the thread") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty() && nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir());
    for (const auto& path : levels) {
        nl_world_def def = nl_default_world_def();
        def.worker_count = 1;
        def.path_worker_count = 2;
        nl_world* world = nullptr;
        REQUIRE(nl_world_create(&def, &world) == NL_STATUS_SUCCESS);
        nl_mesh_id mesh{};
        REQUIRE(nl_mesh_add_obj_file(world, path.c_str(), nullptr, &mesh) == NL_STATUS_SUCCESS);
        const nl_navmesh_build_def build = nl_default_navmesh_build_def();
        nl_navmesh_id navmesh{};
        REQUIRE(nl_navmesh_build(world, &build, &navmesh) == NL_STATUS_SUCCESS);
        nl_navmesh_info info{};
        info.size = sizeof info;
        nl_navmesh_get_info(world, navmesh, &info);
        const auto navmesh_ptr = world->core->navmeshes().navmesh(nl::Handle{navmesh.index1, navmesh.generation});

        std::vector<float> vertices(3 * size_t(info.vertex_count));
        uint32_t vertex_count = 0;
        nl_navmesh_get_vertices(world, navmesh, vertices.data(), info.vertex_count, &vertex_count);
        std::mt19937 rng(5);
        // A random point of a random polygon (a random mix of its corners), a little above it.
        auto random_point = [&](float* out) {
            nl_nav_polygon polygon = nl_nav_polygon_init();
            nl_navmesh_get_polygon(world, navmesh, uint32_t(rng() % info.polygon_count), &polygon);
            float total = 0.0f, mix[3] = {0, 0, 0};
            for (uint32_t c = 0; c < polygon.vertex_count; ++c) {
                const float w = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
                total += w;
                for (int k = 0; k < 3; ++k) mix[k] += w * vertices[3 * size_t(polygon.vertices[c]) + k];
            }
            for (int k = 0; k < 3; ++k) out[k] = mix[k] / total;
            out[1] += 0.3f;
        };
        constexpr int kPairs = 150;
        std::vector<nl_path_request_def> defs(kPairs);
        std::vector<nl_path_ticket> tickets(kPairs);
        for (int i = 0; i < kPairs; ++i) {
            defs[i] = nl_default_path_request_def();
            defs[i].navmesh = navmesh;
            random_point(defs[i].start);
            random_point(defs[i].goal);
            REQUIRE(nl_path_request(world, &defs[i], &tickets[i]) == NL_STATUS_SUCCESS);
        }
        int complete = 0;
        for (int i = 0; i < kPairs; ++i) {
            INFO(path.stem().string(), " pair ", i);
            nl_path_result sync{};
            sync.size = sizeof sync;
            std::vector<nl_path_point> points(512, nl_path_point_init());
            uint32_t count = 0;
            REQUIRE(NL_SUCCEEDED(nl_path_find(world, &defs[i], &sync, points.data(), 512, &count)));
            points.resize(count, nl_path_point_init());

            // The queued answer, planned on a worker, is the same.
            nl_path_outcome outcome = NL_PATH_PENDING;
            for (int spins = 0; outcome == NL_PATH_PENDING && spins < 100000; ++spins) {
                REQUIRE(nl_path_poll(world, tickets[i], &outcome) == NL_STATUS_SUCCESS);
                if (outcome == NL_PATH_PENDING) std::this_thread::sleep_for(std::chrono::microseconds(100));
            }
            nl_path_result queued{};
            queued.size = sizeof queued;
            std::vector<nl_path_point> queued_points(512, nl_path_point_init());
            uint32_t queued_count = 0;
            REQUIRE(NL_SUCCEEDED(nl_path_get_result(world, tickets[i], &queued, queued_points.data(), 512, &queued_count)));
            REQUIRE(nl_path_release(world, tickets[i]) == NL_STATUS_SUCCESS);
            CHECK(queued.outcome == sync.outcome);
            REQUIRE(queued_count == count);
            for (uint32_t k = 0; k < count; ++k)
                CHECK(std::memcmp(&queued_points[k], &points[k], sizeof(nl_path_point)) == 0);

            if (sync.outcome != NL_PATH_COMPLETE) continue;
            ++complete;
            REQUIRE(count >= 1);
            for (int k = 0; k < 3; ++k) {
                CHECK(points.front().position[k] == sync.start[k]);
                CHECK(points.back().position[k] == sync.goal[k]);
            }
            const float straight = std::sqrt(std::pow(sync.goal[0] - sync.start[0], 2.0f) +
                                             std::pow(sync.goal[1] - sync.start[1], 2.0f) +
                                             std::pow(sync.goal[2] - sync.start[2], 2.0f));
            CHECK(sync.length >= straight - 1e-3f);
            // Walked segments run over the navmesh: points along them lie over some polygon.
            for (uint32_t k = 0; k + 1 < count; ++k) {
                CHECK(points[k].segment == NL_SEGMENT_WALK);  // no links on these navmeshes
                for (float t : {0.25f, 0.5f, 0.75f}) {
                    float probe[3];
                    for (int a = 0; a < 3; ++a) probe[a] = points[k].position[a] + t * (points[k + 1].position[a] - points[k].position[a]);
                    CHECK_MESSAGE(over_navmesh(*navmesh_ptr, probe), "segment ", k, " leaves the navmesh at (", probe[0], ", ",
                                  probe[1], ", ", probe[2], ")");
                }
            }
        }
        MESSAGE(path.stem().string(), ": ", complete, " of ", kPairs, " random pairs complete");
        CHECK(complete > 0);
        nl_world_destroy(world);
    }
}
