#include "links/clearance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace nl {

std::vector<SweepPiece> sweep_pieces(PathPoints path_points, float margin, float most_left_out) {
    const Vec3* path = path_points.points;
    const size_t count = path_points.count;
    std::vector<SweepPiece> pieces;
    float total = 0.0f;
    for (size_t i = 1; i < count; ++i) total += (path[i] - path[i - 1]).norm();
    if (total <= 0.0f) return pieces;
    const float left_out = std::min(margin * total, most_left_out);
    const float keep_from = left_out, keep_to = total - left_out;
    float walked = 0.0f;
    for (size_t i = 1; i < count; ++i) {
        const Vec3 a = path[i - 1], b = path[i];
        const float length = (b - a).norm();
        const float from = std::max(walked, keep_from), to = std::min(walked + length, keep_to);
        walked += length;
        if (to <= from || length <= 0.0f) continue;
        pieces.push_back(SweepPiece{a + (b - a) * ((from - (walked - length)) / length),
                                    a + (b - a) * ((to - (walked - length)) / length), path_points.slack,
                                    static_cast<uint32_t>(i - 1)});
    }
    return pieces;
}

namespace {

SweptCylinder body_along(const SweepPiece& piece, const Body& body, float radius) {
    return SweptCylinder{piece.from, piece.to, radius, body.lift() - piece.slack, body.height + piece.slack};
}

// Twice the margin the exact test keeps: a triangle outside the box is proven apart.
float box_pad(const SweepPiece& piece) {
    return 2.0f * body_margin(piece.from.cwiseAbs().cwiseMax(piece.to.cwiseAbs()));
}

}  // namespace

BodyStretch stretch_of(const SweepPiece& piece, const Body& body, float widest) {
    const SweptCylinder at_widest = body_along(piece, body, widest);
    return BodyStretch{at_widest, bounds_of(at_widest, box_pad(piece))};
}

std::vector<PieceRun> straight_runs(const std::vector<SweepPiece>& pieces) {
    const float kMostTurn = std::cos(3.14159265f / 4.0f);
    std::vector<PieceRun> runs;
    uint32_t first = 0;
    for (uint32_t k = 1; k <= pieces.size(); ++k) {
        const bool ends =
            k == pieces.size() ||
            (pieces[k - 1].to - pieces[k - 1].from).normalized().dot((pieces[k].to - pieces[k].from).normalized()) <
                kMostTurn;
        if (!ends) continue;
        if (k - first >= 2) runs.push_back(PieceRun{first, k});
        first = k;
    }
    return runs;
}

OrientedBox run_box(const std::vector<SweepPiece>& pieces, PieceRun run, const Body& body, float widest) {
    std::vector<Vec3> corners;
    corners.reserve(8 * (run.last - run.first));
    float pad = 0.0f;
    for (uint32_t k = run.first; k < run.last; ++k) {
        const OrientedBox b = stretch_of(pieces[k], body, widest).bounds;
        for (float x : {-1.0f, 1.0f})
            for (float y : {-1.0f, 1.0f})
                for (float z : {-1.0f, 1.0f})
                    corners.push_back(b.center + b.axes * b.half_extents.cwiseProduct(Vec3(x, y, z)));
        pad = std::max(pad, box_pad(pieces[k]));
    }
    Vec3 along = pieces[run.last - 1].to - pieces[run.first].from;
    along.y() = 0.0f;
    if (along.squaredNorm() < 1e-8f) along = Vec3::UnitX();
    return box_around(axes_along(along, Vec3::UnitY()), corners.data(), corners.size(), pad);
}

}  // namespace nl
