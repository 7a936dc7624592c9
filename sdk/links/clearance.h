// The geometry of "an agent-sized body fits along this path": the path (a jump arc, a fall) is swept
// by a body of a radius and height, approximated by occlusion segments the level tests in batches.
#pragma once

#include <vector>

#include "level/level.h"
#include "level/oriented_box.h"

namespace nl {

struct Body {
    float radius;
    float height;
};

// A parabola from start to end whose top is `apex_above` over the higher end, cut into `pieces`.
struct JumpArc {
    std::vector<Vec3> points;  // pieces + 1 points, start first
    Vec3 apex;
};
JumpArc jump_arc(const Vec3& start, const Vec3& end, float apex_above, unsigned pieces);

// Lateral offsets of the sweep lines, in agent radii: the centre line, then the two sides of bodies
// 1, 1.5 and 2 radii wide, so that one batch tells the widest body that fits.
constexpr float kSweepOffsets[] = {0.0f, -1.0f, 1.0f, -1.5f, 1.5f, -2.0f, 2.0f};
constexpr unsigned kSweepOffsetCount = sizeof(kSweepOffsets) / sizeof(kSweepOffsets[0]);
constexpr unsigned kSweepHeights = 3;

// One straight stretch of a swept path, its share of the margins cut off: the body's lines run from
// `from` to `to`, each moved sideways by one of kSweepOffsets radii along `side` and up by one of
// `heights`.
struct SweepPiece {
    Vec3 from, to;
    Vec3 side;  // horizontal, across the path's overall heading
    float heights[kSweepHeights];
};
constexpr unsigned kSegmentsPerPiece = kSweepHeights * kSweepOffsetCount * 2;

// A path to sweep, first point to last.
struct PathPoints {
    const Vec3* points;  // borrowed
    size_t count;
};

// The pieces of an agent-sized body swept along `path` (feet on the path), leaving out `margin` of
// the path's length at each end (take-off and landing touch the floor): three heights (near the
// feet, the middle, the head).
std::vector<SweepPiece> sweep_pieces(PathPoints path, const Body& body, float margin);

// Appends the piece's kSegmentsPerPiece segments: for each height, for each offset, the line in both
// directions, so that a surface met from either side blocks. Segment k uses offset
// (k / 2) % kSweepOffsetCount.
void append_piece_segments(const SweepPiece& piece, float radius, std::vector<Segment>& out);

// A box that holds every segment of the piece, padded for rounding: when no triangle touches it,
// none of them is blocked.
OrientedBox piece_box(const SweepPiece& piece, float radius);

// Runs [first, last) of two or more consecutive pieces that turn by less than 45 degrees from one to
// the next: a whole jump arc, the walk out and across of a fall. A run's box is asked before its
// pieces', so a run through open air costs one box query.
struct PieceRun {
    uint32_t first, last;
};
std::vector<PieceRun> straight_runs(const std::vector<SweepPiece>& pieces);

// A box that holds every segment of the pieces [run.first, run.last).
OrientedBox run_box(const std::vector<SweepPiece>& pieces, PieceRun run, float radius);

}  // namespace nl
