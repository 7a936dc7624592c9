// nl::World and its navmesh registry, driven through the core only: what belongs to a navmesh (its
// links and their snapshots, its last generation, its path graph) lives and goes with it, under one
// lock; C++ plugins plug in; failures name fields in the core's own terms.
#include <doctest/doctest.h>

#include <chrono>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "level_generator.h"
#include "core_errors.h"
#include "generated_mesh.h"
#include "links/link_placement.h"
#include "path/path_planner.h"
#include "world/world.h"

namespace {

using nl::Handle;
using nl::Link;
using nl::Vec3;

// Two 4 x 4 m platforms 1 m thick, their tops at y = 0, 2 m apart along x (rim to rim).
nl::TriangleMesh two_platforms() {
    nl::levelgen::GeneratedLevel level;
    level.add_box({{0, -1, 0}, {4, 0, 4}});
    level.add_box({{6, -1, 0}, {10, 0, 4}});
    return nl::test::to_triangle_mesh(level);
}

// The platforms' tops, set in by the agent's radius, as a host navmesh: two quads.
nl::NavMeshInput platform_tops(float radius = 0.3f) {
    nl::NavMeshInput in;
    for (float x0 : {0.0f, 6.0f}) {
        const float a = x0 + radius, b = x0 + 4 - radius, c = radius, d = 4 - radius;
        for (const auto& [x, z] : {std::pair{a, c}, {a, d}, {b, d}, {b, c}}) {
            in.indices.push_back(uint32_t(in.vertices.size()));
            in.vertices.emplace_back(x, 0.0f, z);
        }
        in.polygon_sizes.push_back(4);
    }
    in.agent_type.radius = radius;
    in.agent_type.height = 2.0f;
    return in;
}

struct Scene {
    std::unique_ptr<nl::World> world = std::make_unique<nl::World>(nl::WorldSettings{});
    Handle navmesh;

    Scene() {
        world->level().add_mesh(two_platforms(), nl::Transform::Identity(), 0, 0);
        navmesh = world->add_navmesh(platform_tops());
    }
    nl::LinkGenerationReport generate(nl::GenerationProgress progress = [](float, const char*) { return true; }) {
        return world->generate_links(navmesh, nl::LinkSettings{}, {}, progress);
    }
    Link manual(float x0, float x1) const {
        Link l;
        l.start = Vec3(x0, 0.0f, 2.0f);
        l.end = Vec3(x1, 0.0f, 2.0f);
        nl::set_requirements_from_ends(l);
        return l;
    }
};

std::vector<uint64_t> user_data_of(const nl::LinkSnapshot& snapshot) {
    std::vector<uint64_t> out;
    for (const nl::StoredLink& s : snapshot) out.push_back(s.link.user_data);
    return out;
}

}  // namespace

TEST_CASE("a navmesh's links: a snapshot stays as taken, the next one sees every edit, in the order added") {
    Scene s;
    nl::NavMeshRegistry& r = s.world->navmeshes();
    const auto none = r.links(s.navmesh);
    CHECK(none->empty());
    std::vector<Handle> ids;
    for (uint64_t i = 0; i < 3; ++i) {
        Link l = s.manual(3.5f, 6.5f);
        l.user_data = i;
        ids.push_back(s.world->add_link(s.navmesh, l));
    }
    const auto three = r.links(s.navmesh);
    CHECK(r.links(s.navmesh) == three);  // no edit between: the same snapshot, shared
    Link edited = s.manual(3.5f, 6.5f);
    edited.user_data = 10;
    s.world->update_link(ids[0], edited);
    r.remove_link(ids[1]);
    CHECK(user_data_of(*three) == std::vector<uint64_t>{0, 1, 2});
    const auto now = r.links(s.navmesh);
    CHECK(user_data_of(*now) == std::vector<uint64_t>{10, 2});
    CHECK(now->front().id == ids[0]);
    // Placed on the navmesh: each end knows its polygon.
    CHECK(now->front().link.start_polygon == 0);
    CHECK(now->front().link.end_polygon == 1);
}

TEST_CASE("removing a navmesh takes its links, its last generation and its path graph in one step") {
    Scene s;
    const nl::LinkGenerationReport report = s.generate();
    REQUIRE(report.jump_links > 0);  // across the 2 m gap
    const Handle manual = s.world->add_link(s.navmesh, s.manual(3.5f, 6.5f));
    const auto snapshot = s.world->navmeshes().links(s.navmesh);
    const auto graph = s.world->navmeshes().path_graph(s.navmesh);
    std::vector<Handle> ids;
    for (const nl::StoredLink& l : *snapshot) ids.push_back(l.id);

    s.world->navmeshes().remove(s.navmesh);
    CHECK_FALSE(s.world->navmeshes().contains(s.navmesh));
    for (Handle id : ids) CHECK_FALSE(s.world->navmeshes().contains_link(id));
    CHECK(nl::test::code_of([&] { s.world->navmeshes().links(s.navmesh); }) == nl::ErrorCode::InvalidHandle);
    CHECK(nl::test::code_of([&] { s.world->navmeshes().path_graph(s.navmesh); }) == nl::ErrorCode::InvalidHandle);
    CHECK(nl::test::code_of([&] {
              s.world->update_links_in_box(s.navmesh, nl::Aabb{}, [](float, const char*) { return true; });
          }) == nl::ErrorCode::InvalidHandle);
    CHECK(nl::test::code_of([&] { s.world->navmeshes().remove_link(manual); }) == nl::ErrorCode::InvalidHandle);
    // Readers that held them keep them.
    CHECK(snapshot->size() == ids.size());
    CHECK(graph->navmesh().polygon_count() == 2);
}

TEST_CASE("a generation that finishes after its navmesh was removed keeps nothing") {
    Scene s;
    bool removed = false;
    const nl::ErrorCode code = nl::test::code_of([&] {
        s.generate([&](float fraction, const char*) {
            if (fraction > 0.5f && !removed) {
                s.world->navmeshes().remove(s.navmesh);  // from the progress callback: another thread would do the same
                removed = true;
            }
            return true;
        });
    });
    CHECK(removed);
    CHECK(code == nl::ErrorCode::InvalidHandle);
    CHECK(s.world->navmeshes().handles().empty());
}

TEST_CASE("an update continues the last generation; removing the generated links or a load forgets it") {
    Scene s;
    auto everything = [](float, const char*) { return true; };
    nl::Aabb box;
    box.min = Vec3(4.5f, -1.0f, 0.0f);
    box.max = Vec3(5.5f, 3.0f, 4.0f);
    CHECK(nl::test::code_of([&] { s.world->update_links_in_box(s.navmesh, box, everything); }) ==
          nl::ErrorCode::NotFound);
    s.generate();
    const auto full = s.world->navmeshes().links(s.navmesh);
    s.world->update_links_in_box(s.navmesh, box, everything);
    const auto updated = s.world->navmeshes().links(s.navmesh);
    REQUIRE(updated->size() == full->size());
    for (size_t i = 0; i < full->size(); ++i) CHECK((*updated)[i].link.start == (*full)[i].link.start);

    CHECK(s.world->navmeshes().remove_generated_links(s.navmesh) == full->size());
    CHECK(nl::test::code_of([&] { s.world->update_links_in_box(s.navmesh, box, everything); }) ==
          nl::ErrorCode::NotFound);
    s.generate();
    s.world->load_links(s.navmesh, {s.manual(3.5f, 6.5f)});
    CHECK(nl::test::code_of([&] { s.world->update_links_in_box(s.navmesh, box, everything); }) ==
          nl::ErrorCode::NotFound);
    const auto loaded = s.world->navmeshes().links(s.navmesh);
    CHECK(loaded->size() == 1);
}

TEST_CASE("a generation asked for from inside another's progress callback is refused at once, never waited for") {
    Scene s;
    const Handle other = s.world->add_navmesh(platform_tops(0.4f));
    std::string nested;
    s.generate([&](float, const char*) {
        if (nested.empty())
            nested = nl::test::message_of(
                [&] { s.world->generate_links(other, {}, {}, [](float, const char*) { return true; }); });
        return true;
    });
    CHECK(nested.find("from inside another generation") != std::string::npos);
    s.world->generate_links(other, {}, {}, [](float, const char*) { return true; });  // afterwards it runs
}

TEST_CASE("no generation of either kind runs from inside another's progress callback, whichever kinds they are") {
    Scene s;
    const Handle other = s.world->add_navmesh(platform_tops());  // the same body: cross links between the two
    auto everything = [](float, const char*) { return true; };
    nl::Aabb box;
    box.min = Vec3(0.0f, -1.0f, 0.0f);
    box.max = Vec3(10.0f, 3.0f, 4.0f);
    auto cross = [&] { s.world->generate_cross_links(other, s.navmesh, nl::LinkSettings{}, 0.25f, everything); };
    auto own = [&] { s.world->generate_links(other, {}, {}, everything); };
    auto update = [&] { s.world->update_links_in_box(s.navmesh, box, everything); };
    auto refused = [](const std::string& message) {
        return message.find("from inside another generation") != std::string::npos;
    };

    std::string cross_inside_own;
    s.generate([&](float, const char*) {
        if (cross_inside_own.empty()) cross_inside_own = nl::test::message_of(cross);
        return true;
    });
    CHECK_MESSAGE(refused(cross_inside_own), cross_inside_own);

    std::vector<std::string> inside_cross;
    s.world->generate_cross_links(s.navmesh, other, nl::LinkSettings{}, 0.25f, [&](float, const char*) {
        if (inside_cross.empty())
            inside_cross = {nl::test::message_of(own), nl::test::message_of(update), nl::test::message_of(cross)};
        return true;
    });
    REQUIRE(inside_cross.size() == 3);
    for (const std::string& message : inside_cross) CHECK_MESSAGE(refused(message), message);
    // Afterwards each runs.
    own();
    update();
    cross();
}

TEST_CASE("failures name the field in the core's terms; a caller puts its own name in front") {
    Scene s;
    const std::string off = nl::test::message_of([&] { s.world->add_link(s.navmesh, s.manual(3.5f, 60.0f)); });
    CHECK(off.rfind("end is not within 1 m of the navmesh", 0) == 0);
    const std::string named = nl::test::message_of(
        [&] { nl::naming_fields("def->", [&] { s.world->add_link(s.navmesh, s.manual(3.5f, 60.0f)); }); });
    CHECK(named.rfind("def->end is not within", 0) == 0);
    nl::NavMeshInput bad = platform_tops();
    bad.vertices[3].y() = NAN;
    CHECK(nl::test::message_of([&] { s.world->add_navmesh(bad); }).rfind("vertices[3].y", 0) == 0);
    nl::LinkSettings settings;
    settings.max_jump_gap = -1.0f;
    CHECK(nl::test::message_of([&] {
              s.world->generate_links(s.navmesh, settings, {}, [](float, const char*) { return true; });
          }).rfind("max_jump_gap is -1", 0) == 0);
    // A stale id is not about a field: no name goes in front of it.
    const Handle stale{99, 1};
    CHECK(nl::test::message_of([&] {
              nl::naming_fields("def->", [&] { s.world->add_link(stale, s.manual(3.5f, 6.5f)); });
          }).rfind("navmesh {99, 1}", 0) == 0);
}

namespace {

// A C++ link-kind plugin: a "rope" across the gap in the middle of the platforms, or, when asked, one
// end off the navmesh.
class Ropes final : public nl::Plugin, public nl::LinkKindProvider {
public:
    bool stray = false;
    std::string settings_seen;
    const nl::PluginDescription& description() const noexcept override { return description_; }
    nl::LinkKindProvider* link_kind() noexcept override { return this; }
    uint32_t kind() const noexcept override { return 300; }
    const std::string& kind_name() const noexcept override { return name_; }
    void propose(nl::World&, Handle, const std::string& settings_json, nl::FunctionRef<void(Link)> accept) override {
        settings_seen = settings_json;
        Link rope;
        rope.kind = static_cast<nl::LinkKind>(300);
        rope.start = Vec3(3.6f, 0.0f, 2.0f);
        rope.end = Vec3(stray ? 30.0f : 6.4f, 0.0f, 2.0f);
        rope.requirements.abilities = 0x8;
        accept(rope);
    }

private:
    nl::PluginDescription description_{"ropes", "1", "a test plugin", 0, false};
    std::string name_ = "rope";
};

// A C++ navmesh builder that hands over the platforms' tops for whatever agent is asked.
class Tops final : public nl::Plugin, public nl::NavMeshBuilder {
public:
    const nl::PluginDescription& description() const noexcept override { return description_; }
    nl::NavMeshBuilder* navmesh_builder() noexcept override { return this; }
    nl::BuiltNavMesh build(nl::World&, const nl::NavMeshBuildRequest& request) override {
        nl::BuiltNavMesh built;
        built.navmesh = nl::build_navmesh(platform_tops(request.agent_type.radius));
        built.settings_used = settings_used;
        return built;
    }
    std::string settings_used;

private:
    nl::PluginDescription description_{"tops", "1", "a test builder", 0, false};
};

}  // namespace

TEST_CASE("C++ plugins: a link kind's links are placed and generated with the rest; a builder's navmesh is added") {
    Scene s;
    auto ropes = std::make_unique<Ropes>();
    Ropes& rope_plugin = *ropes;
    s.world->plugins().add(std::move(ropes));
    nl::PluginSettings settings;
    settings["rope"] = "{\"length\":3}";
    const nl::LinkGenerationReport report =
        s.world->generate_links(s.navmesh, {}, settings, [](float, const char*) { return true; });
    CHECK(report.plugin_links == 1);
    CHECK(rope_plugin.settings_seen == "{\"length\":3}");
    // What ran is recorded with the links, as a saved file and a links file say it.
    CHECK(s.world->navmeshes().made_for(s.navmesh).links.plugins ==
          "{\"rope\":{\"plugin\":\"ropes\",\"settings\":{\"length\":3},\"version\":\"1\"}}");
    const auto links = s.world->navmeshes().links(s.navmesh);
    const Link& rope = links->back().link;
    CHECK(uint32_t(rope.kind) == 300);
    CHECK(rope.generated);
    CHECK(rope.start_polygon == 0);
    CHECK(rope.end_polygon == 1);
    CHECK(rope.requirements.abilities == 0x8);

    rope_plugin.stray = true;
    const std::string refused = nl::test::message_of([&] { s.generate(); });
    CHECK(refused == "link-kind plugin 'ropes' proposed a link that was refused: end is not within 1 m of the navmesh");
    const auto after = s.world->navmeshes().links(s.navmesh);
    CHECK(after->size() == links->size());  // nothing changed

    CHECK(nl::test::code_of([&] { s.world->plugins().add(std::make_unique<Ropes>()); }) ==
          nl::ErrorCode::InvalidArgument);

    auto tops_plugin = std::make_unique<Tops>();
    Tops& tops = *tops_plugin;
    s.world->plugins().add(std::move(tops_plugin));
    nl::NavMeshBuildRequest request;
    request.builder = "tops";
    request.agent_type.radius = 0.5f;
    const Handle built = s.world->build_navmesh(request);
    const auto mesh = s.world->navmeshes().navmesh(built);
    CHECK(mesh->agent().radius == 0.5f);
    CHECK(s.world->navmeshes().made_for(built).builder == "tops");
    CHECK(s.world->navmeshes().made_for(built).builder_settings.empty());  // none given, none said
    // What a builder says it used is recorded over what it was given; what is not a JSON object is a
    // builder bug, and nothing is added.
    tops.settings_used = "{ \"layers\" : 1 }";
    const std::string given = "{}";
    request.settings_json = given.c_str();
    request.settings_json_length = given.size();
    CHECK(s.world->navmeshes().made_for(s.world->build_navmesh(request)).builder_settings == "{\"layers\":1}");
    tops.settings_used.clear();
    CHECK(s.world->navmeshes().made_for(s.world->build_navmesh(request)).builder_settings == "{}");
    const size_t navmeshes = s.world->navmeshes().handles().size();
    tops.settings_used = "[1]";
    CHECK(nl::test::message_of([&] { s.world->build_navmesh(request); }) ==
          "builder 'tops' said it used settings that are not a JSON object: an array of 1 value");
    tops.settings_used = "{";
    CHECK(nl::test::code_of([&] { s.world->build_navmesh(request); }) == nl::ErrorCode::Internal);
    CHECK(s.world->navmeshes().handles().size() == navmeshes);
    request.builder = "nobody";
    CHECK(nl::test::message_of([&] { s.world->build_navmesh(request); }) ==
          "no navmesh builder named 'nobody' (loaded: 'tops')");
}

TEST_CASE("the path graph is built once per moment of the links, and an edit makes the next one") {
    Scene s;
    nl::NavMeshRegistry& r = s.world->navmeshes();
    const auto first = r.path_graph(s.navmesh);
    CHECK(r.path_graph(s.navmesh) == first);
    const Handle rope = s.world->add_link(s.navmesh, s.manual(3.5f, 6.5f));
    const auto second = r.path_graph(s.navmesh);
    CHECK(second != first);
    CHECK(second->links_ptr()->size() == 1);
    CHECK(first->links_ptr()->empty());                              // a search that started before keeps what it read
    CHECK(second->search_index_ptr() == first->search_index_ptr());  // the navmesh's, built once
    CHECK(r.path_graph(s.navmesh) == second);
    r.remove_link(rope);
    const auto graph = r.path_graph(s.navmesh);
    CHECK(graph->links().empty());
}

TEST_CASE("waiting for a path: without workers the waiting thread plans, with them it sleeps; never from a callback") {
    using namespace std::chrono_literals;
    constexpr auto forever = std::chrono::steady_clock::duration::max();
    Scene s;
    nl::PathQuery query;
    query.start = Vec3(1.0f, 0.0f, 2.0f);
    query.goal = Vec3(2.0f, 0.0f, 2.0f);
    query.capabilities.radius = 0.3f;
    nl::PathQueue& queue = s.world->paths();
    std::string refused;
    std::vector<Handle> tickets;
    for (int i = 0; i < 3; ++i) {
        tickets.push_back(queue.submit(
            s.world->navmeshes().path_graph(s.navmesh), query,
            [&](Handle t, nl::PathOutcome) { refused = nl::test::message_of([&] { queue.wait(t, 0s); }); }));
    }
    CHECK(queue.wait(tickets[1], 0s) == nl::PathOutcome::Pending);  // a zero timeout only looks
    CHECK(queue.poll(tickets[0]) == nl::PathOutcome::Pending);
    CHECK(queue.wait(tickets[1], forever) == nl::PathOutcome::Complete);
    CHECK(queue.poll(tickets[0]) == nl::PathOutcome::Complete);  // planned first: oldest first
    CHECK(queue.poll(tickets[2]) == nl::PathOutcome::Pending);   // and no further than needed
    CHECK(refused == "a path callback cannot wait for a path: it runs on a thread that finishes them");
    CHECK(queue.wait(tickets[2], 1h) == nl::PathOutcome::Complete);
    queue.release(tickets[2]);
    CHECK(nl::test::code_of([&] { queue.wait(tickets[2], forever); }) == nl::ErrorCode::InvalidHandle);

    // With path workers the waiting thread sleeps until a worker has finished the request.
    nl::WorldSettings settings;
    settings.path_worker_count = 2;
    auto threaded = std::make_unique<nl::World>(std::move(settings));
    const Handle navmesh = threaded->add_navmesh(platform_tops());
    threaded->level().add_mesh(two_platforms(), nl::Transform::Identity(), 0, 0);
    std::vector<Handle> many;
    for (int i = 0; i < 64; ++i)
        many.push_back(threaded->paths().submit(threaded->navmeshes().path_graph(navmesh), query, nullptr));
    for (Handle t : many) {
        const nl::PathOutcome outcome = threaded->paths().wait(t, forever);
        CHECK(outcome == nl::PathOutcome::Complete);
        CHECK(threaded->paths().poll(t) == outcome);
    }
}

TEST_CASE("the path queue: a search-work budget, and finished requests taken once on the host's thread") {
    Scene s;
    s.world->add_link(s.navmesh, s.manual(3.5f, 6.5f));
    nl::PathQuery query;
    query.start = Vec3(1.0f, 0.0f, 2.0f);
    query.goal = Vec3(9.0f, 0.0f, 2.0f);
    query.capabilities.radius = 0.3f;
    query.capabilities.max_jump_distance = 3.0f;
    nl::PathQueue& queue = s.world->paths();
    int users[3] = {0, 1, 2};
    std::vector<Handle> tickets;
    for (int& u : users)
        tickets.push_back(queue.submit(s.world->navmeshes().path_graph(s.navmesh), query, nullptr, &u));

    nl::ProcessBudget one_node;
    one_node.max_search_nodes = 1;  // the first search crosses it: one request per call
    CHECK(queue.process(one_node) == 1);
    CHECK(queue.process(one_node) == 1);
    std::vector<nl::FinishedRequest> finished;
    CHECK(queue.take_finished(8, finished) == 0);
    REQUIRE(finished.size() == 2);
    CHECK(finished[0].ticket == tickets[0]);
    CHECK(finished[0].user == &users[0]);
    CHECK(finished[0].outcome == nl::PathOutcome::Complete);
    CHECK(finished[1].ticket == tickets[1]);
    CHECK(queue.take_finished(8, finished) == 0);
    CHECK(finished.empty());  // each is taken once

    CHECK(queue.process(nl::ProcessBudget{}) == 1);
    queue.release(tickets[2]);  // finished, then released before it was taken: not reported
    CHECK(queue.take_finished(8, finished) == 0);
    CHECK(finished.empty());
    // A small capacity leaves the rest for the next call.
    for (int& u : users)
        tickets.push_back(queue.submit(s.world->navmeshes().path_graph(s.navmesh), query, nullptr, &u));
    CHECK(queue.process(nl::ProcessBudget{}) == 3);
    CHECK(queue.take_finished(2, finished) == 1);
    CHECK(finished.size() == 2);
    CHECK(queue.take_finished(2, finished) == 0);
    CHECK(finished.size() == 1);
}
