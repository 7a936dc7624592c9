// The geometry of "an agent-sized body fits along this path": the path (a jump arc, a fall) is cut
// into straight pieces, and the agent's body (an upright cylinder, level/swept_body.h) swept along
// each is tested exactly against the level's triangles (Level::bodies_clear). The triangles around a
// straight run of pieces are gathered once, so a run through open air costs one query.
#pragma once

#include <vector>

#include "level/level.h"
#include "level/oriented_box.h"

namespace nl {

// The body a link is checked for: an upright cylinder of the agent's radius, from lift() above the
// path point (what the feet step over, or pass above at a rim) to the agent's height above it.
struct Body {
    float radius;
    float height;
    float lift() const { return std::min(0.3f, 0.25f * height); }
};

// Radii of the bodies a sweep tries, in agent radii, narrowest first: one sweep tells the widest
// body that fits (the link's clearance width is twice the widest radius clear).
constexpr float kSweepRadii[] = {1.0f, 1.5f, 2.0f};
constexpr unsigned kSweepRadiusCount = sizeof(kSweepRadii) / sizeof(kSweepRadii[0]);

// One straight stretch of a swept path, its share of the margins cut off. The path strays from it
// by at most `slack` vertically (an arc's sagitta over the piece; 0 for straight paths).
struct SweepPiece {
    Vec3 from, to;
    float slack = 0.0f;
    uint32_t source = 0;  // the path point it starts from, or its part of the path from there to the next
};

// A path to sweep, first point to last; each piece between two points strays from its chord by at
// most `slack` vertically.
struct PathPoints {
    const Vec3* points;  // borrowed
    size_t count;
    float slack = 0.0f;
};

// The pieces of `path`, leaving out `margin` of its length at each end, but never more than
// `most_left_out` (take-off and landing touch the floor).
std::vector<SweepPiece> sweep_pieces(PathPoints path, float margin, float most_left_out);

// The body along a piece (its height span grown by the piece's slack), with a box that holds it at
// `widest` radius.
BodyStretch stretch_of(const SweepPiece& piece, const Body& body, float widest);

// Runs [first, last) of two or more consecutive pieces that turn by less than 45 degrees from one to
// the next: a whole jump arc, the walk out and across of a fall.
struct PieceRun {
    uint32_t first, last;
};
std::vector<PieceRun> straight_runs(const std::vector<SweepPiece>& pieces);

// A box that holds the bodies of the pieces [run.first, run.last) at `widest` radius: when no
// triangle touches it, every one of them is clear.
OrientedBox run_box(const std::vector<SweepPiece>& pieces, PieceRun run, const Body& body, float widest);

}  // namespace nl
