// An independent checker for generated jump and drop links (issue 13): it rebuilds each link's
// documented path from the link itself and proves, with geometry code of its own (nothing from
// sdk/level/swept_body.* or sdk/links/clearance.*), that an upright cylinder of the agent's size
// touches no triangle of the level anywhere along the checked part of the path; it also checks that
// the link's ends stand on the real floor and that its recorded figures (gap, rise, drop, length,
// clearance width, apex) are the floor-to-floor values.
//
// What it checks, per link (the spec of issue 13):
//  - The body: a vertical cylinder of radius r from `lift` = min(0.3, height / 4) above the path
//    point up to `height` above it, along the whole path except `clearance_margin` of its length at
//    each end. Touching is a hit.
//  - The path: a jump is the parabola from start to end (x and z linear in the horizontal fraction t,
//    y(t) = start.y + b t + c t^2) whose top is at the link's apex height; a drop walks out from the
//    start along its heading to the rim + 0.2 m at take-off height, goes across at that height to
//    above the landing, then straight down to the end.
//  - How: the checked part is cut into pieces of at most `sample_step`; at every cut the static
//    cylinder is tested exactly against every nearby triangle (the triangle clipped to the
//    cylinder's height slab, then the disc against the clipped polygon seen from above). A piece is
//    proven clear when one cylinder holding every body along it (centred on the piece's middle,
//    widened by half the piece's horizontal travel, its slab spanning the piece's lowest and highest
//    points) touches nothing; otherwise the piece is halved, down to `finest_step`, and a piece
//    still not proven either way is "inconclusive", never "clear".
//  - Ends: a vertical ray (own code) from 0.5 m above each end, 2 m down; the end must be within
//    `floor_tolerance` of the first surface it meets.
//  - Figures: rise and drop against the floors found; a jump's gap against the rims the checker
//    finds itself along the jump's heading (rim to rim), a drop's against rim to landing; length (if
//    the Link has it) against the horizontal distance end to end; a jump's apex against the
//    documented arc; clearance_width against the widest of the bodies of radius r, 1.5 r, 2 r the
//    checker proves clear; the settings' limits against those figures.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "level/geometry.h"
#include "links/link.h"
#include "links/link_settings.h"

namespace nl::test {

using Vec3d = Eigen::Vector3d;

// The agent the navmesh was built for (NavMesh::agent()).
struct CheckedAgent {
    double radius = 0.6;
    double height = 2.0;
    double max_climb = 0.9;
};

// An upright cylinder: axis vertical through (x, z), from y0 up to y1.
struct UprightCylinder {
    double x, z, y0, y1, radius;
};

// Exact: whether the closed cylinder and the closed triangle share a point (touching counts).
bool cylinder_meets_triangle(const UprightCylinder& cylinder, const Vec3d& a, const Vec3d& b, const Vec3d& c);

struct CheckerTolerances {
    double sample_step = 0.05;       // longest piece of path before subdivision (metres of path)
    double finest_step = 0.002;      // pieces are not halved below this; then "inconclusive"
    double touch_margin = 0.0005;    // a body this close to a triangle (padded by it) "touches"
    double clear_margin = 0.001;     // "clear" means the body padded by this touches nothing (the
                                     // spec's 1 mm: a generator refusing within 1 mm keeps only these)
    double margin_band = 0.01;       // metres of path not judged on either side of each margin cut:
                                     // the generator's and the checker's path lengths differ slightly
    double floor_tolerance = 0.01;   // an end this close to the floor under it is on the floor
    double gap_tolerance = 0.05;     // recorded gap vs the rims found (the spec's +- 0.05)
    double height_tolerance = 0.02;  // recorded rise / drop vs floor to floor
    double length_tolerance = 0.01;  // recorded length vs end to end
    double apex_tolerance = 0.02;    // a jump's apex vs the documented arc's top
    double limit_tolerance = 0.02;   // figures this far past a setting's limit are still within it
    double rim_step = 0.02;          // the checker's rim search: steps, then bisection to 1 mm
    bool check_width = true;         // also test 1.5 r and 2 r against clearance_width
};

enum class LinkVerdict { Ok, Touches, EndNotOnFloor, WrongFigures, Inconclusive, NotChecked };
const char* verdict_name(LinkVerdict verdict);

// Where a body met a triangle: the first cut (along the path) whose static cylinder touches.
struct BodyTouch {
    uint32_t triangle = 0;  // index into the TriangleMesh's triangles
    Vec3d path_point = Vec3d::Zero();
    double along = 0.0;   // fraction of the path's length from the start
    double radius = 0.0;  // radius of the body that touched
};

struct LinkCheck {
    LinkVerdict verdict = LinkVerdict::Ok;  // the worst of the flags below, in the enum's order
    bool touches = false;                   // the agent's body (radius r) touches the level
    bool inconclusive = false;              // some piece was neither proven clear nor touching
    bool end_not_on_floor = false;
    bool wrong_figures = false;         // see `problems`
    std::optional<BodyTouch> touch;     // the first touch of the radius-r body
    uint32_t inconclusive_pieces = 0;   // over every radius tested
    std::vector<std::string> problems;  // each wrong figure or off-floor end, in words

    // What the checker found on its own (NaN when it could not tell).
    double start_floor_y = 0.0, end_floor_y = 0.0;
    double rim_start = 0.0, rim_end = 0.0;  // from each end to its rim, horizontally (jumps: both)
    double gap = 0.0, rise = 0.0, drop = 0.0, length = 0.0;
    double path_length = 0.0;
    float clearance_width = 0.0f;  // 2 x the widest of r, 1.5 r, 2 r proven clear (0: none)
    uint64_t cylinder_tests = 0;   // exact cylinder-triangle tests run

    std::string describe() const;
};

class IndependentLinkChecker {
public:
    // `level`: world-space triangles (Level::world_triangles()); copied.
    IndependentLinkChecker(const TriangleMesh& level, const CheckedAgent& agent, const LinkSettings& settings,
                           const CheckerTolerances& tolerances = {});

    LinkCheck check(const Link& link) const;

    // The documented path the checker rebuilds, as points (`per_piece` per piece), for printing.
    std::vector<Vec3d> path_points(const Link& link, unsigned per_piece = 8) const;
    // The highest surface met by a vertical ray from (x, top, z) down `reach` metres, over every
    // triangle of the level (nullopt: none).
    std::optional<double> floor_below(double x, double z, double top, double reach) const;

    size_t triangle_count() const { return triangles_.size(); }

private:
    struct Tri {
        Vec3d a, b, c;
        Eigen::Vector3d lo, hi;
    };
    // One stretch of path: x, z linear from `from` to `to` over u in [0, 1]; y = y0 + y1 u + y2 u^2.
    struct Piece {
        Eigen::Vector2d from, to;
        double y0, y1, y2;
        std::vector<double> arc;  // arc length at u = k / (arc.size() - 1)
        Vec3d at(double u) const;
        double length() const { return arc.back(); }
        double u_at_length(double s) const;
        void y_range(double u0, double u1, double& lo, double& hi) const;
    };
    struct Path {
        std::vector<Piece> pieces;
        bool valid = true;
        std::string why_not;
    };
    enum class Sweep { Clear, Touches, Inconclusive };
    struct SweepResult {
        Sweep result = Sweep::Clear;
        BodyTouch touch;
        uint32_t inconclusive_pieces = 0;
        uint64_t tests = 0;
    };

    Path documented_path(const Link& link, const LinkCheck& found) const;
    std::vector<uint32_t> candidates(const Path& path, double widest_radius) const;
    std::optional<double> floor_below(const std::vector<uint32_t>& among, double x, double z, double top,
                                      double reach) const;
    // Distance from (x0, z0) along the unit horizontal `heading` to the first point with no ground
    // within a step below `floor_y` (bisected to 1 mm); NaN if none within `limit`.
    double rim_along(const std::vector<uint32_t>& among, const Eigen::Vector2d& from, const Eigen::Vector2d& heading,
                     double floor_y, double limit) const;
    bool any_touches(const std::vector<uint32_t>& among, const UprightCylinder& cylinder, uint32_t* which,
                     uint64_t& tests) const;
    SweepResult sweep(const Path& path, const std::vector<uint32_t>& among, double radius, double extra_clear) const;

    std::vector<Tri> triangles_;
    CheckedAgent agent_;
    LinkSettings settings_;
    CheckerTolerances tol_;
    double lift_;
};

// Counts over many links, for the closing figures: `ok` counts links with no flag at all; each of the
// others counts the links with that flag (a link may have several).
struct CheckTally {
    uint32_t links = 0, ok = 0, touches = 0, end_not_on_floor = 0, wrong_figures = 0, inconclusive = 0;
    uint32_t inconclusive_pieces = 0;
    uint64_t cylinder_tests = 0;
    std::vector<std::string> touching;  // the first few links that touch, described
    std::vector<std::string> failures;  // the first few other failures, described

    void add(const Link& link, const LinkCheck& check);
    void add(const CheckTally& other);
    std::string line() const;
};

std::string describe_link(const Link& link);

}  // namespace nl::test
