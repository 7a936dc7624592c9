#include "links/clearance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

namespace nl {

JumpArc jump_arc(const Vec3& start, const Vec3& end, float apex_above, unsigned pieces) {
    // y(t) = start.y + b t + c t^2 over the horizontal fraction t, through end at t = 1, topping out at
    // h above start.y: c solves c^2 + (4h - 2dy) c + dy^2 = 0 on its negative root.
    const double dy = double(end.y()) - start.y();
    const double h = std::max(double(start.y()), double(end.y())) + apex_above - start.y();
    const double c = -(2.0 * h - dy) - 2.0 * std::sqrt(std::max(0.0, h * (h - dy)));
    const double b = dy - c;
    const double t_apex = c < 0.0 ? std::clamp(-b / (2.0 * c), 0.0, 1.0) : 0.5;
    auto at = [&](double t) {
        const Vec3 flat = start + static_cast<float>(t) * (end - start);
        return Vec3(flat.x(), static_cast<float>(start.y() + b * t + c * t * t), flat.z());
    };
    JumpArc arc;
    for (unsigned i = 0; i <= pieces; ++i) arc.points.push_back(at(double(i) / pieces));
    arc.apex = at(t_apex);
    return arc;
}

std::vector<SweepPiece> sweep_pieces(PathPoints path_points, const Body& body, float margin) {
    const Vec3* path = path_points.points;
    const size_t count = path_points.count;
    std::vector<SweepPiece> pieces;
    float total = 0.0f;
    for (size_t i = 1; i < count; ++i) total += (path[i] - path[i - 1]).norm();
    if (total <= 0.0f) return pieces;
    const float keep_from = margin * total, keep_to = (1.0f - margin) * total;
    // One sideways direction for the whole path: its horizontal heading.
    Vec3 heading = path[count - 1] - path[0];
    heading.y() = 0.0f;
    const Vec3 side = heading.norm() > 1e-4f ? Vec3(-heading.z(), 0.0f, heading.x()).normalized() : Vec3::UnitX();
    float walked = 0.0f;
    for (size_t i = 1; i < count; ++i) {
        const Vec3 a = path[i - 1], b = path[i];
        const float length = (b - a).norm();
        const float from = std::max(walked, keep_from), to = std::min(walked + length, keep_to);
        walked += length;
        if (to <= from || length <= 0.0f) continue;
        SweepPiece piece{a + (b - a) * ((from - (walked - length)) / length), a + (b - a) * ((to - (walked - length)) / length),
                         side, {std::min(0.3f, 0.25f * body.height), 0.5f * body.height,
                                std::max(0.5f * body.height, body.height - 0.1f)}};
        pieces.push_back(piece);
    }
    return pieces;
}

void append_piece_segments(const SweepPiece& piece, float radius, std::vector<Segment>& out) {
    for (float y : piece.heights) {
        for (float x : kSweepOffsets) {
            const Vec3 offset = piece.side * (x * radius) + Vec3(0.0f, y, 0.0f);
            out.push_back(Segment{piece.from + offset, piece.to + offset});
            out.push_back(Segment{piece.to + offset, piece.from + offset});
        }
    }
}

namespace {

// The eight corners of the parallelepiped every segment of the piece lies in.
std::array<Vec3, 8> piece_corners(const SweepPiece& piece, float radius) {
    const float wide = *std::max_element(std::begin(kSweepOffsets), std::end(kSweepOffsets)) * radius;
    const float low = *std::min_element(std::begin(piece.heights), std::end(piece.heights));
    const float high = *std::max_element(std::begin(piece.heights), std::end(piece.heights));
    const Vec3 s = piece.side * wide, l(0.0f, low, 0.0f), h(0.0f, high, 0.0f);
    return {piece.from - s + l, piece.from + s + l, piece.from - s + h, piece.from + s + h,
            piece.to - s + l,   piece.to + s + l,   piece.to - s + h,   piece.to + s + h};
}

// A millimetre, and a few float steps at the size of the coordinates.
float rounding_pad(const Vec3* points, size_t count) {
    float magnitude = 0.0f;
    for (size_t i = 0; i < count; ++i) magnitude = std::max(magnitude, points[i].cwiseAbs().maxCoeff());
    return 1e-3f + 8.0f * std::numeric_limits<float>::epsilon() * magnitude;
}

}  // namespace

OrientedBox piece_box(const SweepPiece& piece, float radius) {
    const std::array<Vec3, 8> corners = piece_corners(piece, radius);
    return box_around(axes_along(piece.to - piece.from, piece.side), corners.data(), corners.size(),
                      rounding_pad(corners.data(), corners.size()));
}

std::vector<PieceRun> straight_runs(const std::vector<SweepPiece>& pieces) {
    const float kMostTurn = std::cos(3.14159265f / 4.0f);
    std::vector<PieceRun> runs;
    uint32_t first = 0;
    for (uint32_t k = 1; k <= pieces.size(); ++k) {
        const bool ends = k == pieces.size() ||
                          (pieces[k - 1].to - pieces[k - 1].from).normalized().dot((pieces[k].to - pieces[k].from).normalized()) < kMostTurn;
        if (!ends) continue;
        if (k - first >= 2) runs.push_back(PieceRun{first, k});
        first = k;
    }
    return runs;
}

OrientedBox run_box(const std::vector<SweepPiece>& pieces, PieceRun run, float radius) {
    std::vector<Vec3> corners;
    corners.reserve(8 * (run.last - run.first));
    for (uint32_t k = run.first; k < run.last; ++k) {
        const std::array<Vec3, 8> c = piece_corners(pieces[k], radius);
        corners.insert(corners.end(), c.begin(), c.end());
    }
    const Vec3 along = pieces[run.last - 1].to - pieces[run.first].from;
    return box_around(axes_along(along.squaredNorm() > 1e-8f ? along : pieces[run.first].to - pieces[run.first].from,
                                 pieces[run.first].side),
                      corners.data(), corners.size(), rounding_pad(corners.data(), corners.size()));
}

}  // namespace nl
