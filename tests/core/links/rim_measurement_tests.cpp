// The rim a body leaves from, measured where it leaves: drops turned from their edge and jumps at an
// angle, over a lip that is notched (a stepped rim) or a bevel that widens along the edge, on decks
// turned to several angles against Recast's voxel grid. The true rim along each link's heading is
// computed from the level's own shape, to the millimetre, and compared with what the link records.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core_world.h"
#include "link_test_helpers.h"
#include "links/generate_links.h"

using nl::Link;
using nl::LinkKind;
using nl::Vec3;
using nl::levelgen::Box;
using nl::levelgen::GeneratedLevel;

namespace {

constexpr float kDeck = 1.3f;       // deck tops, over a floor at 0: within max_jump_up, so drops work both ways
constexpr float kStepDown = 0.95f;  // what a rim probe counts as ground: within climb (0.9) + 5 cm below
constexpr float kRimStep = 0.25f;   // the rim search's step
constexpr float kHalving = kRimStep / 16.0f;  // and its last interval
constexpr float kPastRim = 0.2f;              // a drop's fall leaves the ground this far past its rim

// A level described in its own frame (heights known everywhere), built turned by `yaw` about the origin.
struct RimLevel {
    GeneratedLevel level;
    std::function<float(float x, float z)> height;  // the highest surface at (x, z), own frame
    float yaw = 0.0f;                               // radians

    Vec3 to_own(const Vec3& world) const {
        const float c = std::cos(-yaw), s = std::sin(-yaw);
        return Vec3(c * world.x() + s * world.z(), world.y(), -s * world.x() + c * world.z());
    }
    void turn() {
        const float c = std::cos(yaw), s = std::sin(yaw);
        for (size_t v = 0; v + 2 < level.positions.size(); v += 3) {
            const float x = level.positions[v], z = level.positions[v + 2];
            level.positions[v] = c * x + s * z;
            level.positions[v + 2] = -s * x + c * z;
        }
    }
    // How far from `start` along the horizontal unit `heading` (world) the ground falls more than a step
    // below start's height: where a body leaves it. `first` is the first such point; `wide` the start
    // of the first stretch of air at least a rim search step long (the search steps over narrower
    // slivers, as a body does: the line passing a tooth's corner). On the decks here they are equal
    // but near corners.
    struct Rim {
        float first, wide;
    };
    Rim true_rim(const Vec3& start, const Vec3& heading) const {
        constexpr float kMm = 5e-4f;
        const Vec3 from = to_own(start), along = to_own(heading);
        Rim rim{-1.0f, -1.0f};
        float air_from = -1.0f;
        for (float t = 0.0f; t < 8.0f; t += kMm) {
            const Vec3 p = from + along * t;
            const bool air = height(p.x(), p.z()) < start.y() - kStepDown;
            if (!air) {
                air_from = -1.0f;
                continue;
            }
            if (air_from < 0.0f) air_from = t;
            if (rim.first < 0.0f) rim.first = t;
            if (t - air_from >= kRimStep) return Rim{rim.first, air_from};
        }
        return Rim{rim.first < 0.0f ? 8.0f : rim.first, 8.0f};
    }
};

// A face of a closed solid, fanned from its first corner, facing away from `inside`.
void add_face(GeneratedLevel& level, const std::vector<Vec3>& corners, const Vec3& inside) {
    const auto base = level.vertex_count();
    for (const Vec3& p : corners) level.positions.insert(level.positions.end(), {p.x(), p.y(), p.z()});
    const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const bool outward = normal.dot(corners[0] - inside) > 0.0f;
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) {
        if (outward)
            level.indices.insert(level.indices.end(), {base, base + k, base + k + 1});
        else
            level.indices.insert(level.indices.end(), {base, base + k + 1, base + k});
    }
}

bool inside_box(const Box& b, float x, float z) {
    return x >= b.min[0] && x <= b.max[0] && z >= b.min[2] && z <= b.max[2];
}

// A 30 m floor at height 0 and deck boxes on it; the deck boxes' tops are the surfaces above the floor.
RimLevel boxes_level(const std::vector<Box>& decks, float yaw) {
    RimLevel r;
    r.yaw = yaw;
    r.level.add_box(Box{{-10, -1, -10}, {25, 0, 20}});
    for (const Box& b : decks) r.level.add_box(b);
    r.height = [decks](float x, float z) {
        float h = 0.0f;
        for (const Box& b : decks)
            if (inside_box(b, x, z)) h = std::max(h, b.max[1]);
        return h;
    };
    r.turn();
    return r;
}

// A deck [0, 6] x [0, 10] whose +x lip has 0.5 m teeth, 1 m wide, on every other metre: a stepped rim.
// Teeth narrower than the body vanish from the navmesh, so its edge runs straight past them.
std::vector<Box> notched_deck(float x0, float x1, float tooth_x0, float tooth_x1, int first_strip) {
    std::vector<Box> boxes = {Box{{x0, 0, 0}, {x1, kDeck, 10}}};
    for (int strip = first_strip; strip < 10; strip += 2)
        boxes.push_back(Box{{tooth_x0, 0, float(strip)}, {tooth_x1, kDeck, float(strip + 1)}});
    return boxes;
}

// A deck [0, 6] x [0, 10] with a bevel along its +x side that falls 0.85 m (within a step: ground to a
// rim probe) and widens from 0.15 m at z = 0 to 0.85 m at z = 10, too steep to walk: the navmesh ends
// along the deck's top while the bevel's outer line runs diagonally to it.
RimLevel bevelled_level(float yaw) {
    RimLevel r;
    r.yaw = yaw;
    r.level.add_box(Box{{-10, -1, -10}, {25, 0, 20}});
    const float low = kDeck - 0.85f;
    auto outer = [](float z) { return 6.15f + 0.07f * z; };
    const Vec3 inside(3, 0.5f, 5);
    const Vec3 t0(0, kDeck, 0), t1(6, kDeck, 0), t2(6, kDeck, 10), t3(0, kDeck, 10);
    const Vec3 o0(outer(0), low, 0), o1(outer(10), low, 10);
    const Vec3 f0(outer(0), 0, 0), f1(outer(10), 0, 10), b0(0, 0, 0), b1(0, 0, 10);
    add_face(r.level, {t0, t1, t2, t3}, inside);
    add_face(r.level, {t1, o0, o1, t2}, inside);
    add_face(r.level, {o0, f0, f1, o1}, inside);
    add_face(r.level, {b0, b1, t3, t0}, inside);
    add_face(r.level, {b0, f0, o0, t1, t0}, inside);
    add_face(r.level, {b1, t3, t2, o1, f1}, inside);
    add_face(r.level, {b0, b1, f1, f0}, inside);
    r.height = [outer, low](float x, float z) {
        if (z < 0.0f || z > 10.0f || x < 0.0f) return 0.0f;
        if (x <= 6.0f) return kDeck;
        const float o = outer(z);
        return x <= o ? kDeck - (kDeck - low) * (x - 6.0f) / (o - 6.0f) : 0.0f;
    };
    r.turn();
    return r;
}

std::vector<Link> generate(const RimLevel& r, const nl::LinkSettings& settings = {}) {
    const nl::test::RecastWorld w = nl::test::recast_world(r.level, 2);
    nl::LinkGenerationReport report;
    return nl::generate_links(*w.mesh, w.world->level(), w.world->tasks(), settings, nl::GenerationMethod::Indexed,
                              report, nl::test::keep_going);
}

Vec3 flat(const Vec3& v) { return Vec3(v.x(), 0.0f, v.z()); }

// The deck's outward direction in the world (its +x, turned).
Vec3 deck_outward(const RimLevel& r) { return Vec3(std::cos(r.yaw), 0.0f, -std::sin(r.yaw)); }

// Every drop off the deck top leaves where its heading crosses the rim (to the rim search's last
// interval, on the air side), and records the gap from there; returns how many were turned from the
// deck's outward direction by more than 10 degrees.
int check_drops(const RimLevel& r, const std::vector<Link>& links) {
    int checked = 0, turned = 0;
    for (const Link& l : nl::test::links_of_kind(links, LinkKind::Drop)) {
        if (l.start.y() < kDeck - 0.01f) continue;  // from the bevel, not the deck top
        ++checked;
        const Vec3 out = flat(l.apex - l.start);
        const Vec3 heading = out.normalized();
        const float recorded = out.norm() - kPastRim;
        const RimLevel::Rim rim = r.true_rim(l.start, heading);
        const float widest = flat(l.end - (l.start + heading * rim.first)).norm();
        const float narrowest = flat(l.end - (l.start + heading * rim.wide)).norm();
        INFO("drop (" << l.start.transpose() << ") -> (" << l.end.transpose() << "), heading (" << heading.transpose()
                      << "): leaves at " << recorded << " m, the rim is " << rim.first << " to " << rim.wide
                      << " m out; gap " << l.requirements.gap << " m, truly " << narrowest << " to " << widest << " m");
        CHECK(recorded >= rim.first - 2e-3f);
        CHECK(recorded <= rim.wide + kHalving + 2e-3f);
        CHECK(l.requirements.gap <= widest + 2e-3f);
        CHECK(l.requirements.gap >= narrowest - kHalving - 2e-3f);
        if (heading.dot(deck_outward(r)) < std::cos(10.0f * 3.14159265f / 180.0f)) ++turned;
    }
    CHECK(checked >= 4);
    return turned;
}

}  // namespace

TEST_CASE("a drop turned from its edge leaves where its heading crosses a stepped rim") {
    for (const float degrees : {0.0f, 20.0f, 45.0f}) {
        INFO("deck turned " << degrees << " degrees");
        const RimLevel r = boxes_level(notched_deck(0, 6, 6, 6.5f, 0), degrees * 3.14159265f / 180.0f);
        const std::vector<Link> links = generate(r);
        CHECK(check_drops(r, links) >= 2);
    }
}

TEST_CASE("a drop turned from its edge leaves where its heading crosses a bevel that widens along it") {
    for (const float degrees : {0.0f, 20.0f, 45.0f}) {
        INFO("deck turned " << degrees << " degrees");
        const RimLevel r = bevelled_level(degrees * 3.14159265f / 180.0f);
        const std::vector<Link> links = generate(r);
        CHECK(check_drops(r, links) >= 2);
    }
}

TEST_CASE("a jump's gap is measured along its line, lip to lip, and none is wider than max_jump_gap") {
    // Two notched decks 3 m apart, their teeth staggered: 2.5 m from a tooth to the other deck, 3 m
    // lip to lip between teeth. With max_jump_gap 2.7 only lines that leave from or land on a tooth
    // may be jumped.
    nl::LinkSettings settings;
    settings.max_jump_gap = 2.7f;
    for (const float degrees : {0.0f, 20.0f, 45.0f}) {
        INFO("decks turned " << degrees << " degrees");
        std::vector<Box> boxes = notched_deck(0, 6, 6, 6.5f, 0);
        for (const Box& b : notched_deck(9, 15, 8.5f, 9, 1)) boxes.push_back(b);
        const RimLevel r = boxes_level(boxes, degrees * 3.14159265f / 180.0f);
        const std::vector<Link> jumps = nl::test::links_of_kind(generate(r, settings), LinkKind::Jump);
        CHECK(jumps.size() >= 2);
        for (const Link& l : jumps) {
            const Vec3 line = flat(l.end - l.start);
            const Vec3 heading = line.normalized();
            const RimLevel::Rim a = r.true_rim(l.start, heading), b = r.true_rim(l.end, -heading);
            const float widest = line.norm() - a.first - b.first, narrowest = line.norm() - a.wide - b.wide;
            INFO("jump (" << l.start.transpose() << ") -> (" << l.end.transpose() << "): gap " << l.requirements.gap
                          << " m, truly " << narrowest << " to " << widest << " m");
            CHECK(narrowest <= settings.max_jump_gap + 2e-3f);
            CHECK(l.requirements.gap <= widest + 2e-3f);
            CHECK(l.requirements.gap >= narrowest - 2.0f * kHalving - 2e-3f);
        }
    }
}
