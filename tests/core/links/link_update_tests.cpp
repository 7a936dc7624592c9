// Updating links after the level changes in a box gives exactly what a full generation gives, and
// casts far fewer rays.
#include <doctest/doctest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core_errors.h"
#include "core_world.h"

using nl::levelgen::Box;

namespace {

nl::Aabb aabb_of(const Box& b) {
    nl::Aabb box;
    box.min = nl::Vec3(b.min[0], b.min[1], b.min[2]);
    box.max = nl::Vec3(b.max[0], b.max[1], b.max[2]);
    return box;
}

struct Scene {
    std::unique_ptr<nl::World> world = nl::test::make_world(2);
    nl::Handle navmesh;
    nl::levelgen::GeneratedLevel level = nl::levelgen::generate_default_level(4);

    Scene() {
        add_boxes(level, 0);
        navmesh = nl::test::build_recast_navmesh(*world);
        nl::LinkGenerationReport report = generate_all();
        full_rays = report.rays_cast;
    }

    nl::Handle add_boxes(const nl::levelgen::GeneratedLevel& boxes, uint32_t flags,
                         const nl::Transform& transform = nl::Transform::Identity()) {
        return nl::test::add_level(*world, boxes, flags, transform);
    }
    nl::LinkGenerationReport generate_all() {
        return world->generate_links(navmesh, nl::LinkSettings{}, {}, nl::test::keep_going);
    }
    nl::LinkGenerationReport update(const Box& box) { return update_links_in_box_raw(aabb_of(box)); }
    nl::LinkGenerationReport update_links_in_box_raw(const nl::Aabb& box) {
        return world->update_links_in_box(navmesh, box, nl::test::keep_going);
    }
    std::vector<nl::StoredLink> links() const { return nl::test::links_of(*world, navmesh); }
    // Updates in `box`, then checks the result against a full generation of the same state.
    void check_update_equals_full(const Box& box, const std::string& what) {
        INFO(what);
        const nl::LinkGenerationReport partial = update(box);
        const auto updated_links = links();
        const nl::LinkGenerationReport full = generate_all();
        const auto reference_links = links();
        REQUIRE(updated_links.size() == reference_links.size());
        for (size_t i = 0; i < updated_links.size(); ++i) {
            const nl::Link &updated = updated_links[i].link, &reference = reference_links[i].link;
            CHECK(updated.kind == reference.kind);
            CHECK(updated.bidirectional == reference.bidirectional);
            CHECK(updated.requirements.clearance_width == reference.requirements.clearance_width);
            CHECK(updated.requirements.gap == reference.requirements.gap);
            CHECK(updated.requirements.length == reference.requirements.length);
            CHECK(updated.requirements.rise == reference.requirements.rise);
            CHECK(updated.requirements.drop == reference.requirements.drop);
            CHECK(updated.start_polygon == reference.start_polygon);
            CHECK(updated.end_polygon == reference.end_polygon);
            for (int k = 0; k < 3; ++k) {
                CHECK(updated.start[k] == reference.start[k]);
                CHECK(updated.end[k] == reference.end[k]);
                CHECK(updated.apex[k] == reference.apex[k]);
            }
        }
        CHECK(partial.jump_links == full.jump_links);
        CHECK(partial.drop_links == full.drop_links);
        CHECK(partial.rejected_clearance == full.rejected_clearance);
        CHECK(partial.rejected_wall == full.rejected_wall);
        // Work is rays plus box queries (each stands for a stretch of sweep segments). A full generation
        // already skips the segments of clear stretches, so the update's saving is mostly probes.
        MESSAGE(what, ": update cast ", partial.rays_cast, " rays and ", partial.box_queries,
                " box queries, a full generation ", full.rays_cast, " and ", full.box_queries);
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
    const nl::Handle id = s.add_boxes(wall, 0);
    // An update that does not look where the wall is keeps the jumps through it: the box matters.
    const Box elsewhere{{-30, -30, -30}, {-29, -29, -29}};
    s.update(elsewhere);
    CHECK(s.links().size() == before);
    s.check_update_equals_full(wall_box, "wall added");
    CHECK(s.links().size() < before);  // the jumps over that gap are gone

    s.world->level().remove_mesh(id);
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
    const nl::Handle id =
        s.add_boxes(crate, nl::kMeshMovable, nl::Transform(Eigen::Map<const Eigen::Matrix4f>(before)));
    const Box first{{before[12] - 0.6f, before[13], before[14] - 0.6f},
                    {before[12] + 0.6f, before[13] + 1.8f, before[14] + 0.6f}};
    s.check_update_equals_full(first, "crate placed");

    s.world->level().set_transform(id, nl::Transform(Eigen::Map<const Eigen::Matrix4f>(after)));
    const Box both{{first.min[0], first.min[1], first.min[2]}, {first.max[0], first.max[1], after[14] + 0.6f}};
    s.check_update_equals_full(both, "crate moved");
}

TEST_CASE("an update needs a prior generation and a proper box; a far-away change casts almost nothing") {
    Scene s;
    nl::levelgen::GeneratedLevel far;
    const Box far_box{{200, 0, 200}, {201, 1, 201}};
    far.add_box(far_box);
    s.add_boxes(far, 0);
    const nl::LinkGenerationReport report = s.update(grown(far_box, 0.1f));
    CHECK(report.rays_cast == 0);
    CHECK(report.jump_links + report.drop_links == s.links().size());

    // A box that is not one (min above max, a corner not finite) is refused before anything is read
    // (the C layer names its arguments: abi.links.update_in_box).
    const std::size_t before = s.links().size();
    nl::Aabb inverted = aabb_of(far_box);
    std::swap(inverted.min, inverted.max);
    CHECK(nl::test::code_of([&] { s.update_links_in_box_raw(inverted); }) == nl::ErrorCode::InvalidArgument);
    nl::Aabb not_finite = aabb_of(far_box);
    not_finite.max.x() = std::numeric_limits<float>::infinity();
    CHECK(nl::test::code_of([&] { s.update_links_in_box_raw(not_finite); }) == nl::ErrorCode::InvalidArgument);
    CHECK(s.links().size() == before);

    // A navmesh never generated: nothing to update.
    const nl::Handle other = nl::test::build_recast_navmesh(*s.world);
    CHECK(nl::test::code_of([&] { s.world->update_links_in_box(other, aabb_of(far_box), nl::test::keep_going); }) ==
          nl::ErrorCode::NotFound);
}

TEST_CASE("an update never brings back generated links that were removed or replaced by a load") {
    Scene s;
    const Box anywhere{{-50, -10, -50}, {50, 10, 50}};
    const size_t generated = s.links().size();
    REQUIRE(generated > 0);

    const size_t removed = s.world->navmeshes().remove_generated_links(s.navmesh);
    CHECK(removed == generated);
    std::string message;
    CHECK(nl::test::code_of([&] { s.update(anywhere); }, &message) == nl::ErrorCode::NotFound);
    CHECK(message.find("removed") != std::string::npos);
    CHECK(s.links().empty());

    // Generated again, saved, loaded back: the loaded links stay as loaded.
    s.generate_all();
    const std::string json = nl::test::save_links_json(*s.world, s.navmesh);
    nl::test::load_links_json(*s.world, s.navmesh, json);
    const auto loaded = s.links();
    CHECK(loaded.size() == generated);
    CHECK(nl::test::code_of([&] { s.update(anywhere); }) == nl::ErrorCode::NotFound);
    const auto after = s.links();
    REQUIRE(after.size() == loaded.size());
    for (size_t i = 0; i < after.size(); ++i) CHECK(after[i].id.index1 == loaded[i].id.index1);

    // A new generation can be updated again.
    s.generate_all();
    CHECK(s.update(anywhere).jump_links + s.update(anywhere).drop_links == s.links().size());
}
