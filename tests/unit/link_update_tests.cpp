// Updating links after the level changes in a box gives exactly what a full generation gives, and
// casts far fewer rays.
#include <doctest/doctest.h>
#include <navlink/navlink.h>

#include <string>
#include <vector>

#include "generated_level_c.h"

using nl::levelgen::Box;

namespace {

struct Scene {
    nl_world* world = nullptr;
    nl_navmesh_id navmesh{};
    nl::levelgen::GeneratedLevel level = nl::levelgen::generate_default_level(4);

    Scene() {
        REQUIRE(nl_world_create(nullptr, &world) == NL_STATUS_SUCCESS);
        add_boxes(level, 0);
        const nl_navmesh_build_def build = nl_default_navmesh_build_def();
        REQUIRE(nl_navmesh_build(world, &build, &navmesh) == NL_STATUS_SUCCESS);
        nl_link_generation_report report = generate_all();
        full_rays = report.rays_cast;
    }
    ~Scene() { nl_world_destroy(world); }

    nl_mesh_id add_boxes(const nl::levelgen::GeneratedLevel& boxes, uint32_t flags) {
        nl_mesh_id id{};
        REQUIRE(nl::test::add_generated_level(world, boxes, flags, nullptr, &id) == NL_STATUS_SUCCESS);
        return id;
    }
    nl_link_generation_report generate_all() {
        nl_link_generation_report report{};
        report.size = sizeof report;
        REQUIRE(nl_navmesh_generate_links(world, navmesh, nullptr, nullptr, nullptr, &report) == NL_STATUS_SUCCESS);
        return report;
    }
    nl_link_generation_report update(const Box& box) {
        nl_link_generation_report report{};
        report.size = sizeof report;
        REQUIRE_MESSAGE(nl_navmesh_update_links_in_box(world, navmesh, box.min, box.max, nullptr, nullptr, &report) ==
                            NL_STATUS_SUCCESS,
                        nl_get_last_error_message());
        return report;
    }
    std::vector<nl_link> links() const {
        uint32_t count = 0;
        nl_navmesh_get_links(world, navmesh, nullptr, 0, &count);
        std::vector<nl_link> out(count, nl_link_init());
        REQUIRE(nl_navmesh_get_links(world, navmesh, out.data(), count, &count) == NL_STATUS_SUCCESS);
        return out;
    }
    // Updates in `box`, then checks the result against a full generation of the same state.
    void check_update_equals_full(const Box& box, const std::string& what) {
        INFO(what);
        const nl_link_generation_report partial = update(box);
        const auto updated = links();
        const nl_link_generation_report full = generate_all();
        const auto reference = links();
        REQUIRE(updated.size() == reference.size());
        for (size_t i = 0; i < updated.size(); ++i) {
            CHECK(updated[i].kind == reference[i].kind);
            CHECK(updated[i].bidirectional == reference[i].bidirectional);
            CHECK(updated[i].requirements.clearance_width == reference[i].requirements.clearance_width);
            CHECK(updated[i].requirements.gap == reference[i].requirements.gap);
            CHECK(updated[i].requirements.length == reference[i].requirements.length);
            CHECK(updated[i].requirements.rise == reference[i].requirements.rise);
            CHECK(updated[i].requirements.drop == reference[i].requirements.drop);
            CHECK(updated[i].start_polygon == reference[i].start_polygon);
            CHECK(updated[i].end_polygon == reference[i].end_polygon);
            for (int k = 0; k < 3; ++k) {
                CHECK(updated[i].start[k] == reference[i].start[k]);
                CHECK(updated[i].end[k] == reference[i].end[k]);
                CHECK(updated[i].apex[k] == reference[i].apex[k]);
            }
        }
        CHECK(partial.jump_links == full.jump_links);
        CHECK(partial.drop_links == full.drop_links);
        CHECK(partial.rejected_clearance == full.rejected_clearance);
        CHECK(partial.rejected_wall == full.rejected_wall);
        // Work is rays plus box queries (each stands for a stretch of sweep segments). A full generation
        // already skips the segments of clear stretches, so the update's saving is mostly probes.
        MESSAGE(what, ": update cast ", partial.rays_cast, " rays and ", partial.box_queries, " box queries, a full generation ",
                full.rays_cast, " and ", full.box_queries);
        CHECK((partial.rays_cast + partial.box_queries) * 2 < full.rays_cast + full.box_queries);
    }

    uint64_t full_rays = 0;
};

Box grown(const Box& b, float by) {
    return Box{{b.min[0] - by, b.min[1] - by, b.min[2] - by}, {b.max[0] + by, b.max[1] + by, b.max[2] + by}};
}

}  // namespace

TEST_CASE("a wall put across a gap, then taken away: updates equal full generations") {
    Scene s;
    const size_t before = s.links().size();
    // The first gap lies between the first two platforms (boxes 0 and 1 of the default level).
    const float gap_start = s.level.boxes[0].max[0], gap_end = s.level.boxes[1].min[0];
    const float middle = 0.5f * (gap_start + gap_end);
    nl::levelgen::GeneratedLevel wall;
    const Box wall_box{{middle - 0.2f, -6.0f, -0.5f}, {middle + 0.2f, 4.0f, 6.5f}};
    wall.add_box(wall_box);
    const nl_mesh_id id = s.add_boxes(wall, 0);
    // An update that does not look where the wall is keeps the jumps through it: the box matters.
    const Box elsewhere{{-30, -30, -30}, {-29, -29, -29}};
    s.update(elsewhere);
    CHECK(s.links().size() == before);
    s.check_update_equals_full(wall_box, "wall added");
    CHECK(s.links().size() < before);  // the jumps over that gap are gone

    REQUIRE(nl_mesh_remove(s.world, id) == NL_STATUS_SUCCESS);
    s.check_update_equals_full(wall_box, "wall removed");
    CHECK(s.links().size() == before);
}

TEST_CASE("a shelf that moves a rim, not the jump's ends: the update's gaps equal a full generation's") {
    Scene s;
    // A shelf a step below the first platform's top, just past its rim over the first gap: walkable
    // ground, so the rim moves out by its width while the navmesh (built before it) stays.
    const Box& first = s.level.boxes[0];
    const float top = first.max[1], rim = first.max[0];
    nl::levelgen::GeneratedLevel shelf;
    const Box shelf_box{{rim, top - 0.6f, first.min[2]}, {rim + 0.5f, top - 0.5f, first.max[2]}};
    shelf.add_box(shelf_box);
    s.add_boxes(shelf, 0);
    s.check_update_equals_full(grown(shelf_box, 0.01f), "shelf added past a rim");
}

TEST_CASE("a movable crate moved along a platform edge: the update over both places equals a full generation") {
    Scene s;
    const Box& platform = s.level.boxes[1];
    nl::levelgen::GeneratedLevel crate;
    const Box at_origin{{-0.6f, 0.0f, -0.6f}, {0.6f, 1.8f, 0.6f}};
    crate.add_box(at_origin);
    float before[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, platform.min[0] + 0.3f, platform.max[1], 1.5f, 1};
    float after[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, platform.min[0] + 0.3f, platform.max[1], 4.5f, 1};
    nl_mesh_id id{};
    REQUIRE(nl::test::add_generated_level(s.world, crate, NL_MESH_MOVABLE, before, &id) == NL_STATUS_SUCCESS);
    const Box first{{before[12] - 0.6f, before[13], before[14] - 0.6f}, {before[12] + 0.6f, before[13] + 1.8f, before[14] + 0.6f}};
    s.check_update_equals_full(first, "crate placed");

    REQUIRE(nl_mesh_set_transform(s.world, id, after) == NL_STATUS_SUCCESS);
    const Box both{{first.min[0], first.min[1], first.min[2]}, {first.max[0], first.max[1], after[14] + 0.6f}};
    s.check_update_equals_full(both, "crate moved");
}

TEST_CASE("an update needs a prior generation and a proper box; a far-away change casts almost nothing") {
    Scene s;
    nl::levelgen::GeneratedLevel far;
    const Box far_box{{200, 0, 200}, {201, 1, 201}};
    far.add_box(far_box);
    s.add_boxes(far, 0);
    const nl_link_generation_report report = s.update(grown(far_box, 0.1f));
    CHECK(report.rays_cast == 0);
    CHECK(report.jump_links + report.drop_links == s.links().size());

    const float bad_min[3] = {1, 1, 1}, bad_max[3] = {0, 0, 0};
    CHECK(nl_navmesh_update_links_in_box(s.world, s.navmesh, bad_min, bad_max, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));
    CHECK(nl_navmesh_update_links_in_box(s.world, s.navmesh, nullptr, bad_max, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT));

    // A navmesh never generated: nothing to update.
    nl_navmesh_id other{};
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    REQUIRE(nl_navmesh_build(s.world, &build, &other) == NL_STATUS_SUCCESS);
    CHECK(nl_navmesh_update_links_in_box(s.world, other, far_box.min, far_box.max, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
}

TEST_CASE("an update never brings back generated links that were removed or replaced by a load") {
    Scene s;
    const Box anywhere{{-50, -10, -50}, {50, 10, 50}};
    const size_t generated = s.links().size();
    REQUIRE(generated > 0);

    uint32_t removed = 0;
    REQUIRE(nl_navmesh_remove_generated_links(s.world, s.navmesh, &removed) == NL_STATUS_SUCCESS);
    CHECK(removed == generated);
    CHECK(nl_navmesh_update_links_in_box(s.world, s.navmesh, anywhere.min, anywhere.max, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    CHECK(std::string(nl_get_last_error_message()).find("removed") != std::string::npos);
    CHECK(s.links().empty());

    // Generated again, saved, loaded back: the loaded links stay as loaded.
    s.generate_all();
    size_t length = 0;
    REQUIRE(nl_navmesh_save_links_json(s.world, s.navmesh, nullptr, 0, &length) == NL_STATUS_SUCCESS);
    std::string json(length + 1, '\0');
    REQUIRE(nl_navmesh_save_links_json(s.world, s.navmesh, json.data(), json.size(), &length) == NL_STATUS_SUCCESS);
    REQUIRE(nl_navmesh_load_links_json(s.world, s.navmesh, json.data(), length, nullptr) == NL_STATUS_SUCCESS);
    const auto loaded = s.links();
    CHECK(loaded.size() == generated);
    CHECK(nl_navmesh_update_links_in_box(s.world, s.navmesh, anywhere.min, anywhere.max, nullptr, nullptr, nullptr) ==
          (NL_STATUS_FAILURE | NL_STATUS_NOT_FOUND));
    const auto after = s.links();
    REQUIRE(after.size() == loaded.size());
    for (size_t i = 0; i < after.size(); ++i) CHECK(after[i].id.index1 == loaded[i].id.index1);

    // A new generation can be updated again.
    s.generate_all();
    CHECK(s.update(anywhere).jump_links + s.update(anywhere).drop_links == s.links().size());
}
