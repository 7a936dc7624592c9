// Issue 13: links a body can really take. Procedural levels of boxes with exact answers, each saying
// what MUST exist (the control) and what MUST NOT; every link is also held to the independent checker
// (tests/support/independent_link_checker.h: its own exact cylinder-against-triangle test along the
// documented arc or fall, ends on the real floor, figures floor to floor).
//
// What they hold the generator to (docs/link-generation.md says it at length):
//  - body: upright cylinder of the agent's radius, from min(0.3, height / 4) to height above the path,
//    along the whole path but clearance_margin of its length (at most the radius) at each end;
//    touching is a hit;
//  - ends on the real floor; gap / rise / drop floor to floor; gap = in the air between the rims
//    (rim to rim for a jump, rim to landing for a drop); requirements.length = end to end;
//  - max_jump_gap = the widest gap (rim to rim) a jump may cross; max_jump_up = highest rise,
//    max_drop_distance = deepest drop, floor to floor; drops no deeper than max_climb are walked;
//  - rims to ~2 cm, so a designed 2.0 m gap records 2.0 +- 0.05;
//  - drops along every ledge too high to walk; one drop per take-off point per landing surface;
//  - no jump where walking is about as short (walk <= walk_factor x length + walk_distance).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core_world.h"
#include "generated_mesh.h"
#include "link_test_helpers.h"
#include "independent_link_checker.h"
#include "level_generator.h"
#include "links/generate_links.h"
#include "path/path_graph.h"
#include "path/path_planner.h"
#include "shared_levels.h"

using nl::Link;
using nl::LinkKind;
using nl::Vec3;
using nl::levelgen::Box;

// |a - b| <= tolerance, saying both values when it fails.
#define CHECK_NEAR(a, b, tolerance)                                                                          \
    CHECK_MESSAGE(std::fabs(double(a) - double(b)) <= double(tolerance), #a " = ", double(a), ", expected ", \
                  double(b), " +- ", double(tolerance))

namespace {

// ---------------------------------------------------------------------------------------------
// Generating a level

struct Generated {
    std::string name;
    std::vector<Link> links;
    nl::LinkGenerationReport report;
    nl::LinkSettings settings;
    nl::TriangleMesh triangles;  // world space, as the level holds them
    nl::AgentType agent;
    std::shared_ptr<const nl::NavMesh> navmesh;  // outlives the world (walks are measured on it)

    std::vector<Link> of(LinkKind kind) const { return nl::test::links_of_kind(links, kind); }
    std::string describe() const {
        std::ostringstream s;
        s << name << ": " << links.size() << " links (" << report.jump_links << " jumps, " << report.drop_links
          << " drops); samples " << report.samples << ", take-offs " << report.takeoff_points << ", jump candidates "
          << report.jump_candidates << ", drop candidates " << report.drop_candidates << "; rejected: wall "
          << report.rejected_wall << ", not ledge " << report.rejected_not_ledge << ", distance "
          << report.rejected_distance << ", rise " << report.rejected_rise << ", angle " << report.rejected_angle
          << ", no landing " << report.rejected_no_landing << ", clearance " << report.rejected_clearance
          << ", duplicate " << report.rejected_duplicate;
        s << ", walkable " << report.rejected_walkable << ", too shallow " << report.rejected_too_shallow
          << ", too deep " << report.rejected_too_deep;
        // The first 40 links (NAVLINK_TEST_ALL_LINKS=1 lists them all).
        const size_t shown = std::getenv("NAVLINK_TEST_ALL_LINKS") ? links.size() : std::min<size_t>(links.size(), 40);
        for (size_t i = 0; i < shown; ++i) s << "\n  " << nl::test::describe_link(links[i]);
        if (links.size() > shown)
            s << "\n  ... and " << links.size() - shown << " more (NAVLINK_TEST_ALL_LINKS=1 lists them)";
        return s.str();
    }
};

// Builds the navmesh with Recast's defaults and generates links with `settings`. `add` registers the
// level's geometry.
Generated generate_in_world(const std::string& name, const std::function<void(nl::World&)>& add,
                            const nl::LinkSettings& settings, nl::GenerationMethod method, int threads) {
    const auto world = nl::test::make_world(threads);
    add(*world);
    const nl::Handle navmesh = nl::test::build_recast_navmesh(*world);
    Generated out;
    out.name = name;
    out.settings = settings;
    out.navmesh = world->navmeshes().navmesh(navmesh);
    REQUIRE(out.navmesh);
    out.agent = out.navmesh->agent();
    out.triangles = world->level().world_triangles();
    out.links = nl::generate_links(*out.navmesh, world->level(), world->tasks(), settings, method, out.report,
                                   [](float, const char*) { return true; });
    return out;
}

Generated generate(const std::string& name, const std::vector<Box>& boxes, const nl::LinkSettings& settings = {},
                   nl::GenerationMethod method = nl::GenerationMethod::Indexed, int threads = 2) {
    return generate_in_world(
        name,
        [&](nl::World& world) {
            nl::levelgen::GeneratedLevel level;
            for (const Box& b : boxes) level.add_box(b);
            nl::test::add_level(world, level);
        },
        settings, method, threads);
}

Generated generate_for_obj(const std::string& path, const nl::LinkSettings& settings = {},
                           nl::GenerationMethod method = nl::GenerationMethod::Indexed, int threads = 2) {
    return generate_in_world(
        path, [&](nl::World& world) { nl::test::add_obj_file(world, path); }, settings, method, threads);
}

// ---------------------------------------------------------------------------------------------
// The independent checker over a generation

nl::test::CheckTally check_links(const Generated& b, nl::test::CheckerTolerances tolerances = {}) {
    const nl::test::CheckedAgent agent{b.agent.radius, b.agent.height, b.agent.max_climb};
    const nl::test::IndependentLinkChecker checker(b.triangles, agent, b.settings, tolerances);
    nl::test::CheckTally tally;
    for (const Link& l : b.links) tally.add(l, checker.check(l));
    return tally;
}

// Every link of the generation passes the checker: no body touching the level, ends on the floor, figures
// right. Inconclusive checks are counted and printed, not failed.
nl::test::CheckTally expect_checked(const Generated& b) {
    const nl::test::CheckTally t = check_links(b);
    std::ostringstream failures;
    for (const std::string& f : t.touching) failures << "\n    " << f;
    for (const std::string& f : t.failures) failures << "\n    " << f;
    INFO(b.name, ": checker: ", t.line(), failures.str());
    CHECK(t.touches == 0);
    CHECK(t.end_not_on_floor == 0);
    CHECK(t.wrong_figures == 0);
    if (t.inconclusive > 0) MESSAGE(b.name, ": ", t.inconclusive, " inconclusive link check(s) of ", t.links);
    return t;
}

// ---------------------------------------------------------------------------------------------
// Levels

constexpr float kDeep = -30.0f;  // floors this deep are out of every drop's reach

// Two 10 x 10 m platforms, tops at y = 0 and y = rise, rims at x = 10 and x = 10 + gap, over a floor
// too deep to drop to (only jumps connect them).
std::vector<Box> two_platforms(float gap, float rise = 0.0f) {
    return {Box{{0, -1, 0}, {10, 0, 10}}, Box{{10 + gap, rise - 1, 0}, {20 + gap, rise, 10}},
            Box{{-5, kDeep - 1, -5}, {25 + gap, kDeep, 15}}};
}

// A deck 6 x 10 m (x in [0, 6], z in [0, 10]) `height` high on a wide floor at y = 0: ledges on all
// four sides.
std::vector<Box> deck(float height) { return {Box{{-10, -1, -10}, {20, 0, 20}}, Box{{0, 0, 0}, {6, height, 10}}}; }

std::vector<Box> with(std::vector<Box> level, std::initializer_list<Box> more) {
    level.insert(level.end(), more.begin(), more.end());
    return level;
}

// ---------------------------------------------------------------------------------------------
// Reading links

float lo_x(const Link& l) { return std::min(l.start.x(), l.end.x()); }
float hi_x(const Link& l) { return std::max(l.start.x(), l.end.x()); }

// Jumps from one platform of two_platforms to the other.
std::vector<Link> crossing_jumps(const Generated& b, float gap) {
    std::vector<Link> out;
    for (const Link& l : b.of(LinkKind::Jump))
        if (lo_x(l) < 10.0f && hi_x(l) > 10.0f + gap) out.push_back(l);
    return out;
}

Vec3 flat(const Vec3& v) { return Vec3(v.x(), 0.0f, v.z()); }

// A drop's horizontal heading, start to end, as an angle from `axis` (degrees).
float heading_off(const Link& l, const Vec3& axis) {
    const Vec3 d = flat(l.end - l.start);
    if (d.norm() < 1e-4f) return 180.0f;
    return std::acos(std::clamp(d.normalized().dot(axis), -1.0f, 1.0f)) * 57.2957795f;
}

// Drops off one side of the deck: start within 1.2 m inside the rim and heading within 45 degrees
// of the side's outward direction. side: +x, -x, +z, -z as (axis, rim coordinate).
struct Side {
    std::string name;
    Vec3 outward;
    float rim;       // x or z of the rim
    bool along_x;    // rim is an x coordinate
    float from, to;  // extent of the ledge along it (z for an x rim, x for a z rim)
};
const Side kDeckSides[] = {{"+x", Vec3(1, 0, 0), 6.0f, true, 0.0f, 10.0f},
                           {"-x", Vec3(-1, 0, 0), 0.0f, true, 0.0f, 10.0f},
                           {"+z", Vec3(0, 0, 1), 10.0f, false, 0.0f, 6.0f},
                           {"-z", Vec3(0, 0, -1), 0.0f, false, 0.0f, 6.0f}};

bool off_side(const Link& l, const Side& s) {
    const float c = s.along_x ? l.start.x() : l.start.z();
    const float inside = (s.rim - c) * (s.along_x ? s.outward.x() : s.outward.z());  // >= 0 inside the rim
    return l.kind == LinkKind::Drop && inside >= -0.05f && inside <= 1.2f && heading_off(l, s.outward) < 45.0f;
}
float along_side(const Link& l, const Side& s) { return s.along_x ? l.start.z() : l.start.x(); }

std::vector<Link> drops_off(const Generated& b, const Side& s) {
    std::vector<Link> out;
    for (const Link& l : b.links)
        if (off_side(l, s)) out.push_back(l);
    return out;
}

// The widest stretch of the side's ledge with no drop starting in it (including both ends' stretch
// from the ledge's ends, less the agent radius the navmesh keeps back from each end).
float widest_hole(const std::vector<Link>& drops, const Side& s, float radius) {
    std::vector<float> at;
    for (const Link& l : drops) at.push_back(along_side(l, s));
    std::sort(at.begin(), at.end());
    const float from = s.from + radius, to = s.to - radius;
    if (at.empty()) return to - from;
    float hole = std::max(at.front() - from, to - at.back());
    for (size_t i = 1; i < at.size(); ++i) hole = std::max(hole, at[i] - at[i - 1]);
    return hole;
}

// The height difference the link covers, either way (rise + drop).
float height_of(const Link& l) { return l.requirements.rise + l.requirements.drop; }

// Walking distance between two points on foot (the navmesh alone, no link), or +inf.
double walk_length(const std::shared_ptr<const nl::NavMesh>& navmesh, const Vec3& a, const Vec3& b) {
    const nl::PathGraph graph(navmesh, std::make_shared<const nl::LinkSnapshot>());
    nl::PathQuery q;
    q.start = a;
    q.goal = b;
    q.accept_partial = false;
    nl::PathResult r;
    nl::plan_path(graph, q, nullptr, r);
    return r.outcome == nl::PathOutcome::Complete ? double(r.length) : std::numeric_limits<double>::infinity();
}

double walk_factor(const nl::LinkSettings& s) { return s.walk_factor; }
double walk_distance(const nl::LinkSettings& s) { return s.walk_distance; }

// Bit-for-bit comparison (as link_reference_tests.cpp compares).
bool bits_equal(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(float)) == 0; }
bool bits_equal(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool identical(const Link& a, const Link& b) {
    const nl::LinkRequirements &x = a.requirements, &y = b.requirements;
    return a.kind == b.kind && bits_equal(a.start, b.start) && bits_equal(a.end, b.end) && bits_equal(a.apex, b.apex) &&
           a.bidirectional == b.bidirectional && a.generated == b.generated && bits_equal(x.gap, y.gap) &&
           bits_equal(x.rise, y.rise) && bits_equal(x.drop, y.drop) &&
           bits_equal(x.clearance_width, y.clearance_width) && bits_equal(x.length, y.length) &&
           a.start_polygon == b.start_polygon && a.end_polygon == b.end_polygon;
}
std::string difference(const std::vector<Link>& a, const std::vector<Link>& b) {
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (!identical(a[i], b[i]))
            return "link " + std::to_string(i) + ": " + nl::test::describe_link(a[i]) + " vs " +
                   nl::test::describe_link(b[i]);
    if (a.size() != b.size()) return std::to_string(a.size()) + " links vs " + std::to_string(b.size());
    return {};
}

// Every procedural level of this file, by name, for the all-levels checks.
struct NamedLevel {
    std::string name;
    std::vector<Box> boxes;
    nl::LinkSettings settings;
};

// The bar, the poles, the beam and the ceilings, as designed above their tests.
const Box kBar{{10.95f, 1.75f, -1}, {11.05f, 1.85f, 11}};
std::vector<Box> poles_in_gap() {
    std::vector<Box> poles;
    for (int k = 0; k <= 24; ++k) {
        const float z = -0.75f + 0.5f * float(k);
        poles.push_back(Box{{10.95f, kDeep, z - 0.05f}, {11.05f, 5.0f, z + 0.05f}});
    }
    return poles;
}
const Box kBeam{{6.0f, 4.0f, -1}, {6.4f, 4.2f, 11}};  // over deck(2.2)'s +x rim, 1.8-2.0 m above its floor
const Box kWallBeside{{10.3f, kDeep, 4.85f}, {11.7f, 3.0f, 5.15f}};
const Box kBlockAbove{{10.5f, 4.5f, -1}, {11.5f, 5.0f, 11}};
const Box kLowCeiling{{10.0f, 2.2f, -1}, {12.0f, 2.6f, 11}};
const Box kFullWall{{10.8f, kDeep, -1}, {11.2f, 4.0f, 11}};

// A square pit 3 x 3 m (x, z in [0, 3]) in a floor at y = 0, 30 m deep.
std::vector<Box> pit() {
    return {Box{{-8, -1, -8}, {11, 0, 0}}, Box{{-8, -1, 3}, {11, 0, 11}}, Box{{-8, -1, 0}, {0, 0, 3}},
            Box{{3, -1, 0}, {11, 0, 3}}, Box{{-8, kDeep - 1, -8}, {11, kDeep, 11}}};
}
// A trench 2 m wide (x in [0, 2]) and 30 m long (z in [0, 30]) in a floor at y = 0, walked around
// only at its ends.
std::vector<Box> trench() {
    return {Box{{-12, -1, -5}, {0, 0, 35}}, Box{{2, -1, -5}, {14, 0, 35}}, Box{{0, -1, -5}, {2, 0, 0}},
            Box{{0, -1, 30}, {2, 0, 35}}, Box{{-12, kDeep - 1, -5}, {14, kDeep, 35}}};
}
// deck(4) with a platform 2 m high (x in [6, 10], z in [0, 4.5]) in front of part of its +x side:
// take-offs there land on it, or beside it on the floor. (A platform much smaller gets no navmesh:
// eroded by the radius it is under Recast's region_min_size, 8 x 8 cells.)
std::vector<Box> two_floors() { return with(deck(4.0f), {Box{{6, 0, 0}, {10, 2, 4.5f}}}); }

nl::LinkSettings with_max_jump_gap(float d) {
    nl::LinkSettings s;
    s.max_jump_gap = d;
    return s;
}

std::vector<NamedLevel> all_procedural_levels() {
    std::vector<NamedLevel> out;  // (the 2 m gap without anything in it is in the gaps below)
    out.push_back({"2 m gap, bar", with(two_platforms(2.0f), {kBar}), {}});
    {
        auto l = two_platforms(2.0f);
        for (const Box& p : poles_in_gap()) l.push_back(p);
        out.push_back({"2 m gap, poles", l, {}});
    }
    out.push_back({"2.2 m ledge", deck(2.2f), {}});
    out.push_back({"2.2 m ledge, beam", with(deck(2.2f), {kBeam}), {}});
    out.push_back({"2 m gap, wall beside", with(two_platforms(2.0f), {kWallBeside}), {}});
    out.push_back({"2 m gap, block above", with(two_platforms(2.0f), {kBlockAbove}), {}});
    out.push_back({"2 m gap, low ceiling", with(two_platforms(2.0f), {kLowCeiling}), {}});
    out.push_back({"2 m gap, full wall", with(two_platforms(2.0f), {kFullWall}), {}});
    out.push_back({"0.8 m step", deck(0.8f), {}});
    for (float h : {1.0f, 1.5f, 3.0f, 4.5f, 5.0f, 5.3f})
        out.push_back({std::to_string(h).substr(0, 3) + " m ledge", deck(h), {}});
    for (int g = 1; g <= 8; ++g) out.push_back({std::to_string(g) + " m gap", two_platforms(float(g)), {}});
    out.push_back({"6 m gap, max_jump_gap 6", two_platforms(6.0f), with_max_jump_gap(6.0f)});
    for (float r : {0.5f, 1.0f, 1.5f, 2.0f, 2.5f})
        out.push_back({std::to_string(r).substr(0, 3) + " m rise", two_platforms(2.0f, r), {}});
    out.push_back({"two floors", two_floors(), {}});
    out.push_back({"pit", pit(), {}});
    out.push_back({"trench", trench(), {}});
    return out;
}

// Prints what the closing note wants: links per level, drops per take-off point, checker verdicts.
// "Drops per take-off point" is over the take-off points that have a drop at all (a floor's outer
// rim over nothing has take-off points and never a drop); the report's ratio is printed too.
void print_figures(const Generated& b, const nl::test::CheckTally& t) {
    std::map<std::pair<long, long>, int> starts;
    for (const Link& l : b.of(LinkKind::Drop))
        ++starts[{std::lround(l.start.x() * 1000), std::lround(l.start.z() * 1000)}];
    const double per_start = starts.empty() ? 0.0 : double(b.report.drop_links) / double(starts.size());
    const double per_takeoff = b.report.takeoff_points ? double(b.report.drop_links) / b.report.takeoff_points : 0.0;
    // Jumps a body could walk about as quickly (the walk rule's figure).
    uint32_t walkable = 0;
    for (const Link& l : b.of(LinkKind::Jump)) {
        const double length = (flat(l.end) - flat(l.start)).norm();
        walkable +=
            walk_length(b.navmesh, l.start, l.end) <= walk_factor(b.settings) * length + walk_distance(b.settings);
    }
    MESSAGE(b.name, ": ", b.links.size(), " links (", b.report.jump_links, " jumps, ", walkable, " of them walkable; ",
            b.report.drop_links, " drops); ", b.report.takeoff_points, " take-off points, ", starts.size(),
            " with a drop: ", per_start, " drops per take-off point with one (", per_takeoff,
            " per take-off point); checker: ", t.line());
}

}  // namespace

// =============================================================================================
// The checker itself: it is the judge of everything below, so it is tested first.

TEST_CASE("independent checker: the exact cylinder-triangle test") {
    using nl::test::cylinder_meets_triangle;
    using nl::test::UprightCylinder;
    using V = nl::test::Vec3d;
    const UprightCylinder c{0.0, 0.0, 1.0, 3.0, 0.6};  // r 0.6, y in [1, 3]
    // A wall face: the plane x = d, spanning the slab.
    auto wall = [&](double d) { return cylinder_meets_triangle(c, V(d, 0, -5), V(d, 0, 5), V(d, 5, 0)); };
    CHECK(wall(0.599));
    CHECK(wall(0.6));  // touching is a hit
    CHECK_FALSE(wall(0.601));
    CHECK(wall(-0.5999));
    // A floor under the body and a ceiling over it; each touching at the slab's faces.
    auto level = [&](double y) { return cylinder_meets_triangle(c, V(-5, y, -5), V(5, y, -5), V(0, y, 5)); };
    CHECK_FALSE(level(0.999));
    CHECK(level(1.0));
    CHECK(level(2.0));  // a big horizontal triangle through the body, no corner or edge near it
    CHECK(level(3.0));
    CHECK_FALSE(level(3.001));
    // A thin bar (two long triangles) across the body at mid height: no corner inside, edges cross.
    CHECK(cylinder_meets_triangle(c, V(-5, 2.0, -0.05), V(5, 2.0, -0.05), V(5, 2.0, 0.05)));
    // A sloping triangle whose part within the slab lies outside the disc, though its corners
    // surround the axis from above (the slab clip matters).
    CHECK_FALSE(cylinder_meets_triangle(c, V(-5, 4, -5), V(5, 4, -5), V(0, 20, 5)));
    // A steep triangle entering the slab only far from the axis.
    CHECK_FALSE(cylinder_meets_triangle(c, V(2, 0, 0), V(3, 0, 1), V(2.5, 5, 0.5)));
    // A corner diagonal from the axis: distance sqrt(0.18) = 0.424 inside, 0.6+ outside.
    CHECK(cylinder_meets_triangle(c, V(0.3, 2, 0.3), V(4, 2, 0.3), V(0.3, 2, 4)));
    CHECK_FALSE(cylinder_meets_triangle(c, V(0.43, 2, 0.43), V(4, 2, 0.43), V(0.43, 2, 4)));
    // A vertical triangle seen edge-on from above, in line with the axis but past it.
    CHECK_FALSE(cylinder_meets_triangle(c, V(1, 0, 0), V(2, 0, 0), V(1.5, 5, 0)));
    CHECK(cylinder_meets_triangle(c, V(0.3, 0, 0), V(2, 0, 0), V(1.5, 5, 0)));        // x 0.54 at y = 1
    CHECK_FALSE(cylinder_meets_triangle(c, V(0.5, 0, 0), V(2, 0, 0), V(1.5, 5, 0)));  // x 0.7 at y = 1
}

TEST_CASE("independent checker: hand-made links over a gap with a bar, a floor and a pole") {
    // Two platforms 2 m apart (tops y = 0), a bar across the gap 1.75-1.85 m up, a pole beside.
    nl::levelgen::GeneratedLevel level;
    // The bar covers z in [-1, 4] only, the pole stands at z in [7.0, 7.1].
    for (const Box& b : with(two_platforms(2.0f), {Box{{10.95f, 1.75f, -1}, {11.05f, 1.85f, 4}},
                                                   Box{{10.95f, kDeep, 7.0f}, {11.05f, 5.0f, 7.1f}}}))
        level.add_box(b);
    nl::TriangleMesh mesh;
    for (uint32_t v = 0; v < level.vertex_count(); ++v)
        mesh.vertices.emplace_back(level.positions[3 * v], level.positions[3 * v + 1], level.positions[3 * v + 2]);
    for (uint32_t t = 0; t < level.triangle_count(); ++t)
        mesh.triangles.push_back({level.indices[3 * t], level.indices[3 * t + 1], level.indices[3 * t + 2]});
    const nl::LinkSettings settings;
    const nl::test::IndependentLinkChecker checker(mesh, nl::test::CheckedAgent{}, settings);
    CHECK(checker.floor_below(5, 5, 0.5, 2.0).value_or(-99.0) == doctest::Approx(0.0));
    CHECK_FALSE(checker.floor_below(11, 5, 0.5, 2.0).has_value());

    // A jump as the spec makes it: ends on the floor 0.7 m inside each rim, apex 1 m up, gap 2.
    auto jump = [](float z, float y_start = 0.0f, float y_end = 0.0f) {
        Link l;
        l.kind = LinkKind::Jump;
        l.start = Vec3(9.3f, y_start, z);
        l.end = Vec3(12.7f, y_end, z);
        l.apex = Vec3(11.0f, std::max(y_start, y_end) + 1.0f, z);
        l.bidirectional = true;
        l.requirements.gap = 2.0f;
        l.requirements.rise = std::max(0.0f, y_end - y_start);
        l.requirements.drop = std::max(0.0f, y_start - y_end);
        l.requirements.clearance_width = 2.4f;
        l.requirements.length = 3.4f;
        return l;
    };
    // Through the bar.
    const nl::test::LinkCheck through = checker.check(jump(2.0f));
    INFO(through.describe());
    CHECK(through.verdict == nl::test::LinkVerdict::Touches);
    REQUIRE(through.touch.has_value());
    CHECK(through.touch->path_point.x() > 10.0);
    CHECK(through.touch->path_point.x() < 12.0);
    CHECK(mesh.vertices[mesh.triangles[through.touch->triangle][0]].y() > 1.7f);  // the bar's
    // Between the bar's end and the pole, 1.5 m from each: clear and wide.
    const nl::test::LinkCheck open = checker.check(jump(5.5f));
    INFO(open.describe());
    CHECK(open.verdict == nl::test::LinkVerdict::Ok);
    CHECK_NEAR(open.gap, 2.0, 0.005);
    CHECK(open.clearance_width == doctest::Approx(2.4f));
    // Beside the pole (its face 0.65 m from the path): the agent fits, a 1.5 r body does not.
    Link beside = jump(7.0f - 0.65f);
    beside.requirements.clearance_width = 1.2f;
    const nl::test::LinkCheck b = checker.check(beside);
    INFO(b.describe());
    CHECK(b.verdict == nl::test::LinkVerdict::Ok);
    CHECK(b.clearance_width == doctest::Approx(1.2f));
    beside.requirements.clearance_width = 2.4f;  // overstated
    CHECK(checker.check(beside).verdict == nl::test::LinkVerdict::WrongFigures);
    // Into the pole: touches.
    CHECK(checker.check(jump(7.0f - 0.55f)).verdict == nl::test::LinkVerdict::Touches);
    // Ends floating 0.2 m above the floor (the navmesh's height), figures from those ends.
    Link floating = jump(5.5f, 0.2f, 0.2f);
    const nl::test::LinkCheck f = checker.check(floating);
    INFO(f.describe());
    CHECK(f.end_not_on_floor);
    // A recorded gap that is end to end, not rim to rim.
    Link end_to_end = jump(5.5f);
    end_to_end.requirements.gap = 3.4f;
    const nl::test::LinkCheck e = checker.check(end_to_end);
    INFO(e.describe());
    CHECK(e.verdict == nl::test::LinkVerdict::WrongFigures);

    // A drop off the east platform's far rim (x = 22) to the deep floor: its rim is found, and it is
    // far deeper than max_drop_distance.
    Link drop;
    drop.kind = LinkKind::Drop;
    drop.start = Vec3(21.3f, 0.0f, 5.0f);
    drop.end = Vec3(23.5f, kDeep, 5.0f);
    drop.apex = Vec3(22.2f, 0.0f, 5.0f);
    drop.requirements.gap = 1.5f;
    drop.requirements.drop = -kDeep;
    drop.requirements.clearance_width = 2.4f;
    const nl::test::LinkCheck d = checker.check(drop);
    INFO(d.describe());
    CHECK_NEAR(d.rim_start, 0.7, 0.002);
    CHECK(d.wrong_figures);  // 30 m deeper than max_drop_distance
    CHECK_FALSE(d.touches);
}

// The level's triangles as the checker takes them.
nl::TriangleMesh mesh_of(const std::vector<Box>& boxes) {
    nl::levelgen::GeneratedLevel level;
    for (const Box& b : boxes) level.add_box(b);
    return nl::test::to_triangle_mesh(level);
}

TEST_CASE("independent checker: hand-made drops off a 3 m ledge, under a beam and in the open") {
    // deck(3): rim at x = 6, floor 3 m below. The beam over the rim 1.8-2.0 m above the deck.
    const nl::LinkSettings settings;
    const nl::test::IndependentLinkChecker open(mesh_of(deck(3.0f)), nl::test::CheckedAgent{}, settings);
    const nl::test::IndependentLinkChecker beamed(mesh_of(with(deck(3.0f), {Box{{6.0f, 4.8f, -1}, {6.4f, 5.0f, 11}}})),
                                                  nl::test::CheckedAgent{}, settings);
    Link drop;
    drop.kind = LinkKind::Drop;
    drop.start = Vec3(5.3f, 3.0f, 5.0f);
    drop.end = Vec3(8.0f, 0.0f, 5.0f);
    drop.apex = Vec3(6.2f, 3.0f, 5.0f);  // where the fall leaves the ground: 0.2 m past the rim
    drop.requirements.gap = 2.0f;        // rim (x = 6) to landing
    drop.requirements.drop = 3.0f;
    drop.requirements.clearance_width = 2.4f;
    drop.requirements.length = 2.7f;
    const nl::test::LinkCheck ok = open.check(drop);
    INFO(ok.describe());
    CHECK(ok.verdict == nl::test::LinkVerdict::Ok);
    CHECK_NEAR(ok.rim_start, 0.7, 0.002);
    CHECK_NEAR(ok.path_length, 0.9 + 1.8 + 3.0, 1e-6);  // out to the rim + 0.2, across, down
    const nl::test::LinkCheck hit = beamed.check(drop);
    INFO(hit.describe());
    CHECK(hit.verdict == nl::test::LinkVerdict::Touches);
    REQUIRE(hit.touch.has_value());
    CHECK(hit.touch->path_point.y() == doctest::Approx(3.0));  // walking out or across, at take-off height
    // The out point given in the apex (what the spec could record): a probe turned 30 degrees.
    Link turned = drop;
    turned.apex = Vec3(5.3f + 0.9f, 3.0f, 5.0f + 0.52f);
    turned.end = Vec3(8.0f, 0.0f, 6.0f);
    turned.requirements.gap = float((Eigen::Vector2d(8.0, 6.0) - Eigen::Vector2d(6.0, 5.0 + 0.7 * 0.52 / 0.9)).norm());
    turned.requirements.length = float((Eigen::Vector2d(8.0, 6.0) - Eigen::Vector2d(5.3, 5.0)).norm());
    const nl::test::LinkCheck t = open.check(turned);
    INFO(t.describe());
    CHECK(t.verdict == nl::test::LinkVerdict::Ok);
    CHECK_NEAR(t.path_length, std::hypot(0.9, 0.52) + std::hypot(8.0 - 6.2, 6.0 - 5.52) + 3.0, 1e-5);
    // Too shallow and too deep for the settings.
    Link shallow = drop;
    shallow.end.y() = 2.5f;
    shallow.requirements.drop = 0.5f;
    CHECK(open.check(shallow).end_not_on_floor);  // nothing to stand on 0.5 m under the deck
}

// =============================================================================================
// 1. Thin geometry must not slip between the sweep's lines.

TEST_CASE("a bar across a 2 m gap 1.75-1.85 m above the floor: no jump through it; without the bar, jumps") {
    const Generated control = generate("2 m gap", two_platforms(2.0f));
    const Generated barred = generate("2 m gap, bar", with(two_platforms(2.0f), {kBar}));
    {
        INFO(control.describe());
        CHECK(crossing_jumps(control, 2.0f).size() >= 3);  // MUST: the gap is jumped (control)
        expect_checked(control);
    }
    INFO(barred.describe());
    CHECK(crossing_jumps(barred, 2.0f).empty());  // MUST NOT: every jump across meets the bar
    CHECK(barred.report.rejected_clearance > 0);
    expect_checked(barred);
}

TEST_CASE("0.1 m poles 0.5 m apart standing in a 2 m gap: no jump between them; without poles, jumps") {
    auto level = two_platforms(2.0f);
    for (const Box& p : poles_in_gap()) level.push_back(p);
    const Generated poles = generate("2 m gap, poles", level);
    INFO(poles.describe());
    // The body (1.2 m wide) cannot pass a 0.4 m opening. The control is the previous test's.
    CHECK(crossing_jumps(poles, 2.0f).empty());
    CHECK(poles.report.rejected_clearance > 0);
    expect_checked(poles);
}

TEST_CASE("a 0.4 m beam 1.8-2.0 m above a 2.2 m ledge's floor just past its rim: no drop walks out under it") {
    const Generated control = generate("2.2 m ledge", deck(2.2f));
    const Generated beamed = generate("2.2 m ledge, beam", with(deck(2.2f), {kBeam}));
    const Side& east = kDeckSides[0];
    {
        INFO(control.describe());
        CHECK(drops_off(control, east).size() >= 5);  // MUST (control): drops all along the +x side
        expect_checked(control);
    }
    INFO(beamed.describe());
    CHECK(drops_off(beamed, east).empty());  // MUST NOT: the head meets the beam walking out
    for (int side = 1; side < 4; ++side)     // the other sides are not affected
        CHECK(drops_off(beamed, kDeckSides[side]).size() == drops_off(control, kDeckSides[side]).size());
    expect_checked(beamed);
}

// =============================================================================================
// 2. A body overlapping a solid is refused, whether or not a line crosses a face.

TEST_CASE(
    "a drop beside a tall block: refused when the block's face is closer than the radius, kept at radius + 0.3 m") {
    // deck(4.5); a block 10 m tall stands on the lower floor against the deck's +x face (x in [6, 12],
    // past where the fall lands), its face z = face parallel to a straight-out drop. Placed so, the
    // part of the path checked (10 % cut at each end: the cut falls past x = 6 on a fall this long)
    // starts inside the block on the block's side, so a sweep line offset toward it never crosses a
    // face (issue 13, finding 2); an exact body test sees the overlap.
    const Generated control = generate("4.5 m ledge", deck(4.5f));
    const Side& east = kDeckSides[0];
    // The take-off to put the block beside: the straight-out drop nearest the middle of the side.
    const Link* chosen = nullptr;
    for (const Link& l : control.links)
        if (off_side(l, east) && heading_off(l, east.outward) < 5.0f &&
            (!chosen || std::fabs(l.start.z() - 5.0f) < std::fabs(chosen->start.z() - 5.0f)))
            chosen = &l;
    INFO(control.describe());
    REQUIRE_MESSAGE(chosen != nullptr, "no straight-out drop off the +x side to put the block beside");
    const float z = chosen->start.z(), r = control.agent.radius;
    auto block_at = [&](float face) { return with(deck(4.5f), {Box{{6.0f, 0, face}, {12, 10, face + 4}}}); };
    auto straight_from = [&](const Generated& b) {
        std::vector<Link> out;
        for (const Link& l : b.links)
            if (l.kind == LinkKind::Drop && (flat(l.start) - flat(chosen->start)).norm() < 0.05f &&
                heading_off(l, east.outward) < 10.0f)
                out.push_back(l);
        return out;
    };
    // The block must leave the deck's edge through the chosen take-off as it was (so the take-off
    // is still sampled there): else this test proves nothing, and says so.
    auto same_edge = [&](const Generated& b) {
        auto edge_through = [&](const nl::NavMesh& m) -> std::optional<std::pair<Vec3, Vec3>> {
            for (const nl::BoundaryEdge& e : m.boundary_edges()) {
                if (Vec3(e.outward.x(), 0, e.outward.z()).normalized().dot(east.outward) < 0.98f) continue;
                if (std::fabs(e.start.y() - chosen->start.y()) > 0.5f) continue;
                const Vec3 a = flat(e.start), d = flat(e.end) - a, p = flat(chosen->start);
                const float t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0f, 1.0f);
                if ((a + t * d - p).norm() < 0.01f) return std::pair{e.start, e.end};
            }
            return std::nullopt;
        };
        const auto before = edge_through(*control.navmesh), after = edge_through(*b.navmesh);
        return before && after && (before->first - after->first).norm() < 1e-3f &&
               (before->second - after->second).norm() < 1e-3f;
    };

    SUBCASE("the face 0.2 m from the drop's axis: the body overlaps the block by 0.4 m") {
        const Generated close = generate("4.5 m ledge, block 0.2 m beside", block_at(z + 0.2f));
        INFO(close.describe());
        REQUIRE_MESSAGE(same_edge(close), "the block moved the deck's edge: move the block");
        CHECK(straight_from(close).empty());  // MUST NOT
        // No drop anywhere whose straight walk out passes within the radius of the face.
        for (const Link& l : close.of(LinkKind::Drop))
            if (off_side(l, east) && heading_off(l, east.outward) < 5.0f && l.start.z() < z + 0.2f)
                CHECK_MESSAGE(l.start.z() <= z + 0.2f - r + 1e-3f, nl::test::describe_link(l));
        expect_checked(close);
    }
    SUBCASE("the face at radius + 0.3 m: kept, as wide as 2 radii (a 1.5 r body touches)") {
        const Generated kept = generate("4.5 m ledge, block r + 0.3 m beside", block_at(z + r + 0.3f));
        INFO(kept.describe());
        REQUIRE_MESSAGE(same_edge(kept), "the block moved the deck's edge: move the block");
        const std::vector<Link> drops = straight_from(kept);
        REQUIRE(drops.size() == 1);  // MUST, and one per way down
        CHECK(drops[0].requirements.clearance_width == doctest::Approx(2.0f * r));
        // Control: without the block the same drop is as wide as 4 radii.
        const std::vector<Link> free = straight_from(control);
        REQUIRE(free.size() == 1);
        CHECK(free[0].requirements.clearance_width == doctest::Approx(4.0f * r));
        expect_checked(kept);
    }
}

// =============================================================================================
// Controls and blockers around a 2 m gap.

TEST_CASE(
    "around a 2 m gap: a 0.3 m wall beside the jump and a block 4.5 m above keep it; a low ceiling or a full wall stop "
    "it") {
    const Generated control = generate("2 m gap", two_platforms(2.0f));
    const size_t control_jumps = crossing_jumps(control, 2.0f).size();
    REQUIRE(control_jumps >= 3);
    const float r = control.agent.radius;

    SUBCASE("a 0.3 m wall standing in the gap along the jumps (z 4.85-5.15)") {
        const Generated b = generate("2 m gap, wall beside", with(two_platforms(2.0f), {kWallBeside}));
        INFO(b.describe());
        const auto jumps = crossing_jumps(b, 2.0f);
        bool below = false, above = false;
        for (const Link& l : jumps) {
            const float zs = l.start.z(), ze = l.end.z();
            below = below || (zs < 4.85f - r - 0.05f && ze < 4.85f - r - 0.05f);
            above = above || (zs > 5.15f + r + 0.05f && ze > 5.15f + r + 0.05f);
            // MUST NOT: a straight jump whose body overlaps the wall.
            const bool straight = std::fabs(zs - ze) < 0.05f;
            if (straight) CHECK_MESSAGE((zs <= 4.85f - r || zs >= 5.15f + r), nl::test::describe_link(l));
        }
        CHECK(below);  // MUST: jumps on both sides of the wall
        CHECK(above);
        expect_checked(b);
    }
    SUBCASE("a block 4.5-5.0 m above the gap, above the arc and the body: the same jumps as without it") {
        const Generated b = generate("2 m gap, block above", with(two_platforms(2.0f), {kBlockAbove}));
        INFO(b.describe());
        const auto jumps = crossing_jumps(b, 2.0f), free = crossing_jumps(control, 2.0f);
        CHECK(jumps.size() == free.size());
        for (size_t i = 0; i < std::min(jumps.size(), free.size()); ++i) {
            CHECK(jumps[i].start == free[i].start);
            CHECK(jumps[i].end == free[i].end);
            CHECK(jumps[i].requirements.clearance_width == free[i].requirements.clearance_width);
        }
        expect_checked(b);
    }
    SUBCASE("a low ceiling over the gap only, 2.2 m above the floor: in the way") {
        const Generated b = generate("2 m gap, low ceiling", with(two_platforms(2.0f), {kLowCeiling}));
        INFO(b.describe());
        CHECK(crossing_jumps(b, 2.0f).empty());
        CHECK(b.report.rejected_clearance > 0);
        expect_checked(b);
    }
    SUBCASE("a full wall across the gap, 4 m high") {
        const Generated b = generate("2 m gap, full wall", with(two_platforms(2.0f), {kFullWall}));
        INFO(b.describe());
        CHECK(crossing_jumps(b, 2.0f).empty());
        CHECK(b.report.rejected_clearance > 0);
        expect_checked(b);
    }
}

// =============================================================================================
// 3, 4. Ends on the real floor; drops along every ledge too high to walk, floor to floor.

TEST_CASE(
    "ledges of 1.0, 1.5, 3, 5 and 5.3 m under max_drop_distance 5: drops along the whole ledge up to 5 m, none at 5.3 "
    "m") {
    for (float h : {1.0f, 1.5f, 3.0f, 5.0f, 5.3f}) {
        const Generated b = generate(std::to_string(h).substr(0, 3) + " m ledge", deck(h));
        CAPTURE(h);
        INFO(b.describe());
        const float r = b.agent.radius;
        if (h <= b.settings.max_drop_distance) {
            for (const Side& s : kDeckSides) {
                CAPTURE(s.name);
                const auto drops = drops_off(b, s);
                CHECK(!drops.empty());
                // MUST: along the whole side, not only at its ends: no stretch of 2 m without a drop.
                CHECK(widest_hole(drops, s, r) <= 2.0f);
                for (const Link& l : drops) {
                    CHECK_NEAR(l.requirements.drop, h, 0.05);  // floor to floor
                    CHECK(l.requirements.rise == 0.0f);
                    // One-way unless an agent can jump back up (docs: drop <= max_jump_up); 1.5 m
                    // is that limit exactly, so it is not asserted either way.
                    if (std::fabs(h - b.settings.max_jump_up) > 0.1f)
                        CHECK(l.bidirectional == (h < b.settings.max_jump_up));
                }
            }
        } else {
            CHECK(b.of(LinkKind::Drop).empty());  // MUST NOT: 5.3 m floor to floor is beyond 5
            CHECK(b.report.rejected_too_deep > 0);
        }
        CHECK(b.of(LinkKind::Jump).empty());
        print_figures(b, expect_checked(b));
    }
}

TEST_CASE("a 0.8 m step is walked: no drop") {
    const Generated b = generate("0.8 m step", deck(0.8f));
    INFO(b.describe());
    CHECK(b.of(LinkKind::Drop).empty());
    expect_checked(b);
}

// =============================================================================================
// 6. One meaning of gap: rim to rim, limited by max_jump_gap.

TEST_CASE("gaps of 1 to 8 m: jumps exactly up to max_jump_gap (rim to rim), gap recorded to 5 cm") {
    auto expect_gap = [](float gap, const nl::LinkSettings& settings) {
        std::ostringstream name;
        name << gap << " m gap";
        const Generated b = generate(name.str(), two_platforms(gap), settings);
        CAPTURE(gap);
        CAPTURE(settings.max_jump_gap);
        INFO(b.describe());
        const auto jumps = crossing_jumps(b, gap);
        if (gap <= settings.max_jump_gap) {
            CHECK(jumps.size() >= 3);  // MUST
            for (const Link& l : jumps) {
                CHECK_NEAR(l.requirements.gap, gap, 0.05);                                // rim to rim
                CHECK(l.requirements.gap < (flat(l.end) - flat(l.start)).norm() - 0.5f);  // not end to end
                CHECK_NEAR(l.requirements.length, (flat(l.end) - flat(l.start)).norm(), 0.01);
            }
        } else {
            CHECK(jumps.empty());  // MUST NOT
        }
        expect_checked(b);
    };
    // Rims are found to a couple of centimetres, so no design sits on a limit: 5 cm either side.
    SUBCASE("max_jump_gap 4 (the default)") {
        for (float g : {1.0f, 2.0f, 3.0f, 3.95f, 4.05f, 5.0f, 6.0f, 7.0f, 8.0f}) expect_gap(g, nl::LinkSettings{});
    }
    SUBCASE("max_jump_gap 6") {
        for (float g : {5.0f, 5.95f, 6.05f, 7.0f}) expect_gap(g, with_max_jump_gap(6.0f));
    }
}

TEST_CASE("rises of 0.5 to 2.5 m across a 2 m gap: jumps up to max_jump_up (1.5) only, rise floor to floor") {
    for (float rise : {0.5f, 1.0f, 1.5f, 2.0f, 2.5f}) {
        const Generated b = generate(std::to_string(rise).substr(0, 3) + " m rise", two_platforms(2.0f, rise));
        CAPTURE(rise);
        INFO(b.describe());
        const auto jumps = crossing_jumps(b, 2.0f);
        if (rise <= b.settings.max_jump_up) {
            CHECK(jumps.size() >= 3);  // MUST
            for (const Link& l : jumps) {
                CHECK(l.bidirectional);
                CHECK_NEAR(height_of(l), rise, 0.05);
                // The recorded direction: rise when the end is on the high platform.
                const bool up = l.end.x() > l.start.x();
                CHECK_NEAR(l.requirements.rise, up ? rise : 0.0f, 0.05);
                CHECK_NEAR(l.requirements.gap, 2.0f, 0.05);
            }
        } else {
            CHECK(jumps.empty());  // MUST NOT (a drop down from the high side may remain)
            for (const Link& l : b.of(LinkKind::Drop)) {
                CHECK_FALSE(l.bidirectional);
                CHECK(l.start.y() > l.end.y());
            }
        }
        print_figures(b, expect_checked(b));
    }
}

// =============================================================================================
// 5. Fewer, better links: one drop per way down.

TEST_CASE("one drop per way down: a straight ledge over one floor; a ledge over two floors keeps both") {
    SUBCASE("deck(3): at most one drop per take-off point, about one per metre of ledge") {
        const Generated b = generate("3 m ledge", deck(3.0f));
        INFO(b.describe());
        for (const Side& s : kDeckSides) {
            CAPTURE(s.name);
            const auto drops = drops_off(b, s);
            const float length = s.to - s.from;
            MESSAGE("3 m ledge, side ", s.name, ": ", drops.size(), " drops along ", length, " m");
            CHECK(float(drops.size()) <= 1.1f * length);  // ~1 per metre (one per 1 m sample), not 2-3
        }
        std::map<std::pair<long, long>, int> per_start;
        for (const Link& l : b.of(LinkKind::Drop))
            ++per_start[{std::lround(l.start.x() * 1000), std::lround(l.start.z() * 1000)}];
        for (const auto& entry : per_start) {
            const long x = entry.first.first, z = entry.first.second;  // (clang 14 captures no bindings)
            CAPTURE(x);
            CAPTURE(z);
            CHECK(entry.second == 1);  // one landing floor: one drop per take-off point
        }
        CHECK(b.report.drop_links <= b.report.takeoff_points);
        print_figures(b, expect_checked(b));
    }
    SUBCASE("deck(4) with a 2 m platform in front of part of its +x side") {
        const Generated b = generate("two floors", two_floors());
        INFO(b.describe());
        // Group drops by take-off point, then by landing floor (height band).
        std::map<std::pair<long, long>, std::vector<float>> landings;
        for (const Link& l : b.of(LinkKind::Drop))
            landings[{std::lround(l.start.x() * 1000), std::lround(l.start.z() * 1000)}].push_back(l.end.y());
        bool both = false;
        for (auto& entry : landings) {
            const double x = entry.first.first / 1000.0,
                         z = entry.first.second / 1000.0;  // (clang 14 captures no bindings)
            std::vector<float>& ys = entry.second;
            std::sort(ys.begin(), ys.end());
            for (size_t i = 1; i < ys.size(); ++i)
                CHECK_MESSAGE(ys[i] - ys[i - 1] > 0.5f, "two drops from one take-off onto one floor, at x ", x, " z ",
                              z);
            both = both || (ys.size() >= 2 && ys.back() - ys.front() > 1.5f);
        }
        CHECK(both);  // MUST: a take-off whose probes reach both floors keeps a drop to each
        print_figures(b, expect_checked(b));
    }
}

// =============================================================================================
// 5. No jump where walking is about as short.

TEST_CASE("no jump where walking is about as short: across a pit's corner; a long trench keeps its jump") {
    SUBCASE("a 3 x 3 m pit in a floor") {
        const Generated b = generate("pit", pit());
        INFO(b.describe());
        const double factor = walk_factor(b.settings), extra = walk_distance(b.settings);
        for (const Link& l : b.of(LinkKind::Jump)) {
            const double length = (flat(l.end) - flat(l.start)).norm();
            const double walk = walk_length(b.navmesh, l.start, l.end);
            // MUST NOT: a jump whose ends are walked within factor x length + distance (10 % slack
            // for how the generator and the path planner measure the walk).
            CHECK_MESSAGE(walk > 0.9 * (factor * length + extra), nl::test::describe_link(l), ": walk ", walk,
                          " m for a ", length, " m jump");
            // In particular none across the corner: ends on two adjacent sides of the pit.
            auto side = [](const Vec3& p) { return p.x() < 0 ? 0 : p.x() > 3 ? 1 : p.z() < 0 ? 2 : p.z() > 3 ? 3 : 4; };
            const int a = side(l.start), c = side(l.end);
            CHECK_MESSAGE((a / 2 == c / 2 || a == 4 || c == 4),
                          "a jump across the pit's corner: ", nl::test::describe_link(l));
        }
        CHECK(b.report.rejected_walkable > 0);
        print_figures(b, expect_checked(b));
    }
    SUBCASE("a trench 2 m wide, 30 m long: in its middle the walk around is 30 m") {
        const Generated b = generate("trench", trench());
        INFO(b.describe());
        const double factor = walk_factor(b.settings), extra = walk_distance(b.settings);
        size_t middle = 0;
        for (const Link& l : b.of(LinkKind::Jump)) {
            const double length = (flat(l.end) - flat(l.start)).norm();
            const double walk = walk_length(b.navmesh, l.start, l.end);
            CHECK_MESSAGE(walk > 0.9 * (factor * length + extra), nl::test::describe_link(l), ": walk ", walk, " m");
            if (lo_x(l) < 0 && hi_x(l) > 2 && l.start.z() > 10 && l.start.z() < 20) ++middle;
        }
        CHECK(middle >= 5);  // MUST: jumps across the middle stretch (one per metre or so)
        print_figures(b, expect_checked(b));
    }
}

// =============================================================================================
// Everything above, and the shared levels, against the checker; the reference and thread counts.

TEST_CASE("every link of every procedural level passes the independent checker; figures per level") {
    nl::test::CheckTally total;
    uint32_t takeoffs = 0, drops = 0;
    for (const NamedLevel& level : all_procedural_levels()) {
        const Generated b = generate(level.name, level.boxes, level.settings);
        const nl::test::CheckTally t = expect_checked(b);
        print_figures(b, t);
        total.add(t);
        takeoffs += b.report.takeoff_points;
        drops += b.report.drop_links;
    }
    MESSAGE("procedural levels in all: ", total.line(), "; ", drops, " drops from ", takeoffs, " take-off points");
}

TEST_CASE("every link of every shared level passes the independent checker; figures per level") {
    const auto levels = nl::test::shared_levels();
    if (levels.empty()) {
        if (nl::test::levels_required()) FAIL("no shared levels in ", nl::test::levels_dir().string());
        MESSAGE("no shared levels in ", nl::test::levels_dir().string(), ": skipped");
        return;
    }
    nl::test::CheckTally total;
    uint32_t takeoffs = 0, drops = 0;
    for (const auto& path : levels) {
        Generated b = generate_for_obj(path.string());
        b.name = path.stem().string();
        const nl::test::CheckTally t = expect_checked(b);
        print_figures(b, t);
        total.add(t);
        takeoffs += b.report.takeoff_points;
        drops += b.report.drop_links;
        // No jump a body could simply walk (the walk rule holds on real levels too).
        const double factor = walk_factor(b.settings), extra = walk_distance(b.settings);
        for (const Link& l : b.of(LinkKind::Jump)) {
            const double length = (flat(l.end) - flat(l.start)).norm();
            const double walk = walk_length(b.navmesh, l.start, l.end);
            CHECK_MESSAGE(walk > 0.9 * (factor * length + extra), b.name, ": ", nl::test::describe_link(l), ": walk ",
                          walk, " m");
        }
    }
    MESSAGE("shared levels in all: ", total.line(), "; ", drops, " drops from ", takeoffs, " take-off points");
}

TEST_CASE("the brute-force reference and 1 or 2 threads give the same links on these levels") {
    for (const NamedLevel& level : all_procedural_levels()) {
        CAPTURE(level.name);
        const Generated grid_2 = generate(level.name, level.boxes, level.settings, nl::GenerationMethod::Indexed, 2);
        const Generated grid_1 = generate(level.name, level.boxes, level.settings, nl::GenerationMethod::Indexed, 1);
        const Generated all_1 = generate(level.name, level.boxes, level.settings, nl::GenerationMethod::BruteForce, 1);
        const std::string threads = difference(grid_1.links, grid_2.links);
        CHECK_MESSAGE(threads.empty(), "1 worker vs 2: ", threads);
        const std::string reference = difference(all_1.links, grid_1.links);
        CHECK_MESSAGE(reference.empty(), "brute force vs indexed: ", reference);
    }
}
